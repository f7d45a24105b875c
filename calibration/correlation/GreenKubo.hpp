// Green-Kubo integrals of correlation functions with a plateau criterion and
// a statistical error from independent blocks or replicas.
//
//   D = int_0^inf < v_x(0) v_x(t) > dt        (seed eq 14, per component)
//   eta = int_0^inf < J_xy(0) J_xy(t) > dt    (seed eq 8, up to the caller's
//                                              volume / temperature factor)
#ifndef sdf_correlation_GreenKubo_hpp
#define sdf_correlation_GreenKubo_hpp

#include "correlation/MultipleTauCorrelator.hpp"
#include "correlation/Statistics.hpp"

#include <cstddef>
#include <limits>
#include <vector>

namespace sdf::correlation
{

//- Cumulative trapezoid integral I(t_i) = int_{t_0}^{t_i} f dt on any
//  increasing grid (uniform FFT lags or log-spaced multiple-tau lags).
std::vector<double> runningIntegral
(
    const std::vector<double>& times,
    const std::vector<double>& values
);

//- Uniform grid t_k = k dt, k = 0 .. count-1.
std::vector<double> uniformTimes(std::size_t count, double dt);

struct PlateauSettings
{
    //- The running integral is flat when |I(t') - I(t_p)| <= noiseMultiple *
    //  (standard error of I(t')) for every t' in the window after t_p.
    double noiseMultiple = 1.0;
    //- The window is [t_p, (1 + windowFactor) t_p]: long enough to see a
    //  slow tail, scaled so that it means the same for any time unit.
    double windowFactor = 1.0;
    //- Ignore plateau candidates before this time (e.g. to skip t = 0).
    double earliestTime = 0.0;
    //- Read the integral at lags up to this time only (every window ends by it). The
    //  cell run sets the MSD's longest lag, so that Green-Kubo and the Einstein fit
    //  measure the same lags: past it the few pairs left in a block carry a slow
    //  tail that the MSD cannot see, and the two would differ by construction.
    //  At least the first two lags are read.
    double latestTime = std::numeric_limits<double>::infinity();
    //- A window that would run past the last lag read is cut there if it still
    //  spans end/t_p >= clippedWindowRatio (0: never cut, only full windows; the
    //  cell run takes the Einstein window's minimum, 1.5).
    double clippedWindowRatio = 0.0;
};

struct GreenKuboResult
{
    //- Plateau value: mean of the block-mean running integral over the
    //  window. Standard error: jackknife over blocks of the whole procedure
    //  (each leave-one-out set finds its own plateau), so the scatter that
    //  the data-driven choice of t_p adds is included. Measured on
    //  Ornstein-Uhlenbeck replicas it is honest to slightly conservative.
    Estimate integral;
    double plateauTime = 0.0;   // t_p
    double windowEnd = 0.0;     // (1 + windowFactor) t_p, or the last lag read
    //- false: no time where the integral is flat within its noise (run longer:
    //  with latestTime, longer blocks); the integral then reports the last
    //  window anyway, from earliestTime on where it fits.
    bool plateauFound = false;
    //- The plateau value of each leave-one-block-out set, in block order (the
    //  jackknife's): paired with another estimate's from the same blocks, they give
    //  the error of a difference with the covariance of the two included.
    std::vector<double> leaveOneOut;

    std::vector<double> times;
    std::vector<double> meanCorrelation, correlationError;
    std::vector<double> meanRunningIntegral, runningIntegralError;
};

//- blockCorrelations[b][k]: the correlation function at times[k] measured on
//  block (or replica) b; >= 3 independent blocks are needed (8 to 20 are
//  recommended: fewer make the error itself uncertain, more make each block
//  short compared with the correlation time).
GreenKuboResult greenKubo
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockCorrelations,
    const PlateauSettings& settings = PlateauSettings()
);

//- Green-Kubo from the blocks of a streaming correlator
//  (MultipleTauCorrelator::blocks()): column `column` of the values, or the
//  mean of all columns with column = -1 (isotropic VACF from x, y, z).
//  Uses the lags common to all blocks; times = lag * sampleInterval.
GreenKuboResult greenKubo
(
    const std::vector<LaggedCorrelation>& blocks,
    double sampleInterval,
    int column,
    const PlateauSettings& settings = PlateauSettings()
);

} // namespace sdf::correlation

#endif

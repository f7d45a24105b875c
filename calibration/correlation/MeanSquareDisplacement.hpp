// Mean-square displacement with multiple time origins and the Einstein
// diffusivity, the cross-check of Green-Kubo (validation.md item 12).
//
// Positions must be unwrapped (periodic jumps removed; for Lees-Edwards cells
// also the image shift, and for shear flow the mean streaming displacement).
// The MSD needs far fewer samples than the VACF: store positions every few
// collision times and the memory stays small in long runs.
#ifndef sdf_correlation_MeanSquareDisplacement_hpp
#define sdf_correlation_MeanSquareDisplacement_hpp

#include "correlation/FftCorrelator.hpp"
#include "correlation/Statistics.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace sdf::correlation
{

//- Per-component MSD averaged over particles and time origins, frames
//  [begin, end): row k, column c = < (x_pc(t+k) - x_pc(t))^2 >_{p,t}.
//  O(P N log N) by FFT (MSD = S1 - 2 S2). Returns (maxLag+1) x 3.
Eigen::MatrixX3d meanSquareDisplacement
(
    const VectorFrames& unwrappedPositions,
    std::size_t maxLag,
    std::size_t begin,
    std::size_t end
);

//- meanSquareDisplacement over all frames; per block of the trajectory:
//  blockEstimates(meanSquareDisplacement, ...) (FftCorrelator.hpp).
Eigen::MatrixX3d meanSquareDisplacement
(
    const VectorFrames& unwrappedPositions,
    std::size_t maxLag
);

//- Where the Einstein line is fitted: fitStart <= t <= fitEnd, and how many
//  components the MSD sums: dimensions = 1 for one component, 3 for the sum of
//  x, y, z (D = MSD / 6t).
struct EinsteinWindow
{
    double fitStart = 0.0;
    double fitEnd = 0.0;
    int dimensions = 3;
};

//- Straight-line fit MSD(t) = slope t + intercept over the window (GSL
//  gsl_fit_linear) and D = slope / (2 dimensions).
struct EinsteinFit
{
    double diffusivity = 0.0;
    //- From the residual scatter, assuming independent points. MSD points at
    //  neighbouring lags are strongly correlated, so this underestimates the
    //  statistical error: use einsteinDiffusivity's block error for that.
    double fitStandardError = 0.0;
    double slope = 0.0;
    double intercept = 0.0;
    std::size_t points = 0;
};

EinsteinFit fitEinsteinSlope
(
    const std::vector<double>& times,
    const std::vector<double>& msd,
    const EinsteinWindow& window
);

struct EinsteinResult
{
    //- Mean over blocks of each block's fitted D, with the standard error
    //  from their scatter (the honest one).
    Estimate diffusivity;
    //- Each block's fitted D, in block order (what diffusivity is the mean of).
    std::vector<double> blockDiffusivities;
    //- Fit of the block-mean MSD (same value, shows the fit quality).
    EinsteinFit fitOfMean;
    std::vector<double> meanMsd;
};

//- blockMsd[b][k] at times[k]: one MSD (one component, or a sum of
//  window.dimensions components) per independent block or replica, e.g. from
//  blockEstimates(meanSquareDisplacement, ...).
EinsteinResult einsteinDiffusivity
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockMsd,
    const EinsteinWindow& window
);

} // namespace sdf::correlation

#endif

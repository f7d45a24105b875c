// Is a diffusivity measured in the diffusive regime? The checks every cell run applies
// to its Green-Kubo and Einstein (MSD) estimates before the calibration trusts them:
//
//   1. the Einstein fit window starts past the velocity autocorrelation's decay:
//      t_start >= windowStartCorrelationTimes * tau_v, tau_v = max_t I(t) / C(0)
//      (I the running Green-Kubo integral: the VACF's area over its height). For an
//      exponential VACF the MSD's local slope is then within exp(-5) = 0.7 % of D;
//   2. the MSD's local slope is flat over the window: D fitted over the window's
//      second half minus D over its first half, per block, is zero within
//      agreementSigmas standard errors plus slopeTolerance D (a slow tail of the VACF
//      shows here). The tolerance is there because dense fluids have a slow tail
//      (D(t) approaching D as t^-1/2) that long runs resolve at a few per cent, below
//      the 5 % the calibration aims for: a drift smaller than that is accepted,
//      reported, and counted in the fit's error when the condition fails otherwise;
//   3. Green-Kubo equals the MSD: |D_GK - D_MSD| <= agreementSigmas * the errors
//      combined in quadrature (the two come from the same trajectory, so this
//      overstates the error of the difference: a lenient test);
//   4. the Green-Kubo running integral reached its plateau (GreenKubo.hpp);
//   5. the cell is stationary: D over the window from the later half of the blocks
//      minus D from the earlier half is zero within agreementSigmas combined errors
//      plus slopeTolerance D (a cell that ages, e.g. one that slowly orders or
//      crystallises near phi 0.5, shows a D that falls with the run's length); not
//      checked with fewer than 4 blocks.
//
// Since I(t) is exactly half the MSD's local slope per component, 1-3 ask one
// question three ways: has the velocity forgotten its past within the lags measured?
// A condition that fails is stored as not converged (docs/user/calibration.md says
// what the fit does with it).
#ifndef sdf_correlation_DiffusiveRegime_hpp
#define sdf_correlation_DiffusiveRegime_hpp

#include "correlation/GreenKubo.hpp"
#include "correlation/MeanSquareDisplacement.hpp"
#include "correlation/Statistics.hpp"

#include <limits>
#include <string>
#include <vector>

namespace sdf::correlation
{

struct DiffusiveRegimeSettings
{
    double windowStartCorrelationTimes = 5.0;
    //- The window must span at least this ratio fitEnd/fitStart, and hold this many MSD
    //  lags per half, or the blocks are too short for the check.
    double minimumWindowRatio = 1.5;
    std::size_t minimumPointsPerHalf = 4;
    double agreementSigmas = 2.0;
    double slopeTolerance = 0.05;
};

//- tau_v = max_t I(t) / C(0) of a Green-Kubo result over lags t <= maxTime (0 if
//  C(0) <= 0). Bounding the lags keeps the noisy far end of the VACF, where few pairs
//  remain, from inflating tau_v: the cell run takes the MSD's longest lag.
double velocityCorrelationTime
(
    const GreenKuboResult& greenKubo,
    double maxTime = std::numeric_limits<double>::infinity()
);

//- The Einstein window past the VACF's decay on the MSD's lag grid `times`: from the
//  first lag at or after windowStartCorrelationTimes tau_v to the last lag; when that
//  leaves less than minimumWindowRatio or fewer than 3 lags, from the last lag that
//  leaves both (then the check fails on item 1). Needs >= 3 lags.
EinsteinWindow diffusiveWindow
(
    double correlationTime,
    const std::vector<double>& times,
    int dimensions,
    const DiffusiveRegimeSettings& settings = DiffusiveRegimeSettings()
);

struct DiffusiveRegimeCheck
{
    double correlationTime = 0;   // tau_v [s]
    double fitStart = 0;          // the Einstein window [s]
    double fitEnd = 0;
    Estimate earlySlope;          // D over the window's first half (block mean, error)
    Estimate lateSlope;           // D over its second half
    Estimate slopeChange;         // late - early, per block
    Estimate msd;                 // D_MSD over the whole window
    //- D_GK - D_MSD. Both come from the same blocks of one trajectory and move together
    //  (a block of fast particles raises both), so when the two have one value per block
    //  the error is the jackknife of the difference over those blocks, which includes
    //  their covariance; otherwise (other block counts) the errors in quadrature.
    Estimate greenKuboMinusMsd;
    Estimate drift;               // D of the later blocks - D of the earlier blocks
    bool windowPastDecay = false;
    bool slopeFlat = false;
    bool greenKuboAgrees = false;
    bool plateauFound = false;
    bool stationary = false;

    //- false: no MSD was measured (fewer than 8 frames per block); only
    //  correlationTime and plateauFound are set
    bool measured = false;

    bool converged() const
    {
        return measured && windowPastDecay && slopeFlat && greenKuboAgrees && plateauFound
            && stationary;
    }

    //- "diffusive", or the failed items, e.g. "window before the VACF's decay;
    //  MSD slope not flat (+12 +- 3 %)".
    std::string verdict() const;

    //- "MSD slope change +5.0 +- 1.2 %, Green-Kubo - MSD +4.4 +- 2.7 %, drift over the
    //  run -1.0 +- 2.0 %" (of D_MSD).
    std::string figures() const;
};

//- blockMsd as for einsteinDiffusivity (one series per block, `window.dimensions`
//  components summed); einstein = einsteinDiffusivity's result over the same window
//  (its per-block D serve the stationarity item); correlationTime the tau_v the window
//  was made from. Stationarity (item 5) needs
//  >= 4 blocks: with fewer it is not checked (drift.samples 0).
DiffusiveRegimeCheck checkDiffusiveRegime
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockMsd,
    const EinsteinWindow& window,
    const EinsteinResult& einstein,
    const GreenKuboResult& greenKubo,
    double correlationTime,
    const DiffusiveRegimeSettings& settings = DiffusiveRegimeSettings()
);

} // namespace sdf::correlation

#endif

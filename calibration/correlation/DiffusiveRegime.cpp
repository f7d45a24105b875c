#include "correlation/DiffusiveRegime.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sdf::correlation
{

double velocityCorrelationTime(const GreenKuboResult& greenKubo, double maxTime)
{
    if (greenKubo.meanCorrelation.empty() || !(greenKubo.meanCorrelation.front() > 0))
    {
        return 0;
    }
    double peak = 0;
    for (std::size_t k = 0; k < greenKubo.meanRunningIntegral.size(); ++k)
    {
        if (greenKubo.times[k] > maxTime) break;
        peak = std::max(peak, greenKubo.meanRunningIntegral[k]);
    }
    return peak/greenKubo.meanCorrelation.front();
}


EinsteinWindow diffusiveWindow
(
    double correlationTime,
    const std::vector<double>& times,
    int dimensions,
    const DiffusiveRegimeSettings& settings
)
{
    const std::size_t n = times.size();
    if (n < 3)
    {
        throw std::invalid_argument("diffusiveWindow: needs >= 3 lags, got " + std::to_string(n));
    }
    // Starts on lags of the grid, so that the fit's inclusive bounds never lose a point
    // to round-off: the first lag at or after the target, but no later than the last
    // lag that leaves the minimum ratio and 3 lags
    const double longest = times.back();
    const double target = settings.windowStartCorrelationTimes*correlationTime;
    const double latest = std::min(longest/settings.minimumWindowRatio, times[n - 3]);
    std::size_t k = 0;
    while (k < n - 3 && times[k] < target*(1 - 1e-12)) ++k;
    while (k > 0 && times[k] > latest*(1 + 1e-12)) --k;
    return {times[k], longest, dimensions};
}


namespace
{

//- D fitted over [start, end] of every block's MSD.
std::vector<double> blockSlopes
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockMsd,
    double start,
    double end,
    int dimensions
)
{
    std::vector<double> slopes;
    for (const std::vector<double>& msd : blockMsd)
    {
        slopes.push_back(fitEinsteinSlope(times, msd, {start, end, dimensions}).diffusivity);
    }
    return slopes;
}

//- b - a of independent estimates, their errors in quadrature.
Estimate difference(const Estimate& b, const Estimate& a)
{
    return
    {
        b.value - a.value,
        std::hypot(b.standardError, a.standardError),
        std::min(a.samples, b.samples)
    };
}

//- D_GK - D_MSD with the jackknife error over blocks paired by index (the MSD's
//  leave-one-out means from its per-block D): what the two share cancels, as it does in
//  the difference itself. Errors in quadrature when the block counts differ.
Estimate pairedDifference(const GreenKuboResult& greenKubo, const EinsteinResult& einstein)
{
    const std::vector<double>& gk = greenKubo.leaveOneOut;
    const std::vector<double>& msd = einstein.blockDiffusivities;
    const std::size_t n = msd.size();
    if (gk.size() != n || n < 3)
    {
        return difference(greenKubo.integral, einstein.diffusivity);
    }
    const double all = greenKubo.integral.value - einstein.diffusivity.value;
    double sum = 0;
    for (const double d : msd) sum += d;
    double squares = 0;
    for (std::size_t b = 0; b < n; ++b)
    {
        const double left = gk[b] - (sum - msd[b])/double(n - 1);
        squares += (left - all)*(left - all);
    }
    return {all, std::sqrt(double(n - 1)/double(n)*squares), n};
}

//- |d| within `sigmas` of its standard errors plus `tolerance` (absolute).
bool withinErrors(const Estimate& d, double sigmas, double tolerance)
{
    return std::abs(d.value) <= sigmas*d.standardError + tolerance;
}

std::string percent(const Estimate& change, double reference)
{
    char buf[64];
    std::snprintf
    (
        buf, sizeof buf, "%+.1f +- %.1f %%",
        100*change.value/reference, 100*change.standardError/std::abs(reference)
    );
    return buf;
}

} // namespace


DiffusiveRegimeCheck checkDiffusiveRegime
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockMsd,
    const EinsteinWindow& window,
    const EinsteinResult& einstein,
    const GreenKuboResult& greenKubo,
    double correlationTime,
    const DiffusiveRegimeSettings& settings
)
{
    const Estimate& msd = einstein.diffusivity;
    const double tolerance = settings.slopeTolerance*std::abs(msd.value);
    if (blockMsd.size() < 2)
    {
        throw std::invalid_argument("checkDiffusiveRegime: needs >= 2 blocks or replicas");
    }
    DiffusiveRegimeCheck check;
    check.measured = true;
    check.correlationTime = correlationTime;
    check.fitStart = window.fitStart;
    check.fitEnd = window.fitEnd;
    check.plateauFound = greenKubo.plateauFound;
    check.msd = msd;

    const double middle = 0.5*(window.fitStart + window.fitEnd);
    const auto inRange = [&](double a, double b)
    {
        return std::size_t(std::count_if
        (
            times.begin(), times.end(), [&](double t) { return t >= a && t <= b; }
        ));
    };
    const bool longEnough =
        window.fitEnd >= settings.minimumWindowRatio*window.fitStart*(1 - 1e-12)
     && inRange(window.fitStart, middle) >= settings.minimumPointsPerHalf
     && inRange(middle, window.fitEnd) >= settings.minimumPointsPerHalf;
    check.windowPastDecay =
        longEnough
     && check.correlationTime > 0
     && window.fitStart
     >= settings.windowStartCorrelationTimes*check.correlationTime*(1 - 1e-12);

    if (longEnough)
    {
        const std::vector<double> early =
            blockSlopes(times, blockMsd, window.fitStart, middle, window.dimensions);
        const std::vector<double> late =
            blockSlopes(times, blockMsd, middle, window.fitEnd, window.dimensions);
        std::vector<double> change(early.size());
        for (std::size_t b = 0; b < early.size(); ++b) change[b] = late[b] - early[b];
        check.earlySlope = meanAndStandardError(early);
        check.lateSlope = meanAndStandardError(late);
        check.slopeChange = meanAndStandardError(change);
        check.slopeFlat = withinErrors(check.slopeChange, settings.agreementSigmas, tolerance);
    }

    // stationarity: D over the window (the Einstein fit's per-block values), later half
    // of the blocks against the earlier; not checked with fewer than 4 blocks
    const std::vector<double>& perBlock = einstein.blockDiffusivities;
    const std::size_t half = perBlock.size()/2;
    check.stationary = half < 2;
    if (half >= 2)
    {
        check.drift = difference
        (
            meanAndStandardError(std::vector<double>(perBlock.end() - half, perBlock.end())),
            meanAndStandardError(std::vector<double>(perBlock.begin(), perBlock.begin() + half))
        );
        check.drift.samples = perBlock.size();
        check.stationary = withinErrors(check.drift, settings.agreementSigmas, tolerance);
    }

    check.greenKuboMinusMsd = pairedDifference(greenKubo, einstein);
    check.greenKuboAgrees = withinErrors(check.greenKuboMinusMsd, settings.agreementSigmas, 0);
    return check;
}


namespace
{

//- What the percentages are of: |D_MSD|, or |D_GK| when the MSD's is not positive.
double referenceOf(const Estimate& msd, const Estimate& greenKuboMinusMsd)
{
    if (msd.value > 0) return msd.value;
    const double gk = std::abs(greenKuboMinusMsd.value + msd.value);
    return gk > 0 ? gk : 1.0;
}

} // namespace


std::string DiffusiveRegimeCheck::verdict() const
{
    if (converged()) return "diffusive";
    if (!measured)
    {
        return "MSD not measured (fewer than 8 position frames per block: sample longer)";
    }
    std::string v;
    const auto add = [&v](const std::string& s) { v += (v.empty() ? "" : "; ") + s; };
    const double reference = referenceOf(msd, greenKuboMinusMsd);
    if (!windowPastDecay) add("MSD window before the VACF's decay (blocks too short)");
    if (!slopeFlat)
    {
        add
        (
            "MSD slope not flat ("
          + (slopeChange.samples ? percent(slopeChange, reference) : std::string("window too short"))
          + ")"
        );
    }
    if (!greenKuboAgrees)
    {
        add("Green-Kubo - MSD = " + percent(greenKuboMinusMsd, reference));
    }
    if (!plateauFound) add("no Green-Kubo plateau");
    if (!stationary)
    {
        add
        (
            "D drifts over the run (" + percent(drift, reference) + ")"
        );
    }
    return v;
}

std::string DiffusiveRegimeCheck::figures() const
{
    if (!measured) return "MSD not measured";
    const double reference = referenceOf(msd, greenKuboMinusMsd);
    return "MSD slope change "
      + (slopeChange.samples ? percent(slopeChange, reference) : std::string("not measured"))
      + ", Green-Kubo - MSD " + percent(greenKuboMinusMsd, reference)
      + ", drift over the run "
      + (drift.samples ? percent(drift, reference) : std::string("not checked (< 4 blocks)"));
}

} // namespace sdf::correlation

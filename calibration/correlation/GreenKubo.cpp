#include "correlation/GreenKubo.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::correlation
{

std::vector<double> runningIntegral
(
    const std::vector<double>& times,
    const std::vector<double>& values
)
{
    if (times.size() != values.size() || times.empty())
    {
        throw std::invalid_argument
        (
            "runningIntegral: " + std::to_string(times.size()) + " times and "
          + std::to_string(values.size()) + " values"
        );
    }
    std::vector<double> integral(times.size(), 0.0);
    for (std::size_t i = 1; i < times.size(); ++i)
    {
        const double dt = times[i] - times[i - 1];
        if (!(dt > 0.0))
        {
            throw std::invalid_argument("runningIntegral: times must increase");
        }
        integral[i] = integral[i - 1] + 0.5 * dt * (values[i] + values[i - 1]);
    }
    return integral;
}

std::vector<double> uniformTimes(std::size_t count, double dt)
{
    std::vector<double> t(count);
    for (std::size_t k = 0; k < count; ++k)
    {
        t[k] = dt * static_cast<double>(k);
    }
    return t;
}

namespace
{

// Mean of f over [times[first], times[last]] by the trapezoid rule (the
// window average of a running integral); f itself when first == last.
double windowMean
(
    const std::vector<double>& times,
    const std::vector<double>& f,
    std::size_t first,
    std::size_t last
)
{
    if (first == last)
    {
        return f[first];
    }
    double area = 0.0;
    for (std::size_t i = first + 1; i <= last; ++i)
    {
        area += 0.5 * (times[i] - times[i - 1]) * (f[i] + f[i - 1]);
    }
    return area / (times[last] - times[first]);
}

struct Plateau
{
    std::size_t first = 0;
    std::size_t last = 0;
    bool found = false;
    double value = 0.0;
};

std::vector<std::size_t> allBlocks(std::size_t count)
{
    std::vector<std::size_t> all(count);
    for (std::size_t b = 0; b < count; ++b)
    {
        all[b] = b;
    }
    return all;
}

// The plateau of the mean running integral of the chosen blocks: the first
// t_p after which it stays within noiseMultiple standard errors of I(t_p)
// over [t_p, (1 + windowFactor) t_p], cut at the last lag read (<= latestTime)
// if it still spans clippedWindowRatio; value = window mean of the mean.
Plateau findPlateau
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockIntegrals,
    const std::vector<std::size_t>& chosen,
    const PlateauSettings& settings
)
{
    // only the lags up to latestTime (at least two, so that a window exists)
    std::size_t n = 0;
    while (n < times.size() && times[n] <= settings.latestTime)
    {
        ++n;
    }
    n = std::max<std::size_t>(n, std::min<std::size_t>(2, times.size()));
    std::vector<double> I(n), sigma(n), column(chosen.size());
    for (std::size_t k = 0; k < n; ++k)
    {
        for (std::size_t i = 0; i < chosen.size(); ++i)
        {
            column[i] = blockIntegrals[chosen[i]][k];
        }
        const Estimate e = meanAndStandardError(column);
        I[k] = e.value;
        sigma[k] = e.standardError;
    }

    Plateau plateau;
    std::size_t last = 0;
    for (std::size_t k = 1; k < n && !plateau.found; ++k)
    {
        if (times[k] < settings.earliestTime)
        {
            continue;
        }
        double end = (1.0 + settings.windowFactor) * times[k];
        if (times[n - 1] < end)
        {
            if
            (
                settings.clippedWindowRatio > 0
             && times[n - 1] >= settings.clippedWindowRatio * times[k]
            )
            {
                end = times[n - 1];   // cut at the last lag read
            }
            else
            {
                break;   // no window left in the data
            }
        }
        bool flat = true;
        for (last = k; last < n && times[last] <= end && flat; ++last)
        {
            flat = std::abs(I[last] - I[k]) <= settings.noiseMultiple * sigma[last];
        }
        if (flat)
        {
            plateau.first = k;
            plateau.last = last - 1;
            plateau.found = plateau.last > k;
        }
    }
    if (!plateau.found)
    {
        // The latest full window, from earliestTime on where that leaves two
        // lags (past the decay when the caller set it so): the best the data
        // can give, flagged.
        plateau.last = n - 1;
        plateau.first = n - 1;
        double begin = times[n - 1] / (1.0 + settings.windowFactor);
        if (settings.earliestTime > begin && settings.earliestTime < times[n - 1])
        {
            begin = settings.earliestTime;
        }
        while (plateau.first > 0 && times[plateau.first - 1] >= begin)
        {
            --plateau.first;
        }
        if (plateau.first == plateau.last && plateau.first > 0)
        {
            --plateau.first;
        }
    }
    plateau.value = windowMean(times, I, plateau.first, plateau.last);
    return plateau;
}

} // namespace

GreenKuboResult greenKubo
(
    const std::vector<double>& times,
    const std::vector<std::vector<double>>& blockCorrelations,
    const PlateauSettings& settings
)
{
    const std::size_t blocks = blockCorrelations.size();
    // The jackknife's leave-one-out sets need >= 2 blocks for their own noise.
    if (blocks < 3)
    {
        throw std::invalid_argument
        (
            "greenKubo: needs >= 3 independent blocks or replicas for an error "
            "(8 to 20 recommended), got " + std::to_string(blocks)
        );
    }
    const std::size_t n = times.size();
    for (const std::vector<double>& c : blockCorrelations)
    {
        if (c.size() != n)
        {
            throw std::invalid_argument("greenKubo: a block's correlation does not match the time grid");
        }
    }

    std::vector<std::vector<double>> blockIntegrals;
    blockIntegrals.reserve(blocks);
    for (const std::vector<double>& c : blockCorrelations)
    {
        blockIntegrals.push_back(runningIntegral(times, c));
    }

    GreenKuboResult result;
    result.times = times;
    result.meanCorrelation.resize(n);
    result.correlationError.resize(n);
    result.meanRunningIntegral.resize(n);
    result.runningIntegralError.resize(n);
    std::vector<double> column(blocks);
    for (std::size_t k = 0; k < n; ++k)
    {
        for (std::size_t b = 0; b < blocks; ++b)
        {
            column[b] = blockCorrelations[b][k];
        }
        const Estimate c = meanAndStandardError(column);
        for (std::size_t b = 0; b < blocks; ++b)
        {
            column[b] = blockIntegrals[b][k];
        }
        const Estimate i = meanAndStandardError(column);
        result.meanCorrelation[k] = c.value;
        result.correlationError[k] = c.standardError;
        result.meanRunningIntegral[k] = i.value;
        result.runningIntegralError[k] = i.standardError;
    }

    const Plateau all = findPlateau(times, blockIntegrals, allBlocks(blocks), settings);
    result.plateauTime = times[all.first];
    result.windowEnd = times[all.last];
    result.plateauFound = all.found;
    result.integral.value = all.value;
    result.integral.samples = blocks;

    // Jackknife over blocks of the whole procedure, plateau search included:
    // the plateau time is chosen from the same noisy data, and that choice
    // adds scatter which a block error at a fixed window would miss.
    double squares = 0.0;
    for (std::size_t left = 0; left < blocks; ++left)
    {
        std::vector<std::size_t> subset;
        for (std::size_t b = 0; b < blocks; ++b)
        {
            if (b != left)
            {
                subset.push_back(b);
            }
        }
        const Plateau jack = findPlateau(times, blockIntegrals, subset, settings);
        result.leaveOneOut.push_back(jack.value);
        squares += (jack.value - all.value) * (jack.value - all.value);
    }
    const double count = static_cast<double>(blocks);
    result.integral.standardError = std::sqrt((count - 1.0) / count * squares);
    return result;
}

GreenKuboResult greenKubo
(
    const std::vector<LaggedCorrelation>& blocks,
    double sampleInterval,
    int column,
    const PlateauSettings& settings
)
{
    if (blocks.empty())
    {
        throw std::invalid_argument("greenKubo: no blocks");
    }
    // Lags without pairs are dropped from the end of a block's grid, so the
    // common grid is the shortest block's.
    std::size_t lags = blocks.front().lags.size();
    for (const LaggedCorrelation& block : blocks)
    {
        lags = std::min(lags, block.lags.size());
        if (column < -1 || column >= block.values.cols())
        {
            throw std::invalid_argument
            (
                "greenKubo: column " + std::to_string(column) + " of "
              + std::to_string(block.values.cols())
            );
        }
    }
    std::vector<std::vector<double>> correlations;
    for (const LaggedCorrelation& block : blocks)
    {
        if (!std::equal(block.lags.begin(), block.lags.begin() + lags, blocks.front().lags.begin()))
        {
            throw std::invalid_argument("greenKubo: blocks have different lag grids");
        }
        std::vector<double> c = column < 0 ? block.columnMean() : block.column(column);
        c.resize(lags);
        correlations.push_back(std::move(c));
    }
    std::vector<double> times = blocks.front().times(sampleInterval);
    times.resize(lags);
    return greenKubo(times, correlations, settings);
}

} // namespace sdf::correlation

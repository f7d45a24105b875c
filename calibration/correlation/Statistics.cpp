#include "correlation/Statistics.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::correlation
{

Estimate meanAndStandardError(const std::vector<double>& samples)
{
    if (samples.empty())
    {
        throw std::invalid_argument("meanAndStandardError: no samples");
    }
    const double n = static_cast<double>(samples.size());
    double sum = 0.0;
    for (double x : samples)
    {
        sum += x;
    }
    const double mean = sum / n;
    double squares = 0.0;
    for (double x : samples)
    {
        squares += (x - mean) * (x - mean);
    }
    Estimate result;
    result.value = mean;
    result.samples = samples.size();
    result.standardError =
        samples.size() > 1 ? std::sqrt(squares / (n - 1.0) / n) : 0.0;
    return result;
}

IndexRange blockRange(std::size_t n, std::size_t blockCount, std::size_t block)
{
    if (blockCount == 0 || block >= blockCount || n < blockCount)
    {
        throw std::invalid_argument(
            "blockRange: cannot cut " + std::to_string(n) + " samples into "
            + std::to_string(blockCount) + " blocks (block "
            + std::to_string(block) + ")");
    }
    const std::size_t length = n / blockCount;
    return IndexRange{block * length, (block + 1) * length};
}

Estimate blockAverage(const std::vector<double>& series, std::size_t blockCount)
{
    std::vector<double> means;
    means.reserve(blockCount);
    for (std::size_t b = 0; b < blockCount; ++b)
    {
        const IndexRange range = blockRange(series.size(), blockCount, b);
        double sum = 0.0;
        for (std::size_t i = range.begin; i < range.end; ++i)
        {
            sum += series[i];
        }
        means.push_back(sum / static_cast<double>(range.size()));
    }
    return meanAndStandardError(means);
}

Estimate combineReplicas(const std::vector<Estimate>& replicas)
{
    std::vector<double> values;
    values.reserve(replicas.size());
    for (const Estimate& replica : replicas)
    {
        values.push_back(replica.value);
    }
    return meanAndStandardError(values);
}

Estimate inverseVarianceMean(const std::vector<Estimate>& estimates)
{
    if (estimates.empty())
    {
        throw std::invalid_argument("inverseVarianceMean: no estimates");
    }
    double weightSum = 0.0;
    double weightedSum = 0.0;
    std::size_t samples = 0;
    for (const Estimate& e : estimates)
    {
        if (!(e.standardError > 0.0))
        {
            throw std::invalid_argument(
                "inverseVarianceMean: every estimate needs a standard error > 0");
        }
        const double weight = 1.0 / (e.standardError * e.standardError);
        weightSum += weight;
        weightedSum += weight * e.value;
        samples += e.samples;
    }
    return Estimate{weightedSum / weightSum, std::sqrt(1.0 / weightSum), samples};
}

} // namespace sdf::correlation

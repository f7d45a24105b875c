#include "correlation/Statistics.hpp"

#include <gsl/gsl_cdf.h>

#include <cmath>
#include <cstdio>
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

AgreementOverCells agreementOverCells
(
    const std::vector<double>& z,
    double chiSquareLevel,
    double meanSigmas,
    double familyLevel
)
{
    if (z.size() < 2)
    {
        throw std::invalid_argument
        (
            "agreementOverCells: needs >= 2 cells, got " + std::to_string(z.size())
        );
    }
    for (const double v : z)
    {
        if (!std::isfinite(v))
        {
            throw std::invalid_argument("agreementOverCells: a z is not finite (a zero error?)");
        }
    }
    if (!(chiSquareLevel > 0 && chiSquareLevel < 1) || !(familyLevel > 0 && familyLevel < 1))
    {
        throw std::invalid_argument
        (
            "agreementOverCells: chiSquareLevel " + std::to_string(chiSquareLevel)
          + " and familyLevel " + std::to_string(familyLevel) + " must lie in (0, 1)"
        );
    }
    AgreementOverCells a;
    a.cells = z.size();
    const double dof = double(a.cells);
    for (const double v : z) a.chiSquare += v*v;
    a.chiSquareLow = gsl_cdf_chisq_Pinv(0.5*(1 - chiSquareLevel), dof);
    a.chiSquareHigh = gsl_cdf_chisq_Qinv(0.5*(1 - chiSquareLevel), dof);
    a.meanZ = meanAndStandardError(z);
    a.meanSigmas = meanSigmas;
    // per cell two-sided p with 1 - (1 - p)^n = familyLevel
    const double perCell = -std::expm1(std::log1p(-familyLevel)/dof);
    a.threshold = gsl_cdf_ugaussian_Qinv(0.5*perCell);
    for (std::size_t i = 0; i < z.size(); ++i)
    {
        if (std::abs(z[i]) > a.threshold) a.flagged.push_back(i);
    }
    return a;
}

std::string AgreementOverCells::summary() const
{
    char buf[256];
    std::snprintf
    (
        buf, sizeof buf,
        "%zu cells: chi2 %.1f in [%.1f, %.1f] %s; mean z %+.2f +- %.2f (%.1f of its errors,"
        " limit %g) %s; beyond %.2f: %zu %s",
        cells, chiSquare, chiSquareLow, chiSquareHigh, chiSquareInside() ? "yes" : "NO",
        meanZ.value, meanZ.standardError,
        meanZ.standardError > 0 ? std::abs(meanZ.value)/meanZ.standardError : 0.0, meanSigmas,
        meanWithin() ? "yes" : "NO", threshold, flagged.size(), flagged.empty() ? "yes" : "NO"
    );
    return buf;
}

} // namespace sdf::correlation

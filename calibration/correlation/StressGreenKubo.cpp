#include "correlation/StressGreenKubo.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::correlation
{

namespace
{

double ratioOfCrossToProducts(const StressProductIntegrals& r)
{
    double cross = 0.0, products = 0.0;
    for (std::size_t i = 0; i < r.seriesCount; ++i)
    {
        for (std::size_t j = 0; j < r.seriesCount; ++j)
        {
            (i == j ? products : cross) += std::abs(r.term(i, j).integral.value);
        }
    }
    return products > 0.0 ? cross / products : 0.0;
}

} // namespace

StressProductIntegrals stressProductIntegrals
(
    const std::vector<double>& times,
    const std::vector<SeriesProductCorrelations>& blocks,
    const PlateauSettings& settings
)
{
    if (blocks.empty())
    {
        throw std::invalid_argument("stressProductIntegrals: no blocks");
    }
    StressProductIntegrals result;
    result.seriesCount = blocks.front().seriesCount();
    for (std::size_t i = 0; i < result.seriesCount; ++i)
    {
        for (std::size_t j = 0; j < result.seriesCount; ++j)
        {
            std::vector<std::vector<double>> term;
            for (const SeriesProductCorrelations& block : blocks)
            {
                if (block.seriesCount() != result.seriesCount)
                {
                    throw std::invalid_argument("stressProductIntegrals: blocks differ in series count");
                }
                term.push_back(block(i, j));
            }
            result.terms.push_back(greenKubo(times, term, settings));
        }
    }
    std::vector<std::vector<double>> totals;
    for (const SeriesProductCorrelations& block : blocks)
    {
        totals.push_back(block.total());
    }
    result.total = greenKubo(times, totals, settings);
    result.crossToProductRatio = ratioOfCrossToProducts(result);
    return result;
}

StressProductIntegrals stressProductIntegrals
(
    const std::vector<LaggedCorrelation>& blocks,
    double sampleInterval,
    std::size_t seriesCount,
    const PlateauSettings& settings
)
{
    if (blocks.empty())
    {
        throw std::invalid_argument("stressProductIntegrals: no blocks");
    }
    for (const LaggedCorrelation& block : blocks)
    {
        if (block.values.cols() != static_cast<Eigen::Index>(seriesCount * seriesCount))
        {
            throw std::invalid_argument
            (
                "stressProductIntegrals: blocks have " + std::to_string(block.values.cols())
              + " columns, expected " + std::to_string(seriesCount * seriesCount)
            );
        }
    }
    StressProductIntegrals result;
    result.seriesCount = seriesCount;
    for (std::size_t c = 0; c < seriesCount * seriesCount; ++c)
    {
        result.terms.push_back(greenKubo(blocks, sampleInterval, static_cast<int>(c), settings));
    }
    // The total is the sum of the columns: the mean of the columns times S*S.
    GreenKuboResult mean = greenKubo(blocks, sampleInterval, -1, settings);
    const double factor = static_cast<double>(seriesCount * seriesCount);
    mean.integral.value *= factor;
    mean.integral.standardError *= factor;
    for (auto* v : {&mean.meanCorrelation, &mean.correlationError,
                    &mean.meanRunningIntegral, &mean.runningIntegralError})
    {
        for (double& x : *v)
        {
            x *= factor;
        }
    }
    result.total = std::move(mean);
    result.crossToProductRatio = ratioOfCrossToProducts(result);
    return result;
}

std::vector<LaggedCorrelation> aboutMeans
(
    std::vector<LaggedCorrelation> blocks,
    const std::vector<std::vector<double>>& blockMeans,
    const std::vector<double>& runMeans
)
{
    const std::size_t n = runMeans.size();
    if (blockMeans.size() != blocks.size())
    {
        throw std::invalid_argument
        (
            "aboutMeans: " + std::to_string(blocks.size()) + " blocks but "
          + std::to_string(blockMeans.size()) + " block means"
        );
    }
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        const std::vector<double>& mb = blockMeans[b];
        Eigen::ArrayXXd& values = blocks[b].values;
        if (mb.size() != n || values.cols() != static_cast<Eigen::Index>(n * n))
        {
            throw std::invalid_argument
            (
                "aboutMeans: block " + std::to_string(b) + " has " + std::to_string(mb.size())
              + " means and " + std::to_string(values.cols()) + " columns for "
              + std::to_string(n) + " series"
            );
        }
        const std::vector<double>& m = runMeans;
        for (std::size_t i = 0; i < n; ++i)
        {
            for (std::size_t j = 0; j < n; ++j)
            {
                values.col(static_cast<Eigen::Index>(i * n + j)) -=
                    m[i] * mb[j] + mb[i] * m[j] - m[i] * m[j];
            }
        }
    }
    return blocks;
}

namespace
{

//- Both rules of a binary mixture (series J^1, J^2, J^12): species s owns its
//  part, none of the other's and its composition share of J^12, and gets
//  each product integral I_ab by the mean of its two factors' shares; the
//  seed's rule takes the products of a part with itself only (a == b).
//  Errors: the terms' errors times their weights, in quadrature.
std::vector<Estimate> attributedCoefficients
(
    const StressProductIntegrals& integrals,
    const std::vector<double>& composition,
    bool keepCrossTerms,
    const char* who
)
{
    if (integrals.seriesCount != 3 || composition.size() != 2)
    {
        throw std::invalid_argument
        (
            std::string(who) + ": a binary mixture's rule: "
            "series (J^1, J^2, J^12) and two composition values"
        );
    }
    std::vector<Estimate> eta;
    for (std::size_t s = 0; s < 2; ++s)
    {
        const double share[3] = {s == 0 ? 1.0 : 0.0, s == 1 ? 1.0 : 0.0, composition[s]};
        double value = 0, variance = 0;
        for (std::size_t a = 0; a < 3; ++a)
        {
            for (std::size_t b = 0; b < 3; ++b)
            {
                if (!keepCrossTerms && a != b)
                {
                    continue;
                }
                const Estimate& term = integrals.term(a, b).integral;
                const double w = 0.5*(share[a] + share[b]);
                value += w*term.value;
                variance += w*w*term.standardError*term.standardError;
            }
        }
        eta.push_back(Estimate{value, std::sqrt(variance), integrals.term(s, s).integral.samples});
    }
    return eta;
}

} // namespace


std::vector<Estimate> kineticSievingCoefficients
(
    const StressProductIntegrals& integrals,
    const std::vector<double>& composition
)
{
    return attributedCoefficients(integrals, composition, false, "kineticSievingCoefficients");
}


std::vector<Estimate> kineticSievingCoefficientsWithCrossTerms
(
    const StressProductIntegrals& integrals,
    const std::vector<double>& composition
)
{
    return attributedCoefficients
    (
        integrals, composition, true, "kineticSievingCoefficientsWithCrossTerms"
    );
}

} // namespace sdf::correlation

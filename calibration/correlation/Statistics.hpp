// Statistical estimates with honest standard errors: block averaging of one
// trajectory and combination of independent replicas.
#ifndef sdf_correlation_Statistics_hpp
#define sdf_correlation_Statistics_hpp

#include <cstddef>
#include <cmath>
#include <string>
#include <vector>

namespace sdf::correlation
{

//- A value with its standard error and the number of independent samples
//  (blocks or replicas) the error was estimated from.
struct Estimate
{
    double value = 0.0;
    double standardError = 0.0;
    std::size_t samples = 0;
};

//- Mean and standard error of the mean of independent samples
//  (standard error = sample standard deviation / sqrt(n); 0 for n = 1).
Estimate meanAndStandardError(const std::vector<double>& samples);

//- Mean of a correlated time series with the standard error from the scatter
//  of blockCount contiguous block means (a trailing remainder shorter than a
//  block is dropped so that all blocks have equal weight). The blocks must be
//  longer than the correlation time for the error to be honest.
Estimate blockAverage(const std::vector<double>& series, std::size_t blockCount);

//- Half-open index range [begin, end) of block b when n samples are cut into
//  blockCount equal contiguous blocks (remainder dropped at the end).
struct IndexRange
{
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
};
IndexRange blockRange(std::size_t n, std::size_t blockCount, std::size_t block);

//- perRange(begin, end) evaluated on each of the blockCount equal contiguous
//  blocks of n samples (blockRange), in block order
template<class PerRange>
auto forEachBlock(std::size_t n, std::size_t blockCount, PerRange perRange)
    -> std::vector<decltype(perRange(std::size_t(0), std::size_t(0)))>
{
    std::vector<decltype(perRange(std::size_t(0), std::size_t(0)))> results;
    results.reserve(blockCount);
    for (std::size_t b = 0; b < blockCount; ++b)
    {
        const IndexRange range = blockRange(n, blockCount, b);
        results.push_back(perRange(range.begin, range.end));
    }
    return results;
}

//- Combine estimates from independent replicas: mean of the values and the
//  standard error from their spread (does not trust the replicas' own errors;
//  needs >= 2 replicas for a non-zero error).
Estimate combineReplicas(const std::vector<Estimate>& replicas);

//- Inverse-variance weighted mean of independent estimates, trusting their
//  reported errors (all standard errors must be > 0).
Estimate inverseVarianceMean(const std::vector<Estimate>& estimates);

//- Two estimators of one quantity compared over many cells by their normalised
//  differences z = (a - b)/sigma(a - b), one per cell. A per-cell test at 2 sigma
//  fails somewhere by chance once there are a few dozen cells, so the judgement is
//  over the whole set: (1) sum z^2 inside its central chiSquareLevel interval for
//  `cells` degrees of freedom (the errors are honest), (2) the mean z within
//  meanSigmas of its standard error (sample sd/sqrt(n)) of zero (no bias common to
//  the cells), (3) no |z| beyond the threshold at which one of `cells` independent
//  normal z exceeds it with probability familyLevel (Sidak: 3.19 at 36 cells, 2.73
//  at 8).
struct AgreementOverCells
{
    std::size_t cells = 0;
    double chiSquare = 0;
    double chiSquareLow = 0, chiSquareHigh = 0;   // its interval
    Estimate meanZ;
    double meanSigmas = 0;
    double threshold = 0;                         // |z| that flags a cell
    std::vector<std::size_t> flagged;             // indices of z beyond it

    bool chiSquareInside() const { return chiSquare >= chiSquareLow && chiSquare <= chiSquareHigh; }
    bool meanWithin() const { return std::abs(meanZ.value) <= meanSigmas*meanZ.standardError; }
    bool passes() const { return chiSquareInside() && meanWithin() && flagged.empty(); }
    //- "chi2 34.9 in [17.9, 61.6]; mean z +0.50 +- 0.14 (3.6 of its errors, limit 3);
    //  beyond 3.19: 1"
    std::string summary() const;
};

//- Needs >= 2 finite z; throws std::invalid_argument otherwise or for levels
//  outside (0, 1).
AgreementOverCells agreementOverCells
(
    const std::vector<double>& z,
    double chiSquareLevel = 0.99,
    double meanSigmas = 3.0,
    double familyLevel = 0.05
);

} // namespace sdf::correlation

#endif

#include "CellStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sdf::dem
{

// ---------------------------------------------------------------- StressSplit

Eigen::Matrix3d StressSplit::speciesStress(int s) const
{
    return kinetic[s] + configurational[speciesPairIndex(s, s, nSpecies)];
}

Eigen::Matrix3d StressSplit::crossStress(int s, int t) const
{
    return configurational[speciesPairIndex(s, t, nSpecies)];
}

Eigen::Matrix3d StressSplit::sum() const
{
    Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
    for (int s = 0; s < nSpecies; ++s) total += speciesStress(s);
    for (int s = 0; s < nSpecies; ++s)
    {
        for (int t = s + 1; t < nSpecies; ++t) total += crossStress(s, t);
    }
    return total;
}

// ---------------------------------------------------------------- CollisionStatistics

void CollisionStatistics::reset(int n, double eMin, double eMax, int nBins)
{
    if (!(eMin > 0 && eMax > eMin && nBins > 0))
    {
        throw std::invalid_argument("collision histogram: need 0 < eMin < eMax and nBins > 0");
    }
    nSpecies = n;
    binEdges.resize(nBins + 1);
    for (int b = 0; b <= nBins; ++b)
    {
        binEdges[b] = eMin*std::pow(eMax/eMin, double(b)/nBins);
    }
    clearCounts();
}

void CollisionStatistics::clearCounts()
{
    const int nPairs = numberOfSpeciesPairs(nSpecies);
    counts.assign(nPairs, 0);
    energySum.assign(nPairs, 0.0);
    histogram.assign(nPairs, std::vector<long>(binEdges.empty() ? 0 : binEdges.size() + 1, 0));
    elapsedTime = 0;
}

double CollisionStatistics::frequencyPerParticle
(
    int s, int t, const std::vector<int>& speciesCounts
) const
{
    if (elapsedTime <= 0 || speciesCounts[s] == 0) return 0;
    const double c = double(counts[speciesPairIndex(s, t, nSpecies)]);
    // a collision within species s involves two particles of s
    const double involved = (s == t) ? 2*c : c;
    return involved/(elapsedTime*speciesCounts[s]);
}

} // namespace sdf::dem

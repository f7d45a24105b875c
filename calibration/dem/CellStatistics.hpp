#ifndef sdf_dem_CellStatistics_hpp
#define sdf_dem_CellStatistics_hpp

// What a cell measures of its contacts: the per-species split of the microscopic stress
// and the collision counts with their impact-energy histograms.

#include "Species.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace sdf::dem
{

//- Per-species microscopic stress J (seed eqs 9-13, not divided by volume):
//  kinetic[s] = sum_{i in s} m_i c_i c_i^T
//  configurational[pair(s,t)] = sum_{contacts (i,j), species {s,t}} F_ij r_ij^T
//  (entry (a,b) = F_a r_b; F_ij on i from j, r_ij = x_i - x_j; repulsion gives J_aa > 0)
struct StressSplit
{
    int nSpecies = 0;
    std::vector<Eigen::Matrix3d> kinetic;
    std::vector<Eigen::Matrix3d> configurational;

    //- J^s = kinetic[s] + configurational[(s,s)]
    Eigen::Matrix3d speciesStress(int s) const;
    //- J^{st}, s != t (configurational only)
    Eigen::Matrix3d crossStress(int s, int t) const;
    //- Sum of all parts (eq 13)
    Eigen::Matrix3d sum() const;
};

//- Collision counts and impact-energy histograms per unordered species pair.
//  Impact energy: 0.5 m* v_n^2 at the first step of a contact (normal, centre-of-mass frame).
struct CollisionStatistics
{
    int nSpecies = 0;
    std::vector<double> binEdges;            // nBins + 1 edges [J], log-spaced
    std::vector<long> counts;                // per species pair
    std::vector<std::vector<long>> histogram;// per species pair: nBins + 2 (under, bins, over)
    std::vector<double> energySum;           // per species pair [J]
    double elapsedTime = 0;                  // [s] time over which collisions were counted

    void reset(int nSpecies, double eMin, double eMax, int nBins);
    void clearCounts();
    //- Histogram slot of impact energy e: 0 below the first edge, bins, last above.
    int bin(double e) const
    {
        if (e < binEdges.front()) return 0;
        if (e >= binEdges.back()) return int(binEdges.size());
        return int(std::upper_bound(binEdges.begin(), binEdges.end(), e) - binEdges.begin());
    }
    //- Collisions per unit time of one particle of species s with particles of species t.
    double frequencyPerParticle(int s, int t, const std::vector<int>& speciesCounts) const;
};

} // namespace sdf::dem

#endif

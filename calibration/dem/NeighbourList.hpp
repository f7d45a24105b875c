#ifndef sdf_dem_NeighbourList_hpp
#define sdf_dem_NeighbourList_hpp

// Verlet pair list with a skin, built from linked cells of width >= 2 R_max + skin.
// A pair (i < j) is listed when its gap is below the skin, so for size ratios 2-4 the list
// holds only plausible partners even though the cells are sized by the largest particle.
// Pairs are ordered by (i, j): the order, and hence every reduction over it, is fixed
// for a given configuration whatever the number of threads.

#include "Particles.hpp"
#include "PeriodicBox.hpp"

#include <array>
#include <vector>

namespace sdf::dem
{

class NeighbourList
{
public:
    //- Builds the list; throws std::invalid_argument when the box is thinner than
    //  2 (2 R_max + skin) in any direction (minimum image would not be unique).
    //  nThreads: OpenMP threads for the build (0: runtime default).
    void build(const Particles& particles, const PeriodicBox& box, double skin, int nThreads = 0);

    std::size_t size() const { return first_.size(); }
    const std::vector<int>& first() const { return first_; }
    const std::vector<int>& second() const { return second_; }


    double cutoff() const { return cutoff_; }

    //- Reinstates a pair list from a checkpoint (only used to carry contact histories
    //  over at the next build()).
    void restorePairs(std::vector<int> first, std::vector<int> second)
    {
        first_ = std::move(first);
        second_ = std::move(second);
    }
    long builds() const { return builds_; }

private:
    std::vector<int> first_, second_;
    std::vector<int> cellStart_, cellParticles_, particleCell_;
    std::vector<int> stencilStart_, stencilCells_;          // neighbour cells per cell
    std::vector<std::array<double, 4>> cellPosition_;       // x, y, z, r in cell order
    // per-thread pairs (own cache lines: the threads append to them)
    std::vector<CacheLinePadded<std::vector<int>>> firstLocal_, secondLocal_;
    double cutoff_ = 0;
    long builds_ = 0;
};

} // namespace sdf::dem

#endif

#ifndef sdf_dem_tests_TestCells_hpp
#define sdf_dem_tests_TestCells_hpp

// Small cells shared by the DEM tests.
#include "InitialState.hpp"
#include "Simulation.hpp"

#include <cstring>

namespace sdf::dem::test
{

inline std::vector<Species> binary(double ratio = 2.0)
{
    return {{"fine", 1e-3, 2500}, {"coarse", ratio*1e-3, 2500}};
}

inline std::vector<Species> mono()
{
    return {{"glass", 1e-3, 2500}};
}

//- Relaxed packing with Maxwellian velocities (plus the shear profile if shearRate != 0).
inline Packing packedCell
(
    const std::vector<Species>& species,
    const std::vector<int>& counts,
    double phi,
    double temperature,
    double shearRate = 0,
    std::uint64_t seed = 7
)
{
    PackingSettings ps;
    ps.solidsFraction = phi;
    ps.counts = counts;
    ps.seed = seed;
    Packing packing = makePacking(species, ps);
    assignVelocities(packing.particles, packing.box, temperature, shearRate, seed);
    return packing;
}

inline double totalEnergy(const Simulation& sim)
{
    return sim.translationalKineticEnergy() + sim.rotationalKineticEnergy() + sim.elasticEnergy();
}

//- Same size and the same bits.
template<class Allocator>
bool bitwiseEqual(const std::vector<double, Allocator>& a, const std::vector<double, Allocator>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size()*sizeof(double)) == 0;
}

} // namespace sdf::dem::test

#endif

#ifndef sdf_dem_tests_TestCells_hpp
#define sdf_dem_tests_TestCells_hpp

// Small cells shared by the DEM tests.
#include "InitialState.hpp"
#include "Simulation.hpp"

#include <cstring>
#include <string>

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

//- Linear spring-dashpot contacts of k_n = 2e3 N/m (t_c ~ 6e-5 s for mm grains, overlaps
//  well below 1 % of d at the tests' speeds) on one thread, not driven (nve).
inline SimulationSettings softContacts(double restitution, double friction)
{
    SimulationSettings s;
    s.contact.restitution = restitution;
    s.contact.friction = friction;
    s.contact.normalStiffness = 2e3;
    s.threads = 1;
    return s;
}

//- softContacts in a Lees-Edwards cell sheared at shearRate.
inline SimulationSettings shearedCell(double shearRate, double restitution, double friction)
{
    SimulationSettings s = softContacts(restitution, friction);
    s.mode = CellMode::leesEdwards;
    s.shearRate = shearRate;
    return s;
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

//- The message of the Exception f() throws ("wrong exception type", "no exception"
//  otherwise): refusal tests match a part of it.
template<class Exception, class F>
std::string messageOf(F&& f)
{
    try
    {
        f();
    }
    catch (const Exception& err)
    {
        return err.what();
    }
    catch (...)
    {
        return "wrong exception type";
    }
    return "no exception";
}

inline bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace sdf::dem::test

#endif

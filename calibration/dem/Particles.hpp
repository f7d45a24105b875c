#ifndef sdf_dem_Particles_hpp
#define sdf_dem_Particles_hpp

// Structure-of-arrays particle storage: each quantity is one contiguous array so that the
// hot loops stream through memory and vectorise.

#include "CacheLine.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdf::dem
{

//- One per-particle quantity (cache-line aligned).
using ParticleArray = std::vector<double, CacheLineAllocator<double>>;
//- Doubles in one cache line: thread ranges start at multiples of it.
constexpr int particlesPerCacheLine = int(CacheLineAllocator<double>::alignment/sizeof(double));

struct Particles
{
    // full-step positions, wrapped into the periodic box
    ParticleArray x, y, z;
    // unwrapped displacement since the start (for mean-square displacements); peculiar:
    // under Lees-Edwards shear x excludes the streaming (the non-affine displacement)
    ParticleArray ux, uy, uz;
    // velocities (lab frame; Lees-Edwards: including the streaming velocity)
    ParticleArray vx, vy, vz;
    // angular velocities
    ParticleArray wx, wy, wz;
    // forces and torques of the last evaluation
    ParticleArray fx, fy, fz;
    ParticleArray tx, ty, tz;
    ParticleArray radius, mass, inertia, invMass, invInertia;
    std::vector<int> species;
    // stable identity: the particle's index when the Simulation started (a simulation that
    // renumbers its particles spatially keeps it; Simulation::indexOfId maps it back)
    std::vector<int> id;

    std::size_t size() const { return x.size(); }

    void resize(std::size_t n);

    //- Appends one particle at rest.
    void add(double px, double py, double pz, double r, double m, int speciesId);

    //- Sets radius and derived mass and moment of inertia (solid sphere) from density.
    void setRadius(std::size_t i, double r, double density);

    //- Renumbers the particles: new particle k is old particle order[k] (a permutation);
    //  ids travel with their particles.
    void reorder(const std::vector<int>& order);
};

} // namespace sdf::dem

#endif

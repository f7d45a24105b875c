#ifndef sdf_dem_InitialState_hpp
#define sdf_dem_InitialState_hpp

// Initial states: random insertion at reduced radii, then radii grown while a damped,
// frictionless relaxation removes the overlaps (Lubachevsky-Stillinger-like growth), until
// the target solids fraction is reached with overlaps below a tolerance.

#include "Particles.hpp"
#include "PeriodicBox.hpp"
#include "Species.hpp"

#include <cstdint>
#include <random>
#include <vector>

namespace sdf::dem
{

//- Highest accepted solids fraction (random close packing of spheres ~0.64).
constexpr double jammingSolidsFraction = 0.64;

struct PackingSettings
{
    double solidsFraction = 0.3;       // phi
    std::vector<int> counts;           // particles per species
    std::uint64_t seed = 1;
    double overlapTolerance = 2e-3;    // final max overlap / smaller diameter
    long maxSteps = 400000;            // relaxation step budget
    double heightRatio = 1;            // ly/lx of the box (lz = lx): 1 a cube; a wall-bounded
                                       // cell cut from a packing wants it tall
    bool verbose = false;
};

struct Packing
{
    Particles particles;
    PeriodicBox box;
    long relaxationSteps = 0;
    double maxOverlapFraction = 0;
};

//- Throws std::invalid_argument naming the entry for phi outside (0, 0.64], no particles.
void validatePackingSettings(const std::vector<Species>& species, const PackingSettings& s);

//- Particle counts per species for a total N and solids volume fractions of each species
//  (fractions of the solids volume, summing to 1; e.g. coarse fraction x of a binary mix).
std::vector<int> countsFromVolumeFractions
(
    const std::vector<Species>& species,
    const std::vector<double>& volumeFractions,
    int nTotal
);

//- Periodic box (a cube, or ly = heightRatio lx) at the requested phi with particles at rest, overlaps relaxed.
Packing makePacking(const std::vector<Species>& species, const PackingSettings& settings);

//- How the initial fluctuating energy is shared between particles of different mass.
enum class VelocityPartition
{
    equalVelocities,    //- every particle's velocity from the same Maxwellian
    equipartition       //- each particle's <|c|^2> inversely proportional to its mass
};

//- Maxwellian fluctuating velocities with <|c|^2> = T over all particles (T1 = T/3 per
//  component), zero total momentum, plus the Lees-Edwards streaming profile
//  shearRate (y - ly/2) in x. With equipartition the heavier particles move slower (each
//  species' <|c|^2> exactly inversely proportional to its mass; a one-particle species
//  stays at rest): a stochastically driven cell starts there, because its kicks can add
//  energy but not remove it, and from equal velocities the collisions' exchange towards
//  equipartition raises the number-averaged T of a binary 1:2 cell up to 1.7 times with
//  no energy added, which a nearly elastic cell loses only slowly.
void assignVelocities
(
    Particles& particles,
    const PeriodicBox& box,
    double temperature,
    double shearRate,
    std::uint64_t seed,
    VelocityPartition partition = VelocityPartition::equalVelocities
);

//- Portable random numbers (std distributions differ between standard libraries).
class RandomStream
{
public:
    explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return double(engine_() >> 11)*0x1.0p-53; }   // [0, 1)
    double normal();
private:
    std::mt19937_64 engine_;
    bool hasSpare_ = false;
    double spare_ = 0;
};

} // namespace sdf::dem

#endif

#ifndef sdf_dem_Driving_hpp
#define sdf_dem_Driving_hpp

// How a periodic cell is driven: plain Newtonian dynamics, a thermostat that holds the
// granular temperature of a homogeneous cell, or Lees-Edwards simple shear. A driving
// policy says what the particles' fluctuations are measured from (its velocity reference),
// may collect sums in the force pass's finish (per particle range, while the final
// velocities are in cache) and acts after each step. It is picked once, before the first
// step; its hooks run once per step or per thread range, never per pair.
//
// A new driving, two routes (docs/developer/add-a-dem-contact-law-or-driving.md):
//  - outside the library: a class derived from Driving, handed to the Simulation with
//    Simulation::setDriving before the first step (nothing here changes);
//  - selectable by name: also an enumerator in CellMode (with its names in
//    cellModeFromName/cellModeName), its settings in SimulationSettings and one case in
//    Driving::New.

#include "Particles.hpp"

#include <memory>
#include <string>
#include <vector>

namespace sdf::dem
{

//- The built-in drivings, selectable by name (a driving written outside the library has none).
enum class CellMode
{
    nve,            // plain Newtonian dynamics (energy conserved if elastic and frictionless)
    thermostatted,  // homogeneous cell held at a target granular temperature
    leesEdwards     // simple shear at a prescribed rate, T is an output
};

CellMode cellModeFromName(const std::string& name);
std::string cellModeName(CellMode mode);

class Driving
{
public:
    //- Particles per chunk: the finish ranges are whole chunks (sums per fixed chunk, added
    //  in chunk order, are the same whatever the threads).
    static constexpr int finishChunk = 64;

    //- The driving of mode; throws std::invalid_argument naming the entry (a thermostat
    //  needs targetTemperature > 0, a sheared cell a finite shearRate).
    static std::unique_ptr<Driving> New
    (
        CellMode mode,
        double targetTemperature,
        double thermostatTime,
        double shearRate,
        double timeStep
    );

    virtual ~Driving() = default;

    //- Name written in messages and outputs (the built-ins: cellModeName of their mode).
    virtual std::string name() const = 0;

    // --- velocity reference
    //- Shear rate of the streaming profile the periodic box carries (Lees-Edwards images,
    //  streaming velocity gammaDot (y - ly/2) in x); 0: none.
    virtual double shearRate() const { return 0; }
    //- True: a particle's fluctuation is its velocity minus the streaming velocity at its
    //  y, and no mean velocity is removed; false: the velocity itself, and the
    //  temperature and stresses are taken about the mass-weighted mean velocity.
    virtual bool aboutStreamingVelocity() const { return false; }

    // --- the force pass's finish (second half kick)
    //- Before a force pass; endsStep: the pass finishes the step's velocities particle by
    //  particle. Returns whether finishRange wants the final velocities.
    virtual bool beginForcePass(int /*nParticles*/, bool /*endsStep*/) { return false; }
    //- Particles [begin, end), whole chunks but maybe the last, with their final
    //  velocities; the ranges of different threads are disjoint.
    virtual void finishRange(const Particles& /*particles*/, int /*begin*/, int /*end*/) {}

    // --- after the step
    virtual void afterStep(Particles& /*particles*/, int /*nThreads*/) {}
};

//- No driving: Newtonian dynamics of the cell.
class NoDriving : public Driving
{
public:
    std::string name() const override { return cellModeName(CellMode::nve); }
};

//- Weak-coupling (Berendsen-type) velocity rescaling: after each step the fluctuating
//  translational velocities of all particles are scaled by one factor, so that T relaxes to
//  the target over tau_T while inelastic collisions keep removing energy; the mean velocity
//  and the species' temperature ratio (non-equipartition) are left to the dynamics.
class VelocityRescalingThermostat : public Driving
{
public:
    VelocityRescalingThermostat(double targetTemperature, double relaxationTime, double timeStep);

    std::string name() const override { return cellModeName(CellMode::thermostatted); }
    bool beginForcePass(int nParticles, bool endsStep) override;
    void finishRange(const Particles& particles, int begin, int end) override;
    void afterStep(Particles& particles, int nThreads) override;

private:
    //- Per chunk: mass, mass x velocity, velocity, |velocity|^2.
    struct ChunkSums { static constexpr int size = 8; double value[size]; };

    double targetTemperature_;
    double relaxationTime_;
    double timeStep_;
    std::vector<ChunkSums> chunkSums_;
    bool sumsReady_ = false;   // filled by the last force pass's finish
};

//- Simple shear by Lees-Edwards images: the box carries the streaming profile, the cell's
//  temperature is an output.
class LeesEdwardsShear : public Driving
{
public:
    explicit LeesEdwardsShear(double shearRate) : shearRate_(shearRate) {}

    std::string name() const override { return cellModeName(CellMode::leesEdwards); }
    double shearRate() const override { return shearRate_; }
    bool aboutStreamingVelocity() const override { return true; }

private:
    double shearRate_;
};

} // namespace sdf::dem

#endif

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
//    Driving::New (StochasticDriving.hpp is one, in its own files).

#include "Particles.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sdf::dem
{

//- The built-in drivings, selectable by name (a driving written outside the library has none).
enum class CellMode
{
    nve,            // plain Newtonian dynamics (energy conserved if elastic and frictionless)
    thermostatted,  // homogeneous cell held at a target granular temperature (rescaling)
    leesEdwards,    // simple shear at a prescribed rate, T is an output
    stochastic      // homogeneous cell held at a target T by random kicks per particle
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
    //  needs targetTemperature > 0, a sheared cell a finite shearRate). seed: the
    //  stochastic driving's random numbers.
    static std::unique_ptr<Driving> New
    (
        CellMode mode,
        double targetTemperature,
        double thermostatTime,
        double shearRate,
        double timeStep,
        std::uint64_t seed = 1
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

    //- A speed the driving gives the particles [m/s] (0: none beyond the settings' target
    //  T and shear): the blow-up check's reference energy includes 1/2 M scale^2, so a
    //  driving that feeds a mean flow does not trip it (Simulation::setDriving).
    virtual double velocityScale() const { return 0; }

    // --- the force pass's finish (second half kick)
    //- Before a force pass; endsStep: the pass finishes the step's velocities particle by
    //  particle. Returns whether finishRange wants the final velocities.
    virtual bool beginForcePass(int /*nParticles*/, bool /*endsStep*/) { return false; }
    //- Particles [begin, end), whole chunks but maybe the last, with their final
    //  velocities; the ranges of different threads are disjoint.
    virtual void finishRange(const Particles& /*particles*/, int /*begin*/, int /*end*/) {}

    // --- the contacts' elastic energy, for a driving that balances energy
    //- Whether the coming afterStep wants the contacts' elastic energy (asked every step,
    //  so that a driving wanting it on some steps only leaves the others free of its pass)
    virtual bool wantsElasticEnergy() const { return false; }
    //- The elastic energy of the contacts (and walls) at the end of the step [J], given
    //  just before afterStep when wantsElasticEnergy()
    virtual void setElasticEnergy(double /*energy*/) {}

    // --- after the step
    virtual void afterStep(Particles& /*particles*/, int /*nThreads*/) {}

    // --- state for a bitwise resume (SimulationState::driving)
    virtual std::vector<double> exportState() const { return {}; }
    //- Throws std::invalid_argument for a state this driving did not export.
    virtual void importState(const std::vector<double>& state);
};

//- Sums over the particles per fixed chunk of Driving::finishChunk, added in chunk order
//  (the same totals whatever the threads): mass, mass x velocity, velocity, |velocity|^2,
//  mass x |velocity|^2.
//  Filled by the force pass's finish while the velocities are in cache, or afterwards.
class VelocityChunkSums
{
public:
    static constexpr int size = 9;
    using Totals = std::array<double, size>;

    //- As Driving::beginForcePass: true when the pass ends the step (fill then).
    bool begin(int nParticles, bool endsStep);
    //- Particles [begin, end), whole chunks but maybe the last.
    void addRange(const Particles& particles, int begin, int end);
    //- The totals of the step's final velocities (summed now if the pass did not).
    Totals totals(const Particles& particles);
    //- The totals of particles' velocities as they are now.
    static Totals sum(const Particles& particles);

private:
    std::vector<Totals> chunks_;
    bool ready_ = false;
};

//- T = <|v - u|^2> (sum of 3 components) of n particles about their mass-weighted mean
//  velocity u (written to u), from VelocityChunkSums' totals; 0 without mass.
double temperatureAboutMean(const VelocityChunkSums::Totals& total, int n, double u[3]);

//- K = 1/2 sum m |v - u|^2 about the mass-weighted mean velocity u, from the same totals.
double kineticEnergyAboutMean(const VelocityChunkSums::Totals& total);

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
    double targetTemperature_;
    double relaxationTime_;
    double timeStep_;
    VelocityChunkSums sums_;
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

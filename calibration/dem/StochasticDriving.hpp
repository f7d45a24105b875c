#ifndef sdf_dem_StochasticDriving_hpp
#define sdf_dem_StochasticDriving_hpp

// Local stochastic driving: every particle receives, after each step, an independent
// Gaussian velocity kick (a white-noise acceleration of the same strength for every
// particle, as the stochastic thermostat of the kinetic theory of driven granular gases:
// van Noije & Ernst 1998, Granular Matter 1, 57; Garzo & Montanero 2004, Phys. Rev. E 69,
// 021301), with the kicks' total momentum removed. The global velocity-rescaling
// thermostat scales every velocity by one factor and so feeds any collective motion the
// inelastic collisions start; independent kicks do not.
//
// The kicks' variance is steered, slowly, to hold the target T: a2 per component and step
// = (c T0^(3/2) + (T0 - T) dt/tau)/3, c = <L>/<T^(3/2)> from the dissipation per step L,
// averaged over all kick intervals so far, then exponentially over tau, and divided by the
// share of the kicks' energy their momentum removal keeps (1 - 2/n + sum m^2/M^2).
// L is the fall, over a kick interval and per step, of Theta = T (1 + E_el/K): T with the
// contacts' elastic energy E_el counted in at the present ratio T/K (K the peculiar
// kinetic energy). At steady state E_el is about the same at consecutive kicks and T/K
// fixed, so L is the fall of T, the controlled variable (a fall of K + E_el converted to
// T would not be: in a mixture the kicks and the collisions move T and K in different
// ratios, and T settled 1.5 % high at restitution 0.1).
// The fall of T alone also counts the energy the contacts store: a cell started without
// contacts stores up to 20 % of its kinetic energy in them over its first 60 steps at soft
// springs, and the kicks put that back as if dissipated, which an almost elastic cell
// (restitution 0.99) loses only at its slow collisional cooling rate (with the start at
// equal velocities, InitialState.hpp, it sat at 1.8 T0 after 14000 steps;
// calibration/tests/test_extremes.cpp). E_el costs a pass over the contacts once per kick
// interval (Driving::wantsElasticEnergy). At steady state the mean T is within 0.3-0.6 %
// of T0 at restitution 0.1-0.8 (test_stochastic_driving, test_extremes; the kicks' own
// increment, 10 L, is 6e-4 of T in the dense cell of benchmarks/demDriving), within 3 %
// at 0.99 (the cell's own drift, which only dissipation takes back), the amplitude
// constant to fluctuations of relative order sqrt(dt/tau). tau (thermostatTime) defaults
// to 1000 dt for this driving: set it to several collision times for a white noise of
// steady strength.
//
// The kicks come every kickInterval (10) steps, with the variance of as many: the time
// step is at most a fiftieth of a contact's duration, so they still come five times in
// the shortest contact and many times per collision time (a white noise on the scale of
// the collisions), at a tenth of the cost of the random numbers (a kick every step cost
// 3-5 times the force pass of a dense 300-particle cell).
//
// Random numbers: Philox4x64-10 (Random123, Salmon et al. 2011) keyed on (seed, a
// constant) with the counter (kick, particle id), normal deviates by Box-Muller: a
// particle's kicks depend on nothing but the seed, the step and its id, so the
// trajectories stay independent of the number of threads and of the renumbering. The
// kicks' momentum and the temperatures are summed per fixed chunk of particles in chunk
// order.

#include "Driving.hpp"

#include <cstdint>
#include <vector>

namespace sdf::dem
{

class StochasticDriving : public Driving
{
public:
    //- Throws std::invalid_argument naming the entry: targetTemperature > 0,
    //  thermostatTime > timeStep > 0.
    StochasticDriving
    (
        double targetTemperature,
        double steeringTime,
        double timeStep,
        std::uint64_t seed
    );

    std::string name() const override { return cellModeName(CellMode::stochastic); }
    bool beginForcePass(int nParticles, bool endsStep) override;
    void finishRange(const Particles& particles, int begin, int end) override;
    bool wantsElasticEnergy() const override;
    void setElasticEnergy(double energy) override { elasticEnergy_ = energy; }
    void afterStep(Particles& particles, int nThreads) override;
    std::vector<double> exportState() const override;
    void importState(const std::vector<double>& state) override;

    //- Steps between kicks.
    static constexpr int kickInterval = 10;

    //- The exported state's format (its last value): 2 since the steering counts the
    //  contacts' elastic energy (a state of 7 values, format 1, is refused).
    static constexpr int stateFormat = 2;

    //- The kicks' variance per component of the last kick [m^2/s^2] (0 before the first).
    double kickVariance() const { return kickVariance_; }

    //- The three standard normal deviates of particle id at kick number kick (the kicks
    //  before scaling and momentum removal): the counter-based stream, exposed for tests.
    static void normals(std::uint64_t seed, std::uint64_t kick, std::uint64_t id, double out[3]);

private:
    //- The step being driven (step_ + 1 of the steps so far) ends with kicks.
    bool kicksThisStep() const;

    double targetTemperature_;
    double steeringTime_;
    double timeStep_;
    std::uint64_t seed_;

    // steering state (exported for a bitwise resume)
    std::uint64_t step_ = 0;            // steps driven
    double dissipation_ = 0;            // <L>: fall of Theta per step, averaged over tau
    double temperaturePower_ = 0;       // <T^(3/2)> at the same kicks
    double heldAfterKick_ = -1;         // Theta just after the last kicks (< 0: none yet)
    double kickVariance_ = 0;

    double elasticEnergy_ = 0;          // E_el at the end of this step (kick steps)

    VelocityChunkSums sums_;
    std::vector<double> normalX_, normalY_, normalZ_;   // the kick's normals (scratch)
};

} // namespace sdf::dem

#endif

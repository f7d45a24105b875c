// The DEM at the extremes of its contact parameters and of its time step (the solver's
// extremes are tests/solver/extremes.sh; the table of both is in docs/validation.md):
// - restitution 0.1 and 0.99 with friction 0 and 1: a stochastically driven binary cell
//   keeps its momentum, every coordinate finite, overlaps small and the spin bounded (no
//   energy created by the tangential springs), and is held at the target T: its time
//   average within 1 % at restitution 0.1, within 5 % at 0.99. Started as a cell run
//   starts a stochastically driven cell (at equipartition, InitialState.hpp) and steered
//   on the energy it holds, kinetic and elastic (StochasticDriving.hpp); before both, a
//   cell started at equal velocities sat at 1.81 T0 at restitution 0.99 after 14000 steps;
// - the time step at the stability limit runs and conserves the energy of an elastic,
//   frictionless cell; above it, it is refused naming timeStep and the limit.
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <string>
#include <tuple>

using namespace sdf::dem;

namespace
{

bool allFinite(const Particles& p)
{
    for (const auto* v : {&p.x, &p.y, &p.z, &p.vx, &p.vy, &p.vz, &p.wx, &p.wy, &p.wz})
    {
        for (double a : *v)
        {
            if (!std::isfinite(a)) return false;
        }
    }
    return true;
}

class ContactExtremes : public testing::TestWithParam<std::tuple<double, double>> {};

} // namespace

TEST_P(ContactExtremes, DrivenCellHeldAtTargetFiniteAndBounded)
{
    const auto [restitution, friction] = GetParam();
    const auto species = test::binary(2.0);
    const double target = 0.02;
    // started as a cell run starts a stochastically driven cell: at equipartition
    PackingSettings ps;
    ps.solidsFraction = 0.3;
    ps.counts = {300, 40};
    ps.seed = 17;
    Packing packing = makePacking(species, ps);
    assignVelocities
    (
        packing.particles, packing.box, target, 0, 17, VelocityPartition::equipartition
    );
    SimulationSettings s = test::softContacts(restitution, friction);
    s.mode = CellMode::stochastic;
    s.targetTemperature = target;
    s.seed = 3;
    s.threads = 2;
    Simulation sim(species, s, packing.particles, packing.box);
    const Eigen::Vector3d p0 = sim.totalMomentum();

    sim.run(6000);      // several steering times (1000 dt)
    double sumT = 0, maxOverlap = 0, maxSpinRatio = 0;
    int samples = 0;
    sim.run
    (
        8000,
        [&](const Simulation& x)
        {
            sumT += x.temperature();
            maxOverlap = std::max(maxOverlap, x.maximumOverlapFraction());
            maxSpinRatio = std::max
            (
                maxSpinRatio, x.rotationalKineticEnergy()/x.translationalKineticEnergy()
            );
            ++samples;
        },
        20
    );
    const double meanT = sumT/samples;
    double massSum = 0;
    for (double m : sim.particles().mass) massSum += m;
    const double drift = (sim.totalMomentum() - p0).norm()/(massSum*std::sqrt(target/3));
    std::cout << "e " << restitution << ", mu " << friction << ": T/T_target = "
              << meanT/target << ", momentum drift / (M sqrt(T/3)) = " << drift
              << ", max overlap / d = " << maxOverlap
              << ", max rotational / translational kinetic energy = " << maxSpinRatio << "\n";
    ASSERT_TRUE(allFinite(sim.particles()));
    // A nearly elastic cell still gains about 5 % of its energy in its first 100 steps
    // with no kick (not the stored elastic energy, which the steering now counts), and
    // loses it only at its collisional cooling rate, (1 - e^2) times slower than at e 0.1
    EXPECT_NEAR(meanT/target, 1.0, restitution < 0.5 ? 0.01 : 0.05);
    EXPECT_LT(drift, 1e-10);
    // the tests' soft springs keep overlaps well below the 10 % stop at these speeds
    EXPECT_LT(maxOverlap, 0.05);
    // the kicks feed translation only and friction passes part of it to rotation, which
    // stays below translation (equipartition between them would give 1); frictionless
    // grains keep their initial zero spin
    if (friction == 0.0)
    {
        EXPECT_EQ(maxSpinRatio, 0.0);
    }
    else
    {
        EXPECT_LT(maxSpinRatio, 1.0);
    }
}

INSTANTIATE_TEST_SUITE_P
(
    RestitutionAndFriction, ContactExtremes,
    testing::Combine(testing::Values(0.1, 0.99), testing::Values(0.0, 1.0))
);

TEST(TimeStepExtremes, AtTheLimitConservesEnergyAboveItIsRefused)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.4, 0.02, 0, 5);
    SimulationSettings s = test::softContacts(1.0, 0.0);
    s.threads = 2;
    const double limit = ContactLaw(s.contact, species).maximumTimeStep();

    // at the limit: 5000 steps of an elastic, frictionless cell keep the total energy
    // (the Verlet scheme's error at t_c/50 is of order (dt/t_c)^2, well below 1e-3)
    s.timeStep = limit;
    Simulation sim(species, s, packing.particles, packing.box);
    const double e0 = test::totalEnergy(sim);
    sim.run(5000);
    const double change = std::abs(test::totalEnergy(sim)/e0 - 1);
    std::cout << "dt = limit " << limit << " s: relative energy change over 5000 steps "
              << change << "\n";
    ASSERT_TRUE(allFinite(sim.particles()));
    EXPECT_LT(change, 1e-3);

    // 1 % above it: refused before any step, the message naming the entry and the limit
    s.timeStep = 1.01*limit;
    try
    {
        Simulation refused(species, s, packing.particles, packing.box);
        FAIL() << "a time step 1 % above the limit was accepted";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("timeStep"), std::string::npos) << msg;
        EXPECT_NE(msg.find("recommended maximum"), std::string::npos) << msg;
    }
}

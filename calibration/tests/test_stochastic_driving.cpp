// Stochastic driving (StochasticDriving): random kicks per particle, their momentum
// removed, their variance steered to the target T. The kicks depend only on (seed, kick,
// particle id): 1, 2 and 3 threads give bitwise the same trajectories, and a resumed run
// continues bitwise; an inelastic cell is held at the target T with its momentum kept;
// bad settings are refused naming the entry.
#include "TestCells.hpp"
#include "StochasticDriving.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace sdf::dem;

namespace
{

SimulationSettings stochasticSettings(double target, int threads)
{
    SimulationSettings s = test::softContacts(0.8, 0.3);
    s.mode = CellMode::stochastic;
    s.targetTemperature = target;
    s.threads = threads;
    s.seed = 7;
    return s;
}

} // namespace

TEST(StochasticDriving, NormalDeviatesAreStandard)
{
    // the counter-based stream: mean 0, variance 1 per component over 20000 draws (errors
    // 0.004 and 0.006 for a standard normal), different for another seed, step or id
    double sum = 0, sum2 = 0;
    const int n = 20000;
    for (int id = 0; id < n; ++id)
    {
        double xi[3];
        StochasticDriving::normals(3, 11, std::uint64_t(id), xi);
        for (double v : xi) { sum += v; sum2 += v*v; }
    }
    const double mean = sum/(3*n), variance = sum2/(3*n) - mean*mean;
    EXPECT_NEAR(mean, 0.0, 0.03);
    EXPECT_NEAR(variance, 1.0, 0.03);
    double a[3], b[3], c[3], d[3];
    StochasticDriving::normals(3, 11, 5, a);
    StochasticDriving::normals(4, 11, 5, b);
    StochasticDriving::normals(3, 12, 5, c);
    StochasticDriving::normals(3, 11, 6, d);
    EXPECT_NE(a[0], b[0]);
    EXPECT_NE(a[0], c[0]);
    EXPECT_NE(a[0], d[0]);
    double again[3];
    StochasticDriving::normals(3, 11, 5, again);
    EXPECT_EQ(a[0], again[0]);
}

TEST(StochasticDriving, InelasticCellHeldAtTargetWithMomentumKept)
{
    const auto species = test::binary(2.0);
    const double target = 0.02;
    Packing packing = test::packedCell(species, {300, 40}, 0.3, 0.5*target, 0, 13);
    Simulation sim(species, stochasticSettings(target, 2), packing.particles, packing.box);
    const Eigen::Vector3d p0 = sim.totalMomentum();
    sim.run(6000);      // equilibrate: several steering times (1000 dt)
    double sumT = 0;
    int samples = 0;
    sim.run(12000, [&](const Simulation& x) { sumT += x.temperature(); ++samples; }, 20);
    const double meanT = sumT/samples;
    double massSum = 0;
    for (double m : sim.particles().mass) massSum += m;
    double vScale = std::sqrt(target/3);
    const double drift = (sim.totalMomentum() - p0).norm()/(massSum*vScale);
    std::cout << "T/T_target = " << meanT/target << ", momentum drift / (M sqrt(T/3)) = "
              << drift << "\n";
    EXPECT_NEAR(meanT/target, 1.0, 0.01);   // 1.0025 measured
    EXPECT_LT(drift, 1e-10);
}

TEST(StochasticDriving, OneTwoAndThreeThreadsAndResumeBitwiseIdentical)
{
    const auto species = test::binary(2.0);
    const double target = 0.02;
    auto run = [&](int threads, long steps)
    {
        Packing packing = test::packedCell(species, {300, 40}, 0.35, target, 0, 5);
        SimulationSettings s = stochasticSettings(target, threads);
        s.renumberEvery = 500;
        Simulation sim(species, s, packing.particles, packing.box);
        sim.run(steps);
        return sim;
    };
    const Simulation a = run(1, 3000);
    for (const int threads : {2, 3})
    {
        const Simulation b = run(threads, 3000);
        EXPECT_TRUE(test::bitwiseEqual(a.particles().x, b.particles().x)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles().vz, b.particles().vz)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles().wx, b.particles().wx)) << threads << " threads";
    }
    // resumed at step 1703 (between kicks) from the exported state (the driving's
    // steering included)
    Simulation first = run(2, 1703);
    const SimulationState state = first.exportState();
    ASSERT_EQ(state.driving.size(), 8u);
    Packing packing = test::packedCell(species, {300, 40}, 0.35, target, 0, 5);
    SimulationSettings s = stochasticSettings(target, 2);
    s.renumberEvery = 500;
    Simulation resumed(species, s, packing.particles, packing.box);
    resumed.importState(state);
    resumed.run(1297);
    EXPECT_TRUE(test::bitwiseEqual(a.particles().x, resumed.particles().x));
    EXPECT_TRUE(test::bitwiseEqual(a.particles().vy, resumed.particles().vy));
}

TEST(StochasticDriving, BadSettingsRefusedNamingTheEntry)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {40, 5}, 0.2, 0.01, 0, 3);
    auto message = [&](SimulationSettings s)
    {
        try
        {
            Simulation sim(species, s, packing.particles, packing.box);
        }
        catch (const std::invalid_argument& e)
        {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    SimulationSettings zeroT = stochasticSettings(0.0, 1);
    EXPECT_NE(message(zeroT).find("targetTemperature"), std::string::npos) << message(zeroT);
    SimulationSettings shortSteering = stochasticSettings(0.01, 1);
    shortSteering.timeStep = 1e-6;
    shortSteering.thermostatTime = 1e-7;
    EXPECT_NE(message(shortSteering).find("thermostatTime"), std::string::npos)
        << message(shortSteering);
    EXPECT_THROW(cellModeFromName("stochastik"), std::invalid_argument);
    try { cellModeFromName("stochastik"); }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("stochastic"), std::string::npos);
    }
    // a state of another driving (7 values) refused by the thermostat, and vice versa
    SimulationSettings rescaled = stochasticSettings(0.01, 1);
    rescaled.mode = CellMode::thermostatted;
    Simulation sim(species, rescaled, packing.particles, packing.box);
    SimulationState state = sim.exportState();
    state.driving = {1, 2, 3, 4, 5, 0, 7};
    EXPECT_THROW(sim.importState(state), std::invalid_argument);
    Simulation stochastic(species, stochasticSettings(0.01, 1), packing.particles, packing.box);
    state.driving = {};
    EXPECT_THROW(stochastic.importState(state), std::invalid_argument);
    // a state of the engine before the elastic energy was counted (7 values) is refused,
    // saying so
    state.driving = {0, 0, 0, -1, 0, 0, 7};
    try
    {
        stochastic.importState(state);
        ADD_FAILURE() << "a driving state of format 1 accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("elastic energy"), std::string::npos) << e.what();
    }
    // a checkpoint of another seed (7 here, 8 in the state) names the entry
    state.driving = {0, 0, 0, -1, 0, 0, 8, StochasticDriving::stateFormat};
    try
    {
        stochastic.importState(state);
        ADD_FAILURE() << "a checkpoint of another seed accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("'seed'"), std::string::npos) << e.what();
    }
}

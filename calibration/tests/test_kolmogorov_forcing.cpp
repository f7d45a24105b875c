// Kolmogorov forcing (KolmogorovForcing): a body force a0 sin(k y) along x with its total
// momentum removed. From rest the flow starts as u_x = a0 t sin(k y); the total momentum
// stays zero; a sheared steady flow develops in phase with the force; 1, 2 and 3 threads
// give bitwise the same trajectories; bad settings are refused naming the entry.
#include "TestCells.hpp"
#include "KolmogorovForcing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace sdf::dem;

namespace
{

constexpr double amplitude = 20.0;   // m/s^2

Simulation forcedCell(int threads, double temperature = 1e-8)
{
    const Packing packing = test::packedCell(test::binary(), {300, 40}, 0.4, temperature);
    SimulationSettings s = test::softContacts(0.7, 0.5);
    s.threads = threads;
    s.renumberEvery = 500;
    Simulation sim(test::binary(), s, packing.particles, packing.box);
    sim.setDriving(std::make_unique<KolmogorovForcing>(amplitude, 1, sim.box().ly, sim.timeStep()));
    return sim;
}

//- Mass-weighted projections of u_x on sin(k y) and cos(k y), times 2 (the amplitudes of a
//  uniform cell's flow).
std::pair<double, double> flowAmplitudes(const Simulation& sim)
{
    const Particles& p = sim.particles();
    const double k = 2*M_PI/sim.box().ly;
    double m = 0, s = 0, c = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        m += p.mass[i];
        s += p.mass[i]*p.vx[i]*std::sin(k*p.y[i]);
        c += p.mass[i]*p.vx[i]*std::cos(k*p.y[i]);
    }
    return {2*s/m, 2*c/m};
}

double flowScale(const Simulation& sim)
{
    double m = 0;
    for (double mi : sim.particles().mass) m += mi;
    return m*amplitude*sim.time();
}

} // namespace

TEST(KolmogorovForcing, FlowStartsAsTheForceTimesTimeWithZeroMomentum)
{
    Simulation sim = forcedCell(1);
    // 0.5 ms: a fraction of a collision time of the nearly resting packing, so the
    // particles are still free: u_x = a0 t sin(k y) up to the packing's departure from a
    // uniform density (the projection's error, about 1/sqrt(N))
    sim.run(500);
    const auto [sine, cosine] = flowAmplitudes(sim);
    const double free = amplitude*sim.time();
    EXPECT_NEAR(sine, free, 0.1*free);
    EXPECT_LT(std::abs(cosine), 0.1*free);
    EXPECT_LT(sim.totalMomentum().norm(), 1e-12*flowScale(sim));
    std::cout << "[ figures  ] after " << sim.time() << " s: sine amplitude " << sine
              << " m/s (free flow " << free << "), cosine " << cosine << "\n";
}

TEST(KolmogorovForcing, ShearedFlowInPhaseWithTheForceMomentumKept)
{
    Simulation sim = forcedCell(1);
    sim.run(40000);   // 0.04 s: the collisions have made it a sheared granular flow
    const auto [sine, cosine] = flowAmplitudes(sim);
    const double free = amplitude*sim.time();
    EXPECT_GT(sine, 0.0);
    EXPECT_LT(sine, free);                     // the collisions resist the force
    EXPECT_LT(std::abs(cosine), 0.2*sine);     // in phase with the force
    EXPECT_LT(sim.totalMomentum().norm(), 1e-11*flowScale(sim));
    EXPECT_TRUE(std::isfinite(sim.temperature()));
    std::cout << "[ figures  ] after " << sim.time() << " s: sine amplitude " << sine
              << " m/s (free flow " << free << "), cosine " << cosine << ", momentum "
              << sim.totalMomentum().norm() << " kg m/s\n";
}

TEST(KolmogorovForcing, OneTwoAndThreeThreadsBitwiseIdentical)
{
    auto run = [](int threads)
    {
        Simulation sim = forcedCell(threads, 1e-4);
        sim.run(3000);
        return sim;
    };
    const Simulation a = run(1);
    for (const int threads : {2, 3})
    {
        const Simulation b = run(threads);
        EXPECT_TRUE(test::bitwiseEqual(a.particles().x, b.particles().x)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles().vx, b.particles().vx)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles().wz, b.particles().wz)) << threads << " threads";
    }
}

TEST(KolmogorovForcing, BadSettingsRefusedNamingTheEntry)
{
    auto message = [](double a0, int waves, double ly, double dt)
    {
        try
        {
            KolmogorovForcing(a0, waves, ly, dt);
        }
        catch (const std::invalid_argument& e)
        {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(0, 1, 0.01, 1e-6).find("forcingAmplitude"), std::string::npos);
    EXPECT_NE(message(-1, 1, 0.01, 1e-6).find("forcingAmplitude"), std::string::npos);
    EXPECT_NE(message(std::nan(""), 1, 0.01, 1e-6).find("forcingAmplitude"), std::string::npos);
    EXPECT_NE(message(10, 0, 0.01, 1e-6).find("forcingWaves"), std::string::npos);
    EXPECT_NE(message(10, 1, 0, 1e-6).find("box height"), std::string::npos);
    EXPECT_EQ(message(10, 2, 0.01, 1e-6), "no error");
}

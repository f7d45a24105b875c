// Elastic frictionless gas against Enskog kinetic theory (validation.md item 11):
// collision frequency omega_E = 4 n sigma^2 g0 sqrt(pi T1) and pressure
// p = n m T1 (1 + 4 phi g0) at phi = 0.1 (Carnahan-Starling g0), within 5 %.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

TEST(ElasticGas, CollisionFrequencyAndPressureMatchEnskogAtPhi01)
{
    const auto species = test::mono();
    const double phi = 0.1, T = 0.03, T1 = T/3;
    Packing packing = test::packedCell(species, {400}, phi, T, 0, 31);
    const SimulationSettings s = test::softContacts(1.0, 0.0);   // overlaps ~0.3 % of d
    Simulation sim(species, s, packing.particles, packing.box);
    sim.run(5000);
    sim.enableCollisionStatistics(1e-12, 1e-3, 10);
    double pressureSum = 0, temperatureSum = 0;
    long samples = 0;
    sim.run(60000, [&](const Simulation& x)
    {
        pressureSum += x.totalStress().trace()/(3*x.box().volume());
        temperatureSum += x.temperature();
        ++samples;
    }, 20);
    const double sigma = species[0].diameter, m = species[0].mass();
    const double n = sim.particles().size()/sim.box().volume();
    const double g0 = (1 - phi/2)/std::pow(1 - phi, 3);
    const double T1measured = temperatureSum/samples/3;
    EXPECT_NEAR(T1measured/T1, 1.0, 0.01);

    const double omegaE = 4*n*sigma*sigma*g0*std::sqrt(M_PI*T1measured);
    const double omega = sim.collisionStatistics().frequencyPerParticle(0, 0, sim.speciesCounts());
    const double pE = n*m*T1measured*(1 + 4*phi*g0);
    const double p = pressureSum/samples;
    std::cout << "collision frequency / Enskog = " << omega/omegaE
              << ", pressure / Enskog = " << p/pE << "\n";
    EXPECT_NEAR(omega/omegaE, 1.0, 0.05);
    EXPECT_NEAR(p/pE, 1.0, 0.05);
}

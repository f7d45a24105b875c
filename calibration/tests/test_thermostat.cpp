// Thermostatted (driven) homogeneous cell: an inelastic bidisperse cell is held at the
// target T; per-species temperatures and collision statistics are reported.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

TEST(Thermostat, InelasticCellHeldAtTargetTemperature)
{
    const auto species = test::binary(2.0);
    const double target = 0.02;   // m^2/s^2, sum of the three components
    Packing packing = test::packedCell(species, {300, 40}, 0.3, 0.5*target, 0, 13);
    SimulationSettings s = test::softContacts(0.8, 0.3);
    s.mode = CellMode::thermostatted;
    s.targetTemperature = target;
    Simulation sim(species, s, packing.particles, packing.box);
    sim.run(3000);      // equilibrate
    sim.enableCollisionStatistics(1e-12, 1e-4, 40);
    double sumT = 0, sumT0 = 0, sumT1 = 0;
    int samples = 0;
    sim.run(6000, [&](const Simulation& x)
    {
        sumT += x.temperature();
        const auto ts = x.speciesTemperatures();
        sumT0 += ts[0];
        sumT1 += ts[1];
        ++samples;
    }, 20);
    const double meanT = sumT/samples;
    std::cout << "T/T_target = " << meanT/target << ", T_fine/T_coarse = " << sumT0/sumT1 << "\n";
    EXPECT_NEAR(meanT/target, 1.0, 0.02);
    // number-weighted mixture T lies between the species temperatures
    EXPECT_GE(meanT, std::min(sumT0, sumT1)/samples*(1 - 1e-12));
    EXPECT_LE(meanT, std::max(sumT0, sumT1)/samples*(1 + 1e-12));

    const CollisionStatistics& c = sim.collisionStatistics();
    const auto counts = sim.speciesCounts();
    long total = 0;
    for (int sp = 0; sp < 3; ++sp)
    {
        EXPECT_GT(c.counts[sp], 0);
        long inHist = 0;
        for (long h : c.histogram[sp]) inHist += h;
        EXPECT_EQ(inHist, c.counts[sp]);
        total += c.counts[sp];
    }
    EXPECT_NEAR(c.elapsedTime, 6000*sim.timeStep(), 1e-12);
    // fines collide with fines more often than with the few coarse grains
    EXPECT_GT(c.frequencyPerParticle(0, 0, counts), c.frequencyPerParticle(0, 1, counts));
    std::cout << "collisions: " << total << ", fine-fine frequency per fine "
              << c.frequencyPerParticle(0, 0, counts) << " 1/s\n";
}

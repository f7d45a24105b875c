// The impact-energy spectrum of an elastic frictionless gas against Maxwell-Boltzmann
// (validation of the collision statistics the breakage rates are computed from).
//
// The expected spectrum, in the engine's definitions (docs/developer/dem-engine.md):
//  - T = <|c|^2> is the SUM of the three components, so the per-component velocity
//    variance is T1 = T/3 and, for grains of mass m, "kT" = m T1 = m T/3;
//  - the recorded impact energy is E = 0.5 m* v_n^2 with m* = m_i m_j/(m_i + m_j) and
//    v_n the normal relative velocity at the first step of a contact (centre-of-mass
//    frame; rotation has no normal component).
// In equilibrium the velocities are Maxwellian and independent of the positions, so the
// relative velocity g = v_i - v_j of a pair at contact is Gaussian with per-component
// variance kT/m_i + kT/m_j = kT/m* (= 2 T1 for equal grains), and its component along any
// fixed normal, g_n, is N(0, kT/m*). Pairs collide at the rate of the flux through the
// contact sphere, proportional to g_n for approaching pairs, so the normal speed of the
// colliding pairs has the density
//     p(g_n) = (m*/kT) g_n exp(-m* g_n^2/(2 kT)),   g_n > 0,
// and E = 0.5 m* g_n^2 (dE = m* g_n dg_n) is exponential with mean kT:
//     p(E) = exp(-E/kT)/kT,   <E> = kT = m T/3,
// whatever m* (the same for unlike pairs at equal kT). A bin [a, b) holds the fraction
// exp(-a/kT) - exp(-b/kT). Enskog's dense-gas factor g0 multiplies all rates alike (no
// velocity dependence), so the form holds at any phi; phi = 0.05 keeps contacts binary.
//
// The run: 1000 grains, phi 0.05, e = 1 (the linear dashpot is then off: exactly elastic),
// no friction, NVE (the temperature is steady without driving), dt = t_c/50 (dem.nve:
// energy drift < 1e-4 at this step). T = 0.3 m2/s2 puts the typical overlap at ~0.8 % of
// d (contact time / free time ~1 %: still a binary-collision gas) and gives ~2 10^4
// collisions in ~5 s. Asserted: per-slot counts (under, 20 log bins, over)
// within 4 counting sigmas of the multinomial expectation, chi-square (21 dof) below its
// 0.999 quantile 46.8, and <E>/kT within 3 % (counting error ~1 %).
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace sdf::dem;

TEST(ElasticGas, ImpactEnergySpectrumIsMaxwellBoltzmannAtPhi005)
{
    const auto species = test::mono();
    const double phi = 0.05, T = 0.3;
    Packing packing = test::packedCell(species, {1000}, phi, T, 0, 43);
    SimulationSettings s = test::softContacts(1.0, 0.0);
    {
        // the largest step the contact law allows (t_c/50)
        Simulation probe(species, s, packing.particles, packing.box);
        s.timeStep = probe.contactLaw().maximumTimeStep();
    }
    Simulation sim(species, s, packing.particles, packing.box);
    sim.run(5000);

    const double m = species[0].mass();
    const double kT0 = m*T/3;
    const int nBins = 20;
    sim.enableCollisionStatistics(1e-2*kT0, 8*kT0, nBins);
    double temperatureSum = 0;
    long samples = 0;
    sim.run(150000, [&](const Simulation& x)
    {
        temperatureSum += x.temperature();
        ++samples;
    }, 50);

    const CollisionStatistics& col = sim.collisionStatistics();
    const double kT = m*(temperatureSum/samples)/3;
    const long n = col.counts[0];
    ASSERT_GT(n, 15000) << "too few collisions for the test's tolerances";

    // Expected fraction of each slot: under [0, e_0), bins [e_b, e_b+1), over [e_nBins, inf)
    std::vector<double> expected(nBins + 2);
    expected[0] = 1 - std::exp(-col.binEdges.front()/kT);
    for (int b = 0; b < nBins; ++b)
    {
        expected[b + 1] = std::exp(-col.binEdges[b]/kT) - std::exp(-col.binEdges[b + 1]/kT);
    }
    expected[nBins + 1] = std::exp(-col.binEdges.back()/kT);

    double chiSquare = 0, worst = 0;
    for (int k = 0; k < nBins + 2; ++k)
    {
        const double mean = n*expected[k];
        const double sigma = std::sqrt(n*expected[k]*(1 - expected[k]));
        const double observed = double(col.histogram[0][k]);
        const double z = (observed - mean)/sigma;
        chiSquare += (observed - mean)*(observed - mean)/mean;
        worst = std::max(worst, std::abs(z));
        EXPECT_LT(std::abs(z), 4.0)
            << "slot " << k << ": " << observed << " impacts, expected " << mean;
    }
    const double meanEnergy = col.energySum[0]/n;
    std::cout << n << " impacts, <E>/kT = " << meanEnergy/kT
              << " (counting error " << 1/std::sqrt(double(n)) << "), chi2 = " << chiSquare
              << " (21 dof), worst slot " << worst << " sigma, T/T0 = " << kT/kT0 << "\n";
    EXPECT_LT(chiSquare, 46.8);
    EXPECT_NEAR(meanEnergy/kT, 1.0, 0.03);
    // the gas stays at its temperature (elastic, undriven) and the counts add up
    EXPECT_NEAR(kT/kT0, 1.0, 0.01);
    long total = 0;
    for (long c : col.histogram[0]) total += c;
    EXPECT_EQ(total, n);
}

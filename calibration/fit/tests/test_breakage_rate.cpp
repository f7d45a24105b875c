// The Vogel & Peukert breakage rate from an impact spectrum (fit/BreakageRate.hpp):
// a hand-computed case, the threshold, the exponential-spectrum closed form against the
// bin sum, the histogram conversion, and refusals naming the parameter.
#include "fit/BreakageRate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace sdf::fit::breakage;

namespace
{
//- fMat = 2 kg/(J m), x Wmin = 0.05 J m/kg: Wmin = 50 J/kg at x = 1 mm
VogelPeukertMaterial handMaterial()
{
    return VogelPeukertMaterial{2.0, 0.05};
}

template<class F>
void expectRefusedNaming(const std::string& name, F&& f)
{
    try
    {
        f();
        ADD_FAILURE() << "accepted a bad " << name;
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}
} // namespace

TEST(BreakageRate, HandComputedRateAndParentFraction)
{
    // 10 impacts/s at 15 m/s: W = v^2/2 = 112.5 J/kg; Wmin = 0.05/1e-3 = 50 J/kg;
    // S = 2 * 1e-3 * 10 * (112.5 - 50) = 1.25 1/s; after 1 s exp(-1.25) = 0.2865.
    const double x = 1e-3;
    EXPECT_NEAR(thresholdEnergy(handMaterial(), x), 50.0, 1e-12);
    const ImpactSpectrum spectrum{{0.5*15.0*15.0}, {10.0}};
    const double S = vogelPeukertBreakageRate(handMaterial(), x, spectrum);
    EXPECT_NEAR(S, 1.25, 1e-12);
    EXPECT_NEAR(parentFraction(S, 1.0), 0.2865, 5e-5);
    EXPECT_NEAR(parentFraction(S, 1.0), std::exp(-1.25), 1e-15);
    // one impact breaks with 1 - exp(-0.125); ten survive as exp(-1.25)
    EXPECT_NEAR(impactBreakageProbability(handMaterial(), x, 112.5), 1 - std::exp(-0.125), 1e-15);
    EXPECT_NEAR(std::pow(1 - impactBreakageProbability(handMaterial(), x, 112.5), 10),
                parentFraction(S, 1.0), 1e-14);
}

TEST(BreakageRate, PairEnergyOfEqualGrainsIsTheWallImpactAtHalfTheClosingSpeed)
{
    // equal grains m closing at g_n = 30 m/s: E = 0.5 (m/2) 30^2, W = E/(2m) = 15^2/2
    const double m = 1.3e-6, gn = 30.0;
    const double E = 0.5*(0.5*m)*gn*gn;
    EXPECT_NEAR(massSpecificImpactEnergy(E, m, m), 112.5, 1e-9);
}

TEST(BreakageRate, NoBreakageAtOrBelowTheThreshold)
{
    const double x = 2e-3;   // Wmin = 25 J/kg
    const ImpactSpectrum below{{10.0, 25.0}, {1e3, 1e3}};
    EXPECT_EQ(vogelPeukertBreakageRate(handMaterial(), x, below), 0.0);
    // the threshold falls with size: the same impacts break a larger particle
    const ImpactSpectrum spectrum{{40.0}, {5.0}};
    EXPECT_EQ(vogelPeukertBreakageRate(handMaterial(), 1e-3, spectrum), 0.0);
    EXPECT_NEAR(vogelPeukertBreakageRate(handMaterial(), 2e-3, spectrum), 2*2e-3*5*15.0, 1e-12);
}

TEST(BreakageRate, ExponentialSpectrumClosedFormEqualsTheBinSum)
{
    // omega = 200/s, <W> = 30 J/kg, Wmin = 50 J/kg: fine bins of the exponential density
    const double x = 1e-3, omega = 200, Wmean = 30;
    ImpactSpectrum spectrum;
    const double dW = 0.01;
    for (double W = 0.5*dW; W < 40*Wmean; W += dW)
    {
        spectrum.energy.push_back(W);
        spectrum.frequency.push_back(omega*std::exp(-W/Wmean)*dW/Wmean);
    }
    const double sum = vogelPeukertBreakageRate(handMaterial(), x, spectrum);
    const double closed = vogelPeukertRateExponentialSpectrum(handMaterial(), x, omega, Wmean);
    EXPECT_NEAR(sum/closed, 1.0, 1e-6);
    EXPECT_NEAR(closed, 2*1e-3*200*30*std::exp(-50.0/30), 1e-12);
}

TEST(BreakageRate, SpectrumFromAHistogramOfPairEnergies)
{
    // 2 bins [1, 3) and [3, 5) J, counts (under 4, 10, 20, over 2) over 2 s among 5
    // particles of s colliding within s: frequency = 2 count/(2 s * 5)
    const std::vector<double> edges{1, 3, 5};
    const std::vector<long> counts{4, 10, 20, 2};
    const double m = 0.5;   // W = E/(m + m) = E
    const ImpactSpectrum sp = impactSpectrumFromHistogram(edges, counts, 2.0, 5, true, m, m);
    ASSERT_EQ(sp.energy.size(), 4u);
    EXPECT_DOUBLE_EQ(sp.energy[0], 0.5);
    EXPECT_DOUBLE_EQ(sp.energy[1], 2.0);
    EXPECT_DOUBLE_EQ(sp.energy[2], 4.0);
    EXPECT_DOUBLE_EQ(sp.energy[3], 5.0);
    EXPECT_DOUBLE_EQ(sp.frequency[0], 0.8);
    EXPECT_DOUBLE_EQ(sp.frequency[2], 4.0);
    // unlike species: one particle of s per collision
    const ImpactSpectrum cross = impactSpectrumFromHistogram(edges, counts, 2.0, 5, false, m, m);
    EXPECT_DOUBLE_EQ(cross.frequency[2], 2.0);
    expectRefusedNaming("edges", [&] { impactSpectrumFromHistogram(edges, {1, 2}, 2.0, 5, true, m, m); });
    expectRefusedNaming("elapsedTime", [&] { impactSpectrumFromHistogram(edges, counts, 0.0, 5, true, m, m); });
}

TEST(BreakageRate, RefusesNegativeParametersNamingThem)
{
    const ImpactSpectrum spectrum{{112.5}, {10.0}};
    expectRefusedNaming("fMat", [&] { vogelPeukertBreakageRate({-2.0, 0.05}, 1e-3, spectrum); });
    expectRefusedNaming("xWmMin", [&] { vogelPeukertBreakageRate({2.0, -0.05}, 1e-3, spectrum); });
    expectRefusedNaming("fMat", [&] { vogelPeukertBreakageRate({NAN, 0.05}, 1e-3, spectrum); });
    expectRefusedNaming("x (particle size)", [&] { vogelPeukertBreakageRate(handMaterial(), 0.0, spectrum); });
    expectRefusedNaming("impact frequency", [&]
    {
        vogelPeukertBreakageRate(handMaterial(), 1e-3, ImpactSpectrum{{112.5}, {-10.0}});
    });
    expectRefusedNaming("W (mass-specific impact energy)", [&]
    {
        vogelPeukertBreakageRate(handMaterial(), 1e-3, ImpactSpectrum{{-1.0}, {10.0}});
    });
    expectRefusedNaming("breakage rate", [&] { parentFraction(-1.25, 1.0); });
    expectRefusedNaming("mean impact energy", [&]
    {
        vogelPeukertRateExponentialSpectrum(handMaterial(), 1e-3, 10.0, 0.0);
    });
    expectRefusedNaming("frequencies", [&]
    {
        vogelPeukertBreakageRate(handMaterial(), 1e-3, ImpactSpectrum{{1.0, 2.0}, {10.0}});
    });
}

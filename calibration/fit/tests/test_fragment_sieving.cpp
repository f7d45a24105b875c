// fitAustin: Austin's breakage function back from sieve analyses made from known
// constants (exactly, and with noise within its standard errors), and the sieve
// analyses it must refuse.
#include "fit/FragmentSieving.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

using namespace sdf::fit::breakage;

namespace
{

constexpr double phi = 0.4, gamma_ = 0.9, beta_ = 4;   // austin.H's example

// Fragments of parents of 2 and 4 mm sieved at y/2 ... y/64 and the pan, the masses
// B's differences (times noise)
std::vector<SieveFraction> sieving(double noise, std::mt19937_64* engine)
{
    std::normal_distribution<double> gauss(0, 1);
    std::vector<SieveFraction> rows;
    for (const double y : {2e-3, 4e-3})
    {
        double upper = 1;
        for (int k = 1; k <= 7; ++k)
        {
            const double sieve = k < 7 ? y/std::pow(2.0, k) : 0.0;
            const double lower = k < 7 ? austinFiner(phi, gamma_, beta_, sieve/y) : 0.0;
            const double factor = engine ? 1 + noise*gauss(*engine) : 1.0;
            rows.push_back({y, sieve, (upper - lower)*factor, k});
            upper = lower;
        }
    }
    return rows;
}

void expectRefusal(const std::string& text, const std::string& message)
{
    try
    {
        std::istringstream in(text);
        readFragmentSieving(in, "fragments.dat");
        FAIL() << "accepted: " << text;
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << "message: " << e.what();
    }
}

} // namespace

TEST(FragmentSieving, CumulativeFractions)
{
    std::istringstream in("size sieve mass\n2e-3 1e-3 6\n2e-3 0 1\n2e-3 5e-4 3\n");
    const auto points = finerFractions(readFragmentSieving(in, "fragments.dat"));
    ASSERT_EQ(points.size(), 2u);
    EXPECT_DOUBLE_EQ(points[0].ratio, 0.25);
    EXPECT_DOUBLE_EQ(points[0].finer, 0.1);   // the pan
    EXPECT_DOUBLE_EQ(points[1].ratio, 0.5);
    EXPECT_DOUBLE_EQ(points[1].finer, 0.4);   // the pan and the 0.5 mm sieve
}

TEST(FragmentSieving, RecoversAustinsConstants)
{
    const AustinFitResult fit = fitAustin(sieving(0, nullptr));
    EXPECT_NEAR(fit.phi, phi, 1e-6);
    EXPECT_NEAR(fit.gamma, gamma_, 1e-6);
    EXPECT_NEAR(fit.beta, beta_, 1e-6);
    EXPECT_LT(fit.rms, 1e-8);
    EXPECT_EQ(fit.points, 12);
}

TEST(FragmentSieving, NoisyAnalysesWithinTheirErrors)
{
    // 5 % noise on every retained mass: each constant within 4 of its standard errors
    // in each of 20 analyses
    std::mt19937_64 engine(11);
    for (int draw = 0; draw < 20; ++draw)
    {
        const AustinFitResult fit = fitAustin(sieving(0.05, &engine));
        ASSERT_TRUE(std::isfinite(fit.phiError) && std::isfinite(fit.gammaError) && std::isfinite(fit.betaError));
        EXPECT_LT(std::abs(fit.phi - phi), 4*fit.phiError) << draw;
        EXPECT_LT(std::abs(fit.gamma - gamma_), 4*fit.gammaError) << draw;
        EXPECT_LT(std::abs(fit.beta - beta_), 4*fit.betaError) << draw;
    }
}

TEST(FragmentSieving, Refusals)
{
    expectRefusal("size sieve mass\n2e-3 2e-3 1\n", "fragments.dat:2: column 'sieve': 0.002 must be >= 0 (0: the pan) and below the parent size 0.002 m");
    expectRefusal("size sieve mass\n2e-3 1e-3 -1\n", "fragments.dat:2: column 'mass': -1 must be >= 0");
    expectRefusal("size sieve mass\n2e-3 1e-3 1\n2e-3 1e-3 2\n", "fragments.dat:3: sieve 0.001 m given twice for parents of 0.002 m");
    expectRefusal("size sieve mass\n2e-3 1e-3 0\n2e-3 0 0\n", "the fragments of parents of 0.002 m weigh nothing");
    expectRefusal("size aperture mass\n", "unknown column 'aperture'; valid columns: size sieve mass");
    expectRefusal("size mass\n", "no column 'sieve'");
    expectRefusal("size sieve mass\n", "no rows after the header");
    std::istringstream two("size sieve mass\n2e-3 1e-3 5\n2e-3 5e-4 3\n2e-3 0 2\n");
    EXPECT_THROW(fitAustin(readFragmentSieving(two, "fragments.dat")), std::invalid_argument);
}

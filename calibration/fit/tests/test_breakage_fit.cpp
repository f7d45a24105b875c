// fitVogelPeukert: the constants back from counts drawn from known ones, honest standard
// errors (the 95 % interval's coverage over many draws), the deviance's check, and the
// tables and designs it must refuse.
#include "fit/BreakageFit.hpp"
#include "fit/ImpactTests.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

using namespace sdf::fit::breakage;

namespace
{

const VogelPeukertMaterial truth{0.9, 0.12};   // the pipe-bend tutorial's constants

// The law as the solver's breakage models evaluate it (BreakageRate.hpp: one impact),
// k independent impacts composed: the fit's own formula is not the reference
double lawProbability(const VogelPeukertMaterial& m, const ImpactTest& t)
{
    return 1 - std::pow(1 - impactBreakageProbability(m, t.size, t.energy), t.impacts);
}

// A tester's design: three sizes, six velocities, one impact, n particles per row
std::vector<ImpactTest> design(long n, int impacts = 1)
{
    std::vector<ImpactTest> tests;
    for (const double x : {0.5e-3, 1e-3, 2e-3})
    {
        for (const double v : {10.0, 20.0, 30.0, 40.0, 50.0, 60.0})
        {
            ImpactTest t;
            t.size = x;
            t.energy = 0.5*v*v;
            t.impacts = impacts;
            t.tested = n;
            tests.push_back(t);
        }
    }
    return tests;
}

std::vector<ImpactTest> drawn(std::vector<ImpactTest> tests, const VogelPeukertMaterial& m,
                              std::mt19937_64& engine)
{
    for (ImpactTest& t : tests)
    {
        std::binomial_distribution<long> count(t.tested, lawProbability(m, t));
        t.broken = count(engine);
    }
    return tests;
}

std::vector<ImpactTest> read(const std::string& text)
{
    std::istringstream in(text);
    return readImpactTests(in, "tests.dat");
}

void expectRefusal(const std::string& text, const std::string& message)
{
    try
    {
        read(text);
        FAIL() << "accepted: " << text;
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << "message: " << e.what();
    }
}

void expectFitRefusal(const std::vector<ImpactTest>& tests, const std::string& message)
{
    try
    {
        fitVogelPeukert(tests);
        FAIL() << "fitted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << "message: " << e.what();
    }
}

} // namespace

TEST(BreakageFit, ReadsATable)
{
    const auto tests = read
    (
        "# an impact tester\n"
        "size velocity impacts tested broken\n"
        "1e-3 20 1 100 7   # a comment\n"
        "\n"
        "2e-3 30 2 50 50\n"
    );
    ASSERT_EQ(tests.size(), 2u);
    EXPECT_EQ(tests[0].energy, 200.0);
    EXPECT_EQ(tests[1].impacts, 2);
    EXPECT_EQ(tests[1].broken, 50);
    EXPECT_EQ(tests[1].line, 5);
    const auto energies = read("energy broken tested impacts size\n450 3 10 1 1e-3\n");
    EXPECT_EQ(energies[0].energy, 450.0);
    EXPECT_EQ(energies[0].tested, 10);
}

TEST(BreakageFit, RefusesBadTables)
{
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 10 12\n",
                  "tests.dat:2: column 'broken': 12 particles broken of 10 tested");
    expectRefusal("size velocity impacts tested broken\n1e-3 -20 1 10 1\n",
                  "tests.dat:2: column 'velocity': -20 must be >= 0");
    expectRefusal("size speed impacts tested broken\n",
                  "tests.dat:1: unknown column 'speed'; valid columns: size velocity energy impacts tested broken");
    expectRefusal("size velocity energy impacts tested broken\n", "both 'velocity' and 'energy'");
    expectRefusal("size impacts tested broken\n", "neither 'velocity' [m/s] nor 'energy'");
    expectRefusal("velocity impacts tested broken\n", "no column 'size'");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 10\n", "tests.dat:2: 4 values for 5 columns");
    expectRefusal("size velocity impacts tested broken\n1e-3 2O 1 10 1\n",
                  "tests.dat:2: column 'velocity': '2O' is not a finite number");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 0 10 1\n", "column 'impacts': 0 must be a whole number >= 1");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 10.5 1\n", "column 'tested': 10.5 must be a whole number");
    expectRefusal("size velocity impacts tested broken\n0 20 1 10 1\n", "column 'size': 0 must be > 0");
    expectRefusal("size size impacts tested broken\n", "tests.dat:1: column 'size' given twice");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 0 0\n", "column 'tested': 0 must be a whole number >= 1");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 10 -1\n", "column 'broken': -1 must be a whole number >= 0");
    expectRefusal("size energy impacts tested broken\n1e-3 -200 1 10 1\n", "column 'energy': -200 must be >= 0");
    expectRefusal("size velocity impacts tested broken\n1e-3 nan 1 10 1\n", "column 'velocity': 'nan' is not a finite number");
    expectRefusal("size velocity impacts tested broken\n1e-3 20 1 1e20 1\n", "column 'tested': 1e+20 must be a whole number >= 1 (and at most 1e+15)");
    expectRefusal("1e-3 20 1 10 1\n", "tests.dat:1: numbers before a header line");
    expectRefusal("# nothing\n", "no header line");
    expectRefusal("size velocity impacts tested broken\n", "no rows after the header");
    EXPECT_THROW(readImpactTests("no/such/impactTests.dat"), std::invalid_argument);
}

TEST(BreakageFit, RefusesDesignsItCannotFit)
{
    // one velocity for one size: fMat and the threshold trade off
    std::vector<ImpactTest> one = design(100);
    one.resize(1);
    one[0].broken = 40;
    one.push_back(one[0]);
    expectFitRefusal(one, "not identifiable");
    // nothing broke
    expectFitRefusal(design(100), "no particle broke in any test");
    // everything broke at and above the lowest x W that broke any, nothing below it
    std::vector<ImpactTest> step = design(100);
    for (ImpactTest& t : step) t.broken = t.size*t.energy > 0.3 ? t.tested : 0;
    expectFitRefusal(step, "fMat has no upper bound");
    // breakage at one x W only (the top velocity of one size): only fMat (x W - xWmMin)
    std::vector<ImpactTest> top = design(100);
    top.back().broken = 30;
    expectFitRefusal(top, "particles broke only at x W");
}

TEST(BreakageFit, RecoversTheConstantsFromExpectedCounts)
{
    // counts of 1e9 particles per row at the law's own fractions: the estimates are the
    // truth to the counts' rounding
    std::vector<ImpactTest> tests = design(1000000000L);
    for (ImpactTest& t : tests) t.broken = std::lround(t.tested*lawProbability(truth, t));
    const BreakageFitResult fit = fitVogelPeukert(tests);
    EXPECT_NEAR(fit.material.fMat, truth.fMat, 1e-5*truth.fMat);
    EXPECT_NEAR(fit.material.xWmMin, truth.xWmMin, 1e-5*truth.xWmMin);
    EXPECT_LT(fit.deviance, 1e-3);
    // with two impacts per particle: the same constants
    std::vector<ImpactTest> twice = design(1000000000L, 2);
    for (ImpactTest& t : twice) t.broken = std::lround(t.tested*lawProbability(truth, t));
    const BreakageFitResult fit2 = fitVogelPeukert(twice);
    EXPECT_NEAR(fit2.material.fMat, truth.fMat, 1e-5*truth.fMat);
    EXPECT_NEAR(fit2.material.xWmMin, truth.xWmMin, 1e-5*truth.xWmMin);
}

TEST(BreakageFit, StandardErrorsCoverTheTruth)
{
    // 1000 draws of 100 particles per row: the 95 % interval (1.96 standard errors) must
    // cover the truth 93-97 % of the time for both constants (binomial spread of the
    // fraction 0.7 %: the band is 2.9 of it; a bias of half a standard error would take
    // the coverage to 92 %, so the band bounds the bias too); the deviance, a check of
    // the law, must reject the true law at p 0.05 in 2-10 % of the draws (too few: its
    // degrees of freedom too many)
    constexpr int draws = 1000;
    std::mt19937_64 engine(20261207);
    int coverF = 0, coverC = 0, rejected = 0;
    double biasF = 0, biasC = 0;
    for (int d = 0; d < draws; ++d)
    {
        const BreakageFitResult fit = fitVogelPeukert(drawn(design(100), truth, engine));
        ASSERT_TRUE(std::isfinite(fit.fMatError) && std::isfinite(fit.xWmMinError));
        const double zF = (fit.material.fMat - truth.fMat)/fit.fMatError;
        const double zC = (fit.material.xWmMin - truth.xWmMin)/fit.xWmMinError;
        coverF += std::abs(zF) <= 1.96;
        coverC += std::abs(zC) <= 1.96;
        biasF += zF/draws;
        biasC += zC/draws;
        rejected += fit.pValue < 0.05;
    }
    std::cout << "coverage of the 95 % interval: fMat " << double(coverF)/draws
              << ", xWmMin " << double(coverC)/draws << "; mean z " << biasF << ", " << biasC
              << "; deviance p < 0.05 in " << double(rejected)/draws << " of the draws\n";
    EXPECT_GE(coverF, 930); EXPECT_LE(coverF, 970);
    EXPECT_GE(coverC, 930); EXPECT_LE(coverC, 970);
    EXPECT_GE(rejected, 20); EXPECT_LE(rejected, 100);
}

TEST(BreakageFit, TheDevianceRejectsAnotherLaw)
{
    // counts from a law Vogel-Peukert cannot follow (P rising with sqrt of the excess):
    // the deviance must reject it; the residuals are reported for each size
    std::mt19937_64 engine(7);
    std::vector<ImpactTest> tests = design(400);
    for (ImpactTest& t : tests)
    {
        const double excess = std::max(0.0, t.size*t.energy - 0.12);
        std::binomial_distribution<long> count(t.tested, -std::expm1(-1.2*std::sqrt(excess)));
        t.broken = count(engine);
    }
    const BreakageFitResult fit = fitVogelPeukert(tests);
    EXPECT_LT(fit.pValue, 1e-3) << "deviance " << fit.deviance << " on " << fit.degreesOfFreedom;
    ASSERT_EQ(fit.bySize.size(), 3u);
    for (const SizeResidual& r : fit.bySize) EXPECT_GE(r.rows, 3);
}

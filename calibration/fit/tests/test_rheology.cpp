// The rheology laws and their fit: gradients against finite differences, recovery of
// known mu(I) and phi(I) parameters from noisy synthetic cells (estimates within 3
// standard errors, over many draws the 95 % interval's coverage), the model choice
// picking the law the data were drawn from, the muI dictionary entries, and refusals.
#include "fit/RheologyLaws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

using namespace sdf::fit;

namespace
{

Condition atI(double I)
{
    Condition c;
    c.phi = 0.58; c.T = 1e-3; c.d = 1.5e-3; c.inertialNumber = I;
    return c;
}

template<class Law>
void checkGradient(const Law& law, const Eigen::VectorXd& p, double I)
{
    const Eigen::VectorXd g = law.gradient(atI(I), p);
    for (int k = 0; k < p.size(); ++k)
    {
        const double h = 1e-6*std::max(1.0, std::abs(p[k]));
        Eigen::VectorXd up = p, down = p;
        up[k] += h; down[k] -= h;
        const double fd = (law.evaluate(atI(I), up) - law.evaluate(atI(I), down))/(2*h);
        EXPECT_NEAR(g[k], fd, 1e-6*std::max(1.0, std::abs(fd))) << law.name() << " parameter " << k;
    }
}

//- Cells at 8 I from 0.003 to 0.5 (log spaced) drawn from mu = Jop(0.38, 0.64, 0.28) and
//  phi = 0.60 - 0.2 I with Gaussian errors sigmaMu, sigmaPhi.
std::vector<RheologyPoint> synthetic(std::mt19937_64& rng, double sigmaMu, double sigmaPhi)
{
    std::normal_distribution<double> unit;
    std::vector<RheologyPoint> points;
    for (int k = 0; k < 8; ++k)
    {
        const double I = 0.003*std::pow(0.5/0.003, k/7.0);
        RheologyPoint q;
        q.inertialNumber = I;
        q.stressRatio = 0.38 + (0.64 - 0.38)/(0.28/I + 1) + sigmaMu*unit(rng);
        q.stressRatioError = sigmaMu;
        q.solidsFraction = 0.60 - 0.2*I + sigmaPhi*unit(rng);
        q.solidsFractionError = sigmaPhi;
        q.meanDiameter = 1.5e-3;
        q.temperature = 1e-3;
        points.push_back(q);
    }
    return points;
}

} // namespace

TEST(Rheology, GradientsMatchFiniteDifferences)
{
    Eigen::VectorXd jop(3), power(3), linear(2), phiPower(3);
    jop << 0.38, 0.64, 0.28;
    power << 0.35, 0.4, 0.6;
    linear << 0.6, 0.2;
    phiPower << 0.6, 0.2, 0.8;
    for (const double I : {1e-3, 0.05, 0.7})
    {
        checkGradient(JopMuILaw{}, jop, I);
        checkGradient(PowerMuILaw{}, power, I);
        checkGradient(LinearPhiILaw{}, linear, I);
        checkGradient(PowerPhiILaw{}, phiPower, I);
    }
}

// One draw: every parameter within 3 of its standard errors, muI preferred by AIC; over
// 200 draws the 95 % interval covers the true mu_s, I_0 and phi_c in 90-99 % of them.
TEST(Rheology, RecoversKnownParametersWithHonestErrors)
{
    std::mt19937_64 rng(11);
    const RheologyFit one = fitRheology(synthetic(rng, 0.005, 0.001));
    EXPECT_NEAR(one.muI().parameter("mu_s").value, 0.38, 3*one.muI().parameter("mu_s").standardError);
    EXPECT_NEAR(one.muI().parameter("mu_d").value, 0.64, 3*one.muI().parameter("mu_d").standardError);
    EXPECT_NEAR(one.muI().parameter("I_0").value, 0.28, 3*one.muI().parameter("I_0").standardError);
    EXPECT_NEAR(one.phiILinear().parameter("phi_c").value, 0.60, 3*one.phiILinear().parameter("phi_c").standardError);
    EXPECT_NEAR(one.phiILinear().parameter("a").value, 0.2, 3*one.phiILinear().parameter("a").standardError);
    EXPECT_DOUBLE_EQ(one.inertialNumbers.min, 0.003);
    EXPECT_DOUBLE_EQ(one.inertialNumbers.max, 0.5);

    int covered[3] = {0, 0, 0}, draws = 200, fitted = 0;
    for (int k = 0; k < draws; ++k)
    {
        const RheologyFit f = fitRheology(synthetic(rng, 0.005, 0.001));
        ++fitted;
        const auto within = [](const FittedParameter& p, double truth)
        {
            return std::abs(p.value - truth) <= 1.96*p.standardError;
        };
        covered[0] += within(f.muI().parameter("mu_s"), 0.38);
        covered[1] += within(f.muI().parameter("I_0"), 0.28);
        covered[2] += within(f.phiILinear().parameter("phi_c"), 0.60);
    }
    std::printf("95 %% interval coverage over %d draws: mu_s %.3f, I_0 %.3f, phi_c %.3f\n",
                fitted, double(covered[0])/fitted, double(covered[1])/fitted, double(covered[2])/fitted);
    for (int c : covered)
    {
        // the relative-sigma errors use the chi-square of 8 - 3 points: coverage of the
        // normal 1.96 below 95 % (Student t of 5 degrees: 2.57 for 95 %)
        EXPECT_GE(double(c)/fitted, 0.80);
        EXPECT_LE(double(c)/fitted, 0.99);
    }
}

// Cells drawn from the power law (mu_s 0.3, a 0.5, n 0.6): AIC prefers muIPower.
TEST(Rheology, ModelChoiceFindsTheLawTheDataCameFrom)
{
    std::vector<RheologyPoint> points;
    for (int k = 0; k < 10; ++k)
    {
        const double I = 1e-3*std::pow(1000.0, k/9.0);
        RheologyPoint q;
        q.inertialNumber = I;
        q.stressRatio = 0.3 + 0.5*std::pow(I, 0.6) + 1e-4*((k % 3) - 1);
        q.stressRatioError = 1e-4;
        q.solidsFraction = 0.6 - 0.1*std::pow(I, 0.7) + 1e-5*((k % 2) - 0.5);
        q.solidsFractionError = 1e-5;
        q.meanDiameter = 1e-3;
        q.temperature = 1e-3;
        points.push_back(q);
    }
    const RheologyFit f = fitRheology(points);
    EXPECT_EQ(f.muSelection.best().law, "muIPower");
    EXPECT_EQ(f.phiSelection.best().law, "phiIPower");
}

TEST(Rheology, DictionaryEntriesAndRefusals)
{
    std::mt19937_64 rng(3);
    const RheologyFit f = fitRheology(synthetic(rng, 0.005, 0.001));
    const std::string text = muICoefficientEntries(f);
    for (const char* name : {"mu_s ", "mu_d ", "I_0 ", "packedFraction "})
    {
        EXPECT_NE(text.find(name), std::string::npos) << name << " in\n" << text;
    }
    EXPECT_NE(text.find("fitted on 8 DEM cells over I 0.003 - 0.5"), std::string::npos) << text;

    std::vector<RheologyPoint> few = synthetic(rng, 0.005, 0.001);
    few.resize(3);
    try { fitRheology(few); FAIL() << "3 cells accepted"; }
    catch (const std::invalid_argument& e) { EXPECT_NE(std::string(e.what()).find("needs at least 4"), std::string::npos) << e.what(); }
    std::vector<RheologyPoint> bad = synthetic(rng, 0.005, 0.001);
    bad[2].inertialNumber = -0.1;
    try { fitRheology(bad); FAIL() << "I < 0 accepted"; }
    catch (const std::invalid_argument& e) { EXPECT_NE(std::string(e.what()).find("inertialNumber"), std::string::npos) << e.what(); }
}

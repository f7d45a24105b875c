// The segregation laws and their fit: gradients against finite differences, recovery of
// known parameters from noisy synthetic cells (within 3 standard errors), the model
// choice picking the law the data were drawn from (pressure-dependent or not, symmetric
// or asymmetric in c), C = D/(gammaDot dMean^2), the dictionary entries, and refusals.
#include "fit/SegregationLaws.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sdf::fit;

namespace
{

Condition at(double pStar, double R, double c)
{
    Condition q;
    q.phi = 0.58; q.x = c; q.d = 1e-3; q.pressureNumber = pStar; q.sizeRatio = R;
    return q;
}

template<class Law>
void checkGradient(const Law& law, const Eigen::VectorXd& p)
{
    for (const Condition& c : {at(3, 2, 0.5), at(150, 1.5, 0.2), at(20, 3, 0.8)})
    {
        const Eigen::VectorXd g = law.gradient(c, p);
        for (int k = 0; k < p.size(); ++k)
        {
            const double h = 1e-7*std::max(1.0, std::abs(p[k]));
            Eigen::VectorXd up = p, down = p;
            up[k] += h; down[k] -= h;
            const double fd = (law.evaluate(c, up) - law.evaluate(c, down))/(2*h);
            EXPECT_NEAR(g[k], fd, 1e-6*std::max(1e-9, std::abs(fd))) << law.name() << " parameter " << k;
        }
    }
}

//- Cells at p* 2-500 (log spaced), each size ratio and share given, S drawn from law
//  with parameters p and a 5 % Gaussian error; C = D/(gammaDot dMean^2) 0.05 with 3 %.
template<class Law>
std::vector<SegregationPoint> synthetic
(
    std::mt19937_64& rng, const Law& law, const Eigen::VectorXd& p,
    const std::vector<double>& ratios, const std::vector<double>& shares
)
{
    std::normal_distribution<double> unit;
    std::vector<SegregationPoint> points;
    for (double R : ratios)
    {
        for (double c : shares)
        {
            for (int k = 0; k < 6; ++k)
            {
                const double pStar = 2*std::pow(250.0, k/5.0);
                const double S = law.evaluate(at(pStar, R, c), p);
                SegregationPoint q;
                q.fineDiameter = 1e-3; q.sizeRatio = R; q.coarseShare = c; q.solidsFraction = 0.58;
                q.pressureNumber = pStar; q.inertialNumber = 0.05; q.shearRate = 10;
                q.percolationLength = S*(1 + 0.05*unit(rng));
                q.percolationLengthError = 0.05*S;
                q.shearRateDiffusivity = 0.05*(1 + 0.03*unit(rng));
                q.shearRateDiffusivityError = 0.03*0.05;
                points.push_back(q);
            }
        }
    }
    return points;
}

void expectRecovered(const FitResult& f, const Eigen::VectorXd& truth)
{
    ASSERT_TRUE(f.converged()) << f.message;
    for (int k = 0; k < truth.size(); ++k)
    {
        const FittedParameter& q = f.parameters[std::size_t(k)];
        EXPECT_LT(std::abs(q.value - truth[k]), 3*q.standardError + 1e-12)
            << f.law.name() << " " << q.name << " " << q.value << " +- " << q.standardError << " vs " << truth[k];
    }
}

} // namespace

TEST(SegregationLaws, GradientsMatchFiniteDifferences)
{
    checkGradient(FanSchlickLaw{}, Eigen::VectorXd::Constant(1, 0.26));
    Eigen::VectorXd t(2);
    t << 0.4, 0.8;
    checkGradient(TrewhelaLaw{}, t);
    Eigen::VectorXd a(3);
    a << 0.4, 0.8, 1.5;
    checkGradient(TrewhelaAsymmetricLaw{}, a);
}

TEST(SegregationLaws, EqualSizesDoNotSegregate)
{
    Eigen::VectorXd a(3);
    a << 0.4, 0.8, 1.5;
    EXPECT_EQ(FanSchlickLaw{}.evaluate(at(10, 1, 0.5), Eigen::VectorXd::Constant(1, 0.26)), 0.0);
    EXPECT_EQ(TrewhelaAsymmetricLaw{}.evaluate(at(10, 1, 0.5), a), 0.0);
}

TEST(SegregationLaws, PressureLawRecoveredAndChosen)
{
    std::mt19937_64 rng(7);
    Eigen::VectorXd truth(2);
    truth << 2.0, 5.0;    // S falls fivefold from p* 5 to p* 45
    const SegregationFit fit = fitSegregation(synthetic(rng, TrewhelaLaw{}, truth, {2.0}, {0.5}));
    ASSERT_EQ(fit.fits.size(), 2u) << "c and R fixed: no asymmetric fit";
    expectRecovered(fit.fits[1], truth);
    EXPECT_EQ(fit.best().law.name(), "trewhela");
    EXPECT_GT(fit.selection.ranking.back().delta, 10) << segregationFitSummary(fit);
    EXPECT_NEAR(fit.diffusivityCoefficient, 0.05, 3*fit.diffusivityCoefficientError);
    EXPECT_LT(fit.diffusivityCoefficientError, 0.002);
    const std::string entries = segregationVelocityEntries(fit);
    EXPECT_NE(entries.find("law             trewhela;"), std::string::npos) << entries;
    EXPECT_NE(entries.find("pStarRange      (2 500);"), std::string::npos) << entries;
    EXPECT_NE(entries.find("shearRateDiffusivity"), std::string::npos) << entries;
}

TEST(SegregationLaws, PressureIndependentDataChooseFanSchlick)
{
    std::mt19937_64 rng(11);
    const Eigen::VectorXd truth = Eigen::VectorXd::Constant(1, 0.16);
    const SegregationFit fit = fitSegregation(synthetic(rng, FanSchlickLaw{}, truth, {1.5, 2.0, 3.0}, {0.5}));
    expectRecovered(fit.fits[0], truth);
    EXPECT_EQ(fit.best().law.name(), "fanSchlick") << segregationFitSummary(fit);
}

TEST(SegregationLaws, AsymmetryRecoveredAndChosen)
{
    std::mt19937_64 rng(13);
    Eigen::VectorXd truth(3);
    truth << 2.0, 5.0, 1.5;
    const SegregationFit fit =
        fitSegregation(synthetic(rng, TrewhelaAsymmetricLaw{}, truth, {1.5, 2.0, 3.0}, {0.2, 0.5, 0.8}));
    ASSERT_EQ(fit.fits.size(), 3u);
    expectRecovered(fit.fits[2], truth);
    EXPECT_EQ(fit.best().law.name(), "trewhelaAsymmetric") << segregationFitSummary(fit);
}

TEST(SegregationLaws, BadInputRefusedByName)
{
    std::mt19937_64 rng(1);
    Eigen::VectorXd truth(2);
    truth << 2.0, 5.0;
    std::vector<SegregationPoint> points = synthetic(rng, TrewhelaLaw{}, truth, {2.0}, {0.5});
    const auto refusal = [&](std::vector<SegregationPoint> bad, const std::string& word)
    {
        try
        {
            fitSegregation(bad);
            ADD_FAILURE() << "accepted: " << word;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        }
    };
    refusal({points[0], points[1]}, "at least 3");
    std::vector<SegregationPoint> bad = points;
    bad[2].pressureNumber = 0;
    refusal(bad, "pressureNumber");
    bad = points;
    bad[1].sizeRatio = 0.5;
    refusal(bad, "sizeRatio");
    bad = points;
    bad[3].percolationLengthError = 0;
    refusal(bad, "percolationLengthError");
    bad = points;
    bad[0].shearRate = 0;
    refusal(bad, "shearRate");
}

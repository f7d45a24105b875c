// Recovery: synthetic data from known parameters over a seed-like envelope
// with 3 % multiplicative noise; every parameter must come back within 3 of
// its reported standard errors, and the goodness of fit must say the law fits.
#include "SyntheticData.hpp"

#include "fit/BreakageRate.hpp"
#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace sdf::fit;
using sdf::fit::test::seedLikeEnvelope;
using sdf::fit::test::synthetic;

namespace
{

constexpr double noise = 0.03;

FitResult expectRecovered
(
    const ConstitutiveLaw& law,
    const Eigen::VectorXd& truth,
    std::uint64_t seed,
    const FitOptions& options = FitOptions()
)
{
    std::mt19937_64 engine(seed);
    const std::vector<Observation> data = synthetic(law, truth, seedLikeEnvelope(), noise, engine);
    const FitResult fit = fitLaw(law, data, options);
    EXPECT_TRUE(fit.converged()) << fit.message;
    EXPECT_EQ(fit.points, data.size());
    EXPECT_GT(fit.iterations, 0u);
    EXPECT_GT(fit.rSquared, 0.99);
    // 120 rows: reduced chi-square of a right law with right sigma is 1 +- 0.13.
    EXPECT_GT(fit.reducedChiSquare, 0.6);
    EXPECT_LT(fit.reducedChiSquare, 1.4);
    EXPECT_EQ(fit.residuals.size(), data.size());
    EXPECT_EQ(fit.normalisedResiduals.size(), data.size());
    for (std::size_t j = 0; j < fit.parameters.size(); ++j)
    {
        const FittedParameter& p = fit.parameters[j];
        EXPECT_GT(p.standardError, 0.0) << p.name;
        EXPECT_LT(std::abs(p.value - truth(j)), 3.0 * p.standardError)
            << law.name() << " " << p.name << " = " << p.value << " +- " << p.standardError
            << ", true " << truth(j);
        std::cout << "  " << law.name() << " " << p.name << ": " << p.value << " +- "
                  << p.standardError << " (true " << truth(j) << ", "
                  << (p.value - truth(j)) / p.standardError << " sigma)\n";
    }
    std::cout << "  R2 " << fit.rSquared << ", reduced chi2 " << fit.reducedChiSquare
              << ", AIC " << fit.aic << ", iterations " << fit.iterations << "\n";
    return fit;
}

} // namespace

TEST(Recovery, SeedPowerLawInLogSpace)
{
    Eigen::VectorXd truth(4);
    truth << 6.0, 1.0, 1.0, -1.5;
    const FitResult fit = expectRecovered(SeedPowerLaw{}, truth, 11);
    // The envelope of the test: the data's own ranges.
    EXPECT_DOUBLE_EQ(fit.envelope.phi.min, 0.1);
    EXPECT_DOUBLE_EQ(fit.envelope.phi.max, 0.5);
    EXPECT_DOUBLE_EQ(fit.envelope.x.min, 0.2);
    EXPECT_DOUBLE_EQ(fit.envelope.T.max, 0.1);
    EXPECT_FALSE(fit.envelope.gammaDot.has_value());
}

TEST(Recovery, SeedPowerLawInLinearSpaceFromAFarStart)
{
    Eigen::VectorXd truth(4), start(4);
    truth << 6.0, 1.0, 1.0, -1.5;
    start << 1.0, 0.0, 0.8, -1.0;   // the linearised start is not used here
    FitOptions options;
    options.space = FitSpace::linear;
    options.initialParameters = start;
    const FitResult fit = expectRecovered(SeedPowerLaw{}, truth, 12, options);
    EXPECT_GT(fit.iterations, 3u);
}

TEST(Recovery, KineticTheoryGroups)
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    expectRecovered(KineticTheoryGroupsLaw{}, truth, 13);
}

TEST(Recovery, KineticTheoryGroupsAtTheChapmanEnskogPoint)
{
    Eigen::VectorXd truth(2);
    truth << std::sqrt(M_PI) / 16.0, 0.0;
    expectRecovered(KineticTheoryGroupsLaw{}, truth, 14);
}

TEST(Recovery, SievingPowerLaw)
{
    Eigen::VectorXd truth(3);
    truth << 0.5, -1.2, 2.0;
    expectRecovered(SievingPowerLaw{}, truth, 15);
    expectRecovered(SievingPowerLaw{2}, truth, 16);
}

TEST(Recovery, SievingCompositionPowerLaw)
{
    // q = 3.3: the engine's eta of the coarse grows about tenfold from x 0.2 to 0.4
    Eigen::VectorXd truth(3);
    truth << 0.05, -1.2, 3.3;
    expectRecovered(SievingCompositionPowerLaw{}, truth, 18);
    expectRecovered(SievingCompositionPowerLaw{2}, truth, 19);
}

TEST(Recovery, AbsoluteSigmaGiveUnscaledErrors)
{
    Eigen::VectorXd truth(3);
    truth << 0.5, -1.2, 2.0;
    std::mt19937_64 engine(17);
    const auto data = synthetic(SievingPowerLaw{}, truth, seedLikeEnvelope(), noise, engine);
    FitOptions absolute;
    absolute.sigmaMeaning = SigmaMeaning::absolute;
    const FitResult a = fitLaw(SievingPowerLaw{}, data, absolute);
    const FitResult r = fitLaw(SievingPowerLaw{}, data);
    ASSERT_TRUE(a.converged() && r.converged());
    // Same minimum; errors differ exactly by sqrt(reduced chi-square).
    for (std::size_t j = 0; j < 3; ++j)
    {
        EXPECT_NEAR(a.parameters[j].value, r.parameters[j].value, 1e-8);
        EXPECT_NEAR
        (
            r.parameters[j].standardError / a.parameters[j].standardError,
            std::sqrt(r.reducedChiSquare), 1e-8
        );
    }
    EXPECT_NEAR(a.aic, a.chiSquare + 6.0, 1e-9);
}

// The breakage-rate laws: collision frequency per particle and mean mass-specific impact
// energy, each recovered from its own noisy table; then the Vogel-Peukert rate of an
// exponential spectrum (fit/BreakageRate.hpp) evaluated from the two fitted laws must
// match the rate from the true laws within 5 % at the envelope's corners for a material
// whose threshold is twice the mean impact energy (the error of S is the frequency's
// plus 1 + Wmin/Wmean = 3 times the mean energy's, each ~0.5-1 % at a corner).
namespace
{
Eigen::VectorXd collisionFrequencyTruth()
{
    // Enskog's C = 13.54, b = 1 bent towards a dense inelastic cell
    Eigen::VectorXd truth(3);
    truth << 12.0, 1.3, 0.4;
    return truth;
}

Eigen::VectorXd impactEnergyTruth()
{
    // Maxwell-Boltzmann's K = 1/2, c = 0 bent likewise
    Eigen::VectorXd truth(2);
    truth << 0.42, 0.15;
    return truth;
}
} // namespace

TEST(Recovery, CollisionFrequencyGroups)
{
    expectRecovered(CollisionFrequencyGroupsLaw{}, collisionFrequencyTruth(), 21);
}

TEST(Recovery, ImpactEnergyGroups)
{
    expectRecovered(ImpactEnergyGroupsLaw{}, impactEnergyTruth(), 22);
}

TEST(Recovery, BreakageRateFromTheFittedLaws)
{
    using namespace sdf::fit::breakage;
    const FitResult frequency =
        expectRecovered(CollisionFrequencyGroupsLaw{}, collisionFrequencyTruth(), 23);
    const FitResult energy = expectRecovered(ImpactEnergyGroupsLaw{}, impactEnergyTruth(), 24);
    double worst = 0;
    for (const double phi : {0.1, 0.5})
    {
        for (const double T : {1e-3, 1e-1})
        {
            const Condition c{phi, 0.3, T, 1e-3, std::nullopt, std::nullopt};
            const double omegaTrue = CollisionFrequencyGroupsLaw{}.evaluate(c, collisionFrequencyTruth());
            const double WmeanTrue = ImpactEnergyGroupsLaw{}.evaluate(c, impactEnergyTruth());
            // fMat 2 kg/(J m) and a threshold of twice the state's true mean impact
            // energy: a material at the onset of breakage there
            const VogelPeukertMaterial material{2.0, 2*WmeanTrue*c.d};
            const double fitted = vogelPeukertRateExponentialSpectrum
            (
                material, c.d, frequency.evaluate(c), energy.evaluate(c)
            );
            const double exact = vogelPeukertRateExponentialSpectrum(material, c.d, omegaTrue, WmeanTrue);
            ASSERT_GT(exact, 0.0);
            worst = std::max(worst, std::abs(fitted / exact - 1.0));
            EXPECT_NEAR(fitted / exact, 1.0, 0.05) << "phi " << phi << ", T " << T;
            std::cout << "  phi " << phi << " T " << T << ": S = " << fitted << " 1/s (true "
                      << exact << ")\n";
        }
    }
    std::cout << "  largest relative error of S: " << worst << "\n";
}

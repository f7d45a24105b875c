// The laws themselves: the seed's numbers, the Chapman-Enskog limit, and
// analytic gradients against central finite differences.
#include "fit/ConstitutiveLaw.hpp"
#include "fit/LawFormulas.hpp"
#include "fit/Laws.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::fit;

TEST(Laws, SeedPowerLawWithThePapersValuesIsEq15)
{
    Eigen::VectorXd p(4);
    p << 6.0, 1.0, 1.0, -1.5;
    const Condition c{0.3, 0.2, 0.05, 1e-3, std::nullopt, std::nullopt};
    EXPECT_NEAR(SeedPowerLaw{}.evaluate(c, p), 6.0 * 1.2 * 0.05 * std::pow(0.3, -1.5), 1e-14);
}

TEST(Laws, KineticTheoryGroupsReducesToChapmanEnskog)
{
    // Validation item 11: D_E = d sqrt(pi T1)/(16 phi g0), T1 = T/3.
    Eigen::VectorXd p(2);
    p << std::sqrt(M_PI) / 16.0, 0.0;
    for (const double phi : {0.05, 0.3, 0.55})
    {
        const Condition c{phi, 0.4, 0.03, 2e-3, std::nullopt, std::nullopt};
        const double g0 = (1.0 - phi / 2.0) / std::pow(1.0 - phi, 3);
        const double enskog = 2e-3 * std::sqrt(M_PI * 0.03 / 3.0) / (16.0 * phi * g0);
        EXPECT_NEAR(KineticTheoryGroupsLaw{}.evaluate(c, p) / enskog, 1.0, 1e-13);
    }
    EXPECT_NEAR(carnahanStarlingG0(0.0), 1.0, 1e-15);
    EXPECT_NEAR(carnahanStarlingG0(0.5), 0.75 / 0.125, 1e-12);
}

TEST(Laws, SievingPowerLawUnitsFollowTheDiameterPower)
{
    Eigen::VectorXd p(3);
    p << 0.7, -1.2, 0.5;
    const Condition c{0.4, 0.2, 0.3, 3e-3, std::nullopt, std::nullopt};
    const double common = 0.7 * std::sqrt(0.1) * std::pow(0.4, -1.2) * 1.1;
    EXPECT_NEAR(SievingPowerLaw{}.evaluate(c, p), common * 3e-3, 1e-15);
    EXPECT_NEAR(SievingPowerLaw{2}.evaluate(c, p), common * 9e-6, 1e-18);
    ASSERT_EQ(SievingPowerLaw{2}.fixedEntries().size(), 1u);
    EXPECT_EQ(SievingPowerLaw{2}.fixedEntries()[0].first, "diameterPower");
    EXPECT_EQ(SievingPowerLaw{2}.fixedEntries()[0].second, 2.0);
}

namespace
{
void expectGradientMatchesFiniteDifferences(const ConstitutiveLaw& law, Eigen::VectorXd p)
{
    for (const Condition& c :
         {Condition{0.15, 0.2, 2e-3, 1e-3, std::nullopt, std::nullopt},
          Condition{0.45, 0.4, 8e-2, 4e-3, std::nullopt, std::nullopt}})
    {
        const Eigen::VectorXd analytic = law.gradient(c, p);
        ASSERT_EQ(analytic.size(), p.size());
        for (Eigen::Index j = 0; j < p.size(); ++j)
        {
            const double h = 1e-6 * std::max(1.0, std::abs(p(j)));
            Eigen::VectorXd up = p, down = p;
            up(j) += h;
            down(j) -= h;
            const double numeric = (law.evaluate(c, up) - law.evaluate(c, down)) / (2.0 * h);
            EXPECT_NEAR(analytic(j), numeric, 1e-7 * std::abs(numeric) + 1e-300)
                << law.name() << " parameter " << law.parameterNames()[j];
        }
    }
}
} // namespace

TEST(Laws, AnalyticGradientsMatchFiniteDifferences)
{
    Eigen::VectorXd seed(4), kinetic(2), sieving(3);
    seed << 6.0, 1.0, 1.0, -1.5;
    kinetic << 0.11, 0.6;
    sieving << 0.8, -0.7, 0.3;
    expectGradientMatchesFiniteDifferences(SeedPowerLaw{}, seed);
    expectGradientMatchesFiniteDifferences(KineticTheoryGroupsLaw{}, kinetic);
    expectGradientMatchesFiniteDifferences(SievingPowerLaw{}, sieving);
    expectGradientMatchesFiniteDifferences(SievingPowerLaw{2}, sieving);
    expectGradientMatchesFiniteDifferences(SievingCompositionPowerLaw{}, sieving);
    expectGradientMatchesFiniteDifferences(SievingCompositionPowerLaw{2}, sieving);
    Eigen::VectorXd frequency(3), energy(2);
    frequency << 12.0, 1.3, 0.4;
    energy << 0.45, 0.2;
    expectGradientMatchesFiniteDifferences(CollisionFrequencyGroupsLaw{}, frequency);
    expectGradientMatchesFiniteDifferences(ImpactEnergyGroupsLaw{}, energy);
}

TEST(Laws, CollisionFrequencyGroupsReducesToEnskog)
{
    // dem.kinetic_theory's omega_E = 4 n d^2 g0 sqrt(pi T1), n = 6 phi/(pi d^3)
    Eigen::VectorXd p(3);
    p << 24.0 / std::sqrt(M_PI), 1.0, 0.0;
    for (const double phi : {0.05, 0.3, 0.55})
    {
        const double d = 2e-3, T = 0.03;
        const Condition c{phi, 0.4, T, d, std::nullopt, std::nullopt};
        const double n = 6.0 * phi / (M_PI * d * d * d);
        const double enskog = 4.0 * n * d * d * carnahanStarlingG0(phi) * std::sqrt(M_PI * T / 3.0);
        EXPECT_NEAR(CollisionFrequencyGroupsLaw{}.evaluate(c, p) / enskog, 1.0, 1e-13);
    }
    EXPECT_EQ(ConstitutiveLaw(CollisionFrequencyGroupsLaw{}).name(), "collisionFrequencyGroups");
}

TEST(Laws, ImpactEnergyGroupsIsHalfT1ForAMaxwellianGas)
{
    // <E> = m T1 for equal grains (dem.impact_energy), W = E/(2 m): Wmean = T1/2
    Eigen::VectorXd p(2);
    p << 0.5, 0.0;
    const Condition c{0.05, 0.0, 0.3, 1e-3, std::nullopt, std::nullopt};
    EXPECT_NEAR(ImpactEnergyGroupsLaw{}.evaluate(c, p), 0.05, 1e-15);
    p << 0.4, -0.5;
    EXPECT_NEAR(ImpactEnergyGroupsLaw{}.evaluate(c, p), 0.4 * 0.1 / std::sqrt(0.05), 1e-14);
    EXPECT_EQ(ConstitutiveLaw(ImpactEnergyGroupsLaw{}).name(), "impactEnergyGroups");
}

TEST(Laws, SievingCompositionPowerLawHandValue)
{
    Eigen::VectorXd p(3);
    p << 0.7, -1.2, 3.3;
    const Condition c{0.4, 0.2, 0.3, 3e-3, std::nullopt, std::nullopt};
    const double expected = 0.7 * 3e-3 * std::sqrt(0.1) * std::pow(0.4, -1.2) * std::pow(0.2, 3.3);
    EXPECT_NEAR(SievingCompositionPowerLaw{}.evaluate(c, p) / expected, 1.0, 1e-13);
    EXPECT_EQ(ConstitutiveLaw(SievingCompositionPowerLaw{}).name(), "sievingCompositionPowerLaw");
    EXPECT_EQ(SievingCompositionPowerLaw{}.parameterNames()[2], "q");
}

TEST(Laws, TypeErasedLawKeepsNamesAndCopies)
{
    const ConstitutiveLaw law = SeedPowerLaw{};
    const ConstitutiveLaw copy = law;
    EXPECT_EQ(copy.name(), "powerLaw");
    EXPECT_EQ(copy.parameterCount(), 4u);
    EXPECT_EQ(copy.parameterNames()[3], "b");
    EXPECT_EQ(ConstitutiveLaw(KineticTheoryGroupsLaw{}).name(), "kineticTheoryGroups");
    EXPECT_EQ(ConstitutiveLaw(SievingPowerLaw{}).name(), "sievingPowerLaw");
}

TEST(Laws, LawFromNameBuildsEveryLawAndRefusesOthers)
{
    for (const std::string& name : lawNames())
    {
        EXPECT_EQ(lawFromName(name, 2).name(), name);
    }
    Eigen::VectorXd p(3);
    p << 0.7, -1.2, 3.3;
    const Condition c{0.4, 0.2, 0.3, 3e-3, std::nullopt, std::nullopt};
    EXPECT_EQ(lawFromName("sievingPowerLaw", 2).evaluate(c, p), SievingPowerLaw{2}.evaluate(c, p));
    try
    {
        lawFromName("magic");
        ADD_FAILURE() << "an unknown law was built";
    }
    catch (const std::invalid_argument& e)
    {
        const std::string what = e.what();
        EXPECT_NE(what.find("magic"), std::string::npos) << what;
        EXPECT_NE(what.find("kineticTheoryGroups"), std::string::npos) << what;
    }
}

TEST(Laws, FormulasAreTheLawsEvaluations)
{
    // The header-only formulas (used by the solver's models) and the fitted
    // laws are one definition: bitwise equal
    const Condition c{0.45, 0.3, 0.02, 2e-3, std::nullopt, std::nullopt};
    Eigen::VectorXd seed(4), kinetic(2), sieving(3);
    seed << 6.0, 1.0, 1.0, -1.5;
    kinetic << 0.12, 0.4;
    sieving << 0.8, -0.7, 0.3;
    EXPECT_EQ(SeedPowerLaw{}.evaluate(c, seed), formulas::powerLaw(6, 1, 1, -1.5, c.phi, c.x, c.T));
    EXPECT_EQ
    (
        KineticTheoryGroupsLaw{}.evaluate(c, kinetic),
        formulas::kineticTheoryGroups(0.12, 0.4, c.phi, c.x, c.T, c.d)
    );
    EXPECT_EQ
    (
        SievingPowerLaw{1}.evaluate(c, sieving),
        formulas::sievingPowerLaw(0.8, 1, -0.7, 0.3, c.phi, c.x, c.T, c.d)
    );
    EXPECT_EQ
    (
        SievingCompositionPowerLaw{2}.evaluate(c, sieving),
        formulas::sievingCompositionPowerLaw(0.8, 2, -0.7, 0.3, c.phi, c.x, c.T, c.d)
    );
    EXPECT_EQ(carnahanStarlingG0(c.phi), formulas::carnahanStarlingG0(c.phi));
    Eigen::VectorXd frequency(3), energy(2);
    frequency << 12.0, 1.3, 0.4;
    energy << 0.45, 0.2;
    EXPECT_EQ
    (
        CollisionFrequencyGroupsLaw{}.evaluate(c, frequency),
        formulas::collisionFrequencyGroups(12.0, 1.3, 0.4, c.phi, c.x, c.T, c.d)
    );
    EXPECT_EQ
    (
        ImpactEnergyGroupsLaw{}.evaluate(c, energy),
        formulas::impactEnergyGroups(0.45, 0.2, c.phi, c.T)
    );
}

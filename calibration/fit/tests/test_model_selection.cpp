// Model selection picks the law that generated the data, by a clear margin,
// with both criteria, and refuses to compare fits of different tables.
#include "SyntheticData.hpp"

#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace sdf::fit;
using sdf::fit::test::seedLikeEnvelope;
using sdf::fit::test::seedPowerLawData;
using sdf::fit::test::synthetic;

namespace
{

ModelSelection selectBetweenTheDiffusivityLaws
(
    const std::vector<Observation>& data,
    InformationCriterion criterion
)
{
    const std::vector<FitResult> fits =
    {
        fitLaw(SeedPowerLaw{}, data),
        fitLaw(KineticTheoryGroupsLaw{}, data)
    };
    const ModelSelection s = selectModel(fits, criterion);
    for (const RankedLaw& r : s.ranking)
    {
        std::cout << "  " << toString(criterion) << " " << r.law << ": " << r.criterion
                  << " delta " << r.delta << " weight " << r.weight << "\n";
    }
    return s;
}

} // namespace

TEST(ModelSelection, PicksKineticTheoryWhenItGeneratedTheData)
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    std::mt19937_64 engine(21);
    const auto data = synthetic(KineticTheoryGroupsLaw{}, truth, seedLikeEnvelope(), 0.03, engine);
    for (const auto criterion : {InformationCriterion::AIC, InformationCriterion::BIC})
    {
        const ModelSelection s = selectBetweenTheDiffusivityLaws(data, criterion);
        ASSERT_EQ(s.ranking.size(), 2u);
        EXPECT_TRUE(s.failed.empty());
        EXPECT_EQ(s.best().law, "kineticTheoryGroups");
        EXPECT_EQ(s.best().index, 1u);
        EXPECT_EQ(s.best().delta, 0.0);
        EXPECT_GT(s.ranking[1].delta, 10.0);
        EXPECT_NEAR(s.ranking[0].weight + s.ranking[1].weight, 1.0, 1e-12);
        EXPECT_GT(s.ranking[0].weight, 0.99);
    }
}

TEST(ModelSelection, PicksTheSeedPowerLawWhenItGeneratedTheData)
{
    const auto data = seedPowerLawData(22);
    for (const auto criterion : {InformationCriterion::AIC, InformationCriterion::BIC})
    {
        const ModelSelection s = selectBetweenTheDiffusivityLaws(data, criterion);
        EXPECT_EQ(s.best().law, "powerLaw");
        EXPECT_GT(s.ranking[1].delta, 10.0);
    }
}

TEST(ModelSelection, CriteriaAreTheDocumentedFormulas)
{
    // Relative sigma: the common scale is estimated, so k + 1 parameters.
    const auto data = seedPowerLawData(23);
    const FitResult fit = fitLaw(SeedPowerLaw{}, data);
    ASSERT_TRUE(fit.converged());
    const double n = double(data.size());
    EXPECT_NEAR(fit.aic, n * std::log(fit.chiSquare / n) + 2.0 * 5.0, 1e-9);
    EXPECT_NEAR(fit.bic, n * std::log(fit.chiSquare / n) + 5.0 * std::log(n), 1e-9);
}

TEST(ModelSelection, FailedFitsAreListedNotRanked)
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    std::mt19937_64 engine(24);
    const auto data = synthetic(KineticTheoryGroupsLaw{}, truth, seedLikeEnvelope(), 0.03, engine);
    FitOptions oneIteration;
    oneIteration.maxIterations = 1;
    Eigen::VectorXd farStart(4);
    farStart << 1.0, 0.0, 0.0, 0.0;
    oneIteration.initialParameters = farStart;
    const std::vector<FitResult> fits =
    {
        fitLaw(SeedPowerLaw{}, data, oneIteration),
        fitLaw(KineticTheoryGroupsLaw{}, data)
    };
    ASSERT_FALSE(fits[0].converged());
    const ModelSelection s = selectModel(fits);
    ASSERT_EQ(s.ranking.size(), 1u);
    EXPECT_EQ(s.best().law, "kineticTheoryGroups");
    ASSERT_EQ(s.failed.size(), 1u);
    EXPECT_EQ(s.failed[0].first, "powerLaw");

    // None converged: a FitFailure that carries every reason.
    try
    {
        selectModel({fits[0]});
        FAIL() << "selectModel accepted only failed fits";
    }
    catch (const FitFailure& e)
    {
        EXPECT_NE(std::string(e.what()).find("powerLaw"), std::string::npos) << e.what();
    }
}

TEST(ModelSelection, RefusesFitsOfDifferentTables)
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    std::mt19937_64 engine(25);
    const auto data = synthetic(KineticTheoryGroupsLaw{}, truth, seedLikeEnvelope(), 0.03, engine);
    const std::vector<Observation> half(data.begin(), data.begin() + data.size() / 2);
    FitOptions linear;
    linear.space = FitSpace::linear;
    EXPECT_THROW
    (
        selectModel({fitLaw(KineticTheoryGroupsLaw{}, data), fitLaw(SeedPowerLaw{}, half)}),
        std::invalid_argument
    );
    EXPECT_THROW
    (
        selectModel({fitLaw(KineticTheoryGroupsLaw{}, data), fitLaw(SeedPowerLaw{}, data, linear)}),
        std::invalid_argument
    );
    EXPECT_THROW(selectModel({}), std::invalid_argument);
}

TEST(ModelSelection, OneDiameterOnlyThePhiShapeTellsTheLawsApart)
{
    // With a single diameter and two coarse fractions the power law matches
    // kinetic theory's d sqrt(T) and (1 + alpha x) exactly (m = 1/2, a fitted
    // through two points); only phi^b versus 1/(phi g0(phi)) differs. The
    // generating law must still win, by less than above.
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    std::vector<Condition> conditions;
    for (const Condition& c : seedLikeEnvelope())
    {
        if (c.d == 2e-3)
        {
            conditions.push_back(c);
        }
    }
    std::mt19937_64 engine(26);
    const auto data = synthetic(KineticTheoryGroupsLaw{}, truth, conditions, 0.03, engine);
    const ModelSelection s = selectBetweenTheDiffusivityLaws(data, InformationCriterion::AIC);
    EXPECT_EQ(s.best().law, "kineticTheoryGroups");
    EXPECT_GT(s.ranking[1].delta, 10.0);
    // The power law's phi exponent is then an effective slope of 1/(phi g0)
    // over 0.1..0.5: steeper than -1 (g0 grows with phi).
    const FitResult power = fitLaw(SeedPowerLaw{}, data);
    ASSERT_TRUE(power.converged()) << power.message;
    EXPECT_LT(power.parameter("b").value, -1.0);
    EXPECT_NEAR(power.parameter("m").value, 0.5, 5.0 * power.parameter("m").standardError);
    std::cout << "  power law on kinetic data: b = " << power.parameter("b").value << " +- "
              << power.parameter("b").standardError << ", m = " << power.parameter("m").value
              << "\n";
}

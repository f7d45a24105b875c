// Are the reported standard errors honest? Over many independent replicas
// the true parameter must lie within 1 reported sigma about 68 % of the time
// (and within 2 sigma about 95 %), for every parameter of every law and for
// both meanings of sigma.
#include "SyntheticData.hpp"

#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"

#include <gtest/gtest.h>

#include <iostream>

using namespace sdf::fit;
using sdf::fit::test::seedLikeEnvelope;
using sdf::fit::test::synthetic;

namespace
{

void expectHonestErrors
(
    const ConstitutiveLaw& law,
    const Eigen::VectorXd& truth,
    SigmaMeaning meaning,
    std::uint64_t seed
)
{
    constexpr int replicas = 400;   // binomial spread of a 68 % fraction: 2.3 %
    std::mt19937_64 engine(seed);
    const std::vector<Condition> conditions = seedLikeEnvelope();
    FitOptions options;
    options.sigmaMeaning = meaning;
    std::vector<int> within1(truth.size(), 0), within2(truth.size(), 0);
    for (int r = 0; r < replicas; ++r)
    {
        const auto data = synthetic(law, truth, conditions, 0.03, engine);
        const FitResult fit = fitLaw(law, data, options);
        ASSERT_TRUE(fit.converged()) << fit.message;
        for (Eigen::Index j = 0; j < truth.size(); ++j)
        {
            const double pull = std::abs(fit.parameters[j].value - truth(j))
                              / fit.parameters[j].standardError;
            within1[j] += pull < 1.0;
            within2[j] += pull < 2.0;
        }
    }
    for (Eigen::Index j = 0; j < truth.size(); ++j)
    {
        const double f1 = double(within1[j]) / replicas, f2 = double(within2[j]) / replicas;
        std::cout << "  " << law.name() << " " << law.parameterNames()[j]
                  << (meaning == SigmaMeaning::relative ? " (relative sigma)" : " (absolute sigma)")
                  << ": within 1 sigma " << f1 << ", within 2 sigma " << f2 << "\n";
        EXPECT_GT(f1, 0.55) << law.parameterNames()[j];
        EXPECT_LT(f1, 0.80) << law.parameterNames()[j];
        EXPECT_GT(f2, 0.90) << law.parameterNames()[j];
        EXPECT_LT(f2, 0.99) << law.parameterNames()[j];
    }
}

} // namespace

TEST(Coverage, SeedPowerLaw)
{
    Eigen::VectorXd truth(4);
    truth << 6.0, 1.0, 1.0, -1.5;
    expectHonestErrors(SeedPowerLaw{}, truth, SigmaMeaning::relative, 101);
    expectHonestErrors(SeedPowerLaw{}, truth, SigmaMeaning::absolute, 102);
}

TEST(Coverage, KineticTheoryGroups)
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    expectHonestErrors(KineticTheoryGroupsLaw{}, truth, SigmaMeaning::relative, 103);
    expectHonestErrors(KineticTheoryGroupsLaw{}, truth, SigmaMeaning::absolute, 104);
}

TEST(Coverage, SievingPowerLaw)
{
    Eigen::VectorXd truth(3);
    truth << 0.5, -1.2, 2.0;
    expectHonestErrors(SievingPowerLaw{}, truth, SigmaMeaning::relative, 105);
    expectHonestErrors(SievingPowerLaw{}, truth, SigmaMeaning::absolute, 106);
}

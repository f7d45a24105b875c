// A fit that does not converge, or whose parameters the data cannot identify,
// is reported as failed with the law and the reason, never returned as good.
#include "SyntheticData.hpp"

#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/OpenFOAMDictionary.hpp"

#include <gtest/gtest.h>

#include <sstream>

using namespace sdf::fit;
using sdf::fit::test::seedLikeEnvelope;
using sdf::fit::test::synthetic;

namespace
{

std::vector<Observation> seedData(std::uint64_t seed)
{
    Eigen::VectorXd truth(4);
    truth << 6.0, 1.0, 1.0, -1.5;
    std::mt19937_64 engine(seed);
    return synthetic(SeedPowerLaw{}, truth, seedLikeEnvelope(), 0.03, engine);
}

void expectMessageNames(const std::string& message, const std::string& part)
{
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

} // namespace

TEST(Failure, OneIterationFromAFarStartIsNotConverged)
{
    FitOptions options;
    options.maxIterations = 1;
    Eigen::VectorXd farStart(4);
    farStart << 1.0, 0.0, 0.0, 0.0;
    options.initialParameters = farStart;
    const auto data = seedData(31);
    const FitResult fit = fitLaw(SeedPowerLaw{}, data, options);
    EXPECT_FALSE(fit.converged());
    EXPECT_EQ(fit.status, FitStatus::maxIterationsReached);
    expectMessageNames(fit.message, "powerLaw");
    expectMessageNames(fit.message, "not converged");
    EXPECT_THROW(fit.throwIfFailed(), FitFailure);
    try
    {
        fitLawOrThrow(SeedPowerLaw{}, data, options);
        FAIL() << "fitLawOrThrow returned a failed fit";
    }
    catch (const FitFailure& e)
    {
        expectMessageNames(e.what(), "powerLaw");
        expectMessageNames(e.what(), "maximum iterations");
    }
    // The same data with the default settings converge: the failure above
    // is the iteration limit, not the data.
    EXPECT_TRUE(fitLaw(SeedPowerLaw{}, data).converged());
}

TEST(Failure, UnidentifiableParametersAreASingularCovariance)
{
    // One coarse fraction only: (1 + x)^a is a constant that A absorbs, so
    // A and a cannot be told apart. The cost has a valley, the solver may
    // well stop in it; the fit must still be reported as failed.
    auto data = seedData(32);
    for (Observation& o : data)
    {
        o.condition.x = 0.2;
    }
    const FitResult fit = fitLaw(SeedPowerLaw{}, data);
    EXPECT_FALSE(fit.converged());
    EXPECT_EQ(fit.status, FitStatus::singularCovariance);
    expectMessageNames(fit.message, "powerLaw");
    expectMessageNames(fit.message, "A, a");
    EXPECT_THROW(fitLawOrThrow(SeedPowerLaw{}, data), FitFailure);
}

TEST(Failure, ParameterTheDataDoNotDependOnIsNamed)
{
    // x = 0 everywhere: the kinetic law's alpha multiplies x, so it has no effect.
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.0;
    std::vector<Condition> conditions = seedLikeEnvelope();
    for (Condition& c : conditions)
    {
        c.x = 0.0;
    }
    std::mt19937_64 engine(33);
    const auto data = synthetic(KineticTheoryGroupsLaw{}, truth, conditions, 0.03, engine);
    const FitResult fit = fitLaw(KineticTheoryGroupsLaw{}, data);
    EXPECT_EQ(fit.status, FitStatus::singularCovariance);
    expectMessageNames(fit.message, "kineticTheoryGroups");
    expectMessageNames(fit.message, "alpha");
}

TEST(Failure, StartWhereTheLawIsNotPositiveInLogSpace)
{
    FitOptions options;
    Eigen::VectorXd negative(2);
    negative << -0.1, 0.0;
    options.initialParameters = negative;
    const FitResult fit = fitLaw(KineticTheoryGroupsLaw{}, seedData(34), options);
    EXPECT_EQ(fit.status, FitStatus::invalidLaw);
    expectMessageNames(fit.message, "row 0");
}

TEST(Failure, FailedFitIsNotWrittenToTheDictionary)
{
    FitOptions options;
    options.maxIterations = 1;
    Eigen::VectorXd farStart(4);
    farStart << 1.0, 0.0, 0.0, 0.0;
    options.initialParameters = farStart;
    const FitResult failed = fitLaw(SeedPowerLaw{}, seedData(35), options);
    ASSERT_FALSE(failed.converged());
    std::ostringstream os;
    EXPECT_THROW
    (
        writeOpenFOAMDictionary(os, {CalibratedCoefficient{"D", failed, std::nullopt}}),
        FitFailure
    );
    EXPECT_TRUE(os.str().empty()) << "a partial dictionary was written";
}

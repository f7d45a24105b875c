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
using sdf::fit::test::seedPowerLawData;
using sdf::fit::test::synthetic;

namespace
{

//- One iteration from (1, 0, 0, 0), far from the seed's values: not converged.
FitOptions oneIterationFromAFarStart()
{
    FitOptions options;
    options.maxIterations = 1;
    Eigen::VectorXd farStart(4);
    farStart << 1.0, 0.0, 0.0, 0.0;
    options.initialParameters = farStart;
    return options;
}

void expectMessageNames(const std::string& message, const std::string& part)
{
    EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

} // namespace

TEST(Failure, OneIterationFromAFarStartIsNotConverged)
{
    const FitOptions options = oneIterationFromAFarStart();
    const auto data = seedPowerLawData(31);
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
    auto data = seedPowerLawData(32);
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
    const FitResult fit = fitLaw(KineticTheoryGroupsLaw{}, seedPowerLawData(34), options);
    EXPECT_EQ(fit.status, FitStatus::invalidLaw);
    expectMessageNames(fit.message, "row 0");
}

TEST(Failure, FailedFitIsNotWrittenToTheDictionary)
{
    const FitOptions options = oneIterationFromAFarStart();
    const FitResult failed = fitLaw(SeedPowerLaw{}, seedPowerLawData(35), options);
    ASSERT_FALSE(failed.converged());
    std::ostringstream os;
    EXPECT_THROW
    (
        writeOpenFOAMDictionary(os, {CalibratedCoefficient{"D", failed, std::nullopt}}),
        FitFailure
    );
    EXPECT_TRUE(os.str().empty()) << "a partial dictionary was written";
}

namespace
{
//- A user law (any type with the ConstitutiveLaw interface) whose gradient
//  is broken: NaN wherever it is asked.
struct BrokenGradientLaw
{
    std::string name() const { return "brokenGradient"; }
    std::string formula() const { return "A*T"; }
    std::vector<std::string> parameterNames() const { return {"A"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const { return p(0) * c.T; }
    Eigen::VectorXd gradient(const Condition&, const Eigen::VectorXd&) const
    {
        return Eigen::VectorXd::Constant(1, NAN);
    }
    Eigen::VectorXd initialParameters(const std::vector<Observation>&) const
    {
        return Eigen::VectorXd::Constant(1, 2.0);
    }
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};
} // namespace

TEST(Failure, NonFiniteJacobianIsReported)
{
    const FitResult fit = fitLaw(BrokenGradientLaw{}, seedPowerLawData(36));
    EXPECT_FALSE(fit.converged());
    EXPECT_EQ(fit.status, FitStatus::nonFiniteResult);
    expectMessageNames(fit.message, "brokenGradient");
    expectMessageNames(fit.message, "not finite");
}

namespace
{
//- Gradient fine at the start, NaN once the solver has moved: the failure
//  must surface from inside the GSL iterations as a report, not an abort.
struct GradientBreaksAwayFromStartLaw : BrokenGradientLaw
{
    std::string name() const { return "gradientBreaksAwayFromStart"; }
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const
    {
        return Eigen::VectorXd::Constant(1, std::abs(p(0) - 2.0) < 1e-12 ? c.T : NAN);
    }
};
} // namespace

TEST(Failure, NonFiniteJacobianDuringTheIterationsIsReported)
{
    const FitResult fit = fitLaw(GradientBreaksAwayFromStartLaw{}, seedPowerLawData(37));
    EXPECT_EQ(fit.status, FitStatus::nonFiniteResult);
    expectMessageNames(fit.message, "gradientBreaksAwayFromStart");
    expectMessageNames(fit.message, "gradient is not finite");
    expectMessageNames(fit.message, "iterations");
}

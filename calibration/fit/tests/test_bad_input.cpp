// Bad input throws std::invalid_argument naming the law and the offending row
// and entry.
#include "SyntheticData.hpp"

#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using namespace sdf::fit;

namespace
{

std::vector<Observation> goodData()
{
    Eigen::VectorXd truth(2);
    truth << 0.15, 0.8;
    std::mt19937_64 engine(41);
    return sdf::fit::test::synthetic
    (
        KineticTheoryGroupsLaw{}, truth, sdf::fit::test::seedLikeEnvelope(), 0.03, engine
    );
}

//- Spoils row 7 of good data and expects the message to name it.
void expectRejected
(
    const std::function<void(Observation&)>& spoil,
    const std::string& entry,
    FitSpace space = FitSpace::logarithmic
)
{
    auto data = goodData();
    spoil(data[7]);
    FitOptions options;
    options.space = space;
    try
    {
        fitLaw(KineticTheoryGroupsLaw{}, data, options);
        FAIL() << "accepted bad " << entry;
    }
    catch (const std::invalid_argument& e)
    {
        const std::string message = e.what();
        EXPECT_NE(message.find("row 7"), std::string::npos) << message;
        EXPECT_NE(message.find(entry), std::string::npos) << message;
        EXPECT_NE(message.find("kineticTheoryGroups"), std::string::npos) << message;
    }
}

} // namespace

TEST(BadInput, EmptyTable)
{
    try
    {
        fitLaw(SeedPowerLaw{}, {});
        FAIL();
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
}

TEST(BadInput, NoMoreRowsThanParameters)
{
    const auto data = goodData();
    const std::vector<Observation> four(data.begin(), data.begin() + 4);
    try
    {
        fitLaw(SeedPowerLaw{}, four);
        FAIL();
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("4 rows for 4 parameters"), std::string::npos)
            << e.what();
    }
    const std::vector<Observation> five(data.begin(), data.begin() + 5);
    EXPECT_NO_THROW(fitLaw(SeedPowerLaw{}, five));
}

TEST(BadInput, SigmaNotPositive)
{
    expectRejected([](Observation& o) { o.sigma = 0.0; }, "sigma");
    expectRejected([](Observation& o) { o.sigma = -1e-6; }, "sigma");
}

TEST(BadInput, NonFiniteValues)
{
    expectRejected([](Observation& o) { o.value = NAN; }, "value");
    expectRejected([](Observation& o) { o.sigma = INFINITY; }, "sigma");
    expectRejected([](Observation& o) { o.condition.T = NAN; }, "T");
    expectRejected([](Observation& o) { o.condition.phi = NAN; }, "phi");
    expectRejected([](Observation& o) { o.condition.d = INFINITY; }, "d");
    expectRejected([](Observation& o) { o.condition.gammaDot = NAN; }, "gammaDot");
}

TEST(BadInput, ConditionsOutsideTheirDomain)
{
    expectRejected([](Observation& o) { o.condition.phi = -0.1; }, "phi");
    expectRejected([](Observation& o) { o.condition.phi = 0.0; }, "phi");
    expectRejected([](Observation& o) { o.condition.phi = 1.0; }, "phi");
    expectRejected([](Observation& o) { o.condition.x = 1.5; }, "x");
    expectRejected([](Observation& o) { o.condition.T = 0.0; }, "T");
    expectRejected([](Observation& o) { o.condition.d = -1e-3; }, "d");
    expectRejected([](Observation& o) { o.condition.gammaDot = -1.0; }, "gammaDot");
}

TEST(BadInput, NonPositiveValueOnlyInLogSpace)
{
    expectRejected([](Observation& o) { o.value = -1e-9; }, "value");
    auto data = goodData();
    data[7].value = -1e-9;
    FitOptions linear;
    linear.space = FitSpace::linear;
    const FitResult fit = fitLaw(KineticTheoryGroupsLaw{}, data, linear);
    EXPECT_TRUE(fit.converged()) << fit.message;
}

TEST(BadInput, StartOfTheWrongSize)
{
    FitOptions options;
    options.initialParameters = Eigen::VectorXd::Ones(3);
    EXPECT_THROW(fitLaw(KineticTheoryGroupsLaw{}, goodData(), options), std::invalid_argument);
    options.initialParameters = Eigen::VectorXd::Constant(2, NAN);
    EXPECT_THROW(fitLaw(KineticTheoryGroupsLaw{}, goodData(), options), std::invalid_argument);
    options.initialParameters.reset();
    options.maxIterations = 0;
    EXPECT_THROW(fitLaw(KineticTheoryGroupsLaw{}, goodData(), options), std::invalid_argument);
}

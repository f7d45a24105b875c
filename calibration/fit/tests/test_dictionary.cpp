// The granularCoefficients writer: header, one sub-dictionary per coefficient
// with law, parameters, errors, fit quality and envelope; the numbers read
// back equal the fit's; bad names are refused.
#include "SyntheticData.hpp"

#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"
#include "fit/OpenFOAMDictionary.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <regex>
#include <sstream>

using namespace sdf::fit;
using sdf::fit::test::seedLikeEnvelope;
using sdf::fit::test::synthetic;

namespace
{

//- The text between "name\n{" and its matching "}" (top level or nested).
std::string block(const std::string& text, const std::string& name)
{
    const std::regex opening("(^|\\n)[ ]*" + name + "\\n[ ]*\\{");
    std::smatch match;
    if (!std::regex_search(text, match, opening))
    {
        return {};
    }
    std::size_t pos = match.position(0) + match.length(0);
    const std::size_t begin = pos;
    for (int depth = 1; pos < text.size(); ++pos)
    {
        depth += text[pos] == '{' ? 1 : text[pos] == '}' ? -1 : 0;
        if (depth == 0)
        {
            return text.substr(begin, pos - begin);
        }
    }
    return {};
}

//- The value of `keyword value;` directly in a block (first match).
std::string entry(const std::string& text, const std::string& keyword)
{
    const std::regex pattern("\\n[ ]*" + keyword + "[ ]+([^;\\n]+);");
    std::smatch match;
    return std::regex_search(text, match, pattern) ? match[1].str() : std::string();
}

double number(const std::string& text, const std::string& keyword)
{
    const std::string v = entry(text, keyword);
    EXPECT_FALSE(v.empty()) << "no entry " << keyword;
    return v.empty() ? NAN : std::stod(v);
}

struct Calibration
{
    std::vector<CalibratedCoefficient> coefficients;
};

Calibration seedLikeCalibration()
{
    std::mt19937_64 engine(51);
    Eigen::VectorXd seedTruth(4), sievingTruth(3);
    seedTruth << 6.0, 1.0, 1.0, -1.5;
    sievingTruth << 0.5, -1.2, 2.0;
    const auto diffusion = synthetic(SeedPowerLaw{}, seedTruth, seedLikeEnvelope(), 0.03, engine);
    auto sievingConditions = seedLikeEnvelope();
    for (Condition& c : sievingConditions)
    {
        c.gammaDot = 10.0 * std::sqrt(c.T) / c.d;   // a sheared run
    }
    const auto sieving = synthetic(SievingPowerLaw{}, sievingTruth, sievingConditions, 0.03, engine);

    std::vector<FitResult> diffusionFits =
    {
        fitLaw(SeedPowerLaw{}, diffusion),
        fitLaw(KineticTheoryGroupsLaw{}, diffusion)
    };
    const ModelSelection selection = selectModel(diffusionFits);
    Calibration c;
    c.coefficients.push_back
    (
        CalibratedCoefficient{"D", diffusionFits[selection.best().index], selection}
    );
    c.coefficients.push_back
    (
        CalibratedCoefficient{"eta", fitLawOrThrow(SievingPowerLaw{}, sieving), std::nullopt}
    );
    return c;
}

} // namespace

TEST(Dictionary, WritesEveryEntryAndTheNumbersReadBack)
{
    Calibration calibration = seedLikeCalibration();
    calibration.coefficients[1].provenance = {{"sievingAttribution", "crossTerms"}};
    std::ostringstream os;
    writeOpenFOAMDictionary(os, calibration.coefficients);
    const std::string text = os.str();
    std::cout << text;

    EXPECT_EQ(std::count(text.begin(), text.end(), '{'), std::count(text.begin(), text.end(), '}'));
    const std::string header = block(text, "FoamFile");
    EXPECT_EQ(entry(header, "class"), "dictionary");
    EXPECT_EQ(entry(header, "object"), "granularCoefficients");

    const std::string D = block(text, "D");
    ASSERT_FALSE(D.empty());
    const FitResult& fitD = calibration.coefficients[0].fit;
    EXPECT_EQ(entry(D, "law"), "powerLaw");
    const std::string errorsD = block(D, "errors");
    ASSERT_FALSE(errorsD.empty());
    for (const FittedParameter& p : fitD.parameters)
    {
        EXPECT_NEAR(number(D, p.name), p.value, 1e-9 * std::abs(p.value)) << p.name;
        EXPECT_NEAR(number(errorsD, p.name), p.standardError, 1e-9 * p.standardError) << p.name;
    }
    // Covariance: a list of rows in parameter order, symmetric, errors^2 on the diagonal.
    {
        const std::string rows = entry(D, "covariance");
        const std::regex numberPattern("[-+0-9.eE]+");
        std::vector<double> values;
        for (auto it = std::sregex_iterator(rows.begin(), rows.end(), numberPattern);
             it != std::sregex_iterator(); ++it)
        {
            values.push_back(std::stod(it->str()));
        }
        ASSERT_EQ(values.size(), 16u) << rows;
        for (std::size_t i = 0; i < 4; ++i)
        {
            const double se = fitD.parameters[i].standardError;
            EXPECT_NEAR(values[5 * i], se * se, 1e-9 * se * se);
            for (std::size_t j = 0; j < 4; ++j)
            {
                EXPECT_EQ(values[4 * i + j], values[4 * j + i]);
            }
        }
    }
    EXPECT_NEAR(number(D, "R2"), fitD.rSquared, 1e-9);
    EXPECT_NEAR(number(D, "AIC"), fitD.aic, 1e-8 * std::abs(fitD.aic));
    EXPECT_EQ(entry(D, "points"), "120");
    EXPECT_EQ(entry(D, "fitSpace"), "log");
    EXPECT_EQ(entry(D, "sigma"), "relative");
    EXPECT_EQ(entry(D, "phiRange"), "(0.1 0.5)");
    EXPECT_EQ(entry(D, "xRange"), "(0.2 0.4)");
    EXPECT_EQ(entry(D, "TRange"), "(0.001 0.1)");
    EXPECT_EQ(entry(D, "dRange"), "(0.001 0.004)");
    EXPECT_TRUE(entry(D, "gammaDotRange").empty());
    const std::string selection = block(D, "selection");
    EXPECT_EQ(entry(selection, "criterion"), "AIC");
    EXPECT_EQ(number(selection, "powerLaw"), 0.0);
    EXPECT_GT(number(selection, "kineticTheoryGroups"), 10.0);

    const std::string eta = block(text, "eta");
    ASSERT_FALSE(eta.empty());
    EXPECT_EQ(entry(eta, "law"), "sievingPowerLaw");
    EXPECT_EQ(entry(eta, "diameterPower"), "1");
    EXPECT_NEAR(number(eta, "p"), calibration.coefficients[1].fit.parameter("p").value, 1e-9);
    EXPECT_FALSE(entry(eta, "gammaDotRange").empty());
    EXPECT_TRUE(block(eta, "selection").empty());
    // the attribution rule eta was fitted with, in eta's dictionary only
    EXPECT_EQ(entry(eta, "sievingAttribution"), "crossTerms");
    EXPECT_TRUE(entry(D, "sievingAttribution").empty());
}

TEST(Dictionary, RefusesBadCoefficientNames)
{
    const Calibration calibration = seedLikeCalibration();
    const FitResult& fit = calibration.coefficients[0].fit;
    std::ostringstream os;
    EXPECT_THROW(writeOpenFOAMDictionary(os, {}), std::invalid_argument);
    EXPECT_THROW
    (
        writeOpenFOAMDictionary(os, {CalibratedCoefficient{"D D", fit, std::nullopt}}),
        std::invalid_argument
    );
    EXPECT_THROW
    (
        writeOpenFOAMDictionary
        (
            os,
            {CalibratedCoefficient{"D", fit, std::nullopt}, CalibratedCoefficient{"D", fit, std::nullopt}}
        ),
        std::invalid_argument
    );
    EXPECT_TRUE(os.str().empty());
}

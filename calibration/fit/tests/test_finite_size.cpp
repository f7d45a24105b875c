// Finite-size extrapolation D(N) = D_inf - a N^(-1/3) (fit/FiniteSize.hpp) against
// exactly constructed values and the two-point error propagation by hand.
#include "fit/FiniteSize.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace sdf::fit;

TEST(finite_size, recoversAnExactLine)
{
    // the phi 0.3 cells of docs/validation.md: D_inf 11.9e-6, a 23e-6
    std::vector<SizedValue> rows;
    for (const double n : {300.0, 600.0, 1200.0, 2400.0})
    {
        rows.push_back({n, 11.9e-6 - 23e-6*std::cbrt(1/n), 0.02*11.9e-6});
    }
    const FiniteSizeExtrapolation e = extrapolateInverseCubeRoot(rows);
    EXPECT_NEAR(e.value, 11.9e-6, 1e-15);
    EXPECT_NEAR(e.slope, 23e-6, 1e-14);
    EXPECT_LT(e.reducedChiSquare, 1e-20);
    EXPECT_EQ(e.sizes, 4u);
    EXPECT_GT(e.error, 0.0);
}

TEST(finite_size, twoSizesPropagateTheirErrors)
{
    // u1 = 300^(-1/3), u2 = 1200^(-1/3): D_inf = (D2 u1 - D1 u2)/(u1 - u2),
    // var = (u1^2 s2^2 + u2^2 s1^2)/(u1 - u2)^2
    const double u1 = std::cbrt(1/300.0), u2 = std::cbrt(1/1200.0);
    const double D1 = 8.4e-6, s1 = 0.2e-6, D2 = 9.6e-6, s2 = 0.15e-6;
    const FiniteSizeExtrapolation e = extrapolateInverseCubeRoot({{300, D1, s1}, {1200, D2, s2}});
    EXPECT_NEAR(e.value, (D2*u1 - D1*u2)/(u1 - u2), 1e-18);
    EXPECT_NEAR(e.error, std::sqrt(u1*u1*s2*s2 + u2*u2*s1*s1)/(u1 - u2), 1e-18);
    EXPECT_NEAR(e.slope, (D2 - D1)/(u1 - u2), 1e-16);
    EXPECT_EQ(e.reducedChiSquare, 0.0);
}

TEST(finite_size, scatterWidensTheError)
{
    const double u[] = {std::cbrt(1/300.0), std::cbrt(1/600.0), std::cbrt(1/1200.0)};
    std::vector<SizedValue> exact, scattered;
    for (int i = 0; i < 3; ++i)
    {
        const double n = 300.0*std::pow(2.0, i);
        const double d = 10e-6 - 20e-6*u[i];
        exact.push_back({n, d, 0.1e-6});
        scattered.push_back({n, d + (i == 1 ? 0.5e-6 : 0.0), 0.1e-6});
    }
    const FiniteSizeExtrapolation a = extrapolateInverseCubeRoot(exact);
    const FiniteSizeExtrapolation b = extrapolateInverseCubeRoot(scattered);
    EXPECT_GT(b.reducedChiSquare, 1.0);
    EXPECT_NEAR(b.error/a.error, std::sqrt(b.reducedChiSquare), 1e-9);
}

TEST(finite_size, refusesOneSizeAndBadRows)
{
    EXPECT_THROW(extrapolateInverseCubeRoot({}), std::invalid_argument);
    EXPECT_THROW(extrapolateInverseCubeRoot({{300, 1e-6, 1e-8}, {300, 1.1e-6, 1e-8}}),
                 std::invalid_argument);
    try
    {
        extrapolateInverseCubeRoot({{300, 1e-6, 1e-8}, {600, 1e-6, 0}});
        ADD_FAILURE() << "no exception";
    }
    catch (const std::invalid_argument& err)
    {
        EXPECT_NE(std::string(err.what()).find("row 1"), std::string::npos) << err.what();
    }
    EXPECT_THROW(extrapolateInverseCubeRoot({{300, NAN, 1e-8}, {600, 1e-6, 1e-8}}),
                 std::invalid_argument);
}

#include "correlation/Statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sdf::correlation;

TEST(Statistics, MeanAndStandardErrorOfKnownSamples)
{
    const Estimate e = meanAndStandardError({1.0, 2.0, 3.0, 4.0});
    EXPECT_DOUBLE_EQ(e.value, 2.5);
    // sample variance 5/3, standard error sqrt(5/3/4)
    EXPECT_NEAR(e.standardError, std::sqrt(5.0 / 12.0), 1e-15);
    EXPECT_EQ(e.samples, 4u);
    EXPECT_THROW(meanAndStandardError({}), std::invalid_argument);
}

TEST(Statistics, BlockAverageOfCorrelatedSeriesIsHonest)
{
    // AR(1) with r = 0.9: the naive error is too small by sqrt((1+r)/(1-r)) ~ 4.4;
    // block means over blocks >> 1/(1-r) recover the right error. Check it
    // against the spread of the mean over independent replicas.
    const double r = 0.9;
    const std::size_t n = 20000, replicas = 40;
    std::mt19937_64 engine(42);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> means;
    double reportedSquares = 0.0;
    for (std::size_t rep = 0; rep < replicas; ++rep)
    {
        std::vector<double> s(n);
        double x = normal(engine) / std::sqrt(1.0 - r * r);
        for (double& v : s)
        {
            v = x;
            x = r * x + normal(engine);
        }
        const Estimate e = blockAverage(s, 20);
        means.push_back(e.value);
        reportedSquares += e.standardError * e.standardError;
    }
    const double spread = meanAndStandardError(means).standardError * std::sqrt(double(replicas));
    const double reported = std::sqrt(reportedSquares / replicas);
    EXPECT_GT(spread / reported, 1.0 / 1.4);
    EXPECT_LT(spread / reported, 1.4);
    // The exact error of the mean of n AR(1) samples: sqrt(n (1+r)/(1-r)) / (n sqrt(1-r^2)).
    const double exact = std::sqrt((1.0 + r) / (1.0 - r) / n) / std::sqrt(1.0 - r * r);
    EXPECT_NEAR(reported / exact, 1.0, 0.2);
}

TEST(Statistics, CombiningReplicas)
{
    const Estimate a{1.0, 0.1, 10}, b{3.0, 0.1, 10};
    const Estimate plain = combineReplicas({a, b});
    EXPECT_DOUBLE_EQ(plain.value, 2.0);
    EXPECT_DOUBLE_EQ(plain.standardError, 1.0);   // from the spread, not the 0.1s
    const Estimate weighted = inverseVarianceMean({Estimate{1.0, 1.0, 1}, Estimate{4.0, 0.5, 1}});
    EXPECT_NEAR(weighted.value, (1.0 + 4.0 * 4.0) / 5.0, 1e-15);
    EXPECT_NEAR(weighted.standardError, std::sqrt(1.0 / 5.0), 1e-15);
    EXPECT_THROW(inverseVarianceMean({Estimate{1.0, 0.0, 1}}), std::invalid_argument);
}

TEST(Statistics, BlockRanges)
{
    const IndexRange r = blockRange(103, 10, 9);
    EXPECT_EQ(r.begin, 90u);
    EXPECT_EQ(r.end, 100u);
    EXPECT_THROW(blockRange(5, 10, 0), std::invalid_argument);
}

#include "correlation/FftCorrelator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sdf::correlation;

namespace
{

std::vector<double> randomSeries(std::size_t n, std::uint64_t seed)
{
    std::mt19937_64 engine(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> s(n);
    for (double& x : s)
    {
        x = normal(engine);
    }
    return s;
}

} // namespace

// <cos(w t) cos(w (t+k))> over M = N-k origins, summed in closed form:
// cos(w k)/2 + sin(w M) cos(w (M-1+k)) / (2 M sin w).
TEST(FftCorrelator, CosineGivesAnalyticCorrelationToRoundOff)
{
    const std::size_t n = 1000;
    const std::size_t maxLag = 300;
    const double w = 0.37;
    std::vector<double> a(n);
    for (std::size_t t = 0; t < n; ++t)
    {
        a[t] = std::cos(w * t);
    }
    const std::vector<double> c = autocorrelation(a, maxLag);
    ASSERT_EQ(c.size(), maxLag + 1);
    double worst = 0.0;
    for (std::size_t k = 0; k <= maxLag; ++k)
    {
        const double m = static_cast<double>(n - k);
        const double exact = 0.5 * std::cos(w * k)
            + std::sin(w * m) * std::cos(w * (m - 1.0 + k)) / (2.0 * m * std::sin(w));
        worst = std::max(worst, std::abs(c[k] - exact));
    }
    EXPECT_LT(worst, 1e-13);
}

TEST(FftCorrelator, CosineSineCrossCorrelationIsHalfSine)
{
    // <cos(w t) sin(w (t+k))> -> sin(w k)/2 up to an O(1/M) end term.
    const std::size_t n = 20000;
    const double w = 2.0 * M_PI / 50.0;   // whole periods: end terms cancel
    std::vector<double> a(n), b(n);
    for (std::size_t t = 0; t < n; ++t)
    {
        a[t] = std::cos(w * t);
        b[t] = std::sin(w * t);
    }
    const std::vector<double> c = crossCorrelation(a, b, 100);
    const std::vector<double> direct = crossCorrelationDirect(a, b, 100);
    for (std::size_t k = 0; k <= 100; ++k)
    {
        EXPECT_NEAR(c[k], direct[k], 1e-12) << "lag " << k;
        EXPECT_NEAR(c[k], 0.5 * std::sin(w * k), 1e-3) << "lag " << k;
    }
}

TEST(FftCorrelator, RandomCrossCorrelationMatchesDirectSum)
{
    // Lengths that are not powers of two exercise the padding.
    const std::vector<double> a = randomSeries(777, 1);
    const std::vector<double> b = randomSeries(777, 2);
    const std::vector<double> fft = crossCorrelation(a, b, 776);
    const std::vector<double> direct = crossCorrelationDirect(a, b, 776);
    for (std::size_t k = 0; k < fft.size(); ++k)
    {
        EXPECT_NEAR(fft[k], direct[k], 1e-12) << "lag " << k;
    }
    // Swapping the series reverses time: C_ba(k) = <b(0) a(k)> differs from C_ab(k).
    const std::vector<double> swapped = crossCorrelation(b, a, 10);
    EXPECT_GT(std::abs(swapped[3] - fft[3]), 1e-6);
}

TEST(FftCorrelator, VectorAutocorrelationAveragesParticlesAndComponents)
{
    const std::size_t n = 300, particles = 5;
    VectorFrames frames(n, VectorFrame(particles, 3));
    std::vector<std::vector<double>> series(particles * 3);
    for (std::size_t p = 0; p < particles; ++p)
    {
        for (int c = 0; c < 3; ++c)
        {
            series[p * 3 + c] = randomSeries(n, 100 + p * 3 + c);
            for (std::size_t t = 0; t < n; ++t)
            {
                frames[t](p, c) = series[p * 3 + c][t] + 0.1 * c;
                series[p * 3 + c][t] += 0.1 * c;
            }
        }
    }
    const std::size_t maxLag = 50;
    const Eigen::MatrixX3d acf = vectorAutocorrelation(frames, maxLag, 20, 280);
    ASSERT_EQ(acf.rows(), static_cast<Eigen::Index>(maxLag + 1));
    for (int c = 0; c < 3; ++c)
    {
        std::vector<double> expected(maxLag + 1, 0.0);
        for (std::size_t p = 0; p < particles; ++p)
        {
            const std::vector<double>& s = series[p * 3 + c];
            const std::vector<double> window(s.begin() + 20, s.begin() + 280);
            const std::vector<double> d = crossCorrelationDirect(window, window, maxLag);
            for (std::size_t k = 0; k <= maxLag; ++k)
            {
                expected[k] += d[k] / particles;
            }
        }
        for (std::size_t k = 0; k <= maxLag; ++k)
        {
            EXPECT_NEAR(acf(k, c), expected[k], 1e-12) << "component " << c << " lag " << k;
        }
    }
    // Blocks: each block equals the correlation of its own frame range.
    const auto blocks = blockEstimates(vectorAutocorrelation, frames, maxLag, 3);
    ASSERT_EQ(blocks.size(), 3u);
    EXPECT_LT((blocks[1] - vectorAutocorrelation(frames, maxLag, 100, 200)).cwiseAbs().maxCoeff(), 1e-14);
    const auto mean = componentSeries(blocks, -1);
    EXPECT_NEAR(mean[2][4], blocks[2].row(4).mean(), 1e-15);
    EXPECT_THROW(componentSeries(blocks, 3), std::invalid_argument);
}

TEST(FftCorrelator, NineStressProductsSumToTheTotalAutocorrelation)
{
    // J = J1 + J2 + J12 (seed eq 13), so <J(0)J(t)> is the sum of the nine
    // products; check that the decomposition is exact and each term is right.
    const std::size_t n = 2000, maxLag = 200;
    std::vector<std::vector<double>> parts = {randomSeries(n, 7), randomSeries(n, 8), randomSeries(n, 9)};
    // Make J12 share a component with J1 so cross terms are not zero.
    for (std::size_t t = 0; t < n; ++t)
    {
        parts[2][t] += 0.5 * parts[0][t];
    }
    std::vector<double> total(n);
    for (std::size_t t = 0; t < n; ++t)
    {
        total[t] = parts[0][t] + parts[1][t] + parts[2][t];
    }
    const SeriesProductCorrelations products = seriesProductCorrelations(parts, maxLag);
    const std::vector<double> sum = products.total();
    const std::vector<double> direct = autocorrelation(total, maxLag);
    for (std::size_t k = 0; k <= maxLag; ++k)
    {
        EXPECT_NEAR(sum[k], direct[k], 1e-12) << "lag " << k;
    }
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            const std::vector<double> d = crossCorrelationDirect(parts[i], parts[j], maxLag);
            for (std::size_t k = 0; k <= maxLag; k += 17)
            {
                EXPECT_NEAR(products(i, j)[k], d[k], 1e-12) << i << j << " lag " << k;
            }
        }
    }
    // The planted cross term: <J1(0) J12(0)> = 0.5 <J1^2> ~ 0.5.
    EXPECT_NEAR(products(0, 2)[0], 0.5, 0.05);
    EXPECT_NEAR(products(0, 1)[0], 0.0, 0.1);
}

TEST(FftCorrelator, RejectsBadInput)
{
    const std::vector<double> a = randomSeries(10, 3);
    EXPECT_THROW(autocorrelation(a, 10), std::invalid_argument);
    EXPECT_THROW(crossCorrelation(a, randomSeries(11, 4), 2), std::invalid_argument);
    VectorFrames frames(10, VectorFrame(4, 3));
    frames[5] = VectorFrame(3, 3);
    EXPECT_THROW(vectorAutocorrelation(frames, 2), std::invalid_argument);
}

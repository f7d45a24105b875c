#include "correlation/MultipleTauCorrelator.hpp"
#include "correlation/GreenKubo.hpp"
#include "OrnsteinUhlenbeck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sdf::correlation;
using sdf::correlation::test::OuParameters;
using sdf::correlation::test::makeOuTrajectory;

namespace
{

// Feeds a stored trajectory to a streaming correlator, closing blockCount blocks.
MultipleTauCorrelator stream
(
    const VectorFrames& frames,
    const MultipleTauSettings& settings,
    std::size_t blockCount
)
{
    MultipleTauCorrelator correlator(static_cast<std::size_t>(frames.front().rows()), 3, settings);
    const std::size_t blockLength = frames.size() / blockCount;
    for (std::size_t t = 0; t < blockCount * blockLength; ++t)
    {
        correlator.add(frames[t].array());
        if ((t + 1) % blockLength == 0)
        {
            correlator.closeBlock();
        }
    }
    return correlator;
}

} // namespace

TEST(MultipleTau, LagGridAndBoundedMemory)
{
    MultipleTauSettings s;
    s.pointsPerLevel = 16;
    s.averagingFactor = 2;
    s.levels = 4;
    MultipleTauCorrelator c(1, 1, s);
    for (int t = 0; t < 10000; ++t)
    {
        c.add(Eigen::ArrayXXd::Constant(1, 1, 1.0));
    }
    const LaggedCorrelation r = c.result();
    // 16 lags on level 0, then 8 per level: 0..15, 16..30 step 2, 32..60 step 4, 64..120 step 8.
    ASSERT_EQ(r.lags.size(), 16u + 3u * 8u);
    EXPECT_EQ(r.lags[15], 15u);
    EXPECT_EQ(r.lags[16], 16u);
    EXPECT_EQ(r.lags[17], 18u);
    EXPECT_EQ(r.lags.back(), 120u);
    // A constant correlates to itself at every lag, on every level.
    EXPECT_LT((r.values - 1.0).abs().maxCoeff(), 1e-15);
    EXPECT_EQ(c.samplesAdded(), 10000u);
    EXPECT_THROW(MultipleTauCorrelator(1, 1, MultipleTauSettings{15, 2, 4}), std::invalid_argument);
    EXPECT_THROW(c.add(Eigen::ArrayXXd::Zero(2, 1)), std::invalid_argument);
}

TEST(MultipleTau, CosineLevelZeroMatchesDirectSumToRoundOff)
{
    const std::size_t n = 3000;
    const double w = 0.3;
    std::vector<double> a(n);
    MultipleTauCorrelator c(1, 1);
    for (std::size_t t = 0; t < n; ++t)
    {
        a[t] = std::cos(w * t);
        c.add(Eigen::ArrayXXd::Constant(1, 1, a[t]));
    }
    const LaggedCorrelation r = c.result();
    const std::vector<double> direct = crossCorrelationDirect(a, a, 15);
    for (std::size_t k = 0; k < 16; ++k)
    {
        ASSERT_EQ(r.lags[k], k);
        EXPECT_NEAR(r.values(k, 0), direct[k], 1e-13) << "lag " << k;
        EXPECT_EQ(r.pairs[k], n - k);
    }
}

// Streaming and exact correlators on the same Ornstein-Uhlenbeck data: equal
// at level 0, close beyond, and the same Green-Kubo integral.
TEST(MultipleTau, AgreesWithTheFftCorrelatorOnOrnsteinUhlenbeck)
{
    OuParameters ou;
    ou.particles = 16;
    ou.samples = 20000;
    const auto trajectory = makeOuTrajectory(ou);
    const std::size_t blocks = 8;
    const MultipleTauCorrelator mt = stream(trajectory.velocities, MultipleTauSettings(), blocks);
    const LaggedCorrelation streamed = mt.result();

    const std::size_t maxLag = 600;
    const Eigen::MatrixX3d exact = vectorAutocorrelation(trajectory.velocities, maxLag);
    std::size_t compared = 0;
    for (std::size_t i = 0; i < streamed.lags.size() && streamed.lags[i] <= maxLag; ++i)
    {
        const std::size_t k = streamed.lags[i];
        for (int c = 0; c < 3; ++c)
        {
            const double tolerance = k < 16 ? 1e-12 : 0.01 * ou.variance;
            EXPECT_NEAR(streamed.values(i, c), exact(k, c), tolerance) << "lag " << k;
        }
        ++compared;
    }
    EXPECT_GT(compared, 50u);

    // Green-Kubo from the streamed blocks (log grid) vs the FFT blocks.
    ASSERT_EQ(mt.blocks().size(), blocks);
    const GreenKuboResult gkStreamed = greenKubo(mt.blocks(), ou.dt, -1);
    EXPECT_GE(gkStreamed.times.back(), 40.0 * ou.tau);
    const auto fftBlocks = blockEstimates(vectorAutocorrelation, trajectory.velocities, 400, blocks);
    const GreenKuboResult gkFft = greenKubo(uniformTimes(401, ou.dt), componentSeries(fftBlocks, -1));
    ASSERT_TRUE(gkStreamed.plateauFound);
    EXPECT_NEAR(gkStreamed.integral.value, gkFft.integral.value, 0.01 * gkFft.integral.value);
    EXPECT_NEAR(gkStreamed.integral.value, ou.sampledDiffusivity(), 3.0 * gkStreamed.integral.standardError);
    EXPECT_NEAR(gkStreamed.integral.standardError / gkFft.integral.standardError, 1.0, 0.5);
    std::cout << "[ figures  ] multiple-tau D = " << gkStreamed.integral.value << " +- "
              << gkStreamed.integral.standardError << ", FFT D = " << gkFft.integral.value << " +- "
              << gkFft.integral.standardError << ", exact " << ou.sampledDiffusivity() << "\n";

    // The blocks partition the pairs: their pair-weighted mean is the total.
    for (std::size_t i = 0; i < 20; ++i)
    {
        double weighted = 0.0;
        std::uint64_t pairs = 0;
        for (const LaggedCorrelation& b : mt.blocks())
        {
            weighted += b.values(i, 1) * static_cast<double>(b.pairs[i]);
            pairs += b.pairs[i];
        }
        EXPECT_NEAR(weighted / pairs, streamed.values(i, 1), 1e-12);
    }
}

TEST(MultipleTau, SeriesProductsMatchTheFftProducts)
{
    const std::size_t n = 5000;
    std::mt19937_64 engine(77);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<std::vector<double>> parts(3, std::vector<double>(n));
    double smooth = 0.0;
    for (std::size_t t = 0; t < n; ++t)
    {
        smooth = 0.95 * smooth + normal(engine);   // a correlated shared component
        parts[0][t] = smooth + normal(engine);
        parts[1][t] = normal(engine);
        parts[2][t] = 0.5 * smooth + normal(engine);
    }
    SeriesProductCorrelator streaming(3);
    for (std::size_t t = 0; t < n; ++t)
    {
        streaming.add(Eigen::Vector3d(parts[0][t], parts[1][t], parts[2][t]));
    }
    const LaggedCorrelation r = streaming.result();
    const SeriesProductCorrelations exact = seriesProductCorrelations(parts, 15);
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            const Eigen::Index column = static_cast<Eigen::Index>(SeriesProductCorrelator::column(i, j, 3));
            for (std::size_t k = 0; k < 16; ++k)
            {
                EXPECT_NEAR(r.values(k, column), exact(i, j)[k], 1e-11) << i << j << " lag " << k;
            }
        }
    }
    // <J1(0) J12(5)> ~ 0.5 * 0.95^5 * var(smooth) is clearly non-zero; <J2 J1> is not.
    EXPECT_GT(r.values(5, SeriesProductCorrelator::column(0, 2, 3)), 1.5);
    EXPECT_NEAR(r.values(5, SeriesProductCorrelator::column(1, 0, 3)), 0.0, 0.3);
}

TEST(MultipleTau, ExportedStateResumesBitForBit)
{
    OuParameters ou;
    ou.particles = 3;
    ou.samples = 5000;
    const auto trajectory = makeOuTrajectory(ou);
    MultipleTauSettings settings;
    settings.levels = 8;

    MultipleTauCorrelator uninterrupted(3, 3, settings);
    MultipleTauCorrelator first(3, 3, settings);
    for (std::size_t t = 0; t < ou.samples; ++t)
    {
        uninterrupted.add(trajectory.velocities[t].array());
        if ((t + 1) % 1000 == 0)
        {
            uninterrupted.closeBlock();
        }
        if (t < 2345)
        {
            first.add(trajectory.velocities[t].array());
            if ((t + 1) % 1000 == 0)
            {
                first.closeBlock();
            }
        }
    }
    const MultipleTauState saved = first.exportState();

    MultipleTauCorrelator resumed(3, 3, settings);
    resumed.importState(saved);
    EXPECT_EQ(resumed.samplesAdded(), 2345u);
    for (std::size_t t = 2345; t < ou.samples; ++t)
    {
        resumed.add(trajectory.velocities[t].array());
        if ((t + 1) % 1000 == 0)
        {
            resumed.closeBlock();
        }
    }
    const LaggedCorrelation a = uninterrupted.result(), b = resumed.result();
    EXPECT_EQ(a.lags, b.lags);
    EXPECT_EQ(a.pairs, b.pairs);
    EXPECT_TRUE((a.values == b.values).all());
    ASSERT_EQ(resumed.blocks().size(), 5u);
    EXPECT_TRUE((uninterrupted.blocks()[1].values == resumed.blocks()[1].values).all());
    EXPECT_TRUE((uninterrupted.blocks()[4].values == resumed.blocks()[4].values).all());

    // A state from another shape is refused and leaves the target untouched.
    MultipleTauCorrelator other(2, 3, settings);
    EXPECT_THROW(other.importState(saved), std::invalid_argument);
    EXPECT_EQ(other.samplesAdded(), 0u);
    MultipleTauState truncated = saved;
    truncated.reals.pop_back();
    MultipleTauCorrelator target(3, 3, settings);
    EXPECT_THROW(target.importState(truncated), std::invalid_argument);
    EXPECT_EQ(target.samplesAdded(), 0u);
}

#include "correlation/GreenKubo.hpp"
#include "correlation/MeanSquareDisplacement.hpp"
#include "OrnsteinUhlenbeck.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::correlation;
using sdf::correlation::test::OuParameters;
using sdf::correlation::test::makeOuTrajectory;

TEST(GreenKubo, RunningIntegralOfExponentialIsTheTrapezoidSum)
{
    const double dt = 0.1;
    const std::vector<double> t = uniformTimes(401, dt);
    std::vector<double> f(t.size());
    for (std::size_t k = 0; k < t.size(); ++k)
    {
        f[k] = std::exp(-t[k]);
    }
    const std::vector<double> I = runningIntegral(t, f);
    // Trapezoid of exp(-t) on [0, T]: (dt/2) coth(dt/2) (1 - exp(-T)).
    const double x = dt / 2.0;
    EXPECT_NEAR(I.back(), x / std::tanh(x) * (1.0 - std::exp(-t.back())), 1e-12);
    EXPECT_NEAR(I.back(), 1.0, 1e-3);
    // Non-uniform grid: exact for a straight line.
    const std::vector<double> times = {0.0, 0.5, 2.0, 7.0};
    const std::vector<double> line = {1.0, 2.0, 5.0, 15.0};   // 1 + 2t
    EXPECT_NEAR(runningIntegral(times, line).back(), 7.0 + 49.0, 1e-12);
    EXPECT_THROW(runningIntegral({0.0, 1.0, 1.0}, {1.0, 1.0, 1.0}), std::invalid_argument);
}

// An Ornstein-Uhlenbeck velocity has VACF <v^2> exp(-t/tau): D = <v^2> tau per
// component, exactly. Green-Kubo and MSD must both recover it within their
// reported errors and within 2 %, and agree with each other (item 12).
TEST(GreenKubo, OrnsteinUhlenbeckDiffusivityByGreenKuboAndMsd)
{
    const OuParameters ou;   // 32 particles x 3 components x 40000 samples
    const auto trajectory = makeOuTrajectory(ou);
    const double exact = ou.sampledDiffusivity();
    const std::size_t blocks = 10;

    const std::size_t maxLag = 400;   // 40 tau
    const auto vacf = blockEstimates(vectorAutocorrelation, trajectory.velocities, maxLag, blocks);
    const std::vector<double> times = uniformTimes(maxLag + 1, ou.dt);
    const GreenKuboResult gk = greenKubo(times, componentSeries(vacf, -1));

    ASSERT_TRUE(gk.plateauFound);
    EXPECT_GT(gk.plateauTime, 2.0 * ou.tau);
    EXPECT_LT(gk.plateauTime, 15.0 * ou.tau);
    EXPECT_GT(gk.integral.standardError, 0.0);
    EXPECT_LT(gk.integral.standardError, 0.01 * exact);
    EXPECT_NEAR(gk.integral.value, exact, 3.0 * gk.integral.standardError);
    EXPECT_NEAR(gk.integral.value / ou.continuumDiffusivity(), 1.0, 0.02);
    // The correlation function itself: C(0) = <v^2>, C(tau) = <v^2>/e.
    EXPECT_NEAR(gk.meanCorrelation[0], ou.variance, 0.02 * ou.variance);
    EXPECT_NEAR(gk.meanCorrelation[10], ou.variance * std::exp(-1.0), 0.02 * ou.variance);

    // Per component too (anisotropic flows report D_xx, D_yy, D_zz).
    for (int c = 0; c < 3; ++c)
    {
        const GreenKuboResult gkc = greenKubo(times, componentSeries(vacf, c));
        EXPECT_NEAR(gkc.integral.value, exact, 4.0 * gkc.integral.standardError) << "component " << c;
    }

    const std::size_t msdLag = 800;   // 80 tau; fit 10..80 tau, intercept absorbs -2 D tau
    const auto msdBlocks = blockEstimates(meanSquareDisplacement, trajectory.positions, msdLag, blocks);
    std::vector<std::vector<double>> totalMsd;
    for (const Eigen::MatrixX3d& m : msdBlocks)
    {
        std::vector<double> sum(m.rows());
        for (Eigen::Index k = 0; k < m.rows(); ++k)
        {
            sum[k] = m.row(k).sum();
        }
        totalMsd.push_back(sum);
    }
    const EinsteinResult einstein = einsteinDiffusivity(
        uniformTimes(msdLag + 1, ou.dt), totalMsd, {10.0 * ou.tau, 80.0 * ou.tau, 3});
    EXPECT_GT(einstein.diffusivity.standardError, 0.0);
    EXPECT_NEAR(einstein.diffusivity.value, exact, 3.0 * einstein.diffusivity.standardError);
    EXPECT_NEAR(einstein.diffusivity.value / ou.continuumDiffusivity(), 1.0, 0.02);
    EXPECT_NEAR(einstein.fitOfMean.diffusivity, einstein.diffusivity.value, 1e-9 * exact);
    // Consecutive MSD points are correlated: the naive fit error is far too small.
    EXPECT_LT(einstein.fitOfMean.fitStandardError, 0.5 * einstein.diffusivity.standardError);

    const double combined = std::hypot(gk.integral.standardError, einstein.diffusivity.standardError);
    EXPECT_NEAR(gk.integral.value, einstein.diffusivity.value, 3.0 * combined);

    std::cout << "[ figures  ] OU exact D = " << exact
              << "  Green-Kubo " << gk.integral.value << " +- " << gk.integral.standardError
              << " (plateau at t = " << gk.plateauTime << ", window to " << gk.windowEnd << ")"
              << "  MSD " << einstein.diffusivity.value << " +- " << einstein.diffusivity.standardError
              << " (naive fit error " << einstein.fitOfMean.fitStandardError << ")\n";
}

// The reported errors must be honest: over independent replicas, the spread of
// the estimates matches the mean reported standard error within a factor 1.5.
TEST(GreenKubo, ReportedErrorsMatchTheSpreadOverReplicas)
{
    const std::size_t replicas = 30;
    std::vector<Estimate> gkEstimates, msdEstimates;
    for (std::size_t r = 0; r < replicas; ++r)
    {
        OuParameters ou;
        ou.particles = 4;
        ou.samples = 8000;
        ou.seed = 1000 + r;
        const auto trajectory = makeOuTrajectory(ou);
        const auto vacf = blockEstimates(vectorAutocorrelation, trajectory.velocities, 200, 8);
        gkEstimates.push_back(greenKubo(uniformTimes(201, ou.dt), componentSeries(vacf, -1)).integral);

        const auto msd = blockEstimates(meanSquareDisplacement, trajectory.positions, 300, 8);
        std::vector<std::vector<double>> x;
        for (const auto& m : msd)
        {
            x.push_back(std::vector<double>(m.col(0).data(), m.col(0).data() + m.rows()));
        }
        msdEstimates.push_back(einsteinDiffusivity(uniformTimes(301, ou.dt), x, {5.0, 15.0, 1}).diffusivity);
    }
    for (const auto* estimates : {&gkEstimates, &msdEstimates})
    {
        double reportedSquares = 0.0;
        for (const Estimate& e : *estimates)
        {
            reportedSquares += e.standardError * e.standardError;
        }
        const double reported = std::sqrt(reportedSquares / replicas);
        const Estimate combined = combineReplicas(*estimates);
        const double spread = combined.standardError * std::sqrt(double(replicas));
        std::cout << "[ figures  ] replica spread " << spread << ", mean reported error " << reported
                  << ", ratio " << spread / reported << ", combined D " << combined.value
                  << " +- " << combined.standardError << "\n";
        EXPECT_GT(spread / reported, 1.0 / 1.5);
        EXPECT_LT(spread / reported, 1.5);
        EXPECT_NEAR(combined.value, OuParameters().sampledDiffusivity(), 3.0 * combined.standardError);
    }
}

TEST(GreenKubo, NoPlateauIsReportedWhenTheIntegralKeepsGrowing)
{
    // A correlation that has not decayed within the data (e.g. a run too short).
    const std::vector<double> times = uniformTimes(101, 0.1);
    std::vector<std::vector<double>> blocks;
    for (int b = 0; b < 5; ++b)
    {
        std::vector<double> c(times.size());
        for (std::size_t k = 0; k < c.size(); ++k)
        {
            c[k] = std::exp(-times[k] / 50.0) * (1.0 + 0.01 * b);
        }
        blocks.push_back(c);
    }
    const GreenKuboResult gk = greenKubo(times, blocks);
    EXPECT_FALSE(gk.plateauFound);
    EXPECT_DOUBLE_EQ(gk.windowEnd, times.back());
    EXPECT_THROW(greenKubo(times, {blocks[0]}), std::invalid_argument);
}

TEST(GreenKubo, NegativeBackscatteringIsIntegratedNotCutOff)
{
    // Dense-fluid VACF shape: exp(-t) cos(2t) has a negative lobe; its integral
    // is 1/5. Tiny block-to-block noise: the plateau must come after the lobe.
    const std::vector<double> times = uniformTimes(2001, 0.01);
    std::vector<std::vector<double>> blocks;
    for (int b = 0; b < 6; ++b)
    {
        std::vector<double> c(times.size());
        for (std::size_t k = 0; k < c.size(); ++k)
        {
            c[k] = std::exp(-times[k]) * std::cos(2.0 * times[k]) + 1e-4 * (b - 2.5) * std::exp(-times[k]);
        }
        blocks.push_back(c);
    }
    const GreenKuboResult gk = greenKubo(times, blocks);
    ASSERT_TRUE(gk.plateauFound);
    EXPECT_NEAR(gk.integral.value, 0.2, 1e-3);
    EXPECT_GT(gk.plateauTime, 2.0);
}

TEST(GreenKubo, WindowEndsByTheLatestTime)
{
    // I(t) = t (a correlation that never decays): without a plateau the integral is
    // the mean over the latest full window, [t_end / 2, t_end]. Bounded by latestTime
    // 4 the window is [2, 4] (mean 3); unbounded it is the data's end, [5, 10] (7.5).
    const std::vector<double> times = uniformTimes(101, 0.1);
    std::vector<std::vector<double>> blocks;
    for (int b = 0; b < 5; ++b)
    {
        blocks.emplace_back(times.size(), 1.0 + 0.01 * (b - 2));
    }
    PlateauSettings bounded;
    bounded.latestTime = 4.0;
    const GreenKuboResult gk = greenKubo(times, blocks, bounded);
    EXPECT_FALSE(gk.plateauFound);
    EXPECT_NEAR(gk.windowEnd, 4.0, 1e-12);
    EXPECT_NEAR(gk.plateauTime, 2.0, 1e-12);
    EXPECT_NEAR(gk.integral.value, 3.0, 1e-9);
    // the jackknife reads the same window: the block scatter of a window mean of
    // (1 + 0.01 (b - 2)) t, i.e. 3 x 0.01 sqrt(2.5/5) (7.5 x that unbounded)
    EXPECT_NEAR(gk.integral.standardError, 3 * 0.01 * std::sqrt(0.5), 1e-9);
    const GreenKuboResult unbounded = greenKubo(times, blocks);
    EXPECT_NEAR(unbounded.windowEnd, 10.0, 1e-12);
    EXPECT_NEAR(unbounded.integral.value, 7.5, 1e-9);
    EXPECT_NEAR(unbounded.integral.standardError, 7.5 * 0.01 * std::sqrt(0.5), 1e-9);
    // a bound between lags: the window ends at the last lag before it
    PlateauSettings offGrid;
    offGrid.latestTime = 4.05;
    EXPECT_NEAR(greenKubo(times, blocks, offGrid).windowEnd, 4.0, 1e-12);
    // without a plateau the window starts at earliestTime where that is later
    // than t_end / 2: [3, 4], mean 3.5
    PlateauSettings pastDecay = bounded;
    pastDecay.earliestTime = 3.0;
    const GreenKuboResult late = greenKubo(times, blocks, pastDecay);
    EXPECT_NEAR(late.plateauTime, 3.0, 1e-12);
    EXPECT_NEAR(late.integral.value, 3.5, 1e-9);

    // exp(-t) with tiny noise: the plateau (I = 1 within 1e-4) comes near t = 9;
    // with latestTime 3 no window [t_p, 2 t_p] inside 3 is flat, so the integral is
    // the mean of 1 - exp(-t) over [1.5, 3], flagged, and never read past 3
    const std::vector<double> fine = uniformTimes(3001, 0.01);
    std::vector<std::vector<double>> decaying;
    for (int b = 0; b < 6; ++b)
    {
        std::vector<double> c(fine.size());
        for (std::size_t k = 0; k < c.size(); ++k)
        {
            c[k] = std::exp(-fine[k]) * (1.0 + 1e-4 * (b - 2.5));
        }
        decaying.push_back(c);
    }
    const GreenKuboResult free = greenKubo(fine, decaying);
    ASSERT_TRUE(free.plateauFound);
    EXPECT_GT(free.plateauTime, 5.0);
    EXPECT_NEAR(free.integral.value, 1.0, 1e-3);
    PlateauSettings short3;
    short3.latestTime = 3.0;
    const GreenKuboResult cut = greenKubo(fine, decaying, short3);
    EXPECT_FALSE(cut.plateauFound);
    EXPECT_LE(cut.windowEnd, 3.0 + 1e-12);
    const double expected = 1.0 - (std::exp(-1.5) - std::exp(-3.0)) / 1.5;
    EXPECT_NEAR(cut.integral.value, expected, 1e-3);

    // latestTime 12: a full window [t_p, 2 t_p] needs t_p <= 6, before the
    // plateau; cut at the last lag it is accepted down to end/t_p = 1.2
    PlateauSettings short12;
    short12.latestTime = 12.0;
    EXPECT_FALSE(greenKubo(fine, decaying, short12).plateauFound);
    short12.clippedWindowRatio = 1.2;
    const GreenKuboResult clipped = greenKubo(fine, decaying, short12);
    ASSERT_TRUE(clipped.plateauFound);
    EXPECT_GT(clipped.plateauTime, 6.0);
    EXPECT_LE(clipped.plateauTime, 10.0 + 1e-12);
    EXPECT_NEAR(clipped.windowEnd, 12.0, 1e-9);
    EXPECT_NEAR(clipped.integral.value, 1.0, 1e-3);
}

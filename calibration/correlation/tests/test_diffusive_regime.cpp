// The diffusive-regime check on processes whose diffusivity is known exactly:
// an Ornstein-Uhlenbeck velocity (exponential VACF) measured over long blocks passes;
// the same over blocks of a few correlation times fails on the window; a velocity with
// a slow second mode (a VACF tail carrying half of D) fails on the MSD's slope; one whose
// variance halves in mid-run fails on the drift.
#include "correlation/DiffusiveRegime.hpp"
#include "correlation/FftCorrelator.hpp"
#include "OrnsteinUhlenbeck.hpp"

#include <gtest/gtest.h>

using namespace sdf::correlation;
using sdf::correlation::test::OuParameters;
using sdf::correlation::test::OuTrajectory;
using sdf::correlation::test::makeOuTrajectory;

namespace
{

//- The cell run's sequence (transport/Measurements.cpp): Green-Kubo, tau_v, the window
//  past the decay, Green-Kubo again with its plateau searched from the window's start,
//  the MSD over the window, the check.
DiffusiveRegimeCheck measure
(
    const OuTrajectory& trajectory,
    double dt,
    std::size_t maxLag,
    std::size_t blocks,
    GreenKuboResult& gk,
    EinsteinResult& einstein
)
{
    const std::vector<double> times = uniformTimes(maxLag + 1, dt);
    const auto vacf = componentSeries
    (
        blockEstimates(vectorAutocorrelation, trajectory.velocities, maxLag, blocks), -1
    );
    const double tauV = velocityCorrelationTime(greenKubo(times, vacf));
    const EinsteinWindow window = diffusiveWindow(tauV, times, 3);
    PlateauSettings plateau;
    plateau.earliestTime = window.fitStart;
    gk = greenKubo(times, vacf, plateau);

    std::vector<std::vector<double>> msd;
    for (const Eigen::MatrixX3d& b :
         blockEstimates(meanSquareDisplacement, trajectory.positions, maxLag, blocks))
    {
        msd.push_back(std::vector<double>(b.rows()));
        for (Eigen::Index k = 0; k < b.rows(); ++k) msd.back()[k] = b.row(k).sum();
    }
    einstein = einsteinDiffusivity(times, msd, window);
    return checkDiffusiveRegime(times, msd, window, einstein, gk, tauV);
}

} // namespace


TEST(DiffusiveRegime, CorrelationTimeOfAnExponentialIsTau)
{
    GreenKuboResult gk;
    gk.times = uniformTimes(2001, 0.01);
    for (double t : gk.times) gk.meanCorrelation.push_back(3.0*std::exp(-t/0.5));
    gk.meanRunningIntegral = runningIntegral(gk.times, gk.meanCorrelation);
    EXPECT_NEAR(velocityCorrelationTime(gk), 0.5, 1e-4);
    // A negative lobe lowers the final integral, not the decay time.
    gk.meanCorrelation.back() = -1e3;
    gk.meanRunningIntegral = runningIntegral(gk.times, gk.meanCorrelation);
    EXPECT_NEAR(velocityCorrelationTime(gk), 0.5, 1e-4);

    // The window starts on the lag grid: the first lag at or after 5 tau_v
    const std::vector<double> lags = uniformTimes(101, 0.1);
    const EinsteinWindow w = diffusiveWindow(0.5, lags, 3);
    EXPECT_EQ(w.fitStart, lags[25]);
    EXPECT_EQ(w.fitEnd, 10.0);
    EXPECT_EQ(diffusiveWindow(0.493, lags, 3).fitStart, lags[25]);
    // A decay time past the lags: the last third, flagged by the check
    EXPECT_EQ(diffusiveWindow(0.5, uniformTimes(31, 0.1), 1).fitStart, uniformTimes(31, 0.1)[20]);
    // Few lags: the last three stay in the window (the fit needs 3 points)
    const std::vector<double> five = uniformTimes(5, 0.1);
    EXPECT_EQ(diffusiveWindow(10.0, five, 3).fitStart, five[2]);
    EXPECT_THROW(diffusiveWindow(0.5, uniformTimes(2, 0.1), 3), std::invalid_argument);
    // tau_v over bounded lags: the exponential's tau from its first 2 time units
    EXPECT_NEAR(velocityCorrelationTime(gk, 2.0), 0.5*(1 - std::exp(-4.0)), 1e-3);
}

TEST(DiffusiveRegime, LongBlocksOfAnExponentialVacfPass)
{
    const OuParameters ou;   // tau 0.5, 40000 samples of 0.05: 10 blocks of 400 tau
    GreenKuboResult gk;
    EinsteinResult einstein;
    const DiffusiveRegimeCheck check = measure(makeOuTrajectory(ou), ou.dt, 400, 10, gk, einstein);
    EXPECT_NEAR(check.correlationTime, ou.tau, 0.05*ou.tau);
    EXPECT_GE(check.fitStart, 5*check.correlationTime);
    EXPECT_LT(check.fitStart, 5*check.correlationTime + ou.dt);
    EXPECT_TRUE(check.windowPastDecay);
    EXPECT_TRUE(check.slopeFlat) << check.verdict();
    EXPECT_TRUE(check.greenKuboAgrees) << check.verdict();
    EXPECT_TRUE(check.stationary) << check.verdict();
    EXPECT_TRUE(check.converged()) << check.verdict();
    EXPECT_EQ(check.verdict(), "diffusive");
    // Both estimates within 3 of their errors of the exact D; the plateau searched
    // from the window's start.
    EXPECT_NEAR(gk.integral.value, ou.sampledDiffusivity(), 3*gk.integral.standardError);
    EXPECT_NEAR(einstein.diffusivity.value, ou.sampledDiffusivity(), 3*einstein.diffusivity.standardError);
    EXPECT_GE(gk.plateauTime, check.fitStart);
}

TEST(DiffusiveRegime, BlocksOfAFewCorrelationTimesFailOnTheWindow)
{
    OuParameters ou;
    ou.samples = 4000;   // 20 blocks of 200 samples = 20 tau; MSD lags to 2 tau
    GreenKuboResult gk;
    EinsteinResult einstein;
    const DiffusiveRegimeCheck check = measure(makeOuTrajectory(ou), ou.dt, 20, 20, gk, einstein);
    EXPECT_FALSE(check.windowPastDecay);
    EXPECT_FALSE(check.converged());
    EXPECT_NE(check.verdict().find("before the VACF's decay"), std::string::npos) << check.verdict();
    // The MSD there is short of D (over [4/3, 2] tau the chord slope is 0.81 D): what
    // the check exists to catch.
    EXPECT_LT(einstein.diffusivity.value, 0.9*ou.sampledDiffusivity());
}

TEST(DiffusiveRegime, ASlowVacfTailFailsOnTheMsdSlope)
{
    // Fast mode: variance 2, tau 0.5 (D 1); slow mode: variance 0.05, tau 20 (D 1).
    OuParameters fast, slow;
    slow.variance = 0.05;
    slow.tau = 20.0;
    slow.seed = 777;
    OuTrajectory sum = makeOuTrajectory(fast);
    const OuTrajectory s = makeOuTrajectory(slow);
    for (std::size_t k = 0; k < sum.velocities.size(); ++k)
    {
        sum.velocities[k] += s.velocities[k];
        sum.positions[k] += s.positions[k];
    }
    GreenKuboResult gk;
    EinsteinResult einstein;
    const DiffusiveRegimeCheck check = measure(sum, fast.dt, 1000, 10, gk, einstein);
    EXPECT_TRUE(check.windowPastDecay);   // past the fast decay ...
    EXPECT_FALSE(check.slopeFlat);        // ... but the slow mode still adds
    EXPECT_GT(check.slopeChange.value, 0.0);
    EXPECT_FALSE(check.converged());
    EXPECT_NE(check.verdict().find("MSD slope not flat"), std::string::npos) << check.verdict();
}

TEST(DiffusiveRegime, ACellThatAgesFailsOnTheDrift)
{
    // The velocity variance halves in the middle of the run (as D falls when a dense
    // cell slowly orders): D of the later blocks is half that of the earlier ones.
    OuParameters first;
    OuParameters second;
    second.variance = 0.5*first.variance;
    second.seed = 99;
    first.samples = second.samples = 20000;
    OuTrajectory run = makeOuTrajectory(first);
    const OuTrajectory later = makeOuTrajectory(second);
    const Eigen::MatrixX3d end = run.positions.back() + run.velocities.back()*first.dt;
    for (std::size_t k = 0; k < later.velocities.size(); ++k)
    {
        run.velocities.push_back(later.velocities[k]);
        run.positions.push_back(end + later.positions[k]);
    }
    GreenKuboResult gk;
    EinsteinResult einstein;
    const DiffusiveRegimeCheck check = measure(run, first.dt, 400, 10, gk, einstein);
    EXPECT_TRUE(check.windowPastDecay);
    EXPECT_FALSE(check.stationary);
    EXPECT_LT(check.drift.value, -0.3*einstein.diffusivity.value);
    EXPECT_FALSE(check.converged());
    EXPECT_NE(check.verdict().find("D drifts over the run"), std::string::npos) << check.verdict();
}

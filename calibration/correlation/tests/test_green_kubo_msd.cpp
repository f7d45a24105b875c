// Green-Kubo = MSD over an envelope of cells, the way the calibration's cells are
// judged (benchmarks/demDriving/run gkMsd): z = (D_GK - D_MSD)/sigma per cell, and
// over the cells (1) chi2 inside its 99 % interval, (2) mean z within 3 of its
// standard errors, (3) no cell beyond the multiplicity-corrected threshold. The cells
// here are Ornstein-Uhlenbeck trajectories (exact D, no bias between the two
// estimators), measured by the cell run's sequence: the criterion must pass on them,
// and must fail when Green-Kubo is biased by 5 % or when sigma ignores that both
// estimates come from the same blocks.
#include "correlation/DiffusiveRegime.hpp"
#include "correlation/FftCorrelator.hpp"
#include "OrnsteinUhlenbeck.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::correlation;
using sdf::correlation::test::OuParameters;
using sdf::correlation::test::makeOuTrajectory;

namespace
{

struct Cell
{
    Estimate gk;
    Estimate msd;
    Estimate difference;   // as the check reports it (paired over blocks)
};

//- One cell: Green-Kubo with its plateau searched from the Einstein window's start,
//  the MSD over that window, the check's D_GK - D_MSD (DiffusiveRegime's test does
//  the same, one cell).
Cell measureCell(const OuParameters& ou, std::size_t maxLag, std::size_t blocks)
{
    const auto trajectory = makeOuTrajectory(ou);
    const std::vector<double> times = uniformTimes(maxLag + 1, ou.dt);
    const auto vacf = componentSeries
    (
        blockEstimates(vectorAutocorrelation, trajectory.velocities, maxLag, blocks), -1
    );
    const double tauV = velocityCorrelationTime(greenKubo(times, vacf));
    const EinsteinWindow window = diffusiveWindow(tauV, times, 3);
    PlateauSettings plateau;
    plateau.earliestTime = window.fitStart;
    const GreenKuboResult gk = greenKubo(times, vacf, plateau);
    std::vector<std::vector<double>> msd;
    for (const Eigen::MatrixX3d& b :
         blockEstimates(meanSquareDisplacement, trajectory.positions, maxLag, blocks))
    {
        msd.push_back(std::vector<double>(b.rows()));
        for (Eigen::Index k = 0; k < b.rows(); ++k) msd.back()[k] = b.row(k).sum();
    }
    const EinsteinResult einstein = einsteinDiffusivity(times, msd, window);
    const DiffusiveRegimeCheck check =
        checkDiffusiveRegime(times, msd, window, einstein, gk, tauV);
    return {gk.integral, einstein.diffusivity, check.greenKuboMinusMsd};
}

//- An envelope of 24 cells: three correlation times (a dense cell's fast decay to a
//  slow one, as the envelope's phi and T span), eight seeds each; blocks of 200 tau
//  or more, so that every cell is in the diffusive regime.
std::vector<Cell> envelope()
{
    std::vector<Cell> cells;
    for (const double tau : {0.25, 0.5, 1.0})
    {
        for (std::uint64_t seed = 1; seed <= 8; ++seed)
        {
            OuParameters ou;
            ou.tau = tau;
            ou.particles = 16;
            ou.samples = 32000;   // 8 blocks of 4000 samples (200 tau at tau 1)
            ou.seed = 1000*seed + std::uint64_t(4*tau);
            cells.push_back(measureCell(ou, 400, 8));
        }
    }
    return cells;
}

//- z of every cell, D_GK scaled by gkFactor; sigma paired over blocks (the check's)
//  or, pairedError false, the two errors in quadrature.
std::vector<double> zOf(const std::vector<Cell>& cells, double gkFactor, bool pairedError)
{
    std::vector<double> z;
    for (const Cell& c : cells)
    {
        const double sigma = pairedError
          ? c.difference.standardError
          : std::hypot(c.gk.standardError, c.msd.standardError);
        z.push_back((gkFactor*c.gk.value - c.msd.value)/sigma);
    }
    return z;
}

} // namespace


TEST(GreenKuboMsd, CriterionFiguresAreExact)
{
    // chi2 quantiles for 36 degrees of freedom (tables: 17.887, 61.581); the two-sided
    // 5 % family-wise threshold over 36 normal z: 1 - (1 - p)^36 = 0.05, p = 1.4238e-3
    std::vector<double> z(36, 1.0);
    const AgreementOverCells a = agreementOverCells(z);
    EXPECT_NEAR(a.chiSquareLow, 17.887, 1e-3);
    EXPECT_NEAR(a.chiSquareHigh, 61.581, 1e-3);
    EXPECT_NEAR(a.threshold, 3.1898, 1e-4);
    EXPECT_DOUBLE_EQ(a.chiSquare, 36.0);
    EXPECT_DOUBLE_EQ(a.meanZ.value, 1.0);
    EXPECT_DOUBLE_EQ(a.meanZ.standardError, 0.0);
    EXPECT_FALSE(a.meanWithin());   // every z +1: a common bias, however small its scatter
    EXPECT_TRUE(a.chiSquareInside());
    EXPECT_TRUE(a.flagged.empty());
    EXPECT_NEAR(agreementOverCells(std::vector<double>(8, 0.0)).threshold, 2.7270, 1e-4);

    // one cell at 3.3 of 36 otherwise alternating +-0.9: flagged, the rest passes
    std::vector<double> one(36);
    for (std::size_t i = 0; i < one.size(); ++i) one[i] = i % 2 ? 0.9 : -0.9;
    one[7] = 3.3;
    const AgreementOverCells b = agreementOverCells(one);
    ASSERT_EQ(b.flagged.size(), 1u);
    EXPECT_EQ(b.flagged[0], 7u);
    EXPECT_TRUE(b.chiSquareInside());
    EXPECT_TRUE(b.meanWithin()) << b.summary();
    EXPECT_FALSE(b.passes());

    EXPECT_THROW(agreementOverCells({1.0}), std::invalid_argument);
    EXPECT_THROW(agreementOverCells({1.0, NAN}), std::invalid_argument);
    EXPECT_THROW(agreementOverCells({1.0, 2.0}, 1.0), std::invalid_argument);
}

TEST(GreenKuboMsd, AnUnbiasedEnvelopePassesAndABiasedOneFails)
{
    const std::vector<Cell> cells = envelope();
    const AgreementOverCells honest = agreementOverCells(zOf(cells, 1.0, true));
    std::cout << "unbiased, paired errors: " << honest.summary() << '\n';
    EXPECT_TRUE(honest.passes()) << honest.summary();

    // Green-Kubo 5 % high: the common shift of z is caught by the mean (item 2)
    const AgreementOverCells biased = agreementOverCells(zOf(cells, 1.05, true));
    std::cout << "Green-Kubo +5 %:         " << biased.summary() << '\n';
    EXPECT_FALSE(biased.meanWithin()) << biased.summary();

    // Both estimates integrate the same velocities of the same blocks, so their
    // errors are strongly correlated: in quadrature, sigma is too large and chi2 falls
    // below its interval (item 1 catches errors that are not honest either way).
    const AgreementOverCells quadrature = agreementOverCells(zOf(cells, 1.0, false));
    std::cout << "errors in quadrature:    " << quadrature.summary() << '\n';
    EXPECT_LT(quadrature.chiSquare, quadrature.chiSquareLow) << quadrature.summary();
}

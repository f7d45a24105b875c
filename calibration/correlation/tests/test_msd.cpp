#include "correlation/MeanSquareDisplacement.hpp"
#include "correlation/GreenKubo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace sdf::correlation;

TEST(Msd, BallisticMotionGivesExactQuadratic)
{
    // x_p(t) = x0_p + u_p t: MSD_c(k) = <u_pc^2> (k dt)^2 exactly.
    const std::size_t n = 500, particles = 7;
    const double dt = 0.01;
    std::mt19937_64 engine(5);
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixX3d x0(particles, 3), u(particles, 3);
    for (Eigen::Index p = 0; p < x0.rows(); ++p)
    {
        for (int c = 0; c < 3; ++c)
        {
            x0(p, c) = 10.0 * normal(engine);
            u(p, c) = normal(engine);
        }
    }
    VectorFrames frames;
    for (std::size_t t = 0; t < n; ++t)
    {
        frames.push_back(x0 + u * (dt * t));
    }
    const Eigen::MatrixX3d msd = meanSquareDisplacement(frames, 300);
    const Eigen::RowVector3d meanSquareSpeed = u.cwiseAbs2().colwise().mean();
    for (std::size_t k = 0; k <= 300; k += 7)
    {
        for (int c = 0; c < 3; ++c)
        {
            const double exact = meanSquareSpeed(c) * (k * dt) * (k * dt);
            EXPECT_NEAR(msd(k, c), exact, 1e-10 * (1.0 + exact)) << "lag " << k;
        }
    }
}

TEST(Msd, MatchesTheDirectDoubleSum)
{
    const std::size_t n = 400, particles = 3;
    std::mt19937_64 engine(9);
    std::normal_distribution<double> normal(0.0, 1.0);
    VectorFrames frames(n, VectorFrame(particles, 3));
    Eigen::MatrixX3d x = Eigen::MatrixX3d::Zero(particles, 3);
    for (auto& f : frames)
    {
        for (Eigen::Index p = 0; p < x.rows(); ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                x(p, c) += normal(engine);
            }
        }
        f = x;
    }
    const std::size_t maxLag = 150;
    const Eigen::MatrixX3d msd = meanSquareDisplacement(frames, maxLag, 50, 350);
    for (std::size_t k = 0; k <= maxLag; k += 5)
    {
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        for (std::size_t t = 50; t + k < 350; ++t)
        {
            sum += (frames[t + k] - frames[t]).cwiseAbs2().colwise().sum();
        }
        sum /= double((300 - k) * particles);
        EXPECT_LT((msd.row(k) - sum).cwiseAbs().maxCoeff(), 1e-9 * (1.0 + sum.maxCoeff())) << "lag " << k;
    }
    // Random walk of unit steps: MSD(1) = <step^2> = 1 per component.
    EXPECT_NEAR(msd.row(1).mean(), 1.0, 0.15);
}

TEST(Msd, EinsteinFitRecoversAKnownLine)
{
    const std::vector<double> t = uniformTimes(101, 0.1);
    std::vector<double> msd(t.size());
    for (std::size_t k = 0; k < t.size(); ++k)
    {
        msd[k] = 6.0 * 0.25 * t[k] - 0.3;   // D = 0.25, 3 dimensions
    }
    const EinsteinFit fit = fitEinsteinSlope(t, msd, {2.0, 9.0, 3});
    EXPECT_NEAR(fit.diffusivity, 0.25, 1e-13);
    EXPECT_NEAR(fit.intercept, -0.3, 1e-12);
    EXPECT_NEAR(fit.fitStandardError, 0.0, 1e-12);
    EXPECT_EQ(fit.points, 71u);
    EXPECT_NEAR(fitEinsteinSlope(t, msd, {2.0, 9.0, 1}).diffusivity, 0.75, 1e-13);
    EXPECT_THROW(fitEinsteinSlope(t, msd, {2.0, 2.1, 3}), std::invalid_argument);
}

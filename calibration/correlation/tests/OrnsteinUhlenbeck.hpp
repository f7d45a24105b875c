// Test helper: Ornstein-Uhlenbeck velocities, exact discretisation, so the
// sampled autocorrelation is exactly variance * exp(-|k| dt / tau) and the
// diffusivity per component is variance * tau (times the trapezoid factor of
// the sampling, x coth x with x = dt / (2 tau), which both Green-Kubo
// trapezoids and positions x += v dt reproduce exactly).
#ifndef sdf_correlation_tests_OrnsteinUhlenbeck_hpp
#define sdf_correlation_tests_OrnsteinUhlenbeck_hpp

#include "correlation/FftCorrelator.hpp"

#include <cmath>
#include <cstdint>
#include <random>

namespace sdf::correlation::test
{

struct OuParameters
{
    double variance = 2.0;      // <v_x^2>
    double tau = 0.5;           // correlation time
    double dt = 0.05;           // sample interval
    std::size_t particles = 32;
    std::size_t samples = 40000;
    std::uint64_t seed = 12345;

    double continuumDiffusivity() const { return variance * tau; }
    double sampledDiffusivity() const
    {
        const double x = dt / (2.0 * tau);
        return variance * tau * x / std::tanh(x);
    }
};

struct OuTrajectory
{
    VectorFrames velocities;
    VectorFrames positions;   // unwrapped, x(t+dt) = x(t) + v(t) dt
};

inline OuTrajectory makeOuTrajectory(const OuParameters& ou)
{
    std::mt19937_64 engine(ou.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double decay = std::exp(-ou.dt / ou.tau);
    const double kick = std::sqrt(ou.variance * (1.0 - decay * decay));
    const Eigen::Index rows = static_cast<Eigen::Index>(ou.particles);

    OuTrajectory trajectory;
    trajectory.velocities.reserve(ou.samples);
    trajectory.positions.reserve(ou.samples);
    Eigen::MatrixX3d v(rows, 3), x = Eigen::MatrixX3d::Zero(rows, 3);
    for (Eigen::Index p = 0; p < rows; ++p)
    {
        for (int c = 0; c < 3; ++c)
        {
            v(p, c) = std::sqrt(ou.variance) * normal(engine);   // stationary start
        }
    }
    for (std::size_t t = 0; t < ou.samples; ++t)
    {
        trajectory.velocities.push_back(v);
        trajectory.positions.push_back(x);
        x += v * ou.dt;
        for (Eigen::Index p = 0; p < rows; ++p)
        {
            for (int c = 0; c < 3; ++c)
            {
                v(p, c) = decay * v(p, c) + kick * normal(engine);
            }
        }
    }
    return trajectory;
}

} // namespace sdf::correlation::test

#endif

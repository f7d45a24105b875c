#include "KolmogorovForcing.hpp"
#include "ThreadTeam.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

KolmogorovForcing::KolmogorovForcing
(
    double amplitude,
    int waves,
    double boxHeight,
    double timeStep
)
:
    amplitude_(amplitude),
    waves_(waves),
    wavenumber_(2*M_PI*waves/boxHeight),
    timeStep_(timeStep)
{
    if (!std::isfinite(amplitude) || !(amplitude > 0))
    {
        throw std::invalid_argument
        (
            "Kolmogorov forcing: forcingAmplitude must be finite and positive [m/s^2], got "
          + std::to_string(amplitude)
        );
    }
    if (waves < 1)
    {
        throw std::invalid_argument
        (
            "Kolmogorov forcing: forcingWaves must be a whole number >= 1 (periods of the"
            " forcing over the box height), got " + std::to_string(waves)
        );
    }
    if (!(boxHeight > 0) || !(timeStep > 0))
    {
        throw std::invalid_argument("Kolmogorov forcing: box height and time step must be positive");
    }
}

double KolmogorovForcing::acceleration(double y) const
{
    return amplitude_*std::sin(wavenumber_*y);
}

void KolmogorovForcing::afterStep(Particles& p, int nThreads)
{
    const int n = int(p.size());
    // momentum of the increments, in index order (independent of the threads)
    double mass = 0, momentum = 0;
    for (int i = 0; i < n; ++i)
    {
        mass += p.mass[i];
        momentum += p.mass[i]*acceleration(p.y[i]);
    }
    const double meanIncrement = momentum/mass*timeStep_;
    forEachIndex(nThreads, n, [&](int i)
    {
        p.vx[i] += acceleration(p.y[i])*timeStep_ - meanIncrement;
    });
}

} // namespace sdf::dem

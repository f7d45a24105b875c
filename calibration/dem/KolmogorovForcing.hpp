#ifndef sdf_dem_KolmogorovForcing_hpp
#define sdf_dem_KolmogorovForcing_hpp

// Kolmogorov flow: a body force per unit mass a(y) = a0 sin(2 pi m y / ly) along x acts on
// every particle, so the cell carries a steady sinusoidal mean flow u_x(y) whose shear
// rate |du_x/dy| is largest where u_x = 0 and zero where |u_x| is largest. The shear
// heats the grains, the inelastic collisions cool them, and nothing else steers the
// temperature: the cell holds side by side a hot high-shear layer and a cold low-shear
// one, the non-uniform shear in which kinetic sieving acts (the direct sieving test,
// apps/kineticSievingCell.cpp; benchmarks/kineticSieving).
//
// The force is applied as a velocity increment a(y_i) dt after each step (first order in
// the splitting, the force being smooth on the particles' scale); the increments'
// mass-weighted mean is removed, so the total momentum stays exactly zero (the sum over
// particles is taken in index order on one thread: the same whatever the threads).
// Temperatures and stresses of the Simulation are taken about the cell's mean velocity,
// so they include the mean flow: measure profiles per layer instead (the app does).
//
// Not selectable by name: hand it to a Simulation built with mode nve through
// Simulation::setDriving.

#include "Driving.hpp"

#include <cmath>

namespace sdf::dem
{

class KolmogorovForcing : public Driving
{
public:
    //- Throws std::invalid_argument naming the entry: forcingAmplitude finite and > 0,
    //  forcingWaves (m) >= 1, box height and time step > 0.
    KolmogorovForcing(double amplitude, int waves, double boxHeight, double timeStep);

    std::string name() const override { return "kolmogorov"; }
    void afterStep(Particles& particles, int nThreads) override;
    //- sqrt(a0/k): the speed the force gives over a 1/k of the box (a flow a thousand
    //  times more energetic than this is taken for a blow-up)
    double velocityScale() const override { return std::sqrt(amplitude_/wavenumber_); }

    //- Body force per unit mass at height y [m/s^2].
    double acceleration(double y) const;

    double amplitude() const { return amplitude_; }
    int waves() const { return waves_; }
    //- 2 pi m / ly [1/m]
    double wavenumber() const { return wavenumber_; }

private:
    double amplitude_;
    int waves_;
    double wavenumber_;
    double timeStep_;
};

} // namespace sdf::dem

#endif

// Elastic frictionless NVE: relative energy drift < 1e-4 over 1e5 steps, and the energy
// error of velocity Verlet scales as dt^2 (three time steps).
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::dem;

namespace
{

struct EnergyRecord
{
    double maxDeviation = 0;   // max |E(t) - E0| / E0
    double finalDrift = 0;     // (E_end - E0) / E0
    double maxTimeStep = 0;    // dt_max: the contact law's recommended maximum
};

//- An elastic frictionless run of the binary cell over timeInMaxSteps x dt_max at
//  dt = dtFraction dt_max.
EnergyRecord runElastic(ContactModel model, double dtFraction, double timeInMaxSteps)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {240, 30}, 0.3, 0.03, 0, 11);
    SimulationSettings s = test::softContacts(1.0, 0.0);
    s.contact.model = model;
    s.contact.youngsModulus = 5e7;
    EnergyRecord rec;
    rec.maxTimeStep = ContactLaw(s.contact, species).maximumTimeStep();
    s.timeStep = dtFraction*rec.maxTimeStep;
    Simulation sim(species, s, packing.particles, packing.box);
    const double e0 = test::totalEnergy(sim);
    const long steps = std::lround(timeInMaxSteps*rec.maxTimeStep/s.timeStep);
    sim.run(steps, [&](const Simulation& x)
    {
        rec.maxDeviation = std::max(rec.maxDeviation, std::abs(test::totalEnergy(x) - e0)/e0);
    }, 10);
    rec.finalDrift = (test::totalEnergy(sim) - e0)/e0;
    return rec;
}

} // namespace

TEST(ElasticNVE, LinearDriftBelow1e4Over1e5Steps)
{
    // 1e5 steps at the largest admissible dt (t_c/50)
    const EnergyRecord rec = runElastic(ContactModel::linearSpringDashpot, 1.0, 1e5);
    std::cout << "linear, dt = t_c/50, 1e5 steps: drift " << rec.finalDrift
              << ", max deviation " << rec.maxDeviation << "\n";
    EXPECT_LT(std::abs(rec.finalDrift), 1e-4);
}

TEST(ElasticNVE, HertzDriftBelow1e4Over1e5Steps)
{
    // dt_max = 0.2 t_Rayleigh gives only ~20 steps per contact for these soft grains
    // (E = 5e7 Pa, v ~ 0.1 m/s) and a drift of ~1e-3 over 1e5 steps; a quarter of it
    // (0.05 t_Rayleigh, ~90 steps per contact) meets 1e-4
    const EnergyRecord rec = runElastic(ContactModel::hertzMindlin, 0.25, 0.25e5);
    std::cout << "Hertz, dt = 0.05 t_Rayleigh, 1e5 steps: drift " << rec.finalDrift
              << ", max deviation " << rec.maxDeviation << "\n";
    EXPECT_LT(std::abs(rec.finalDrift), 1e-4);
}

TEST(ElasticNVE, EnergyErrorScalesAsDtSquared)
{
    std::vector<double> dts, errors;
    for (double f : {1.0, 0.5, 0.25})
    {
        const EnergyRecord rec = runElastic(ContactModel::linearSpringDashpot, f, 2500);
        dts.push_back(f*rec.maxTimeStep);
        errors.push_back(rec.maxDeviation);
        std::cout << "dt = " << f << " dt_max: max |dE|/E " << rec.maxDeviation << "\n";
    }
    // least-squares slope of log(error) against log(dt)
    double mx = 0, my = 0;
    for (int k = 0; k < 3; ++k) { mx += std::log(dts[k])/3; my += std::log(errors[k])/3; }
    double sxy = 0, sxx = 0;
    for (int k = 0; k < 3; ++k)
    {
        sxy += (std::log(dts[k]) - mx)*(std::log(errors[k]) - my);
        sxx += (std::log(dts[k]) - mx)*(std::log(dts[k]) - mx);
    }
    const double order = sxy/sxx;
    std::cout << "energy error order in dt: " << order << "\n";
    EXPECT_NEAR(order, 2.0, 0.3);
}

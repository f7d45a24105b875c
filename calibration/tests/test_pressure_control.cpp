// The pressure-controlled sheared cell (Barostat.hpp, RheologyMeasurement): the barostat's
// law and its affine dilation exactly, a bitwise resume, the target held with the density
// an output, the rheology's two signatures (rate strengthening of mu and dilatancy of phi
// with I), the regimes at the extremes (jammed, gas, ordered: the bond order Q6 of
// crystals against its known values), and the refusals. The comparison with
// LAMMPS is benchmarks/rheologyVsLammps (docs/validation.md).
#include "CellRun.hpp"
#include "Measurements.hpp"
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>

using namespace sdf::dem;
using test::contains;
using test::messageOf;

namespace
{

// the cell of benchmarks/rheologyVsLammps, small: 1 and 2 mm, equal solids volume,
// k_n 2000 N/m, e 0.7, friction 0.5, targetPressure 1333 Pa (k_n/(p d) = 1000)
constexpr double pressure = 1333, rhoS = 2500, dMean = 1.5e-3;

double shearRateFor(double inertialNumber)
{
    return inertialNumber*std::sqrt(pressure/rhoS)/dMean;
}

CellRunSettings pressureControlledCell(double inertialNumber, int particles = 200)
{
    CellRunSettings s;
    s.species = test::binary();
    s.volumeFractions = {0.5, 0.5};
    s.particles = particles;
    s.solidsFraction = 0.5;
    s.simulation = test::shearedCell(shearRateFor(inertialNumber), 0.7, 0.5);
    s.simulation.contact.tangentialStiffnessRatio = 2.0/7.0;
    s.simulation.contact.tangentialDampingRatio = 0.5;
    s.simulation.timeStep = 1e-6;
    s.simulation.targetPressure = pressure;
    const double strain = 1/s.simulation.shearRate;
    s.equilibrationTime = 6*strain;
    s.maxEquilibrationTime = 12*strain;
    s.samplingTime = 8*strain;
    s.sampleEvery = 100;
    s.blocks = 8;
    s.seed = 3;
    return s;
}

//- Close-packed spheres of diameter 1 mm touching their 12 neighbours with an overlap of
//  0.1 % of d, in a periodic box: face-centred cubic (n^3 cubic cells of 4) or hexagonal
//  close packed (hexagonal layers A B A B along z, 2n rows of n in a layer, 2n layers)
std::pair<Particles, PeriodicBox> closePacked(bool hexagonal, int n = 4)
{
    const double d = 1e-3, r = 0.5005*d, m = 2500*4.0/3.0*M_PI*r*r*r;
    Particles p;
    PeriodicBox box;
    if (!hexagonal)
    {
        const double a = d*std::sqrt(2.0);
        box.lx = box.ly = box.lz = n*a;
        const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                for (int k = 0; k < n; ++k)
                    for (const auto& b : basis)
                        p.add((i + b[0])*a, (j + b[1])*a, (k + b[2])*a, r, m, 0);
    }
    else
    {
        const double rowSpacing = d*std::sqrt(3.0)/2, layerSpacing = d*std::sqrt(2.0/3.0);
        box.lx = n*d;
        box.ly = 2*n*rowSpacing;
        box.lz = 2*n*layerSpacing;
        for (int layer = 0; layer < 2*n; ++layer)
        {
            // B layers over the A layers' triangle centres
            const double sx = layer % 2 ? 0.5*d : 0, sy = layer % 2 ? rowSpacing/3 : 0;
            for (int row = 0; row < 2*n; ++row)
                for (int i = 0; i < n; ++i)
                    p.add((i + 0.5*(row % 2))*d + sx, row*rowSpacing + sy,
                          layer*layerSpacing, r, m, 0);
        }
    }
    for (std::size_t i = 0; i < p.size(); ++i) p.id[i] = int(i);
    return {p, box};
}

} // namespace

// Q6 of the contacts against its values for the perfect crystals (Steinhardt, Nelson &
// Ronchetti 1983: 0.57452 fcc, 0.48476 hcp), one bond in any direction (exactly 1: the
// addition theorem, sum_m |Y_6m|^2 = 13/(4 pi), which every m's term enters), and a random
// packing's near 0
TEST(BondOrder, CrystalsAndDisorder)
{
    const auto species = test::mono();
    for (const Eigen::Vector3d& direction :
         {Eigen::Vector3d(0.3, -0.5, 0.8), Eigen::Vector3d(-0.9, 0.2, 0.1),
          Eigen::Vector3d(0.1, 0.7, -0.2), Eigen::Vector3d(0, 0, 1)})
    {
        const double d = 1e-3, r = 0.5005*d, m = 2500*4.0/3.0*M_PI*r*r*r;
        const Eigen::Vector3d n = direction.normalized(), c(5*d, 5*d, 5*d);
        Particles pair;
        pair.add(c.x(), c.y(), c.z(), r, m, 0);
        pair.add(c.x() + d*n.x(), c.y() + d*n.y(), c.z() + d*n.z(), r, m, 0);
        pair.id = {0, 1};
        PeriodicBox box;
        box.lx = box.ly = box.lz = 10*d;
        Simulation sim(species, test::softContacts(0.7, 0.5), pair, box);
        const Simulation::ContactSummary bond = sim.contactSummary();
        ASSERT_EQ(bond.contacts, 1);
        EXPECT_NEAR(bond.bondOrderQ6, 1.0, 1e-12) << direction.transpose();
    }
    for (const bool hexagonal : {false, true})
    {
        auto [particles, box] = closePacked(hexagonal);
        Simulation sim(species, test::softContacts(0.7, 0.5), particles, box);
        const Simulation::ContactSummary c = sim.contactSummary();
        ASSERT_EQ(c.contacts, 6*long(sim.particles().size())) << "12 neighbours each";
        EXPECT_NEAR(c.bondOrderQ6, hexagonal ? 0.48476 : 0.57452, 5e-5)
            << (hexagonal ? "hcp" : "fcc");
    }
    const Packing random = test::packedCell(species, {300}, 0.6, 1e-6);
    Simulation sim(species, test::softContacts(0.7, 0.5), random.particles, random.box);
    const Simulation::ContactSummary c = sim.contactSummary();
    ASSERT_GT(c.contacts, 150);
    std::cout << "random packing (phi 0.6, " << c.contacts << " contacts): Q6 "
              << c.bondOrderQ6 << std::endl;
    EXPECT_LT(c.bondOrderQ6, 0.1);
}

// A cell whose contacts are a crystal's is "ordered", not a dense flow (its mu and phi are
// not the bulk's); nothing else about it is refused
TEST(PressureControl, CrystallisedCellIsOrdered)
{
    auto [particles, box] = closePacked(false);
    const auto species = test::mono();
    Simulation sim(species, test::softContacts(0.7, 0.5), particles, box);
    RheologyMeasurement m(8);
    for (long k = 0; k < 16; ++k) m.sample(sim, k);
    CellRunResult result;
    result.settings = pressureControlledCell(0.05);
    result.settings.species = species;
    result.settings.volumeFractions = {1.0};
    result.meanDiameter = 1e-3;
    m.finish(result, 16);
    const RheologyResult& r = result.rheology;
    EXPECT_NEAR(r.bondOrder.value, 0.57452, 5e-5);
    EXPECT_EQ(r.regime, "ordered") << r.regimeReason;
    EXPECT_TRUE(contains(r.regimeReason, "crystallised")) << r.regimeReason;
    EXPECT_FALSE(r.denseSteadyFlow());
}

TEST(PressureControl, BarostatLaw)
{
    const double dt = 1e-6, tau = 0.1;
    const Barostat b(100, tau, dt);
    // ln s = every dt/tau (sigma/p - 1), clamped to maxStrainPerUpdate (exp and log
    // round trip: within 1e-16 of the exponent)
    EXPECT_EQ(b.dilation(100), 1.0);
    EXPECT_NEAR(std::log(b.dilation(150)), Barostat::every*dt/tau*0.5, 1e-16);
    EXPECT_NEAR(std::log(b.dilation(50)), -Barostat::every*dt/tau*0.5, 1e-16);
    EXPECT_NEAR(std::log(b.dilation(1e9)), Barostat::maxStrainPerUpdate, 1e-16);
    EXPECT_NEAR(std::log(b.dilation(-1e9)), -Barostat::maxStrainPerUpdate, 1e-16);
    // loop gain 1/5 in a packing of modulus k/d
    EXPECT_DOUBLE_EQ(Barostat::automaticRelaxationTime(2e3, 1e-3, 1333, dt), 5.0*Barostat::every*dt*2e3/(1333*1e-3));
}

// Every update scales ly and every y by the barostat's factor for the sigma_yy it measured
// (bitwise); between updates ly does not move; a resumed run continues bit for bit.
TEST(PressureControl, AffineDilationAndBitwiseResume)
{
    const auto species = test::binary();
    SimulationSettings st = test::shearedCell(shearRateFor(0.1), 0.7, 0.5);
    st.timeStep = 1e-6;
    st.targetPressure = pressure;
    const Packing packing = test::packedCell(species, {80, 10}, 0.55, 0.01, st.shearRate);
    Simulation sim(species, st, packing.particles, packing.box);
    ASSERT_NE(sim.barostat(), nullptr);
    EXPECT_GT(sim.settings().barostatTime, 0);   // the automatic one, reported
    int updates = 0;
    for (int k = 0; k < 3*Barostat::every; ++k)
    {
        const double ly = sim.box().ly;
        const std::vector<double> y(sim.particles().y.begin(), sim.particles().y.end());
        sim.step();
        if (sim.stepCount() % Barostat::every != 0)
        {
            EXPECT_EQ(sim.box().ly, ly);
            continue;
        }
        ++updates;
        const double s = sim.barostat()->dilation(sim.lastBarostatStress());
        EXPECT_NE(s, 1.0);
        EXPECT_EQ(sim.box().ly, ly*s);
    }
    EXPECT_EQ(updates, 3);

    // bitwise resume across an update
    sim.run(1234);
    const SimulationState state = sim.exportState();
    Simulation resumed(species, st, packing.particles, packing.box);
    resumed.importState(state);
    sim.run(2000);
    resumed.run(2000);
    EXPECT_EQ(resumed.box().ly, sim.box().ly);
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().y, sim.particles().y));
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().vx, sim.particles().vx));
}

// From a loose start (phi 0.5) the cell compresses until sigma_yy holds the target; the
// solids fraction is then an output. mu rises and phi falls with I (rate strengthening and
// dilatancy), each by more than 3 combined standard errors.
TEST(PressureControl, HoldsThePressureAndMeasuresTheRheology)
{
    CellRunResult low, high;
    for (auto [I, result] : {std::pair{0.1, &low}, std::pair{0.4, &high}})
    {
        *result = runCell(pressureControlledCell(I, 300));
        std::cout << summary(*result);
        const RheologyResult& r = result->rheology;
        SCOPED_TRACE(I);
        ASSERT_TRUE(r.measured);
        EXPECT_TRUE(r.pressureControlled);
        EXPECT_LE(std::abs(r.pressure.value - pressure), 3*r.pressure.standardError);
        EXPECT_LE(std::abs(r.pressure.value - pressure), 0.05*pressure);
        EXPECT_GT(r.solidsFraction.value, 0.54) << "compressed from the loose start";
        EXPECT_NEAR(r.inertialNumber.value, I, 0.05*I);
        EXPECT_TRUE(r.steady) << r.steadyCheck;
        EXPECT_EQ(r.regime, "dense flow") << r.regimeReason;
        EXPECT_TRUE(r.denseSteadyFlow());
        EXPECT_DOUBLE_EQ(r.meanDiameter, dMean);
    }
    const auto sigmas = [](const sdf::correlation::Estimate& a, const sdf::correlation::Estimate& b)
    {
        return (a.value - b.value)/std::hypot(a.standardError, b.standardError);
    };
    EXPECT_GT(sigmas(high.rheology.stressRatio, low.rheology.stressRatio), 3);
    EXPECT_GT(sigmas(low.rheology.solidsFraction, high.rheology.solidsFraction), 3);
}

// I -> 0: a one-species cell sheared a thousand times slower than its pressure's inertial
// time is reported as jammed (quasi-static), not a dense flow.
TEST(PressureControl, VanishingInertialNumberIsReportedJammed)
{
    CellRunSettings s = pressureControlledCell(1e-6, 150);
    s.species = test::mono();
    s.volumeFractions = {1.0};
    s.equilibrationTime = 0.02;
    s.maxEquilibrationTime = 0.1;
    s.samplingTime = 0.02;
    const RheologyResult r = runCell(s).rheology;
    EXPECT_EQ(r.regime, "jammed") << r.regimeReason;
    EXPECT_FALSE(r.denseSteadyFlow());
}

// Very high I: a volume-controlled dilute sheared cell is a gas (Z < 1), outside the
// dense regime.
TEST(PressureControl, DiluteShearIsReportedAsGas)
{
    CellRunSettings s = pressureControlledCell(0.1, 150);
    s.simulation.targetPressure = 0;
    s.solidsFraction = 0.05;
    s.simulation.shearRate = 100;
    s.equilibrationTime = s.maxEquilibrationTime = 0.02;
    s.samplingTime = 0.04;
    const RheologyResult r = runCell(s).rheology;
    EXPECT_FALSE(r.pressureControlled);
    EXPECT_EQ(r.regime, "gas") << r.regimeReason;
    EXPECT_LT(r.coordinationNumber.value, 1);
    EXPECT_FALSE(r.denseSteadyFlow());
}

TEST(PressureControl, Refusals)
{
    CellRunSettings s = pressureControlledCell(0.2, 100);
    s.simulation.targetPressure = -5;
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { runCell(s); }), "targetPressure must be a finite pressure > 0"));
    s.simulation.targetPressure = std::nan("");
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { runCell(s); }), "targetPressure"));
    s = pressureControlledCell(0.2, 100);
    s.simulation.mode = CellMode::thermostatted;
    s.simulation.targetTemperature = 0.01;
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { runCell(s); }), "pressure control is for a sheared cell"));
    s = pressureControlledCell(0.2, 100);
    s.simulation.barostatTime = -1;
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { runCell(s); }), "barostatTime must be >= 0"));

    // walls cannot stand in a cell whose extent moves
    const auto species = test::binary();
    SimulationSettings st = test::shearedCell(10, 0.7, 0.5);
    st.targetPressure = pressure;
    const Packing packing = test::packedCell(species, {160, 20}, 0.5, 0.01, 10);
    Simulation sim(species, st, packing.particles, packing.box);
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { sim.addWall(Wall{}); }), "cannot hold walls"));
}

// A target below what the shear's agitation alone exerts: the cell expands without end
// and is stopped with what it reached.
TEST(PressureControl, UnreachableLowPressureStopsTheRun)
{
    CellRunSettings s = pressureControlledCell(0.2, 100);
    s.simulation.targetPressure = 1e-6;
    s.simulation.barostatTime = 1e-4;
    s.simulation.shearRate = 300;
    s.equilibrationTime = s.maxEquilibrationTime = 0.05;
    const std::string message = messageOf<std::runtime_error>([&] { runCell(s); });
    EXPECT_TRUE(contains(message, "pressure control failed")) << message;
    EXPECT_TRUE(contains(message, "expanded to solids fraction")) << message;
}

// A barostat far too slow for the run: the pressure is not reached, and the run says so
// with what it reached instead of returning a result at another pressure.
TEST(PressureControl, PressureNotHeldIsAnError)
{
    CellRunSettings s = pressureControlledCell(0.2, 100);
    s.simulation.barostatTime = 1e3;
    s.equilibrationTime = s.maxEquilibrationTime = 0.002;
    s.samplingTime = 0.004;
    const std::string message = messageOf<std::runtime_error>([&] { runCell(s); });
    EXPECT_TRUE(contains(message, "did not hold targetPressure 1333 Pa")) << message;
    EXPECT_TRUE(contains(message, "sigma_yy reached")) << message;
}

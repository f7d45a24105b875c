// Bad input is refused with std::invalid_argument naming the entry; unstable runs stop
// with std::runtime_error and a diagnosis instead of producing garbage.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

using test::contains;
using test::messageOf;

TEST(InputValidation, SolidsFractionAboveJamming)
{
    PackingSettings ps;
    ps.solidsFraction = 0.66;
    ps.counts = {100};
    const std::string msg = messageOf<std::invalid_argument>([&] { makePacking(test::mono(), ps); });
    EXPECT_TRUE(contains(msg, "solidsFraction")) << msg;
    EXPECT_TRUE(contains(msg, "jamming")) << msg;
    ps.solidsFraction = 0.0;
    EXPECT_THROW(makePacking(test::mono(), ps), std::invalid_argument);
}

TEST(InputValidation, NonPositiveDiameterOrDensity)
{
    std::vector<Species> bad = {{"fine", 1e-3, 2500}, {"coarse", -2e-3, 2500}};
    const std::string msg = messageOf<std::invalid_argument>([&] { validateSpecies(bad); });
    EXPECT_TRUE(contains(msg, "coarse")) << msg;
    EXPECT_TRUE(contains(msg, "diameter")) << msg;
    bad[1].diameter = 0;
    EXPECT_THROW(validateSpecies(bad), std::invalid_argument);
    bad[1] = {"heavy", 1e-3, 0.0};
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { validateSpecies(bad); }), "density"));
}

TEST(InputValidation, RestitutionOutsideUnitInterval)
{
    for (double e : {0.0, -0.5, 1.01})
    {
        ContactSettings c;
        c.restitution = e;
        const std::string msg = messageOf<std::invalid_argument>([&] { ContactLaw(c, test::mono()); });
        EXPECT_TRUE(contains(msg, "restitution")) << msg;
    }
    ContactSettings ok;
    ok.restitution = 1.0;
    EXPECT_NO_THROW(ContactLaw(ok, test::mono()));
}

TEST(InputValidation, UnknownNames)
{
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([] { contactModelFromName("hooke2"); }), "linearSpringDashpot"));
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([] { cellModeFromName("sheared"); }), "leesEdwards"));
}

TEST(InputValidation, ThermostatNeedsPositiveTemperature)
{
    Packing packing = test::packedCell(test::mono(), {100}, 0.2, 0.01);
    SimulationSettings s;
    s.mode = CellMode::thermostatted;
    s.targetTemperature = 0;
    EXPECT_THROW(Simulation(test::mono(), s, packing.particles, packing.box), std::invalid_argument);
}

TEST(Stability, OverlapBeyondLimitStopsWithDiagnosis)
{
    // far too soft contacts for the impact speed: overlaps grow beyond 10 % of d
    Packing packing = test::packedCell(test::mono(), {150}, 0.3, 1.0);
    SimulationSettings s;
    s.contact.normalStiffness = 1.0;
    s.contact.restitution = 0.9;
    s.threads = 1;
    Simulation sim(test::mono(), s, packing.particles, packing.box);
    const std::string msg = messageOf<std::runtime_error>([&] { sim.run(200000); });
    EXPECT_TRUE(contains(msg, "overlap")) << msg;
    EXPECT_TRUE(contains(msg, "recommended maximum")) << msg;
}

TEST(Stability, EnergyBlowUpStopsWithDiagnosis)
{
    // unchecked time step far above the stability limit of the springs
    Packing packing = test::packedCell(test::mono(), {150}, 0.4, 0.01);
    SimulationSettings s;
    s.contact.normalStiffness = 2e3;
    s.contact.restitution = 1.0;
    s.contact.friction = 0.0;
    s.checkTimeStep = false;
    s.maxOverlapFraction = 0;       // only the energy check is active
    s.threads = 1;
    {
        ContactLaw law(s.contact, test::mono());
        s.timeStep = 60*law.maximumTimeStep();
    }
    Simulation sim(test::mono(), s, packing.particles, packing.box);
    const std::string msg = messageOf<std::runtime_error>([&] { sim.run(100000); });
    EXPECT_TRUE(contains(msg, "blow-up")) << msg;
}

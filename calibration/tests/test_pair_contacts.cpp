// Contact constants per species pair: the coefficient tables take a pair's restitution,
// friction and stiffness where set and the single values elsewhere (walls included);
// head-on collisions of each pair rebound with that pair's e (linear and Hertz); bad
// pair entries are refused naming the pair.
#include "Simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::dem;

namespace
{

// Two species of the same size and density, so only the pair constants differ.
const std::vector<Species> twoSpecies{{"glassA", 1e-3, 2500}, {"glassB", 1e-3, 2500}};

ContactSettings contactWithPairs(ContactModel model)
{
    ContactSettings c;
    c.model = model;
    c.restitution = 0.9;
    c.friction = 0.5;
    c.normalStiffness = 1e3;
    c.youngsModulus = 1e8;
    PairContactSettings ab;
    ab.first = "glassB";                // either order
    ab.second = "glassA";
    ab.restitution = 0.5;
    ab.friction = 0.1;
    if (model == ContactModel::linearSpringDashpot) ab.normalStiffness = 2e3;
    PairContactSettings bb;
    bb.first = bb.second = "glassB";
    bb.restitution = 0.7;
    c.pairs = {ab, bb};
    return c;
}

//- Restitution of a head-on collision of a particle of species a with one of b.
double headOn(const ContactSettings& contact, int a, int b)
{
    const double d = 1e-3, L = 20*d;
    Particles p;
    p.add(0.5*L - 0.501*d, 0.5*L, 0.5*L, 0.5*d, twoSpecies[a].mass(), a);
    p.add(0.5*L + 0.501*d, 0.5*L, 0.5*L, 0.5*d, twoSpecies[b].mass(), b);
    p.vx[0] = 0.25;
    p.vx[1] = -0.25;
    PeriodicBox box;
    box.lx = box.ly = box.lz = L;
    SimulationSettings s;
    s.contact = contact;
    s.mode = CellMode::nve;
    s.threads = 1;
    s.timeStep = 0.1*ContactLaw(contact, twoSpecies).maximumTimeStep();
    Simulation sim(twoSpecies, s, p, box);
    bool touched = false;
    for (long k = 0; k < 2000000; ++k)
    {
        sim.step();
        const double gap = std::abs(sim.particles().x[1] - sim.particles().x[0]) - d;
        if (gap < 0) touched = true;
        if (touched && gap > 1e-4*d) break;
    }
    EXPECT_TRUE(touched);
    // the particles keep their indices over a few hundred steps of two particles
    const Particles& q = sim.particles();
    const int i0 = sim.indexOfId(0), i1 = sim.indexOfId(1);
    return -(q.vx[i0] - q.vx[i1])/0.5;
}

} // namespace


TEST(PairContacts, TablesTakeThePairValuesWhereSet)
{
    const ContactLaw law(contactWithPairs(ContactModel::linearSpringDashpot), twoSpecies);
    EXPECT_EQ(law.pair(0, 0).restitution, 0.9);
    EXPECT_EQ(law.pair(0, 0).friction, 0.5);
    EXPECT_EQ(law.pair(0, 0).kn, 1e3);
    for (const auto& [a, b] : {std::pair{0, 1}, std::pair{1, 0}})
    {
        EXPECT_EQ(law.pair(a, b).restitution, 0.5);
        EXPECT_EQ(law.pair(a, b).friction, 0.1);
        EXPECT_EQ(law.pair(a, b).kn, 2e3);
    }
    EXPECT_EQ(law.pair(1, 1).restitution, 0.7);
    EXPECT_EQ(law.pair(1, 1).friction, 0.5);    // unset: the single value
    EXPECT_EQ(law.pair(1, 1).kn, 1e3);
    EXPECT_EQ(law.wall(1).restitution, 0.9);    // walls keep the single values
    // the dashpot of the pair's e: gamma_n = -2 ln e sqrt(m* k)/sqrt(pi^2 + ln^2 e)
    const double m = twoSpecies[0].mass()/2, le = std::log(0.5);
    EXPECT_NEAR(law.pair(0, 1).gammaN, -2*le*std::sqrt(m*2e3)/std::sqrt(M_PI*M_PI + le*le), 1e-15);
    // the time step follows the stiffest pair: t_c of kn 2e3 and e 0.5, over 50
    EXPECT_NEAR(law.maximumTimeStep(), std::sqrt(M_PI*M_PI + le*le)/std::sqrt(2e3/m)/50, 1e-15);
}

TEST(PairContacts, HeadOnCollisionsReboundWithThePairsRestitution)
{
    for (ContactModel model : {ContactModel::linearSpringDashpot, ContactModel::hertzMindlin})
    {
        const ContactSettings c = contactWithPairs(model);
        SCOPED_TRACE(contactModelName(model));
        EXPECT_NEAR(headOn(c, 0, 0), 0.9, 0.01*0.9);
        EXPECT_NEAR(headOn(c, 0, 1), 0.5, 0.01*0.5);
        EXPECT_NEAR(headOn(c, 1, 0), 0.5, 0.01*0.5);
        EXPECT_NEAR(headOn(c, 1, 1), 0.7, 0.01*0.7);
    }
}

TEST(PairContacts, BadPairsAreRefusedNamingThePair)
{
    const auto refused = [](const ContactSettings& c, const std::string& expected)
    {
        try
        {
            ContactLaw law(c, twoSpecies);
            ADD_FAILURE() << "accepted; expected: " << expected;
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    ContactSettings c = contactWithPairs(ContactModel::linearSpringDashpot);
    c.pairs[0].first = "sand";
    refused(c, "pair sand/glassA: unknown species 'sand'; valid: glassA glassB");

    c = contactWithPairs(ContactModel::linearSpringDashpot);
    c.pairs[1].first = "glassA";
    c.pairs[1].second = "glassB";     // glassA/glassB after glassB/glassA
    refused(c, "pair glassA/glassB given more than once");

    c = contactWithPairs(ContactModel::linearSpringDashpot);
    c.pairs[0].restitution = 1.5;
    refused(c, "pair glassB/glassA: restitution e = 1.5");

    c = contactWithPairs(ContactModel::linearSpringDashpot);
    c.pairs[1].friction = -0.1;
    refused(c, "pair glassB/glassB: friction must be >= 0");

    c = contactWithPairs(ContactModel::linearSpringDashpot);
    c.pairs[0].normalStiffness = 0.0;
    refused(c, "pair glassB/glassA: normalStiffness must be positive");

    c = contactWithPairs(ContactModel::hertzMindlin);
    c.pairs[1].normalStiffness = 3e3;
    refused(c, "pair glassB/glassB: normalStiffness applies to the linearSpringDashpot law only");

    EXPECT_EQ(pairContactText(contactWithPairs(ContactModel::linearSpringDashpot).pairs[0]),
              "glassB/glassA: e 0.5, mu 0.1, kn 2000");
}

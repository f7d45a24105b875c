// Rolling resistance (LAMMPS pair granular `rolling sds`, ContactForce.hpp): one contact's
// rolling force and torques against the formulas by hand (stick and slip), nothing changes
// when it is off, the couple conserves the pair's spin and dissipates their spin
// difference in a collision, a resume is bitwise, and the refusals. Its effect on the
// rheology against LAMMPS: benchmarks/rheologyVsLammps.
#include "ContactForce.hpp"
#include "Simulation.hpp"
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::dem;

namespace
{

//- Two 1 mm spheres overlapping by 1 % of d along x (i above j), at rest but spinning
//  about z with w_i - w_j = dw.
ContactKinematics spinningContact(double dw)
{
    ContactKinematics k{};
    const double r = 0.5e-3;
    k.r[0] = 2*r*0.99; k.r[1] = k.r[2] = 0;
    k.radiusI = k.radiusJ = r;
    k.wHalfI[2] = k.wSyncI[2] = 0.5*dw;
    k.wHalfJ[2] = k.wSyncJ[2] = -0.5*dw;
    return k;
}

PairCoefficients rollingPair(double muR)
{
    ContactSettings cs;
    cs.normalStiffness = 2e3;
    cs.friction = 0;                 // isolates the rolling part
    cs.restitution = 0.7;
    cs.rollingFriction = muR;
    const ContactLaw law(cs, test::mono());
    return law.pair(0, 0);
}

} // namespace

// Stick: xi_r = R* (dw x n) dt, F_r = -k_r xi_r - gamma_r R* (dw x n), torque R* n x F_r on
// i and the opposite on j; k_r and gamma_r default to the pair's k_t and gamma_t.
TEST(RollingResistance, StickAgainstTheFormula)
{
    const PairCoefficients c = rollingPair(10.0);
    EXPECT_EQ(c.rollingStiffness, c.kt);
    EXPECT_EQ(c.rollingDamping, c.gammaT);
    const double dw = 3.0, dt = 1e-6, rs = c.effectiveRadius, r = 0.5e-3;
    ContactHistory h;
    h.touching = true;
    h.n[0] = 1;
    const ContactResult res = evaluateContact<LinearSpringDashpot>(c, spinningContact(dw), h, dt);
    // n = x, dw = dw z: dw x n = dw y
    const double xi = rs*dw*dt, vr = rs*dw;
    EXPECT_DOUBLE_EQ(h.xr[1], xi);
    EXPECT_EQ(h.xr[0], 0.0);
    const double fr = -c.rollingStiffness*xi - c.rollingDamping*vr;   // along y
    // n x F_r = fr z; torque on i = R* fr z = -R_i torqueSumI
    EXPECT_DOUBLE_EQ(res.rollingTorque[2], rs*fr);
    EXPECT_DOUBLE_EQ(-r*res.torqueSumI[2], rs*fr);
    EXPECT_DOUBLE_EQ(-r*res.torqueSumJ[2], -rs*fr);
    EXPECT_EQ(res.force[1], 0.0) << "a couple, no force";
}

// Slip: |F_r| = mu_r |F_n| and the spring reset to xi_r = -(F_r + gamma_r v_r)/k_r.
TEST(RollingResistance, SlipIsCappedAndTheSpringReset)
{
    const double muR = 1e-3;
    const PairCoefficients c = rollingPair(muR);
    ContactHistory h;
    h.touching = true;
    h.n[0] = 1;
    h.xr[1] = 1e-3;   // a large stored displacement: slips
    const ContactResult res = evaluateContact<LinearSpringDashpot>(c, spinningContact(3.0), h, 1e-6);
    const double fn = c.kn*1e-5;   // overlap 1 % of 1 mm, at rest: no normal dashpot
    const double fr = -muR*fn;     // the spring pulls back (-y)
    EXPECT_NEAR(res.rollingTorque[2], c.effectiveRadius*fr, 1e-15*c.effectiveRadius*fn);
    const double vr = c.effectiveRadius*3.0;
    EXPECT_NEAR(h.xr[1], -(fr + c.rollingDamping*vr)/c.rollingStiffness, 1e-12*std::abs(h.xr[1]));
}

// Off: the torque sums are n x F_t, bit for bit, and no history is kept.
TEST(RollingResistance, OffChangesNothing)
{
    const PairCoefficients c = rollingPair(0.0);
    ContactHistory h;
    h.touching = true;
    h.n[0] = 1;
    const ContactResult res = evaluateContact<LinearSpringDashpot>(c, spinningContact(3.0), h, 1e-6);
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_EQ(res.torqueSumI[d], res.nCrossFt[d]);
        EXPECT_EQ(res.torqueSumJ[d], res.nCrossFt[d]);
        EXPECT_EQ(res.rollingTorque[d], 0.0);
        EXPECT_EQ(h.xr[d], 0.0);
    }
}

// A head-on collision of a spinning sphere with a resting one (no sliding friction): the
// rolling couple conserves the total spin I w_i + I w_j (equal spheres: the sum of the
// spins) and takes the spin difference down; without it the spins are untouched.
TEST(RollingResistance, CoupleConservesSpinAndBrakesTheDifference)
{
    for (const double muR : {0.0, 0.3})
    {
        SCOPED_TRACE(muR);
        const auto species = test::mono();
        SimulationSettings s = test::softContacts(0.7, 0.0);
        s.contact.rollingFriction = muR;
        s.timeStep = 1e-6;
        Particles p;
        const double L = 20e-3, r = 0.5e-3;
        p.add(0.5*L - 0.51e-3, 0.5*L, 0.5*L, r, species[0].mass(), 0);
        p.add(0.5*L + 0.51e-3, 0.5*L, 0.5*L, r, species[0].mass(), 0);
        p.vx[0] = 0.05; p.vx[1] = -0.05;
        p.wz[0] = 200;
        PeriodicBox box; box.lx = box.ly = box.lz = L;
        Simulation sim(species, s, p, box);
        sim.run(1000);   // touch after 2e-4 s, contact t_c ~ 6e-5 s, then apart
        const Particles& q = sim.particles();
        EXPECT_GT(q.x[1] - q.x[0], 2*r) << "separated";
        EXPECT_LT(q.vx[0], 0) << "collided";
        EXPECT_NEAR(q.wz[0] + q.wz[1], 200.0, 1e-9*200);
        if (muR == 0)
        {
            EXPECT_EQ(q.wz[0], 200.0);
            EXPECT_EQ(q.wz[1], 0.0);
        }
        else
        {
            EXPECT_LT(q.wz[0] - q.wz[1], 0.9*200) << "the couple brakes the spin difference";
            EXPECT_GT(q.wz[1], 0.0);
        }
    }
}

// A dense sheared cell with rolling resistance resumes bit for bit (the rolling
// displacements are part of the state).
TEST(RollingResistance, BitwiseResume)
{
    const auto species = test::binary();
    SimulationSettings st = test::shearedCell(50, 0.7, 0.5);
    st.timeStep = 1e-6;
    st.contact.rollingFriction = 0.2;
    const Packing packing = test::packedCell(species, {160, 20}, 0.58, 0.01, st.shearRate);
    Simulation sim(species, st, packing.particles, packing.box);
    sim.run(3000);
    const SimulationState state = sim.exportState();
    double stored = 0;
    for (const ContactHistory& h : state.history) stored += std::abs(h.xr[0]) + std::abs(h.xr[1]) + std::abs(h.xr[2]);
    EXPECT_GT(stored, 0) << "rolling displacements are kept";
    Simulation resumed(species, st, packing.particles, packing.box);
    resumed.importState(state);
    sim.run(2000);
    resumed.run(2000);
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().wz, sim.particles().wz));
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().x, sim.particles().x));
}

TEST(RollingResistance, Refusals)
{
    const auto message = [](const ContactSettings& cs)
    {
        return test::messageOf<std::invalid_argument>([&] { validateContactSettings(cs); });
    };
    ContactSettings cs;
    cs.rollingFriction = -0.1;
    EXPECT_NE(message(cs).find("rollingFriction must be >= 0"), std::string::npos) << message(cs);
    cs = {};
    cs.rollingStiffness = -1;
    EXPECT_NE(message(cs).find("rollingStiffness must be >= 0"), std::string::npos) << message(cs);
    cs = {};
    cs.pairs.push_back({"a", "b", {}, {}, {}, -0.2});
    EXPECT_NE(message(cs).find("pair a/b: rollingFriction must be >= 0"), std::string::npos) << message(cs);
    cs = {};
    cs.model = ContactModel::hertzMindlin;
    cs.rollingFriction = 0.1;
    EXPECT_NE(message(cs).find("needs rollingStiffness > 0 and rollingDamping > 0"), std::string::npos) << message(cs);
}

// The batched contact loop (ContactBatch.hpp) gives the bits of evaluateContact, contact by
// contact: over random contacts that take every branch of the law (new and old contacts,
// sticking and sliding, no friction, a tangential force that is zero or along the normal,
// a normal that turned round; rolling resistance sticking, at its cap and off for a pair),
// for both laws; and whole sheared runs, batched against contact by contact, on 1 and 2
// threads, with a frictionless species pair, with and without rolling resistance.
#include "ContactBatch.hpp"
#include "ContactForce.hpp"
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <cmath>
#include <cstring>
#include <optional>
#include <random>

using namespace sdf::dem;

namespace
{

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

enum class Kind { sticking, sliding, fresh, frictionless, turnedNormal, alongNormal, zeroForce };

struct Case
{
    Kind kind;
    ContactKinematics kin;
    ContactHistory history;
    int pair;   // 0: frictional, 1: frictionless
};

//- Random contacts of 1 and 2 mm spheres overlapping by up to 2 %, of the kind asked.
Case randomCase(Kind kind, std::mt19937_64& rng, double kn)
{
    const double kt = 2.0/7.0*kn;
    std::normal_distribution<double> gauss(0, 1);
    std::uniform_real_distribution<double> uniform(0, 1);
    Case c{kind, {}, {}, kind == Kind::frictionless ? 1 : 0};
    ContactKinematics& k = c.kin;
    k.radiusI = uniform(rng) < 0.5 ? 0.5e-3 : 1e-3;
    k.radiusJ = uniform(rng) < 0.5 ? 0.5e-3 : 1e-3;
    double dir[3] = {gauss(rng), gauss(rng), gauss(rng)};
    if (kind == Kind::alongNormal) { dir[0] = 1; dir[1] = dir[2] = 0; }  // n exactly x
    const double len = std::sqrt(dir[0]*dir[0] + dir[1]*dir[1] + dir[2]*dir[2]);
    const double dist = (k.radiusI + k.radiusJ)*(1 - 0.02*uniform(rng));
    for (int d = 0; d < 3; ++d)
    {
        k.r[d] = dist*dir[d]/len;
        k.dvHalf[d] = 0.1*gauss(rng);
        k.dvSync[d] = k.dvHalf[d] + 1e-3*gauss(rng);
        k.wHalfI[d] = 100*gauss(rng); k.wHalfJ[d] = 100*gauss(rng);
        k.wSyncI[d] = k.wHalfI[d] + gauss(rng); k.wSyncJ[d] = k.wHalfJ[d] + gauss(rng);
    }
    ContactHistory& h = c.history;
    h.touching = kind != Kind::fresh;
    const double n[3] = {k.r[0]/dist, k.r[1]/dist, k.r[2]/dist};
    const double fn = kn*(k.radiusI + k.radiusJ - dist);
    // sliding: an elastic tangential force far above mu F_n; sticking: far below, so that
    // most stick (the step's own increment and the dashpot still slide a few)
    const double scale = kind == Kind::sliding ? 5*fn : 1e-3*fn;
    for (int d = 0; d < 3; ++d)
    {
        h.n[d] = n[d] + 0.01*gauss(rng);
        h.ft[d] = scale*gauss(rng);
        h.xr[d] = scale/kt*gauss(rng);   // rolling springs of the same range (k_r = k_t)
    }
    if (kind == Kind::turnedNormal) for (int d = 0; d < 3; ++d) h.n[d] = -n[d];
    if (kind == Kind::alongNormal)
    {
        h.n[0] = 1; h.n[1] = h.n[2] = 0;
        h.ft[0] = scale; h.ft[1] = h.ft[2] = 0;
    }
    if (kind == Kind::zeroForce || kind == Kind::frictionless) h.ft[0] = h.ft[1] = h.ft[2] = 0;
    return c;
}

//- The random contacts' law: friction 0.5 with the fine/coarse pair frictionless, and
//  rolling resistance mu_r (0: off) with that pair rolling freely, so that lanes with and
//  without friction and the couple stand side by side.
ContactSettings randomContactSettings(ContactModel model, double rollingFriction)
{
    ContactSettings settings;
    settings.model = model;
    if (model == ContactModel::linearSpringDashpot) settings.normalStiffness = 2e3;
    settings.restitution = 0.7;
    settings.friction = 0.5;
    settings.rollingFriction = rollingFriction;
    std::optional<double> pairRolling;
    if (rollingFriction > 0)
    {
        pairRolling = 0.0;
        if (model == ContactModel::hertzMindlin)
        {
            // Hertz has no pair k_t to default to
            settings.rollingStiffness = 500;
            settings.rollingDamping = 1e-3;
        }
    }
    settings.pairs.push_back({"fine", "coarse", std::nullopt, 0.0, std::nullopt, pairRolling});
    return settings;
}

template<class Law>
void compareOverRandomContacts(const ContactSettings& settings)
{
    const bool rolling = hasRollingResistance(settings);
    const ContactLaw law(settings, test::binary());
    const PairCoefficients pairs[2] = {law.pair(0, 0), law.pair(0, 1)};
    ASSERT_GT(pairs[0].friction, 0);
    ASSERT_EQ(pairs[1].friction, 0);
    const double dt = 1e-6;
    std::mt19937_64 rng(12345);
    std::vector<Case> cases;
    for (const Kind kind : {Kind::sticking, Kind::sliding, Kind::fresh, Kind::frictionless,
                            Kind::turnedNormal, Kind::alongNormal, Kind::zeroForce})
    {
        for (int m = 0; m < 200; ++m) cases.push_back(randomCase(kind, rng, 2e3));
    }
    const int n = int(cases.size());
    ContactBatch batch;
    batch.reserveFor(n);
    for (int c = 0; c < n; ++c)
    {
        const ContactKinematics& k = cases[c].kin;
        const ContactHistory& h = cases[c].history;
        const PairCoefficients& p = pairs[cases[c].pair];
        batch.rx[c] = k.r[0]; batch.ry[c] = k.r[1]; batch.rz[c] = k.r[2];
        batch.radiusI[c] = k.radiusI; batch.radiusJ[c] = k.radiusJ;
        batch.dvHalfX[c] = k.dvHalf[0]; batch.dvHalfY[c] = k.dvHalf[1]; batch.dvHalfZ[c] = k.dvHalf[2];
        batch.dvSyncX[c] = k.dvSync[0]; batch.dvSyncY[c] = k.dvSync[1]; batch.dvSyncZ[c] = k.dvSync[2];
        batch.wHalfIX[c] = k.wHalfI[0]; batch.wHalfIY[c] = k.wHalfI[1]; batch.wHalfIZ[c] = k.wHalfI[2];
        batch.wHalfJX[c] = k.wHalfJ[0]; batch.wHalfJY[c] = k.wHalfJ[1]; batch.wHalfJZ[c] = k.wHalfJ[2];
        batch.wSyncIX[c] = k.wSyncI[0]; batch.wSyncIY[c] = k.wSyncI[1]; batch.wSyncIZ[c] = k.wSyncI[2];
        batch.wSyncJX[c] = k.wSyncJ[0]; batch.wSyncJY[c] = k.wSyncJ[1]; batch.wSyncJZ[c] = k.wSyncJ[2];
        const std::array<double, 4> constants = Law::stiffnessConstants(p);
        batch.constant0[c] = constants[0]; batch.constant1[c] = constants[1];
        batch.constant2[c] = constants[2]; batch.constant3[c] = constants[3];
        batch.friction[c] = p.friction;
        batch.touching[c] = h.touching ? 1 : 0;
        batch.ftX[c] = h.ft[0]; batch.ftY[c] = h.ft[1]; batch.ftZ[c] = h.ft[2];
        batch.nX[c] = h.n[0]; batch.nY[c] = h.n[1]; batch.nZ[c] = h.n[2];
        batch.rollingFriction[c] = p.rollingFriction;
        batch.rollingStiffness[c] = p.rollingStiffness;
        batch.rollingDamping[c] = p.rollingDamping;
        batch.effectiveRadius[c] = p.effectiveRadius;
        batch.xrX[c] = h.xr[0]; batch.xrY[c] = h.xr[1]; batch.xrZ[c] = h.xr[2];
    }
    // with traps on, as OpenFOAM runs (FOAM_SIGFPE): the discarded lanes' 0/0 must not
    // trap, and the loop leaves no flag behind
    std::feclearexcept(FE_ALL_EXCEPT);
#ifdef __GLIBC__
    feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
#endif
    evaluateContactBatch(Law::model, rolling, batch, n, dt);
#ifdef __GLIBC__
    fedisableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
#endif
    EXPECT_FALSE(std::fetestexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW))
        << "the batch left a floating-point exception flag";

    int slidingOfSliding = 0, slidingOfSticking = 0, rollingSlides = 0, mismatches = 0;
    for (int c = 0; c < n; ++c)
    {
        ContactHistory h = cases[c].history;
        if (!rolling) h.xr[0] = h.xr[1] = h.xr[2] = 0;   // as a cell without it keeps them
        const ContactKinematics& k = cases[c].kin;
        const ContactResult res = evaluateContact<Law>(pairs[cases[c].pair], k, h, dt);
        const double expected[] =
        {
            res.force[0], res.force[1], res.force[2],
            res.nCrossFt[0], res.nCrossFt[1], res.nCrossFt[2],
            h.ft[0], h.ft[1], h.ft[2], h.n[0], h.n[1], h.n[2],
            res.normalVelocity, res.overlap/(2*std::min(k.radiusI, k.radiusJ))
        };
        const double got[] =
        {
            batch.forceX[c], batch.forceY[c], batch.forceZ[c],
            batch.nCrossFtX[c], batch.nCrossFtY[c], batch.nCrossFtZ[c],
            batch.ftX[c], batch.ftY[c], batch.ftZ[c], batch.nX[c], batch.nY[c], batch.nZ[c],
            batch.normalVelocity[c], batch.overlapFraction[c]
        };
        std::vector<double> expectedAll(std::begin(expected), std::end(expected));
        std::vector<double> gotAll(std::begin(got), std::end(got));
        if (rolling)
        {
            for (const double v : {h.xr[0], h.xr[1], h.xr[2], res.torqueSumI[0], res.torqueSumI[1],
                                   res.torqueSumI[2], res.torqueSumJ[0], res.torqueSumJ[1], res.torqueSumJ[2]})
            {
                expectedAll.push_back(v);
            }
            for (const double v : {batch.xrX[c], batch.xrY[c], batch.xrZ[c],
                                   batch.torqueSumIX[c], batch.torqueSumIY[c], batch.torqueSumIZ[c],
                                   batch.torqueSumJX[c], batch.torqueSumJY[c], batch.torqueSumJZ[c]})
            {
                gotAll.push_back(v);
            }
            // the rolling couple at its cap mu_r |F_n| R* (|n x F_r| = |F_r|)
            const PairCoefficients& pc = pairs[cases[c].pair];
            const double couple = std::hypot(res.rollingTorque[0], res.rollingTorque[1], res.rollingTorque[2]);
            const double fnAbs = std::abs(res.force[0]*h.n[0] + res.force[1]*h.n[1] + res.force[2]*h.n[2]);
            if (pc.rollingFriction > 0
                && std::abs(couple - pc.rollingFriction*fnAbs*pc.effectiveRadius)
                   <= 1e-12*fnAbs*pc.effectiveRadius) ++rollingSlides;
        }
        for (std::size_t q = 0; q < expectedAll.size(); ++q)
        {
            const double expectedQ = expectedAll[q], gotQ = gotAll[q];
            if (!sameBits(expectedQ, gotQ))
            {
                if (++mismatches <= 5)
                {
                    ADD_FAILURE() << "contact " << c << " (kind " << int(cases[c].kind)
                                  << ") output " << q << ": " << gotQ << " against "
                                  << expectedQ;
                }
            }
        }
        // the branches were taken: slides carry mu |F_n| (|n x F_t| = |F_t|)
        const double ft = std::hypot(res.nCrossFt[0], res.nCrossFt[1], res.nCrossFt[2]);
        const double fn = res.force[0]*h.n[0] + res.force[1]*h.n[1] + res.force[2]*h.n[2];
        const bool slides = pairs[cases[c].pair].friction > 0
                         && std::abs(ft - pairs[0].friction*std::abs(fn)) <= 1e-12*std::abs(fn);
        if (slides && cases[c].kind == Kind::sliding) ++slidingOfSliding;
        if (slides && cases[c].kind == Kind::sticking) ++slidingOfSticking;
    }
    EXPECT_EQ(mismatches, 0);
    // both sides of the Coulomb limit were taken
    EXPECT_EQ(slidingOfSliding, 200);
    EXPECT_LT(slidingOfSticking, 100);
    if (rolling)
    {
        EXPECT_GE(rollingSlides, 100);
    }
}

struct RunResult
{
    Particles particles;
    CollisionStatistics collisions;
    Eigen::Matrix3d stress;   // from the pairs' force slots
};

RunResult shearedRun(ContactModel model, bool batched, int threads, double rollingFriction = 0)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.5, 0.0, 80.0, 5);
    SimulationSettings s = test::shearedCell(80.0, 0.7, 0.5);
    s.contact.model = model;
    // a frictionless pair beside frictional ones
    PairContactSettings pair;
    pair.first = "coarse";
    pair.second = "coarse";
    pair.friction = 0.0;
    s.contact.rollingFriction = rollingFriction;
    s.contact.pairs.push_back(pair);
    s.threads = threads;
    s.batchedContacts = batched;
    Simulation sim(species, s, packing.particles, packing.box);
    sim.enableCollisionStatistics(1e-12, 1e-6, 20);
    sim.run(3000);
    return {sim.particles(), sim.collisionStatistics(), sim.totalStress()};
}

} // namespace

TEST(ContactBatch, LinearSameBitsAsContactByContact)
{
    compareOverRandomContacts<LinearSpringDashpot>(randomContactSettings(ContactModel::linearSpringDashpot, 0));
}

TEST(ContactBatch, HertzSameBitsAsContactByContact)
{
    compareOverRandomContacts<HertzMindlin>(randomContactSettings(ContactModel::hertzMindlin, 0));
}

TEST(ContactBatch, LinearRollingSameBitsAsContactByContact)
{
    compareOverRandomContacts<LinearSpringDashpot>(randomContactSettings(ContactModel::linearSpringDashpot, 0.1));
}

TEST(ContactBatch, HertzRollingSameBitsAsContactByContact)
{
    compareOverRandomContacts<HertzMindlin>(randomContactSettings(ContactModel::hertzMindlin, 0.1));
}

TEST(ContactBatch, ShearedRunsSameBitsAsContactByContact)
{
    for (const auto& [model, rollingFriction] :
         {std::pair{ContactModel::linearSpringDashpot, 0.0}, std::pair{ContactModel::hertzMindlin, 0.0},
          std::pair{ContactModel::linearSpringDashpot, 0.2}})
    {
        const RunResult reference = shearedRun(model, false, 1, rollingFriction);
        ASSERT_GT(reference.collisions.counts[0], 0);
        for (const int threads : {1, 2})
        {
            const RunResult batched = shearedRun(model, true, threads, rollingFriction);
            const std::string what = contactModelName(model) + ", mu_r " + std::to_string(rollingFriction)
                                   + ", " + std::to_string(threads) + " threads";
            EXPECT_TRUE(test::bitwiseEqual(reference.particles.x, batched.particles.x)) << what;
            EXPECT_TRUE(test::bitwiseEqual(reference.particles.vy, batched.particles.vy)) << what;
            EXPECT_TRUE(test::bitwiseEqual(reference.particles.wz, batched.particles.wz)) << what;
            EXPECT_TRUE(test::bitwiseEqual(reference.particles.fx, batched.particles.fx)) << what;
            EXPECT_EQ(reference.collisions.counts, batched.collisions.counts) << what;
            EXPECT_EQ(std::memcmp(reference.stress.data(), batched.stress.data(), 9*sizeof(double)), 0)
                << what;
            EXPECT_TRUE(test::bitwiseEqual(reference.collisions.energySum,
                                           batched.collisions.energySum)) << what;
        }
    }
}

// Coincident centres have no normal: the batch leaves them to evaluateContact, with their
// history as it was. Two grains on one spot beside a third touching both.
TEST(ContactBatch, CoincidentCentresContactByContact)
{
    const auto species = test::mono();
    const double r = 0.5e-3, m = 2500*4.0/3.0*M_PI*r*r*r;
    const auto run = [&](bool batched)
    {
        Particles p;
        p.add(5e-3, 5e-3, 5e-3, r, m, 0);
        p.add(5e-3, 5e-3, 5e-3, r, m, 0);
        p.add(5e-3 + 1.999*r, 5e-3, 5e-3, r, m, 0);
        p.vx[2] = -0.01;
        PeriodicBox box;
        box.lx = box.ly = box.lz = 1e-2;
        SimulationSettings s = test::softContacts(0.7, 0.5);
        s.maxOverlapFraction = 0;   // the coincident pair overlaps by a whole diameter
        s.batchedContacts = batched;
        Simulation sim(species, s, p, box);
        sim.run(200);
        return sim.particles();
    };
    const Particles one = run(false), batch = run(true);
    EXPECT_TRUE(test::bitwiseEqual(one.x, batch.x));
    EXPECT_TRUE(test::bitwiseEqual(one.vx, batch.vx));
    EXPECT_TRUE(test::bitwiseEqual(one.wz, batch.wz));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(batch.vx[i])) << i;
    // the third grain was pushed back by the pair
    EXPECT_GT(batch.vx[2], -0.01);
}

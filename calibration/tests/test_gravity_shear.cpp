// The sheared cell under gravity (GravityShear.hpp): the walls cut from the packing, the
// lithostatic stress of a bed at rest measured by the slab stresses against the weight
// of the grains above (the momentum balance the cell's pressures rest on), the top wall
// holding the load, the same bits on 1, 2 and 3 threads while it shears, and the
// refusals. The segregation it measures: apps/gravityShearCell.cpp, docs/validation.md.
#include "GravityShear.hpp"
#include "GravityShearRun.hpp"
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>

using namespace sdf::dem;
using test::contains;
using test::messageOf;

namespace
{

constexpr double rhoS = 2500, g = 9.81;

//- A bed of 1 and 2 mm grains (equal solids volume) between walls 1.5 coarse diameters
//  thick, cut from a packing three times taller than wide.
WallBoundedCell smallCell(int particles)
{
    const std::vector<Species> species = test::binary();
    PackingSettings ps;
    ps.solidsFraction = 0.55;
    ps.counts = countsFromVolumeFractions(species, {0.5, 0.5}, particles);
    ps.heightRatio = 3;
    ps.seed = 5;
    Packing packing = makePacking(species, ps);
    return cutWallBoundedCell(std::move(packing.particles), packing.box, 3e-3, 0.5*packing.box.ly);
}

struct Cell
{
    std::unique_ptr<Simulation> sim;
    GravityShear* driving = nullptr;
};

Cell shearedUnderGravity
(
    const WallBoundedCell& cut, const GravityShearSettings& settings, int threads, long renumberEvery = 0
)
{
    SimulationSettings s = test::softContacts(0.7, 0.5);
    s.timeStep = 1e-6;
    s.threads = threads;
    s.renumberEvery = renumberEvery;
    Cell cell;
    cell.sim = std::make_unique<Simulation>(test::binary(), s, cut.particles, cut.box);
    auto driving = std::make_unique<GravityShear>(settings, cut, 1e-3, s.timeStep);
    cell.driving = driving.get();
    cell.sim->setDriving(std::move(driving));
    return cell;
}

} // namespace

TEST(GravityShear, WallsAreCutFromThePackingAndFrozen)
{
    const WallBoundedCell cut = smallCell(600);
    const Particles& p = cut.particles;
    int walls = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const GrainRole role = cut.roleById[std::size_t(p.id[i])];
        EXPECT_EQ(p.id[i], int(i));
        if (role == GrainRole::flowing)
        {
            EXPECT_GE(p.y[i], cut.bottomPlane);
            EXPECT_LT(p.y[i], cut.topPlane);
            EXPECT_GT(p.invMass[i], 0);
            continue;
        }
        ++walls;
        EXPECT_EQ(p.invMass[i], 0);
        EXPECT_EQ(p.invInertia[i], 0);
        if (role == GrainRole::bottomWall) EXPECT_LT(p.y[i], cut.bottomPlane);
        else EXPECT_GE(p.y[i], cut.topPlane);
    }
    EXPECT_GT(walls, 0);
    // the empty gap: the bottom wall's periodic image is beyond the top wall's reach
    EXPECT_GT(cut.box.ly - cut.topPlane, 0.4*cut.topPlane);
}

// A bed at rest (the top wall does not slide): the slab stresses sigma_yy (contacts
// shared along their branch vectors, plus the kinetic part) against the load the grains
// carry, the top wall's stress plus the weight of the grains whose centres lie above,
// averaged over each slab. The gradient is measured, not put in, so within 2 %.
TEST(GravityShear, LithostaticStressOfABedAtRest)
{
    const WallBoundedCell cut = smallCell(600);
    GravityShearSettings settings;
    settings.normalStress = 150;
    settings.wallSpeed = 0;
    Cell cell = shearedUnderGravity(cut, settings, 2);
    Simulation& sim = *cell.sim;
    const GravityShear& drive = *cell.driving;
    sim.run(150000);   // 0.15 s: the bed settles and the wall comes down onto it

    const int slabs = 6;
    std::vector<double> measured(slabs), expected(slabs);
    int samples = 0;
    cell.driving->resetWallStresses();
    const double area = drive.area();
    auto sample = [&](const Simulation& s)
    {
        const Particles& p = s.particles();
        const double y0 = drive.bottomPlane(), h = drive.gap()/slabs;
        const std::vector<Eigen::Matrix3d> J = s.contactStressBySlab(y0, h, slabs);
        for (int l = 0; l < slabs; ++l)
        {
            double kinetic = 0, weightAbove = 0;
            const double lo = y0 + l*h, hi = lo + h;
            for (std::size_t i = 0; i < p.size(); ++i)
            {
                if (drive.role(p, int(i)) != GrainRole::flowing) continue;
                if (p.y[i] >= lo && p.y[i] < hi) kinetic += p.mass[i]*p.vy[i]*p.vy[i];
                // a grain at y_i loads the planes below it: the part of the slab under y_i
                const double under = std::clamp(p.y[i], lo, hi) - lo;
                weightAbove += p.mass[i]*g*under/h;
            }
            measured[std::size_t(l)] += (J[std::size_t(l)](1, 1) + kinetic)/(area*h);
            expected[std::size_t(l)] += weightAbove/area;
        }
        ++samples;
    };
    sim.run(20000, sample, 1000);
    const double top = drive.meanTopWallStress();
    EXPECT_NEAR(top/settings.normalStress, 1, 0.02) << "the grains carry the top wall's load";
    for (int l = 0; l < slabs; ++l)
    {
        measured[std::size_t(l)] /= samples;
        expected[std::size_t(l)] = expected[std::size_t(l)]/samples + top;
    }
    // the gradient over the slabs, and each slab
    const double measuredDrop = measured.front() - measured.back();
    const double expectedDrop = expected.front() - expected.back();
    EXPECT_GT(expectedDrop, 100) << "a bed several grains deep";
    EXPECT_NEAR(measuredDrop/expectedDrop, 1, 0.02);
    for (int l = 0; l < slabs; ++l)
    {
        std::cout << "slab " << l << ": sigma_yy " << measured[std::size_t(l)] << " Pa, load above "
                  << expected[std::size_t(l)] << " Pa\n";
        EXPECT_NEAR(measured[std::size_t(l)]/expected[std::size_t(l)], 1, 0.02) << "slab " << l;
    }
    // the bottom wall carries the load and the flowing grains' weight
    double weight = 0;
    const Particles& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (drive.role(p, int(i)) == GrainRole::flowing) weight += p.mass[i]*g;
    }
    EXPECT_NEAR(drive.meanBottomWallStress()/(top + weight/area), 1, 0.02);
}

TEST(GravityShear, SameBitsOnOneTwoAndThreeThreads)
{
    const WallBoundedCell cut = smallCell(500);
    GravityShearSettings settings;
    settings.normalStress = 150;
    settings.wallSpeed = 0.2;
    settings.profileRelaxationTime = 0.01;
    std::vector<Particles> finals;
    for (int threads : {1, 2, 3})
    {
        Cell cell = shearedUnderGravity(cut, settings, threads, 400);
        cell.sim->run(3000);
        finals.push_back(cell.sim->particles());
        EXPECT_GT(cell.sim->particles().size(), 0u);
    }
    for (std::size_t k = 1; k < finals.size(); ++k)
    {
        EXPECT_TRUE(test::bitwiseEqual(finals[0].x, finals[k].x)) << "threads " << k + 1;
        EXPECT_TRUE(test::bitwiseEqual(finals[0].y, finals[k].y)) << "threads " << k + 1;
        EXPECT_TRUE(test::bitwiseEqual(finals[0].vx, finals[k].vx)) << "threads " << k + 1;
        EXPECT_TRUE(test::bitwiseEqual(finals[0].wz, finals[k].wz)) << "threads " << k + 1;
    }
}

TEST(GravityShear, RefusesBadSettingsByName)
{
    const WallBoundedCell cut = smallCell(300);
    auto refusal = [&](GravityShearSettings s, double dt = 1e-6)
    {
        return messageOf<std::invalid_argument>([&] { GravityShear(s, cut, 1e-3, dt); });
    };
    GravityShearSettings good;
    good.normalStress = 100;
    good.wallSpeed = 0.1;
    GravityShearSettings s = good;
    s.gravity = 0;
    EXPECT_TRUE(contains(refusal(s), "entry 'gravity' must be finite and positive"));
    s.gravity = -9.81;
    EXPECT_TRUE(contains(refusal(s), "entry 'gravity'"));
    s = good;
    s.normalStress = 0;
    EXPECT_TRUE(contains(refusal(s), "entry 'normalStress' must be a stress > 0 Pa"));
    s.normalStress = -5;
    EXPECT_TRUE(contains(refusal(s), "entry 'normalStress'"));
    s = good;
    s.wallSpeed = -0.1;
    EXPECT_TRUE(contains(refusal(s), "entry 'wallSpeed'"));
    s = good;
    s.profileRelaxationTime = 5e-6;
    EXPECT_TRUE(contains(refusal(s), "entry 'profileRelaxationTime' must be 0 (off) or at least 10 time steps"));

    const std::vector<Species> species = test::binary();
    PackingSettings ps;
    ps.solidsFraction = 0.5;
    ps.counts = {100, 20};
    ps.heightRatio = 0;
    EXPECT_TRUE(contains(messageOf<std::invalid_argument>([&] { makePacking(species, ps); }), "heightRatio"));
    ps.heightRatio = 2;
    const Packing packing = makePacking(species, ps);
    EXPECT_TRUE
    (
        contains
        (
            messageOf<std::invalid_argument>
            ([&] { cutWallBoundedCell(packing.particles, packing.box, 0.6*packing.box.ly, 0.01); }),
            "entry 'wallThickness' must be positive and leave room for a flowing layer"
        )
    );
}


// I -> 0: a cell whose interior flows below the dense regime's floor (the rheology cell's
// I 1e-4, where it reports a cell as jammed) is reported as quasi-static, so a
// calibration leaves it out with that reason; just above the floor, and with the wall
// loaded and sliding, it is a state the estimators read. The wall's checks come first.
TEST(GravityShear, QuasiStaticCellIsReportedAsSuch)
{
    SegregationMeasurement m;
    m.slidingStrainAtDrift = 2;
    m.topWallLoad = 1.01;
    m.inertialNumber = 2e-4;
    EXPECT_FALSE(m.quasiStatic());
    EXPECT_EQ(m.unreachedState(), "");
    m.inertialNumber = 5e-5;
    EXPECT_TRUE(m.quasiStatic());
    EXPECT_TRUE(contains(m.unreachedState(), "quasi-static: I = 5e-05 < 0.0001"));
    m.inertialNumber = 0;
    EXPECT_TRUE(contains(m.unreachedState(), "quasi-static"));
    m.topWallLoad = 0.5;
    EXPECT_FALSE(contains(m.unreachedState(), "quasi-static"));
}

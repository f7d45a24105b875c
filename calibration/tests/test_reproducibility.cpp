// Bitwise reproducibility: the same seed and thread count give identical trajectories;
// because per-particle force sums run in a fixed pair order, 1, 2 and 3 threads agree too,
// although the block boundaries follow measured busy times (they differ between runs).
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace sdf::dem;

namespace
{

struct RunResult
{
    Particles particles;
    CollisionStatistics collisions;
};

RunResult shearedRun
(
    int threads,
    std::uint64_t seed,
    long steps = 800,
    bool thermostatted = false,
    long renumberEvery = 0,
    bool shuffled = false
)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.4, 0.0, 80.0, seed);
    if (shuffled)
    {
        // particles in no spatial order: the first renumbering turns many pairs round
        const int n = int(packing.particles.size());
        std::vector<int> order(static_cast<std::size_t>(n));
        for (int i = 0; i < n; ++i) order[i] = (i*97) % n;   // 97 and 340 are coprime
        packing.particles.reorder(order);
    }
    SimulationSettings s = test::shearedCell(80.0, 0.7, 0.5);
    if (thermostatted) s.mode = CellMode::thermostatted;
    s.targetTemperature = 0.01;
    s.threads = threads;
    s.renumberEvery = renumberEvery;
    Simulation sim(species, s, packing.particles, packing.box);
    sim.enableCollisionStatistics(1e-12, 1e-6, 20);
    sim.run(steps);
    return {sim.particles(), sim.collisionStatistics()};
}


} // namespace

TEST(Reproducibility, SameSeedSameThreadsBitwiseIdentical)
{
    const Particles a = shearedRun(2, 3).particles;
    const Particles b = shearedRun(2, 3).particles;
    EXPECT_TRUE(test::bitwiseEqual(a.x, b.x));
    EXPECT_TRUE(test::bitwiseEqual(a.vy, b.vy));
    EXPECT_TRUE(test::bitwiseEqual(a.wz, b.wz));
}

TEST(Reproducibility, OneTwoAndThreeThreadsBitwiseIdentical)
{
    // long enough for several list rebuilds, at each of which the block shares move
    const RunResult a = shearedRun(1, 3, 4000);
    for (const int threads : {2, 3})
    {
        const RunResult b = shearedRun(threads, 3, 4000);
        EXPECT_TRUE(test::bitwiseEqual(a.particles.x, b.particles.x)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.vx, b.particles.vx)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.wy, b.particles.wy)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.fz, b.particles.fz)) << threads << " threads";
        // impact energies are summed in pair order whatever the blocks
        EXPECT_GT(a.collisions.counts[0], 0);
        EXPECT_EQ(a.collisions.counts, b.collisions.counts) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.collisions.energySum, b.collisions.energySum))
            << threads << " threads";
        EXPECT_EQ(a.collisions.histogram, b.collisions.histogram) << threads << " threads";
    }
}

TEST(Reproducibility, ThermostattedOneTwoAndThreeThreadsBitwiseIdentical)
{
    // the thermostat's sums are filled per fixed chunk by each thread's finish range
    const RunResult a = shearedRun(1, 5, 3000, true);
    for (const int threads : {2, 3})
    {
        const RunResult b = shearedRun(threads, 5, 3000, true);
        EXPECT_TRUE(test::bitwiseEqual(a.particles.vx, b.particles.vx)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.z, b.particles.z)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.wx, b.particles.wx)) << threads << " threads";
    }
}

TEST(Reproducibility, RenumberedRunFollowsThePlainRunById)
{
    // the renumbering (every 100 steps) reorders particles, pairs and contact histories,
    // turning pairs round where i and j swap: the same motion, up to the round-off of the
    // changed summation order
    const RunResult plain = shearedRun(1, 3, 600, false, 0, true);
    const RunResult renumbered = shearedRun(1, 3, 600, false, 100, true);
    const Particles& a = plain.particles;
    const Particles& b = renumbered.particles;
    ASSERT_EQ(a.size(), b.size());
    int moved = 0;
    double worst = 0, worstSpin = 0;
    for (std::size_t k = 0; k < b.size(); ++k)
    {
        const int i = b.id[k];
        moved += i != int(k);
        worst = std::max({worst, std::abs(a.ux[i] - b.ux[k]), std::abs(a.uy[i] - b.uy[k]),
                          std::abs(a.uz[i] - b.uz[k])});
        worstSpin = std::max({worstSpin, std::abs(a.wx[i] - b.wx[k]), std::abs(a.wy[i] - b.wy[k]),
                              std::abs(a.wz[i] - b.wz[k])});
    }
    EXPECT_GT(moved, int(b.size())/10) << "the particles were not renumbered";
    // displacements of ~1e-4 m and spins of ~10 rad/s agree to round-off growth
    EXPECT_LT(worst, 1e-10);
    EXPECT_LT(worstSpin, 1e-5);
    EXPECT_EQ(plain.collisions.counts, renumbered.collisions.counts);
}

TEST(Reproducibility, RenumberedOneTwoAndThreeThreadsBitwiseIdentical)
{
    const RunResult a = shearedRun(1, 3, 3000, false, 500);
    for (const int threads : {2, 3})
    {
        const RunResult b = shearedRun(threads, 3, 3000, false, 500);
        EXPECT_EQ(a.particles.id, b.particles.id) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.x, b.particles.x)) << threads << " threads";
        EXPECT_TRUE(test::bitwiseEqual(a.particles.wz, b.particles.wz)) << threads << " threads";
    }
}

TEST(Reproducibility, DifferentSeedsDiffer)
{
    const Particles a = shearedRun(1, 3).particles;
    const Particles b = shearedRun(1, 4).particles;
    EXPECT_FALSE(test::bitwiseEqual(a.x, b.x));
}

TEST(Reproducibility, ParticleArraysStartOnCacheLines)
{
    // thread ranges start at multiples of particlesPerCacheLine; only with line-aligned
    // arrays does that keep every cache line to one thread (docs/developer/dem-engine.md, "Threads")
    const Particles p = shearedRun(2, 5, 50, false, 20).particles;
    for (const ParticleArray* a : {&p.x, &p.ux, &p.vx, &p.wz, &p.fx, &p.tz, &p.invMass})
    {
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(a->data()) % cacheLineBytes, 0u);
    }
    EXPECT_EQ(std::size_t(particlesPerCacheLine)*sizeof(double), cacheLineBytes);
}

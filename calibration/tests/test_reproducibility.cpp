// Bitwise reproducibility: the same seed and thread count give identical trajectories;
// because per-particle force sums run in a fixed pair order, 1 and 2 threads agree too.
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace sdf::dem;

namespace
{

Particles shearedRun(int threads, std::uint64_t seed)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.4, 0.0, 80.0, seed);
    SimulationSettings s;
    s.contact.restitution = 0.7;
    s.contact.friction = 0.5;
    s.contact.normalStiffness = 2e3;
    s.mode = CellMode::leesEdwards;
    s.shearRate = 80.0;
    s.threads = threads;
    Simulation sim(species, s, packing.particles, packing.box);
    sim.run(800);
    return sim.particles();
}

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size()*sizeof(double)) == 0;
}

} // namespace

TEST(Reproducibility, SameSeedSameThreadsBitwiseIdentical)
{
    const Particles a = shearedRun(2, 3);
    const Particles b = shearedRun(2, 3);
    EXPECT_TRUE(bitwiseEqual(a.x, b.x));
    EXPECT_TRUE(bitwiseEqual(a.vy, b.vy));
    EXPECT_TRUE(bitwiseEqual(a.wz, b.wz));
}

TEST(Reproducibility, OneAndTwoThreadsBitwiseIdentical)
{
    const Particles a = shearedRun(1, 3);
    const Particles b = shearedRun(2, 3);
    EXPECT_TRUE(bitwiseEqual(a.x, b.x));
    EXPECT_TRUE(bitwiseEqual(a.vx, b.vx));
    EXPECT_TRUE(bitwiseEqual(a.wy, b.wy));
}

TEST(Reproducibility, DifferentSeedsDiffer)
{
    const Particles a = shearedRun(1, 3);
    const Particles b = shearedRun(1, 4);
    EXPECT_FALSE(bitwiseEqual(a.x, b.x));
}

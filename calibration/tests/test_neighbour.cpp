// The Verlet list holds exactly the pairs within R_i + R_j + skin (minimum image, with
// Lees-Edwards offsets), for size ratio 4; the list stays valid while particles move.
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>

using namespace sdf::dem;

namespace
{

std::set<std::pair<int, int>> bruteForcePairs(const Particles& p, const PeriodicBox& box, double skin)
{
    std::set<std::pair<int, int>> pairs;
    for (int i = 0; i < int(p.size()); ++i)
    {
        for (int j = i + 1; j < int(p.size()); ++j)
        {
            double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
            box.minimumImage(dx, dy, dz, dvx);
            const double reach = p.radius[i] + p.radius[j] + skin;
            if (dx*dx + dy*dy + dz*dz < reach*reach) pairs.insert({i, j});
        }
    }
    return pairs;
}

} // namespace

TEST(NeighbourList, MatchesBruteForceWithLeesEdwardsOffsets)
{
    const auto species = test::binary(4.0);
    RandomStream random(17);
    PeriodicBox box;
    box.lx = 0.021; box.ly = 0.017; box.lz = 0.019;
    box.shearRate = 10;
    Particles p;
    for (int i = 0; i < 900; ++i)
    {
        const int s = i % 10 == 0 ? 1 : 0;
        p.add(box.lx*random.uniform(), box.ly*random.uniform(), box.lz*random.uniform(),
              species[s].radius(), species[s].mass(), s);
    }
    const double skin = 0.3e-3;
    for (double offset : {0.0, 0.0013, 0.0071, 0.0109, 0.0203})
    {
        box.offset = offset;
        NeighbourList list;
        list.build(p, box, skin);
        std::set<std::pair<int, int>> listed;
        for (std::size_t k = 0; k < list.size(); ++k)
        {
            EXPECT_LT(list.first()[k], list.second()[k]);
            if (k > 0)
            {
                // ordered by (i, j): the reduction order is fixed
                const bool ordered = list.first()[k - 1] < list.first()[k]
                    || (list.first()[k - 1] == list.first()[k] && list.second()[k - 1] < list.second()[k]);
                EXPECT_TRUE(ordered);
            }
            listed.insert({list.first()[k], list.second()[k]});
        }
        EXPECT_EQ(listed.size(), list.size()) << "duplicate pairs at offset " << offset;
        EXPECT_EQ(listed, bruteForcePairs(p, box, skin)) << "offset " << offset;
    }
}

TEST(NeighbourList, BoxTooSmallIsRefused)
{
    const auto species = test::binary(4.0);
    Particles p;
    p.add(0.001, 0.001, 0.001, species[1].radius(), species[1].mass(), 1);
    PeriodicBox box;
    box.lx = box.ly = box.lz = 0.006;
    NeighbourList list;
    EXPECT_THROW(list.build(p, box, 0.3e-3), std::invalid_argument);
}

TEST(NeighbourList, NoContactMissedDuringShearedRun)
{
    // every touching pair found by brute force must be touching in the engine's list
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.45, 0.0, 50.0, 21);
    const SimulationSettings s = test::shearedCell(50.0, 0.7, 0.3);
    Simulation sim(species, s, packing.particles, packing.box);
    for (int block = 0; block < 20; ++block)
    {
        sim.run(250);
        const auto touching = bruteForcePairs(sim.particles(), sim.box(), 0.0);
        const auto& list = sim.neighbourList();
        std::set<std::pair<int, int>> listed;
        for (std::size_t k = 0; k < list.size(); ++k) listed.insert({list.first()[k], list.second()[k]});
        for (const auto& pr : touching)
        {
            EXPECT_TRUE(listed.count(pr)) << "pair " << pr.first << "," << pr.second
                                          << " touching but not listed";
        }
    }
    EXPECT_GT(sim.neighbourList().builds(), 2);
}

// Microscopic stress split (seed eqs 9-13): J^1 + J^2 + J^12 equals the total to round-off;
// the cross part has no kinetic term; repulsive contacts give a positive pressure.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

TEST(StressSplit, PartsSumToTotalToRoundOff)
{
    const auto species = test::binary(2.0);
    const double shearRate = 100.0;
    Packing packing = test::packedCell(species, {300, 40}, 0.5, 0.0, shearRate, 9);
    const SimulationSettings s = test::shearedCell(shearRate, 0.7, 0.4);
    Simulation sim(species, s, packing.particles, packing.box);
    int checked = 0;
    sim.run(4000, [&](const Simulation& x)
    {
        const StressSplit J = x.stressSplit();
        const Eigen::Matrix3d total = x.totalStress();
        const Eigen::Matrix3d sum = J.speciesStress(0) + J.speciesStress(1) + J.crossStress(0, 1);
        EXPECT_LE((sum - total).norm(), 1e-13*total.norm());
        EXPECT_LE((J.sum() - total).norm(), 1e-13*total.norm());
        ++checked;
        if (checked == 20)
        {
            // a dense frictional sheared cell has contacts of all three kinds
            EXPECT_GT(J.configurational[speciesPairIndex(0, 0, 2)].trace(), 0);
            EXPECT_GT(J.configurational[speciesPairIndex(0, 1, 2)].trace(), 0);
            EXPECT_GT(J.configurational[speciesPairIndex(1, 1, 2)].trace(), 0);
            // shear flow u_x(y) with dv/dy > 0: J_xy < 0 (momentum flows down the gradient)
            EXPECT_LT(total(0, 1), 0);
        }
    }, 200);
    EXPECT_EQ(checked, 20);
}

TEST(StressSplit, SymmetricForFrictionlessContacts)
{
    // central forces: the configurational tensor is symmetric
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.5, 0.01, 0, 4);
    const SimulationSettings s = test::softContacts(0.9, 0.0);
    Simulation sim(species, s, packing.particles, packing.box);
    sim.run(500);
    const Eigen::Matrix3d J = sim.totalStress();
    EXPECT_LE((J - J.transpose()).norm(), 1e-12*J.norm());
    EXPECT_GT(J.trace(), 0);
}

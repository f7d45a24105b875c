// Checkpoint and resume: a sheared frictional run interrupted, written to HDF5, read into a
// fresh Simulation and continued is bitwise identical to the uninterrupted run.
#include "SimulationCheckpoint.hpp"
#include "TestCells.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

using namespace sdf::dem;

TEST(Checkpoint, ResumedRunIsBitwiseIdentical)
{
    const auto species = test::binary(2.0);
    Packing packing = test::packedCell(species, {300, 40}, 0.45, 0.0, 80.0, 12);
    const SimulationSettings s = test::shearedCell(80.0, 0.7, 0.5);

    Simulation reference(species, s, packing.particles, packing.box);
    reference.run(1200);

    Simulation first(species, s, packing.particles, packing.box);
    first.run(500);
    const std::string path = "dem_checkpoint_test.h5";
    std::remove(path.c_str());
    writeSimulationCheckpoint(path, first);

    // a fresh simulation from an unrelated state, then restored
    Simulation resumed(species, s, packing.particles, packing.box);
    resumed.run(17);
    readSimulationCheckpoint(path, resumed);
    EXPECT_EQ(resumed.stepCount(), 500);
    EXPECT_DOUBLE_EQ(resumed.time(), first.time());
    EXPECT_LE((resumed.totalStress() - first.totalStress()).norm(), 0.0);
    resumed.run(700);

    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().x, reference.particles().x));
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().vx, reference.particles().vx));
    EXPECT_TRUE(test::bitwiseEqual(resumed.particles().wz, reference.particles().wz));
    EXPECT_EQ(resumed.box().offset, reference.box().offset);
}

TEST(Checkpoint, MissingFileIsReported)
{
    const auto species = test::mono();
    Packing packing = test::packedCell(species, {100}, 0.2, 0.01);
    SimulationSettings s;
    Simulation sim(species, s, packing.particles, packing.box);
    EXPECT_ANY_THROW(readSimulationCheckpoint("no_such_checkpoint.h5", sim));
}

#include "CellRun.hpp"

TEST(Checkpoint, CellRunResumedGivesTheUninterruptedResult)
{
    CellRunSettings s;
    s.species = test::binary(2.0);
    s.volumeFractions = {0.6, 0.4};
    s.particles = 320;
    s.solidsFraction = 0.45;
    s.simulation = test::shearedCell(80, 0.7, 0.5);
    s.simulation.timeStep = 1e-6;
    s.equilibrationTime = 0.002;
    s.samplingTime = 0.004;
    s.sampleEvery = 10;
    s.blocks = 4;
    s.seed = 9;

    const CellRunResult reference = runCell(s);

    const std::string path = "cellrun_checkpoint_test.h5";
    std::remove(path.c_str());
    CellRunSettings first = s;
    first.checkpointFile = path;
    first.checkpointEvery = 700;
    first.stopAfterSteps = 1500;
    const CellRunResult partial = runCell(first);
    EXPECT_TRUE(partial.interrupted);

    CellRunSettings second = s;
    second.checkpointFile = path;
    second.checkpointEvery = 700;
    second.resume = true;
    const CellRunResult resumed = runCell(second);
    EXPECT_TRUE(resumed.resumed);
    EXPECT_FALSE(resumed.interrupted);

    EXPECT_EQ(resumed.temperature, reference.temperature);
    for (std::size_t k = 0; k < reference.species.size(); ++k)
    {
        EXPECT_EQ(resumed.species[k].greenKubo.integral.value, reference.species[k].greenKubo.integral.value);
        EXPECT_EQ(resumed.species[k].diffusivityMsd.value, reference.species[k].diffusivityMsd.value);
        EXPECT_EQ(resumed.species[k].temperature, reference.species[k].temperature);
        EXPECT_EQ(resumed.species[k].temperatureError, reference.species[k].temperatureError);
        const auto& a = resumed.species[k].diffusiveRegime;
        const auto& b = reference.species[k].diffusiveRegime;
        EXPECT_EQ(a.verdict(), b.verdict());
        EXPECT_EQ(a.correlationTime, b.correlationTime);
        EXPECT_EQ(a.slopeChange.value, b.slopeChange.value);
        EXPECT_EQ(a.drift.value, b.drift.value);
    }
    EXPECT_EQ(resumed.collectiveMotionTransverse.value, reference.collectiveMotionTransverse.value);
    EXPECT_EQ(resumed.collectiveMotionLongitudinal.value, reference.collectiveMotionLongitudinal.value);
    EXPECT_EQ(resumed.meanStress, reference.meanStress);
    EXPECT_EQ(resumed.collisions.counts, reference.collisions.counts);
    EXPECT_EQ(resumed.collisions.histogram, reference.collisions.histogram);
    EXPECT_EQ(resumed.stressIntegrals.crossToProductRatio, reference.stressIntegrals.crossToProductRatio);
    EXPECT_EQ(resumed.stressIntegrals.total.integral.value, reference.stressIntegrals.total.integral.value);
    ASSERT_EQ(resumed.kineticSieving.size(), reference.kineticSieving.size());
    for (std::size_t k = 0; k < reference.kineticSieving.size(); ++k)
    {
        // the stress products about the means: the open block's sums and the closed
        // blocks' means come back bit for bit
        EXPECT_EQ(resumed.kineticSieving[k].value, reference.kineticSieving[k].value);
        EXPECT_EQ(resumed.kineticSievingWithCrossTerms[k].value, reference.kineticSievingWithCrossTerms[k].value);
    }

    // a checkpoint of other sampling settings is refused
    CellRunSettings other = second;
    other.sampleEvery = 20;
    EXPECT_THROW(runCell(other), std::invalid_argument);
}

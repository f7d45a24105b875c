// The merge of the MPI ranks' stores into the main store: every condition
// moved once and exactly, the rank stores and their leftovers removed, a
// foreign rank store refused with every file left as it was.
#include "store/ProcessorStores.hpp"
#include "store/Store.hpp"
#include "StoreTestData.hpp"

#include "io/Hdf5File.hpp"
#include "io/tests/TemporaryDirectory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace sdf::store;
using sdf::io::test::TemporaryDirectory;
using sdf::store::test::inputs;
using sdf::store::test::syntheticResult;

TEST(processorStores, pathIsBesideTheMainStore)
{
    EXPECT_EQ(processorStorePath("case/constant/calibration.h5", 3), "case/constant/calibration.processor3.h5");
}


TEST(processorStores, mergeMovesEveryConditionOnce)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const std::string rank0 = processorStorePath(h5, 0);
    const std::string rank1 = processorStorePath(h5, 1);

    // Main store with one condition; rank 0 stored it too (a merge killed
    // after the main store was updated) and another; rank 1 a third
    appendCondition(h5, "small", "large", "k", inputs(0.2, 0.4, 0.01, 1), syntheticResult(1));
    appendCondition(rank0, "small", "large", "k", inputs(0.2, 0.4, 0.01, 1), syntheticResult(5));
    appendCondition(rank0, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), syntheticResult(2));
    appendCondition(rank1, "small", "large", "k", inputs(0.4, 0.4, 0.01, 1), syntheticResult(3));
    std::ofstream(rank1 + ".tmp") << "half a copy";

    const MergeSummary summary = mergeProcessorStores(h5);
    EXPECT_EQ(summary.stores.size(), 2u);
    EXPECT_EQ(summary.conditionsMoved, 2u);
    EXPECT_FALSE(std::filesystem::exists(rank0));
    EXPECT_FALSE(std::filesystem::exists(rank1));
    EXPECT_FALSE(std::filesystem::exists(rank1 + ".tmp"));

    const StoreContents contents = readStore(h5);
    ASSERT_EQ(contents.conditions.size(), 3u);
    const double D1 = syntheticResult(1).species[0].greenKubo.integral.value;
    EXPECT_EQ(contents.conditions[0].fine.D, D1);        // the main store's copy kept
    EXPECT_EQ(contents.conditions[1].fine.D, syntheticResult(2).species[0].greenKubo.integral.value);
    EXPECT_EQ(contents.conditions[2].fine.D, syntheticResult(3).species[0].greenKubo.integral.value);

    // Exact copies: every attribute of every sub-group
    const sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group g = f.root().openGroup("conditions/" + conditionName(0.4, 0.4, 0.01, 1));
    EXPECT_EQ(g.readInt64("steps"), 12345);
    EXPECT_EQ(g.readString("settingsKey"), "k");
    EXPECT_EQ(g.openGroup("timing").readDouble("cpuSeconds"), 1.4);
    EXPECT_EQ(g.openGroup("species/large").readString("role"), "coarse");
    // and the collision statistics' datasets (bin edges, integer histograms)
    const sdf::dem::CellRunResult r3 = syntheticResult(3);
    const CollisionRecord& col = *contents.conditions[2].collisions;
    EXPECT_EQ(col.binEdges, r3.collisions.binEdges);
    EXPECT_EQ(col.elapsedTime, r3.collisions.elapsedTime);
    EXPECT_EQ(col.pair("small", "large")->energySum, r3.collisions.energySum[1]);
    EXPECT_EQ
    (
        col.pair("large", "large")->histogram,
        std::vector<std::int64_t>(r3.collisions.histogram[2].begin(), r3.collisions.histogram[2].end())
    );
    EXPECT_TRUE(g.openGroup("collisions/small/small").isIntegerDataset("histogram"));

    // Nothing left to merge
    EXPECT_EQ(mergeProcessorStores(h5).conditionsMoved, 0u);
}


TEST(processorStores, mergeCreatesTheMainStore)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    appendCondition(processorStorePath(h5, 0), "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), syntheticResult());
    EXPECT_EQ(mergeProcessorStores(h5).conditionsMoved, 1u);
    const StoreContents contents = readStore(h5);
    EXPECT_EQ(contents.fineSpecies, "small");
    EXPECT_EQ(contents.coarseSpecies, "large");
    EXPECT_EQ(contents.conditions.size(), 1u);
}


TEST(processorStores, foreignRankStoreStopsTheMergeUntouched)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const std::string rank0 = processorStorePath(h5, 0);
    const std::string rank1 = processorStorePath(h5, 1);
    appendCondition(rank0, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), syntheticResult());
    std::ofstream(rank1) << "not HDF5";
    try
    {
        mergeProcessorStores(h5);
        ADD_FAILURE() << "a foreign rank store was merged";
    }
    catch (const StoreError& e)
    {
        EXPECT_EQ(e.file(), rank1);
    }
    EXPECT_TRUE(std::filesystem::exists(rank0));
    EXPECT_TRUE(std::filesystem::exists(rank1));
    EXPECT_FALSE(std::filesystem::exists(h5));
}

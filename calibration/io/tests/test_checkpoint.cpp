#include "io/Checkpoint.hpp"
#include "io/Hdf5File.hpp"
#include "TemporaryDirectory.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <sstream>

using namespace sdf::io;
using sdf::io::test::TemporaryDirectory;

namespace
{

Checkpoint sampleCheckpoint(std::mt19937_64& engine)
{
    std::normal_distribution<double> normal(0.0, 1.0);
    Checkpoint c;
    c.scalars["time"] = 12.345678901234567;
    c.scalars["dt"] = 1e-5;
    c.scalars["tiny"] = std::numeric_limits<double>::denorm_min();
    c.integers["step"] = 1234567;
    c.integers["seed"] = std::numeric_limits<std::int64_t>::max();
    c.strings["contactLaw"] = "hookeHistory";
    Eigen::MatrixXd positions(50, 3), velocities(50, 3);
    for (Eigen::Index i = 0; i < positions.size(); ++i)
    {
        positions.data()[i] = normal(engine);
        velocities.data()[i] = normal(engine);
    }
    c.matrices["positions"] = positions;
    c.matrices["velocities"] = velocities;
    c.matrices["tangentialSprings"] = Eigen::MatrixXd::Random(17, 3);
    c.integerVectors["species"] = std::vector<std::int64_t>(50, 1);
    c.integerVectors["contactPairs"] = {0, 1, 4, 9, 16};
    c.vectors["vacfSums"] = {1.0, 0.5, 0.25};
    c.vectors["emptyHistory"] = {};
    std::ostringstream state;
    state << engine;   // the RNG state, to continue the same random sequence
    c.strings["rngState"] = state.str();
    return c;
}

} // namespace

TEST(Checkpoint, RoundTripIsBitForBitAndResumesTheRandomSequence)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("checkpoint.h5");
    std::mt19937_64 engine(2026);
    engine.discard(1000);
    const Checkpoint written = sampleCheckpoint(engine);
    const std::uint64_t nextDraw = engine();

    writeCheckpoint(path, written);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const Checkpoint read = readCheckpoint(path);
    EXPECT_TRUE(read == written);
    EXPECT_EQ(read.matrices.at("positions"), written.matrices.at("positions"));
    EXPECT_EQ(read.scalars.at("time"), 12.345678901234567);
    EXPECT_EQ(read.integers.at("step"), 1234567);

    std::mt19937_64 resumed;
    std::istringstream(read.strings.at("rngState")) >> resumed;
    EXPECT_EQ(resumed(), nextDraw);

    // It is one of our files, with the checkpoint in its own group.
    const File file = File::openReadOnly(path);
    EXPECT_EQ(file.root().openGroup(checkpointGroup).readString("kind"), "periodicDEM checkpoint");
}

TEST(Checkpoint, AFailedRewriteKeepsThePreviousCheckpoint)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("checkpoint.h5");
    std::mt19937_64 engine(7);
    const Checkpoint first = sampleCheckpoint(engine);
    writeCheckpoint(path, first);

    // Fails after some datasets are written: an empty name is invalid in HDF5.
    Checkpoint broken = sampleCheckpoint(engine);
    broken.matrices[""] = Eigen::MatrixXd::Zero(2, 2);
    EXPECT_THROW(writeCheckpoint(path, broken), Hdf5Error);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    EXPECT_TRUE(readCheckpoint(path) == first);

    // Duplicate names across maps are refused before anything is written.
    Checkpoint duplicate = first;
    duplicate.integers["time"] = 3;
    EXPECT_THROW(writeCheckpoint(path, duplicate), Hdf5Error);
    EXPECT_TRUE(readCheckpoint(path) == first);
}

TEST(Checkpoint, FilesWithoutACheckpointAreRejectedNamingTheFile)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("results.h5");
    File::create(path).root().createGroup("conditions");
    try
    {
        readCheckpoint(path);
        FAIL() << "no exception";
    }
    catch (const Hdf5Error& e)
    {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.objectPath(), "/checkpoint");
    }
    const std::string foreign = dir.file("foreign.h5");
    {
        Handle raw(H5Fcreate(foreign.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    }
    EXPECT_THROW(readCheckpoint(foreign), ForeignFileError);
}

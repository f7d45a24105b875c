#include "io/Hdf5File.hpp"
#include "TemporaryDirectory.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

using namespace sdf::io;
using sdf::io::test::TemporaryDirectory;

namespace
{

std::string readText(const std::string& path)
{
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Expects statement to throw E whose what() names the file; returns the message.
template<class E, class F>
std::string expectThrowNamingFile(F statement, const std::string& file)
{
    try
    {
        statement();
    }
    catch (const E& e)
    {
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
        EXPECT_EQ(e.file(), file);
        return e.what();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "unexpected exception type: " << e.what();
        return "";
    }
    ADD_FAILURE() << "no exception";
    return "";
}

} // namespace

TEST(Hdf5File, RoundTripOfAttributesGroupsAndDatasets)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("round.h5");
    Eigen::MatrixXd matrix(3, 4);
    for (int r = 0; r < 3; ++r)
    {
        for (int c = 0; c < 4; ++c)
        {
            matrix(r, c) = 10.0 * r + c + 0.125;
        }
    }
    const std::vector<double> vector = {
        1.0 / 3.0, -0.0, std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::max(), -1e-300};
    const std::vector<std::int64_t> integers = {
        std::numeric_limits<std::int64_t>::min(), -1, 0, std::numeric_limits<std::int64_t>::max()};
    {
        File file = File::create(path);
        const Group root = file.root();
        root.setAttribute("seed", std::int64_t(1234567890123));
        root.setAttribute("version", "0.1.0-g1a2b3c");
        const Group condition = root.createGroup("conditions/phi0.30_x0.2");
        EXPECT_EQ(condition.path(), "/conditions/phi0.30_x0.2");
        condition.setAttribute("phi", 0.3);
        condition.setAttribute("label", "");
        condition.setAttribute("unicode", "T in m\u00b2/s\u00b2");
        condition.setAttribute("phi", 0.31);   // replaces
        condition.writeVector("D/fine", vector).setAttribute("units", "m2/s");
        condition.writeVector("empty", {});
        condition.writeMatrix("vacf", matrix);
        condition.writeInt64Vector("species", integers);
        file.close();
    }
    const File file = File::openReadOnly(path);
    EXPECT_EQ(file.formatVersion(), currentFormatVersion);
    const Group root = file.root();
    EXPECT_EQ(root.readString("format"), formatName);
    EXPECT_EQ(root.readInt64("seed"), 1234567890123);
    EXPECT_EQ(root.readString("version"), "0.1.0-g1a2b3c");
    EXPECT_EQ(root.childNames(), std::vector<std::string>{"conditions"});
    const Group condition = root.openGroup("conditions/phi0.30_x0.2");
    EXPECT_EQ(condition.readDouble("phi"), 0.31);
    EXPECT_EQ(condition.readString("label"), "");
    EXPECT_EQ(condition.readString("unicode"), "T in m\u00b2/s\u00b2");
    EXPECT_EQ(condition.attributeNames(), (std::vector<std::string>{"label", "phi", "unicode"}));
    EXPECT_EQ(condition.attributeType("phi"), AttributeType::floating);
    EXPECT_EQ(condition.attributeType("nothing"), AttributeType::missing);
    EXPECT_EQ(condition.childNames(), (std::vector<std::string>{"D", "empty", "species", "vacf"}));

    const std::vector<double> back = condition.readVector("D/fine");
    ASSERT_EQ(back.size(), vector.size());
    for (std::size_t i = 0; i < back.size(); ++i)
    {
        EXPECT_EQ(std::memcmp(&back[i], &vector[i], sizeof(double)), 0) << i;   // bit for bit, -0.0 too
    }
    EXPECT_EQ(condition.openDataset("D/fine").readString("units"), "m2/s");
    EXPECT_TRUE(condition.readVector("empty").empty());
    EXPECT_EQ(condition.readMatrix("vacf"), matrix);
    EXPECT_EQ(condition.openDataset("vacf").shape(), (std::vector<std::size_t>{3, 4}));
    EXPECT_EQ(condition.readInt64Vector("species"), integers);
    EXPECT_TRUE(condition.hasGroup("D"));
    EXPECT_TRUE(condition.hasDataset("D/fine"));
    EXPECT_FALSE(condition.hasDataset("D"));
    EXPECT_FALSE(condition.has("E/fine"));   // missing intermediate: false, not an error
}

TEST(Hdf5File, ErrorsNameTheFileAndTheObject)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("errors.h5");
    File file = File::create(path);
    const Group root = file.root();
    root.createGroup("a").setAttribute("n", std::int64_t(3));
    root.writeVector("v", {1.0, 2.0});
    try
    {
        root.openGroup("missing/deeper");
        FAIL() << "no exception";
    }
    catch (const Hdf5Error& e)
    {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(e.objectPath(), "/missing/deeper");
        EXPECT_NE(std::string(e.what()).find("/missing/deeper"), std::string::npos);
    }
    const Group a = root.openGroup("a");
    // Types are not converted silently.
    EXPECT_THROW(a.readDouble("n"), Hdf5Error);
    EXPECT_THROW(a.readString("n"), Hdf5Error);
    EXPECT_THROW(a.readInt64("absent"), Hdf5Error);
    EXPECT_THROW(root.readMatrix("v"), Hdf5Error);        // rank 1, not 2
    EXPECT_THROW(root.readInt64Vector("v"), Hdf5Error);   // doubles, not integers
    EXPECT_THROW(root.createGroup("a"), Hdf5Error);       // exists
    EXPECT_EQ(root.requireGroup("a").readInt64("n"), 3);  // opens instead
    // After the file is closed, the open group fails cleanly instead of crashing.
    file.close();
    EXPECT_THROW(a.writeVector("late", {1.0}), Hdf5Error);
}

TEST(Hdf5File, AppendAddsOneGroupPerCondition)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("calibration.h5");
    File::create(path).root().createGroup("conditions/c0").setAttribute("phi", 0.1);
    {
        File file = File::openForAppend(path);
        file.root().requireGroup("conditions").createGroup("c1").setAttribute("phi", 0.2);
    }
    // The group keeps the file open after the temporary File is gone.
    const Group conditions = File::openReadOnly(path).root().openGroup("conditions");
    EXPECT_EQ(conditions.childNames(), (std::vector<std::string>{"c0", "c1"}));
    EXPECT_EQ(conditions.openGroup("c1").readDouble("phi"), 0.2);
    EXPECT_EQ(conditions.openGroup("c0").readDouble("phi"), 0.1);
}

TEST(Hdf5File, AtomicWriteLeavesNoPartialFileWhenInterrupted)
{
    TemporaryDirectory dir;
    const std::string path = dir.file("run.h5");
    const std::vector<double> big(100000, 1.5);
    EXPECT_THROW(
        {
            AtomicFile out = AtomicFile::create(path);
            out.root().writeVector("positions", big);
            EXPECT_TRUE(std::filesystem::exists(path + ".tmp"));
            EXPECT_FALSE(std::filesystem::exists(path));
            throw std::runtime_error("simulated failure mid-write");
        },
        std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));

    {
        AtomicFile out = AtomicFile::create(path);
        out.root().createGroup("conditions/c0").writeVector("T", {1.0});
        out.commit();
    }
    EXPECT_TRUE(std::filesystem::exists(path));
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const auto bytesBefore = std::filesystem::file_size(path);

    // An interrupted update leaves the committed file exactly as it was.
    EXPECT_THROW(
        {
            AtomicFile out = AtomicFile::update(path);
            out.root().openGroup("conditions").createGroup("c1").writeVector("T", big);
            throw std::runtime_error("simulated failure mid-update");
        },
        std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    EXPECT_EQ(std::filesystem::file_size(path), bytesBefore);
    EXPECT_EQ(File::openReadOnly(path).root().openGroup("conditions").childNames(),
              std::vector<std::string>{"c0"});

    // A committed update adds the group.
    {
        AtomicFile out = AtomicFile::update(path);
        out.root().openGroup("conditions").createGroup("c1").writeVector("T", {2.0});
        out.commit();
        EXPECT_THROW(out.commit(), Hdf5Error);
    }
    EXPECT_EQ(File::openReadOnly(path).root().openGroup("conditions").childNames(),
              (std::vector<std::string>{"c0", "c1"}));
}

TEST(Hdf5File, CorruptMissingAndTruncatedFilesAreRejectedNamingTheFile)
{
    TemporaryDirectory dir;
    const std::string missing = dir.file("missing.h5");
    expectThrowNamingFile<Hdf5Error>([&] { File::openReadOnly(missing); }, missing);

    const std::string text = dir.file("notes.h5");
    std::ofstream(text) << "this is not HDF5\n";
    const std::string message = expectThrowNamingFile<Hdf5Error>([&] { File::openReadOnly(text); }, text);
    EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
    EXPECT_FALSE(File::isOurs(text));

    const std::string truncated = dir.file("truncated.h5");
    File::create(truncated).root().writeVector("data", std::vector<double>(200000, 2.0));
    std::filesystem::resize_file(truncated, std::filesystem::file_size(truncated) / 2);
    expectThrowNamingFile<Hdf5Error>([&] { File::openReadOnly(truncated).root().readVector("data"); }, truncated);
    EXPECT_THROW(AtomicFile::update(truncated), Hdf5Error);
    EXPECT_FALSE(std::filesystem::exists(truncated + ".tmp"));
}

TEST(Hdf5File, ForeignHdf5FilesAreRejectedNamingTheFile)
{
    TemporaryDirectory dir;
    // A valid HDF5 file written by someone else: no format attribute.
    const std::string plain = dir.file("plain.h5");
    {
        Handle raw(H5Fcreate(plain.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
        ASSERT_TRUE(raw.valid());
    }
    std::string message = expectThrowNamingFile<ForeignFileError>([&] { File::openReadOnly(plain); }, plain);
    EXPECT_NE(message.find("format"), std::string::npos) << message;
    expectThrowNamingFile<ForeignFileError>([&] { File::openForAppend(plain); }, plain);
    EXPECT_THROW(AtomicFile::update(plain), ForeignFileError);
    EXPECT_FALSE(File::isOurs(plain));

    // Another program's format name.
    const std::string other = dir.file("other.h5");
    File::create(other).root().setAttribute("format", "someone-else");
    message = expectThrowNamingFile<ForeignFileError>([&] { File::openReadOnly(other); }, other);
    EXPECT_NE(message.find("someone-else"), std::string::npos) << message;

    // Ours, from a newer format version.
    const std::string newer = dir.file("newer.h5");
    File::create(newer).root().setAttribute("formatVersion", currentFormatVersion + 1);
    message = expectThrowNamingFile<ForeignFileError>([&] { File::openReadOnly(newer); }, newer);
    EXPECT_NE(message.find("formatVersion"), std::string::npos) << message;

    // A formatVersion of the wrong type is not ours either.
    const std::string oddVersion = dir.file("oddVersion.h5");
    File::create(oddVersion).root().setAttribute("formatVersion", 1.0);
    expectThrowNamingFile<ForeignFileError>([&] { File::openReadOnly(oddVersion); }, oddVersion);

    const std::string ours = dir.file("ours.h5");
    File::create(ours);
    EXPECT_TRUE(File::isOurs(ours));
}

TEST(Hdf5File, H5dumpReadsTheOutput)
{
#ifndef SDF_H5DUMP
    GTEST_SKIP() << "h5dump not found at configure time";
#else
    TemporaryDirectory dir;
    const std::string path = dir.file("dump.h5");
    {
        AtomicFile out = AtomicFile::create(path);
        const Group condition = out.root().createGroup("conditions/phi0.3");
        condition.setAttribute("T", 0.01);
        condition.setAttribute("note", "a string");
        condition.writeMatrix("vacf", Eigen::MatrixXd::Ones(5, 3));
        condition.writeInt64Vector("collisions", {1, 2, 3});
        out.commit();
    }
    const std::string listing = dir.file("dump.txt");
    const std::string command = std::string(SDF_H5DUMP) + " -H '" + path + "' > '" + listing + "' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(listing);
    const std::string header = readText(listing);
    EXPECT_NE(header.find("ATTRIBUTE \"format\""), std::string::npos) << header;
    EXPECT_NE(header.find("ATTRIBUTE \"formatVersion\""), std::string::npos) << header;
    EXPECT_NE(header.find("GROUP \"phi0.3\""), std::string::npos) << header;
    EXPECT_NE(header.find("DATASET \"vacf\""), std::string::npos) << header;
    EXPECT_NE(header.find("( 5, 3 )"), std::string::npos) << header;
    // Values, row-major as written: h5dump -d shows the attribute string.
    const std::string values = dir.file("values.txt");
    const std::string dump = std::string(SDF_H5DUMP) + " -a /conditions/phi0.3/note '" + path + "' > '" + values + "' 2>&1";
    ASSERT_EQ(std::system(dump.c_str()), 0) << readText(values);
    EXPECT_NE(readText(values).find("\"a string\""), std::string::npos) << readText(values);
#endif
}

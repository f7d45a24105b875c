// HDF5 files of segregationDegradationFoam calibration runs: typed access to
// groups, attributes (double, int64, string) and 1-D / 2-D datasets over the
// HDF5 C API, with every handle owned by RAII and every failure thrown as an
// Hdf5Error naming the file and object. Layout of a run: docs/developer/hdf5-layout.md.
//
//   sdf::io::AtomicFile out("run.h5");          // writes run.h5.tmp
//   sdf::io::Group condition = out.root().createGroup("conditions/phi0.3");
//   condition.setAttribute("phi", 0.3);
//   condition.writeVector("vacf/fine", values).setAttribute("units", "m2/s2");
//   out.commit();                               // renames to run.h5
//
// Our files carry root attributes format = "segregationDegradationFoam-
// calibration" and formatVersion; opening checks them.
//
// The Debian HDF5 library is built without thread safety: use these classes
// from one thread at a time (the DEM writes results after its OpenMP loops).
#ifndef sdf_io_Hdf5File_hpp
#define sdf_io_Hdf5File_hpp

#include "io/Hdf5Error.hpp"
#include "io/Handle.hpp"

#include <Eigen/Dense>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sdf::io
{

inline constexpr const char* formatName = "segregationDegradationFoam-calibration";
inline constexpr std::int64_t currentFormatVersion = 1;

class Dataset;
class Group;

enum class AttributeType { missing, floating, integer, string, other };

//- What groups and datasets share: a named object in a file with attributes.
class Node
{
public:
    const std::string& fileName() const { return fileName_; }
    const std::string& path() const { return path_; }   // e.g. "/conditions/phi0.3"

    bool hasAttribute(const std::string& name) const;
    std::vector<std::string> attributeNames() const;
    AttributeType attributeType(const std::string& name) const;

    //- Writes (replacing an existing attribute of the same name).
    void setAttribute(const std::string& name, double value) const;
    void setAttribute(const std::string& name, std::int64_t value) const;
    void setAttribute(const std::string& name, int value) const
    {
        setAttribute(name, static_cast<std::int64_t>(value));
    }
    void setAttribute(const std::string& name, const std::string& value) const;
    void setAttribute(const std::string& name, const char* value) const
    {
        setAttribute(name, std::string(value));
    }

    //- Reads; throws Hdf5Error if missing or of another type (an integer
    //  attribute is not silently read as double, nor the reverse).
    double readDouble(const std::string& name) const;
    std::int64_t readInt64(const std::string& name) const;
    std::string readString(const std::string& name) const;

protected:
    Node(std::shared_ptr<Handle> file, Handle handle, std::string fileName, std::string path);
    const std::shared_ptr<Handle>& fileHandle() const { return file_; }
    hid_t id() const { return handle_.get(); }
    [[noreturn]] void fail(const std::string& message, const std::string& child = "") const;
    std::string childPath(const std::string& name) const;

private:
    // Declared first so it is released last: an open group or dataset keeps
    // its file open (like h5py), even after the File object is gone.
    std::shared_ptr<Handle> file_;
    Handle handle_;
    std::string fileName_;
    std::string path_;
};

class Dataset : public Node
{
public:
    //- Dimensions: {n} for a vector, {rows, cols} for a matrix.
    std::vector<std::size_t> shape() const;

private:
    friend class Group;
    using Node::Node;
};

class Group : public Node
{
public:
    //- Creates the group, with missing intermediate groups ("a/b/c");
    //  throws if it exists.
    Group createGroup(const std::string& name) const;
    //- Opens an existing group; throws naming the file and path if missing.
    Group openGroup(const std::string& name) const;
    //- Opens, or creates if missing (groups per condition when appending).
    Group requireGroup(const std::string& name) const;

    //- A direct or nested link exists ("a" or "a/b").
    bool has(const std::string& name) const;
    bool hasGroup(const std::string& name) const;
    bool hasDataset(const std::string& name) const;
    //- Names of the direct children, sorted.
    std::vector<std::string> childNames() const;

    //- Datasets of doubles (replacing an existing dataset of the same name).
    //  A matrix is stored row-major as HDF5 dims {rows, cols}, which is how
    //  h5dump, h5py and numpy show it.
    Dataset writeVector(const std::string& name, const std::vector<double>& values) const;
    Dataset writeMatrix(const std::string& name, const Eigen::MatrixXd& values) const;
    Dataset writeInt64Vector(const std::string& name, const std::vector<std::int64_t>& values) const;

    std::vector<double> readVector(const std::string& name) const;
    Eigen::MatrixXd readMatrix(const std::string& name) const;
    std::vector<std::int64_t> readInt64Vector(const std::string& name) const;

    Dataset openDataset(const std::string& name) const;
    //- true if the dataset holds integers (false: floating point).
    bool isIntegerDataset(const std::string& name) const;

private:
    friend class File;
    using Node::Node;
    Dataset createDataset
    (
        const std::string& name,
        hid_t memoryType,
        hid_t fileType,
        const std::vector<hsize_t>& dims,
        const void* data
    ) const;
    //- Dimensions of an existing dataset after checking its type class
    //  (H5T_FLOAT or H5T_INTEGER) and rank.
    std::vector<hsize_t> datasetDims
    (
        const std::string& name,
        H5T_class_t expectedClass,
        std::size_t expectedRank
    ) const;
    void readData(const std::string& name, hid_t memoryType, void* out) const;
};

class File
{
public:
    //- New file (an existing one is truncated), stamped as ours.
    static File create(const std::string& path);
    //- Existing file of ours, read only. Throws Hdf5Error naming the file if
    //  it is missing or not HDF5 (corrupt), ForeignFileError if not ours.
    static File openReadOnly(const std::string& path);
    //- Existing file of ours, read-write, to append groups.
    static File openForAppend(const std::string& path);

    //- true if path is an HDF5 file with our format attribute (no throw).
    static bool isOurs(const std::string& path);

    const std::string& path() const { return path_; }
    Group root() const;
    std::int64_t formatVersion() const;

    //- Writes buffered data to disk.
    void flush() const;
    //- Closes now, and reports a failure. Groups and datasets still open in
    //  it are closed too (later use throws Hdf5Error). Without close(), the
    //  file closes silently when the File and every group and dataset
    //  opened from it are gone.
    void close();

private:
    File(Handle handle, std::string path);
    static File open(const std::string& path, bool writable);
    void checkOurs() const;

    std::shared_ptr<Handle> handle_;
    std::string path_;
};

//- Writes a file so that no half-written file ever carries the final name:
//  everything goes to "<path>.tmp", and commit() renames it over <path>
//  (rename is atomic on POSIX filesystems). Destroyed without commit() (an
//  exception mid-write), it deletes the temporary and leaves <path> as it was.
class AtomicFile
{
public:
    //- A new file.
    static AtomicFile create(const std::string& path);
    //- A copy of the existing file of ours at path, to add or replace groups;
    //  the original stays intact until commit().
    static AtomicFile update(const std::string& path);

    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&&) = delete;
    ~AtomicFile();

    Group root() const { return file_.root(); }
    File& file() { return file_; }
    const std::string& finalPath() const { return finalPath_; }
    const std::string& temporaryPath() const { return file_.path(); }

    //- Closes the file and moves it to the final path. Call once.
    void commit();

private:
    AtomicFile(File file, std::string finalPath);

    File file_;
    std::string finalPath_;
    bool done_ = false;
};

} // namespace sdf::io

#endif

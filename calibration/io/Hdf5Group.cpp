#include "io/Hdf5File.hpp"
#include "io/Hdf5Internals.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sdf::io
{

using namespace detail;

// * * * * * * * * * * * * * * * * Dataset * * * * * * * * * * * * * * * * //

std::vector<std::size_t> Dataset::shape() const
{
    QuietErrors quiet;
    Handle space = makeHandle(H5Dget_space(id()), H5Sclose);
    const int rank = space.valid() ? H5Sget_simple_extent_ndims(space.get()) : -1;
    if (rank < 0)
    {
        fail("cannot read the dataset's shape");
    }
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return std::vector<std::size_t>(dims.begin(), dims.end());
}


// * * * * * * * * * * * * * * * * Group * * * * * * * * * * * * * * * * * //

bool Group::has(const std::string& name) const
{
    QuietErrors quiet;
    if (name.empty())
    {
        return false;
    }
    // H5Lexists fails (not false) when an intermediate group is missing, so
    // walk the path one link at a time.
    std::string partial = name.front() == '/' ? "/" : "";
    for (const std::string& part : splitPath(name))
    {
        partial += (partial.empty() || partial == "/" ? "" : "/") + part;
        if (H5Lexists(id(), partial.c_str(), H5P_DEFAULT) <= 0)
        {
            return false;
        }
    }
    return true;
}

namespace
{

H5I_type_t objectType(hid_t id, const std::string& name)
{
    Handle object = makeHandle(H5Oopen(id, name.c_str(), H5P_DEFAULT), H5Oclose);
    return object.valid() ? H5Iget_type(object.get()) : H5I_BADID;
}

} // namespace

bool Group::hasGroup(const std::string& name) const
{
    QuietErrors quiet;
    return has(name) && objectType(id(), name) == H5I_GROUP;
}

bool Group::hasDataset(const std::string& name) const
{
    QuietErrors quiet;
    return has(name) && objectType(id(), name) == H5I_DATASET;
}

std::vector<std::string> Group::childNames() const
{
    QuietErrors quiet;
    std::vector<std::string> names;
    hsize_t index = 0;
    const herr_t status = H5Literate
    (
        id(), H5_INDEX_NAME, H5_ITER_INC, &index,
        [](hid_t, const char* name, const H5L_info_t*, void* data) -> herr_t
        {
            static_cast<std::vector<std::string>*>(data)->push_back(name);
            return 0;
        },
        &names
    );
    if (status < 0)
    {
        fail("cannot list the group's members");
    }
    std::sort(names.begin(), names.end());
    return names;
}

Group Group::createGroup(const std::string& name) const
{
    QuietErrors quiet;
    if (has(name))
    {
        throw Hdf5Error("cannot create group: it already exists", fileName(), childPath(name));
    }
    Handle links = linkCreationWithParents();
    Handle group = makeHandle
    (
        H5Gcreate2(id(), name.c_str(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Gclose
    );
    if (!group.valid())
    {
        fail("cannot create group", name);
    }
    return Group(fileHandle(), std::move(group), fileName(), childPath(name));
}

Group Group::openGroup(const std::string& name) const
{
    QuietErrors quiet;
    if (!hasGroup(name))
    {
        throw Hdf5Error("no such group", fileName(), childPath(name));
    }
    Handle group = makeHandle(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), H5Gclose);
    if (!group.valid())
    {
        fail("cannot open group", name);
    }
    return Group(fileHandle(), std::move(group), fileName(), childPath(name));
}

Group Group::requireGroup(const std::string& name) const
{
    return has(name) ? openGroup(name) : createGroup(name);
}

Dataset Group::createDataset
(
    const std::string& name,
    hid_t memoryType,
    hid_t fileType,
    const std::vector<hsize_t>& dims,
    const void* data
) const
{
    QuietErrors quiet;
    if (has(name) && H5Ldelete(id(), name.c_str(), H5P_DEFAULT) < 0)
    {
        fail("cannot replace the existing dataset", name);
    }
    Handle space = makeHandle
    (
        H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
        H5Sclose
    );
    Handle links = linkCreationWithParents();
    Handle dataset = space.valid() && links.valid()
      ? makeHandle
        (
            H5Dcreate2(id(), name.c_str(), fileType, space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
            H5Dclose
        )
      : Handle();
    if (!dataset.valid())
    {
        fail("cannot create dataset", name);
    }
    hsize_t elements = 1;
    for (hsize_t d : dims)
    {
        elements *= d;
    }
    if (elements > 0 && H5Dwrite(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    {
        fail("cannot write dataset", name);
    }
    return Dataset(fileHandle(), std::move(dataset), fileName(), childPath(name));
}

Dataset Group::writeVector(const std::string& name, const std::vector<double>& values) const
{
    return createDataset(name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, {values.size()}, values.data());
}

Dataset Group::writeInt64Vector(const std::string& name, const std::vector<std::int64_t>& values) const
{
    return createDataset(name, H5T_NATIVE_INT64, H5T_STD_I64LE, {values.size()}, values.data());
}

Dataset Group::writeMatrix(const std::string& name, const Eigen::MatrixXd& values) const
{
    // Eigen is column-major by default; HDF5 (like C and numpy) is row-major.
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor = values;
    return createDataset
    (
        name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
        {static_cast<hsize_t>(values.rows()), static_cast<hsize_t>(values.cols())},
        rowMajor.data()
    );
}

Dataset Group::openDataset(const std::string& name) const
{
    QuietErrors quiet;
    if (!hasDataset(name))
    {
        throw Hdf5Error("no such dataset", fileName(), childPath(name));
    }
    Handle dataset = makeHandle(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid())
    {
        fail("cannot open dataset", name);
    }
    return Dataset(fileHandle(), std::move(dataset), fileName(), childPath(name));
}

bool Group::isIntegerDataset(const std::string& name) const
{
    QuietErrors quiet;
    Handle dataset = makeHandle(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    Handle type = dataset.valid() ? makeHandle(H5Dget_type(dataset.get()), H5Tclose) : Handle();
    if (!type.valid())
    {
        fail("cannot open dataset", name);
    }
    return H5Tget_class(type.get()) == H5T_INTEGER;
}

std::vector<hsize_t> Group::datasetDims
(
    const std::string& name,
    H5T_class_t expectedClass,
    std::size_t expectedRank
) const
{
    QuietErrors quiet;
    if (!hasDataset(name))
    {
        throw Hdf5Error("no such dataset", fileName(), childPath(name));
    }
    Handle dataset = makeHandle(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    Handle type = dataset.valid() ? makeHandle(H5Dget_type(dataset.get()), H5Tclose) : Handle();
    Handle space = dataset.valid() ? makeHandle(H5Dget_space(dataset.get()), H5Sclose) : Handle();
    if (!type.valid() || !space.valid())
    {
        fail("cannot open dataset", name);
    }
    const H5T_class_t typeClass = H5Tget_class(type.get());
    if (typeClass != expectedClass)
    {
        throw Hdf5Error
        (
            std::string("dataset holds ") + className(typeClass) + ", expected "
          + className(expectedClass),
            fileName(), childPath(name)
        );
    }
    const int rank = H5Sget_simple_extent_ndims(space.get());
    if (rank != static_cast<int>(expectedRank))
    {
        throw Hdf5Error
        (
            "dataset has rank " + std::to_string(rank) + ", expected "
          + std::to_string(expectedRank),
            fileName(), childPath(name)
        );
    }
    std::vector<hsize_t> dims(expectedRank);
    H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
    return dims;
}

void Group::readData(const std::string& name, hid_t memoryType, void* out) const
{
    QuietErrors quiet;
    Handle dataset = makeHandle(H5Dopen2(id(), name.c_str(), H5P_DEFAULT), H5Dclose);
    if (!dataset.valid() || H5Dread(dataset.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0)
    {
        fail("cannot read dataset", name);
    }
}

std::vector<double> Group::readVector(const std::string& name) const
{
    const std::vector<hsize_t> dims = datasetDims(name, H5T_FLOAT, 1);
    std::vector<double> values(dims[0]);
    if (!values.empty())
    {
        readData(name, H5T_NATIVE_DOUBLE, values.data());
    }
    return values;
}

std::vector<std::int64_t> Group::readInt64Vector(const std::string& name) const
{
    const std::vector<hsize_t> dims = datasetDims(name, H5T_INTEGER, 1);
    std::vector<std::int64_t> values(dims[0]);
    if (!values.empty())
    {
        readData(name, H5T_NATIVE_INT64, values.data());
    }
    return values;
}

Eigen::MatrixXd Group::readMatrix(const std::string& name) const
{
    const std::vector<hsize_t> dims = datasetDims(name, H5T_FLOAT, 2);
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rowMajor
    (
        static_cast<Eigen::Index>(dims[0]), static_cast<Eigen::Index>(dims[1])
    );
    if (rowMajor.size() > 0)
    {
        readData(name, H5T_NATIVE_DOUBLE, rowMajor.data());
    }
    return rowMajor;
}


} // namespace sdf::io

#include "io/Hdf5File.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sdf::io
{

namespace
{

// HDF5 prints its error stack to stderr by default; we throw instead, so the
// printing is switched off for the duration of each call and then restored
// (the setting is the library's, not ours to change for good).
class QuietErrors
{
public:
    QuietErrors()
    {
        H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, function_, data_); }
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t function_ = nullptr;
    void* data_ = nullptr;
};

// The most specific description on the current HDF5 error stack, as ": ..."
// (empty if none). Must run before any other HDF5 call clears the stack.
std::string libraryMessage()
{
    std::vector<std::string> descriptions;
    H5Ewalk2
    (
        H5E_DEFAULT,
        H5E_WALK_UPWARD,
        [](unsigned, const H5E_error2_t* error, void* data) -> herr_t
        {
            if (error->desc != nullptr && error->desc[0] != '\0')
            {
                static_cast<std::vector<std::string>*>(data)->push_back(error->desc);
            }
            return 0;
        },
        &descriptions
    );
    return descriptions.empty() ? std::string() : ": " + descriptions.front();
}

[[noreturn]] void throwFileError(const std::string& message, const std::string& path)
{
    const std::string detail = libraryMessage();
    throw Hdf5Error(message + detail, path, "/");
}

Handle makeHandle(hid_t id, Handle::Closer close)
{
    return id < 0 ? Handle() : Handle(id, close);
}

Handle scalarSpace()
{
    return makeHandle(H5Screate(H5S_SCALAR), H5Sclose);
}

// A fixed-length, null-terminated UTF-8 string type holding `length` chars.
Handle stringType(std::size_t length)
{
    Handle type = makeHandle(H5Tcopy(H5T_C_S1), H5Tclose);
    if (type.valid())
    {
        H5Tset_size(type.get(), length + 1);
        H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
        H5Tset_cset(type.get(), H5T_CSET_UTF8);
    }
    return type;
}

Handle linkCreationWithParents()
{
    Handle list = makeHandle(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (list.valid())
    {
        H5Pset_create_intermediate_group(list.get(), 1);
    }
    return list;
}

std::vector<std::string> splitPath(const std::string& name)
{
    std::vector<std::string> parts;
    std::string part;
    for (char c : name)
    {
        if (c == '/')
        {
            if (!part.empty())
            {
                parts.push_back(part);
            }
            part.clear();
        }
        else
        {
            part += c;
        }
    }
    if (!part.empty())
    {
        parts.push_back(part);
    }
    return parts;
}

} // namespace


// * * * * * * * * * * * * * * * * Node  * * * * * * * * * * * * * * * * * //

Node::Node
(
    std::shared_ptr<Handle> file,
    Handle handle,
    std::string fileName,
    std::string path
)
:
    file_(std::move(file)),
    handle_(std::move(handle)),
    fileName_(std::move(fileName)),
    path_(std::move(path))
{}

std::string Node::childPath(const std::string& name) const
{
    if (!name.empty() && name.front() == '/')
    {
        return name;
    }
    return path_ == "/" ? "/" + name : path_ + "/" + name;
}

void Node::fail(const std::string& message, const std::string& child) const
{
    const std::string detail = libraryMessage();
    throw Hdf5Error(message + detail, fileName_, child.empty() ? path_ : childPath(child));
}

bool Node::hasAttribute(const std::string& name) const
{
    QuietErrors quiet;
    const htri_t exists = H5Aexists(id(), name.c_str());
    if (exists < 0)
    {
        fail("cannot query attribute '" + name + "'");
    }
    return exists > 0;
}

std::vector<std::string> Node::attributeNames() const
{
    QuietErrors quiet;
    std::vector<std::string> names;
    hsize_t index = 0;
    const herr_t status = H5Aiterate2
    (
        id(), H5_INDEX_NAME, H5_ITER_INC, &index,
        [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t
        {
            static_cast<std::vector<std::string>*>(data)->push_back(name);
            return 0;
        },
        &names
    );
    if (status < 0)
    {
        fail("cannot list attributes");
    }
    return names;
}

namespace
{

// Creates attribute `name` of fileType on object id, replacing an old one.
Handle createAttribute(hid_t id, const std::string& name, hid_t fileType)
{
    if (H5Aexists(id, name.c_str()) > 0 && H5Adelete(id, name.c_str()) < 0)
    {
        return Handle();
    }
    Handle space = scalarSpace();
    if (!space.valid())
    {
        return Handle();
    }
    return makeHandle
    (
        H5Acreate2(id, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT),
        H5Aclose
    );
}

} // namespace

void Node::setAttribute(const std::string& name, double value) const
{
    QuietErrors quiet;
    Handle attribute = createAttribute(id(), name, H5T_IEEE_F64LE);
    if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    {
        fail("cannot write double attribute '" + name + "'");
    }
}

void Node::setAttribute(const std::string& name, std::int64_t value) const
{
    QuietErrors quiet;
    Handle attribute = createAttribute(id(), name, H5T_STD_I64LE);
    if (!attribute.valid() || H5Awrite(attribute.get(), H5T_NATIVE_INT64, &value) < 0)
    {
        fail("cannot write integer attribute '" + name + "'");
    }
}

void Node::setAttribute(const std::string& name, const std::string& value) const
{
    QuietErrors quiet;
    Handle type = stringType(value.size());
    Handle attribute = type.valid() ? createAttribute(id(), name, type.get()) : Handle();
    if (!attribute.valid() || H5Awrite(attribute.get(), type.get(), value.c_str()) < 0)
    {
        fail("cannot write string attribute '" + name + "'");
    }
}

namespace
{

struct OpenedAttribute
{
    Handle attribute;
    Handle type;
    H5T_class_t typeClass = H5T_NO_CLASS;
};

OpenedAttribute openAttribute(hid_t id, const std::string& name)
{
    OpenedAttribute opened;
    if (H5Aexists(id, name.c_str()) <= 0)
    {
        return opened;
    }
    opened.attribute = makeHandle(H5Aopen(id, name.c_str(), H5P_DEFAULT), H5Aclose);
    if (opened.attribute.valid())
    {
        opened.type = makeHandle(H5Aget_type(opened.attribute.get()), H5Tclose);
        if (opened.type.valid())
        {
            opened.typeClass = H5Tget_class(opened.type.get());
        }
    }
    return opened;
}

const char* className(H5T_class_t typeClass)
{
    switch (typeClass)
    {
        case H5T_INTEGER: return "integer";
        case H5T_FLOAT: return "floating point";
        case H5T_STRING: return "string";
        default: return "another type";
    }
}

} // namespace

AttributeType Node::attributeType(const std::string& name) const
{
    QuietErrors quiet;
    const OpenedAttribute a = openAttribute(id(), name);
    if (!a.attribute.valid())
    {
        return AttributeType::missing;
    }
    switch (a.typeClass)
    {
        case H5T_FLOAT: return AttributeType::floating;
        case H5T_INTEGER: return AttributeType::integer;
        case H5T_STRING: return AttributeType::string;
        default: return AttributeType::other;
    }
}

double Node::readDouble(const std::string& name) const
{
    QuietErrors quiet;
    OpenedAttribute a = openAttribute(id(), name);
    if (!a.attribute.valid())
    {
        fail("attribute '" + name + "' is missing");
    }
    if (a.typeClass != H5T_FLOAT)
    {
        fail("attribute '" + name + "' is " + className(a.typeClass) + ", expected floating point");
    }
    double value = 0.0;
    if (H5Aread(a.attribute.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    {
        fail("cannot read attribute '" + name + "'");
    }
    return value;
}

std::int64_t Node::readInt64(const std::string& name) const
{
    QuietErrors quiet;
    OpenedAttribute a = openAttribute(id(), name);
    if (!a.attribute.valid())
    {
        fail("attribute '" + name + "' is missing");
    }
    if (a.typeClass != H5T_INTEGER)
    {
        fail("attribute '" + name + "' is " + className(a.typeClass) + ", expected integer");
    }
    std::int64_t value = 0;
    if (H5Aread(a.attribute.get(), H5T_NATIVE_INT64, &value) < 0)
    {
        fail("cannot read attribute '" + name + "'");
    }
    return value;
}

std::string Node::readString(const std::string& name) const
{
    QuietErrors quiet;
    OpenedAttribute a = openAttribute(id(), name);
    if (!a.attribute.valid())
    {
        fail("attribute '" + name + "' is missing");
    }
    if (a.typeClass != H5T_STRING)
    {
        fail("attribute '" + name + "' is " + className(a.typeClass) + ", expected string");
    }
    // Written by us: fixed length. Written by h5py and others: often variable.
    if (H5Tis_variable_str(a.type.get()) > 0)
    {
        Handle memoryType = makeHandle(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(memoryType.get(), H5T_VARIABLE);
        char* text = nullptr;
        if (H5Aread(a.attribute.get(), memoryType.get(), &text) < 0 || text == nullptr)
        {
            fail("cannot read attribute '" + name + "'");
        }
        std::string value(text);
        H5free_memory(text);
        return value;
    }
    const std::size_t size = H5Tget_size(a.type.get());
    std::vector<char> buffer(size + 1, '\0');
    Handle memoryType = stringType(size);
    if (H5Aread(a.attribute.get(), memoryType.get(), buffer.data()) < 0)
    {
        fail("cannot read attribute '" + name + "'");
    }
    return std::string(buffer.data());
}


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


// * * * * * * * * * * * * * * * * File  * * * * * * * * * * * * * * * * * //

namespace
{

// Closing the file closes every group and dataset still open in it, so that
// close() really releases the file before an atomic rename.
Handle strongCloseAccess()
{
    Handle list = makeHandle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (list.valid())
    {
        H5Pset_fclose_degree(list.get(), H5F_CLOSE_STRONG);
    }
    return list;
}

} // namespace

File::File(Handle handle, std::string path)
:
    handle_(std::make_shared<Handle>(std::move(handle))),
    path_(std::move(path))
{}

File File::create(const std::string& path)
{
    QuietErrors quiet;
    Handle access = strongCloseAccess();
    Handle file = makeHandle
    (
        H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
        H5Fclose
    );
    if (!file.valid())
    {
        throwFileError("cannot create HDF5 file", path);
    }
    File result(std::move(file), path);
    const Group root = result.root();
    root.setAttribute("format", std::string(formatName));
    root.setAttribute("formatVersion", currentFormatVersion);
    return result;
}

File File::open(const std::string& path, bool writable)
{
    QuietErrors quiet;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
    {
        throw Hdf5Error("no such file", path, "");
    }
    if (H5Fis_hdf5(path.c_str()) <= 0)
    {
        throw Hdf5Error
        (
            "not an HDF5 file (corrupt, truncated, or another format)" + libraryMessage(),
            path, ""
        );
    }
    Handle access = strongCloseAccess();
    Handle file = makeHandle
    (
        H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, access.get()),
        H5Fclose
    );
    if (!file.valid())
    {
        throwFileError
        (
            std::string("cannot open HDF5 file ") + (writable ? "for writing" : "for reading")
          + " (corrupt or truncated?)",
            path
        );
    }
    File result(std::move(file), path);
    result.checkOurs();
    return result;
}

File File::openReadOnly(const std::string& path)
{
    return open(path, false);
}

File File::openForAppend(const std::string& path)
{
    return open(path, true);
}

bool File::isOurs(const std::string& path)
{
    try
    {
        openReadOnly(path);
        return true;
    }
    catch (const Hdf5Error&)
    {
        return false;
    }
}

void File::checkOurs() const
{
    const Group top = root();
    const std::string expected = std::string("not a segregationDegradationFoam calibration file: ")
        + "expected root attribute format = \"" + formatName + "\"";
    if (!top.hasAttribute("format"))
    {
        throw ForeignFileError(expected + ", found none", path_, "/");
    }
    std::string format;
    try
    {
        format = top.readString("format");
    }
    catch (const Hdf5Error&)
    {
        throw ForeignFileError(expected + ", found one that is not a string", path_, "/");
    }
    if (format != formatName)
    {
        throw ForeignFileError(expected + ", found \"" + format + "\"", path_, "/");
    }
    const std::int64_t version =
        top.attributeType("formatVersion") == AttributeType::integer ? top.readInt64("formatVersion") : -1;
    if (version < 1 || version > currentFormatVersion)
    {
        throw ForeignFileError
        (
            "formatVersion " + std::to_string(version) + " is not readable by this code (reads 1 to "
          + std::to_string(currentFormatVersion) + ")",
            path_, "/"
        );
    }
}

Group File::root() const
{
    QuietErrors quiet;
    if (!handle_)
    {
        throw Hdf5Error("the File was moved from", path_, "/");
    }
    Handle group = makeHandle(H5Gopen2(handle_->get(), "/", H5P_DEFAULT), H5Gclose);
    if (!group.valid())
    {
        throwFileError("cannot open the root group (file closed?)", path_);
    }
    return Group(handle_, std::move(group), path_, "/");
}

std::int64_t File::formatVersion() const
{
    return root().readInt64("formatVersion");
}

void File::flush() const
{
    QuietErrors quiet;
    if (!handle_ || H5Fflush(handle_->get(), H5F_SCOPE_GLOBAL) < 0)
    {
        throwFileError("cannot flush", path_);
    }
}

void File::close()
{
    if (!handle_ || !handle_->valid())
    {
        return;
    }
    QuietErrors quiet;
    // H5F_CLOSE_STRONG: this also closes groups and datasets still open.
    if (H5Fclose(handle_->release()) < 0)
    {
        throwFileError("cannot close (data may not be on disk)", path_);
    }
}


// * * * * * * * * * * * * * * * AtomicFile  * * * * * * * * * * * * * * * //

AtomicFile::AtomicFile(File file, std::string finalPath)
:
    file_(std::move(file)),
    finalPath_(std::move(finalPath))
{}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
:
    file_(std::move(other.file_)),
    finalPath_(std::move(other.finalPath_)),
    done_(other.done_)
{
    other.done_ = true;   // the moved-from object must not delete our temporary
}

AtomicFile AtomicFile::create(const std::string& path)
{
    return AtomicFile(File::create(path + ".tmp"), path);
}

AtomicFile AtomicFile::update(const std::string& path)
{
    File::openReadOnly(path).close();   // ours, and readable, before we copy it
    const std::string temporary = path + ".tmp";
    std::error_code error;
    std::filesystem::copy_file
    (
        path, temporary, std::filesystem::copy_options::overwrite_existing, error
    );
    if (error)
    {
        throw Hdf5Error("cannot copy to '" + temporary + "' for update: " + error.message(), path, "");
    }
    try
    {
        return AtomicFile(File::openForAppend(temporary), path);
    }
    catch (...)
    {
        std::filesystem::remove(temporary, error);
        throw;
    }
}

void AtomicFile::commit()
{
    if (done_)
    {
        throw Hdf5Error("AtomicFile::commit called twice", finalPath_, "");
    }
    const std::string temporary = file_.path();
    file_.close();
    std::error_code error;
    std::filesystem::rename(temporary, finalPath_, error);
    if (error)
    {
        throw Hdf5Error
        (
            "cannot rename '" + temporary + "' to the final name: " + error.message(),
            finalPath_, ""
        );
    }
    done_ = true;
}

AtomicFile::~AtomicFile()
{
    if (done_)
    {
        return;
    }
    const std::string temporary = file_.path();
    try
    {
        file_.close();
    }
    catch (...)
    {
        // Unwinding already; the temporary goes anyway.
    }
    std::error_code error;
    std::filesystem::remove(temporary, error);
}

} // namespace sdf::io

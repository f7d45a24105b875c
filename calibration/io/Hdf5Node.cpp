#include "io/Hdf5File.hpp"
#include "io/Hdf5Internals.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sdf::io
{

using namespace detail;

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


} // namespace sdf::io

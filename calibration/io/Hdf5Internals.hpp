// Internal helpers shared by the HDF5 wrapper's translation units
// (Hdf5Node.cpp, Hdf5Group.cpp, Hdf5File.cpp): not part of the public interface.
#ifndef sdf_io_detail_Hdf5Internals_hpp
#define sdf_io_detail_Hdf5Internals_hpp

#include "io/Hdf5File.hpp"

#include <string>
#include <vector>

namespace sdf::io::detail
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
inline std::string libraryMessage()
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

[[noreturn]] inline void throwFileError(const std::string& message, const std::string& path)
{
    const std::string detail = libraryMessage();
    throw Hdf5Error(message + detail, path, "/");
}

inline Handle makeHandle(hid_t id, Handle::Closer close)
{
    return id < 0 ? Handle() : Handle(id, close);
}

inline Handle scalarSpace()
{
    return makeHandle(H5Screate(H5S_SCALAR), H5Sclose);
}

// A fixed-length, null-terminated UTF-8 string type holding `length` chars.
inline Handle stringType(std::size_t length)
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

inline Handle linkCreationWithParents()
{
    Handle list = makeHandle(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    if (list.valid())
    {
        H5Pset_create_intermediate_group(list.get(), 1);
    }
    return list;
}

inline std::vector<std::string> splitPath(const std::string& name)
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


//- What an HDF5 type class is called in error messages.
inline const char* className(H5T_class_t typeClass)
{
    switch (typeClass)
    {
        case H5T_INTEGER: return "integer";
        case H5T_FLOAT: return "floating point";
        case H5T_STRING: return "string";
        default: return "another type";
    }
}

} // namespace sdf::io::detail

#endif

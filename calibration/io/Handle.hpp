// RAII ownership of one HDF5 identifier (file, group, dataset, attribute,
// dataspace, datatype, property list): closed exactly once, in the destructor.
#ifndef sdf_io_Handle_hpp
#define sdf_io_Handle_hpp

#include <hdf5.h>

namespace sdf::io
{

class Handle
{
public:
    using Closer = herr_t (*)(hid_t);

    Handle() = default;
    //- Takes ownership of id (which must be valid) and closes it with close.
    Handle(hid_t id, Closer close) : id_(id), close_(close) {}

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(other.id_), close_(other.close_)
    {
        other.id_ = invalid;
    }
    Handle& operator=(Handle&& other) noexcept
    {
        if (this != &other)
        {
            reset();
            id_ = other.id_;
            close_ = other.close_;
            other.id_ = invalid;
        }
        return *this;
    }
    ~Handle() { reset(); }

    hid_t get() const { return id_; }
    //- Gives up ownership without closing (the caller closes and checks).
    hid_t release() noexcept
    {
        const hid_t id = id_;
        id_ = invalid;
        return id;
    }
    bool valid() const { return id_ >= 0; }

    //- Closes now. Identifiers already closed by the library (objects of a
    //  file closed with H5F_CLOSE_STRONG) are skipped, not closed twice.
    void reset() noexcept
    {
        if (id_ >= 0 && close_ != nullptr && H5Iis_valid(id_) > 0)
        {
            close_(id_);
        }
        id_ = invalid;
    }

private:
    static constexpr hid_t invalid = -1;
    hid_t id_ = invalid;
    Closer close_ = nullptr;
};

} // namespace sdf::io

#endif

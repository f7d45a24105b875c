#include "io/Hdf5File.hpp"
#include "io/Hdf5Internals.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace sdf::io
{

using namespace detail;

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

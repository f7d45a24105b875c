// Exceptions of sdf::io: every failure names the file and the object path, so
// a user can tell which of many calibration files (and which group) is wrong.
#ifndef sdf_io_Hdf5Error_hpp
#define sdf_io_Hdf5Error_hpp

#include <stdexcept>
#include <string>

namespace sdf::io
{

class Hdf5Error : public std::runtime_error
{
public:
    //- message: what failed; file and objectPath: where. what() joins them.
    Hdf5Error(const std::string& message, const std::string& file, const std::string& objectPath);

    const std::string& file() const { return file_; }
    const std::string& objectPath() const { return objectPath_; }

private:
    std::string file_;
    std::string objectPath_;
};

//- A readable HDF5 file that is not ours (no or another root `format`
//  attribute), or ours but from a newer formatVersion than this code reads.
class ForeignFileError : public Hdf5Error
{
public:
    using Hdf5Error::Hdf5Error;
};

} // namespace sdf::io

#endif

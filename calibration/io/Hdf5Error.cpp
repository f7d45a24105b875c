#include "io/Hdf5Error.hpp"

namespace sdf::io
{

Hdf5Error::Hdf5Error
(
    const std::string& message,
    const std::string& file,
    const std::string& objectPath
)
:
    std::runtime_error
    (
        message + " [file '" + file + "'"
      + (objectPath.empty() ? std::string() : ", object '" + objectPath + "'") + "]"
    ),
    file_(file),
    objectPath_(objectPath)
{}

} // namespace sdf::io

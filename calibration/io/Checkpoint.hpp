// Checkpoints for resuming a DEM run: a flat set of named arrays and scalar
// attributes, written atomically (a crash while writing leaves the previous
// checkpoint intact) and read back bit for bit.
//
// What goes in is the caller's choice; a DEM run typically stores positions,
// velocities, angular velocities (matrices N x 3), species (int64 vector),
// the tangential contact history (pair keys as int64, springs as N_c x 3),
// step, time, the RNG state (string, from operator<<), and the correlators'
// accumulated sums.
#ifndef sdf_io_Checkpoint_hpp
#define sdf_io_Checkpoint_hpp

#include <Eigen/Dense>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace sdf::io
{

struct Checkpoint
{
    std::map<std::string, double> scalars;
    std::map<std::string, std::int64_t> integers;
    std::map<std::string, std::string> strings;
    std::map<std::string, std::vector<double>> vectors;
    std::map<std::string, std::vector<std::int64_t>> integerVectors;
    std::map<std::string, Eigen::MatrixXd> matrices;

    bool operator==(const Checkpoint& other) const;
};

//- Group of a checkpoint inside its file.
inline constexpr const char* checkpointGroup = "checkpoint";

//- Writes path atomically (via path.tmp). Names must be unique across the
//  three scalar maps and across the three array maps; throws otherwise.
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);

//- Reads a checkpoint written by writeCheckpoint; Hdf5Error / ForeignFileError
//  naming the file if it is missing, corrupt, foreign or has no checkpoint.
Checkpoint readCheckpoint(const std::string& path);

} // namespace sdf::io

#endif

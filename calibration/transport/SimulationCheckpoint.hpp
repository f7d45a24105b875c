#ifndef sdf_dem_SimulationCheckpoint_hpp
#define sdf_dem_SimulationCheckpoint_hpp

// Checkpoint files of a DEM run (HDF5 through io/Checkpoint: written atomically, read back
// bit for bit). Restoring into a Simulation built with the same species and settings
// continues the run bitwise.

#include "Simulation.hpp"

#include "io/Checkpoint.hpp"

#include <string>

namespace sdf::dem
{

void writeSimulationCheckpoint(const std::string& path, const Simulation& simulation);

//- The simulation's state as entries of a checkpoint (names prefixed "particles_",
//  "pairs_", and time, shearOffset, stepCount, format), to combine with other state.
void addSimulationState(io::Checkpoint& checkpoint, const Simulation& simulation);
void loadSimulationState(const io::Checkpoint& checkpoint, Simulation& simulation, const std::string& source);

//- Reads the checkpoint and imports it; throws (naming the file) if it is missing, foreign
//  or does not fit the simulation.
void readSimulationCheckpoint(const std::string& path, Simulation& simulation);

} // namespace sdf::dem

#endif

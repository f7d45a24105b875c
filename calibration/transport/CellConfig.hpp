#ifndef sdf_dem_CellConfig_hpp
#define sdf_dem_CellConfig_hpp

// The key = value files of the command-line drivers (apps/periodicDEM-cli.cpp,
// apps/kineticSievingCell.cpp): '#' starts a comment, command-line pairs override the
// file, every key is checked against the driver's valid keys. The cell's own keys (its
// scalar settings from CellSettings.hpp, species, volumeFractions, model, pairs, mode,
// progressEvery, label) are read into a CellRunSettings here, once for both drivers.

#include "CellRun.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace sdf::dem
{

using CellConfig = std::map<std::string, std::string>;

//- The keys cellRunSettingsFrom reads: the scalar settings and the cell's other keys.
std::set<std::string> cellConfigKeys();

//- Reads path, then the arguments argv[first..argc) as key=value overrides; throws
//  std::invalid_argument naming the file and line (or argument) for a line that is not
//  key = value or a key not in validKeys (listing them), std::runtime_error for an
//  unreadable file.
CellConfig readCellConfig
(
    const std::string& path,
    int argc,
    char** argv,
    int first,
    const std::set<std::string>& validKeys
);

//- The number under key (fallback if absent); throws naming the entry if not a number.
double configNumber(const CellConfig& config, const std::string& key, double fallback);

//- The text under key, or fallback.
std::string configText(const CellConfig& config, const std::string& key, const std::string& fallback);

//- Throws std::invalid_argument for the first of keys present in config: "entry 'key' is
//  not used by <cell>: <reason>" (a driver whose own settings decide what those keys would).
void refuseKeys
(
    const CellConfig& config,
    const std::vector<std::string>& keys,
    const std::string& cell,
    const std::string& reason
);

//- The drivers that take the last species for the coarse one: throws naming 'species'
//  unless it is the largest (strictly, or at least as large when equalAllowed).
void requireCoarseLast(const CellRunSettings& settings, bool equalAllowed);

//- The cell described by config (species name:diameter:density ..., volumeFractions,
//  mode (default thermostatted), model, pairs, progressEvery, label and every scalar
//  setting); throws std::invalid_argument naming the entry.
CellRunSettings cellRunSettingsFrom(const CellConfig& config);

} // namespace sdf::dem

#endif

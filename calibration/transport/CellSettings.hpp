#ifndef sdf_dem_CellSettings_hpp
#define sdf_dem_CellSettings_hpp

// The scalar settings of a DEM cell, described once. The periodicDEM-cli keys
// (apps/periodicDEM-cli.cpp), the OpenFOAM dictionary entries (run controls and the
// `contact` sub-dictionary: src/calibratedModels/demDictionary/demDictionary.H), the
// cell file's /inputs attributes (CellRunHdf5.cpp) and the calibration store's settings
// key (store/Store.cpp) are all generated from this table, so they cannot drift apart:
// a new scalar setting is one line in cellSettings(). Settings that are not one number
// (species, volume fractions, mode, contact model, per-pair constants, file names) are
// read by hand in each place.

#include "CellRun.hpp"

#include <string>
#include <vector>

namespace sdf::dem
{

struct CellSetting
{
    //- Where an OpenFOAM dictionary holds it: condition (set per calibration condition,
    //  or at the top of system/periodicDEMDict), runControl (the top level of
    //  calibrationDict and periodicDEMDict), contact (their `contact` sub-dictionary).
    enum class Scope { condition, runControl, contact };

    const char* name;          // CLI key, dictionary keyword and /inputs attribute
    Scope scope;
    bool integer;
    //- Its label in the store's settings key; nullptr: not part of the key (a setting of
    //  the condition, or one that does not change the physics, e.g. threads).
    const char* fingerprint;
    //- Required in an OpenFOAM dictionary (the CLI requires nothing: defaults of
    //  CellRunSettings; runCell refuses what is missing).
    bool required;
    double (*get)(const CellRunSettings&);
    void (*set)(CellRunSettings&, double);
};

//- All scalar settings, in the order of the store's settings key.
const std::vector<CellSetting>& cellSettings();

//- The setting called name, or nullptr.
const CellSetting* findCellSetting(const std::string& name);

//- Names of the settings of one scope (the valid entries of a dictionary).
std::vector<std::string> cellSettingNames(CellSetting::Scope scope);

//- Throws std::invalid_argument naming the entry when v cannot be the setting's value:
//  not finite, or for an integer setting not a whole number in [0, 2^31) (the seed:
//  [0, 2^53), what a double holds exactly).
void checkCellSettingValue(const CellSetting& setting, double v);

//- Sets the setting `name` from text, refusing what is not a number (or, for an integer
//  setting, not a whole number in range) with a message naming the entry. False: no such
//  setting.
bool setCellSetting(CellRunSettings& settings, const std::string& name, const std::string& text);

//- The value as text: integers as integers, reals with %.10g (the store's key format).
std::string cellSettingText(const CellSetting& setting, const CellRunSettings& settings);

} // namespace sdf::dem

#endif

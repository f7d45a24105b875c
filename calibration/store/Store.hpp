// The calibration store constant/calibration.h5: one group per finished DEM
// condition, written by calibrateGranularMixture and by the calibrated
// models' runDEM policy, read by both and by the tabulated models. One
// definition of the layout, so that each writer recognises the other's
// conditions:
//
//   /                        attributes format, formatVersion (sdf::io),
//                            content = contentName, fineSpecies, coarseSpecies
//   /conditions/<name>       one group per condition, <name> = conditionName()
//                            attributes phi x seed particles settingsKey and
//                            targetT (driven cells) or gammaDot (sheared cells)
//                            (inputs), T TError equilibrated equilibrationTime
//                            timeStep boxLength steps, savageJeffreyR (sheared
//                            cells) (results)
//   /conditions/<name>/species/<species>
//                            role (fine | coarse), d, count, T, D, DError,
//                            DPlateauFound, DMsd, DMsdError, eta, etaError,
//                            etaWithCrossTerms, etaWithCrossTermsError
//   /conditions/<name>/species/<species>/diffusiveRegime
//                            the diffusive-regime check of D (dem::writeDiffusiveRegime:
//                            converged, verdict, correlationTime, fitStart, fitEnd,
//                            slopes and differences with errors, the items' flags);
//                            absent in stores written before the check existed
//   /conditions/<name>/collisions
//                            attributes elapsedTime [s] (over which collisions were
//                            counted), impactEnergy (its definition); dataset
//                            binEdges [J] (nBins + 1, log-spaced, pair impact energy
//                            E = 0.5 m* v_n^2 at the first step of a contact)
//   /conditions/<name>/collisions/<a>/<b>
//                            one group per unordered species pair, a <= b in the
//                            cell's species order (fine/fine, fine/coarse,
//                            coarse/coarse): attributes count, energySum [J];
//                            int64 dataset histogram (nBins + 2: under, bins, over)
//   /conditions/<name>/rheology
//                            pressure-controlled cells of a rheology calibration (inputs:
//                            targetInertialNumber on the condition): dem::writeRheology's
//                            attributes (targetPressure, meanDiameter, solidsDensity, the
//                            estimates with <name>Error, steady, regime); only steady dense
//                            flows are stored
//   /conditions/<name>/segregation
//                            sheared cells under gravity of a segregation calibration
//                            (inputs: normalStress on the condition; no species groups,
//                            no T): the interior's SegregationRecord as attributes, the
//                            wall's load and speed among them; only cells at their
//                            condition (SegregationMeasurement::unreachedState) are stored
//   /conditions/<name>/timing
//                            wallSeconds cpuSeconds particleStepsPerSecond (the
//                            only values that differ between identical runs)
//
// Every write is atomic (sdf::io::AtomicFile: a copy is written and renamed
// over the store), so a killed run leaves every condition it finished.
// Failures throw StoreError naming the file.
#ifndef sdf_store_Store_hpp
#define sdf_store_Store_hpp

#include "CellRun.hpp"
#include "GravityShearRun.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sdf::io
{
class Group;
}

namespace sdf::store
{

//- Root attribute `content` of a calibration store.
inline constexpr const char* contentName = "calibrateGranularMixture conditions";

//- A failure to use a file as a calibration store; what() names the file.
class StoreError : public std::runtime_error
{
public:
    StoreError(const std::string& file, const std::string& message);

    const std::string& file() const { return file_; }
    //- What went wrong, without the file name
    const std::string& message() const { return message_; }

private:
    std::string file_;
    std::string message_;
};

//- A condition stored with DEM settings other than the current ones.
class SettingsMismatch : public StoreError
{
public:
    SettingsMismatch
    (
        const std::string& file,
        const std::string& condition,
        const std::string& storedKey,
        const std::string& currentKey
    );

    const std::string& storedKey() const { return storedKey_; }
    const std::string& currentKey() const { return currentKey_; }
    //- What the current key adds at its end when the stored one is its beginning
    //  (a store written before a measurement changed: the settings are the same,
    //  the conditions must be rerun); empty otherwise.
    std::string addedSinceStored() const;

private:
    std::string storedKey_;
    std::string currentKey_;
};

//- Throws std::runtime_error unless root is the root group of a calibration
//  store (a file of ours with another content, e.g. a periodicDEM result, is
//  refused).
void checkIsStore(const io::Group& root);

//- Group name of a condition, e.g. phi0.3_x0.4_T0.01_seed1 (%.6g values).
std::string conditionName(double phi, double x, double T, std::int64_t seed);

//- Group name of a sheared condition, e.g. phi0.5_x0.4_gammaDot20_seed1.
std::string shearedConditionName(double phi, double x, double gammaDot, std::int64_t seed);

//- Group name of a pressure-controlled rheology cell, e.g. rheology_I0.01_p1000_x0.5_seed1.
std::string rheologyConditionName
(
    double inertialNumber,
    double pressure,
    double x,
    std::int64_t seed
);

//- Group name of a sheared cell under gravity, e.g. segregation_sigma368_x0.5_seed1.
std::string segregationConditionName(double normalStress, double x, std::int64_t seed);

//- Group name of one cell size of a finite-size calibration: name + "_N<particles>",
//  e.g. phi0.3_x0.4_T0.01_seed1_N300.
std::string sizedConditionName(const std::string& name, std::int64_t particles);

//- Fingerprint of the DEM settings (everything but the condition): a stored
//  condition is reused only if it was run with the same settings.
std::string settingsKey(const dem::CellRunSettings& settings, const std::string& contactModel);

//- What identifies one condition of the envelope.
struct ConditionInputs
{
    std::string name;
    double phi = 0;
    double x = 0;
    double targetT = 0;                  // driven cells (gammaDot absent)
    std::optional<double> gammaDot;      // sheared cells [1/s] (targetT unused)
    std::optional<double> inertialNumber;   // rheology cells: the I they are sheared at
    std::optional<double> normalStress;     // sheared cells under gravity: sigma_N [Pa]
    std::int64_t seed = 0;
};

//- Appends one finished condition to the store at path, atomically; a new
//  store gets the root attributes (content and the species names).
void appendCondition
(
    const std::string& path,
    const std::string& fineSpecies,
    const std::string& coarseSpecies,
    const std::string& settingsKey,
    const ConditionInputs& inputs,
    const dem::CellRunResult& result
);

//- What the segregation fit reads back of a sheared cell under gravity
//  (dem::SegregationMeasurement as stored, with the wall's load and speed).
struct SegregationRecord
{
    double normalStress = 0, wallSpeed = 0;     // [Pa], [m/s]
    double fineDiameter = 0, sizeRatio = 0, meanDiameter = 0;
    double solidsFraction = 0, pressureNumber = 0, inertialNumber = 0;
    double early = 0, earlyError = 0, earlyCoarseShare = 0, earlyShearRate = 0;
    double balance = 0, balanceError = 0, coarseShare = 0;
    double shearRate = 0, shearRateError = 0;
    double diffusivity = 0, diffusivityError = 0;
    double shearRateDiffusivity = 0, shearRateDiffusivityError = 0;
    double diffusiveShare = 0, topWallLoad = 0;
};

//- The record of a run (its settings' load and speed, its measurement)
SegregationRecord segregationRecordOf(const dem::GravityShearRunResult& result);

//- Appends one finished sheared cell under gravity to the store at path, atomically (as
//  appendCondition): the group `segregation` with its SegregationRecord, and timing.
void appendSegregationCondition
(
    const std::string& path,
    const std::string& fineSpecies,
    const std::string& coarseSpecies,
    const std::string& settingsKey,
    const ConditionInputs& inputs,
    const dem::GravityShearRunResult& result
);

//- Settings keys of the conditions in the store, by condition name; empty if
//  there is no file. Throws StoreError if the file is not a calibration store
//  of ours (corrupt, truncated, foreign); the file is left untouched.
std::map<std::string, std::string> storedSettingsKeys(const std::string& path);

//- Whether condition `name` is among `stored` (storedSettingsKeys of the
//  store at path); throws SettingsMismatch if it was run with settings other
//  than `key`: a stored condition is reused only with the same settings.
bool isStored
(
    const std::string& path,
    const std::map<std::string, std::string>& stored,
    const std::string& name,
    const std::string& key
);

//- What the fits and the tables read back of a species of a condition.
struct SpeciesRecord
{
    std::optional<std::int64_t> count;   // particles of the species in the cell
    double D = 0;
    std::optional<double> DError;
    std::optional<double> DMsd;
    std::optional<double> DMsdError;
    //- The diffusive-regime check (absent in older stores): converged, its verdict,
    //  the change of the MSD's slope over the window (late - early half) and the drift
    //  of D over the run (later blocks - earlier blocks).
    std::optional<bool> DConverged;
    std::string DVerdict;
    double DSlopeChange = 0;
    double DDrift = 0;
    //- the Einstein window's start and tau_v [s]; whether it starts past 5 tau_v
    double DFitStart = 0;
    double DCorrelationTime = 0;
    bool DWindowPastDecay = true;
    std::optional<double> eta;        // engine units (kg^2 m s^-3), the seed's rule
    std::optional<double> etaError;
    //- the stress ACF's cross terms kept (absent in stores written before)
    std::optional<double> etaWithCrossTerms;
    std::optional<double> etaWithCrossTermsError;
};

//- Collisions of one unordered species pair of a condition (for breakage rates).
struct PairCollisionRecord
{
    std::string first;                    // species names, first <= second in the
    std::string second;                   // cell's species order
    std::int64_t count = 0;               // collisions counted
    double energySum = 0;                 // sum of their impact energies [J]
    std::vector<std::int64_t> histogram;  // binEdges.size() + 1 slots: under, bins, over
};

//- The collision statistics of a condition (dem::CollisionStatistics as stored).
struct CollisionRecord
{
    double elapsedTime = 0;               // [s]
    std::vector<double> binEdges;         // pair impact energy E = 0.5 m* v_n^2 [J]
    std::vector<PairCollisionRecord> pairs;

    //- The pair of species a and b, in either order; nullptr if not stored.
    const PairCollisionRecord* pair(const std::string& a, const std::string& b) const;
    //- Collisions per unit time of one particle of species `of` with particles of
    //  species `with`, countOf being the particles of `of` in the cell (a collision
    //  within one species involves two of its particles). Throws std::invalid_argument
    //  if the pair is not stored or countOf <= 0; 0 if elapsedTime is 0.
    double frequencyPerParticle
    (
        const std::string& of,
        const std::string& with,
        std::int64_t countOf
    ) const;
};

//- What the rheology fit reads back of a pressure-controlled cell (steady dense flow).
struct RheologyRecord
{
    double targetInertialNumber = 0;
    double targetPressure = 0;        // [Pa]
    double meanDiameter = 0;          // d of I [m]
    double solidsDensity = 0;         // rho_s of I [kg/m3]
    double inertialNumber = 0, inertialNumberError = 0;
    double stressRatio = 0, stressRatioError = 0;
    double solidsFraction = 0, solidsFractionError = 0;
    double pressure = 0, pressureError = 0;         // sigma_yy [Pa]
    double coordinationNumber = 0;
    std::string regime;
};

//- What the fits and the tables read back of one condition.
struct ConditionRecord
{
    std::string name;
    double phi = 0;
    double x = 0;
    double targetT = 0;               // driven cells; 0 in sheared ones
    std::optional<double> gammaDot;   // sheared cells: the imposed shear rate [1/s]
    double T = 0;                     // measured
    std::int64_t particles = 0;       // the cell's size (0: not recorded)
    //- Sheared cells: d_mean gammaDot sqrt(3/T) (the seed's eq 7 solved for R)
    std::optional<double> savageJeffreyR;
    SpeciesRecord fine;
    SpeciesRecord coarse;
    //- Absent in conditions stored before the collisions were (their settings key is
    //  the same: the binning follows from the species and targetT, both in the key or
    //  the name, so such a condition is reused, not rerun).
    std::optional<CollisionRecord> collisions;
    //- Rheology cells only (pressure-controlled); the transport fits and tables skip them
    std::optional<RheologyRecord> rheology;
    //- Sheared cells under gravity only (no species, no T); the other fits skip them
    std::optional<SegregationRecord> segregation;
};

struct StoreContents
{
    std::string fineSpecies;
    std::string coarseSpecies;
    std::vector<ConditionRecord> conditions;   // sorted by name
};

//- Reads the whole store. Throws StoreError (file named) if it is missing,
//  not a calibration store, or a condition lacks phi, x, targetT (or gammaDot), T or the
//  fine species' D.
StoreContents readStore(const std::string& path);

//- Writes a text file atomically (to <path>.tmp, renamed over path); throws
//  StoreError on failure.
void writeTextAtomically(const std::string& path, const std::string& text);

} // namespace sdf::store

#endif

#ifndef sdf_transport_GravityShearRun_hpp
#define sdf_transport_GravityShearRun_hpp

// A run of the sheared cell under gravity (dem/GravityShear.hpp) and what it measures: the
// grains start mixed, the top wall slides under its load, the cell records how the coarse
// species rises (the early drift) and, after the development, the profiles across the
// layer per block, from which the flux balance gives the segregation velocity. One run
// for its two users: apps/gravityShearCell (the text files) and calibrateGranularMixture
// (the calibration store), so that a calibrated law is the cell's own measurement.
//
// The segregation velocity is read as the percolation length S of
// w_coarse = S gammaDot (1 - c) over the interior layers (two coarse diameters from either
// wall), by two estimators:
// - early: the drift of the mixed start, sum w / sum gammaDot (1 - c) over 5 windows from
//   driftStartStrain to driftEndStrain;
// - balance: the sampled profile's flux balance c w_seg = c w + D dc/dy per block (w the
//   coarse drift measured, D from the displacements over diffusionStrain), summed over the
//   interior and divided by sum gammaDot c (1 - c); with the share the diffusive term
//   carries (1 at steady state, where w = 0; near 0 in a mixed layer, where the balance is
//   the drift itself).

#include "CellRun.hpp"
#include "GravityShear.hpp"

#include "correlation/Statistics.hpp"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace sdf::dem
{

struct GravityShearRunSettings
{
    //- The grains, contact law and run controls (mode, temperature, shearRate and the
    //  barostat are not used: the walls set the flow); equilibrationTime is the whole
    //  development before the sampling
    CellRunSettings cell;
    GravityShearSettings walls;
    double heightRatio = 3;          //- the packing's height over its width
    double wallThickness = 1.5;      //- each wall's thickness [coarse diameters]
    int layers = 10;                 //- layers across the flowing layer
    double driftStartStrain = 2;     //- the early drift is read from this strain U t/gap
    double driftEndStrain = 0;       //- ... up to this one; 0: the development's end
    double diffusionStrain = 2;      //- the lag of D's displacements [strains U/gap]
    std::string lammpsData;          //- if set: the cell as cut written for a LAMMPS peer
};

//- Throws std::invalid_argument naming the entry, before the packing (which takes
//  seconds): the walls' settings, two species with the coarse last, layers in [2, 1000],
//  the walls at least 10 coarse diameters apart, wallSpeed > 0, the strains, two
//  interior layers and the early drift's window within the development (on the
//  packing's gap: the run checks them again on the cut cell's).
void validateGravityShearRunSettings(const GravityShearRunSettings& settings);

//- The percolation length of the interior and the conditions it was read at.
struct SegregationMeasurement
{
    double fineDiameter = 0;         //- [m]
    double sizeRatio = 0;            //- d_coarse/d_fine
    double meanDiameter = 0;         //- the solids' volume-weighted mean at the start [m]
    double solidsFraction = 0;       //- the interior's phi over the sampling
    //- p* = sigma_yy/(rho_s g dMean) of the interior, weighted as the balance weighs its
    //  layers (gammaDot c (1 - c)), with each layer's own dMean
    double pressureNumber = 0;
    double inertialNumber = 0;
    correlation::Estimate early;     //- S of the early drift [m]
    double earlyCoarseShare = 0;     //- c, gammaDot and w over its windows
    double earlyShearRate = 0;
    double earlyDrift = 0;
    correlation::Estimate balance;   //- S of the flux balance [m]
    double coarseShare = 0;          //- c over the sampling, weighted as p*
    correlation::Estimate shearRate; //- gammaDot over the sampling [1/s]
    correlation::Estimate diffusivity;   //- D of all grains along gravity [m2/s]
    correlation::Estimate shearRateDiffusivity;  //- C = D/(gammaDot dMean^2)
    double diffusiveShare = 0;       //- the mean share of the balance D dc/dy carries
    double topWallLoad = 0;          //- the top wall's mean load over the sampling / sigma_N
    //- The top wall's sliding strain U t/gap since it landed, when the early drift's
    //  windows started and when the sampling started
    double slidingStrainAtDrift = 0, slidingStrainAtSampling = 0;
    std::vector<double> earlyWindows, balanceBlocks, diffusiveShares;

    //- Whether the top wall carried its load (within 5 %): else the cell was not at the
    //  condition asked for
    bool loaded() const;

    //- Whether the top wall had finished its ramp (slid one strain) before the early
    //  drift's windows: else they were read in a flow still starting
    bool slidingBeforeDrift() const { return slidingStrainAtDrift >= 1; }

    //- Whether the interior's I is below the dense regime's floor (the rheology cell's
    //  RheologyResult::minimumInertialNumber, one floor for both): a quasi-static layer
    //  whose shear localises, where the law w = S gammaDot (1 - c) only says that the
    //  drift vanishes with gammaDot, and S is not read
    bool quasiStatic() const { return inertialNumber < RheologyResult::minimumInertialNumber; }

    //- All three: the cell reached the state its estimators read (a calibration stores
    //  no other); what is missing, or empty
    std::string unreachedState() const;
};

//- The profile columns, per layer (block means and block standard errors).
enum GravityShearColumn
{
    phiColumn, coarseColumn, velocityColumn, sigmaYYColumn, sigmaXYColumn,
    coarseDriftColumn, fineDriftColumn, fineDiffusivityColumn, coarseDiffusivityColumn,
    diffusivityColumn, nGravityShearColumns
};

struct GravityShearRunResult
{
    GravityShearRunSettings settings;
    std::size_t grains = 0;          //- all grains, the walls' included
    double boxLength = 0, boxDepth = 0;   //- the periodic extents along x and z [m]
    double gap = 0;                  //- the walls' mean distance over the sampling [m]
    double timeStep = 0;
    double developmentTime = 0, blockTime = 0, diffusionLag = 0;   //- [s]
    int interiorFirst = 0, interiorLast = -1;
    //- t, gap, the top and bottom walls' stresses (means since the last row), the coarse
    //  and fine centres' heights above the bottom wall and their difference in coarse
    //  diameters
    std::vector<std::array<double, 7>> series;
    //- [layer][column]
    std::vector<std::array<correlation::Estimate, nGravityShearColumns>> profiles;
    SegregationMeasurement segregation;
    double wallSeconds = 0, cpuSeconds = 0;
};

//- Runs the cell (validateGravityShearRunSettings first). Throws std::runtime_error if the
//  interior was not sheared (the top wall had not landed, or not started sliding) or the
//  cell stopped being finite; std::invalid_argument for bad settings.
//  log: where the cell's one-line description goes (nullptr: nowhere); the engine's
//  progress follows cell.progressEvery.
GravityShearRunResult runGravityShearCell
(
    const GravityShearRunSettings& settings,
    std::ostream* log = nullptr
);

//- <prefix>-series.dat, -profiles.dat and -segregation.dat (text, a header line per
//  column; the segregation file's `interior` line is what fitSegregationVelocity reads).
//  Throws std::runtime_error if a file cannot be written.
void writeGravityShearFiles(const GravityShearRunResult& result, const std::string& prefix);

//- One line: both estimators, the diffusive share, C and the top wall's load.
std::string gravityShearSummary(const SegregationMeasurement& s);

} // namespace sdf::dem

#endif

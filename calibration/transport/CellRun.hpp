#ifndef sdf_dem_CellRun_hpp
#define sdf_dem_CellRun_hpp

// One calibration cell from start to finish: packing, equilibration (detected from the
// granular temperature), sampling of per-species velocity autocorrelations (multiple-tau,
// many time origins, block errors), mean-square displacements, the stress split
// J^1, J^2, J^12 (xy components) and their nine product correlations, collision
// statistics. Green-Kubo and Einstein estimates come from sdf_correlation.
// Where things are: the run in CellRun.cpp, its measurements in Measurements.hpp (one
// interface: Measurement.hpp), the HDF5 file in CellRunHdf5.cpp, the summary and the
// LAMMPS data file in CellRunOutput.cpp, checkpoints of a Simulation in
// SimulationCheckpoint.hpp.

#include "InitialState.hpp"
#include "Simulation.hpp"

#include "correlation/DiffusiveRegime.hpp"
#include "correlation/GreenKubo.hpp"
#include "correlation/StressGreenKubo.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace sdf::io
{
class Group;
}

namespace sdf::dem
{

struct CellRunSettings
{
    std::vector<Species> species;
    std::vector<double> volumeFractions;   // solids volume fraction of each species (sum 1)
    int particles = 1000;
    double solidsFraction = 0.3;
    SimulationSettings simulation;         // contact law, dt, mode, target T, shear rate
    double initialTemperature = -1;        // < 0: target T, or (gammaDot d_mean)^2 if sheared
    double equilibrationTime = 0;          // [s] minimum equilibration
    double maxEquilibrationTime = 0;       // [s] 0: 5 x equilibrationTime
    double samplingTime = 0;               // [s]
    int sampleEvery = 10;                  // steps between correlator samples
    int blocks = 8;                        // independent blocks for the errors
    int maxMsdFrames = 2000;               // stored position frames for the MSD
    std::uint64_t seed = 1;
    long progressEvery = 0;                // steps between progress lines (0: quiet)
    std::string label = "periodicDEM";
    //- If set: the initial state (after packing and velocities) is also written as a
    //  LAMMPS data file (atom_style sphere, triclinic box) for peer comparisons.
    std::string lammpsDataFile;
    //- If set: measurements are skipped, the cell only runs (throughput benchmarks);
    //  T is still sampled every sampleEvery steps.
    bool throughputOnly = false;
    //- With throughputOnly: > 0 runs the equilibrated state for samplingTime with 1 thread
    //  and with simulation.threads threads, alternately, this many rounds (both from the
    //  same state, side by side in one process: a thread speed-up on a shared machine).
    int threadScalingRounds = 0;
    //- Checkpoints during sampling (HDF5): the simulation, the correlators,
    //  series, MSD frames and collision counts are written to checkpointFile every
    //  checkpointEvery steps (rounded to whole samples); resume = true continues from it
    //  (same settings) and gives bit for bit the result of an uninterrupted run.
    std::string checkpointFile;
    long checkpointEvery = 0;
    bool resume = false;
    //- Testing aid: stop the sampling after this many steps (after a checkpoint).
    long stopAfterSteps = 0;
};

//- LAMMPS data file (atom_style sphere: id type diameter density x y z; velocities).
//  streamingShift is added to vx (LAMMPS' deforming box streams as u = gammaDot (y - ylo),
//  ours as gammaDot (y - ly/2)).
void writeLammpsData
(
    const std::string& path,
    const Particles& particles,
    const PeriodicBox& box,
    const std::vector<Species>& species,
    double streamingShift = 0
);

//- Throws std::invalid_argument naming the entry.
void validateCellRunSettings(const CellRunSettings& settings);

//- Mean diameter of the species weighted by their solids volume fractions.
double meanDiameter(const CellRunSettings& settings);

//- Mean density of the species weighted by their solids volume fractions (rho_s of I).
double solidsDensity(const CellRunSettings& settings);

//- settings sheared at inertial number I at its targetPressure p (a rheology cell): mode
//  leesEdwards, gammaDot = I sqrt(p/rho_s)/d with d and rho_s as the cell measures I
//  (meanDiameter, solidsDensity), the run lengths given in strain (time = strain/gammaDot).
CellRunSettings atInertialNumber
(
    CellRunSettings settings,
    double inertialNumber,
    double equilibrationStrain,
    double maxEquilibrationStrain,
    double samplingStrain
);

//- The cell's packing at its solids fraction with Maxwellian velocities at T0 (at
//  equipartition for a stochastically driven cell, InitialState.hpp; plus the
//  streaming profile if sheared); also written as a LAMMPS data file if
//  settings.lammpsDataFile is set. runCell's start; other drivers of a Simulation
//  (apps/kineticSievingCell.cpp) start from it too.
Packing initialCell(const CellRunSettings& settings, double T0);

//- A wall-bounded or forced cell's schedule in steps of dt: samples every sampleEvery
//  (at least 1) steps, the development (equilibrationTime) and blocks of whole samples
//  (samplingTime/blocks, at least one sample); seriesEvery: a series row every that many
//  steps, on the samples' grid, about `rows` rows over the run
struct SampledSchedule
{
    long sampleEvery = 1, equilibrationSteps = 0, blockSteps = 1, seriesSamples = 1, seriesEvery = 1;
};
SampledSchedule sampledSchedule(const CellRunSettings& settings, double dt, long rows);

struct SpeciesTransport
{
    std::string name;
    int count = 0;
    double temperature = 0;                       // <|c|^2> over the sampling
    double temperatureError = 0;                  // its block standard error
    correlation::GreenKuboResult greenKubo;       // D from the VACF (per component)
    correlation::Estimate diffusivityMsd;         // Einstein slope, block error
    std::vector<double> msdTimes, msd;            // mean MSD (per component)
    //- Green-Kubo and MSD in the diffusive regime? (not run: converged() false,
    //  correlationTime 0)
    correlation::DiffusiveRegimeCheck diffusiveRegime;
};

//- The cell's rheology (sheared cells): block means of the stresses, the solids fraction
//  and the contacts; mu and I per block from the block's means, errors from the blocks.
struct RheologyResult
{
    bool measured = false;
    bool pressureControlled = false;
    double targetPressure = 0;             // [Pa] (pressure-controlled)
    double barostatTime = 0;               // tau_p [s] (pressure-controlled)
    double meanDiameter = 0;               // d of I: solids-volume weighted mean [m]
    double solidsDensity = 0;              // rho_s of I: solids-volume weighted [kg/m3]
    correlation::Estimate pressure;        // sigma_yy [Pa] (kinetic + contact, compressive > 0)
    correlation::Estimate shearStress;     // |sigma_xy| [Pa]
    correlation::Estimate stressRatio;     // mu = |sigma_xy|/sigma_yy
    correlation::Estimate inertialNumber;  // I = |gammaDot| d/sqrt(sigma_yy/rho_s)
    correlation::Estimate solidsFraction;  // phi
    correlation::Estimate coordinationNumber;      // Z = 2 contacts/N
    correlation::Estimate meanOverlapFraction;     // <delta/(R_i + R_j)> over the contacts
    correlation::Estimate bondOrder;       // Q6 of the contacts (Simulation::ContactSummary)
    //- Steady: the first and second halves of the blocks agree in phi and mu within 3
    //  combined standard errors or within 1e-3 (phi) and 5e-3 (mu); steadyCheck says by
    //  how much
    bool steady = false;
    std::string steadyCheck;
    //- "dense flow", "jammed" (I below minimumInertialNumber: quasi-static, no inertial
    //  rheology to measure), "gas" (I above maximumInertialNumber or Z below 1: outside
    //  the dense regime) or "ordered" (Q6 above maximumBondOrder: crystallised);
    //  regimeReason: the figures that decided
    std::string regime;
    std::string regimeReason;
    static constexpr double minimumInertialNumber = 1e-4;
    static constexpr double maximumInertialNumber = 1.0;
    //- Q6 above which a cell of N grains with Z contacts each is ordered: 0.25, between a
    //  disordered cell's (about 1/sqrt(bonds): 0.05-0.09 at 200 grains) and a crystallised
    //  one's (0.26-0.38; a perfect crystal 0.48-0.57), and in a cell so small that
    //  disorder reads high, 4/sqrt(Z N/2)
    //  (docs/validation.md, "Crystallised cells")
    static double maximumBondOrder(double Z, int particles)
    {
        const double bonds = 0.5*Z*double(particles);
        return bonds > 0 ? std::max(0.25, 4/std::sqrt(bonds)) : 0.25;
    }
    bool denseSteadyFlow() const { return measured && steady && regime == "dense flow"; }
};

struct CellRunResult
{
    CellRunSettings settings;
    double timeStep = 0;
    double boxLength = 0;
    double meanDiameter = 0;               // solids-volume weighted
    double temperature = 0;                // mixture <|c|^2> over the sampling
    double temperatureError = 0;           // block standard error
    double savageJeffreyR = 0;             // d_mean gammaDot sqrt(3/T) (sheared cells)
    bool equilibrated = false;
    double equilibrationTime = 0;
    std::vector<SpeciesTransport> species;
    //- diffusion component: -1 isotropic mean (homogeneous cells), 1 = y (sheared cells)
    int diffusionComponent = -1;
    // stress: series s_k = J_xy^k / sqrt(V), k over species parts then cross parts
    std::vector<std::string> stressSeriesNames;
    std::vector<double> meanStress;        // time mean of J_xy^k / V [Pa]
    correlation::StressProductIntegrals stressIntegrals;
    std::vector<correlation::Estimate> kineticSieving;   // binary mixtures only: the seed's rule
    //- the same with the stress ACF's cross terms kept (kineticSievingCoefficientsWithCrossTerms)
    std::vector<correlation::Estimate> kineticSievingWithCrossTerms;
    CollisionStatistics collisions;
    //- Kinetic energy of the longest-wavelength modes of the momentum density over
    //  equipartition (1: no collective motion), transverse (shear) and longitudinal
    //  components; block mean and error (Measurements.hpp CollectiveMotionMeasurement)
    correlation::Estimate collectiveMotionTransverse;
    correlation::Estimate collectiveMotionLongitudinal;
    RheologyResult rheology;
    std::vector<int> speciesCounts;
    bool interrupted = false;              // stopped by stopAfterSteps: results incomplete
    bool resumed = false;                  // continued from a checkpoint
    long steps = 0;
    double wallSeconds = 0;
    double cpuSeconds = 0;                 // process CPU time of the sampling (all threads)
    double particleStepsPerSecond = 0;     // per wall-clock second
    //- threadScalingRounds: per round, particle-steps per wall-clock second on 1 thread and
    //  on scalingThreads threads
    int scalingThreads = 0;
    std::vector<std::array<double, 2>> threadScaling;
};

CellRunResult runCell(const CellRunSettings& settings);

//- The diffusive-regime check as attributes of g (converged, verdict, correlationTime,
//  fitStart, fitEnd, the slopes and differences with their errors, the five items'
//  flags): the cell file's and the calibration store's.
void writeDiffusiveRegime(const io::Group& g, const correlation::DiffusiveRegimeCheck& check);

//- The rheology of a sheared cell as the group `rheology` of parent (nothing if not
//  measured): each estimate with its block standard error (<name>Error), the steady check
//  and the regime; the cell file's results/rheology and the calibration store's.
void writeRheology(const io::Group& parent, const RheologyResult& rheology);

//- Human-readable summary.
std::string summary(const CellRunResult& result);

//- Writes inputs, timings, T, R, D_i with errors, correlation functions, stress ACF terms
//  and collision statistics to an HDF5 file, atomically (written to <path>.tmp and renamed:
//  a failed run never leaves a half-written file under the final name). Layout: docs/developer/hdf5-layout.md.
void writeCellRun(const CellRunResult& result, const std::string& path);

} // namespace sdf::dem

#endif

// periodicDEM-cli: runs one periodic DEM cell from a key = value file and prints a summary
// (and writes HDF5 when output = file.h5 is given).
//
//   periodicDEM-cli cell.cfg [key=value ...]      command-line pairs override the file
//
// Keys (SI units; '#' starts a comment): the scalar settings of the cell, by the names of
// transport/CellSettings.cpp (particles, solidsFraction, temperature, shearRate,
// targetPressure (> 0 with mode leesEdwards: sigma_yy held there, calibration/dem/Barostat.hpp),
// seed; the contact constants restitution, friction, normalStiffness, tangentialStiffnessRatio,
// tangentialDampingRatio, youngsModulus, poissonRatio, rollingFriction, rollingStiffness,
// rollingDamping; the run controls barostatTime, timeStep (0: half
// the recommended maximum), thermostatTime, equilibrationTime, maxEquilibrationTime,
// samplingTime [s], sampleEvery [steps], blocks, threads, skin [m], maxOverlapFraction),
// and:
//   species          name:diameter:density [name:diameter:density ...]
//   volumeFractions  solids volume fraction of each species (default: equal)
//   mode             nve | thermostatted (default) | leesEdwards | stochastic
//   model            linearSpringDashpot | hertzMindlin
//   pairs            per species pair, first/second:key=value[:key=value ...] with keys
//                    restitution, friction, normalStiffness, rollingFriction (unset: the
//                    single values)
//   progressEvery [steps], output (HDF5 file), label
//   lammpsData (write the initial state as a LAMMPS data file), throughputOnly (1: no
//   measurements, only T; for speed comparisons), threadScalingRounds (with throughputOnly:
//   the equilibrated state run alternately on 1 and on `threads` threads, this many
//   rounds; prints the speed-ups), checkpointFile, checkpointEvery [steps],
//   resume (1: continue the sampling from checkpointFile, same settings)
#include "CellConfig.hpp"

#include <iostream>
#include <set>
#include <stdexcept>

using namespace sdf::dem;

namespace
{

//- The keys of this driver besides the cell's (CellConfig.hpp)
std::set<std::string> validKeys()
{
    std::set<std::string> keys = cellConfigKeys();
    keys.insert
    ({
        "output", "lammpsData", "throughputOnly", "threadScalingRounds", "checkpointFile",
        "checkpointEvery", "resume"
    });
    return keys;
}

CellRunSettings settingsFrom(const CellConfig& c)
{
    CellRunSettings s = cellRunSettingsFrom(c);
    s.lammpsDataFile = configText(c, "lammpsData", "");
    s.throughputOnly = configNumber(c, "throughputOnly", 0) != 0;
    s.threadScalingRounds = int(configNumber(c, "threadScalingRounds", 0));
    s.checkpointFile = configText(c, "checkpointFile", "");
    s.checkpointEvery = long(configNumber(c, "checkpointEvery", 0));
    s.resume = configNumber(c, "resume", 0) != 0;
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: periodicDEM-cli cell.cfg [key=value ...]\n";
        return 2;
    }
    try
    {
        const CellConfig config = readCellConfig(argv[1], argc, argv, 2, validKeys());
        const CellRunSettings settings = settingsFrom(config);
        const CellRunResult result = runCell(settings);
        std::cout << summary(result);
        const std::string output = configText(config, "output", "");
        if (!output.empty())
        {
            writeCellRun(result, output);
            std::cout << "written " << output << "\n";
        }
    }
    catch (const std::exception& err)
    {
        std::cerr << "periodicDEM-cli: error: " << err.what() << "\n";
        return 1;
    }
    return 0;
}

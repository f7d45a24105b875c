// gravityShearCell: plane shear under gravity between rough walls (dem/GravityShear.hpp),
// the cell in which gravity-driven size segregation is measured. The grains start mixed;
// the top wall slides at wallSpeed under normalStress; the cell records how the coarse
// species rises and, after equilibrationTime, the profiles across the layer per block.
//
//   gravityShearCell cell.cfg [key=value ...]      command-line pairs override the file
//
// Keys: those of the cell as for periodicDEM-cli (species, volumeFractions, particles:
// all grains, the walls' included; solidsFraction: of the packing the cell is cut from,
// the contact constants, model, pairs, timeStep, seed, threads, equilibrationTime,
// samplingTime, sampleEvery, blocks, progressEvery, label), and
//   gravity               g [m/s^2] along -y (default 9.81)
//   normalStress          the top wall's load sigma_N [Pa] (required)
//   wallSpeed             the top wall's speed U along x [m/s] (required)
//   heightRatio           the packing's height over its width (default 3)
//   wallThickness         each wall's thickness in coarse diameters (default 1.5)
//   profileRelaxationTime tau_u of the force holding the linear profile [s] (default 0: off)
//   layers                layers across the flowing layer for the profiles (default 10)
//   driftStartStrain      the early drift is read from this strain U t/gap of the
//                         development on (default 2: the flow has formed)
//   driftEndStrain        ... up to this strain (default: the development's end); the
//                         development goes on after it, so that a long run samples a
//                         developed profile after an early drift read in the first strains
//   diffusionStrain       the lag of the diffusivity's displacements, in strains U/gap
//                         (default 2: past the ballistic start, a fraction of a layer)
//   lammpsData            if set: the cell as cut (walls included, all at rest) written as a
//                         LAMMPS data file, for a peer (benchmarks/gravityShearVsLammps)
//   output                prefix of the output files (default gravityShearCell)
// The walls set the flow: mode, temperature, shearRate, thermostatTime, targetPressure,
// barostatTime and maxEquilibrationTime are refused. The flowing layer must be at least 10
// coarse diameters deep (the wall-affected layers are about two diameters each).
//
// Output (text, one header line per column):
//   <output>-series.dat    t, the gap, the top and bottom walls' stresses (means since
//                          the last line), the coarse and fine centres' heights above
//                          the bottom wall and their difference in coarse diameters
//   <output>-profiles.dat  per layer (block means, block standard errors): height,
//                          solids fraction, coarse share, u_x, sigma_yy and sigma_xy
//                          (Irving-Kirkwood slabs, kinetic part about the layer's mean
//                          velocity), the coarse and fine species' mean y velocities
//                          relative to the solids' volume-weighted mean, and the fine,
//                          the coarse and all grains' diffusivities D along y
//   <output>-segregation.dat  the percolation length S of w_coarse = S gammaDot (1 - c)
//                          by two estimators over the interior layers (two coarse
//                          diameters from either wall): the early drift of the mixed
//                          start (5 windows from driftStartStrain to driftEndStrain:
//                          sum w / sum gammaDot (1 - c)), and the sampled profile's
//                          flux balance c w_seg = c w + D dc/dy (per block: sum (c w +
//                          D dc/dy) / sum gammaDot c (1 - c), w the coarse drift
//                          measured, D from the displacements); with the share of the
//                          balance the diffusive term carries (1 at steady state, where
//                          w = 0; near 0 in a mixed layer, where the balance is the
//                          drift itself) and the interior's p*, I, gammaDot, c, D and
//                          C = D/(gammaDot dMean^2)
// The species are taken in the order given; the last one is "coarse" (the largest).
#include "CellConfig.hpp"
#include "GravityShearRun.hpp"

#include <cmath>
#include <iostream>
#include <set>
#include <stdexcept>

using namespace sdf::dem;

namespace
{

std::set<std::string> validKeys()
{
    std::set<std::string> keys = cellConfigKeys();
    keys.insert
    ({
        "gravity", "normalStress", "wallSpeed", "heightRatio", "wallThickness",
        "profileRelaxationTime", "layers", "driftStartStrain", "driftEndStrain",
        "diffusionStrain", "lammpsData", "output"
    });
    return keys;
}

double requiredNumber(const CellConfig& config, const std::string& key, const std::string& what)
{
    if (!config.count(key)) throw std::invalid_argument("entry '" + key + "' missing: " + what);
    return configNumber(config, key, 0);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: gravityShearCell cell.cfg [key=value ...]\n";
        return 2;
    }
    try
    {
        const CellConfig config = readCellConfig(argv[1], argc, argv, 2, validKeys());
        refuseKeys
        (
            config,
            {"mode", "temperature", "shearRate", "thermostatTime", "targetPressure", "barostatTime",
             "maxEquilibrationTime"},
            "the sheared cell under gravity",
            "the walls (wallSpeed, normalStress) set the flow, and equilibrationTime is the whole"
            " development before the sampling"
        );
        GravityShearRunSettings run;
        run.walls.normalStress = requiredNumber(config, "normalStress", "the top wall's load sigma_N [Pa]");
        run.walls.wallSpeed = requiredNumber(config, "wallSpeed", "the top wall's speed U [m/s]");
        run.walls.gravity = configNumber(config, "gravity", 9.81);
        run.walls.profileRelaxationTime = configNumber(config, "profileRelaxationTime", 0);
        // before the packing, which takes seconds
        validateGravityShearSettings(run.walls, 0);
        run.cell = cellRunSettingsFrom(config);
        run.cell.simulation.mode = CellMode::nve;
        if (!config.count("label")) run.cell.label = "gravityShear";
        const double layers = configNumber(config, "layers", 10);
        if (layers != std::floor(layers) || layers < 2 || layers > 1000)
        {
            throw std::invalid_argument("entry 'layers': a whole number in [2, 1000], got " + config.at("layers"));
        }
        run.layers = int(layers);
        run.heightRatio = configNumber(config, "heightRatio", 3);
        run.wallThickness = configNumber(config, "wallThickness", 1.5);
        run.driftStartStrain = configNumber(config, "driftStartStrain", 2);
        run.driftEndStrain = configNumber(config, "driftEndStrain", 0);
        run.diffusionStrain = configNumber(config, "diffusionStrain", 2);
        run.lammpsData = configText(config, "lammpsData", "");
        const std::string output = configText(config, "output", "gravityShearCell");

        const GravityShearRunResult result = runGravityShearCell(run, &std::cout);
        writeGravityShearFiles(result, output);
        if (!result.segregation.unreachedState().empty())
        {
            std::cout << "warning: " << result.segregation.unreachedState() << '\n';
        }
        std::cout << gravityShearSummary(result.segregation) << '\n'
                  << "written " << output << "-series.dat, " << output << "-profiles.dat, "
                  << output << "-segregation.dat\n";
    }
    catch (const std::exception& err)
    {
        std::cerr << "gravityShearCell: error: " << err.what() << "\n";
        return 1;
    }
    return 0;
}

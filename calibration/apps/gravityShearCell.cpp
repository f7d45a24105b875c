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
#include "GravityShear.hpp"
#include "InitialState.hpp"

#include "correlation/Statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
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

//- The profile columns, per layer.
enum Column
{
    phiColumn, coarseColumn, velocityColumn, sigmaYYColumn, sigmaXYColumn,
    coarseDriftColumn, fineDriftColumn, nColumns
};
const char* const columnHeader =
    "phi phiErr c cErr ux[m/s] uxErr sigmaYY[Pa] sigmaYYErr sigmaXY[Pa] sigmaXYErr"
    " wCoarse[m/s] wCoarseErr wFine[m/s] wFineErr";

//- The flowing grains' state per layer now, between the bottom plane and the top wall.
std::vector<std::array<double, nColumns>> layerProfile
(
    const Simulation& sim,
    const GravityShear& cell,
    int layers,
    int coarse
)
{
    const Particles& p = sim.particles();
    const std::size_t n = p.size(), nl = std::size_t(layers);
    const double h = cell.gap()/layers, y0 = cell.bottomPlane();
    std::vector<int> layer(n, -1);
    std::vector<double> mass(nl), mx(nl), my(nl), mz(nl), volume(nl), coarseVolume(nl);
    std::vector<double> coarseVy(nl), fineVy(nl), fineV(nl), volumeVy(nl);
    for (std::size_t i = 0; i < n; ++i)
    {
        if (cell.role(p, int(i)) != GrainRole::flowing) continue;
        const int l = std::clamp(int(std::floor((p.y[i] - y0)/h)), 0, layers - 1);
        layer[i] = l;
        const std::size_t L = std::size_t(l);
        const double v = 4.0/3.0*M_PI*p.radius[i]*p.radius[i]*p.radius[i];
        mass[L] += p.mass[i];
        mx[L] += p.mass[i]*p.vx[i]; my[L] += p.mass[i]*p.vy[i]; mz[L] += p.mass[i]*p.vz[i];
        volume[L] += v;
        volumeVy[L] += v*p.vy[i];
        if (p.species[i] == coarse) { coarseVolume[L] += v; coarseVy[L] += v*p.vy[i]; }
        else { fineVy[L] += v*p.vy[i]; fineV[L] += v; }
    }
    // kinetic stress about each layer's mean velocity (compressive positive, as the
    // contacts' f r^T)
    std::vector<double> kyy(nl), kxy(nl);
    for (std::size_t i = 0; i < n; ++i)
    {
        if (layer[i] < 0) continue;
        const std::size_t L = std::size_t(layer[i]);
        const double cx = p.vx[i] - mx[L]/mass[L], cy = p.vy[i] - my[L]/mass[L];
        kyy[L] += p.mass[i]*cy*cy;
        kxy[L] += p.mass[i]*cx*cy;
    }
    const std::vector<Eigen::Matrix3d> J = sim.contactStressBySlab(y0, h, layers);
    const double layerVolume = cell.area()*h;
    std::vector<std::array<double, nColumns>> out(nl);
    for (std::size_t L = 0; L < nl; ++L)
    {
        std::array<double, nColumns>& o = out[L];
        o[phiColumn] = volume[L]/layerVolume;
        o[coarseColumn] = volume[L] > 0 ? coarseVolume[L]/volume[L] : 0;
        o[velocityColumn] = mass[L] > 0 ? mx[L]/mass[L] : 0;
        o[sigmaYYColumn] = (kyy[L] + J[L](1, 1))/layerVolume;
        // the shear stress a wall moving toward +x at the top exerts: positive
        o[sigmaXYColumn] = -(kxy[L] + 0.5*(J[L](0, 1) + J[L](1, 0)))/layerVolume;
        const double mean = volume[L] > 0 ? volumeVy[L]/volume[L] : 0;
        o[coarseDriftColumn] = coarseVolume[L] > 0 ? coarseVy[L]/coarseVolume[L] - mean : 0;
        o[fineDriftColumn] = fineV[L] > 0 ? fineVy[L]/fineV[L] - mean : 0;
    }
    return out;
}

//- The coarse and the fine species' centres of volume above the bottom plane [m].
std::array<double, 2> speciesCentres(const Simulation& sim, const GravityShear& cell, int coarse)
{
    const Particles& p = sim.particles();
    double vc = 0, yc = 0, vf = 0, yf = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (cell.role(p, int(i)) != GrainRole::flowing) continue;
        const double v = p.radius[i]*p.radius[i]*p.radius[i], y = p.y[i] - cell.bottomPlane();
        if (p.species[i] == coarse) { vc += v; yc += v*y; }
        else { vf += v; yf += v*y; }
    }
    return {vc > 0 ? yc/vc : 0, vf > 0 ? yf/vf : 0};
}

//- The layers farther than two coarse diameters from either wall: [first, last].
struct Interior
{
    int first = 0, last = -1;
};

//- The interior now: the coarse grains' drift relative to the solids (coarse-volume
//  weighted over the layers), the coarse share and the shear rate (least-squares slope
//  of u_x over the layers' centres).
struct BulkState
{
    double drift = 0, share = 0, shearRate = 0;
};

BulkState bulkState(const std::vector<std::array<double, nColumns>>& profile, const Interior& in, double h)
{
    double solids = 0, coarseSolids = 0, drift = 0, sy = 0, su = 0, syy = 0, syu = 0;
    int n = 0;
    for (int l = in.first; l <= in.last; ++l)
    {
        const std::array<double, nColumns>& o = profile[std::size_t(l)];
        solids += o[phiColumn];
        coarseSolids += o[phiColumn]*o[coarseColumn];
        drift += o[phiColumn]*o[coarseColumn]*o[coarseDriftColumn];
        const double y = (l + 0.5)*h;
        sy += y; su += o[velocityColumn]; syy += y*y; syu += y*o[velocityColumn];
        ++n;
    }
    BulkState b;
    b.share = solids > 0 ? coarseSolids/solids : 0;
    b.drift = coarseSolids > 0 ? drift/coarseSolids : 0;
    const double det = n*syy - sy*sy;
    b.shearRate = det > 0 ? (n*syu - sy*su)/det : 0;
    return b;
}

//- Per layer and species (fine, coarse, all): the y displacements over one lag.
struct DisplacementTally
{
    std::vector<std::array<double, 3>> count, sum, sumSquares;
    explicit DisplacementTally(int layers) : count(std::size_t(layers)), sum(std::size_t(layers)), sumSquares(std::size_t(layers))
    {
        for (int l = 0; l < layers; ++l)
        {
            count[std::size_t(l)].fill(0); sum[std::size_t(l)].fill(0); sumSquares[std::size_t(l)].fill(0);
        }
    }
    //- D = variance / (2 lag) per layer and species (0 without displacements)
    double diffusivity(int l, int s, double lag) const
    {
        const double n = count[std::size_t(l)][std::size_t(s)];
        if (n < 2) return 0;
        const double mean = sum[std::size_t(l)][std::size_t(s)]/n;
        return (sumSquares[std::size_t(l)][std::size_t(s)]/n - mean*mean)/(2*lag);
    }
};

//- The flowing grains' unwrapped y and layer at the start of a lag, by id.
struct DisplacementOrigin
{
    std::vector<double> y;
    std::vector<int> layer;    // -1: a wall grain
};

DisplacementOrigin displacementOrigin(const Simulation& sim, const GravityShear& cell, int layers)
{
    const Particles& p = sim.particles();
    DisplacementOrigin o;
    o.y.assign(p.size(), 0);
    o.layer.assign(p.size(), -1);
    const double h = cell.gap()/layers;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (cell.role(p, int(i)) != GrainRole::flowing) continue;
        const std::size_t id = std::size_t(p.id[i]);
        o.y[id] = p.uy[i];
        o.layer[id] = std::clamp(int(std::floor((p.y[i] - cell.bottomPlane())/h)), 0, layers - 1);
    }
    return o;
}

void tallyDisplacements
(
    const Simulation& sim, const DisplacementOrigin& origin, int coarse, DisplacementTally& tally
)
{
    const Particles& p = sim.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const std::size_t id = std::size_t(p.id[i]);
        const int l = origin.layer[id];
        if (l < 0) continue;
        const double dy = p.uy[i] - origin.y[id];
        for (int s : {p.species[i] == coarse ? 1 : 0, 2})
        {
            tally.count[std::size_t(l)][std::size_t(s)] += 1;
            tally.sum[std::size_t(l)][std::size_t(s)] += dy;
            tally.sumSquares[std::size_t(l)][std::size_t(s)] += dy*dy;
        }
    }
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
        GravityShearSettings cellSettings;
        cellSettings.normalStress = requiredNumber(config, "normalStress", "the top wall's load sigma_N [Pa]");
        cellSettings.wallSpeed = requiredNumber(config, "wallSpeed", "the top wall's speed U [m/s]");
        cellSettings.gravity = configNumber(config, "gravity", 9.81);
        cellSettings.profileRelaxationTime = configNumber(config, "profileRelaxationTime", 0);

        // before the packing, which takes seconds
        validateGravityShearSettings(cellSettings, 0);
        CellRunSettings settings = cellRunSettingsFrom(config);
        settings.simulation.mode = CellMode::nve;
        if (!config.count("label")) settings.label = "gravityShear";
        validateCellRunSettings(settings);
        if (settings.species.size() < 2)
        {
            throw std::invalid_argument
            (
                "entry 'species': the segregation cell needs two species (fine, coarse); a"
                " one-species cell has nothing to segregate (equal sizes: give two species"
                " of the same diameter)"
            );
        }
        const int coarse = int(settings.species.size()) - 1;
        requireCoarseLast(settings, true);
        const double dCoarse = settings.species.back().diameter;
        const double dFine = settings.species.front().diameter;
        double dMin = dCoarse;
        for (const Species& s : settings.species) dMin = std::min(dMin, s.diameter);
        const double layersValue = configNumber(config, "layers", 10);
        if (layersValue != std::floor(layersValue) || layersValue < 2 || layersValue > 1000)
        {
            throw std::invalid_argument("entry 'layers': a whole number in [2, 1000], got " + config.at("layers"));
        }
        const int layers = int(layersValue);
        const std::string output = configText(config, "output", "gravityShearCell");

        PackingSettings ps;
        ps.solidsFraction = settings.solidsFraction;
        ps.counts = countsFromVolumeFractions(settings.species, settings.volumeFractions, settings.particles);
        ps.seed = settings.seed;
        ps.heightRatio = configNumber(config, "heightRatio", 3);
        const double wallThickness = configNumber(config, "wallThickness", 1.5)*dCoarse;
        // the flowing layer's depth, known before the packing is made
        {
            double solids = 0;
            for (std::size_t s = 0; s < settings.species.size(); ++s) solids += ps.counts[s]*settings.species[s].volume();
            const double height = ps.heightRatio*std::cbrt(solids/(ps.solidsFraction*ps.heightRatio));
            const double gap = height - 2*wallThickness;
            if (!(gap >= 10*dCoarse))
            {
                throw std::invalid_argument
                (
                    "entries 'particles', 'heightRatio', 'wallThickness': the walls would be "
                  + std::to_string(gap/dCoarse) + " coarse diameters apart; at least 10 are needed"
                    " (more particles, a larger heightRatio or thinner walls)"
                );
            }
        }
        Packing packing = makePacking(settings.species, ps);
        WallBoundedCell cut = cutWallBoundedCell
        (
            std::move(packing.particles), packing.box, wallThickness, 0.5*packing.box.ly + 4*dCoarse
        );
        const std::string lammpsData = configText(config, "lammpsData", "");
        if (!lammpsData.empty()) writeLammpsData(lammpsData, cut.particles, cut.box, settings.species);
        SimulationSettings simSettings = settings.simulation;
        simSettings.renumberEvery = 1000;
        Simulation sim(settings.species, simSettings, cut.particles, cut.box);
        auto driving = std::make_unique<GravityShear>
        (
            cellSettings, cut, dMin, sim.timeStep()
        );
        GravityShear& cell = *driving;
        sim.setDriving(std::move(driving));

        const double dt = sim.timeStep();
        const long sampleEvery = std::max(1, settings.sampleEvery);
        const long equilibrationSteps = std::lround(settings.equilibrationTime/dt);
        const long blockSteps =
            std::max(sampleEvery, std::lround(settings.samplingTime/settings.blocks/dt)/sampleEvery*sampleEvery);
        const long seriesSamples =
            std::max(1L, (equilibrationSteps + settings.blocks*blockSteps)/1000/sampleEvery);
        const long seriesEvery = seriesSamples*sampleEvery;
        const double rhoS = settings.species.back().density;
        const double dMean = meanDiameter(settings);
        const double nominalShearRate = cellSettings.wallSpeed/cell.gap();
        const double driftStartStrain = configNumber(config, "driftStartStrain", 2);
        const double diffusionStrain = configNumber(config, "diffusionStrain", 2);
        if (!(nominalShearRate > 0))
        {
            throw std::invalid_argument("entry 'wallSpeed' must be > 0 for the segregation cell (U/gap is the shear)");
        }
        if (!(driftStartStrain >= 0) || !(diffusionStrain > 0))
        {
            throw std::invalid_argument("entries 'driftStartStrain' (>= 0) and 'diffusionStrain' (> 0): strains U t/gap");
        }
        // the lag of the diffusivity, whole samples, and at most a block
        const long lagSamples = std::clamp
        (
            std::lround(diffusionStrain/nominalShearRate/dt/sampleEvery), 1L, blockSteps/sampleEvery
        );
        const double lag = lagSamples*sampleEvery*dt;
        const long driftStartStep = std::lround(driftStartStrain/nominalShearRate/dt);
        const long driftEndStep = config.count("driftEndStrain")
            ? std::lround(configNumber(config, "driftEndStrain", 0)/nominalShearRate/dt) : equilibrationSteps;
        if (driftStartStep >= driftEndStep || driftEndStep > equilibrationSteps)
        {
            throw std::invalid_argument
            (
                "entries 'driftStartStrain', 'driftEndStrain', 'equilibrationTime': the early drift is"
                " read from " + std::to_string(driftStartStep*dt) + " s to " + std::to_string(driftEndStep*dt)
              + " s, which must be an interval within the development (" + std::to_string(equilibrationSteps*dt)
              + " s)"
            );
        }
        std::cout << "Sheared cell under gravity: " << sim.particles().size() << " grains, box "
                  << cut.box.lx << " x " << cut.box.lz << " m, the walls " << cell.gap()
                  << " m apart (" << cell.gap()/dCoarse << " coarse diameters), dt " << dt
                  << " s, top wall " << cell.wallMass() << " kg; the walls' planes y_b "
                  << cell.bottomPlane() << " m, y_t " << cell.topPlane() << " m; sigma_N " << cellSettings.normalStress
                  << " Pa (p* " << cellSettings.normalStress/(rhoS*cellSettings.gravity*dMean)
                  << " at the top), U " << cellSettings.wallSpeed << " m/s (U/gap "
                  << nominalShearRate << " 1/s); " << equilibrationSteps
                  << " steps of development (the early drift from step " << driftStartStep << " to "
                  << driftEndStep << "), "
                  << settings.blocks << " blocks of " << blockSteps << " steps, diffusion lag "
                  << lag << " s\n";

        // the interior: two coarse diameters from either wall
        const double h0 = cell.gap()/layers;
        Interior interior;
        interior.first = std::max(1, int(std::ceil(2*dCoarse/h0)));
        interior.last = layers - 1 - interior.first;
        if (interior.last - interior.first < 1)
        {
            throw std::invalid_argument
            (
                "entry 'layers': " + std::to_string(layers) + " layers leave fewer than two layers"
                " two coarse diameters from the walls; more layers or a deeper cell"
            );
        }

        // the top wall's load over the sampling: the check that the grains carried it
        bool sampling = false;
        double topStressSum = 0;
        long topStressSteps = 0;
        std::ofstream series(output + "-series.dat");
        series << "# t[s] gap[m] topWallStress[Pa] bottomWallStress[Pa] yCoarse[m] yFine[m]"
                  " (yCoarse-yFine)/dCoarse\n" << std::setprecision(8);
        auto writeSeries = [&](const Simulation& s)
        {
            const std::array<double, 2> y = speciesCentres(s, cell, coarse);
            if (!std::isfinite(y[0]) || !std::isfinite(cell.gap()))
            {
                throw std::runtime_error("gravityShear: the cell is not finite at t = " + std::to_string(s.time()));
            }
            series << s.time() << ' ' << cell.gap() << ' ' << cell.meanTopWallStress() << ' '
                   << cell.meanBottomWallStress() << ' ' << y[0] << ' ' << y[1] << ' '
                   << (y[0] - y[1])/dCoarse << '\n';
            if (sampling)
            {
                topStressSum += cell.meanTopWallStress()*cell.wallStressSteps();
                topStressSteps += cell.wallStressSteps();
            }
            cell.resetWallStresses();
        };
        writeSeries(sim);
        sim.run(driftStartStep, writeSeries, seriesEvery, settings.progressEvery, settings.label + " development");

        // the early drift: 5 windows of the rest of the development
        constexpr int driftWindows = 5;
        const long driftSteps = driftEndStep - driftStartStep;
        std::vector<double> earlyS;
        BulkState earlyMean;
        long earlySamples = 0;
        for (int w = 0; w < driftWindows; ++w)
        {
            const long steps = driftSteps*(w + 1)/driftWindows - driftSteps*w/driftWindows;
            double driftSum = 0, rateSum = 0;
            long taken = 0;
            auto sample = [&](const Simulation& s)
            {
                const BulkState b = bulkState(layerProfile(s, cell, layers, coarse), interior, cell.gap()/layers);
                driftSum += b.drift;
                rateSum += b.shearRate*(1 - b.share);
                earlyMean.drift += b.drift; earlyMean.share += b.share; earlyMean.shearRate += b.shearRate;
                ++earlySamples;
                if (++taken % seriesSamples == 0) writeSeries(s);
            };
            sim.run
            (
                steps, sample, sampleEvery, settings.progressEvery,
                settings.label + " early drift " + std::to_string(w + 1) + "/" + std::to_string(driftWindows)
            );
            if (rateSum > 0) earlyS.push_back(driftSum/rateSum);
        }
        if (equilibrationSteps > driftEndStep)
        {
            sim.run
            (
                equilibrationSteps - driftEndStep, writeSeries, seriesEvery, settings.progressEvery,
                settings.label + " development after the early drift"
            );
        }

        const int blocks = settings.blocks;
        // blockMeans[column][layer][block]
        std::vector<std::vector<std::vector<double>>> blockMeans
        (
            nColumns, std::vector<std::vector<double>>(std::size_t(layers))
        );
        // blockD[species: fine, coarse, all][layer][block]
        std::vector<std::vector<std::vector<double>>> blockD
        (
            3, std::vector<std::vector<double>>(std::size_t(layers))
        );
        std::vector<double> blockGap;
        long samplesTaken = 0;
        if (cell.wallStressSteps() > 0) writeSeries(sim);   // the development's last stresses
        sampling = true;
        for (int b = 0; b < blocks; ++b)
        {
            std::vector<std::array<double, nColumns>> sum(static_cast<std::size_t>(layers));
            for (auto& row : sum) row.fill(0);
            DisplacementTally tally(layers);
            DisplacementOrigin origin = displacementOrigin(sim, cell, layers);
            long sinceOrigin = 0;
            double gapSum = 0;
            long samples = 0;
            auto sample = [&](const Simulation& s)
            {
                const std::vector<std::array<double, nColumns>> now = layerProfile(s, cell, layers, coarse);
                for (std::size_t l = 0; l < now.size(); ++l)
                {
                    for (int c = 0; c < nColumns; ++c) sum[l][std::size_t(c)] += now[l][std::size_t(c)];
                }
                gapSum += cell.gap();
                ++samples;
                if (++sinceOrigin == lagSamples)
                {
                    tallyDisplacements(s, origin, coarse, tally);
                    origin = displacementOrigin(s, cell, layers);
                    sinceOrigin = 0;
                }
                if (++samplesTaken % seriesSamples == 0) writeSeries(s);
            };
            sim.run
            (
                blockSteps, sample, sampleEvery, settings.progressEvery,
                settings.label + " block " + std::to_string(b + 1) + "/" + std::to_string(blocks)
            );
            for (std::size_t l = 0; l < sum.size(); ++l)
            {
                for (int c = 0; c < nColumns; ++c) blockMeans[std::size_t(c)][l].push_back(sum[l][std::size_t(c)]/samples);
                for (int sp = 0; sp < 3; ++sp) blockD[std::size_t(sp)][l].push_back(tally.diffusivity(int(l), sp, lag));
            }
            blockGap.push_back(gapSum/samples);
        }
        if (cell.wallStressSteps() > 0) writeSeries(sim);
        series.close();
        const double topWallLoad = topStressSteps > 0 ? topStressSum/topStressSteps/cellSettings.normalStress : 0;

        const double gap = sdf::correlation::meanAndStandardError(blockGap).value;
        const double h = gap/layers;
        std::ofstream profiles(output + "-profiles.dat");
        profiles << "# sheared cell under gravity: sigma_N " << cellSettings.normalStress << " Pa, U "
                 << cellSettings.wallSpeed << " m/s, g " << cellSettings.gravity << " m/s^2, gap "
                 << gap << " m, " << sim.particles().size() << " grains, " << blocks << " blocks of "
                 << blockSteps*dt << " s after " << equilibrationSteps*dt
                 << " s; errors: block standard errors; y from the bottom wall's plane; D over "
                 << lag << " s lags\n"
                 << "# y[m] " << columnHeader
                 << " Dfine[m2/s] DfineErr Dcoarse[m2/s] DcoarseErr D[m2/s] Derr\n" << std::setprecision(8);
        for (int l = 0; l < layers; ++l)
        {
            profiles << (l + 0.5)*h;
            for (int c = 0; c < nColumns; ++c)
            {
                const sdf::correlation::Estimate e =
                    sdf::correlation::meanAndStandardError(blockMeans[std::size_t(c)][std::size_t(l)]);
                profiles << ' ' << e.value << ' ' << e.standardError;
            }
            for (int sp = 0; sp < 3; ++sp)
            {
                const sdf::correlation::Estimate e =
                    sdf::correlation::meanAndStandardError(blockD[std::size_t(sp)][std::size_t(l)]);
                profiles << ' ' << e.value << ' ' << e.standardError;
            }
            profiles << '\n';
        }

        // the flux balance per block over the interior: the segregation flux c w_seg is the
        // net coarse flux measured (c w) plus the diffusive back-flux D dc/dy it works
        // against; S = sum (c w + D dc/dy) / sum gammaDot c (1 - c), derivatives by central
        // differences. At steady state w = 0 and this is the steady profile's balance
        // c w_seg = D dc/dy; before it, it holds at every instant the model holds, which is
        // what makes it an estimator independent of the early drift once the diffusive term
        // carries most of it (diffusiveShare). And the interior's conditions.
        std::vector<double> balanceS, diffusiveShare, pStar, inertial, shearRate, share, diffusivity, solids;
        for (int b = 0; b < blocks; ++b)
        {
            auto at = [&](int column, int l) { return blockMeans[std::size_t(column)][std::size_t(l)][std::size_t(b)]; };
            // p* and c weighted as the balance weighs its layers (gammaDot c (1 - c)), p*
            // with each layer's own dMean, as the solver evaluates the law; plain means
            // where nothing segregates (an unsheared or one-species interior)
            double diffusive = 0, net = 0, drive = 0, p = 0, gd = 0, c = 0, d = 0, inum = 0, phi = 0;
            double pWeighted = 0, cWeighted = 0;
            for (int l = interior.first; l <= interior.last; ++l)
            {
                const double dcdy = (at(coarseColumn, l + 1) - at(coarseColumn, l - 1))/(2*h);
                const double rate = (at(velocityColumn, l + 1) - at(velocityColumn, l - 1))/(2*h);
                const double D = blockD[2][std::size_t(l)][std::size_t(b)];
                const double cl = at(coarseColumn, l);
                const double weight = rate*cl*(1 - cl);
                const double dMeanLayer = dFine + cl*(dCoarse - dFine);
                diffusive += D*dcdy;
                net += cl*at(coarseDriftColumn, l);
                drive += weight;
                pWeighted += weight*at(sigmaYYColumn, l)/(rhoS*cellSettings.gravity*dMeanLayer);
                cWeighted += weight*cl;
                p += at(sigmaYYColumn, l); gd += rate; c += cl; d += D; phi += at(phiColumn, l);
                inum += rate*dMean/std::sqrt(std::max(at(sigmaYYColumn, l), 1e-300)/rhoS);
            }
            const int n = interior.last - interior.first + 1;
            if (drive > 0)
            {
                balanceS.push_back((net + diffusive)/drive);
                if (std::abs(net + diffusive) > 0) diffusiveShare.push_back(diffusive/(net + diffusive));
                pStar.push_back(pWeighted/drive);
                share.push_back(cWeighted/drive);
            }
            else
            {
                pStar.push_back(p/n/(rhoS*cellSettings.gravity*dMean));
                share.push_back(c/n);
            }
            inertial.push_back(inum/n);
            shearRate.push_back(gd/n);
            diffusivity.push_back(d/n);
            solids.push_back(phi/n);
        }
        if (earlyS.empty() || balanceS.empty())
        {
            throw std::runtime_error
            (
                "the interior was not sheared during the " + std::string(earlyS.empty() ? "development" : "sampling")
              + " (the top wall had not landed on the grains, or not started sliding): a longer"
                " equilibrationTime; nothing written for the segregation"
            );
        }
        using sdf::correlation::meanAndStandardError;
        const sdf::correlation::Estimate sEarly = meanAndStandardError(earlyS);
        const sdf::correlation::Estimate sBalance = meanAndStandardError(balanceS);
        const sdf::correlation::Estimate rate = meanAndStandardError(shearRate);
        const sdf::correlation::Estimate D = meanAndStandardError(diffusivity);
        std::ofstream segregation(output + "-segregation.dat");
        segregation << std::setprecision(6)
                    << "# w_coarse = S gammaDot (1 - c) over the interior layers " << interior.first
                    << "-" << interior.last << " of " << layers << " (two coarse diameters from the walls);"
                    << " errors: standard errors over " << driftWindows << " windows (early) and "
                    << blocks << " blocks (balance)\n"
                    << "# estimator S[m] S_err[m] S/dFine S/dFine_err\n";
        segregation << "early " << sEarly.value << ' ' << sEarly.standardError << ' '
                    << sEarly.value/dFine << ' ' << sEarly.standardError/dFine << '\n'
                    << "balance " << sBalance.value << ' ' << sBalance.standardError << ' '
                    << sBalance.value/dFine << ' ' << sBalance.standardError/dFine << '\n';
        segregation << "# per window (early): ";
        for (double v : earlyS) segregation << ' ' << v;
        segregation << "\n# per block (balance): ";
        for (double v : balanceS) segregation << ' ' << v;
        segregation << "\n# per block, the share of the balance carried by the diffusive term D dc/dy: ";
        for (double v : diffusiveShare) segregation << ' ' << v;
        segregation << '\n';
        segregation << "# the top wall's mean load over the sampling: " << topWallLoad << " sigma_N\n";
        if (std::abs(topWallLoad - 1) > 0.05)
        {
            const std::string warning =
                "warning: the top wall carried " + std::to_string(topWallLoad) + " sigma_N over the"
                " sampling, not 1 +- 0.05: the layer was not under its load (a longer"
                " equilibrationTime), and these numbers are not the condition asked for";
            segregation << "# " << warning << '\n';
            std::cout << warning << '\n';
        }
        const double n = std::max<long>(earlySamples, 1);
        segregation << "# the early drift's interior: w " << earlyMean.drift/n << " m/s, gammaDot "
                    << earlyMean.shearRate/n << " 1/s, c " << earlyMean.share/n << "\n"
                    << "# the sampled interior: p* " << meanAndStandardError(pStar).value << ", I "
                    << meanAndStandardError(inertial).value << ", gammaDot " << rate.value << " +- "
                    << rate.standardError << " 1/s, c " << meanAndStandardError(share).value << ", D "
                    << D.value << " +- " << D.standardError << " m2/s, C = D/(gammaDot dMean^2) "
                    << D.value/(rate.value*dMean*dMean) << " (dMean " << dMean << " m)\n";
        // one line for the fit (fitSegregationVelocity): each estimator with the interior's
        // c and gammaDot over the time it was read; C = D/(gammaDot dMean^2) of the sampling
        const double cError = D.standardError/(rate.value*dMean*dMean)
            + D.value*rate.standardError/(rate.value*rate.value*dMean*dMean);
        segregation << "# interior (for fitSegregationVelocity): dFine[m] R phi pStar I S_early[m] S_earlyErr"
                       " c_early gammaDot_early[1/s] S_balance[m] S_balanceErr c gammaDot[1/s] C Cerr"
                       " topWallLoad\n"
                    << "interior " << dFine << ' ' << dCoarse/dFine << ' ' << meanAndStandardError(solids).value
                    << ' ' << meanAndStandardError(pStar).value << ' ' << meanAndStandardError(inertial).value
                    << ' ' << sEarly.value << ' ' << sEarly.standardError << ' ' << earlyMean.share/n << ' '
                    << earlyMean.shearRate/n << ' ' << sBalance.value << ' ' << sBalance.standardError << ' '
                    << meanAndStandardError(share).value << ' ' << rate.value << ' '
                    << D.value/(rate.value*dMean*dMean) << ' ' << cError << ' ' << topWallLoad << '\n';
        if (!profiles || !series || !segregation)
        {
            throw std::runtime_error("cannot write " + output + "-profiles.dat, -series.dat or -segregation.dat");
        }
        std::cout << "S (early drift) " << sEarly.value << " +- " << sEarly.standardError
                  << " m, S (flux balance) " << sBalance.value << " +- " << sBalance.standardError
                  << " m (the diffusive term's share " << meanAndStandardError(diffusiveShare).value
                  << "); C " << D.value/(rate.value*dMean*dMean) << "; the top wall's load "
                  << topWallLoad << " sigma_N\n"
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

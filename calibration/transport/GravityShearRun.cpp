#include "GravityShearRun.hpp"

#include "CellConfig.hpp"
#include "InitialState.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace sdf::dem
{

namespace
{

std::string topWallLoadWarning(double topWallLoad)
{
    return
        "the top wall carried " + std::to_string(topWallLoad) + " sigma_N over the"
        " sampling, not 1 +- 0.05: the layer was not under its load (a longer"
        " equilibrationTime), and these numbers are not the condition asked for";
}

} // namespace


namespace
{

//- The early drift is read over this many windows of the development
constexpr int driftWindows = 5;

//- The columns sampled at an instant (the diffusivities come from displacements).
constexpr int nColumns = fineDriftColumn + 1;
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

} // namespace


bool SegregationMeasurement::loaded() const
{
    return std::abs(topWallLoad - 1) <= 0.05;
}


std::string SegregationMeasurement::unreachedState() const
{
    if (!slidingBeforeDrift())
    {
        return
            "the top wall had slid " + std::to_string(slidingStrainAtDrift) + " strains (U t/gap)"
            " when the early drift's windows started, not the 1 of its ramp: the drift was read"
            " in a flow still starting (a later driftStartStrain or a longer developmentTime)";
    }
    if (!loaded())
    {
        return topWallLoadWarning(topWallLoad);
    }
    if (quasiStatic())
    {
        std::ostringstream why;
        why << "quasi-static: I = " << inertialNumber << " < "
            << RheologyResult::minimumInertialNumber << " in the interior, below the dense"
            << " flow the law is fitted in (there w = S gammaDot (1 - c) vanishes with"
            << " gammaDot; a faster wall or a lighter load)";
        return why.str();
    }
    return "";
}


void validateGravityShearRunSettings(const GravityShearRunSettings& s)
{
    validateGravityShearSettings(s.walls, 0);
    validateCellRunSettings(s.cell);
    if (s.cell.species.size() < 2)
    {
        throw std::invalid_argument
        (
            "entry 'species': the segregation cell needs two species (fine, coarse); a"
            " one-species cell has nothing to segregate (equal sizes: give two species"
            " of the same diameter)"
        );
    }
    requireCoarseLast(s.cell, true);
    if (s.layers < 2 || s.layers > 1000)
    {
        throw std::invalid_argument("entry 'layers': a whole number in [2, 1000], got " + std::to_string(s.layers));
    }
    if (!(s.walls.wallSpeed > 0))
    {
        throw std::invalid_argument("entry 'wallSpeed' must be > 0 for the segregation cell (U/gap is the shear)");
    }
    if (!(s.driftStartStrain >= 0) || !(s.diffusionStrain > 0) || !(s.driftEndStrain >= 0))
    {
        throw std::invalid_argument
        (
            "entries 'driftStartStrain' (>= 0), 'driftEndStrain' (>= 0; 0: the development's end) and"
            " 'diffusionStrain' (> 0): strains U t/gap"
        );
    }
    if (!(s.heightRatio > 0) || !(s.wallThickness > 0))
    {
        throw std::invalid_argument("entries 'heightRatio' and 'wallThickness' must be > 0");
    }
    // the flowing layer's depth, known before the packing is made
    const auto counts =
        countsFromVolumeFractions(s.cell.species, s.cell.volumeFractions, s.cell.particles);
    double solids = 0;
    for (std::size_t i = 0; i < s.cell.species.size(); ++i) solids += counts[i]*s.cell.species[i].volume();
    const double dCoarse = s.cell.species.back().diameter;
    const double height = s.heightRatio*std::cbrt(solids/(s.cell.solidsFraction*s.heightRatio));
    const double gap = height - 2*s.wallThickness*dCoarse;
    if (!(gap >= 10*dCoarse))
    {
        throw std::invalid_argument
        (
            "entries 'particles', 'heightRatio', 'wallThickness': the walls would be "
          + std::to_string(gap/dCoarse) + " coarse diameters apart; at least 10 are needed"
            " (more particles, a larger heightRatio or thinner walls)"
        );
    }
    // the run checks both again on the cut cell's gap; here on the packing's, so that
    // a calibration refuses them before any cell runs
    const int first = std::max(1, int(std::ceil(2*dCoarse/(gap/s.layers))));
    if (s.layers - 1 - 2*first < 1)
    {
        throw std::invalid_argument
        (
            "entry 'layers': " + std::to_string(s.layers) + " layers leave fewer than two layers"
            " two coarse diameters from the walls; more layers or a deeper cell"
        );
    }
    const double rate = s.walls.wallSpeed/gap;
    const double driftStart = s.driftStartStrain/rate;
    const double driftEnd = s.driftEndStrain > 0 ? s.driftEndStrain/rate : s.cell.equilibrationTime;
    if (!(driftStart < driftEnd) || driftEnd > s.cell.equilibrationTime)
    {
        throw std::invalid_argument
        (
            "entries 'driftStartStrain', 'driftEndStrain', 'equilibrationTime': the early drift would"
            " be read from " + std::to_string(driftStart) + " s to " + std::to_string(driftEnd)
          + " s (U/gap about " + std::to_string(rate) + " 1/s), which must be an interval within the"
            " development (" + std::to_string(s.cell.equilibrationTime) + " s)"
        );
    }
}


GravityShearRunResult runGravityShearCell(const GravityShearRunSettings& runSettings, std::ostream* log)
{
    validateGravityShearRunSettings(runSettings);
    const auto wallStart = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    GravityShearRunResult result;
    result.settings = runSettings;
    const GravityShearSettings& cellSettings = runSettings.walls;
    CellRunSettings settings = runSettings.cell;
    settings.simulation.mode = CellMode::nve;
    const int coarse = int(settings.species.size()) - 1;
    const double dCoarse = settings.species.back().diameter;
    const double dFine = settings.species.front().diameter;
    double dMin = dCoarse;
    for (const Species& s : settings.species) dMin = std::min(dMin, s.diameter);
    const int layers = runSettings.layers;

    PackingSettings ps;
    ps.solidsFraction = settings.solidsFraction;
    ps.counts = countsFromVolumeFractions(settings.species, settings.volumeFractions, settings.particles);
    ps.seed = settings.seed;
    ps.heightRatio = runSettings.heightRatio;
    const double wallThickness = runSettings.wallThickness*dCoarse;
    Packing packing = makePacking(settings.species, ps);
    WallBoundedCell cut = cutWallBoundedCell
    (
        std::move(packing.particles), packing.box, wallThickness, 0.5*packing.box.ly + 4*dCoarse
    );
    if (!runSettings.lammpsData.empty())
    {
        writeLammpsData(runSettings.lammpsData, cut.particles, cut.box, settings.species);
    }
    SimulationSettings simSettings = settings.simulation;
    simSettings.renumberEvery = 1000;
    Simulation sim(settings.species, simSettings, cut.particles, cut.box);
    auto driving = std::make_unique<GravityShear>(cellSettings, cut, dMin, sim.timeStep());
    GravityShear& cell = *driving;
    sim.setDriving(std::move(driving));

    const double dt = sim.timeStep();
    // about 1000 series rows
    const SampledSchedule schedule = sampledSchedule(settings, dt, 1000);
    const long sampleEvery = schedule.sampleEvery;
    const long equilibrationSteps = schedule.equilibrationSteps;
    const long blockSteps = schedule.blockSteps;
    const long seriesSamples = schedule.seriesSamples;
    const long seriesEvery = schedule.seriesEvery;
    const double rhoS = settings.species.back().density;
    const double dMean = meanDiameter(settings);
    const double nominalShearRate = cellSettings.wallSpeed/cell.gap();
    // the lag of the diffusivity, whole samples, and at most a block
    const long lagSamples = std::clamp
    (
        std::lround(runSettings.diffusionStrain/nominalShearRate/dt/sampleEvery), 1L, blockSteps/sampleEvery
    );
    const double lag = lagSamples*sampleEvery*dt;
    const long driftStartStep = std::lround(runSettings.driftStartStrain/nominalShearRate/dt);
    const long driftEndStep = runSettings.driftEndStrain > 0
        ? std::lround(runSettings.driftEndStrain/nominalShearRate/dt) : equilibrationSteps;
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
    result.grains = sim.particles().size();
    result.boxLength = cut.box.lx;
    result.boxDepth = cut.box.lz;
    result.timeStep = dt;
    result.developmentTime = equilibrationSteps*dt;
    result.blockTime = blockSteps*dt;
    result.diffusionLag = lag;
    if (log)
    {
        *log << "Sheared cell under gravity: " << sim.particles().size() << " grains, box "
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
    }

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
    result.interiorFirst = interior.first;
    result.interiorLast = interior.last;

    // the top wall's load over the sampling: the check that the grains carried it
    bool sampling = false;
    double topStressSum = 0;
    long topStressSteps = 0;
    auto writeSeries = [&](const Simulation& s)
    {
        const std::array<double, 2> y = speciesCentres(s, cell, coarse);
        if (!std::isfinite(y[0]) || !std::isfinite(cell.gap()))
        {
            throw std::runtime_error("gravityShear: the cell is not finite at t = " + std::to_string(s.time()));
        }
        result.series.push_back
        ({
            s.time(), cell.gap(), cell.meanTopWallStress(), cell.meanBottomWallStress(), y[0], y[1],
            (y[0] - y[1])/dCoarse
        });
        if (sampling)
        {
            topStressSum += cell.meanTopWallStress()*cell.wallStressSteps();
            topStressSteps += cell.wallStressSteps();
        }
        cell.resetWallStresses();
    };
    writeSeries(sim);
    sim.run(driftStartStep, writeSeries, seriesEvery, settings.progressEvery, settings.label + " development");
    const double slidingStrainAtDrift = cell.slidingTime()*cellSettings.wallSpeed/cell.gap();

    // the early drift: 5 windows of the rest of the development
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
    const double slidingStrainAtSampling = cell.slidingTime()*cellSettings.wallSpeed/cell.gap();
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

    const double topWallLoad = topStressSteps > 0 ? topStressSum/topStressSteps/cellSettings.normalStress : 0;


    using correlation::meanAndStandardError;
    result.gap = meanAndStandardError(blockGap).value;
    const double h = result.gap/layers;
    result.profiles.resize(std::size_t(layers));
    for (int l = 0; l < layers; ++l)
    {
        for (int c = 0; c < nColumns; ++c)
        {
            result.profiles[std::size_t(l)][std::size_t(c)] =
                meanAndStandardError(blockMeans[std::size_t(c)][std::size_t(l)]);
        }
        for (int sp = 0; sp < 3; ++sp)
        {
            result.profiles[std::size_t(l)][std::size_t(fineDiffusivityColumn + sp)] =
                meanAndStandardError(blockD[std::size_t(sp)][std::size_t(l)]);
        }
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
    SegregationMeasurement& m = result.segregation;
    m.fineDiameter = dFine;
    m.sizeRatio = dCoarse/dFine;
    m.meanDiameter = dMean;
    m.solidsFraction = meanAndStandardError(solids).value;
    m.pressureNumber = meanAndStandardError(pStar).value;
    m.inertialNumber = meanAndStandardError(inertial).value;
    m.early = meanAndStandardError(earlyS);
    const double n = double(std::max<long>(earlySamples, 1));
    m.earlyCoarseShare = earlyMean.share/n;
    m.earlyShearRate = earlyMean.shearRate/n;
    m.earlyDrift = earlyMean.drift/n;
    m.balance = meanAndStandardError(balanceS);
    m.coarseShare = meanAndStandardError(share).value;
    m.shearRate = meanAndStandardError(shearRate);
    m.diffusivity = meanAndStandardError(diffusivity);
    const double scale = m.shearRate.value*dMean*dMean;
    m.shearRateDiffusivity.value = m.diffusivity.value/scale;
    m.shearRateDiffusivity.standardError = m.diffusivity.standardError/scale
        + m.diffusivity.value*m.shearRate.standardError/(m.shearRate.value*scale);
    m.shearRateDiffusivity.samples = m.diffusivity.samples;
    m.diffusiveShare = meanAndStandardError(diffusiveShare).value;
    m.topWallLoad = topWallLoad;
    m.slidingStrainAtDrift = slidingStrainAtDrift;
    m.slidingStrainAtSampling = slidingStrainAtSampling;
    m.earlyWindows = earlyS;
    m.balanceBlocks = balanceS;
    m.diffusiveShares = diffusiveShare;
    result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
    result.cpuSeconds = double(std::clock() - cpuStart)/CLOCKS_PER_SEC;
    return result;
}


std::string gravityShearSummary(const SegregationMeasurement& s)
{
    std::ostringstream o;
    o << "S (early drift) " << s.early.value << " +- " << s.early.standardError
      << " m, S (flux balance) " << s.balance.value << " +- " << s.balance.standardError
      << " m (the diffusive term's share " << s.diffusiveShare << "); C "
      << s.shearRateDiffusivity.value << "; the top wall's load " << s.topWallLoad << " sigma_N";
    return o.str();
}


void writeGravityShearFiles(const GravityShearRunResult& r, const std::string& output)
{
    const GravityShearSettings& cellSettings = r.settings.walls;
    const SegregationMeasurement& m = r.segregation;
    const int layers = r.settings.layers;
    const int blocks = r.settings.cell.blocks;
    const double h = r.gap/layers;
    std::ofstream series(output + "-series.dat");
    series << "# t[s] gap[m] topWallStress[Pa] bottomWallStress[Pa] yCoarse[m] yFine[m]"
              " (yCoarse-yFine)/dCoarse\n" << std::setprecision(8);
    for (const std::array<double, 7>& row : r.series)
    {
        for (std::size_t i = 0; i < row.size(); ++i) series << (i ? " " : "") << row[i];
        series << '\n';
    }
    std::ofstream profiles(output + "-profiles.dat");
    profiles << "# sheared cell under gravity: sigma_N " << cellSettings.normalStress << " Pa, U "
             << cellSettings.wallSpeed << " m/s, g " << cellSettings.gravity << " m/s^2, gap "
             << r.gap << " m, " << r.grains << " grains, " << blocks << " blocks of "
             << r.blockTime << " s after " << r.developmentTime
             << " s; errors: block standard errors; y from the bottom wall's plane; D over "
             << r.diffusionLag << " s lags\n"
             << "# y[m] " << columnHeader
             << " Dfine[m2/s] DfineErr Dcoarse[m2/s] DcoarseErr D[m2/s] Derr\n" << std::setprecision(8);
    for (int l = 0; l < layers; ++l)
    {
        profiles << (l + 0.5)*h;
        for (const correlation::Estimate& e : r.profiles[std::size_t(l)])
        {
            profiles << ' ' << e.value << ' ' << e.standardError;
        }
        profiles << '\n';
    }
    const double dFine = m.fineDiameter;
    std::ofstream segregation(output + "-segregation.dat");
    segregation << std::setprecision(6)
                << "# w_coarse = S gammaDot (1 - c) over the interior layers " << r.interiorFirst
                << "-" << r.interiorLast << " of " << layers << " (two coarse diameters from the walls);"
                << " errors: standard errors over " << driftWindows << " windows (early) and "
                << blocks << " blocks (balance)\n"
                << "# estimator S[m] S_err[m] S/dFine S/dFine_err\n";
    segregation << "early " << m.early.value << ' ' << m.early.standardError << ' '
                << m.early.value/dFine << ' ' << m.early.standardError/dFine << '\n'
                << "balance " << m.balance.value << ' ' << m.balance.standardError << ' '
                << m.balance.value/dFine << ' ' << m.balance.standardError/dFine << '\n';
    segregation << "# per window (early): ";
    for (double v : m.earlyWindows) segregation << ' ' << v;
    segregation << "\n# per block (balance): ";
    for (double v : m.balanceBlocks) segregation << ' ' << v;
    segregation << "\n# per block, the share of the balance carried by the diffusive term D dc/dy: ";
    for (double v : m.diffusiveShares) segregation << ' ' << v;
    segregation << '\n';
    segregation << "# the top wall's mean load over the sampling: " << m.topWallLoad << " sigma_N\n"
                << "# the top wall's sliding strain since it landed: " << m.slidingStrainAtDrift
                << " when the early drift started, " << m.slidingStrainAtSampling << " when the sampling started\n";
    if (!m.unreachedState().empty())
    {
        segregation << "# warning: " << m.unreachedState() << '\n';
    }
    segregation << "# the early drift's interior: w " << m.earlyDrift << " m/s, gammaDot "
                << m.earlyShearRate << " 1/s, c " << m.earlyCoarseShare << "\n"
                << "# the sampled interior: p* " << m.pressureNumber << ", I "
                << m.inertialNumber << ", gammaDot " << m.shearRate.value << " +- "
                << m.shearRate.standardError << " 1/s, c " << m.coarseShare << ", D "
                << m.diffusivity.value << " +- " << m.diffusivity.standardError << " m2/s, C = D/(gammaDot dMean^2) "
                << m.shearRateDiffusivity.value << " (dMean " << m.meanDiameter << " m)\n";
    // one line for the fit (fitSegregationVelocity): each estimator with the interior's
    // c and gammaDot over the time it was read; C = D/(gammaDot dMean^2) of the sampling
    segregation << "# interior (for fitSegregationVelocity): dFine[m] R phi pStar I S_early[m] S_earlyErr"
                   " c_early gammaDot_early[1/s] S_balance[m] S_balanceErr c gammaDot[1/s] C Cerr"
                   " topWallLoad\n"
                << "interior " << dFine << ' ' << m.sizeRatio << ' ' << m.solidsFraction
                << ' ' << m.pressureNumber << ' ' << m.inertialNumber << ' '
                << m.early.value << ' ' << m.early.standardError << ' ' << m.earlyCoarseShare << ' '
                << m.earlyShearRate << ' ' << m.balance.value << ' ' << m.balance.standardError << ' '
                << m.coarseShare << ' ' << m.shearRate.value << ' '
                << m.shearRateDiffusivity.value << ' ' << m.shearRateDiffusivity.standardError << ' '
                << m.topWallLoad << '\n';
    if (!profiles || !series || !segregation)
    {
        throw std::runtime_error("cannot write " + output + "-profiles.dat, -series.dat or -segregation.dat");
    }
}


} // namespace sdf::dem

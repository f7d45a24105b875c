// runCell: one calibration cell from start to finish. The measurements are objects
// (Measurements.hpp) the sampling loop calls once per sample; this file holds the cell's
// set-up, its equilibration, the sampling with checkpoints, and the thread-scaling mode.

#include "CellRun.hpp"
#include "InitialState.hpp"
#include "Measurements.hpp"
#include "SimulationCheckpoint.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <sstream>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

void validateCellRunSettings(const CellRunSettings& s)
{
    validateSpecies(s.species);
    validateContactSettings(s.simulation.contact);
    if (!s.simulation.contact.pairs.empty())
    {
        ContactLaw(s.simulation.contact, s.species);   // the pairs' species names
    }
    if (s.volumeFractions.size() != s.species.size())
    {
        throw std::invalid_argument("volumeFractions: one value per species required");
    }
    if (s.particles < 2) throw std::invalid_argument("particles must be >= 2");
    if (!(s.samplingTime > 0)) throw std::invalid_argument("samplingTime must be positive");
    if (!(s.equilibrationTime >= 0)) throw std::invalid_argument("equilibrationTime must be >= 0");
    if (s.sampleEvery < 1) throw std::invalid_argument("sampleEvery must be >= 1");
    if (s.blocks < 2) throw std::invalid_argument("blocks must be >= 2 (errors need two)");
    if (s.threadScalingRounds < 0 || (s.threadScalingRounds > 0 && !s.throughputOnly))
    {
        throw std::invalid_argument("threadScalingRounds must be >= 0 and needs throughputOnly");
    }
    if ((s.resume || s.checkpointEvery > 0) && s.checkpointFile.empty())
    {
        throw std::invalid_argument("checkpointFile must be given with checkpointEvery or resume");
    }
    if (s.simulation.mode == CellMode::leesEdwards && !(std::abs(s.simulation.shearRate) > 0))
    {
        throw std::invalid_argument("shearRate must be non-zero for a leesEdwards cell");
    }
    const double p = s.simulation.targetPressure;
    if (!(p >= 0) || !std::isfinite(p))
    {
        throw std::invalid_argument
        (
            "targetPressure must be a finite pressure > 0 Pa (0: volume-controlled), not "
          + std::to_string(p)
        );
    }
    if (p > 0 && s.simulation.mode != CellMode::leesEdwards)
    {
        throw std::invalid_argument
        (
            "targetPressure: pressure control is for a sheared cell (mode leesEdwards), not"
            " mode " + cellModeName(s.simulation.mode)
        );
    }
}

namespace
{

using Clock = std::chrono::steady_clock;

//- Runs the state of sim for nSteps on 1 and on settings' threads, alternately,
//  threadScalingRounds times (the same equilibrated state each time); stores the
//  particle-steps per second in result.threadScaling and prints each round (and, with
//  progress on, each phase's busy times and the list rebuilds).
void measureThreadScaling
(
    const CellRunSettings& settings,
    const std::vector<Species>& species,
    const SimulationSettings& simSettings,
    const Simulation& sim,
    long nSteps,
    CellRunResult& result
)
{
    using clock = std::chrono::steady_clock;
    const SimulationState start = sim.exportState();
    result.scalingThreads = settings.simulation.threads;
#ifdef _OPENMP
    if (result.scalingThreads <= 0) result.scalingThreads = omp_get_max_threads();
#endif
    result.scalingThreads = std::max(1, result.scalingThreads);
    const bool showPhases = settings.progressEvery > 0 && result.scalingThreads > 1;
    // where the time went, per phase: busy seconds of each thread, wall
    const auto show = [](const char* name, const BlockBalance& t)
    {
        std::printf("  %s busy", name);
        for (std::size_t b = 0; b < t.share.size(); ++b) std::printf(" %.3f", t.busySeconds(int(b)));
        if (t.totalWall > 0) std::printf(" s, wall %.3f", t.totalWall);
        std::printf(" s, shares");
        for (const double f : t.share) std::printf(" %.3f", f);
        std::printf("\n");
    };
    for (int round = 0; round < settings.threadScalingRounds; ++round)
    {
        std::array<double, 2> rates{};
        for (int k = 0; k < 2; ++k)
        {
            SimulationSettings st = simSettings;
            st.threads = k == 0 ? 1 : result.scalingThreads;
            Simulation copy(species, st, start.particles, sim.box());
            copy.importState(start);
            const auto t0 = clock::now();
            copy.run(nSteps);
            const double wall = std::chrono::duration<double>(clock::now() - t0).count();
            rates[k] = double(nSteps)*copy.particles().size()/wall;
            if (!showPhases) continue;
            if (k == 1)
            {
                std::printf("%s: %d threads, %.3f s:\n", settings.label.c_str(), result.scalingThreads, wall);
                show("drift", copy.driftTimings());
                show("force pass to the barrier", copy.forceTimings());
                show("cross contacts + finish", copy.finishTimings());
            }
            std::printf
            (
                "  %d thread(s): %ld list rebuilds, wall %.3f s\n", st.threads,
                copy.rebuildTimings().count, copy.rebuildTimings().wallSeconds
            );
        }
        result.threadScaling.push_back(rates);
        if (settings.progressEvery > 0)
        {
            std::printf
            (
                "%s: thread scaling round %d/%d: 1 thread %.4g, %d threads %.4g "
                "particle-steps/s, speed-up %.3f\n",
                settings.label.c_str(), round + 1, settings.threadScalingRounds, rates[0],
                result.scalingThreads, rates[1], rates[1]/rates[0]
            );
            std::fflush(stdout);
        }
    }
}

//- Initial temperature: the given one, else (gammaDot d_mean)^2 if sheared, else the
//  thermostat's target.
double initialTemperature(const CellRunSettings& settings, double dMean)
{
    const SimulationSettings& sim = settings.simulation;
    if (settings.initialTemperature >= 0) return settings.initialTemperature;
    return sim.mode == CellMode::leesEdwards
        ? std::pow(sim.shearRate*dMean, 2)
        : sim.targetTemperature;
}

//- Windows of equilibrationTime/4; equilibrated when the mean T of two consecutive windows
//  differs by < 3 % after the minimum time; under pressure control also their mean solids
//  fractions by < 0.002 and the last window's sigma_yy lies within 10 % of the target.
void equilibrate(Simulation& sim, const CellRunSettings& settings, CellRunResult& result)
{
    const Barostat* barostat = sim.barostat();
    const double dt = sim.timeStep();
    const double maxTime = settings.maxEquilibrationTime > 0
        ? settings.maxEquilibrationTime : 5*settings.equilibrationTime;
    const long window = std::max(1L, std::lround(0.25*settings.equilibrationTime/dt));
    double previous = -1, previousPhi = -1;
    double elapsed = 0;
    while (elapsed < maxTime || previous < 0)
    {
        double sumT = 0, sumPhi = 0, sumStress = 0;
        long n = 0;
        sim.run
        (
            window,
            [&](const Simulation& x)
            {
                sumT += x.temperature();
                if (barostat)
                {
                    sumPhi += x.solidsFraction();
                    sumStress += x.lastBarostatStress();
                }
                ++n;
            },
            std::max(1L, window/50), settings.progressEvery, settings.label + " equilibration"
        );
        elapsed += window*dt;
        const double meanT = n ? sumT/n : sim.temperature();
        const double meanPhi = n ? sumPhi/n : sim.solidsFraction();
        const bool pressureHeld = !barostat
         || (previousPhi > 0 && std::abs(meanPhi - previousPhi) < 0.002
          && n > 0 && std::abs(sumStress/n/barostat->targetPressure() - 1) < 0.1);
        if (barostat && settings.progressEvery > 0)
        {
            std::printf
            (
                "%s equilibration: t %.4g s, phi %.4f, sigma_yy %.4g Pa (target %.4g Pa)\n",
                settings.label.c_str(), elapsed, meanPhi, n ? sumStress/n : 0.0,
                barostat->targetPressure()
            );
        }
        if (elapsed >= settings.equilibrationTime && previous > 0
         && std::abs(meanT - previous) < 0.03*meanT && pressureHeld)
        {
            result.equilibrated = true;
            break;
        }
        previous = meanT;
        previousPhi = meanPhi;
        if (settings.equilibrationTime == 0 && pressureHeld) { result.equilibrated = true; break; }
    }
    result.equilibrationTime = elapsed;
}

//- The measurements of the run: only the temperature and the collisions when it
//  measures its throughput.
Measurements makeMeasurements
(
    const CellRunSettings& settings,
    Simulation& sim,
    const SamplingPlan& plan,
    double T0
)
{
    const std::vector<Species>& species = settings.species;
    const int nSpecies = int(species.size());
    const double energyScale = 0.5*species[0].mass()*std::max(T0, 1e-30);
    Measurements m;
    m.push_back(std::make_unique<TemperatureMeasurement>(nSpecies, plan.blocks, !settings.throughputOnly));
    if (!settings.throughputOnly)
    {
        const std::vector<std::vector<int>> members = speciesMembers(sim);
        m.push_back(std::make_unique<VelocityAutocorrelation>(members, plan, settings.maxMsdFrames));
        m.push_back(std::make_unique<MeanSquareDisplacementMeasurement>(members, plan, settings.maxMsdFrames));
        m.push_back(std::make_unique<StressAutocorrelation>(species, sim.box().volume(), plan));
        m.push_back(std::make_unique<CollectiveMotionMeasurement>(plan.blocks));
        if (settings.simulation.mode == CellMode::leesEdwards)
        {
            m.push_back(std::make_unique<RheologyMeasurement>(plan.blocks));
        }
    }
    m.push_back(std::make_unique<CollisionMeasurement>(sim, energyScale));
    return m;
}

//- Where the sampling stands (what a checkpoint holds besides the simulation and the
//  measurements).
struct SamplingProgress
{
    long sample = 0;
    long stepsDone = 0;
    double wallBefore = 0;     // wall and CPU seconds of the run before a resume
    double cpuBefore = 0;
};

// 2: the collective-motion sums were added (a format-1 checkpoint lacks them); 3: the
// stress series' block means (their products are correlated about them)
const std::string checkpointFormat = "sdf_dem CellRun 4";

void writeCellCheckpoint
(
    const CellRunSettings& settings,
    const Simulation& sim,
    const Measurements& measurements,
    const SamplingPlan& plan,
    const SamplingProgress& progress,
    const CellRunResult& result,
    double wallSeconds,
    double cpuSeconds
)
{
    io::Checkpoint c;
    addSimulationState(c, sim);
    c.strings["cellRun_format"] = checkpointFormat;
    c.integers["cellRun_sample"] = progress.sample;
    c.integers["cellRun_stepsDone"] = progress.stepsDone;
    c.integers["cellRun_totalSteps"] = plan.totalSteps;
    c.integers["cellRun_sampleEvery"] = settings.sampleEvery;
    c.integers["cellRun_equilibrated"] = result.equilibrated ? 1 : 0;
    c.scalars["cellRun_equilibrationTime"] = result.equilibrationTime;
    c.scalars["cellRun_wallSeconds"] = wallSeconds;
    c.scalars["cellRun_cpuSeconds"] = cpuSeconds;
    for (const auto& m : measurements) m->save(c);
    io::writeCheckpoint(settings.checkpointFile, c);
}

void readCellCheckpoint
(
    const CellRunSettings& settings,
    Simulation& sim,
    Measurements& measurements,
    const SamplingPlan& plan,
    SamplingProgress& progress,
    CellRunResult& result
)
{
    const io::Checkpoint c = io::readCheckpoint(settings.checkpointFile);
    const std::string& f = settings.checkpointFile;
    auto needInt = [&](const std::string& k)
    {
        if (!c.integers.count(k)) throw std::runtime_error("checkpoint '" + f + "': missing " + k);
        return c.integers.at(k);
    };
    if (!c.strings.count("cellRun_format") || c.strings.at("cellRun_format") != checkpointFormat)
    {
        throw std::runtime_error
        (
            "checkpoint '" + f + "': not a CellRun checkpoint of this version (format '"
          + checkpointFormat + "'; one written before the stress series' block means or"
            " the collective-motion measurement cannot be resumed: start the run again)"
        );
    }
    if (needInt("cellRun_totalSteps") != plan.totalSteps || needInt("cellRun_sampleEvery") != settings.sampleEvery)
    {
        throw std::invalid_argument
        (
            "checkpoint '" + f + "' was written with other samplingTime/sampleEvery settings"
        );
    }
    loadSimulationState(c, sim, f);
    progress.sample = long(needInt("cellRun_sample"));
    progress.stepsDone = long(needInt("cellRun_stepsDone"));
    result.equilibrated = needInt("cellRun_equilibrated") != 0;
    result.equilibrationTime = c.scalars.at("cellRun_equilibrationTime");
    progress.wallBefore = c.scalars.at("cellRun_wallSeconds");
    progress.cpuBefore = c.scalars.at("cellRun_cpuSeconds");
    for (const auto& m : measurements) m->load(c, f);
    result.resumed = true;
}

//- Runs the sampling, every measurement sampled every sampleEvery steps, with checkpoints
//  (not when only the throughput is measured); false if stopped by stopAfterSteps.
bool sample
(
    const CellRunSettings& settings,
    Simulation& sim,
    Measurements& measurements,
    const SamplingPlan& plan,
    CellRunResult& result
)
{
    const bool checkpoints = !settings.throughputOnly;
    const auto start = Clock::now();
    const std::clock_t cpuStart = std::clock();
    SamplingProgress progress;
    const auto wallNow = [&]()
    {
        return progress.wallBefore + std::chrono::duration<double>(Clock::now() - start).count();
    };
    const auto cpuNow = [&]()
    {
        return progress.cpuBefore + double(std::clock() - cpuStart)/CLOCKS_PER_SEC;
    };
    if (checkpoints && settings.resume)
    {
        readCellCheckpoint(settings, sim, measurements, plan, progress, result);
    }
    const auto observe = [&](const Simulation& x)
    {
        for (const auto& m : measurements) m->sample(x, progress.sample);
        ++progress.sample;
        if (progress.sample % plan.samplesPerBlock == 0 && progress.sample/plan.samplesPerBlock <= plan.blocks)
        {
            for (const auto& m : measurements) m->closeBlock();
        }
    };
    const long totalSteps = plan.totalSteps;
    long chunk = totalSteps;
    if (checkpoints && settings.checkpointEvery > 0)
    {
        chunk = std::max<long>(1, settings.checkpointEvery/settings.sampleEvery)*settings.sampleEvery;
    }
    long stopAt = totalSteps;
    if (checkpoints && settings.stopAfterSteps > 0)
    {
        stopAt = std::min(totalSteps, std::max<long>(1, settings.stopAfterSteps/settings.sampleEvery)*settings.sampleEvery);
    }
    while (progress.stepsDone < totalSteps)
    {
        long n = std::min(chunk, totalSteps - progress.stepsDone);
        if (progress.stepsDone < stopAt) n = std::min(n, stopAt - progress.stepsDone);
        sim.run(n, observe, settings.sampleEvery, settings.progressEvery, settings.label);
        progress.stepsDone += n;
        if (checkpoints && settings.checkpointEvery > 0 && progress.stepsDone < totalSteps)
        {
            writeCellCheckpoint(settings, sim, measurements, plan, progress, result, wallNow(), cpuNow());
        }
        if (progress.stepsDone == stopAt && stopAt < totalSteps)
        {
            result.interrupted = true;
            result.steps = progress.stepsDone;
            return false;
        }
    }
    result.wallSeconds = wallNow();
    result.cpuSeconds = cpuNow();
    result.steps = totalSteps;
    result.particleStepsPerSecond = double(totalSteps)*sim.particles().size()/result.wallSeconds;
    for (const auto& m : measurements) m->finish(result, progress.sample);
    return true;
}

} // namespace

double meanDiameter(const CellRunSettings& settings)
{
    double sum = 0, wsum = 0;
    for (std::size_t s = 0; s < settings.species.size(); ++s)
    {
        sum += settings.volumeFractions[s]*settings.species[s].diameter;
        wsum += settings.volumeFractions[s];
    }
    return sum/wsum;
}

double solidsDensity(const CellRunSettings& settings)
{
    double sum = 0, wsum = 0;
    for (std::size_t s = 0; s < settings.species.size(); ++s)
    {
        sum += settings.volumeFractions[s]*settings.species[s].density;
        wsum += settings.volumeFractions[s];
    }
    return sum/wsum;
}

CellRunSettings atInertialNumber
(
    CellRunSettings settings,
    double inertialNumber,
    double equilibrationStrain,
    double maxEquilibrationStrain,
    double samplingStrain
)
{
    CellRunSettings& s = settings;
    s.simulation.mode = CellMode::leesEdwards;
    s.simulation.shearRate =
        inertialNumber*std::sqrt(s.simulation.targetPressure/solidsDensity(s))/meanDiameter(s);
    s.equilibrationTime = equilibrationStrain/s.simulation.shearRate;
    s.maxEquilibrationTime = maxEquilibrationStrain/s.simulation.shearRate;
    s.samplingTime = samplingStrain/s.simulation.shearRate;
    return s;
}

Packing initialCell(const CellRunSettings& settings, double T0)
{
    PackingSettings ps;
    ps.solidsFraction = settings.solidsFraction;
    ps.counts = countsFromVolumeFractions
    (
        settings.species, settings.volumeFractions, settings.particles
    );
    ps.seed = settings.seed;
    Packing packing = makePacking(settings.species, ps);
    const SimulationSettings& sim = settings.simulation;
    const double shearRate = sim.mode == CellMode::leesEdwards ? sim.shearRate : 0.0;
    // a stochastically driven cell starts at equipartition (InitialState.hpp: its kicks
    // cannot take back the energy the collisions would otherwise release)
    assignVelocities
    (
        packing.particles, packing.box, T0, shearRate, settings.seed,
        sim.mode == CellMode::stochastic
      ? VelocityPartition::equipartition : VelocityPartition::equalVelocities
    );
    if (!settings.lammpsDataFile.empty())
    {
        writeLammpsData
        (
            settings.lammpsDataFile, packing.particles, packing.box, settings.species,
            0.5*shearRate*packing.box.ly
        );
    }
    return packing;
}

CellRunResult runCell(const CellRunSettings& settings)
{
    validateCellRunSettings(settings);
    CellRunResult result;
    result.settings = settings;
    const std::vector<Species>& species = settings.species;
    result.meanDiameter = meanDiameter(settings);
    const double T0 = initialTemperature(settings, result.meanDiameter);
    const Packing packing = initialCell(settings, T0);
    result.boxLength = packing.box.lx;

    // the particles are renumbered in y every 1000 steps (the threads' ranges stay slabs);
    // the per-particle measurements follow ids
    SimulationSettings simSettings = settings.simulation;
    simSettings.seed = settings.seed;   // the stochastic driving's kicks
    if (simSettings.renumberEvery == 0) simSettings.renumberEvery = 1000;
    Simulation sim(species, simSettings, packing.particles, packing.box);
    result.timeStep = sim.timeStep();
    result.speciesCounts = sim.speciesCounts();

    // skipped on resume: the checkpoint holds the sampled state
    if (!settings.resume) equilibrate(sim, settings, result);

    const SamplingPlan plan(settings, sim.timeStep());
    result.diffusionComponent = plan.diffusionComponent;
    result.stressSeriesNames = StressAutocorrelation::seriesNames(species);
    result.meanStress.assign(result.stressSeriesNames.size(), 0.0);
    Measurements measurements = makeMeasurements(settings, sim, plan, T0);

    if (settings.threadScalingRounds > 0)
    {
        measureThreadScaling(settings, species, simSettings, sim, plan.totalSteps, result);
    }
    const std::vector<int> counts = sim.speciesCounts();
    for (std::size_t s = 0; s < species.size(); ++s)
    {
        SpeciesTransport st;
        st.name = species[s].name;
        st.count = counts[s];
        result.species.push_back(st);
    }
    if (!sample(settings, sim, measurements, plan, result)) result.species.clear();
    RheologyResult& rheology = result.rheology;
    if (const Barostat* barostat = sim.barostat(); barostat && rheology.measured)
    {
        rheology.barostatTime = barostat->relaxationTime();
        // a pressure the barostat did not hold is not the condition asked for
        const correlation::Estimate& p = rheology.pressure;
        const double target = barostat->targetPressure();
        const double tolerance = std::isfinite(p.standardError)
            ? std::max(3*p.standardError, 0.05*target) : 0.05*target;
        if (!(std::abs(p.value - target) <= tolerance))
        {
            std::ostringstream msg;
            msg << settings.label << ": the barostat did not hold targetPressure " << target
                << " Pa: sigma_yy reached " << p.value << " +- " << p.standardError
                << " Pa at solids fraction " << rheology.solidsFraction.value
                << " (barostatTime " << barostat->relaxationTime() << " s, equilibrated: "
                << (result.equilibrated ? "yes" : "no") << "); lengthen equilibrationTime"
                << " or samplingTime, or shorten barostatTime";
            throw std::runtime_error(msg.str());
        }
    }
    return result;
}

SampledSchedule sampledSchedule(const CellRunSettings& settings, double dt, long rows)
{
    SampledSchedule s;
    s.sampleEvery = std::max(1, settings.sampleEvery);
    s.equilibrationSteps = std::lround(settings.equilibrationTime/dt);
    s.blockSteps = std::max
    (
        s.sampleEvery, std::lround(settings.samplingTime/settings.blocks/dt)/s.sampleEvery*s.sampleEvery
    );
    s.seriesSamples = std::max(1L, (s.equilibrationSteps + settings.blocks*s.blockSteps)/rows/s.sampleEvery);
    s.seriesEvery = s.seriesSamples*s.sampleEvery;
    return s;
}


} // namespace sdf::dem

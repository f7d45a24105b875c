#include "CellRun.hpp"
#include "InitialState.hpp"
#ifdef SDF_DEM_HAVE_HDF5
#include "SimulationCheckpoint.hpp"
#endif

#include "correlation/MeanSquareDisplacement.hpp"
#include "correlation/MultipleTauCorrelator.hpp"
#include "correlation/Statistics.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <cmath>
#include <cstdio>
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
#ifndef SDF_DEM_HAVE_HDF5
    if (s.resume || s.checkpointEvery > 0)
    {
        throw std::invalid_argument("checkpoints need HDF5 (built without sdf_io)");
    }
#endif
    if (s.simulation.mode == CellMode::leesEdwards && !(std::abs(s.simulation.shearRate) > 0))
    {
        throw std::invalid_argument("shearRate must be non-zero for a leesEdwards cell");
    }
}

namespace
{

correlation::MultipleTauSettings correlatorSettings()
{
    correlation::MultipleTauSettings m;
    m.pointsPerLevel = 16;
    m.averagingFactor = 2;
    m.levels = 24;
    return m;
}

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

} // namespace

CellRunResult runCell(const CellRunSettings& settings)
{
    validateCellRunSettings(settings);
    using clock = std::chrono::steady_clock;
    CellRunResult result;
    result.settings = settings;
    const std::vector<Species>& species = settings.species;
    const int nSpecies = int(species.size());

    // mean diameter weighted by solids volume
    {
        double sum = 0, wsum = 0;
        for (int s = 0; s < nSpecies; ++s)
        {
            sum += settings.volumeFractions[s]*species[s].diameter;
            wsum += settings.volumeFractions[s];
        }
        result.meanDiameter = sum/wsum;
    }

    PackingSettings ps;
    ps.solidsFraction = settings.solidsFraction;
    ps.counts = countsFromVolumeFractions(species, settings.volumeFractions, settings.particles);
    ps.seed = settings.seed;
    Packing packing = makePacking(species, ps);

    const SimulationSettings& sim0 = settings.simulation;
    double T0 = settings.initialTemperature;
    if (T0 < 0)
    {
        T0 = sim0.mode == CellMode::leesEdwards
            ? std::pow(sim0.shearRate*result.meanDiameter, 2)
            : sim0.targetTemperature;
    }
    const double shearRate = sim0.mode == CellMode::leesEdwards ? sim0.shearRate : 0.0;
    assignVelocities(packing.particles, packing.box, T0, shearRate, settings.seed);
    result.boxLength = packing.box.lx;
    if (!settings.lammpsDataFile.empty())
    {
        writeLammpsData
        (
            settings.lammpsDataFile, packing.particles, packing.box, species,
            0.5*shearRate*packing.box.ly
        );
    }

    // the particles are renumbered in y every 1000 steps (the threads' ranges stay slabs);
    // the per-particle measurements below follow ids
    SimulationSettings simSettings = sim0;
    if (simSettings.renumberEvery == 0) simSettings.renumberEvery = 1000;
    Simulation sim(species, simSettings, packing.particles, packing.box);
    result.timeStep = sim.timeStep();
    result.speciesCounts = sim.speciesCounts();
    const double dt = sim.timeStep();

    // --- equilibration: windows of equilibrationTime/4; equilibrated when the mean T of
    // two consecutive windows differs by < 3 % after the minimum time (skipped on resume:
    // the checkpoint holds the sampled state)
    if (!settings.resume)
    {
        const double maxTime = settings.maxEquilibrationTime > 0
            ? settings.maxEquilibrationTime : 5*settings.equilibrationTime;
        const long window = std::max(1L, std::lround(0.25*settings.equilibrationTime/dt));
        double previous = -1;
        double elapsed = 0;
        while (elapsed < maxTime || previous < 0)
        {
            double sumT = 0;
            long n = 0;
            sim.run(window, [&](const Simulation& x) { sumT += x.temperature(); ++n; },
                    std::max(1L, window/50), settings.progressEvery, settings.label + " equilibration");
            elapsed += window*dt;
            const double meanT = n ? sumT/n : sim.temperature();
            if (elapsed >= settings.equilibrationTime && previous > 0
             && std::abs(meanT - previous) < 0.03*meanT)
            {
                result.equilibrated = true;
                break;
            }
            previous = meanT;
            if (settings.equilibrationTime == 0) { result.equilibrated = true; break; }
        }
        result.equilibrationTime = elapsed;
    }

    // --- sampling
    const int comp = sim0.mode == CellMode::leesEdwards ? 1 : -1;
    result.diffusionComponent = comp;
    const long totalSteps = std::max(1L, std::lround(settings.samplingTime/dt));
    const long nSamples = std::max(1L, totalSteps/settings.sampleEvery);
    const long samplesPerBlock = std::max(1L, nSamples/settings.blocks);
    const double sampleInterval = settings.sampleEvery*dt;
    const long msdEvery = std::max(1L, (nSamples + settings.maxMsdFrames - 1)/settings.maxMsdFrames);

    // per species: the particle ids, in increasing id (the same on resume, whatever the
    // particles' current order)
    std::vector<std::vector<int>> members(nSpecies);
    for (int id = 0; id < int(sim.particles().size()); ++id)
    {
        members[sim.particles().species[sim.indexOfId(id)]].push_back(id);
    }
    std::vector<correlation::MultipleTauCorrelator> vacf;
    for (int s = 0; s < nSpecies; ++s)
    {
        vacf.emplace_back(std::max<std::size_t>(1, members[s].size()), 3, correlatorSettings());
    }
    std::vector<correlation::VectorFrames> frames(nSpecies);

    // stress series: species parts, then cross parts
    std::vector<std::pair<int, int>> parts;
    for (int s = 0; s < nSpecies; ++s)
    {
        parts.push_back({s, s});
        result.stressSeriesNames.push_back("J_" + species[s].name);
    }
    for (int s = 0; s < nSpecies; ++s)
    {
        for (int t = s + 1; t < nSpecies; ++t)
        {
            parts.push_back({s, t});
            result.stressSeriesNames.push_back("J_" + species[s].name + "_" + species[t].name);
        }
    }
    const std::size_t nSeries = parts.size();
    correlation::SeriesProductCorrelator stressCorrelator(nSeries, correlatorSettings());
    result.meanStress.assign(nSeries, 0.0);
    const double volume = sim.box().volume();
    const double sqrtV = std::sqrt(volume);

    std::vector<double> temperatureSeries;
    std::vector<std::vector<double>> speciesT(nSpecies);

    double eScale = 0.5*species[0].mass()*std::max(T0, 1e-30);
    sim.enableCollisionStatistics(1e-4*eScale, 1e3*eScale, 56);

    long sample = 0;
    if (settings.threadScalingRounds > 0)
    {
        measureThreadScaling(settings, species, simSettings, sim, totalSteps, result);
    }
    if (settings.throughputOnly)
    {
        std::vector<double> ts;
        const auto t0 = clock::now();
        const std::clock_t c0 = std::clock();
        sim.run(totalSteps, [&](const Simulation& x) { ts.push_back(x.temperature()); },
                settings.sampleEvery, settings.progressEvery, settings.label);
        result.wallSeconds = std::chrono::duration<double>(clock::now() - t0).count();
        result.cpuSeconds = double(std::clock() - c0)/CLOCKS_PER_SEC;
        result.steps = totalSteps;
        result.particleStepsPerSecond = double(totalSteps)*sim.particles().size()/result.wallSeconds;
        const correlation::Estimate T = correlation::blockAverage(ts, settings.blocks);
        result.temperature = T.value;
        result.temperatureError = T.standardError;
        if (sim0.mode == CellMode::leesEdwards && T.value > 0)
        {
            result.savageJeffreyR = result.meanDiameter*std::abs(sim0.shearRate)*std::sqrt(3.0/T.value);
        }
        for (int s = 0; s < nSpecies; ++s)
        {
            SpeciesTransport st;
            st.name = species[s].name;
            st.count = int(members[s].size());
            result.species.push_back(st);
        }
        result.collisions = sim.collisionStatistics();
        return result;
    }
    const auto start = clock::now();
    const std::clock_t cpuStart = std::clock();
    auto observe = [&](const Simulation& x)
    {
        const Particles& p = x.particles();
        for (int s = 0; s < nSpecies; ++s)
        {
            const std::vector<int>& m = members[s];
            if (m.empty()) continue;
            Eigen::ArrayXXd v(m.size(), 3);
            for (std::size_t k = 0; k < m.size(); ++k)
            {
                const Eigen::Vector3d c = x.fluctuatingVelocity(x.indexOfId(m[k]));
                v(k, 0) = c.x(); v(k, 1) = c.y(); v(k, 2) = c.z();
            }
            vacf[s].add(v);
            if (sample % msdEvery == 0)
            {
                Eigen::MatrixX3d pos(m.size(), 3);
                for (std::size_t k = 0; k < m.size(); ++k)
                {
                    const int i = x.indexOfId(m[k]);
                    pos(k, 0) = p.ux[i]; pos(k, 1) = p.uy[i]; pos(k, 2) = p.uz[i];
                }
                frames[s].push_back(pos);
            }
        }
        const StressSplit J = x.stressSplit();
        Eigen::VectorXd series(nSeries);
        for (std::size_t k = 0; k < nSeries; ++k)
        {
            const auto [a, b] = parts[k];
            const Eigen::Matrix3d Jk = a == b ? J.speciesStress(a) : J.crossStress(a, b);
            series[k] = Jk(0, 1)/sqrtV;
            result.meanStress[k] += Jk(0, 1)/volume;
        }
        stressCorrelator.add(series);
        temperatureSeries.push_back(x.temperature());
        const std::vector<double> ts = x.speciesTemperatures();
        for (int s = 0; s < nSpecies; ++s) speciesT[s].push_back(ts[s]);
        ++sample;
        if (sample % samplesPerBlock == 0 && sample/samplesPerBlock <= settings.blocks)
        {
            for (auto& c : vacf) c.closeBlock();
            stressCorrelator.closeBlock();
        }
    };
    long stepsDone = 0;
    double wallBefore = 0, cpuBefore = 0;
#ifdef SDF_DEM_HAVE_HDF5
    const std::string ckFormat = "sdf_dem CellRun 1";
    auto flatten = [](const correlation::VectorFrames& f)
    {
        std::vector<double> v;
        for (const Eigen::MatrixX3d& m : f)
        {
            for (Eigen::Index r = 0; r < m.rows(); ++r)
            {
                v.push_back(m(r, 0)); v.push_back(m(r, 1)); v.push_back(m(r, 2));
            }
        }
        return v;
    };
    auto writeCheckpointNow = [&]()
    {
        io::Checkpoint c;
        addSimulationState(c, sim);
        c.strings["cellRun_format"] = ckFormat;
        c.integers["cellRun_sample"] = sample;
        c.integers["cellRun_stepsDone"] = stepsDone;
        c.integers["cellRun_totalSteps"] = totalSteps;
        c.integers["cellRun_sampleEvery"] = settings.sampleEvery;
        c.integers["cellRun_equilibrated"] = result.equilibrated ? 1 : 0;
        c.scalars["cellRun_equilibrationTime"] = result.equilibrationTime;
        c.scalars["cellRun_wallSeconds"] = wallBefore + std::chrono::duration<double>(clock::now() - start).count();
        c.scalars["cellRun_cpuSeconds"] = cpuBefore + double(std::clock() - cpuStart)/CLOCKS_PER_SEC;
        c.vectors["cellRun_temperature"] = temperatureSeries;
        c.vectors["cellRun_meanStress"] = result.meanStress;
        for (int s = 0; s < nSpecies; ++s)
        {
            const std::string k = std::to_string(s);
            c.vectors["cellRun_speciesT" + k] = speciesT[s];
            c.vectors["cellRun_frames" + k] = flatten(frames[s]);
            const correlation::MultipleTauState st = vacf[s].exportState();
            c.vectors["cellRun_vacfReals" + k] = st.reals;
            c.integerVectors["cellRun_vacfIntegers" + k] = st.integers;
        }
        const correlation::MultipleTauState ss = stressCorrelator.exportState();
        c.vectors["cellRun_stressReals"] = ss.reals;
        c.integerVectors["cellRun_stressIntegers"] = ss.integers;
        const CollisionStatistics& col = sim.collisionStatistics();
        c.scalars["cellRun_collisionTime"] = col.elapsedTime;
        c.vectors["cellRun_collisionEnergy"] = col.energySum;
        c.integerVectors["cellRun_collisionCounts"].assign(col.counts.begin(), col.counts.end());
        std::vector<std::int64_t> hist;
        for (const auto& h : col.histogram) hist.insert(hist.end(), h.begin(), h.end());
        c.integerVectors["cellRun_collisionHistogram"] = hist;
        io::writeCheckpoint(settings.checkpointFile, c);
    };
    if (settings.resume)
    {
        const io::Checkpoint c = io::readCheckpoint(settings.checkpointFile);
        const std::string& f = settings.checkpointFile;
        auto needInt = [&](const std::string& k)
        {
            if (!c.integers.count(k)) throw std::runtime_error("checkpoint '" + f + "': missing " + k);
            return c.integers.at(k);
        };
        if (!c.strings.count("cellRun_format") || c.strings.at("cellRun_format") != ckFormat)
        {
            throw std::runtime_error("checkpoint '" + f + "': not a CellRun checkpoint");
        }
        if (needInt("cellRun_totalSteps") != totalSteps || needInt("cellRun_sampleEvery") != settings.sampleEvery)
        {
            throw std::invalid_argument
            (
                "checkpoint '" + f + "' was written with other samplingTime/sampleEvery settings"
            );
        }
        loadSimulationState(c, sim, f);
        sample = long(needInt("cellRun_sample"));
        stepsDone = long(needInt("cellRun_stepsDone"));
        result.equilibrated = needInt("cellRun_equilibrated") != 0;
        result.equilibrationTime = c.scalars.at("cellRun_equilibrationTime");
        wallBefore = c.scalars.at("cellRun_wallSeconds");
        cpuBefore = c.scalars.at("cellRun_cpuSeconds");
        temperatureSeries = c.vectors.at("cellRun_temperature");
        result.meanStress = c.vectors.at("cellRun_meanStress");
        for (int s = 0; s < nSpecies; ++s)
        {
            const std::string k = std::to_string(s);
            speciesT[s] = c.vectors.at("cellRun_speciesT" + k);
            const std::vector<double>& fl = c.vectors.at("cellRun_frames" + k);
            const std::size_t rows = members[s].size();
            frames[s].clear();
            if (rows > 0)
            {
                for (std::size_t off = 0; off + 3*rows <= fl.size(); off += 3*rows)
                {
                    Eigen::MatrixX3d m(rows, 3);
                    for (std::size_t r = 0; r < rows; ++r)
                    {
                        m(r, 0) = fl[off + 3*r]; m(r, 1) = fl[off + 3*r + 1]; m(r, 2) = fl[off + 3*r + 2];
                    }
                    frames[s].push_back(m);
                }
            }
            correlation::MultipleTauState st;
            st.reals = c.vectors.at("cellRun_vacfReals" + k);
            st.integers = c.integerVectors.at("cellRun_vacfIntegers" + k);
            vacf[s].importState(st);
        }
        correlation::MultipleTauState ss;
        ss.reals = c.vectors.at("cellRun_stressReals");
        ss.integers = c.integerVectors.at("cellRun_stressIntegers");
        stressCorrelator.importState(ss);
        CollisionStatistics col = sim.collisionStatistics();
        col.elapsedTime = c.scalars.at("cellRun_collisionTime");
        col.energySum = c.vectors.at("cellRun_collisionEnergy");
        const auto& counts = c.integerVectors.at("cellRun_collisionCounts");
        col.counts.assign(counts.begin(), counts.end());
        const auto& hist = c.integerVectors.at("cellRun_collisionHistogram");
        const std::size_t nb = col.histogram.empty() ? 0 : col.histogram[0].size();
        if (hist.size() != nb*col.histogram.size())
        {
            throw std::runtime_error("checkpoint '" + f + "': collision histogram does not fit");
        }
        for (std::size_t a = 0; a < col.histogram.size(); ++a)
        {
            for (std::size_t b = 0; b < nb; ++b) col.histogram[a][b] = hist[a*nb + b];
        }
        sim.setCollisionStatistics(col);
        result.resumed = true;
    }
#endif
    long chunk = totalSteps;
    if (settings.checkpointEvery > 0)
    {
        chunk = std::max<long>(1, settings.checkpointEvery/settings.sampleEvery)*settings.sampleEvery;
    }
    long stopAt = totalSteps;
    if (settings.stopAfterSteps > 0)
    {
        stopAt = std::min(totalSteps, std::max<long>(1, settings.stopAfterSteps/settings.sampleEvery)*settings.sampleEvery);
    }
    while (stepsDone < totalSteps)
    {
        long n = std::min(chunk, totalSteps - stepsDone);
        if (stepsDone < stopAt) n = std::min(n, stopAt - stepsDone);
        sim.run(n, observe, settings.sampleEvery, settings.progressEvery, settings.label);
        stepsDone += n;
#ifdef SDF_DEM_HAVE_HDF5
        if (settings.checkpointEvery > 0 && stepsDone < totalSteps) writeCheckpointNow();
#endif
        if (stepsDone == stopAt && stopAt < totalSteps)
        {
            result.interrupted = true;
            result.steps = stepsDone;
            return result;
        }
    }
    result.wallSeconds = wallBefore + std::chrono::duration<double>(clock::now() - start).count();
    result.cpuSeconds = cpuBefore + double(std::clock() - cpuStart)/CLOCKS_PER_SEC;
    result.steps = totalSteps;
    result.particleStepsPerSecond = double(totalSteps)*sim.particles().size()/result.wallSeconds;
    for (double& m : result.meanStress) m /= std::max(1L, sample);

    // --- analysis
    const correlation::Estimate T = correlation::blockAverage(temperatureSeries, settings.blocks);
    result.temperature = T.value;
    result.temperatureError = T.standardError;
    if (sim0.mode == CellMode::leesEdwards && T.value > 0)
    {
        result.savageJeffreyR = result.meanDiameter*std::abs(sim0.shearRate)*std::sqrt(3.0/T.value);
    }
    correlation::PlateauSettings plateau;
    plateau.earliestTime = sampleInterval;
    for (int s = 0; s < nSpecies; ++s)
    {
        SpeciesTransport st;
        st.name = species[s].name;
        st.count = int(members[s].size());
        double sumT = 0;
        for (double v : speciesT[s]) sumT += v;
        st.temperature = speciesT[s].empty() ? 0 : sumT/speciesT[s].size();
        if (!members[s].empty() && vacf[s].blocks().size() >= 2)
        {
            st.greenKubo = correlation::greenKubo(vacf[s].blocks(), sampleInterval, comp, plateau);
        }
        // Einstein: MSD of y (sheared) or x+y+z (homogeneous), fit over the last 60 % of
        // the lag range, per block
        const std::size_t nFrames = frames[s].size();
        const std::size_t nBlocks = std::size_t(settings.blocks);
        if (!members[s].empty() && nFrames >= 8*nBlocks)
        {
            const std::size_t maxLag = nFrames/nBlocks/2;
            const auto blockMsd = correlation::blockMeanSquareDisplacements(frames[s], maxLag, nBlocks);
            const double frameInterval = msdEvery*sampleInterval;
            std::vector<double> times(maxLag + 1);
            for (std::size_t k = 0; k <= maxLag; ++k) times[k] = k*frameInterval;
            std::vector<std::vector<double>> series;
            for (const Eigen::MatrixX3d& b : blockMsd)
            {
                std::vector<double> v(maxLag + 1);
                for (std::size_t k = 0; k <= maxLag; ++k)
                {
                    v[k] = comp == 1 ? b(k, 1) : b(k, 0) + b(k, 1) + b(k, 2);
                }
                series.push_back(v);
            }
            const auto einstein = correlation::einsteinDiffusivity
            (
                times, series, 0.4*times.back(), times.back(), comp == 1 ? 1 : 3
            );
            st.diffusivityMsd = einstein.diffusivity;
            st.msdTimes = times;
            st.msd = einstein.meanMsd;
        }
        result.species.push_back(st);
    }
    if (stressCorrelator.blocks().size() >= 2)
    {
        result.stressIntegrals = correlation::stressProductIntegrals
        (
            stressCorrelator.blocks(), sampleInterval, nSeries, plateau
        );
        if (nSpecies == 2)
        {
            result.kineticSieving = correlation::kineticSievingCoefficients
            (
                result.stressIntegrals, settings.volumeFractions
            );
        }
    }
    result.collisions = sim.collisionStatistics();
    return result;
}

void writeLammpsData
(
    const std::string& path,
    const Particles& p,
    const PeriodicBox& box,
    const std::vector<Species>& species,
    double streamingShift
)
{
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write LAMMPS data file '" + path + "'");
    out.precision(17);
    out << "LAMMPS data file written by sdf_dem (SI units)\n\n"
        << p.size() << " atoms\n" << species.size() << " atom types\n\n"
        << "0 " << box.lx << " xlo xhi\n0 " << box.ly << " ylo yhi\n0 " << box.lz << " zlo zhi\n"
        << box.offset << " 0 0 xy xz yz\n\nAtoms # sphere\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Species& s = species[p.species[i]];
        out << i + 1 << " " << p.species[i] + 1 << " " << 2*p.radius[i] << " " << s.density
            << " " << p.x[i] << " " << p.y[i] << " " << p.z[i] << "\n";
    }
    out << "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        out << i + 1 << " " << p.vx[i] + streamingShift << " " << p.vy[i] << " " << p.vz[i] << " "
            << p.wx[i] << " " << p.wy[i] << " " << p.wz[i] << "\n";
    }
}

std::string summary(const CellRunResult& r)
{
    std::ostringstream out;
    const auto& s = r.settings;
    out << "periodic cell: " << cellModeName(s.simulation.mode) << ", N = " << s.particles
        << ", phi = " << s.solidsFraction << ", box " << r.boxLength << " m, dt = "
        << r.timeStep << " s, " << contactModelName(s.simulation.contact.model)
        << ", e = " << s.simulation.contact.restitution << ", mu = "
        << s.simulation.contact.friction << "\n";
    out << "  equilibrated: " << (r.equilibrated ? "yes" : "NO") << " after "
        << r.equilibrationTime << " s\n";
    out << "  T = " << r.temperature << " +- " << r.temperatureError
        << " m2/s2 (sum of 3 components; T1 = T/3)\n";
    if (s.simulation.mode == CellMode::leesEdwards)
    {
        out << "  gammaDot = " << s.simulation.shearRate << " 1/s, Savage-Jeffrey R = "
            << r.savageJeffreyR << "\n";
    }
    if (r.settings.throughputOnly)
    {
        out << "  throughput " << r.particleStepsPerSecond << " particle-steps/s ("
            << r.steps << " steps, " << r.wallSeconds << " s, CPU use "
            << 100*r.cpuSeconds/r.wallSeconds << " %)\n";
        if (!r.threadScaling.empty())
        {
            std::vector<double> speedUps;
            for (const auto& rates : r.threadScaling) speedUps.push_back(rates[1]/rates[0]);
            std::sort(speedUps.begin(), speedUps.end());
            const std::size_t m = speedUps.size();
            const double median = m % 2 ? speedUps[m/2] : 0.5*(speedUps[m/2 - 1] + speedUps[m/2]);
            out << "  thread scaling (" << m << " rounds, same state): speed-up on "
                << r.scalingThreads << " threads: median " << median << ", min "
                << speedUps.front() << ", max " << speedUps.back() << "\n";
            for (const auto& rates : r.threadScaling)
            {
                out << "    1 thread " << rates[0] << ", " << r.scalingThreads << " threads "
                    << rates[1] << " particle-steps/s\n";
            }
        }
        return out.str();
    }
    for (const SpeciesTransport& st : r.species)
    {
        out << "  " << st.name << " (" << st.count << "): T = " << st.temperature
            << ", D_GK = " << st.greenKubo.integral.value << " +- "
            << st.greenKubo.integral.standardError << " m2/s"
            << (st.greenKubo.plateauFound ? "" : " (no plateau)")
            << ", D_MSD = " << st.diffusivityMsd.value << " +- "
            << st.diffusivityMsd.standardError << " m2/s\n";
    }
    for (std::size_t k = 0; k < r.kineticSieving.size(); ++k)
    {
        out << "  eta_" << r.species[k].name << " = " << r.kineticSieving[k].value << " +- "
            << r.kineticSieving[k].standardError << "\n";
    }
    if (!r.stressIntegrals.terms.empty())
    {
        out << "  stress ACF cross/product ratio = " << r.stressIntegrals.crossToProductRatio << "\n";
    }
    const int n = int(r.species.size());
    for (int a = 0; a < n; ++a)
    {
        for (int b = a; b < n; ++b)
        {
            out << "  collisions " << r.species[a].name << "-" << r.species[b].name << ": "
                << r.collisions.counts[speciesPairIndex(a, b, n)] << ", per "
                << r.species[a].name << " particle "
                << r.collisions.frequencyPerParticle(a, b, r.speciesCounts) << " 1/s\n";
        }
    }
    out << "  throughput " << r.particleStepsPerSecond << " particle-steps/s ("
        << r.steps << " steps, " << r.wallSeconds << " s, CPU use "
        << 100*r.cpuSeconds/r.wallSeconds << " %)\n";
    return out.str();
}

} // namespace sdf::dem

// kineticSievingCell: the direct kinetic-sieving test. A periodic binary cell driven by a
// Kolmogorov body force (dem/KolmogorovForcing.hpp) carries a sinusoidal mean flow
// u_x(y) = U sin(k y): high shear where u_x = 0, none where |u_x| is largest, the
// temperature set by shear heating against inelastic cooling. Starting from a random
// mixture it records how the coarse species redistributes across the layers and, after
// equilibrationTime, the profiles of the steady state per layer with block errors.
//
//   kineticSievingCell cell.cfg [key=value ...]      command-line pairs override the file
//
// Keys: those of the cell as for periodicDEM-cli (species, volumeFractions, particles,
// solidsFraction, the contact constants, model, pairs, timeStep, seed, threads,
// equilibrationTime, samplingTime, sampleEvery, blocks, progressEvery, label), and
//   forcingAmplitude  a0 of the body force a0 sin(2 pi m y/ly) [m/s^2] (required)
//   forcingWaves      m, periods over the box height (default 1)
//   layers            layers in y for the profiles (default 16)
//   output            prefix of the output files (default kineticSievingCell)
// The forcing sets the flow and the temperature: mode, temperature, shearRate and
// thermostatTime are refused.
//
// Output (text, one header line per column):
//   <output>-series.dat    t, mixture T about the mean flow's fit, the flow's sine and
//                          cosine amplitudes, and A: the coarse fraction's mode
//                          cos(2 k y) (A > 0: coarse in the high-shear layers)
//   <output>-profiles.dat  per layer: y, solids fraction, coarse fraction of the solids,
//                          u_x, T about the layer's mean velocity, each with its block
//                          standard error
// The species are taken in the order given; the last one is "coarse" (the largest).
#include "CellConfig.hpp"
#include "InitialState.hpp"
#include "KolmogorovForcing.hpp"

#include "correlation/Statistics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <stdexcept>

using namespace sdf::dem;

namespace
{

std::set<std::string> validKeys()
{
    std::set<std::string> keys = cellConfigKeys();
    keys.insert({"forcingAmplitude", "forcingWaves", "layers", "output"});
    return keys;
}

//- Sums over the particles of one layer at one sample.
struct LayerSums
{
    VelocityChunkSums::Totals velocity{};   // mass, m v, v, |v|^2 (Driving.hpp layout)
    int count = 0;
    double solidsVolume = 0;
    double coarseVolume = 0;
};

std::vector<LayerSums> layerSums(const Simulation& sim, int layers, int coarse)
{
    const Particles& p = sim.particles();
    const double ly = sim.box().ly;
    std::vector<LayerSums> sums(static_cast<std::size_t>(layers));
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const int l = std::min(layers - 1, int(p.y[i]/ly*layers));
        LayerSums& s = sums[std::size_t(l)];
        const double vx = p.vx[i], vy = p.vy[i], vz = p.vz[i];
        double* t = s.velocity.data();
        t[0] += p.mass[i]; t[1] += p.mass[i]*vx; t[2] += p.mass[i]*vy; t[3] += p.mass[i]*vz;
        t[4] += vx; t[5] += vy; t[6] += vz; t[7] += vx*vx + vy*vy + vz*vz;
        const double volume = 4.0/3.0*M_PI*std::pow(p.radius[i], 3);
        s.solidsVolume += volume;
        ++s.count;
        if (p.species[i] == coarse) s.coarseVolume += volume;
    }
    return sums;
}

//- One line of the series: the mean flow's Fourier amplitudes, T about the fitted flow,
//  the coarse fraction's cos(2 k y) mode.
struct SeriesPoint
{
    double sine = 0, cosine = 0, temperature = 0, segregation = 0;
};

SeriesPoint seriesPoint(const Simulation& sim, double k, int coarse)
{
    const Particles& p = sim.particles();
    const int n = int(p.size());
    double mass = 0, ms = 0, mc = 0, volume = 0, coarseCos = 0;
    for (int i = 0; i < n; ++i)
    {
        mass += p.mass[i];
        ms += p.mass[i]*p.vx[i]*std::sin(k*p.y[i]);
        mc += p.mass[i]*p.vx[i]*std::cos(k*p.y[i]);
        const double v = std::pow(p.radius[i], 3);
        volume += v;
        if (p.species[i] == coarse) coarseCos += v*std::cos(2*k*p.y[i]);
    }
    SeriesPoint s;
    // u_x(y) = sine sin(k y) + cosine cos(k y): projections of a uniform mass density
    s.sine = 2*ms/mass;
    s.cosine = 2*mc/mass;
    s.segregation = 2*coarseCos/volume;
    double sum = 0;
    for (int i = 0; i < n; ++i)
    {
        const double cx = p.vx[i] - s.sine*std::sin(k*p.y[i]) - s.cosine*std::cos(k*p.y[i]);
        sum += cx*cx + p.vy[i]*p.vy[i] + p.vz[i]*p.vz[i];
    }
    s.temperature = sum/n;
    return s;
}

void refuse(const CellConfig& config, const std::string& key)
{
    if (config.count(key))
    {
        throw std::invalid_argument
        (
            "entry '" + key + "' is not used by the Kolmogorov cell: the forcing"
            " (forcingAmplitude, forcingWaves) sets the flow and the temperature"
        );
    }
}

//- Mean and block standard error of the per-block values.
std::pair<double, double> blockMean(const std::vector<double>& values)
{
    const sdf::correlation::Estimate e = sdf::correlation::meanAndStandardError(values);
    return {e.value, e.standardError};
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: kineticSievingCell cell.cfg [key=value ...]\n";
        return 2;
    }
    try
    {
        const CellConfig config = readCellConfig(argv[1], argc, argv, 2, validKeys());
        for (const char* key : {"mode", "temperature", "shearRate", "thermostatTime"})
        {
            refuse(config, key);
        }
        CellRunSettings settings = cellRunSettingsFrom(config);
        settings.simulation.mode = CellMode::nve;
        validateCellRunSettings(settings);
        if (settings.species.size() < 2)
        {
            throw std::invalid_argument("entry 'species': the sieving cell needs two species (fine, coarse)");
        }
        const double amplitude = configNumber(config, "forcingAmplitude", 0);
        const double wavesValue = configNumber(config, "forcingWaves", 1);
        const double layersValue = configNumber(config, "layers", 16);
        if (wavesValue != std::floor(wavesValue) || wavesValue < 1 || wavesValue > 1000)
        {
            throw std::invalid_argument("entry 'forcingWaves': a whole number in [1, 1000], got " + config.at("forcingWaves"));
        }
        if (layersValue != std::floor(layersValue) || layersValue < 2 || layersValue > 10000)
        {
            throw std::invalid_argument("entry 'layers': a whole number in [2, 10000], got " + config.at("layers"));
        }
        const int layers = int(layersValue);
        const std::string output = configText(config, "output", "kineticSievingCell");
        const int coarse = int(settings.species.size()) - 1;

        PackingSettings ps;
        ps.solidsFraction = settings.solidsFraction;
        ps.counts = countsFromVolumeFractions(settings.species, settings.volumeFractions, settings.particles);
        ps.seed = settings.seed;
        Packing packing = makePacking(settings.species, ps);
        double dMean = 0;
        for (std::size_t s = 0; s < settings.species.size(); ++s)
        {
            dMean += settings.volumeFractions[s]*settings.species[s].diameter;
        }
        // a start well below the sheared state's temperature (the forcing heats the cell)
        assignVelocities(packing.particles, packing.box, 0.01*amplitude*dMean, 0, settings.seed);
        SimulationSettings simSettings = settings.simulation;
        simSettings.renumberEvery = 1000;
        Simulation sim(settings.species, simSettings, packing.particles, packing.box);
        auto forcing = std::make_unique<KolmogorovForcing>
        (
            amplitude, int(wavesValue), sim.box().ly, sim.timeStep()
        );
        const double k = forcing->wavenumber();
        sim.setDriving(std::move(forcing));

        const double dt = sim.timeStep();
        const long sampleEvery = std::max(1, settings.sampleEvery);
        const long equilibrationSteps = std::lround(settings.equilibrationTime/dt);
        const long blockSteps =
            std::max(sampleEvery, std::lround(settings.samplingTime/settings.blocks/dt)/sampleEvery*sampleEvery);
        // about 2000 lines, on the samples' grid
        const long seriesEvery =
            std::max(1L, (equilibrationSteps + settings.blocks*blockSteps)/2000/sampleEvery)*sampleEvery;
        std::cout << "Kolmogorov cell: " << sim.particles().size() << " particles, box "
                  << sim.box().lx << " m, dt " << dt << " s, a0 " << amplitude
                  << " m/s^2, k " << k << " 1/m; " << equilibrationSteps << " steps to the steady state, "
                  << settings.blocks << " blocks of " << blockSteps << " steps\n";

        std::ofstream series(output + "-series.dat");
        series << "# t[s] T[m2/s2] uSine[m/s] uCosine[m/s] coarseModeCos2ky[-]\n"
               << std::setprecision(8);
        auto writeSeries = [&](const Simulation& s)
        {
            const SeriesPoint p = seriesPoint(s, k, coarse);
            if (!std::isfinite(p.temperature) || !std::isfinite(p.sine))
            {
                throw std::runtime_error("Kolmogorov cell: the flow is not finite at t = " + std::to_string(s.time()));
            }
            series << s.time() << ' ' << p.temperature << ' ' << p.sine << ' ' << p.cosine
                   << ' ' << p.segregation << '\n';
        };
        writeSeries(sim);
        sim.run(equilibrationSteps, writeSeries, seriesEvery, settings.progressEvery, settings.label + " development");

        // steady state: per block and layer, the means of the samples
        const int blocks = settings.blocks;
        enum { phiColumn, coarseColumn, velocityColumn, temperatureColumn, nColumns };
        // blockMeans[column][layer][block]
        std::vector<std::vector<std::vector<double>>> blockMeans
        (
            nColumns, std::vector<std::vector<double>>(std::size_t(layers))
        );
        const double layerVolume = sim.box().volume()/layers;
        for (int b = 0; b < blocks; ++b)
        {
            std::vector<std::array<double, nColumns>> sum(std::size_t(layers), {0, 0, 0, 0});
            long samples = 0;
            auto sample = [&](const Simulation& s)
            {
                const std::vector<LayerSums> sums = layerSums(s, layers, coarse);
                for (std::size_t l = 0; l < sums.size(); ++l)
                {
                    const LayerSums& ls = sums[l];
                    double u[3];
                    sum[l][phiColumn] += ls.solidsVolume/layerVolume;
                    sum[l][coarseColumn] += ls.solidsVolume > 0 ? ls.coarseVolume/ls.solidsVolume : 0;
                    sum[l][temperatureColumn] += temperatureAboutMean(ls.velocity, ls.count, u);
                    sum[l][velocityColumn] += u[0];
                }
                ++samples;
                if (s.stepCount() % seriesEvery == 0) writeSeries(s);
            };
            sim.run
            (
                blockSteps, sample, sampleEvery, settings.progressEvery,
                settings.label + " block " + std::to_string(b + 1) + "/" + std::to_string(blocks)
            );
            for (std::size_t l = 0; l < sum.size(); ++l)
            {
                for (int col = 0; col < nColumns; ++col)
                {
                    blockMeans[col][l].push_back(sum[l][col]/samples);
                }
            }
        }
        series.close();

        std::ofstream profiles(output + "-profiles.dat");
        profiles << "# Kolmogorov cell: a0 " << amplitude << " m/s^2, k " << k << " 1/m, box "
                 << sim.box().lx << " m, " << sim.particles().size() << " particles, "
                 << blocks << " blocks of " << blockSteps*dt << " s after " << equilibrationSteps*dt
                 << " s; errors: block standard errors\n"
                 << "# y[m] phi phiErr c c_err ux[m/s] uxErr T[m2/s2] T_err\n"
                 << std::setprecision(8);
        for (int l = 0; l < layers; ++l)
        {
            profiles << (l + 0.5)*sim.box().ly/layers;
            for (int col = 0; col < nColumns; ++col)
            {
                const auto [mean, error] = blockMean(blockMeans[col][std::size_t(l)]);
                profiles << ' ' << mean << ' ' << error;
            }
            profiles << '\n';
        }
        if (!profiles || !series)
        {
            throw std::runtime_error("cannot write " + output + "-profiles.dat or -series.dat");
        }
        std::cout << "written " << output << "-series.dat, " << output << "-profiles.dat\n";
    }
    catch (const std::exception& err)
    {
        std::cerr << "kineticSievingCell: error: " << err.what() << "\n";
        return 1;
    }
    return 0;
}

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
// The forcing sets the flow and the temperature: mode, temperature, shearRate,
// thermostatTime and maxEquilibrationTime (the development is equilibrationTime, whole)
// are refused.
//
// Output (text, one header line per column):
//   <output>-series.dat    t, mixture T about the mean flow's fit, the flow's sine and
//                          cosine amplitudes, the solids' and the coarse volume's
//                          cos(2 k y) modes, and A, the coarse share's: their difference
//                          (A > 0: coarse over-represented in the high-shear layers, at
//                          u_x = 0; for c = c0 (1 + A cos 2ky) on uniform solids, A)
//   <output>-profiles.dat  per layer: y, solids fraction, coarse fraction of the solids,
//                          u_x, T about the mean flow (interpolated between the layers),
//                          each with its block standard error
// The species are taken in the order given; the last one is "coarse" (the largest).
#include "CellConfig.hpp"
#include "KolmogorovForcing.hpp"

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
    keys.insert({"forcingAmplitude", "forcingWaves", "layers", "output"});
    return keys;
}

//- One layer at one sample: solids fraction, coarse share of the solids, mean u_x and T.
struct LayerState
{
    double solidsFraction = 0, coarseShare = 0, velocity = 0, temperature = 0;
};

//- The layers' state now. T is taken about the mean flow interpolated linearly in y
//  between the layers' centres (periodic), not about each layer's mean: the shear inside
//  a layer would add (gammaDot h)^2/12 to T, a tenth of it in the high-shear layers.
std::vector<LayerState> layerStates(const Simulation& sim, int layers, int coarse)
{
    const Particles& p = sim.particles();
    const double ly = sim.box().ly, h = ly/layers;
    const std::size_t n = p.size(), nl = std::size_t(layers);
    std::vector<int> layer(n);
    std::vector<double> mass(nl), momentum(nl * 3), volume(nl), coarseVolume(nl), count(nl);
    for (std::size_t i = 0; i < n; ++i)
    {
        const int l = std::min(layers - 1, int(p.y[i]/h));
        layer[i] = l;
        const std::size_t L = std::size_t(l);
        mass[L] += p.mass[i];
        momentum[3*L] += p.mass[i]*p.vx[i];
        momentum[3*L + 1] += p.mass[i]*p.vy[i];
        momentum[3*L + 2] += p.mass[i]*p.vz[i];
        const double v = 4.0/3.0*M_PI*std::pow(p.radius[i], 3);
        volume[L] += v;
        if (p.species[i] == coarse) coarseVolume[L] += v;
        count[L] += 1;
    }
    std::vector<LayerState> state(nl);
    std::vector<double> mean(nl * 3);
    for (std::size_t l = 0; l < nl; ++l)
    {
        for (int a = 0; a < 3; ++a) mean[3*l + a] = mass[l] > 0 ? momentum[3*l + a]/mass[l] : 0;
        state[l].solidsFraction = volume[l]/(sim.box().volume()/layers);
        state[l].coarseShare = volume[l] > 0 ? coarseVolume[l]/volume[l] : 0;
        state[l].velocity = mean[3*l];
    }
    std::vector<double> sumC2(nl);
    for (std::size_t i = 0; i < n; ++i)
    {
        // the flow at y_i: between the centres of the layer below and above (periodic)
        const double s = p.y[i]/h - 0.5;
        const int below = int(std::floor(s));
        const double w = s - below;
        const std::size_t lo = std::size_t((below + layers) % layers);
        const std::size_t hi = std::size_t((below + 1 + layers) % layers);
        double c2 = 0;
        for (int a = 0; a < 3; ++a)
        {
            const double v = a == 0 ? p.vx[i] : a == 1 ? p.vy[i] : p.vz[i];
            const double u = (1 - w)*mean[3*lo + std::size_t(a)] + w*mean[3*hi + std::size_t(a)];
            c2 += (v - u)*(v - u);
        }
        sumC2[std::size_t(layer[i])] += c2;
    }
    for (std::size_t l = 0; l < nl; ++l)
    {
        state[l].temperature = count[l] > 0 ? sumC2[l]/count[l] : 0;
    }
    return state;
}

//- One line of the series: the mean flow's Fourier amplitudes, T about the fitted flow,
//  the cos(2 k y) modes of the solids' and of the coarse species' volume distributions
//  (2 <cos 2ky> over each: the layers' solids fraction varies with the shear rate too, so
//  the coarse share's mode is the difference).
struct SeriesPoint
{
    double sine = 0, cosine = 0, temperature = 0, solidsMode = 0, coarseMode = 0;
};

SeriesPoint seriesPoint(const Simulation& sim, double k, int coarse)
{
    const Particles& p = sim.particles();
    const int n = int(p.size());
    double mass = 0, ms = 0, mc = 0, volume = 0, solidsCos = 0, coarseVolume = 0, coarseCos = 0;
    for (int i = 0; i < n; ++i)
    {
        mass += p.mass[i];
        ms += p.mass[i]*p.vx[i]*std::sin(k*p.y[i]);
        mc += p.mass[i]*p.vx[i]*std::cos(k*p.y[i]);
        const double v = std::pow(p.radius[i], 3), c2 = std::cos(2*k*p.y[i]);
        volume += v;
        solidsCos += v*c2;
        if (p.species[i] == coarse)
        {
            coarseVolume += v;
            coarseCos += v*c2;
        }
    }
    SeriesPoint s;
    // u_x(y) = sine sin(k y) + cosine cos(k y): projections of a uniform mass density
    s.sine = 2*ms/mass;
    s.cosine = 2*mc/mass;
    s.solidsMode = 2*solidsCos/volume;
    s.coarseMode = coarseVolume > 0 ? 2*coarseCos/coarseVolume : 0;
    double sum = 0;
    for (int i = 0; i < n; ++i)
    {
        const double cx = p.vx[i] - s.sine*std::sin(k*p.y[i]) - s.cosine*std::cos(k*p.y[i]);
        sum += cx*cx + p.vy[i]*p.vy[i] + p.vz[i]*p.vz[i];
    }
    s.temperature = sum/n;
    return s;
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
        refuseKeys
        (
            config, {"mode", "temperature", "shearRate", "thermostatTime", "maxEquilibrationTime"},
            "the Kolmogorov cell",
            "the forcing (forcingAmplitude, forcingWaves) sets the flow and the temperature, and"
            " equilibrationTime is the whole development before the sampling"
        );
        if (!config.count("forcingAmplitude"))
        {
            throw std::invalid_argument("entry 'forcingAmplitude' missing: the body force's amplitude a0 [m/s^2]");
        }
        CellRunSettings settings = cellRunSettingsFrom(config);
        settings.simulation.mode = CellMode::nve;
        if (!config.count("label")) settings.label = "kolmogorov";
        validateCellRunSettings(settings);
        if (settings.species.size() < 2)
        {
            throw std::invalid_argument("entry 'species': the sieving cell needs two species (fine, coarse)");
        }
        requireCoarseLast(settings, false);
        const double amplitude = configNumber(config, "forcingAmplitude", 0);
        if (!std::isfinite(amplitude) || !(amplitude > 0))
        {
            // before the packing (KolmogorovForcing says the same once the box is known)
            throw std::invalid_argument
            (
                "entry 'forcingAmplitude' must be finite and positive [m/s^2], got "
              + config.at("forcingAmplitude")
            );
        }
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

        // a start well below the sheared state's temperature (the forcing heats the cell);
        // mode nve: no streaming profile
        const Packing packing = initialCell(settings, 0.01*amplitude*meanDiameter(settings));
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
        // about 2000 lines, on the samples' grid
        const SampledSchedule schedule = sampledSchedule(settings, dt, 2000);
        const long sampleEvery = schedule.sampleEvery;
        const long equilibrationSteps = schedule.equilibrationSteps;
        const long blockSteps = schedule.blockSteps;
        const long seriesSamples = schedule.seriesSamples;
        const long seriesEvery = schedule.seriesEvery;
        std::cout << "Kolmogorov cell: " << sim.particles().size() << " particles, box "
                  << sim.box().lx << " m, dt " << dt << " s, a0 " << amplitude
                  << " m/s^2, k " << k << " 1/m; " << equilibrationSteps << " steps to the steady state, "
                  << settings.blocks << " blocks of " << blockSteps << " steps\n";

        std::ofstream series(output + "-series.dat");
        series << "# t[s] T[m2/s2] uSine[m/s] uCosine[m/s] solidsMode coarseMode A=coarseMode-solidsMode\n"
               << std::setprecision(8);
        auto writeSeries = [&](const Simulation& s)
        {
            const SeriesPoint p = seriesPoint(s, k, coarse);
            if (!std::isfinite(p.temperature) || !std::isfinite(p.sine))
            {
                throw std::runtime_error("Kolmogorov cell: the flow is not finite at t = " + std::to_string(s.time()));
            }
            series << s.time() << ' ' << p.temperature << ' ' << p.sine << ' ' << p.cosine
                   << ' ' << p.solidsMode << ' ' << p.coarseMode << ' '
                   << p.coarseMode - p.solidsMode << '\n';
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
        long samplesTaken = 0;
        for (int b = 0; b < blocks; ++b)
        {
            std::vector<std::array<double, nColumns>> sum(std::size_t(layers), {0, 0, 0, 0});
            long samples = 0;
            auto sample = [&](const Simulation& s)
            {
                const std::vector<LayerState> state = layerStates(s, layers, coarse);
                for (std::size_t l = 0; l < state.size(); ++l)
                {
                    sum[l][phiColumn] += state[l].solidsFraction;
                    sum[l][coarseColumn] += state[l].coarseShare;
                    sum[l][velocityColumn] += state[l].velocity;
                    sum[l][temperatureColumn] += state[l].temperature;
                }
                ++samples;
                if (++samplesTaken % seriesSamples == 0) writeSeries(s);
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
                const sdf::correlation::Estimate e =
                    sdf::correlation::meanAndStandardError(blockMeans[col][std::size_t(l)]);
                profiles << ' ' << e.value << ' ' << e.standardError;
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

// rheologyEnvelope: the mu(I) and phi(I) rheology of a material from pressure-controlled
// sheared DEM cells (mode leesEdwards with targetPressure, calibration/dem/Barostat.hpp),
// one cell per inertial number, fitted with the solver's muI law and an alternative
// (fit/RheologyLaws.hpp); prints the muI coefficients and writes them with the table.
//
//   rheologyEnvelope cell.cfg [key=value ...]      command-line pairs override the file
//
// Keys: every key of periodicDEM-cli's cell (species, contact law, particles, timeStep,
// rollingFriction, ...; mode and shearRate are set here), and
//   targetPressure       the normal stress of every cell [Pa], > 0 (the pressure scale of
//                        the case: rho_s g H of its depth, for instance)
//   inertialNumbers      the I of the cells, each in (0, 1] (e.g. 0.005 0.01 0.03 0.1 0.3);
//                        the shear rate of each is I sqrt(p/rho_s)/d
//   equilibrationStrain  gammaDot t of the equilibration (default 10; up to 3 x that while
//                        the density is not steady)
//   samplingStrain       gammaDot t of the sampling (default 20)
//   output               prefix of the files written (default rheology): <output>-cells.dat
//                        (one row per cell, with its steady check and regime) and
//                        <output>-muICoeffs (the muI entries with their errors)
// A cell that is not a steady dense flow (jammed, a gas, crystallised, or drifting) or that the run
// refused (a pressure the barostat could not hold, a cell blown into a gas) is reported,
// written as such in the table and left out of the fit; the fit needs 4 cells.
#include "CellConfig.hpp"

#include "fit/RheologyLaws.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>

using namespace sdf::dem;

namespace
{

std::set<std::string> validKeys()
{
    std::set<std::string> keys = cellConfigKeys();
    keys.insert({"inertialNumbers", "equilibrationStrain", "samplingStrain", "output"});
    return keys;
}

std::vector<double> inertialNumbersFrom(const CellConfig& c)
{
    if (!c.count("inertialNumbers"))
    {
        throw std::invalid_argument("entry 'inertialNumbers' missing: the I of the cells, each in (0, 1]");
    }
    std::istringstream in(c.at("inertialNumbers"));
    std::vector<double> values;
    std::string word;
    while (in >> word)
    {
        double I = 0;
        try { std::size_t used = 0; I = std::stod(word, &used); if (used != word.size()) throw 0; }
        catch (...) { throw std::invalid_argument("entry 'inertialNumbers': '" + word + "' is not a number"); }
        if (!(I > 0 && I <= 1))
        {
            throw std::invalid_argument
            (
                "entry 'inertialNumbers': " + word + " outside (0, 1] (the dense regime of"
                " mu(I); I -> 0 is quasi-static, I > 1 a granular gas)"
            );
        }
        values.push_back(I);
    }
    if (values.empty()) throw std::invalid_argument("entry 'inertialNumbers' is empty");
    return values;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: rheologyEnvelope cell.cfg [key=value ...]\n";
        return 2;
    }
    try
    {
        const CellConfig config = readCellConfig(argv[1], argc, argv, 2, validKeys());
        CellRunSettings base = cellRunSettingsFrom(config);
        base.simulation.mode = CellMode::leesEdwards;
        if (!(base.simulation.targetPressure > 0))
        {
            throw std::invalid_argument
            (
                "entry 'targetPressure' must be a pressure > 0 Pa (the normal stress of the"
                " cells), got " + std::to_string(base.simulation.targetPressure)
            );
        }
        const std::vector<double> inertialNumbers = inertialNumbersFrom(config);
        const double equilibrationStrain = configNumber(config, "equilibrationStrain", 10);
        const double samplingStrain = configNumber(config, "samplingStrain", 20);
        for (const auto& [name, v] : {std::pair{"equilibrationStrain", equilibrationStrain},
                                      std::pair{"samplingStrain", samplingStrain}})
        {
            if (!(v > 0) || !std::isfinite(v))
            {
                throw std::invalid_argument(std::string("entry '") + name + "' must be > 0");
            }
        }
        const std::string output = configText(config, "output", "rheology");

        const double rho = solidsDensity(base);
        const double d = meanDiameter(base);
        const double p = base.simulation.targetPressure;
        std::printf
        (
            "rheologyEnvelope: %zu cells at sigma_yy %g Pa, d %g m, rho_s %g kg/m3"
            " (I = gammaDot d/sqrt(p/rho_s))\n", inertialNumbers.size(), p, d, rho
        );

        std::ofstream table(output + "-cells.dat");
        table << "# rheologyEnvelope: pressure-controlled sheared cells at targetPressure " << p
              << " Pa; d " << d << " m, rho_s " << rho << " kg/m3; errors: block standard errors\n"
              << "# I_target gammaDot[1/s] I I_err mu mu_err phi phi_err Z Q6 sigma_yy[Pa]"
                 " sigma_yy_err T[m2/s2] steady regime\n";
        std::vector<sdf::fit::RheologyPoint> points;
        const auto start = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < inertialNumbers.size(); ++k)
        {
            const double I = inertialNumbers[k];
            CellRunSettings s = atInertialNumber
            (
                base, I, equilibrationStrain, 3*equilibrationStrain, samplingStrain
            );
            s.label = "I " + std::to_string(I);
            CellRunResult r;
            try
            {
                r = runCell(s);
            }
            catch (const std::runtime_error& err)
            {
                // a cell the barostat could not hold, or one blown into a gas: reported,
                // left out, the envelope goes on
                table << I << " " << s.simulation.shearRate
                      << " nan nan nan nan nan nan nan nan nan nan nan no \"refused\"\n";
                table.flush();
                std::printf
                (
                    "cell %zu/%zu: I %g refused, left out of the fit: %s\n",
                    k + 1, inertialNumbers.size(), I, err.what()
                );
                std::fflush(stdout);
                continue;
            }
            const RheologyResult& h = r.rheology;
            table << I << " " << s.simulation.shearRate << " " << h.inertialNumber.value << " "
                  << h.inertialNumber.standardError << " " << h.stressRatio.value << " "
                  << h.stressRatio.standardError << " " << h.solidsFraction.value << " "
                  << h.solidsFraction.standardError << " " << h.coordinationNumber.value << " "
                  << h.bondOrder.value << " " << h.pressure.value << " " << h.pressure.standardError << " "
                  << r.temperature << " " << (h.steady ? "yes" : "no") << " \""
                  << h.regime << "\"\n";
            table.flush();
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::printf
            (
                "cell %zu/%zu: I %.4g (target %g), mu %.4f +- %.4f, phi %.4f +- %.4f, Z %.2f,"
                " Q6 %.3f, %s, %s; %.0f s so far\n", k + 1, inertialNumbers.size(),
                h.inertialNumber.value, I, h.stressRatio.value, h.stressRatio.standardError,
                h.solidsFraction.value, h.solidsFraction.standardError,
                h.coordinationNumber.value, h.bondOrder.value, h.steady ? "steady" : "NOT steady",
                h.regime.c_str(), elapsed
            );
            std::fflush(stdout);
            if (!h.denseSteadyFlow())
            {
                std::printf("  left out of the fit: %s; %s\n", h.steadyCheck.c_str(), h.regimeReason.c_str());
                continue;
            }
            points.push_back
            ({
                h.inertialNumber.value, h.stressRatio.value, h.stressRatio.standardError,
                h.solidsFraction.value, h.solidsFraction.standardError, d, r.temperature
            });
        }
        const sdf::fit::RheologyFit fit = sdf::fit::fitRheology(points);
        std::cout << sdf::fit::rheologyFitSummary(fit);
        const std::string entries = sdf::fit::muICoefficientEntries(fit);
        std::ofstream(output + "-muICoeffs") << entries;
        std::cout << "muICoeffs entries (written " << output << "-muICoeffs, table "
                  << output << "-cells.dat):\n" << entries;
    }
    catch (const std::exception& err)
    {
        std::cerr << "rheologyEnvelope: error: " << err.what() << "\n";
        return 1;
    }
    return 0;
}

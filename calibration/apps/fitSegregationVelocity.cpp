// fitSegregationVelocity: the percolation length S of w_coarse = S gammaDot (1 - c) as a
// law of p*, the size ratio and c (fit/SegregationLaws.hpp: fanSchlick, trewhela,
// trewhelaAsymmetric, chosen by AIC), fitted to sheared cells under gravity
// (gravityShearCell's <output>-segregation.dat, one per cell), with the shear-rate
// diffusivity C = D/(gammaDot dMean^2) of the same cells.
//
//   fitSegregationVelocity [-estimator early|balance] [-output FILE] cell-segregation.dat ...
//
//   -estimator  which of the cell's two estimators of S is fitted (default balance: the
//               flux balance of the sampled profile, read over the same time as the
//               cell's p*, I, c and gammaDot, the diffusive back-flux included; early:
//               the drift of the mixed start, with the c and gammaDot of its windows)
//   -output     the segregationVelocity and shearRateDiffusivity entries are written
//               there as an OpenFOAM dictionary (default segregationVelocityCoeffs): a
//               case reads it from constant/ (percolation calibrated { file <name>; })
// A cell whose top wall did not carry its load (off by more than 5 %) is refused by name:
// it was not at the condition it claims.
#include "fit/SegregationLaws.hpp"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{

sdf::fit::SegregationPoint readCell(const std::string& path, bool early)
{
    std::ifstream in(path);
    if (!in) throw std::invalid_argument(path + ": cannot open (a gravityShearCell <output>-segregation.dat)");
    std::string line;
    while (std::getline(in, line))
    {
        std::istringstream words(line);
        std::string key;
        words >> key;
        if (key != "interior") continue;
        sdf::fit::SegregationPoint q;
        double sEarly, sEarlyErr, cEarly, rateEarly, sBalance, sBalanceErr, c, rate, load;
        words >> q.fineDiameter >> q.sizeRatio >> q.solidsFraction >> q.pressureNumber >> q.inertialNumber
              >> sEarly >> sEarlyErr >> cEarly >> rateEarly >> sBalance >> sBalanceErr >> c >> rate
              >> q.shearRateDiffusivity >> q.shearRateDiffusivityError >> load;
        if (!words)
        {
            throw std::invalid_argument(path + ": the 'interior' line has fewer than 16 numbers: " + line);
        }
        if (!(std::abs(load - 1) <= 0.05))
        {
            throw std::invalid_argument
            (
                path + ": the top wall carried " + std::to_string(load) + " sigma_N, not 1 +- 0.05: the"
                " cell was not at its condition (a longer equilibrationTime); leave it out or rerun it"
            );
        }
        q.coarseShare = early ? cEarly : c;
        q.shearRate = early ? rateEarly : rate;
        q.percolationLength = early ? sEarly : sBalance;
        q.percolationLengthError = early ? sEarlyErr : sBalanceErr;
        return q;
    }
    throw std::invalid_argument(path + ": no 'interior' line (not a gravityShearCell -segregation.dat?)");
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        std::string estimator = "balance", output = "segregationVelocityCoeffs";
        std::vector<std::string> files;
        for (int i = 1; i < argc; ++i)
        {
            const std::string a = argv[i];
            if ((a == "-estimator" || a == "-output") && i + 1 < argc)
            {
                (a == "-estimator" ? estimator : output) = argv[++i];
            }
            else if (!a.empty() && a[0] == '-')
            {
                throw std::invalid_argument("unknown option '" + a + "' (valid: -estimator early|balance, -output FILE)");
            }
            else
            {
                files.push_back(a);
            }
        }
        if (estimator != "early" && estimator != "balance")
        {
            throw std::invalid_argument("-estimator '" + estimator + "': valid choices are early, balance");
        }
        if (files.empty())
        {
            std::cerr << "usage: fitSegregationVelocity [-estimator early|balance] [-output FILE] cell-segregation.dat ...\n";
            return 2;
        }
        std::vector<sdf::fit::SegregationPoint> points;
        for (const std::string& f : files)
        {
            points.push_back(readCell(f, estimator == "early"));
            const auto& q = points.back();
            std::cout << f << ": p* " << q.pressureNumber << ", I " << q.inertialNumber << ", R " << q.sizeRatio
                      << ", c " << q.coarseShare << ": S " << q.percolationLength << " +- "
                      << q.percolationLengthError << " m\n";
        }
        const sdf::fit::SegregationFit fit = sdf::fit::fitSegregation(points);
        std::cout << sdf::fit::segregationFitSummary(fit);
        // an OpenFOAM dictionary of its own (object: the file's name), so that a case can
        // read it as it is (percolation calibrated { file <name>; }) or take its entries
        // into constant/granularCoefficients
        const std::string object = output.substr(output.find_last_of('/') + 1);
        std::ofstream out(output);
        out << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
            << "    location    \"constant\";\n    object      " << object << ";\n}\n"
            << "// fitSegregationVelocity -estimator " << estimator << " on " << files.size() << " cells:\n";
        for (const std::string& f : files) out << "//   " << f << "\n";
        out << sdf::fit::segregationVelocityEntries(fit);
        if (!out) throw std::runtime_error("cannot write " + output);
        std::cout << "written " << output << "\n";
    }
    catch (const std::exception& e)
    {
        std::cerr << "fitSegregationVelocity: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

// fitBreakageParameters: the Vogel-Peukert constants of a material from its single-particle
// impact tests (fit/ImpactTests.hpp: the table; fit/BreakageFit.hpp: the maximum-likelihood
// fit), written as the entries a case's wallImpactCoeffs includes.
//
//   fitBreakageParameters TABLE [fragments=SIEVING] [output=PREFIX]
//
// With SIEVING (fit/FragmentSieving.hpp: the broken particles' fragments sieved) it also
// fits Austin's breakage function and writes PREFIX-daughterSizeDistribution (the
// `austin` daughters, to `#include` inside breakage). Writes PREFIX-wallImpactCoeffs (fMat and xWmMin, their standard errors, correlation and
// the fit's check as comments; `#include` it inside breakage/wallImpactCoeffs),
// PREFIX-fit.dat (per test: the observed and fitted fractions broken, the Pearson
// residual) and PREFIX-fit.png (gnuplot, when installed). PREFIX defaults to TABLE
// without its extension. Bad input: a message naming the file, line and column, exit
// status 1, nothing written.
#include "fit/BreakageFit.hpp"
#include "fit/ColumnTable.hpp"
#include "fit/FragmentSieving.hpp"
#include "fit/ImpactTests.hpp"

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace sdf::fit::breakage;
using sdf::fit::numberText;

namespace
{

struct Arguments
{
    std::string table;
    std::string fragments;
    std::string prefix;
};

Arguments parse(int argc, char** argv)
{
    Arguments a;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg.rfind("output=", 0) == 0) a.prefix = arg.substr(7);
        else if (arg.rfind("fragments=", 0) == 0) a.fragments = arg.substr(10);
        else if (a.table.empty() && arg.find('=') == std::string::npos) a.table = arg;
        else throw std::invalid_argument("unknown argument '" + arg + "' (usage: fitBreakageParameters TABLE [fragments=SIEVING] [output=PREFIX])");
    }
    if (a.table.empty()) throw std::invalid_argument("no table of impact tests (usage: fitBreakageParameters TABLE [fragments=SIEVING] [output=PREFIX])");
    if (a.prefix.empty())
    {
        const std::size_t slash = a.table.find_last_of('/');
        const std::size_t dot = a.table.find_last_of('.');
        a.prefix = dot != std::string::npos && (slash == std::string::npos || dot > slash)
            ? a.table.substr(0, dot) : a.table;
    }
    return a;
}

std::string entries(const BreakageFitResult& fit, const Arguments& a, std::size_t rows)
{
    std::ostringstream s;
    s << std::setprecision(6);
    s << "// Vogel & Peukert's constants fitted by fitBreakageParameters to " << rows
      << " rows of impact tests (" << a.table << ")\n"
      << "// by maximum likelihood of the binomial counts; the errors are standard errors\n"
      << "fMat            " << fit.material.fMat << ";   // [kg/(J m)] +- " << fit.fMatError << "\n"
      << "xWmMin          " << fit.material.xWmMin << ";   // [J m/kg] "
      << (fit.thresholdAtZero ? std::string("at its bound 0 (no standard error)")
                              : "+- " + numberText(fit.xWmMinError)) << "\n"
      << "// correlation of the two estimates " << fit.correlation << "; deviance "
      << fit.deviance << " on " << fit.degreesOfFreedom << " degrees of freedom (p "
      << fit.pValue << ")\n";
    return s.str();
}

} // namespace

int main(int argc, char** argv)
{
    try
    {
        const Arguments a = parse(argc, argv);
        const auto tests = readImpactTests(a.table);
        const BreakageFitResult fit = fitVogelPeukert(tests);
        // the fragments before anything is written: bad sieving writes nothing either
        std::string daughters;
        std::ostringstream austinSummary;
        if (!a.fragments.empty())
        {
            const AustinFitResult austin = fitAustin(readFragmentSieving(a.fragments));
            std::ostringstream d;
            d << std::setprecision(6)
              << "// Austin's breakage function B = phi (x/y)^gamma + (1 - phi) (x/y)^beta fitted by\n"
              << "// fitBreakageParameters to " << austin.points << " cumulative fractions of the sieving "
              << a.fragments << "\n// (least squares; rms " << austin.rms << "; standard errors)\n"
              << "daughterSizeDistribution\n{\n    model austin;\n    austinCoeffs\n    {\n"
              << "        phi     " << austin.phi << ";   // +- " << austin.phiError << "\n"
              << "        gamma   " << austin.gamma << ";   // +- " << austin.gammaError << "\n"
              << "        beta    " << austin.beta << ";   // +- " << austin.betaError << "\n"
              << "    }\n}\n";
            daughters = d.str();
            austinSummary << "  Austin's daughters from " << a.fragments << ": phi " << austin.phi << " +- "
                      << austin.phiError << ", gamma " << austin.gamma << " +- " << austin.gammaError
                      << ", beta " << austin.beta << " +- " << austin.betaError << " (rms "
                      << austin.rms << " over " << austin.points << " fractions)\n";
        }

        std::cout << "fitBreakageParameters: " << tests.size() << " rows of impact tests from "
                  << a.table << "\n"
                  << "  fMat   " << fit.material.fMat << " +- " << fit.fMatError << " kg/(J m)\n"
                  << "  xWmMin " << fit.material.xWmMin
                  << (fit.thresholdAtZero ? std::string(" J m/kg: the likelihood is largest at the bound 0 (no standard error)")
                                          : " +- " + numberText(fit.xWmMinError) + " J m/kg") << "\n"
                  << "  correlation " << fit.correlation << "\n"
                  << "  check: deviance " << fit.deviance << " on " << fit.degreesOfFreedom
                  << " degrees of freedom, p " << fit.pValue
                  << (fit.pValue < 0.01 ? ": the law does not describe these tests (p < 0.01); see the residuals" : "")
                  << "\n  mean Pearson residual by size:";
        for (const SizeResidual& s : fit.bySize)
        {
            std::cout << " " << s.size << " m: " << s.meanResidual << " (" << s.rows << " rows)";
        }
        std::cout << "\n" << austinSummary.str();

        if (!std::isfinite(fit.fMatError))
        {
            throw std::runtime_error("the likelihood has no curvature in fMat at its maximum: "
                                     "no standard error, nothing written");
        }
        // every file composed before any is written: a failure leaves none
        const std::string coeffs = a.prefix + "-wallImpactCoeffs";
        const std::string data = a.prefix + "-fit.dat";
        std::ostringstream table;
        table << "# size[m] energy[J/kg] impacts tested broken xW[J m/kg] observedFraction fittedProbability pearsonResidual\n"
              << std::setprecision(8);
        for (std::size_t i = 0; i < tests.size(); ++i)
        {
            const ImpactTest& t = tests[i];
            table << t.size << " " << t.energy << " " << t.impacts << " " << t.tested << " "
                  << t.broken << " " << t.size*t.energy << " "
                  << double(t.broken)/double(t.tested) << " " << fit.probability[i] << " "
                  << fit.pearsonResidual[i] << "\n";
        }
        const std::string daughterFile = a.prefix + "-daughterSizeDistribution";
        std::vector<std::pair<std::string, std::string>> files =
            {{coeffs, entries(fit, a, tests.size())}, {data, table.str()}};
        if (!daughters.empty()) files.push_back({daughterFile, daughters});
        for (const auto& [path, text] : files)
        {
            std::ofstream out(path);
            out << text;
            if (!out)
            {
                for (const auto& f : files) std::remove(f.first.c_str());
                throw std::runtime_error("cannot write " + path);
            }
        }

        std::cout << "written " << coeffs << " (include it in breakage/wallImpactCoeffs) and " << data << "\n";
        if (!daughters.empty()) std::cout << "written " << daughterFile << " (include it in breakage)\n";

        // the plot: observed and fitted fractions against x W per impacts
        std::ostringstream gp;
        gp << std::setprecision(8)
           << "set terminal pngcairo size 900,600 enhanced font ',11'\n"
           << "set output '" << a.prefix << "-fit.png'\n"
           << "set title 'Impact tests and the fitted Vogel-Peukert law (fMat " << fit.material.fMat
           << ", xWmMin " << fit.material.xWmMin << ")'\n"
           << "set xlabel 'x W, size times mass-specific impact energy [J m/kg]'\n"
           << "set ylabel 'fraction broken'\nset yrange [0:1]\nset key bottom right\n"
           << "f = " << fit.material.fMat << "; c = " << fit.material.xWmMin << "\n"
           << "P(u, k) = u > c ? 1 - exp(-f*k*(u - c)) : 0\n"
           << "plot '" << data << "' using 6:7:(sqrt($7*(1-$7)/$4)) with yerrorbars pt 7 title 'tests (binomial error)', "
           << "P(x, 1) with lines lw 2 title 'fit, one impact', P(x, 2) with lines lw 2 dt 2 title 'fit, two impacts'\n";
        // without gnuplot the shell exits at once: a write to its pipe must not kill us
        std::signal(SIGPIPE, SIG_IGN);
        FILE* pipe = popen("gnuplot 2>/dev/null", "w");
        if (pipe)
        {
            std::fputs(gp.str().c_str(), pipe);
            if (pclose(pipe) == 0) std::cout << "plot " << a.prefix << "-fit.png\n";
            else std::cout << "gnuplot failed: no plot\n";
        }
        return 0;
    }
    catch (const std::exception& e)
    {
        std::cerr << "fitBreakageParameters: error: " << e.what() << "\n";
        return 1;
    }
}

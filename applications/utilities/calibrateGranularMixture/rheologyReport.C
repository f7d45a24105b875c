/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "rheologyReport.H"
#include "numberText.H"
#include "OSspecific.H"

#include "fit/RheologyLaws.hpp"
#include "fit/OpenFOAMDictionary.hpp"
#include "store/Store.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <utility>
#include <vector>
#include <algorithm>

using namespace Foam;
using numberText::fmt;

namespace
{

//- The sub-dictionary rheology: the muI entries with their errors, what I
//  means (d, rho_s, pressure), the I range, the model choices
std::string rheologyBlock
(
    const sdf::fit::RheologyFit& fit,
    const double d,
    const double rhoS,
    const double pressure
)
{
    std::ostringstream os;
    os << std::setprecision(10);
    os << "// The bulk's rheology from pressure-controlled sheared DEM cells\n"
       << "// (calibrateGranularMixture, coefficient rheology): what\n"
       << "// bulkFlow/muICoeffs/rheology calibrated reads\n"
       << "rheology\n{\n"
       << sdf::fit::muICoefficientEntries(fit)
       << "    d               " << d << ";   // [m] d of I = gammaDot d/sqrt(p/rho_s):"
       << " the cells' solids-volume weighted mean\n"
       << "    rhoS            " << rhoS << ";   // [kg/m3] rho_s of I\n"
       << "    pressure        " << pressure << ";   // [Pa] sigma_yy of the cells\n"
       << "    IRange          (" << fit.inertialNumbers.min << " "
       << fit.inertialNumbers.max << ");\n"
       << "    cells           " << fit.muI().points << ";\n";
    const auto selection = [&](const char* name, const sdf::fit::ModelSelection& s)
    {
        os << "    " << name << "\n    {\n";
        for (const sdf::fit::RankedLaw& r : s.ranking)
        {
            os << "        " << r.law << " " << r.delta << ";   // AIC difference\n";
        }
        os << "    }\n";
    };
    selection("muSelection", fit.muSelection);
    selection("phiSelection", fit.phiSelection);
    os << "}\n\n";
    return os.str();
}


//- postProcessing/calibration/rheology.dat and, with gnuplot, rheology.png
//  (mu(I) and phi(I): the cells with their errors and the fitted laws)
void plotRheology
(
    const fileName& dir,
    const std::vector<sdf::fit::RheologyPoint>& points,
    const sdf::fit::RheologyFit& fit,
    const bool plot
)
{
    mkDir(dir);
    const fileName dat(dir/"rheology.dat");
    {
        std::ofstream os(dat);
        os << std::setprecision(10)
           << "# rheology cells (steady dense flow) and the fitted muI and phiILinear laws\n"
           << "# I mu mu_err phi phi_err mu_fitted phi_fitted\n";
        for (const sdf::fit::RheologyPoint& p : points)
        {
            sdf::fit::Condition c;
            c.inertialNumber = p.inertialNumber;
            os << p.inertialNumber << " " << p.stressRatio << " " << p.stressRatioError
               << " " << p.solidsFraction << " " << p.solidsFractionError << " "
               << fit.muI().evaluate(c) << " " << fit.phiILinear().evaluate(c) << "\n";
        }
    }
    Info<< "Written " << dat << nl;
    if (!plot || std::system("command -v gnuplot > /dev/null 2>&1") != 0)
    {
        return;
    }
    const fileName gp(dir/"rheology.gp");
    const fileName png(dir/"rheology.png");
    {
        std::ofstream os(gp);
        os << "set terminal pngcairo size 1000,450\n"
           << "set output '" << png.c_str() << "'\n"
           << "set multiplot layout 1,2\n"
           << "set logscale x\nset key top left\nset xlabel 'I'\n"
           << "set ylabel 'mu = |sigma_xy|/sigma_yy'\nset title 'mu(I): DEM and muI fit'\n"
           << "plot '" << dat.c_str() << "' using 1:2:3 with yerrorbars pt 7 title 'DEM',"
           << " '' using 1:6 with lines title 'muI'\n"
           << "set key top right\nset ylabel 'phi'\nset title 'phi(I): DEM and linear fit'\n"
           << "plot '" << dat.c_str() << "' using 1:4:5 with yerrorbars pt 7 title 'DEM',"
           << " '' using 1:7 with lines title 'phi_c - a I'\n"
           << "unset multiplot\n";
    }
    const std::string cmd = "gnuplot '" + std::string(gp) + "' > /dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0)
    {
        Info<< "Written " << png << nl;
    }
}


//- The lines of a text, without their line ends ('\n', and a '\r' before it)
std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
    {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

//- A line without the blanks at its end
std::string trimmed(std::string line)
{
    while (!line.empty() && (line.back() == ' ' || line.back() == '\t'))
    {
        line.pop_back();
    }
    return line;
}

//- The lines [first, last] of the rheology block as written ("rheology",
//  "{" or "rheology {", ..., "}" at the line's start, with the comment run
//  just before it); first > last if there is none
std::pair<std::size_t, std::size_t> rheologyLines
(
    const std::vector<std::string>& lines
)
{
    for (std::size_t i = 0; i < lines.size(); ++i)
    {
        const std::string head(trimmed(lines[i]));
        const bool sameLine = head == "rheology {" || head == "rheology{";
        if (!sameLine && !(head == "rheology" && i + 1 < lines.size()
                          && trimmed(lines[i + 1]) == "{"))
        {
            continue;
        }
        std::size_t first = i;
        while
        (
            first > 0 && lines[first - 1].rfind("// ", 0) == 0
         && lines[first - 1].rfind("// *", 0) != 0
        )
        {
            --first;
        }
        std::size_t last = sameLine ? i + 1 : i + 2;
        while (last < lines.size() && trimmed(lines[last]) != "}")
        {
            ++last;
        }
        return {first, std::min(last, lines.size() - 1)};
    }
    return {1, 0};
}

} // End anonymous namespace


std::string Foam::fileText(const fileName& file)
{
    if (!isFile(file))
    {
        return std::string();
    }
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}


std::string Foam::rheologyBlockOf(const std::string& text)
{
    const std::vector<std::string> lines(linesOf(text));
    const auto [first, last] = rheologyLines(lines);
    std::string block;
    for (std::size_t k = first; k <= last && first <= last; ++k)
    {
        block += lines[k] + "\n";
    }
    return block.empty() ? block : block + "\n";
}


std::string Foam::withRheologyBlock
(
    const std::string& text,
    const std::string& block
)
{
    std::vector<std::string> lines(linesOf(text));
    const auto [first, last] = rheologyLines(lines);
    if (first <= last)
    {
        // the block and the blank line after it
        std::size_t end = last + 1;
        if (end < lines.size() && trimmed(lines[end]).empty()) ++end;
        lines.erase(lines.begin() + first, lines.begin() + end);
    }
    // before the closing "// ***" line, else at the end
    std::size_t at = lines.size();
    for (std::size_t k = lines.size(); k-- > 0;)
    {
        if (lines[k].rfind("// ****", 0) == 0)
        {
            at = k;
            break;
        }
    }
    std::string out;
    for (std::size_t k = 0; k < lines.size(); ++k)
    {
        if (k == at) out += block;
        out += lines[k] + "\n";
    }
    if (at == lines.size()) out += block;
    return out;
}


void Foam::fitRheologyAndReport
(
    const Time& runTime,
    const fileName& h5,
    const calibrationSettings& settings,
    const std::vector<calibrationCondition>& conds
)
{
    // the rheology of each stored rheology cell, and its T (measured)
    std::map<std::string, std::pair<sdf::store::RheologyRecord, double>> stored;
    try
    {
        // no store: no cell was stored (each was left out)
        const std::vector<sdf::store::ConditionRecord> conditions =
            isFile(h5)
          ? sdf::store::readStore(h5).conditions
          : std::vector<sdf::store::ConditionRecord>();
        for (const sdf::store::ConditionRecord& c : conditions)
        {
            if (c.rheology)
            {
                stored[c.name] = {*c.rheology, c.T};
            }
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Reading the rheology cells failed: " << err.what() << nl
            << "    The rheology of constant/granularCoefficients is not"
            << " written." << nl << exit(FatalError);
    }

    std::vector<sdf::fit::RheologyPoint> points;
    double d = 0, rhoS = 0;
    label leftOut = 0;
    for (const calibrationCondition& c : conds)
    {
        const auto it = stored.find(c.name);
        if (it == stored.end())
        {
            ++leftOut;
            continue;
        }
        const sdf::store::RheologyRecord& h = it->second.first;
        d = h.meanDiameter;
        rhoS = h.solidsDensity;
        points.push_back
        ({
            h.inertialNumber, h.stressRatio, h.stressRatioError,
            h.solidsFraction, h.solidsFractionError, h.meanDiameter,
            it->second.second
        });
    }
    const calibrationSettings::rheologyEnvelope& r = settings.rheology();
    Info<< nl << "Rheology: " << label(points.size()) << " of "
        << label(conds.size()) << " cells are steady dense flows";
    if (leftOut)
    {
        Info<< " (" << leftOut << " left out: see their lines above)";
    }
    Info<< nl;
    if (points.size() < 4)
    {
        FatalErrorInFunction
            << "The rheology fit needs at least 4 steady dense cells (three"
            << " parameters of mu(I)); " << label(points.size()) << " of "
            << label(conds.size()) << " cells at sigma_yy " << r.pressure
            << " Pa are." << nl
            << "    Give more inertial numbers within the dense regime"
            << " (rheology/inertialNumber, e.g. 0.01-0.4). Cells that were"
            << " not steady need longer strains or more grains: both are part"
            << " of the stored cells' settings, so calibrate them in a fresh"
            << " store (move constant/calibration.h5 away)." << nl
            << "    The rheology of constant/granularCoefficients is not"
            << " written." << nl
            << exit(FatalError);
    }

    sdf::fit::RheologyFit fit = [&]()
    {
        try
        {
            return sdf::fit::fitRheology(points);
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "The rheology fit failed: " << err.what() << nl
                << "    The rheology of constant/granularCoefficients is not"
                << " written." << nl << exit(FatalError);
        }
        throw;   // not reached
    }();
    // what muI accepts (it would refuse the case later, naming muICoeffs)
    {
        const scalar muS = fit.muI().parameter("mu_s").value;
        const scalar muD = fit.muI().parameter("mu_d").value;
        const scalar I0 = fit.muI().parameter("I_0").value;
        const scalar phiC = fit.phiILinear().parameter("phi_c").value;
        if (!(muS > 0 && muD > muS && I0 > 0 && phiC > 0 && phiC <= 1))
        {
            FatalErrorInFunction
                << "The fitted rheology is not a muI law: mu_s " << muS
                << ", mu_d " << muD << ", I_0 " << I0 << ", phi_c " << phiC
                << " (muI needs mu_d > mu_s > 0, I_0 > 0, 0 < phi_c <= 1):"
                << " mu does not grow with I over the cells" << nl
                << "    The rheology of constant/granularCoefficients is not"
                << " written." << nl << exit(FatalError);
        }
    }
    {
        std::istringstream summary(sdf::fit::rheologyFitSummary(fit));
        for (std::string line; std::getline(summary, line);)
        {
            Info<< "  " << line.c_str() << nl;
        }
    }
    Info<< "  the solver's muI takes the muI and phiILinear fits" << nl;

    plotRheology
    (
        runTime.globalPath()/"postProcessing"/"calibration", points, fit,
        settings.plot()
    );

    const fileName coeffFile
    (
        runTime.globalPath()/runTime.constant()/"granularCoefficients"
    );
    // (a granularCoefficients of the rheology alone: the header, the block)
    std::string text(fileText(coeffFile));
    if (text.empty())
    {
        text =
            sdf::fit::coefficientsFileHeader() + "\n"
            "// ************************************************************************* //\n";
    }
    try
    {
        sdf::store::writeTextAtomically
        (
            coeffFile,
            withRheologyBlock(text, rheologyBlock(fit, d, rhoS, r.pressure))
        );
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction << err.what() << nl << exit(FatalError);
    }
    Info<< "Written " << coeffFile << " (rheology)" << nl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "segregationReport.H"
#include "numberText.H"

#include "store/Store.hpp"
#include "fit/SegregationLaws.hpp"

#include <map>
#include <sstream>

using namespace Foam;
using numberText::fmt;

void Foam::fitSegregationAndReport
(
    const Time& runTime,
    const fileName& h5,
    const calibrationSettings& settings,
    const std::vector<calibrationCondition>& conds
)
{
    std::map<std::string, sdf::store::SegregationRecord> stored;
    try
    {
        // no store: no cell was stored (each was left out)
        if (isFile(h5))
        {
            for (const auto& c : sdf::store::readStore(h5).conditions)
            {
                if (c.segregation)
                {
                    stored[c.name] = *c.segregation;
                }
            }
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Reading the segregation cells failed: " << err.what() << nl
            << "    constant/segregationVelocity is not written." << nl
            << exit(FatalError);
    }

    const bool early = settings.segregation().estimator == "early";
    std::vector<sdf::fit::SegregationPoint> points;
    std::vector<std::string> names;
    std::ostringstream table;
    table
        << "# sheared cells under gravity of calibrateGranularMixture: the"
        << " percolation length S of w_coarse = S gammaDot (1 - c) by both"
        << " estimators (the fit reads " << settings.segregation().estimator
        << ")\n# condition sigma_N[Pa] pStar I phi c gammaDot[1/s]"
        << " S_balance[m] S_balanceErr S_early[m] S_earlyErr diffusiveShare"
        << " C Cerr topWallLoad\n";
    label leftOut = 0;
    for (const calibrationCondition& c : conds)
    {
        const auto it = stored.find(c.name);
        if (it == stored.end())
        {
            ++leftOut;
            continue;
        }
        const sdf::store::SegregationRecord& r = it->second;
        sdf::fit::SegregationPoint q;
        q.fineDiameter = r.fineDiameter;
        q.sizeRatio = r.sizeRatio;
        q.solidsFraction = r.solidsFraction;
        q.pressureNumber = r.pressureNumber;
        q.inertialNumber = r.inertialNumber;
        q.coarseShare = early ? r.earlyCoarseShare : r.coarseShare;
        q.shearRate = early ? r.earlyShearRate : r.shearRate;
        q.percolationLength = early ? r.early : r.balance;
        q.percolationLengthError = early ? r.earlyError : r.balanceError;
        q.shearRateDiffusivity = r.shearRateDiffusivity;
        q.shearRateDiffusivityError = r.shearRateDiffusivityError;
        points.push_back(q);
        names.push_back(c.name);
        table
            << c.name << ' ' << r.normalStress << ' ' << r.pressureNumber << ' '
            << r.inertialNumber << ' ' << r.solidsFraction << ' '
            << r.coarseShare << ' ' << r.shearRate << ' ' << r.balance << ' '
            << r.balanceError << ' ' << r.early << ' ' << r.earlyError << ' '
            << r.diffusiveShare << ' ' << r.shearRateDiffusivity << ' '
            << r.shearRateDiffusivityError << ' ' << r.topWallLoad << '\n';
    }
    Info<< nl << "Segregation velocity: " << label(points.size())
        << " sheared cells under gravity stored";
    if (leftOut > 0)
    {
        Info<< ", " << leftOut << " left out (not stored: see above)";
    }
    Info<< "; S by the " << settings.segregation().estimator.c_str()
        << " estimator" << nl;
    if (points.size() < 3)
    {
        FatalErrorInFunction
            << "Only " << label(points.size()) << " sheared cells under gravity"
            << " reached their condition (" << leftOut << " left out): at least"
            << " 3 are needed to fit the segregation velocity (the pressure"
            << " law has two parameters); give more loads"
            << " in segregationVelocity/normalStress, or longer runs"
            << " (developmentTime) so that the top wall carries its load" << nl
            << "    constant/segregationVelocity is not written." << nl
            << exit(FatalError);
    }

    sdf::fit::SegregationFit fit;
    try
    {
        fit = sdf::fit::fitSegregation(points);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "The segregation velocity's fit failed: " << err.what() << nl
            << "    constant/segregationVelocity is not written." << nl
            << exit(FatalError);
    }
    Info<< sdf::fit::segregationFitSummary(fit).c_str();

    // the cells' table beside the other calibration outputs
    const fileName outDir
    (
        runTime.globalPath()/"postProcessing"/"calibration"
    );
    mkDir(outDir);
    sdf::store::writeTextAtomically(outDir/"segregation.dat", table.str());

    // constant/segregationVelocity: an OpenFOAM dictionary of its own, as
    // fitSegregationVelocity writes it, that percolation calibrated reads
    std::ostringstream out;
    out << "FoamFile\n{\n    version     2.0;\n    format      ascii;\n"
        << "    class       dictionary;\n    location    \"constant\";\n"
        << "    object      segregationVelocity;\n}\n"
        << "// calibrateGranularMixture: " << points.size()
        << " sheared cells under gravity (" << settings.fine().name << " d "
        << settings.fine().d << " m / " << settings.coarse().name << " d "
        << settings.coarse().d << " m, x " << settings.segregation().x
        << "), estimator " << settings.segregation().estimator << ", store "
        << h5.name() << ":\n";
    for (const std::string& n : names)
    {
        out << "//   " << n << "\n";
    }
    out << sdf::fit::segregationVelocityEntries(fit);
    const fileName file(runTime.globalPath()/runTime.constant()/"segregationVelocity");
    sdf::store::writeTextAtomically(file, out.str());
    Info<< "Written " << file << " (percolation calibrated { file"
        << " segregationVelocity; }; shearRateDiffusivity C "
        << fit.diffusivityCoefficient << ") and " << outDir/"segregation.dat"
        << nl << endl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "fitReport.H"
#include "numberText.H"
#include "OSspecific.H"

#include "store/Store.hpp"
#include "fit/FitData.hpp"
#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"
#include "fit/OpenFOAMDictionary.hpp"
#include "fit/SievingNormalisation.hpp"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

using namespace Foam;
using numberText::fmt;

namespace
{

struct StoredResult
{
    calibrationCondition cond;
    scalar T = 0;
    scalar D = 0, DError = 0;        // fines
    scalar eta = 0, etaError = 0;    // coarse, m2/s (converted on reading)
    bool hasEta = false;
};


std::vector<StoredResult> readResults
(
    const fileName& h5,
    const calibrationSettings& settings,
    const std::vector<calibrationCondition>& conds
)
{
    std::vector<StoredResult> out;
    try
    {
        const sdf::store::StoreContents contents = sdf::store::readStore(h5);
        std::map<std::string, const sdf::store::ConditionRecord*> byName;
        for (const sdf::store::ConditionRecord& record : contents.conditions)
        {
            byName[record.name] = &record;
        }
        for (const calibrationCondition& c : conds)
        {
            const auto it = byName.find(c.name);
            if (it == byName.end())
            {
                throw std::runtime_error("condition " + c.name + " is missing");
            }
            const sdf::store::ConditionRecord& record = *it->second;
            if (!record.fine.DError)
            {
                throw std::runtime_error
                (
                    "condition " + c.name + " has no DError of the fines"
                );
            }
            StoredResult r;
            r.cond = c;
            r.T = record.T;
            r.D = record.fine.D;
            r.DError = *record.fine.DError;
            if (record.coarse.eta && !record.coarse.etaError)
            {
                throw std::runtime_error
                (
                    "condition " + c.name + " has eta but no etaError"
                );
            }
            if (record.coarse.eta)
            {
                // stored in engine units (kg^2 m s^-3); fitted and plotted
                // in the m2/s of the solver's flux
                // (docs/developer/calibration-fit.md)
                const double toKinematic =
                    sdf::fit::kinematicSievingCoefficient
                    (
                        1.0, c.phi, c.x, r.T,
                        {settings.fine().d, settings.fine().rho},
                        {settings.coarse().d, settings.coarse().rho}
                    );
                r.hasEta = true;
                r.eta = toKinematic*(*record.coarse.eta);
                r.etaError = toKinematic*(*record.coarse.etaError);
            }
            out.push_back(r);
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Reading the results back from " << h5 << " failed:" << nl
            << "    " << err.what() << nl << exit(FatalError);
    }
    return out;
}


void reportFit(const sdf::fit::FitResult& fit)
{
    Info<< "    law " << fit.law.name().c_str() << ": "
        << fit.law.formula().c_str() << nl;
    if (!fit.converged())
    {
        Info<< "      FAILED: " << fit.message.c_str() << nl;
        return;
    }
    for (const auto& p : fit.parameters)
    {
        Info<< "      " << p.name.c_str() << " = " << fmt(p.value).c_str()
            << " +- " << fmt(p.standardError).c_str() << nl;
    }
    Info<< "      R2 = " << fmt(fit.rSquared).c_str()
        << ", reduced chi2 = " << fmt(fit.reducedChiSquare).c_str()
        << ", AIC = " << fmt(fit.aic).c_str()
        << ", BIC = " << fmt(fit.bic).c_str()
        << ", points = " << label(fit.points) << nl;
}


//- Data file and gnuplot PNG of a coefficient (D of the fines or eta of
//  the coarse) vs T per phi, one figure per x
void plotCoefficient
(
    const fileName& dir,
    const std::vector<StoredResult>& results,
    const calibrationSettings& settings,
    const calibrationSettings::envelopeAxes& envelope,
    const sdf::fit::FitResult* fit,
    const bool isD
)
{
    const std::string prefix = isD ? "D" : "eta";
    const std::string what =
        isD
      ? "D of the fines [m^2/s]"
      : "eta of the coarse [m^2/s]";
    const scalar d = (isD ? settings.fine() : settings.coarse()).d;
    mkDir(dir);
    for (const scalar x : envelope.x)
    {
        const std::string tag = "x" + fmt(x);
        const fileName dat(dir/(prefix + "_" + tag + ".dat"));
        {
            std::ofstream os(dat);
            os << "# " << what << " vs T at x = " << fmt(x)
               << "; blocks per phi: T value error fitted\n";
            for (const scalar phi : envelope.phi)
            {
                os << "# phi " << fmt(phi) << "\n";
                for (const StoredResult& r : results)
                {
                    if (r.cond.x != x || r.cond.phi != phi) continue;
                    if (!isD && !r.hasEta) continue;
                    sdf::fit::Condition c{phi, x, r.T, d, {}};
                    os << std::setprecision(10) << r.T << " "
                       << (isD ? r.D : r.eta) << " "
                       << (isD ? r.DError : r.etaError) << " "
                       << (fit ? fit->evaluate(c) : 0.0) << "\n";
                }
                os << "\n\n";
            }
        }
        if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
        {
            continue;
        }
        const fileName gp(dir/(prefix + "_" + tag + ".gp"));
        const fileName png(dir/(prefix + "_" + tag + ".png"));
        {
            std::ofstream os(gp);
            os << "set terminal pngcairo size 800,600\n"
               << "set output '" << png.c_str() << "'\n"
               << (isD ? "set logscale xy\n" : "set logscale x\n")
               << "set key top left\n"
               << "set xlabel 'T [m^2/s^2] (sum of 3 components)'\n"
               << "set ylabel '" << what << "'\n"
               << "set title 'DEM (Green-Kubo)"
               << (fit ? " and fitted law " + fit->law.name() : std::string())
               << ", x = " << fmt(x) << "'\n"
               << "plot ";
            label i = 0;
            for (const scalar phi : envelope.phi)
            {
                if (i) os << ", ";
                os << "'" << dat.c_str() << "' index " << i
                   << " using 1:2:3 with yerrorbars lc " << i + 1
                   << " pt 7 title 'DEM phi = " << fmt(phi) << "'";
                if (fit)
                {
                    os << ", '' index " << i << " using 1:4 with lines lc " << i + 1
                       << " notitle";
                }
                ++i;
            }
            os << "\n";
        }
        const std::string cmd = "gnuplot '" + std::string(gp) + "' > /dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0)
        {
            Info<< "Written " << png << nl;
        }
    }
}

} // End anonymous namespace


void Foam::fitAndReport
(
    const Time& runTime,
    const fileName& h5,
    const calibrationSettings& settings,
    const calibrationSettings::envelopeAxes& envelope,
    const wordList& coefficients,
    const std::vector<calibrationCondition>& conds
)
{
    // Fits
    const std::vector<StoredResult> results = readResults(h5, settings, conds);
    std::vector<sdf::fit::CalibratedCoefficient> calibrated;
    std::optional<sdf::fit::FitResult> bestD, bestEta;

    for (const word& coeff : coefficients)
    {
        std::vector<sdf::fit::Observation> rows;
        bool allPositive = true;
        for (const StoredResult& r : results)
        {
            const bool isD = coeff == "D";
            if (!isD && !r.hasEta)
            {
                FatalErrorInFunction
                    << "Condition " << r.cond.name.c_str() << " in " << h5
                    << " has no kinetic sieving coefficient eta" << nl
                    << exit(FatalError);
            }
            sdf::fit::Observation o;
            o.condition.phi = r.cond.phi;
            o.condition.x = r.cond.x;
            o.condition.T = r.T;
            o.condition.d = (isD ? settings.fine() : settings.coarse()).d;
            o.value = isD ? r.D : r.eta;
            o.sigma = isD ? r.DError : r.etaError;
            allPositive = allPositive && o.value > 0;
            rows.push_back(o);
        }

        sdf::fit::FitOptions options;
        options.maxIterations = std::size_t(settings.fitMaxIterations());
        wordList laws;
        if (coeff == "D")
        {
            laws = settings.laws();
        }
        else
        {
            laws = settings.etaLaws();
            if (!allPositive)
            {
                options.space = sdf::fit::FitSpace::linear;
            }
        }

        Info<< "Fit of " << coeff << " ("
            << (coeff == "D"
                ? "diffusivity of " + settings.fine().name
                : "kinetic sieving coefficient of " + settings.coarse().name).c_str()
            << ") to " << label(rows.size()) << " rows, "
            << (options.space == sdf::fit::FitSpace::linear ? "linear" : "log")
            << " space:" << nl;

        std::vector<sdf::fit::FitResult> fits;
        for (const word& lawName : laws)
        {
            const sdf::fit::ConstitutiveLaw law =
                sdf::fit::lawFromName(lawName, int(settings.etaDiameterPower()));
            try
            {
                fits.push_back(sdf::fit::fitLaw(law, rows, options));
            }
            catch (const std::exception& err)
            {
                FatalErrorInFunction
                    << "Fit of law '" << lawName << "' to " << coeff
                    << " refused its data:" << nl << "    " << err.what() << nl
                    << "    constant/granularCoefficients is not written."
                    << nl << exit(FatalError);
            }
            reportFit(fits.back());
        }

        try
        {
            sdf::fit::ModelSelection sel = sdf::fit::selectModel(fits);
            Info<< "  model selection by AIC for " << coeff << ":" << nl;
            for (const auto& rk : sel.ranking)
            {
                Info<< "    " << rk.law.c_str() << ": AIC = " << fmt(rk.criterion).c_str()
                    << ", delta = " << fmt(rk.delta).c_str()
                    << ", weight = " << fmt(rk.weight).c_str() << nl;
            }
            for (const auto& f : sel.failed)
            {
                Warning
                    << "Law '" << f.first.c_str() << "' for " << coeff
                    << " did not converge and takes no part: "
                    << f.second.c_str() << endl;
            }
            const sdf::fit::FitResult& best = fits[sel.best().index];
            Info<< "  chosen for " << coeff << ": " << sel.best().law.c_str()
                << nl << endl;
            if (coeff == "D") bestD = best; else bestEta = best;
            calibrated.push_back({coeff, best, sel});
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "No law for " << coeff << " could be fitted:" << nl
                << "    " << err.what() << nl
                << "    constant/granularCoefficients is not written." << nl
                << exit(FatalError);
        }
    }

    std::ostringstream text;
    try
    {
        sdf::fit::writeOpenFOAMDictionary(text, calibrated);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Writing the coefficients failed: " << err.what() << nl
            << "    constant/granularCoefficients is not written." << nl
            << exit(FatalError);
    }
    const fileName coeffFile(runTime.globalPath()/runTime.constant()/"granularCoefficients");
    try
    {
        sdf::store::writeTextAtomically(coeffFile, text.str());
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << err.what() << nl << exit(FatalError);
    }
    Info<< "Written " << coeffFile << nl;

    if (settings.plot())
    {
        const fileName dir(runTime.globalPath()/"postProcessing"/"calibration");
        plotCoefficient(dir, results, settings, envelope, bestD ? &*bestD : nullptr, true);
        bool haveEta = true;
        for (const StoredResult& r : results) haveEta = haveEta && r.hasEta;
        if (haveEta)
        {
            plotCoefficient
            (
                dir, results, settings, envelope, bestEta ? &*bestEta : nullptr, false
            );
        }
    }
}


// ************************************************************************* //

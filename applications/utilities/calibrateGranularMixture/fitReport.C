/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "fitReport.H"
#include "rheologyReport.H"
#include "numberText.H"
#include "OSspecific.H"

#include "store/Store.hpp"
#include "fit/FitData.hpp"
#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"
#include "fit/OpenFOAMDictionary.hpp"
#include "fit/SievingNormalisation.hpp"
#include "fit/BreakageRate.hpp"
#include "fit/ShearScaling.hpp"
#include "fit/FiniteSize.hpp"

#include <cmath>
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

//- The impacts one particle of a species suffers (breakage rates), from the
//  stored collisions of a condition
struct SpeciesImpacts
{
    //- Collisions per second of one particle, with all partners [1/s]
    scalar omega = 0, omegaError = 0;

    //- Mean mass-specific impact energy W = E/(m_i + m_j) of its impacts
    //  [J/kg]
    scalar Wmean = 0, WmeanError = 0;

    //- Distinct collisions counted (the statistics behind the errors)
    label collisions = 0;

    //- Its impact spectrum (every partner, bins of the store): for the
    //  check of the exponential-spectrum closed form
    sdf::fit::breakage::ImpactSpectrum spectrum;
};


struct StoredResult
{
    calibrationCondition cond;
    scalar T = 0;
    scalar D = 0, DError = 0;        // fines
    //- D failed the diffusive-regime check (stores written before the check
    //  have none: taken as they are); DError is then raised (readResults)
    bool DNotConverged = false;
    std::string DVerdict;
    scalar eta = 0, etaError = 0;    // coarse, m2/s (converted on reading)
    bool hasEta = false;

    //- The collisions were stored (conditions stored before they were
    //  recorded have none)
    bool hasCollisions = false;

    //- Why the stored collisions could not be read (empty: they were)
    std::string collisionsError;

    //- 0: fine, 1: coarse
    SpeciesImpacts impacts[2];

    //- A finite-size calibration: D and DError above are the infinite
    //  cell's, extrapolated from these cells (smallest first)
    std::optional<sdf::fit::FiniteSizeExtrapolation> finiteSize;
    std::vector<StoredResult> cells;
};


//- Mass of one particle of a species [kg]
double particleMass(const granularSpecies& s)
{
    return s.rho*M_PI*s.d*s.d*s.d/6.0;
}


//- The impacts of one particle of each species from the collisions of a
//  condition: a collision within a species is an impact for both of its
//  particles; W = E/(m_i + m_j) (fit/BreakageRate.hpp). Errors: Poisson,
//  omega/sqrt(collisions); the standard error of the mean of an
//  exponential spectrum, Wmean/sqrt(collisions).
void readImpacts
(
    const sdf::store::ConditionRecord& record,
    const calibrationSettings& settings,
    StoredResult& r
)
{
    namespace bk = sdf::fit::breakage;
    const sdf::store::CollisionRecord& coll = *record.collisions;
    const granularSpecies* sp[2] = {&settings.fine(), &settings.coarse()};
    const std::optional<std::int64_t> counts[2] =
        {record.fine.count, record.coarse.count};
    for (int s = 0; s < 2; ++s)
    {
        if (!counts[s] || *counts[s] <= 0)
        {
            throw std::runtime_error
            (
                "condition " + r.cond.name + " has no particle count of "
              + std::string(sp[s]->name)
            );
        }
        SpeciesImpacts& imp = r.impacts[s];
        double impacts = 0, Wsum = 0;
        for (int t = 0; t < 2; ++t)
        {
            const sdf::store::PairCollisionRecord* p =
                coll.pair(sp[s]->name, sp[t]->name);
            if (!p)
            {
                throw std::runtime_error
                (
                    "condition " + r.cond.name + " has no collisions of the"
                    " pair " + std::string(sp[s]->name) + "/"
                  + std::string(sp[t]->name)
                );
            }
            const double ms = particleMass(*sp[s]), mt = particleMass(*sp[t]);
            const double involved = s == t ? 2.0 : 1.0;
            impacts += involved*double(p->count);
            Wsum += involved*p->energySum/(ms + mt);
            imp.collisions += label(p->count);
            if (coll.elapsedTime > 0)
            {
                const bk::ImpactSpectrum pairSpectrum =
                    bk::impactSpectrumFromHistogram
                    (
                        coll.binEdges,
                        std::vector<long>(p->histogram.begin(), p->histogram.end()),
                        coll.elapsedTime,
                        int(*counts[s]),
                        s == t,
                        ms,
                        mt
                    );
                imp.spectrum.energy.insert
                (
                    imp.spectrum.energy.end(),
                    pairSpectrum.energy.begin(), pairSpectrum.energy.end()
                );
                imp.spectrum.frequency.insert
                (
                    imp.spectrum.frequency.end(),
                    pairSpectrum.frequency.begin(), pairSpectrum.frequency.end()
                );
            }
        }
        if (coll.elapsedTime > 0)
        {
            imp.omega = impacts/(coll.elapsedTime*double(*counts[s]));
        }
        imp.Wmean = impacts > 0 ? Wsum/impacts : 0;
        if (imp.collisions > 0)
        {
            const double rel = 1/std::sqrt(double(imp.collisions));
            imp.omegaError = rel*imp.omega;
            imp.WmeanError = rel*imp.Wmean;
        }
    }
    r.hasCollisions = true;
}


//- The result of one stored cell (condition c, its record in the store)
StoredResult storedResultOf
(
    const calibrationCondition& c,
    const sdf::store::ConditionRecord& record,
    const calibrationSettings& settings
)
{
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
    if (settings.diffusivityFromMsd())
    {
        if (!record.fine.DMsd || !record.fine.DMsdError)
        {
            throw std::runtime_error
            (
                "condition " + c.name + " has no D_MSD of the fines (a store"
                " written before the MSD was measured): diffusivityEstimate"
                " meanSquareDisplacement needs it; use greenKubo or rerun"
            );
        }
        r.D = *record.fine.DMsd;
        r.DError = *record.fine.DMsdError;
    }
    if (record.fine.DConverged && !*record.fine.DConverged)
    {
        // Weighted down, not dropped: the disagreements that failed
        // the check (Green-Kubo - MSD, the MSD slope's change over its
        // window, the drift of D over the run) and, for a window that
        // starts before the VACF's decay, the deficit of an
        // exponential VACF there, D exp(-t_start/tau_v), are added to
        // the error in quadrature, so a condition whose lags were too
        // short counts as what it is, an estimate with a systematic
        // error of that size (docs/user/calibration.md)
        const sdf::store::SpeciesRecord& f = record.fine;
        const scalar gkMinusMsd = f.DMsd ? f.D - *f.DMsd : f.D;
        const scalar truncation =
            !f.DWindowPastDecay && f.DCorrelationTime > 0
          ? r.D*std::exp(-f.DFitStart/f.DCorrelationTime)
          : 0;
        r.DNotConverged = true;
        r.DVerdict = f.DVerdict;
        const scalar measuredError = r.DError;
        r.DError = std::sqrt
        (
            sqr(r.DError) + sqr(gkMinusMsd) + sqr(f.DSlopeChange)
          + sqr(f.DDrift) + sqr(truncation)
        );
        Info<< "    condition " << c.name.c_str()
            << ": D of the fines not in the diffusive regime ("
            << r.DVerdict.c_str() << "); its error in the fit raised from "
            << measuredError << " to " << r.DError << " m2/s" << nl;
    }
    // eta by the attribution rule chosen (sievingAttribution; the fit's
    // choice only: the tabulated models read the seed's eta)
    const bool crossTerms = settings.sievingAttribution() == "crossTerms";
    const std::optional<double>& eta =
        crossTerms ? record.coarse.etaWithCrossTerms : record.coarse.eta;
    const std::optional<double>& etaError =
        crossTerms ? record.coarse.etaWithCrossTermsError : record.coarse.etaError;
    if (crossTerms && record.coarse.eta && !eta)
    {
        throw std::runtime_error
        (
            "condition " + c.name + " was stored before eta with the cross"
            " terms kept was recorded: remove it from the store to rerun it,"
            " or use 'sievingAttribution seed;'"
        );
    }
    if (eta && !etaError)
    {
        throw std::runtime_error
        (
            "condition " + c.name + " has eta but no etaError"
        );
    }
    if (eta)
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
        r.eta = toKinematic*(*eta);
        r.etaError = toKinematic*(*etaError);
    }
    if (record.collisions)
    {
        // Needed by breakage only: a fault here stops breakage's fit,
        // not the others
        try
        {
            readImpacts(record, settings, r);
        }
        catch (const std::exception& err)
        {
            r.hasCollisions = false;
            r.collisionsError = err.what();
        }
    }
    return r;
}


//- A finite-size calibration's point: its cells' D extrapolated to the
//  infinite cell (fit/FiniteSize.hpp); the rest (T, eta, collisions) from
//  the largest cell, the last of `cells`
StoredResult extrapolatedResult(const std::vector<StoredResult>& cells)
{
    StoredResult r = cells.back();
    std::vector<sdf::fit::SizedValue> rows;
    for (const StoredResult& c : cells)
    {
        rows.push_back({scalar(c.cond.particles), c.D, c.DError});
        r.DNotConverged = r.DNotConverged || c.DNotConverged;
    }
    try
    {
        r.finiteSize = sdf::fit::extrapolateInverseCubeRoot(rows);
    }
    catch (const std::exception& err)
    {
        // name the point (the library knows its rows only)
        std::ostringstream msg;
        msg << "point phi " << r.cond.phi << " x " << r.cond.x << ": " << err.what();
        throw std::invalid_argument(msg.str());
    }
    r.cells = cells;
    r.cond.particles = 0;   // the point, no longer one cell
    r.D = r.finiteSize->value;
    r.DError = r.finiteSize->error;
    return r;
}


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
        // The envelope's points in order, each with its cells (one, or one
        // per size of finiteSize, consecutive in conds)
        std::vector<StoredResult> cells;
        for (std::size_t i = 0; i < conds.size(); ++i)
        {
            const calibrationCondition& c = conds[i];
            const auto it = byName.find(c.name);
            if (it == byName.end())
            {
                throw std::runtime_error("condition " + c.name + " is missing");
            }
            cells.push_back(storedResultOf(c, *it->second, settings));
            if
            (
                c.particles > 0 && i + 1 < conds.size()
             && conds[i + 1].pointName == c.pointName
            )
            {
                continue;
            }
            out.push_back
            (
                cells.size() > 1 ? extrapolatedResult(cells) : cells.front()
            );
            cells.clear();
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


//- The calibration's output directory, postProcessing/calibration of the case
fileName outputDirectory(const Time& runTime)
{
    return runTime.globalPath()/"postProcessing"/"calibration";
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
                    sdf::fit::Condition c{phi, x, r.T, d, {}, {}};
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
               << "set title 'DEM ("
               << (
                      isD && settings.diffusivityFromMsd()
                    ? "MSD" : "Green-Kubo"
                  )
               << (
                      isD && !results.empty() && results.front().finiteSize
                    ? std::string(", infinite cell")
                    : std::string()
                  )
               << ")"
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

//- Fit every candidate law of one coefficient to rows, print the fits and
//  the ranking by AIC, and return the chosen law; a law refusing its data
//  or no converged law stops with a FatalError (nothing written)
sdf::fit::CalibratedCoefficient fitCoefficient
(
    const word& coeff,
    const std::string& what,
    const std::vector<sdf::fit::Observation>& rows,
    const wordList& laws,
    const sdf::fit::FitOptions& options,
    const calibrationSettings& settings
)
{
    Info<< "Fit of " << coeff << " (" << what.c_str() << ") to "
        << label(rows.size()) << " rows, "
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
        return {coeff, best, sel};
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "No law for " << coeff << " could be fitted:" << nl
            << "    " << err.what() << nl
            << "    constant/granularCoefficients is not written." << nl
            << exit(FatalError);
    }
    return {coeff, fits.front(), std::nullopt};
}


//- Breakage: for each species s the collisions per second of one particle
//  (omega.<s>, collisionFrequencyLaws) and the mean mass-specific energy
//  of its impacts (Wmean.<s>, impactEnergyLaws), d the diameter of s; then
//  the check of the exponential spectrum the solver's closed form assumes
void fitBreakage
(
    const fileName& h5,
    const std::vector<StoredResult>& results,
    const calibrationSettings& settings,
    std::vector<sdf::fit::CalibratedCoefficient>& calibrated
)
{
    const granularSpecies* sp[2] = {&settings.fine(), &settings.coarse()};
    for (const StoredResult& r : results)
    {
        if (!r.collisionsError.empty())
        {
            FatalErrorInFunction
                << "Reading the collisions back from " << h5 << " failed: "
                << r.collisionsError.c_str() << nl << exit(FatalError);
        }
        if (!r.hasCollisions)
        {
            FatalErrorInFunction
                << "Condition " << r.cond.name.c_str() << " in " << h5
                << " has no collision statistics (stored before they were"
                << " recorded): move " << h5 << " away and rerun to"
                << " calibrate breakage" << nl << exit(FatalError);
        }
        for (int s = 0; s < 2; ++s)
        {
            if (r.impacts[s].collisions == 0 || !(r.impacts[s].Wmean > 0))
            {
                FatalErrorInFunction
                    << "Condition " << r.cond.name.c_str() << " in " << h5
                    << ": no impacts of " << sp[s]->name << " were counted"
                    << " (collision frequency and impact energy need at"
                    << " least one): sample longer (samplingTime) or use"
                    << " more particles" << nl
                    << "    constant/granularCoefficients is not written."
                    << nl << exit(FatalError);
            }
        }
    }

    sdf::fit::FitOptions options;
    options.maxIterations = std::size_t(settings.fitMaxIterations());

    for (const bool isOmega : {true, false})
    {
        for (int s = 0; s < 2; ++s)
        {
            std::vector<sdf::fit::Observation> rows;
            for (const StoredResult& r : results)
            {
                sdf::fit::Observation o;
                o.condition.phi = r.cond.phi;
                o.condition.x = r.cond.x;
                o.condition.T = r.T;
                o.condition.d = sp[s]->d;
                o.value = isOmega ? r.impacts[s].omega : r.impacts[s].Wmean;
                o.sigma =
                    isOmega ? r.impacts[s].omegaError : r.impacts[s].WmeanError;
                rows.push_back(o);
            }
            calibrated.push_back
            (
                fitCoefficient
                (
                    (isOmega ? "omega." : "Wmean.") + sp[s]->name,
                    isOmega
                  ? "collisions per second of one " + sp[s]->name
                  + " particle [1/s]"
                  : "mean mass-specific impact energy of a " + sp[s]->name
                  + " particle [J/kg]",
                    rows,
                    isOmega
                  ? settings.collisionFrequencyLaws()
                  : settings.impactEnergyLaws(),
                    options,
                    settings
                )
            );
        }
    }

    // The solver evaluates S = fMat x omega Wmean exp(-Wmin/Wmean), the
    // sum over the impact spectrum when it is exponential. Per species, the
    // ratio of the DEM spectrum's sum, sum_b f_b (W_b - Wmin)+, to
    // omega Wmean exp(-Wmin/Wmean) (both measured, fMat x cancels) at
    // thresholds Wmin = 0, 1 and 3 Wmean: 1 for an exponential spectrum
    Info<< "Exponential-spectrum check (sum over the DEM impact spectrum /"
        << " closed form, measured omega and Wmean; 1 if exponential):" << nl;
    for (int s = 0; s < 2; ++s)
    {
        for (const double k : {0.0, 1.0, 3.0})
        {
            double lo = GREAT, hi = -GREAT;
            for (const StoredResult& r : results)
            {
                const SpeciesImpacts& imp = r.impacts[s];
                const double Wmin = k*imp.Wmean;
                double sum = 0;
                for (std::size_t b = 0; b < imp.spectrum.energy.size(); ++b)
                {
                    sum += imp.spectrum.frequency[b]
                       *std::max(imp.spectrum.energy[b] - Wmin, 0.0);
                }
                const double closed =
                    imp.omega*imp.Wmean*std::exp(-Wmin/imp.Wmean);
                lo = std::min(lo, sum/closed);
                hi = std::max(hi, sum/closed);
            }
            Info<< "    " << sp[s]->name << ", Wmin = " << k
                << " Wmean: ratio in [" << fmt(lo).c_str() << ", "
                << fmt(hi).c_str() << "] over " << label(results.size())
                << " conditions" << nl;
        }
    }
    Info<< endl;
}

//- A file in the calibration's output directory (created)
fileName outputFile(const Time& runTime, const word& name)
{
    const fileName dir(outputDirectory(runTime));
    mkDir(dir);
    return dir/name;
}


//- A sheared calibration's dimensionless groups (fit/ShearScaling.hpp):
//  C = D/(gammaDot dMean^2) of the fines against the Lueptow group's 0.042
//  and R = dMean gammaDot sqrt(3/T) against the seed's R = 1, per condition
//  and summarised; written to postProcessing/calibration/shearScaling.dat
sdf::fit::ShearScaling reportShearScaling
(
    const Time& runTime,
    const std::vector<StoredResult>& results,
    const calibrationSettings& settings
)
{
    // The closure of Fan et al. (2014), J. Fluid Mech. 741, 252 (bounded
    // heap DEM), used by Schlick et al. (2015) and the shearRate model
    constexpr scalar lueptowC = 0.042;

    std::vector<sdf::fit::ShearedObservation> rows;
    for (const StoredResult& r : results)
    {
        sdf::fit::ShearedObservation o;
        o.phi = r.cond.phi;
        o.x = r.cond.x;
        o.gammaDot = r.cond.gammaDot;
        o.T = r.T;
        o.dMean = sdf::fit::volumeMeanDiameter
        (
            r.cond.x, settings.fine().d, settings.coarse().d
        );
        o.D = r.D;
        o.DError = r.DError;
        rows.push_back(o);
    }
    sdf::fit::ShearScaling s;
    try
    {
        s = sdf::fit::shearScaling(rows);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "The sheared conditions' dimensionless groups: " << err.what()
            << nl << "    constant/granularCoefficients is not written." << nl
            << exit(FatalError);
    }

    const fileName dat(outputFile(runTime, "shearScaling.dat"));
    {
        std::ofstream os(dat);
        os << "# Sheared calibration: fines' D across the shear (yy) in units of"
           << " gammaDot dMean^2, and R = dMean gammaDot sqrt(3/T)\n"
           << "# phi x gammaDot[1/s] T[m2/s2] D[m2/s] DError[m2/s] C CError R"
           << " notDiffusive\n";
        for (std::size_t i = 0; i < rows.size(); ++i)
        {
            const sdf::fit::ShearedObservation& o = rows[i];
            os << std::setprecision(8) << o.phi << " " << o.x << " "
               << o.gammaDot << " " << o.T << " " << o.D << " " << o.DError
               << " " << s.C[i] << " " << s.CError[i] << " " << s.R[i] << " "
               << (results[i].DNotConverged ? 1 : 0) << "\n";
        }
    }

    Info<< "Sheared cells: D of " << settings.fine().name << " across the shear"
        << " in units of gammaDot dMean^2 (C) and R = dMean gammaDot sqrt(3/T):"
        << nl;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        Info<< "    " << results[i].cond.text().c_str() << ": C = "
            << fmt(s.C[i]).c_str() << " +- " << fmt(s.CError[i]).c_str()
            << ", R = " << fmt(s.R[i]).c_str()
            << (results[i].DNotConverged ? " (D not diffusive)" : "") << nl;
    }
    Info<< "  C = " << fmt(s.meanC.value).c_str() << " +- "
        << fmt(s.meanC.error).c_str() << " (weighted mean, reduced chi2 "
        << fmt(s.meanC.reducedChiSquare).c_str() << "): "
        << fmt(s.meanC.value/lueptowC).c_str() << " x the closure 0.042 of"
        << " Fan et al. 2014 (" << fmt((s.meanC.value - lueptowC)/s.meanC.error).c_str()
        << " errors)" << nl;
    if (s.CLaw.fitted)
    {
        Info<< "  C = A phi^b: A = " << fmt(s.CLaw.A).c_str() << " +- "
            << fmt(s.CLaw.AError).c_str() << ", b = " << fmt(s.CLaw.b).c_str()
            << " +- " << fmt(s.CLaw.bError).c_str() << " (reduced chi2 "
            << fmt(s.CLaw.reducedChiSquare).c_str() << ")" << nl;
    }
    Info<< "  R = " << fmt(s.meanR).c_str() << " (spread "
        << fmt(s.spreadR).c_str() << " over the conditions; the seed assumed"
        << " R = 1)";
    if (s.RLaw.fitted)
    {
        Info<< "; R = A phi^b: A = " << fmt(s.RLaw.A).c_str() << " +- "
            << fmt(s.RLaw.AError).c_str() << ", b = " << fmt(s.RLaw.b).c_str()
            << " +- " << fmt(s.RLaw.bError).c_str();
    }
    Info<< nl << "Written " << dat << nl << endl;
    return s;
}

//- A finite-size calibration's extrapolations, per point: printed and
//  written to postProcessing/calibration/finiteSize.dat
void reportFiniteSize
(
    const Time& runTime,
    const std::vector<StoredResult>& results,
    const calibrationSettings& settings
)
{
    const fileName dat(outputFile(runTime, "finiteSize.dat"));
    std::ofstream os(dat);
    os << "# D of the fines per cell size and extrapolated to the infinite cell,"
       << " D(N) = D_inf - a N^(-1/3)\n# condition N D DError ... D_inf error a"
       << " aError reducedChi2\n";
    Info<< "Finite size: D of " << settings.fine().name << " extrapolated to"
        << " the infinite cell, D(N) = D_inf - a N^(-1/3):" << nl;
    for (const StoredResult& r : results)
    {
        const sdf::fit::FiniteSizeExtrapolation& e = *r.finiteSize;
        os << r.cond.pointName;
        Info<< "    " << r.cond.pointName.c_str() << ":";
        for (const StoredResult& c : r.cells)
        {
            os << std::setprecision(8) << " " << c.cond.particles << " " << c.D
               << " " << c.DError;
            Info<< " N " << c.cond.particles << " " << fmt(c.D).c_str()
                << " +- " << fmt(c.DError).c_str() << ",";
        }
        os << " " << e.value << " " << e.error << " " << e.slope << " "
           << e.slopeError << " " << e.reducedChiSquare << "\n";
        Info<< " -> D_inf " << fmt(e.value).c_str() << " +- "
            << fmt(e.error).c_str() << " (largest cell "
            << fmt(100*(r.cells.back().D/e.value - 1)).c_str() << " %";
        if (e.sizes > 2)
        {
            Info<< ", reduced chi2 " << fmt(e.reducedChiSquare).c_str();
        }
        Info<< ")" << nl;
    }
    Info<< "Written " << dat << nl << endl;
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
    if (!settings.finiteSizeParticles().empty())
    {
        reportFiniteSize(runTime, results, settings);
    }
    std::vector<sdf::fit::CalibratedCoefficient> calibrated;
    std::optional<sdf::fit::FitResult> bestD, bestEta;

    // D and eta: one fit each; breakage: the collision frequency omega and
    // the mean impact energy Wmean of one particle of each species
    for (const word& coeff : coefficients)
    {
        if (coeff == "breakage")
        {
            fitBreakage(h5, results, settings, calibrated);
            continue;
        }
        const bool isD = coeff == "D";
        std::vector<sdf::fit::Observation> rows;
        bool allPositive = true;
        for (const StoredResult& r : results)
        {
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
            if (r.cond.sheared())
            {
                o.condition.gammaDot = r.cond.gammaDot;
            }
            o.condition.d = (isD ? settings.fine() : settings.coarse()).d;
            o.value = isD ? r.D : r.eta;
            o.sigma = isD ? r.DError : r.etaError;
            allPositive = allPositive && o.value > 0;
            rows.push_back(o);
        }

        sdf::fit::FitOptions options;
        options.maxIterations = std::size_t(settings.fitMaxIterations());
        if (!isD && !allPositive)
        {
            options.space = sdf::fit::FitSpace::linear;
        }

        sdf::fit::CalibratedCoefficient chosen = fitCoefficient
        (
            coeff,
            isD
          ? "diffusivity of " + settings.fine().name
          + ", diffusivityEstimate " + settings.diffusivityEstimate()
          : "kinetic sieving coefficient of " + settings.coarse().name
          + ", sievingAttribution " + settings.sievingAttribution(),
            rows,
            isD ? settings.laws() : settings.etaLaws(),
            options,
            settings
        );
        // which estimate the law was fitted to, in granularCoefficients
        chosen.provenance.push_back
        (
            isD
          ? std::pair<std::string, std::string>
            {"diffusivityEstimate", settings.diffusivityEstimate()}
          : std::pair<std::string, std::string>
            {"sievingAttribution", settings.sievingAttribution()}
        );
        if (isD) bestD = chosen.fit; else bestEta = chosen.fit;
        calibrated.push_back(chosen);
    }

    std::optional<sdf::fit::ShearScaling> shear;
    if (settings.sheared())
    {
        // D of the fines and T are measured in every cell, whichever
        // coefficients are calibrated
        shear = reportShearScaling(runTime, results, settings);
    }

    std::ostringstream text;
    try
    {
        sdf::fit::writeOpenFOAMDictionary
        (
            text, calibrated, shear ? &*shear : nullptr
        );
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Writing the coefficients failed: " << err.what() << nl
            << "    constant/granularCoefficients is not written." << nl
            << exit(FatalError);
    }
    const fileName coeffFile(runTime.globalPath()/runTime.constant()/"granularCoefficients");
    // the rheology of an earlier calibration stays (it is run apart)
    const std::string kept(rheologyBlockOf(fileText(coeffFile)));
    try
    {
        sdf::store::writeTextAtomically
        (
            coeffFile, withRheologyBlock(text.str(), kept)
        );
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << err.what() << nl << exit(FatalError);
    }
    Info<< "Written " << coeffFile << nl;

    if (settings.plot())
    {
        const fileName dir(outputDirectory(runTime));
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

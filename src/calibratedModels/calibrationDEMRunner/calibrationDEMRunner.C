/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibrationDEMRunner.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "Pstream.H"

#include "calibrationStore.H"
#include "numberText.H"
#include "store/Store.hpp"

#include <cfenv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace
{

//- Composition limits of the DEM runs: a cell of one species has no
//  partner to sieve through, and a handful of particles no statistics
const Foam::scalar xLowest = 0.02;
const Foam::scalar xHighest = 0.98;

using Foam::numberText::fmt;

std::string fmtList(const Foam::scalarList& values)
{
    return Foam::numberText::listText(values);
}


//- v rounded to the 6 significant digits of the condition names, so that
//  a condition's name and its phi/x/targetT attributes say the same;
//  rounded away from the grid (up = true: not below v)
double roundOutward(const double v, const bool up)
{
    double r = std::strtod(fmt(v).c_str(), nullptr);
    // A cell value a rounding error off a 6-digit value keeps that value
    if (std::abs(r - v) <= 1e-9*std::abs(v))
    {
        return r;
    }
    if (up ? r < v : r > v)
    {
        r = std::strtod(fmt(up ? v*(1 + 5e-6) : v*(1 - 5e-6)).c_str(), nullptr);
    }
    return r;
}


//- The DEM engine handles IEEE infinities and NaNs itself: no OpenFOAM
//  floating-point trap while it runs (as calibrateGranularMixture)
class noFloatingPointTraps
{
    std::fenv_t saved_;

public:

    noFloatingPointTraps() { std::feholdexcept(&saved_); }
    ~noFloatingPointTraps() { std::fesetenv(&saved_); }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::calibrationDEMRunner::calibrationDEMRunner
(
    const granularMixture& mixture,
    const calibrationTable& table,
    const dictionary& modelDict
)
:
    file_(table.file()),
    settings_(),
    margin_(modelDict.getOrDefault<scalar>("runDEMMargin", 1)),
    maxPhi_(modelDict.getOrDefault<scalar>("runDEMMaxPhi", 0.6)),
    minT_(modelDict.getOrDefault<scalar>("runDEMMinT", 1e-4)),
    minPhi_(mixture.phiMin()),
    conditionsRun_(0),
    secondsRun_(0)
{
    if (!(margin_ >= 0) || !(maxPhi_ > 0 && maxPhi_ < 0.64) || !(minT_ > 0))
    {
        FatalIOErrorInFunction(modelDict)
            << "runDEM limits: runDEMMargin " << margin_ << " must be >= 0,"
            << " runDEMMaxPhi " << maxPhi_ << " in (0, 0.64) (jamming),"
            << " runDEMMinT " << minT_ << " > 0 [m2/s2]" << nl
            << exit(FatalIOError);
    }

    const word& fineName = table.fineSpecies();
    const word& coarseName = table.coarseSpecies();
    const label finei = mixture.names().find(fineName);
    const label coarsei = mixture.names().find(coarseName);
    if (mixture.size() != 2 || !(mixture.d(coarsei) > mixture.d(finei)))
    {
        FatalIOErrorInFunction(modelDict)
            << "outsideEnvelope runDEM runs binary mixtures whose coarse"
            << " species (" << coarseName << ") is larger than the fine ("
            << fineName << "); the mixture has " << mixture.names() << nl
            << exit(FatalIOError);
    }

    // The DEM settings of the calibration (system/calibrationDict), read as
    // calibrateGranularMixture reads them
    const IOdictionary dict
    (
        IOobject
        (
            "calibrationDict",
            mixture.mesh().time().system(),
            mixture.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    granularSpecies fine, coarse;
    fine.name = fineName;
    fine.d = mixture.d(finei);
    fine.rho = mixture.rho(finei);
    coarse.name = coarseName;
    coarse.d = mixture.d(coarsei);
    coarse.rho = mixture.rho(coarsei);
    settings_.reset(new calibrationSettings(dict, fine, coarse));
    if (!settings_->finiteSizeParticles().empty())
    {
        FatalIOErrorInFunction(dict)
            << "outsideEnvelope runDEM runs one cell size per condition; "
            << dict.objectPath() << " has 'finiteSize' (cells of "
            << settings_->finiteSizeParticles() << " particles, D"
            << " extrapolated): use its fitted laws (mode law), or give"
            << " 'particles' for runDEM" << nl << exit(FatalIOError);
    }
    if (settings_->sheared())
    {
        FatalIOErrorInFunction(dict)
            << "outsideEnvelope runDEM extends a table of driven cells on its"
            << " T grid; " << dict.objectPath() << " has 'mode leesEdwards;'"
            << " (sheared cells, T measured). Use mode thermostatted or"
            << " stochastic for runDEM, or a sheared calibration's fitted"
            << " laws (mode law)" << nl << exit(FatalIOError);
    }

    Info<< "    calibrated: outside the grid, runDEM with the DEM settings of "
        << dict.objectPath() << " (" << settings_->base().particles
        << " particles, sampling " << settings_->base().samplingTime << " s, "
        << settings_->replicas().size() << " replicas)" << nl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::calibrationDEMRunner::runCondition
(
    const scalar phi,
    const scalar x,
    const scalar T
)
{
    const calibrationSettings& settings = *settings_;
    const std::map<std::string, std::string> stored =
        calibrationStore::storedConditions(file_);

    label ran = 0;
    for (const label seed : settings.replicas())
    {
        const std::string name = sdf::store::conditionName(phi, x, T, seed);

        // Stored already (by the utility or another calibrated model)?
        if
        (
            calibrationStore::isStored
            (
                file_, stored, name, settings.settingsKey()
            )
        )
        {
            continue;
        }

        const sdf::dem::CellRunSettings s =
            settings.conditionSettings(phi, x, T, seed, name);

        const auto t0 = std::chrono::steady_clock::now();
        sdf::dem::CellRunResult r;
        try
        {
            sdf::dem::validateCellRunSettings(s);
            noFloatingPointTraps guard;
            r = sdf::dem::runCell(s);
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "runDEM: the DEM engine stopped condition " << name.c_str()
                << ":" << nl << "    " << err.what() << nl << exit(FatalError);
        }

        // Stored at once, atomically, as calibrateGranularMixture stores a
        // condition
        try
        {
            sdf::store::ConditionInputs inputs;
            inputs.name = name;
            inputs.phi = phi;
            inputs.x = x;
            inputs.targetT = T;
            inputs.seed = seed;
            settings.appendToStore(file_, inputs, r);
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "runDEM: storing condition " << name.c_str() << " in "
                << file_ << " failed:" << nl << "    " << err.what() << nl
                << exit(FatalError);
        }

        const scalar seconds = std::chrono::duration<double>
        (
            std::chrono::steady_clock::now() - t0
        ).count();
        ++ran;
        ++conditionsRun_;
        secondsRun_ += seconds;
        Info<< "    runDEM: " << name.c_str() << " done in "
            << fmt(seconds).c_str() << " s (T = "
            << fmt(r.temperature).c_str() << ", D_"
            << settings.fine().name << " = "
            << fmt(r.species[0].greenKubo.integral.value).c_str()
            << " m2/s)" << endl;
        if (!r.species[0].diffusiveRegime.converged())
        {
            Info<< "    runDEM: " << name.c_str() << ": D_"
                << settings.fine().name << " not in the diffusive regime: "
                << r.species[0].diffusiveRegime.verdict().c_str()
                << " (stored as not converged; longer samplingTime or fewer"
                << " blocks lengthen the lags)" << endl;
        }
    }
    return ran;
}


bool Foam::calibrationDEMRunner::extend
(
    calibrationTable& table,
    const cellRanges& localRanges
)
{
    cellRanges r = localRanges;
    reduce(r.phiMin, minOp<scalar>());
    reduce(r.xMin, minOp<scalar>());
    reduce(r.TMin, minOp<scalar>());
    reduce(r.phiMax, maxOp<scalar>());
    reduce(r.xMax, maxOp<scalar>());
    reduce(r.TMax, maxOp<scalar>());

    // New axis values: where the cells (lo, hi) leave the axis, the extreme
    // cell value widened (wideLo, wideHi), rounded outward, clipped to the
    // DEM's range; kept only if it extends the axis (so a cell just beyond
    // a clip limit runs nothing again)
    auto newValues = []
    (
        const scalarList& axis,
        const scalar lo,
        const scalar hi,
        const scalar wideLo,
        const scalar wideHi,
        const scalar clipLo,
        const scalar clipHi
    )
    {
        // Within the 6 digits of the names a cell is on the grid's edge
        const scalar tol = 1e-6;
        DynamicList<scalar> values;
        if (lo < axis.first()*(1 - tol))
        {
            const scalar v = max(roundOutward(wideLo, false), clipLo);
            if (v < axis.first())
            {
                values.append(v);
            }
        }
        if (hi > axis.last()*(1 + tol))
        {
            const scalar v = min(roundOutward(wideHi, true), clipHi);
            if (v > axis.last())
            {
                values.append(v);
            }
        }
        return scalarList(values);
    };

    const scalar grow = 1 + margin_;
    const scalarList newPhi
    (
        newValues
        (
            table.phiAxis(), r.phiMin, r.phiMax, r.phiMin/grow, r.phiMax*grow,
            minPhi_, maxPhi_
        )
    );

    // x is a linear axis: widened by the margin times the grid's x span.
    // Why a margin at all: in silo2D the composition drifts by ~0.004 per
    // time step; the bare extreme value (margin 0) ran a new 9-condition
    // slice every step (1125 DEM runs in the first 0.28 s of discharge)
    const scalar xWiden =
        margin_*max(table.xAxis().last() - table.xAxis().first(), 0.1);
    const scalarList newX
    (
        newValues
        (
            table.xAxis(), r.xMin, r.xMax, r.xMin - xWiden, r.xMax + xWiden,
            xLowest, xHighest
        )
    );
    const scalarList newT
    (
        newValues
        (
            table.TAxis(), r.TMin, r.TMax, r.TMin/grow, r.TMax*grow,
            minT_, GREAT
        )
    );

    if (newPhi.empty() && newX.empty() && newT.empty())
    {
        return false;
    }

    // The new grid slices, axis after axis, so that the grid stays complete
    struct condition { scalar phi, x, T; };
    DynamicList<condition> conditions;
    scalarList phiAxis(table.phiAxis()), xAxis(table.xAxis());
    const scalarList& TAxis = table.TAxis();
    for (const scalar phi : newPhi)
    {
        for (const scalar x : xAxis)
        {
            for (const scalar T : TAxis)
            {
                conditions.append(condition{phi, x, T});
            }
        }
    }
    phiAxis.append(newPhi);
    for (const scalar x : newX)
    {
        for (const scalar phi : phiAxis)
        {
            for (const scalar T : TAxis)
            {
                conditions.append(condition{phi, x, T});
            }
        }
    }
    xAxis.append(newX);
    for (const scalar T : newT)
    {
        for (const scalar phi : phiAxis)
        {
            for (const scalar x : xAxis)
            {
                conditions.append(condition{phi, x, T});
            }
        }
    }

    Info<< "runDEM: cells holding material reach phi ["
        << fmt(r.phiMin).c_str() << ", " << fmt(r.phiMax).c_str() << "], x ["
        << fmt(r.xMin).c_str() << ", " << fmt(r.xMax).c_str() << "], T ["
        << fmt(r.TMin).c_str() << ", " << fmt(r.TMax).c_str()
        << "] beyond the grid of " << file_ << nl
        << "    new grid values: phi " << fmtList(newPhi).c_str()
        << ", x " << fmtList(newX).c_str() << ", T " << fmtList(newT).c_str()
        << ": " << conditions.size()
        << " conditions x " << settings_->replicas().size() << " replicas"
        << endl;

    const auto start = std::chrono::steady_clock::now();
    label ran = 0;
    if (Pstream::master())
    {
        for (const condition& c : conditions)
        {
            ran += runCondition(c.phi, c.x, c.T);
        }
    }
    // Every rank waits for the master's file before reading it
    reduce(ran, sumOp<label>());

    table.read();

    Info<< "runDEM: " << ran << " DEM runs in "
        << fmt
           (
               std::chrono::duration<double>
               (
                   std::chrono::steady_clock::now() - start
               ).count()
           ).c_str()
        << " s; table now " << table.phiAxis().size() << " phi x "
        << table.xAxis().size() << " x x " << table.TAxis().size()
        << " T, " << table.nConditions() << " conditions" << endl;

    return true;
}


// ************************************************************************* //

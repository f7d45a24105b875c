/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    calibrateGranularMixture

Group
    grpPreProcessingUtilities

Description
    Calibration workflow of a binary mixture: runs the embedded periodic DEM
    engine (calibration/dem) over an envelope of conditions (solids fraction
    phi, coarse fraction x, granular temperature T or, with mode leesEdwards,
    shear rate gammaDot, replicas), stores every
    finished condition at once in constant/calibration.h5 (a rerun skips the
    stored ones), fits constitutive laws (calibration/fit) to the diffusivity
    of the fines (D), the kinetic sieving coefficient of the coarse (eta)
    and, for breakage, the collision frequency (omega.<species>) and mean
    mass-specific impact energy (Wmean.<species>) of a particle of each
    species, chooses among candidate laws by AIC and writes
    constant/granularCoefficients.

    Species (d, rho) come from constant/granularProperties (exactly two: the
    smaller is the fine species); the rest from system/calibrationDict
    (entries: calibrationSettings.H). The units of the utility:
    - caseEnvelope       -fromCase [time]: the envelope (phi, x, T or gammaDot over the
                         cells with phi >= phiMin) from the case's fields and
                         the coefficients from the mechanisms granularProperties
                         switches on
    - conditionScheduler the conditions on worker threads (only the main
                         thread calls HDF5) and, under mpirun with -parallel,
                         over the ranks round-robin; progress with an ETA
    - calibration/store  the store: each rank appends to
                         constant/calibration.processor<N>.h5, the master
                         merges those into calibration.h5 at the end and at
                         the start of any run (no decomposition needed)
    - fitReport          fits, model selection, granularCoefficients, plots
    Bad input stops with a FatalIOError naming the entry; a calibration.h5
    that is not ours (corrupt, foreign) stops with a FatalError naming the
    file and is left untouched. Documentation: docs/user/calibration.md.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "sigFpe.H"
#include "Time.H"
#include "IOdictionary.H"

#include "granularMixture.H"
#include "calibrationSettings.H"
#include "demDictionary.H"
#include "calibrationStore.H"
#include "caseEnvelope.H"
#include "conditionScheduler.H"
#include "fitReport.H"
#include "rheologyReport.H"
#include "segregationReport.H"
#include "numberText.H"

#include "store/ProcessorStores.hpp"
#include "dem/ContactLaw.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

using namespace Foam;
using numberText::fmt;
using numberText::listText;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    #include "setOptions.H"

    #include "setRootCase.H"

    // The DEM engine and GSL's least squares handle IEEE infinities and
    // NaNs themselves (GSL's trust-region steps may overflow and recover);
    // OpenFOAM's floating-point trap would abort them
    sigFpe::unset();
    #include "createTime.H"

    #include "readDictionaries.H"

    // Species (the one reader of granularProperties), fine first
    const FixedList<granularSpecies, 2> species
    (
        calibrationSettings::fineAndCoarse
        (
            granularMixture::readSpecies(properties),
            properties.subDict("species")
        )
    );

    // With -fromCase the case gives the rheology cells' pressure
    calibrationSettings settings
    (
        dict, species[0], species[1], args.found("fromCase")
    );

    std::optional<caseEnvelope> fromCase;
    if (args.found("fromCase"))
    {
        fromCase = deriveEnvelope
        (
            runTime, properties, settings, args.get<word>("fromCase")
        );
        if (fromCase->rheologyPressure > 0)
        {
            settings.setRheologyPressure(fromCase->rheologyPressure);
        }
        if (!fromCase->segregationNormalStress.empty())
        {
            settings.setSegregationNormalStresses
            (
                fromCase->segregationNormalStress
            );
        }
        if
        (
            fromCase->coefficients.empty() && !settings.calibratesRheology()
         && !settings.calibratesSegregation()
        )
        {
            Info<< "Nothing to calibrate: constant/granularProperties switches"
                << " off both diffusivity and kineticSieving (model none)"
                << " and breakage is not calibrated."
                << " Nothing is run or written." << nl << nl << "End" << nl
                << endl;
            return 0;
        }
    }

    // The transport cells (D, eta, breakage) over the envelope phi x x x T
    // (or gammaDot), the rheology cells over I at the rheology's pressure
    calibrationSettings::envelopeAxes envelope;
    wordList coefficients(settings.transportCoefficients());
    if (fromCase)
    {
        envelope = fromCase->axes;
        coefficients = fromCase->coefficients;
    }
    else if (!coefficients.empty())
    {
        envelope = settings.envelope();
    }

    std::vector<calibrationCondition> conds;
    if (!coefficients.empty())
    {
        conds = envelopeConditions
        (
            envelope, settings.replicas(), settings.finiteSizeParticles()
        );
    }
    const std::vector<calibrationCondition> transportConds(conds);
    const std::vector<calibrationCondition> rheologyConds
    (
        rheologyConditions(settings)
    );
    conds.insert(conds.end(), rheologyConds.begin(), rheologyConds.end());
    const std::vector<calibrationCondition> segregationConds
    (
        segregationConditions(settings)
    );
    conds.insert(conds.end(), segregationConds.begin(), segregationConds.end());

    // Check every condition's DEM settings before running anything
    for (const calibrationCondition& c : conds)
    {
        try
        {
            if (c.segregation())
            {
                sdf::dem::validateGravityShearRunSettings
                (
                    settings.segregationCellSettings(c.normalStress, c.seed, c.name)
                );
            }
            else
            {
                sdf::dem::validateCellRunSettings(cellSettings(c, settings));
            }
        }
        catch (const std::exception& err)
        {
            FatalIOErrorInFunction(dict)
                << "The DEM engine refuses condition " << c.name.c_str() << ":"
                << nl << "    " << err.what() << nl << exit(FatalIOError);
        }
    }

    // The case's own directories (under -parallel runTime.path() is a
    // processor directory that need not exist)
    const fileName h5(runTime.globalPath()/runTime.constant()/"calibration.h5");
    // Conditions a killed parallel run left in processor stores first
    if (Pstream::master())
    {
        calibrationStore::mergeProcessorStores(h5);
    }
    if (Pstream::parRun())
    {
        label synchronised = 0;
        reduce(synchronised, sumOp<label>());
    }
    const std::map<std::string, std::string> stored =
        calibrationStore::storedConditions(h5);

    Info<< "Calibration of " << settings.fine().name << " (fine, d = "
        << settings.fine().d << ") / " << settings.coarse().name
        << " (coarse, d = " << settings.coarse().d << "), store " << h5 << nl;
    if (!transportConds.empty())
    {
        Info<< "Transport: "
            << label(transportConds.size()) << " conditions ("
            << envelope.phi.size() << " phi x " << envelope.x.size()
            << " x x " << envelope.rates().size() << " "
            << settings.rateName() << " x " << settings.replicas().size()
            << " replicas"
            << (
                   settings.finiteSizeParticles().empty()
                 ? std::string()
                 : " x "
                 + std::to_string(settings.finiteSizeParticles().size())
                 + " cell sizes"
               ).c_str()
            << (settings.sheared() ? ", sheared cells (Lees-Edwards)" : "")
            << ")" << nl;
    }
    if (!rheologyConds.empty())
    {
        const calibrationSettings::rheologyEnvelope& r = settings.rheology();
        const sdf::dem::CellRunSettings cell =
            cellSettings(rheologyConds.front(), settings);
        Info<< "Rheology: " << label(rheologyConds.size()) << " pressure-"
            << "controlled sheared cells (inertial number I "
            << listText(r.inertialNumber).c_str() << " x "
            << settings.replicas().size() << " replicas) at sigma_yy "
            << r.pressure << " Pa, x " << r.x << "; I = gammaDot d/sqrt(p/rho_s)"
            << " with d " << sdf::dem::meanDiameter(cell) << " m, rho_s "
            << sdf::dem::solidsDensity(cell) << " kg/m3" << nl;
    }
    if (!segregationConds.empty())
    {
        const calibrationSettings::segregationEnvelope& e = settings.segregation();
        const sdf::dem::CellRunSettings cell =
            cellSettings(segregationConds.front(), settings);
        const scalar pStarUnit =
            sdf::dem::solidsDensity(cell)*e.gravity*sdf::dem::meanDiameter(cell);
        Info<< "Segregation velocity: " << label(segregationConds.size())
            << " sheared cells under gravity (sigma_N "
            << listText(e.normalStress).c_str() << " Pa, p* = sigma_N/(rho_s g"
            << " dMean) " << listText(scalarList(e.normalStress/pStarUnit)).c_str()
            << " at the top wall, x " << settings.replicas().size()
            << " replicas): " << e.particles << " grains, x " << e.x
            << ", U " << e.wallSpeed << " m/s, " << e.developmentTime
            << " s of development and " << e.samplingTime << " s of sampling;"
            << " S by the " << e.estimator.c_str() << " estimator" << nl;
    }
    if (!conds.empty())
    {
        // the step the cells run at and the largest the engine accepts, so a
        // user can set `timeStep` (e.g. t_c/50 for a case's sheared envelope)
        const calibrationCondition& c = conds.front();
        const sdf::dem::CellRunSettings cell = cellSettings(c, settings);
        const sdf::dem::ContactLaw law(cell.simulation.contact, cell.species);
        const double maximum = law.maximumTimeStep();
        const double step = cell.simulation.timeStep;
        Info<< "DEM time step "
            << (step > 0 ? step : law.defaultTimeStep()) << " s ("
            << (
                   step > 0 ? std::string("timeStep")
                 : "timeStep 0: " + law.defaultTimeStepRule()
               ).c_str()   // a std::string would be written quoted
            << "; the largest accepted, " << law.maximumTimeStepRule().c_str()
            << ": " << maximum << " s)" << nl;
    }
    Info<< endl;

    // A stored condition is reused only if run with the same DEM settings
    std::vector<bool> isStored(conds.size());
    for (std::size_t i = 0; i < conds.size(); ++i)
    {
        isStored[i] = calibrationStore::isStored
        (
            h5, stored, conds[i].name, settingsKeyOf(conds[i], settings)
        );
    }

    if (args.found("dryRun"))
    {
        label toRun = 0;
        for (const bool s : isStored)
        {
            if (!s) ++toRun;
        }
        if (!transportConds.empty())
        {
            Info<< "Envelope: phi " << listText(envelope.phi).c_str()
                << ", x " << listText(envelope.x).c_str() << ", "
                << settings.rateName() << " "
                << listText(envelope.rates()).c_str() << ", coefficients (";
            for (const word& c : coefficients)
            {
                Info<< (&c == &coefficients.first() ? "" : " ") << c;
            }
            Info<< ")" << nl;
        }
        Info<< "Dry run (-dryRun): " << toRun << " of "
            << label(conds.size()) << " conditions would run, "
            << label(conds.size()) - toRun << " are stored; nothing is run"
            << " or written" << nl << nl << "End" << nl << endl;
        return 0;
    }

    // Run the conditions still missing from the store: without -parallel
    // several at once on this machine's cores; with -parallel spread over
    // the ranks, each storing its conditions in its own store, merged by
    // the master at the end
    std::vector<label> toRun;
    for (label i = 0; i < label(conds.size()); ++i)
    {
        const calibrationCondition& c = conds[i];
        if (isStored[i])
        {
            Info<< "skipping condition " << i + 1 << "/" << label(conds.size())
                << " (" << c.text().c_str() << ") (already in calibration.h5)"
                << endl;
        }
        else
        {
            toRun.push_back(i);
        }
    }
    const std::vector<label> mine
    (
        longestFirst(conds, conditionsOfThisRank(conds, toRun), settings)
    );

    OSstream& progress = Pstream::parRun() ? Pout : Info();
    const label workers =
        conditionWorkers(settings, label(mine.size()), progress);
    const fileName store =
        Pstream::parRun()
      ? fileName(sdf::store::processorStorePath(h5, Pstream::myProcNo()))
      : h5;
    const auto start = std::chrono::steady_clock::now();
    label ran = runConditions(conds, mine, settings, workers, store, progress);

    if (Pstream::parRun())
    {
        // Every rank has stored its conditions once all arrive here
        reduce(ran, sumOp<label>());
        if (Pstream::master())
        {
            calibrationStore::mergeProcessorStores(h5);
        }
    }
    label taken = 0;
    for (const bool s : isStored)
    {
        if (s) ++taken;
    }
    Info<< nl << "DEM: " << ran << " conditions run and stored, "
        << taken << " taken from " << h5 << ", "
        << fmt(std::chrono::duration<double>
           (std::chrono::steady_clock::now() - start).count()).c_str()
        << " s" << nl << endl;

    // Only the master fits and writes
    if (!Pstream::master())
    {
        return 0;
    }
    if (args.found("noFit"))
    {
        Info<< "End (no fit: -noFit)" << nl << endl;
        return 0;
    }

    if (!transportConds.empty())
    {
        fitAndReport
        (
            runTime, h5, settings, envelope, coefficients, transportConds
        );
    }
    if (!rheologyConds.empty())
    {
        fitRheologyAndReport(runTime, h5, settings, rheologyConds);
    }
    if (!segregationConds.empty())
    {
        fitSegregationAndReport(runTime, h5, settings, segregationConds);
    }

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    periodicDEM

Group
    grpPreProcessingUtilities

Description
    Front door of the embedded DEM engine (calibration/): runs one periodic
    DEM cell in a case directory, prints a summary and writes
    postProcessing/periodicDEM/<name>.h5 (layout: docs/developer/hdf5-layout.md).

    Species (d, rho) come from constant/granularProperties; the cell from
    system/periodicDEMDict:
    \verbatim
    name            dilute;         // output postProcessing/periodicDEM/<name>.h5
    composition     { fine 0.8; coarse 0.2; }   // share of the solids volume
    particles       1000;
    solidsFraction  0.3;
    mode            thermostatted;  // nve | thermostatted | stochastic | leesEdwards
    temperature     0.03;           // target T, sum of 3 components [m2/s2]
    shearRate       10;             // [1/s], leesEdwards
    contact
    {
        model       linearSpringDashpot;    // linearSpringDashpot | hertzMindlin
        restitution 0.9;
        friction    0.5;
        normalStiffness 2e5;        // [N/m] linear
        youngsModulus   1e7;        // [Pa] Hertz
        poissonRatio    0.3;
        pairs                       // optional: constants of one species pair
        {
            fineCoarse { species (fine coarse); restitution 0.7; friction 0.4; }
        }
    }
    timeStep            0;          // 0: half the recommended maximum
    equilibrationTime   0.02;       // [s]
    samplingTime        0.5;        // [s]
    sampleEvery         10;         // [steps]
    blocks              8;          // for the statistical errors
    seed                1;
    threads             0;          // OpenMP threads (0: default)
    progressEvery       10000;      // [steps]
    \endverbatim
    Bad input (an unknown entry, a value the engine refuses) stops with a
    FatalIOError naming the entry; no output file is left half-written (the
    engine writes <name>.h5.tmp and renames it).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "sigFpe.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OSspecific.H"

#include "demDictionary.H"
#include "granularMixture.H"

#include <stdexcept>

using namespace Foam;

namespace
{

//- Entries besides the cell's settings (calibration/transport/CellSettings.hpp)
const wordList otherEntries
({
    "name", "composition", "mode", "progressEvery"
});


sdf::dem::CellRunSettings readSettings
(
    const dictionary& properties,
    const dictionary& dict
)
{
    wordList valid(otherEntries);
    valid.append(demDictionary::settingNames(sdf::dem::CellSetting::Scope::condition));
    valid.append(demDictionary::runControlEntries());
    modelCoeffs::checkKeys(dict, valid);

    sdf::dem::CellRunSettings s;

    // Species (granularMixture's reader) and composition
    const List<granularSpecies> declared
    (
        granularMixture::readSpecies(properties)
    );
    const dictionary& composition = dict.subDict("composition");
    for (const word& name : composition.toc())
    {
        const granularSpecies* found = nullptr;
        for (const granularSpecies& sp : declared)
        {
            if (sp.name == name)
            {
                found = &sp;
            }
        }
        if (!found)
        {
            FatalIOErrorInFunction(composition)
                << "Species '" << name << "' of 'composition' is not declared"
                << " in constant/granularProperties; declared: "
                << properties.subDict("species").toc() << nl
                << exit(FatalIOError);
        }
        s.species.push_back({name, found->d, found->rho});
        s.volumeFractions.push_back(composition.get<scalar>(name));
    }
    if (s.species.empty())
    {
        FatalIOErrorInFunction(composition)
            << "'composition' names no species" << nl << exit(FatalIOError);
    }

    // particles, solidsFraction, temperature, shearRate, seed
    demDictionary::readSettings(dict, sdf::dem::CellSetting::Scope::condition, s);

    sdf::dem::SimulationSettings& sim = s.simulation;
    try
    {
        sim.mode = sdf::dem::cellModeFromName
        (
            dict.getOrDefault<word>("mode", "thermostatted")
        );
    }
    catch (const std::exception& err)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mode': " << err.what() << nl << exit(FatalIOError);
    }
    demDictionary::readRunControls(dict, s);
    s.progressEvery = dict.getOrDefault<label>("progressEvery", 10000);
    s.label = dict.getOrDefault<word>("name", "periodicDEM");

    return s;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Run one periodic DEM cell (system/periodicDEMDict, species from"
        " constant/granularProperties) and write"
        " postProcessing/periodicDEM/<name>.h5"
    );
    argList::noParallel();

    #include "setRootCase.H"

    // The DEM engine and GSL's least squares handle IEEE infinities and
    // NaNs themselves (GSL's trust-region steps may overflow and recover);
    // OpenFOAM's floating-point trap would abort them
    sigFpe::unset();
    #include "createTime.H"

    const IOdictionary properties
    (
        demDictionary::readCaseDictionary
        (
            runTime, "granularProperties", runTime.constant()
        )
    );
    const IOdictionary dict
    (
        demDictionary::readCaseDictionary(runTime, "periodicDEMDict", runTime.system())
    );

    const sdf::dem::CellRunSettings settings = readSettings(properties, dict);

    const fileName outDir(runTime.globalPath()/"postProcessing"/"periodicDEM");
    const fileName outFile(outDir/(settings.label + ".h5"));

    sdf::dem::CellRunResult result;
    try
    {
        sdf::dem::validateCellRunSettings(settings);
        Info<< "Running periodic DEM cell '" << settings.label << "': "
            << settings.particles << " particles, solids fraction "
            << settings.solidsFraction << nl << endl;
        result = sdf::dem::runCell(settings);
    }
    catch (const std::exception& err)
    {
        FatalIOErrorInFunction(dict)
            << "The DEM engine refused or stopped the cell:" << nl
            << "    " << err.what() << nl << exit(FatalIOError);
    }

    Info<< sdf::dem::summary(result).c_str() << nl;

    mkDir(outDir);
    try
    {
        sdf::dem::writeCellRun(result, outFile);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Writing " << outFile << " failed:" << nl
            << "    " << err.what() << nl << exit(FatalError);
    }

    Info<< "Written " << outFile << " (h5dump -H to inspect)" << nl
        << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

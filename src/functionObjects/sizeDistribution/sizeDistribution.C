/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "sizeDistribution.H"
#include "caseFields.H"
#include "fvc.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(sizeDistribution, 0);
    addToRunTimeSelectionTable(functionObject, sizeDistribution, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::sizeDistribution::sizeDistribution
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    species_(caseSpecies(mesh_)),
    file_(),
    volume_(species_.size(), Zero),
    hasDust_(false),
    hasBroken_(false),
    dust_(0),
    broken_(0),
    startTimeName_(runTime.timeName()),
    headerWritten_(false)
{
    const dictionary properties(caseGranularProperties(mesh_));
    if (properties.isDict("breakage"))
    {
        const dictionary& breakage = properties.subDict("breakage");
        const bool breaks =
            breakage.getOrDefault<word>("model", "none") != "none";
        hasDust_ =
            breaks
         && breakage.getOrDefault<word>("fines", "finestClass") == "dust";
        hasBroken_ =
            breaks
         && properties.getOrDefault<wordList>("writeFields", wordList())
           .found("brokenVolume");
    }

    std::stable_sort
    (
        species_.begin(),
        species_.end(),
        [](const granularSpecies& a, const granularSpecies& b)
        {
            return a.d < b.d;
        }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::sizeDistribution::execute()
{
    forAll(species_, k)
    {
        volume_[k] = fvc::domainIntegrate
        (
            registeredOrRead(mesh_, "n." + species_[k].name)()
        ).value();
    }

    auto optionalVolume = [this](const bool column, const word& fieldName)
    {
        if (!column)
        {
            return scalar(0);
        }
        tmp<volScalarField> tfield(registeredOrRead(mesh_, fieldName, true));
        return tfield.valid() ? fvc::domainIntegrate(tfield()).value() : 0;
    };
    dust_ = optionalVolume(hasDust_, "dust");
    broken_ = optionalVolume(hasBroken_, "brokenVolume");
    return true;
}


bool Foam::functionObjects::sizeDistribution::write()
{
    if (!Pstream::master())
    {
        return true;
    }
    if (!headerWritten_)
    {
        const fileName dir
        (
            time_.globalPath()/functionObject::outputPrefix/name()
           /startTimeName_
        );
        mkDir(dir);
        fileName path(dir/"sizeDistribution.dat");
        if (postProcess && isFile(path))
        {
            path = dir/"sizeDistribution_" + startTimeName_ + ".dat";
        }
        file_.reset(new OFstream(path));
        OFstream& os = file_();
        os.precision(12);
        os  << "# Size distribution of the solids in the domain (species by"
            << " increasing d; number = volume/(pi d^3/6))" << nl
            << "# time[s]";
        for (const granularSpecies& s : species_)
        {
            os << " volume." << s.name << "[m3]";
        }
        for (const granularSpecies& s : species_)
        {
            os << " number." << s.name;
        }
        if (hasDust_)
        {
            os << " dust[m3]";
        }
        if (hasBroken_)
        {
            os << " broken[m3]";
        }
        os << endl;
        headerWritten_ = true;
    }

    OFstream& os = file_();
    os << time_.value();
    for (const scalar v : volume_)
    {
        os << ' ' << v;
    }
    forAll(species_, k)
    {
        os << ' '
           << volume_[k]/species_[k].particleVolume();
    }
    if (hasDust_)
    {
        os << ' ' << dust_;
    }
    if (hasBroken_)
    {
        os << ' ' << broken_;
    }
    os << endl;
    return true;
}


// ************************************************************************* //

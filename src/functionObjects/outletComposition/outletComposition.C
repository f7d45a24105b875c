/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "outletComposition.H"
#include "granularMixture.H"
#include "openPatches.H"
#include "caseFields.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(outletComposition, 0);
    addToRunTimeSelectionTable(functionObject, outletComposition, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField>
Foam::functionObjects::outletComposition::flux
(
    const word& phiName,
    const bool optional
) const
{
    if (postProcess)
    {
        IOobject phiHeader
        (
            phiName,
            time_.timeName(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (phiHeader.typeHeaderOk<surfaceScalarField>(true))
        {
            return tmp<surfaceScalarField>::New(phiHeader, mesh_);
        }
    }

    const surfaceScalarField* registered =
        mesh_.findObject<surfaceScalarField>(phiName);
    if (!registered && optional)
    {
        return tmp<surfaceScalarField>();
    }
    if (!registered)
    {
        FatalErrorInFunction
            << "Function object " << name() << ": no face flux '"
            << phiName << "' at time " << time_.timeName()
            << " (registered or written in the time directory)" << nl
            << exit(FatalError);
    }
    return tmp<surfaceScalarField>(*registered);
}


void Foam::functionObjects::outletComposition::createFiles()
{
    files_.clear();
    if (!Pstream::master())
    {
        return;
    }

    const fileName dir
    (
        time_.globalPath()/functionObject::outputPrefix/name()
       /time_.timeName()
    );
    mkDir(dir);

    files_.setSize(patches_.size());
    forAll(patches_, pi)
    {
        const word& patchName = mesh_.boundary()[patches_[pi]].name();

        // Post-processing keeps the run's file: <patch>_<time>.dat beside
        // it, as OpenFOAM's writeFile does
        fileName path(dir/patchName + ".dat");
        if (postProcess && isFile(path))
        {
            path = dir/patchName + "_" + time_.timeName() + ".dat";
        }
        files_.set(pi, new OFstream(path));

        OFstream& os = files_[pi];
        // 15 digits: balances over a run are checked to 1e-10 of the inflow
        os.precision(15);
        os  << "# Flow through patch " << patchName
            << " (positive leaving the domain)" << nl
            << "# time[s] Q[m3/s] massFlow[kg/s]";
        for (const granularSpecies& s : species_)
        {
            os << " massFlow." << s.name << "[kg/s]";
        }
        for (const granularSpecies& s : species_)
        {
            os << " massFraction." << s.name;
        }
        for (const granularSpecies& s : species_)
        {
            os << " cumulativeMass." << s.name << "[kg]";
        }
        os << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::outletComposition::outletComposition
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    species_(),
    phiName_("phi"),
    patches_(),
    files_(),
    flows_(),
    cumulative_(),
    previousTime_(runTime.value())
{
    // The species of the running solver's mixture, else of the case's
    // constant/granularProperties (post-processing)
    species_ = caseSpecies(mesh_);

    read(dict);

    // Optional, default every open patch: non-coupled, generic type `patch`
    if (dict.found("patches"))
    {
        const wordRes patchNames(dict.get<wordRes>("patches"));
        patches_ = mesh_.boundaryMesh().patchSet(patchNames).sortedToc();
        if (patches_.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Function object " << name << ": 'patches' "
                << patchNames << " match no patch; patches: "
                << mesh_.boundaryMesh().names() << nl << exit(FatalIOError);
        }
    }
    else
    {
        patches_ = openPatches(mesh_);
    }

    flows_.setSize(patches_.size(), scalarList(species_.size() + 1, Zero));
    cumulative_.setSize(patches_.size(), scalarList(species_.size(), Zero));

    // Files in the directory of the run's start time; when post-processing
    // in that of the first time processed (created there)
    if (!postProcess)
    {
        createFiles();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::outletComposition::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);

    // Optional, default phi (the solver's bulk flux)
    phiName_ = dict.getOrDefault<word>("phi", "phi");

    return true;
}


bool Foam::functionObjects::outletComposition::execute()
{
    const tmp<surfaceScalarField> tphi(flux(phiName_));
    const surfaceScalarField& phi = tphi();

    // A species with a flux of its own (phi.<species>, bulkFlow
    // particlePass) crosses with it; the species of a bulk with a free
    // surface (bulkFlow muI) have their volume fluxes, nPhi.<species>
    List<tmp<volScalarField>> n(species_.size());
    List<tmp<surfaceScalarField>> speciesPhi(species_.size());
    List<tmp<surfaceScalarField>> speciesFlux(species_.size());
    forAll(species_, k)
    {
        speciesFlux[k] = flux("nPhi." + species_[k].name, true);
        if (!speciesFlux[k].valid())
        {
            n[k] = registeredOrRead(mesh_, "n." + species_[k].name);
            speciesPhi[k] = flux(phiName_ + "." + species_[k].name, true);
        }
    }

    // The solver's time step; between the processed times afterwards
    const scalar dt =
        postProcess
      ? time_.value() - previousTime_
      : time_.deltaTValue();
    previousTime_ = time_.value();

    forAll(patches_, pi)
    {
        const label patchi = patches_[pi];
        const scalarField& phip = phi.boundaryField()[patchi];

        scalarList& flows = flows_[pi];
        flows[0] = gSum(phip);
        forAll(species_, k)
        {
            scalar massFlow = 0;
            if (speciesFlux[k].valid())
            {
                massFlow =
                    species_[k].rho
                   *gSum(speciesFlux[k]().boundaryField()[patchi]);
            }
            else
            {
                const scalarField& phik =
                    speciesPhi[k].valid()
                  ? speciesPhi[k]().boundaryField()[patchi]
                  : phip;
                massFlow =
                    species_[k].rho
                   *gSum(phik*n[k]().boundaryField()[patchi]);
            }
            flows[k + 1] = massFlow;
            cumulative_[pi][k] += massFlow*dt;
        }
    }

    return true;
}


bool Foam::functionObjects::outletComposition::write()
{
    if (!Pstream::master())
    {
        return true;
    }
    if (files_.empty() && !patches_.empty())
    {
        createFiles();
    }

    forAll(patches_, pi)
    {
        const scalarList& flows = flows_[pi];
        scalar total = 0;
        forAll(species_, k)
        {
            total += flows[k + 1];
        }

        OFstream& os = files_[pi];
        os  << time_.value() << ' ' << flows[0] << ' ' << total;
        forAll(species_, k)
        {
            os << ' ' << flows[k + 1];
        }
        forAll(species_, k)
        {
            os << ' ' << (mag(total) > VSMALL ? flows[k + 1]/total : 0);
        }
        forAll(species_, k)
        {
            os << ' ' << cumulative_[pi][k];
        }
        os << endl;
    }

    return true;
}


// ************************************************************************* //

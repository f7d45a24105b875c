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
#include "convectionScheme.H"
#include "coupledPolyPatch.H"
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


Foam::scalar Foam::functionObjects::outletComposition::zoneSum
(
    const label zonei,
    const surfaceScalarField& f
) const
{
    const faceZone& zone = mesh_.faceZones()[zonei];
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    scalar sum = 0;
    forAll(zone, i)
    {
        const label facei = zone[i];
        const scalar sign = zone.flipMap()[i] ? -1 : 1;
        if (mesh_.isInternalFace(facei))
        {
            sum += sign*f[facei];
            continue;
        }
        const label patchi = patches.whichPatch(facei);
        const polyPatch& pp = patches[patchi];
        // Only what crosses inside the domain: a zone's faces on walls or
        // other boundaries are not crossings. A processor face is in the
        // zone on both sides: counted on the owner's (its value there is
        // the owner's orientation)
        if
        (
            !isA<coupledPolyPatch>(pp)
         || !refCast<const coupledPolyPatch>(pp).owner()
        )
        {
            continue;
        }
        sum += sign*f.boundaryField()[patchi][facei - pp.start()];
    }
    return returnReduce(sum, sumOp<scalar>());
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

    files_.setSize(patches_.size() + zones_.size());
    forAll(files_, pi)
    {
        const bool isZone = pi >= patches_.size();
        const word& patchName =
            isZone
          ? mesh_.faceZones()[zones_[pi - patches_.size()]].name()
          : mesh_.boundary()[patches_[pi]].name();

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
        if (isZone)
        {
            os  << "# Flow through face zone " << patchName
                << " (positive along its orientation; advective)" << nl;
        }
        else
        {
            os  << "# Flow through patch " << patchName
                << " (positive leaving the domain)" << nl;
        }
        os
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

    // Optional, default none: face zones inside the domain
    if (dict.found("faceZones"))
    {
        const wordRes zoneNames(dict.get<wordRes>("faceZones"));
        zones_ = mesh_.faceZones().indices(zoneNames);
        if (zones_.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Function object " << name << ": 'faceZones' "
                << zoneNames << " match no face zone; face zones: "
                << mesh_.faceZones().names() << nl << exit(FatalIOError);
        }
    }

    const label nMonitored = patches_.size() + zones_.size();
    flows_.setSize(nMonitored, scalarList(species_.size() + 1, Zero));
    cumulative_.setSize(nMonitored, scalarList(species_.size(), Zero));

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

    if (zones_.empty())
    {
        return true;
    }

    // Through the face zones: each species' advective volume flux on every
    // face, as the solver forms it
    List<tmp<surfaceScalarField>> advective(species_.size());
    forAll(species_, k)
    {
        if (speciesFlux[k].valid())
        {
            advective[k] = speciesFlux[k];
            continue;
        }
        if (!speciesPhi[k].valid())
        {
            FatalErrorInFunction
                << "Function object " << name() << ": faceZones need each "
                << "species' own flux (phi." << species_[k].name
                << ", bulkFlow particlePass) or nPhi." << species_[k].name
                << " (bulkFlow muI); species sharing the bulk flux cross "
                << "with speciesAdvection's limited weights, which this "
                << "function object does not see" << nl << exit(FatalError);
        }
        const surfaceScalarField& phik = speciesPhi[k]();
        advective[k] =
            fv::convectionScheme<scalar>::New
            (
                mesh_,
                phik,
                mesh_.divScheme("div(phi,n)")
            )().flux(phik, n[k]());
    }
    forAll(zones_, zi)
    {
        const label pi = patches_.size() + zi;
        scalarList& flows = flows_[pi];
        flows[0] = zoneSum(zones_[zi], phi);
        forAll(species_, k)
        {
            const scalar massFlow =
                species_[k].rho*zoneSum(zones_[zi], advective[k]());
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
    if (files_.empty() && (patches_.size() || zones_.size()))
    {
        createFiles();
    }

    forAll(files_, pi)
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

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "ParticlePass.H"
#include "caseFields.H"
#include "parcelSpecies.H"
#include "countingWindow.H"
#include "BreakingRebound.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "OFstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::label Foam::ParticlePass<CloudType>::speciesOf(const parcelType& p) const
{
    return parcelSpecies(species_, p.d(), p.rho());
}


template<class CloudType>
bool Foam::ParticlePass<CloudType>::recording() const
{
    return countingFrom(this->owner().mesh().time(), startTime_);
}


template<class CloudType>
Foam::scalar Foam::ParticlePass<CloudType>::span() const
{
    return max(this->owner().mesh().time().value() - startTime_, scalar(0));
}


template<class CloudType>
void Foam::ParticlePass<CloudType>::writeFields() const
{
    const fvMesh& mesh = this->owner().mesh();
    const scalar T = span();
    if (!(T > 0))
    {
        return;
    }
    const surfaceScalarField& phiGas =
        mesh.template lookupObject<surfaceScalarField>("phi");
    const vectorField& Ugas =
        mesh.template lookupObject<volVectorField>("U").primitiveField();
    const labelUList& own = mesh.faceOwner();
    const labelUList& nei = mesh.faceNeighbour();
    const scalarField& V = mesh.V().field();

    auto ioNew = [&mesh](const word& name)
    {
        return IOobject
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        );
    };

    // Fragments born and volume broken per cell, when the walls break
    // parcels (breakingRebound)
    const auto* breaking =
        dynamic_cast<const BreakingRebound<CloudType>*>
        (
            &this->owner().patchInteraction()
        );
    if (breaking && mag(breaking->startTime() - startTime_) > SMALL)
    {
        FatalErrorInFunction
            << "particlePass startTime " << startTime_ << " and"
            << " breakingRebound startTime " << breaking->startTime()
            << " differ: the fragments born and the volume broken would be"
            << " counted over another window than the crossings. Set both"
            << " to the same time (tutorials/pipeBend: recordFrom)"
            << exit(FatalError);
    }

    // Cells beside an open (non-wall) patch: their inflow is the feed
    boolList feedCell(mesh.nCells(), false);
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (!isA<wallPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                feedCell[own[pp.start() + i]] = true;
            }
        }
    }

    forAll(species_, j)
    {
        const word& name = species_[j].name;

        // Mean velocity of the class: residence-weighted, so alphaPass
        // UPass is the time-averaged solids volume flux density
        const scalarField& residence = residence_[j];
        volVectorField U
        (
            ioNew("UPass." + name),
            mesh,
            dimensionedVector(dimVelocity, Zero),
            zeroGradientFvPatchVectorField::typeName
        );
        forAll(U, celli)
        {
            if (residence[celli] > 0)
            {
                U[celli] = momentumResidence_[j][celli]/residence[celli];
            }
        }
        U.correctBoundaryConditions();
        U.write();

        // The crossed solids volume per second: the class's volume flux F
        // through every face, outward positive on boundary faces
        scalarField F(crossed_[j]/T);

        // What each cell receives and gives per second. With
        // breakingRebound walls, fragments born in a cell add to what it
        // receives and the volume broken out of the class takes from it
        // (the continuum's own sources do the same there)
        scalarField outflow(mesh.nCells()), inflow(mesh.nCells());
        auto balance = [&]()
        {
            outflow = Zero;
            inflow = Zero;
            forAll(nei, facei)
            {
                outflow[F[facei] > 0 ? own[facei] : nei[facei]] += mag(F[facei]);
                inflow[F[facei] > 0 ? nei[facei] : own[facei]] += mag(F[facei]);
            }
            for (label facei = mesh.nInternalFaces(); facei < F.size(); ++facei)
            {
                outflow[own[facei]] += max(F[facei], scalar(0));
                inflow[own[facei]] += max(-F[facei], scalar(0));
            }
            if (breaking)
            {
                inflow += breaking->bornVolume()[j]/T;
                inflow = max(inflow - breaking->lostVolume()[j]/T, scalar(0));
            }
        };
        balance();

        // Cells the class enters and never leaves: its particles came to
        // rest there (on the pipe floor, where the gas at the wall is too
        // slow to lift them; the pass has no particle contact). In the
        // continuum such a cell would fill without bound: it passes on what
        // it receives with the gas instead, through the faces the gas
        // leaves it by and the class never crossed, shared as the gas
        // flux; repeated while that makes a new such cell downstream
        label drained = 0;
        for (label sweep = 0; sweep < 1000; ++sweep)
        {
            label drainedNow = 0;
            forAll(inflow, celli)
            {
                if (feedCell[celli] || !(inflow[celli] > 0) || outflow[celli] > 0)
                {
                    continue;
                }
                const labelList& faces = mesh.cells()[celli];
                scalar gasOut = 0;
                for (const label facei : faces)
                {
                    if (mesh.isInternalFace(facei) && F[facei] == 0)
                    {
                        const scalar out =
                            own[facei] == celli ? phiGas[facei] : -phiGas[facei];
                        gasOut += max(out, scalar(0));
                    }
                }
                if (!(gasOut > 0))
                {
                    continue;
                }
                for (const label facei : faces)
                {
                    if (mesh.isInternalFace(facei) && F[facei] == 0)
                    {
                        const scalar sign = own[facei] == celli ? 1 : -1;
                        const scalar out = sign*phiGas[facei];
                        if (out > 0)
                        {
                            F[facei] = sign*inflow[celli]*out/gasOut;
                        }
                    }
                }
                ++drainedNow;
            }
            if (!drainedNow)
            {
                break;
            }
            drained += drainedNow;
            balance();
        }

        // Each cell passes on what it receives: its outflow is scaled by
        // inflow/outflow, so the continuum's steady hold-up is alphaPass in
        // every cell. A pass is never quite steady (particles inside when
        // recording starts or ends): unscaled, a cell that received more
        // than it gave would fill up in the continuum without bound. Cells
        // beside an open patch keep their crossings (their inflow is the
        // feed, not a crossing); cells the class left without entering
        // (present when recording started) too
        scalarField passOn(mesh.nCells(), scalar(1));
        label sinks = 0;
        forAll(passOn, celli)
        {
            if (feedCell[celli] || !(inflow[celli] > 0))
            {
                continue;
            }
            if (outflow[celli] > 0)
            {
                passOn[celli] = inflow[celli]/outflow[celli];
            }
            else
            {
                ++sinks;
            }
        }

        // The volume fraction the flux carries: the residence fraction,
        // raised in cells the class only clipped (a particle crossing a
        // corner spends almost no time in the cell, so crossed volume over
        // residence would be an unbounded velocity): no cell's outflow
        // velocity exceeds twice the largest of the class's and the gas's
        // speed there and the class's mean speed (cell Courant number
        // bounded by that speed's; the mean speed bounds cells the class
        // left without residence, in still gas)
        scalar speedSum = 0;
        forAll(residence, celli)
        {
            speedSum += mag(momentumResidence_[j][celli]);
        }
        const scalar meanSpeed = speedSum/max(sum(residence), VSMALL);
        volScalarField alpha
        (
            ioNew("alphaPass." + name),
            mesh,
            dimensionedScalar(dimless, Zero),
            zeroGradientFvPatchScalarField::typeName
        );
        label raised = 0, visited = 0;
        forAll(alpha, celli)
        {
            visited += (residence[celli] > 0);
            alpha[celli] = residence[celli]/(V[celli]*T);
            if (outflow[celli] > 0)
            {
                const scalar speedCap =
                    2*max(max(mag(U[celli]), mag(Ugas[celli])), meanSpeed)
                  + SMALL;
                const scalar minAlpha =
                    passOn[celli]*outflow[celli]
                   /(speedCap*Foam::cbrt(sqr(V[celli])));
                if (alpha[celli] < minAlpha)
                {
                    alpha[celli] = minAlpha;
                    ++raised;
                }
            }
        }
        alpha.correctBoundaryConditions();
        alpha.write();

        // The class's own face flux: the crossed volume over the upwind
        // cell's alphaPass, so that alphaPass advected with phiPass and
        // upwind weights carries exactly the crossed volume (the continuum
        // holds the pass's hold-up and impacts the pass's wall cells).
        // Faces between cells the class never visited carry the gas flux
        // (its fragments move with the gas where it never went), and so do
        // faces from such a cell into a visited one where the gas flows
        // that way (fragments drain into the class's own flow); nothing
        // enters an unvisited region, so no pocket of it fills up. Faces
        // the class never crossed between visited cells, or from a visited
        // cell into an unvisited one, carry 0; walls 0
        surfaceScalarField phi(ioNew("phiPass." + name), phiGas);
        forAll(nei, facei)
        {
            const label up = F[facei] > 0 ? own[facei] : nei[facei];
            const bool o = residence[own[facei]] > 0;
            const bool n = residence[nei[facei]] > 0;
            if (F[facei] != 0)
            {
                phi[facei] = F[facei]*passOn[up]/alpha[up];
            }
            else if (o && n)
            {
                phi[facei] = 0;
            }
            else if (o || n)
            {
                // Gas from the unvisited side (owner to neighbour positive)
                const scalar g = phiGas[facei];
                phi[facei] = ((g > 0) == n) ? g : 0;
            }
        }
        forAll(mesh.boundaryMesh(), patchi)
        {
            const polyPatch& pp = mesh.boundaryMesh()[patchi];
            scalarField& pphi = phi.boundaryFieldRef()[patchi];
            if (isA<wallPolyPatch>(pp))
            {
                pphi = 0;
                continue;
            }
            // Open patches: what left through the face; inflow (an inlet:
            // parcels are injected inside the first cells and never cross
            // the inlet face) at the class's velocity in the cell beside
            // the face; beside cells the class never visited, only what
            // the gas carries out (the feed enters where the class went)
            forAll(pp, i)
            {
                const label facei = pp.start() + i;
                const label celli = own[facei];
                const scalar outward =
                    mesh.Sf().boundaryField()[patchi][i] & U[celli];
                if (F[facei] > 0)
                {
                    pphi[i] = F[facei]*passOn[celli]/alpha[celli];
                }
                else if (residence[celli] > 0)
                {
                    pphi[i] = min(outward, scalar(0));
                }
                else
                {
                    pphi[i] = max(pphi[i], scalar(0));
                }
            }
        }
        phi.write();

        Info<< "    particlePass: " << name << ": alphaPass raised in "
            << raised << " clipped cells (of " << visited << " visited); "
            << drained << " cells pass it on with the gas (where it came to"
            << " rest, and downstream); " << sinks
            << " cells received it and never gave it on"
            << endl;

        // Wall fields: nParticle-weighted means over the impacts of each
        // wall face, 0 on faces without impacts
        const label nB = mesh.nBoundaryFaces();
        scalarField count(nB, Zero), volume(nB, Zero), speed(nB, Zero);
        scalarField normal(nB, Zero), tangential(nB, Zero), angle(nB, Zero);
        const scalar Vp = species_[j].particleVolume();
        for (const impactRecord& r : impacts_[j])
        {
            const label b = r.face - mesh.nInternalFaces();
            count[b] += r.nParticle;
            volume[b] += r.nParticle*Vp;
            speed[b] += r.nParticle*r.speed();
            normal[b] += r.nParticle*r.Un;
            tangential[b] += r.nParticle*r.Ut;
            angle[b] += r.nParticle*r.angle();
        }

        auto writeWallField =
            [&](const word& fieldName, const dimensionSet& dims,
                const scalarField& sum, const bool perAreaTime)
        {
            volScalarField f
            (
                ioNew(fieldName + "." + name),
                mesh,
                dimensionedScalar(dims, Zero)
            );
            forAll(mesh.boundaryMesh(), patchi)
            {
                const polyPatch& pp = mesh.boundaryMesh()[patchi];
                if (!isA<wallPolyPatch>(pp))
                {
                    continue;
                }
                scalarField& pf = f.boundaryFieldRef()[patchi];
                const scalarField& magSf = mesh.magSf().boundaryField()[patchi];
                forAll(pp, i)
                {
                    const label b = pp.start() + i - mesh.nInternalFaces();
                    if (perAreaTime)
                    {
                        pf[i] = sum[b]/(magSf[i]*T);
                    }
                    else if (count[b] > 0)
                    {
                        pf[i] = sum[b]/count[b];
                    }
                }
            }
            f.write();
        };
        writeWallField("impactRate", inv(dimArea*dimTime), count, true);
        writeWallField
        (
            "impactVolumeRate", dimVolume/dimArea/dimTime, volume, true
        );
        writeWallField("impactSpeed", dimVelocity, speed, false);
        writeWallField("impactNormalSpeed", dimVelocity, normal, false);
        writeWallField("impactTangentialSpeed", dimVelocity, tangential, false);
        writeWallField("impactAngle", dimless, angle, false);
    }
}


template<class CloudType>
void Foam::ParticlePass<CloudType>::writeTables() const
{
    const fvMesh& mesh = this->owner().mesh();
    const scalar T = span();
    if (!(T > 0))
    {
        return;
    }
    const fileName dir(this->writeTimeDir());
    mkDir(dir);

    OFstream summary(dir/"summary.dat");
    summary
        << "# particlePass over " << T << " s from t = " << startTime_ << nl
        << "# species  d[m]  residenceVolume[m3]  impactsPerSecond[1/s]"
        << "  impactVolumeRate[m3/s]  meanImpactSpeed[m/s]"
        << "  meanNormalSpeed[m/s]  meanTangentialSpeed[m/s]"
        << "  meanImpactAngle[deg]  firstImpacts"
        << "  grazingContactsPerSecond[1/s]" << nl;

    forAll(species_, j)
    {
        const granularSpecies& s = species_[j];
        const scalar Vp = s.particleVolume();

        OFstream impacts(dir/"impacts." + s.name);
        impacts
            << "# Wall impacts of species " << s.name << " (d " << s.d
            << " m) over " << T << " s" << nl
            << "# face: mesh face index; rate: particles per second this"
            << " record stands for (nParticle/T)" << nl
            << "# face  rate[1/s]  Un[m/s]  Ut[m/s]" << nl;
        scalar n = 0, speed = 0, normal = 0, tangential = 0, angle = 0;
        for (const impactRecord& r : impacts_[j])
        {
            impacts
                << r.face << ' ' << r.nParticle/T << ' ' << r.Un << ' '
                << r.Ut << nl;
            n += r.nParticle;
            speed += r.nParticle*r.speed();
            normal += r.nParticle*r.Un;
            tangential += r.nParticle*r.Ut;
            angle += r.nParticle*r.angle();
        }
        const scalar nSafe = max(n, VSMALL);
        summary
            << s.name << ' ' << s.d << ' ' << sum(residence_[j])/T << ' '
            << n/T << ' ' << n*Vp/T << ' ' << speed/nSafe << ' '
            << normal/nSafe << ' ' << tangential/nSafe << ' '
            << angle/nSafe << ' ' << firstImpacts_[j].size();
        scalar grazing = 0;
        OFstream contacts(dir/"grazingContacts." + s.name);
        contacts
            << "# Wall contacts of species " << s.name << " that are not"
            << " impacts (moving along or away from the wall) over " << T
            << " s" << nl
            << "# face  rate[1/s]  Un[m/s] (<= 0)  Ut[m/s]" << nl;
        for (const impactRecord& r : grazing_[j])
        {
            contacts
                << r.face << ' ' << r.nParticle/T << ' ' << r.Un << ' '
                << r.Ut << nl;
            grazing += r.nParticle;
        }
        summary << ' ' << grazing/T << nl;

        OFstream first(dir/"firstImpacts." + s.name);
        first
            << "# First wall impact of every parcel of species " << s.name
            << " (origId: the parcel's number, in injection order)" << nl
            << "# x[m]  y[m]  z[m]  Un[m/s]  Ut[m/s]  nParticle  origId" << nl;
        forAll(firstImpacts_[j], i)
        {
            const vector& x = firstImpactPositions_[j][i];
            const impactRecord& r = firstImpacts_[j][i];
            first
                << x.x() << ' ' << x.y() << ' ' << x.z() << ' ' << r.Un
                << ' ' << r.Ut << ' ' << r.nParticle << ' '
                << firstImpactIds_[j][i] << nl;
        }

        const scalar speedTotal = max(sum(speedHistogram_[j]), VSMALL);
        OFstream speeds(dir/"impactSpeedDistribution." + s.name);
        speeds
            << "# Distribution (particle fraction per bin) of the impact speed,"
            << " its normal and tangential parts, species " << s.name << nl
            << "# low[m/s]  high[m/s]  speed  normal  tangential" << nl;
        const scalar dv = maxSpeed_/speedBins_;
        for (label b = 0; b < speedBins_; ++b)
        {
            speeds
                << b*dv << ' ' << (b + 1)*dv << ' '
                << speedHistogram_[j][b]/speedTotal << ' '
                << normalHistogram_[j][b]/speedTotal << ' '
                << tangentialHistogram_[j][b]/speedTotal << nl;
        }

        const scalar angleTotal = max(sum(angleHistogram_[j]), VSMALL);
        OFstream angles(dir/"impactAngleDistribution." + s.name);
        angles
            << "# Distribution (particle fraction per bin) of the impact angle"
            << " to the wall, species " << s.name << nl
            << "# low[deg]  high[deg]  fraction" << nl;
        const scalar da = 90.0/angleBins_;
        for (label b = 0; b < angleBins_; ++b)
        {
            angles
                << b*da << ' ' << (b + 1)*da << ' '
                << angleHistogram_[j][b]/angleTotal << nl;
        }
    }

    OFstream outflow(dir/"outflow.dat");
    outflow
        << "# Solids volume rate [m3/s] leaving through each non-wall patch,"
        << " per species, over " << T << " s" << nl << "# patch";
    forAll(species_, j)
    {
        outflow << ' ' << species_[j].name;
    }
    outflow << nl;
    forAll(mesh.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        if (isA<wallPolyPatch>(pp) || polyPatch::constraintType(pp.type()))
        {
            continue;
        }
        outflow << pp.name();
        forAll(species_, j)
        {
            scalar out = 0;
            forAll(pp, i)
            {
                out += max(crossed_[j][pp.start() + i], scalar(0));
            }
            outflow << ' ' << out/T;
        }
        outflow << nl;
    }
}


// * * * * * * * * * * * * * * * Protected Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::ParticlePass<CloudType>::write()
{
    writeFields();
    writeTables();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ParticlePass<CloudType>::ParticlePass
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    species_(caseSpecies(owner.mesh())),
    startTime_(this->coeffDict().getOrDefault("startTime", scalar(0))),
    speedBins_(this->coeffDict().getOrDefault("speedBins", label(60))),
    maxSpeed_(this->coeffDict().getOrDefault("maxSpeed", scalar(60))),
    angleBins_(this->coeffDict().getOrDefault("angleBins", label(45)))
{
    if (Pstream::parRun())
    {
        FatalErrorInFunction
            << "particlePass (" << this->coeffDict().name() << ") records"
            << " face crossings in serial only: run the particle pass"
            << " without -parallel (segregationDegradationFoam, which uses"
            << " its results, runs decomposed)" << exit(FatalError);
    }
    if (speedBins_ < 1 || angleBins_ < 1 || !(maxSpeed_ > 0))
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "speedBins " << speedBins_ << ", angleBins " << angleBins_
            << " and maxSpeed " << maxSpeed_ << " in "
            << this->coeffDict().name() << " must be > 0" << exit(FatalIOError);
    }

    const fvMesh& mesh = owner.mesh();
    const label nS = species_.size();
    residence_.setSize(nS, scalarField(mesh.nCells(), Zero));
    momentumResidence_.setSize(nS, vectorField(mesh.nCells(), Zero));
    crossed_.setSize(nS, scalarField(mesh.nFaces(), Zero));
    impacts_.setSize(nS);
    grazing_.setSize(nS);
    firstImpactPositions_.setSize(nS);
    firstImpacts_.setSize(nS);
    firstImpactIds_.setSize(nS);
    speedHistogram_.setSize(nS, scalarField(speedBins_, Zero));
    normalHistogram_.setSize(nS, scalarField(speedBins_, Zero));
    tangentialHistogram_.setSize(nS, scalarField(speedBins_, Zero));
    angleHistogram_.setSize(nS, scalarField(angleBins_, Zero));

    Info<< "    particlePass: species";
    for (const granularSpecies& s : species_)
    {
        Info<< ' ' << s.name << " (d " << s.d << " m)";
    }
    Info<< ", recording from t = " << startTime_ << " s" << endl;
}


template<class CloudType>
Foam::ParticlePass<CloudType>::ParticlePass
(
    const ParticlePass<CloudType>& pp
)
:
    CloudFunctionObject<CloudType>(pp),
    species_(pp.species_),
    startTime_(pp.startTime_),
    speedBins_(pp.speedBins_),
    maxSpeed_(pp.maxSpeed_),
    angleBins_(pp.angleBins_),
    residence_(pp.residence_),
    momentumResidence_(pp.momentumResidence_),
    crossed_(pp.crossed_),
    impacts_(pp.impacts_),
    grazing_(pp.grazing_),
    firstImpactPositions_(pp.firstImpactPositions_),
    firstImpacts_(pp.firstImpacts_),
    firstImpactIds_(pp.firstImpactIds_),
    hitWall_(pp.hitWall_),
    speedHistogram_(pp.speedHistogram_),
    normalHistogram_(pp.normalHistogram_),
    tangentialHistogram_(pp.tangentialHistogram_),
    angleHistogram_(pp.angleHistogram_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParticlePass<CloudType>::postMove
(
    parcelType& p,
    const scalar dt,
    const point&,
    bool&
)
{
    if (!recording() || !(dt > 0))
    {
        return;
    }
    // The sub-step ended on a face or inside the cell: either way it was
    // spent in p.cell() (hitFace, which changes the cell, comes after)
    const label j = speciesOf(p);
    const scalar w = p.nParticle()*p.volume()*dt;
    residence_[j][p.cell()] += w;
    momentumResidence_[j][p.cell()] += w*p.U();
}


template<class CloudType>
void Foam::ParticlePass<CloudType>::postFace
(
    const parcelType& p,
    bool&
)
{
    if (!recording())
    {
        return;
    }
    const fvMesh& mesh = this->owner().mesh();
    const label facei = p.face();
    scalar sign = 1;
    if (mesh.isInternalFace(facei))
    {
        sign = (p.cell() == mesh.faceOwner()[facei]) ? 1 : -1;
    }
    else
    {
        const polyPatch& pp =
            mesh.boundaryMesh()[mesh.boundaryMesh().whichPatch(facei)];
        if (isA<wallPolyPatch>(pp))
        {
            // Not a crossing: the impact is recorded by postPatch
            return;
        }
    }
    const label j = speciesOf(p);
    crossed_[j][facei] += sign*p.nParticle()*p.volume();
}


template<class CloudType>
void Foam::ParticlePass<CloudType>::postPatch
(
    const parcelType& p,
    const polyPatch& pp,
    bool&
)
{
    if (!recording() || !isA<wallPolyPatch>(pp))
    {
        return;
    }

    vector nw, Up;
    this->owner().patchData(p, pp, nw, Up);
    const vector U(p.U() - Up);
    const scalar Un = U & nw;
    const scalar Ut = mag(U - Un*nw);
    const label j = speciesOf(p);
    const impactRecord r{p.face(), p.nParticle(), Un, Ut};
    if (!(Un > 0))
    {
        // Moving away from (or along) the wall: no impact
        grazing_[j].append(r);
        return;
    }
    impacts_[j].append(r);

    if (hitWall_.insert(labelPair(p.origProc(), p.origId())))
    {
        firstImpacts_[j].append(r);
        firstImpactPositions_[j].append(p.position());
        firstImpactIds_[j].append(p.origId());
    }

    const scalar dv = maxSpeed_/speedBins_;
    auto bin = [&](const scalar v)
    {
        return min(label(v/dv), speedBins_ - 1);
    };
    speedHistogram_[j][bin(r.speed())] += p.nParticle();
    normalHistogram_[j][bin(Un)] += p.nParticle();
    tangentialHistogram_[j][bin(Ut)] += p.nParticle();
    angleHistogram_[j][min(label(r.angle()/(90.0/angleBins_)), angleBins_ - 1)] +=
        p.nParticle();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "segregationFlux.H"
#include "scratchField.H"
#include "fvc.H"
#include "surfaceInterpolate.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::segregationFlux::segregationFlux
(
    const granularMixture& mixture,
    const UPtrList<pairwiseDrift>& models
)
:
    mixture_(mixture)
{
    label nActive = 0;
    forAll(models, modeli)
    {
        if (models.set(modeli) && models[modeli].active())
        {
            ++nActive;
        }
    }
    models_.setSize(nActive);
    nActive = 0;
    forAll(models, modeli)
    {
        if (models.set(modeli) && models[modeli].active())
        {
            models_.set(nActive++, const_cast<pairwiseDrift*>(&models[modeli]));
        }
    }

    if (models_.empty())
    {
        return;
    }

    DynamicList<Tuple2<label, label>> pairs;
    for (label i = 0; i < mixture.size(); ++i)
    {
        for (label j = 0; j < mixture.size(); ++j)
        {
            if (mixture.d(i) < mixture.d(j))
            {
                pairs.append(Tuple2<label, label>(i, j));
            }
        }
    }
    pairs_.transfer(pairs);

    const fvMesh& mesh = mixture.mesh();
    drift_.setSize(pairs_.size());
    forAll(pairs_, pairi)
    {
        drift_.set
        (
            pairi,
            new surfaceScalarField
            (
                IOobject
                (
                    "drift." + mixture.names()[pairs_[pairi].first()]
                  + "." + mixture.names()[pairs_[pairi].second()],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh,
                dimensionedScalar("s", dimVolume/dimTime, Zero)
            )
        );
    }

    speciesFlux_.setSize(mixture.size());
    forAll(speciesFlux_, k)
    {
        speciesFlux_.set
        (
            k,
            new surfaceScalarField
            (
                IOobject
                (
                    "segregationFlux." + mixture.names()[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh,
                dimensionedScalar("s", dimVolume/dimTime, Zero)
            )
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::segregationFlux::correctDrift()
{
    if (!active())
    {
        return;
    }

    forAll(models_, modeli)
    {
        models_[modeli].correct();
    }

    forAll(pairs_, pairi)
    {
        surfaceScalarField& W = drift_[pairi];
        W == dimensionedScalar("s", dimVolume/dimTime, Zero);
        forAll(models_, modeli)
        {
            W += models_[modeli].driftFlux
            (
                pairs_[pairi].first(),
                pairs_[pairi].second()
            );
        }
        pairwiseDrift::zeroUncoupledPatches(W);
    }
}


Foam::scalar Foam::segregationFlux::courantNumber(const scalar deltaT) const
{
    if (!active())
    {
        return 0;
    }

    const fvMesh& mesh = mixture_.mesh();
    scalarField sumW(mesh.nCells(), Zero);
    forAll(drift_, pairi)
    {
        sumW += fvc::surfaceSum(mag(drift_[pairi]))().primitiveField();
    }
    return 0.5*gMax(sumW/mesh.V().field())*deltaT;
}


void Foam::segregationFlux::correctFluxes(const scalar deltaT)
{
    if (!active())
    {
        return;
    }

    const fvMesh& mesh = mixture_.mesh();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const PtrList<volScalarField>& n = mixture_.n();

    // 1. Unlimited pair fluxes F = W n_i|from c_j|to
    PtrList<surfaceScalarField> F(pairs_.size());
    PtrList<volScalarField> c(mixture_.size());
    forAll(c, k)
    {
        c.set(k, mixture_.c(k).ptr());
    }

    forAll(pairs_, pairi)
    {
        const label i = pairs_[pairi].first();
        const label j = pairs_[pairi].second();
        const surfaceScalarField& W = drift_[pairi];

        F.set
        (
            pairi,
            new surfaceScalarField
            (
                "F",
                W
               *fvc::interpolate(n[i], W, "reconstruct(n)")
               *fvc::interpolate(c[j], -W, "reconstruct(n)")
            )
        );
        pairwiseDrift::zeroUncoupledPatches(F[pairi]);
    }

    // 2. Volume of each species leaving each cell in deltaT
    PtrList<volScalarField> lambda(mixture_.size());
    forAll(lambda, k)
    {
        lambda.set(k, scratchField(mesh, "lambda", dimless));
    }

    // Outflow per species: fine i leaves the cell on the -F side... i.e.
    // the owner when F > 0; coarse j leaves the other cell
    PtrList<scalarField> outflow(mixture_.size());
    forAll(outflow, k)
    {
        outflow.set(k, new scalarField(mesh.nCells(), Zero));
    }

    forAll(pairs_, pairi)
    {
        const label i = pairs_[pairi].first();
        const label j = pairs_[pairi].second();
        const scalarField& Fi = F[pairi].primitiveField();

        forAll(Fi, facei)
        {
            const scalar vol = mag(Fi[facei])*deltaT;
            if (Fi[facei] > 0)
            {
                outflow[i][own[facei]] += vol;
                outflow[j][nei[facei]] += vol;
            }
            else
            {
                outflow[i][nei[facei]] += vol;
                outflow[j][own[facei]] += vol;
            }
        }

        forAll(F[pairi].boundaryField(), patchi)
        {
            const fvsPatchScalarField& Fp = F[pairi].boundaryField()[patchi];
            if (!Fp.coupled())
            {
                continue;
            }
            const labelUList& faceCells = mesh.boundary()[patchi].faceCells();
            forAll(Fp, facei)
            {
                const scalar vol = mag(Fp[facei])*deltaT;
                // F > 0: fine leaves the local cell, coarse enters it
                if (Fp[facei] > 0)
                {
                    outflow[i][faceCells[facei]] += vol;
                }
                else
                {
                    outflow[j][faceCells[facei]] += vol;
                }
            }
        }
    }

    // 3. Limiter: lambda_k = min(1, content/outflow)
    const scalarField& V = mesh.V();
    forAll(lambda, k)
    {
        scalarField& lk = lambda[k].primitiveFieldRef();
        const scalarField& nk = n[k].primitiveField();
        forAll(lk, celli)
        {
            const scalar content = max(nk[celli], scalar(0))*V[celli];
            lk[celli] =
                outflow[k][celli] > content
              ? content/outflow[k][celli]
              : 1.0;
        }
        lambda[k].correctBoundaryConditions();
    }

    // 4. Limited species fluxes
    forAll(speciesFlux_, k)
    {
        speciesFlux_[k] == dimensionedScalar("s", dimVolume/dimTime, Zero);
    }

    forAll(pairs_, pairi)
    {
        const label i = pairs_[pairi].first();
        const label j = pairs_[pairi].second();
        surfaceScalarField& Fpair = F[pairi];

        scalarField& Fi = Fpair.primitiveFieldRef();
        const scalarField& li = lambda[i].primitiveField();
        const scalarField& lj = lambda[j].primitiveField();
        forAll(Fi, facei)
        {
            const label fromFine = Fi[facei] > 0 ? own[facei] : nei[facei];
            const label fromCoarse = Fi[facei] > 0 ? nei[facei] : own[facei];
            Fi[facei] *= min(li[fromFine], lj[fromCoarse]);
        }

        forAll(Fpair.boundaryField(), patchi)
        {
            fvsPatchScalarField& Fp = Fpair.boundaryFieldRef()[patchi];
            if (!Fp.coupled())
            {
                continue;
            }
            const scalarField liLocal
            (
                lambda[i].boundaryField()[patchi].patchInternalField()
            );
            const scalarField ljLocal
            (
                lambda[j].boundaryField()[patchi].patchInternalField()
            );
            const scalarField liRemote
            (
                lambda[i].boundaryField()[patchi].patchNeighbourField()
            );
            const scalarField ljRemote
            (
                lambda[j].boundaryField()[patchi].patchNeighbourField()
            );
            forAll(Fp, facei)
            {
                Fp[facei] *=
                    Fp[facei] > 0
                  ? min(liLocal[facei], ljRemote[facei])
                  : min(liRemote[facei], ljLocal[facei]);
            }
        }

        speciesFlux_[i] += Fpair;
        speciesFlux_[j] -= Fpair;
    }
}


// ************************************************************************* //

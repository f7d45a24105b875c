/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "diffusivityModel.H"
#include "modelCoeffs.H"
#include "zeroGradientFvPatchFields.H"
#include "wallFvPatch.H"

namespace Foam
{
    defineTypeNameAndDebug(diffusivityModel, 0);
    defineRunTimeSelectionTable(diffusivityModel, dictionary);
}


Foam::diffusivityModel::diffusivityModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type))
{}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModel::D
(
    const label i,
    const volScalarField& T
) const
{
    tmp<volScalarField> tD(Dlaw(i, T)*mixture_.presence());
    tD.ref().rename("D." + mixture_.names()[i]);
    return tD;
}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModel::Dmixture
(
    const volScalarField& T
) const
{
    const label N = mixture_.size();

    if (N == 1)
    {
        return D(0, T);
    }

    tmp<volScalarField> tDmix
    (
        volScalarField::New
        (
            "D",
            mixture_.mesh(),
            dimensionedScalar("s", dimArea/dimTime, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    volScalarField& Dmix = tDmix.ref();

    // sum_i (1 - c_i) D_i/(N - 1) with c_i as granularMixture::c and D_i
    // as D(i, T), in one pass over the cells per species: the same
    // arithmetic without a dozen field temporaries per species (the
    // largest per-species cost outside the linear solve)
    const volScalarField presence(mixture_.presence());
    const scalarField& nTotal = mixture_.nTotal().primitiveField();
    scalarField& Dcells = Dmix.primitiveFieldRef();
    for (label i = 0; i < N; ++i)
    {
        const tmp<volScalarField> tDlaw(Dlaw(i, T));
        const scalarField& Dlaw = tDlaw().primitiveField();
        const scalarField& n = mixture_.n()[i].primitiveField();
        forAll(Dcells, celli)
        {
            const scalar c =
                nTotal[celli] - SMALL > 0
              ? min(max(n[celli]/max(nTotal[celli], SMALL), scalar(0)), scalar(1))
              : scalar(0);
            Dcells[celli] +=
                (1 - c)*(Dlaw[celli]*presence[celli])/scalar(N - 1);
        }
    }

    // Empty cells: c_i = 0 gives sum_i D_i/(N-1), already 0 by presence
    Dmix.correctBoundaryConditions();
    return tDmix;
}


// ************************************************************************* //


Foam::tmp<Foam::surfaceScalarField>
Foam::diffusivityModel::faceDiffusivity(const volScalarField& D)
{
    const fvMesh& mesh = D.mesh();

    auto harmonicMean = [](const scalar a, const scalar b)
    {
        const scalar sum = a + b;
        return sum > VSMALL ? 2*a*b/sum : scalar(0);
    };

    tmp<surfaceScalarField> tDf
    (
        surfaceScalarField::New
        (
            "Df",
            mesh,
            dimensionedScalar("Df", D.dimensions(), Zero)
        )
    );
    surfaceScalarField& Df = tDf.ref();

    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    scalarField& Dfi = Df.primitiveFieldRef();
    forAll(Dfi, facei)
    {
        Dfi[facei] = harmonicMean(D[own[facei]], D[nei[facei]]);
    }

    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& p = mesh.boundary()[patchi];
        fvsPatchScalarField& Dfp = Df.boundaryFieldRef()[patchi];
        const fvPatchScalarField& Dp = D.boundaryField()[patchi];

        if (Dp.coupled())
        {
            const scalarField Dlocal(Dp.patchInternalField());
            const scalarField Dremote(Dp.patchNeighbourField());
            forAll(Dfp, facei)
            {
                Dfp[facei] = harmonicMean(Dlocal[facei], Dremote[facei]);
            }
        }
        // Other patches keep Dfp = 0: only the bulk flow carries material
        // across a boundary, diffusion never does (walls, inlets, outlets,
        // the open top of a silo)
    }

    return tDf;
}


// ************************************************************************* //

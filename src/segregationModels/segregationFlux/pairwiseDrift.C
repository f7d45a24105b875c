/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "pairwiseDrift.H"
#include "granularMixture.H"

Foam::scalar Foam::pairwiseDrift::pairScale
(
    const granularMixture& mixture,
    const label finei,
    const label coarsej
)
{
    const scalar range = log(mixture.dMax()/mixture.dMin());
    if (range <= 0)
    {
        return 0;
    }
    return max(log(mixture.d(coarsej)/mixture.d(finei)), scalar(0))/range;
}


void Foam::pairwiseDrift::zeroUncoupledPatches(surfaceScalarField& W)
{
    forAll(W.boundaryField(), patchi)
    {
        if (!W.boundaryField()[patchi].coupled())
        {
            W.boundaryFieldRef()[patchi] = Zero;
        }
    }
}


Foam::tmp<Foam::surfaceScalarField> Foam::pairwiseDrift::gravityFaceAreas
(
    const granularMixture& mixture
)
{
    const fvMesh& mesh = mixture.mesh();
    const vector gHat(mixture.gravity()/mag(mixture.gravity()));
    tmp<surfaceScalarField> tgSf
    (
        surfaceScalarField::New
        (
            "gSf",
            mesh.Sf() & dimensionedVector("gHat", dimless, gHat)
        )
    );
    zeroUncoupledPatches(tgSf.ref());
    return tgSf;
}


// ************************************************************************* //

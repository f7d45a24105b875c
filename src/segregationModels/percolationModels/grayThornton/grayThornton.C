/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "grayThornton.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace percolationModels
{
    defineTypeNameAndDebug(grayThornton, 0);
    addToRunTimeSelectionTable(percolationModel, grayThornton, dictionary);
}
}


Foam::percolationModels::grayThornton::grayThornton
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel&
)
:
    percolationModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"Sr"}),
        mixture
    ),
    Sr_(modelCoeffs::get(coeffs_, "Sr", dimVelocity).value()),
    gSf_(gravityFaceAreas(mixture))
{
    if (!(Sr_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Percolation velocity 'Sr " << Sr_ << "' must be >= 0 [m/s]"
            << nl << exit(FatalIOError);
    }
}


Foam::tmp<Foam::surfaceScalarField>
Foam::percolationModels::grayThornton::driftFlux
(
    const label finei,
    const label coarsej
) const
{
    const scalar pairSr = Sr_*pairScale(mixture_, finei, coarsej);
    return dimensionedScalar("W", dimVelocity, pairSr)*gSf_;
}


// ************************************************************************* //

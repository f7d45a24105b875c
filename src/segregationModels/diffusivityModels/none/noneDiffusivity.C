/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "noneDiffusivity.H"
#include "addToRunTimeSelectionTable.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(diffusivityModel, none, dictionary);
}
}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModels::none::Dlaw
(
    const label,
    const volScalarField&
) const
{
    return volScalarField::New
    (
        "Dlaw",
        mixture_.mesh(),
        dimensionedScalar("s", dimArea/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "constantDiffusivity.H"
#include "addToRunTimeSelectionTable.H"
#include "zeroGradientFvPatchFields.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(constantDiffusivity, 0);
    addToRunTimeSelectionTable(diffusivityModel, constantDiffusivity, dictionary);
}
}


Foam::diffusivityModels::constantDiffusivity::constantDiffusivity
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    diffusivityModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"D"}),
        mixture
    ),
    D0_(modelCoeffs::get(coeffs_, "D", dimArea/dimTime).value())
{
    if (!(D0_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Diffusivity 'D " << D0_ << "' must be >= 0 [m2/s]" << nl
            << exit(FatalIOError);
    }
}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModels::constantDiffusivity::Dlaw
(
    const label i,
    const volScalarField& T
) const
{
    return volScalarField::New
    (
        "Dlaw",
        mixture_.mesh(),
        dimensionedScalar("s", dimArea/dimTime, D0_),
        zeroGradientFvPatchScalarField::typeName
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "granularTemperatureModel.H"
#include "modelCoeffs.H"
#include "zeroGradientFvPatchFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(granularTemperatureModel, 0);
    defineRunTimeSelectionTable(granularTemperatureModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularTemperatureModel::granularTemperatureModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type)),
    T_
    (
        IOobject
        (
            "T",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            mixture.writeField("T") ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimVelocity*dimVelocity, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    gammaDot_
    (
        IOobject
        (
            "gammaDot",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            mixture.writeField("gammaDot")
          ? IOobject::AUTO_WRITE
          : IOobject::NO_WRITE
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimless/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    )
{}


// ************************************************************************* //

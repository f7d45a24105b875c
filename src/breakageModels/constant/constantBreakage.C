/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "constantBreakage.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(constant, 0);
    addToRunTimeSelectionTable(breakageModel, constant, dictionary);
}
}


Foam::breakageModels::constant::constant
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    breakageModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"S"}),
        mixture
    ),
    S0_(mixture.size(), Zero)
{
    const dictionary& rates = coeffs_.subDict("S");
    modelCoeffs::checkKeys(rates, mixture.names());
    forAll(S0_, j)
    {
        S0_[j] = modelCoeffs::getOrDefault
        (
            rates,
            mixture.names()[j],
            inv(dimTime),
            0
        ).value();
        checkNonNegative("S." + mixture.names()[j], S0_[j]);
    }
}


void Foam::breakageModels::constant::calcS
(
    const label j,
    const granularTemperatureModel&,
    volScalarField& S
) const
{
    S == dimensionedScalar("S", inv(dimTime), S0_[j]);
}


// ************************************************************************* //

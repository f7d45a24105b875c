/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibratedDiffusivity.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(calibrated, 0);
    addToRunTimeSelectionTable(diffusivityModel, calibrated, dictionary);
}
}


Foam::diffusivityModels::calibrated::calibrated
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    diffusivityModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, calibratedLaw::coeffsKeys()),
        mixture
    ),
    law_(mixture, "D", coeffs_)
{}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModels::calibrated::Dlaw
(
    const label i,
    const volScalarField& T
) const
{
    return law_.evaluate(mixture_, T, mixture_.d(i), dimArea/dimTime);
}


// ************************************************************************* //

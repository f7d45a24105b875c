/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "shearRateDiffusivity.H"
#include "bulkFlowModel.H"
#include "addToRunTimeSelectionTable.H"
#include "zeroGradientFvPatchFields.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(shearRateDiffusivity, 0);
    addToRunTimeSelectionTable(diffusivityModel, shearRateDiffusivity, dictionary);
}
}


Foam::diffusivityModels::shearRateDiffusivity::shearRateDiffusivity
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    diffusivityModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"C"}),
        mixture
    ),
    C_(modelCoeffs::get(coeffs_, "C", dimless).value()),
    gammaDot_
    (
        IOobject
        (
            "shearRateDiffusivity:gammaDot",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimless/dimTime, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    corrected_(false)
{
    if (!(C_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Diffusivity prefactor 'C " << C_ << "' must be >= 0"
            << " (0.042: Fan et al. 2014)" << nl << exit(FatalIOError);
    }
}


void Foam::diffusivityModels::shearRateDiffusivity::correct
(
    const bulkFlowModel& bulkFlow
)
{
    gammaDot_ = bulkFlow.gammaDot();
    corrected_ = true;
}


Foam::tmp<Foam::volScalarField>
Foam::diffusivityModels::shearRateDiffusivity::Dlaw
(
    const label i,
    const volScalarField& T
) const
{
    if (!corrected_)
    {
        FatalErrorInFunction
            << "diffusivity shearRate: Dlaw called before correct(bulkFlow)"
            << " gave it the shear rate" << exit(FatalError);
    }
    tmp<volScalarField> tD
    (
        volScalarField::New
        (
            "Dlaw",
            mixture_.mesh(),
            dimensionedScalar("s", dimArea/dimTime, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    tD.ref() = C_*gammaDot_*sqr(mixture_.dMean());
    tD.ref().correctBoundaryConditions();
    return tD;
}


// ************************************************************************* //

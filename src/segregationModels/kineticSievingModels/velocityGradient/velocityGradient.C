/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "velocityGradient.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"
#include "fvcSnGrad.H"

namespace Foam
{
namespace kineticSievingModels
{
    defineTypeNameAndDebug(velocityGradient, 0);
    addToRunTimeSelectionTable
    (
        kineticSievingModel,
        velocityGradient,
        dictionary
    );
}
}


Foam::kineticSievingModels::velocityGradient::velocityGradient
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
:
    kineticSievingModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"eta", "Umin"}),
        mixture
    ),
    bulkFlow_(bulkFlow),
    eta_(modelCoeffs::get(coeffs_, "eta", dimArea/dimTime).value()),
    // Optional, default 1e-6 m/s: the speed below which ln|U| is cut off
    Umin_(modelCoeffs::getOrDefault(coeffs_, "Umin", dimVelocity, 1e-6).value()),
    gradLnUSf_
    (
        IOobject
        (
            "gradLnUSf",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimLength, Zero)
    )
{
    if (!(eta_ >= 0) || !(Umin_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "kinetic sieving: 'eta " << eta_ << "' must be >= 0 [m2/s] and"
            << " 'Umin " << Umin_ << "' > 0 [m/s]" << nl
            << exit(FatalIOError);
    }
    correct();
}


void Foam::kineticSievingModels::velocityGradient::correct()
{
    gradLnUSf_ = gradLnUSf(bulkFlow_, Umin_);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::kineticSievingModels::velocityGradient::driftFlux
(
    const label finei,
    const label coarsej
) const
{
    // The coarse moves up the gradient, so the fine drifts down it
    const scalar pairEta = eta_*pairScale(mixture_, finei, coarsej);
    return dimensionedScalar("W", dimArea/dimTime, -pairEta)*gradLnUSf_;
}


// ************************************************************************* //

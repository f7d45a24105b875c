/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "shearRatePercolation.H"
#include "addToRunTimeSelectionTable.H"
#include "surfaceInterpolate.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace percolationModels
{
    defineTypeNameAndDebug(shearRatePercolation, 0);
    addToRunTimeSelectionTable
    (
        percolationModel,
        shearRatePercolation,
        dictionary
    );
}
}


Foam::percolationModels::shearRatePercolation::shearRatePercolation
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
:
    percolationModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"C_s"}),
        mixture
    ),
    Cs_(modelCoeffs::get(coeffs_, "C_s", dimless).value()),
    bulkFlow_(bulkFlow),
    gSf_(gravityFaceAreas(mixture)),
    gammaDotf_
    (
        IOobject
        (
            "shearRatePercolation:gammaDotf",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimless/dimTime, Zero)
    )
{
    if (!(Cs_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Segregation prefactor 'C_s " << Cs_ << "' must be >= 0"
            << " (0.26: Schlick et al. 2015)" << nl << exit(FatalIOError);
    }
}


void Foam::percolationModels::shearRatePercolation::correct()
{
    gammaDotf_ = fvc::interpolate(bulkFlow_.gammaDot());
}


Foam::tmp<Foam::surfaceScalarField>
Foam::percolationModels::shearRatePercolation::driftFlux
(
    const label finei,
    const label coarsej
) const
{
    const scalar S =
        Cs_*mixture_.d(finei)*Foam::log(mixture_.d(coarsej)/mixture_.d(finei));
    return dimensionedScalar("S", dimLength, S)*gammaDotf_*gSf_;
}


// ************************************************************************* //

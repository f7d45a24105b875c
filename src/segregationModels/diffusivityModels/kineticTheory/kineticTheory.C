/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "kineticTheory.H"
#include "addToRunTimeSelectionTable.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(kineticTheory, 0);
    addToRunTimeSelectionTable(diffusivityModel, kineticTheory, dictionary);
}
}


Foam::diffusivityModels::kineticTheory::kineticTheory
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    diffusivityModel(typeName, dict, mixture),
    e_(coeffs_.get<scalar>("e")),
    phiMax_(coeffs_.getOrDefault<scalar>("phiMax", 0.63))
{
    if (!(e_ > 0 && e_ <= 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Restitution coefficient 'e " << e_ << "' must lie in (0, 1]"
            << nl << exit(FatalIOError);
    }
    if (!(phiMax_ > 0 && phiMax_ < 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'phiMax " << phiMax_ << "' must lie in (0, 1)"
            << nl << exit(FatalIOError);
    }
}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModels::kineticTheory::Dlaw
(
    const label i,
    const volScalarField& T
) const
{
    const volScalarField phi
    (
        min(mixture_.phiRegularised(), dimensionedScalar("s", dimless, phiMax_))
    );
    const volScalarField g0((1 - 0.5*phi)/pow3(1 - phi));
    const volScalarField T1(max(T, dimensionedScalar("s", T.dimensions(), Zero))/3);

    return
        dimensionedScalar("s", dimLength, mixture_.d(i))
       *sqrt(constant::mathematical::pi*T1)
       /(8*(1 + e_)*phi*g0);
}


// ************************************************************************* //

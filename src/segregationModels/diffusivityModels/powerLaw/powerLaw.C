/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "powerLaw.H"
#include "addToRunTimeSelectionTable.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace diffusivityModels
{
    defineTypeNameAndDebug(powerLaw, 0);
    addToRunTimeSelectionTable(diffusivityModel, powerLaw, dictionary);
}
}


Foam::diffusivityModels::powerLaw::powerLaw
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    diffusivityModel(typeName, dict, mixture),
    A_(coeffs_.getOrDefault<scalar>("A", 6)),
    a_(coeffs_.getOrDefault<scalar>("a", 1)),
    m_(coeffs_.getOrDefault<scalar>("m", 1)),
    b_(coeffs_.getOrDefault<scalar>("b", -1.5))
{
    if (!(A_ >= 0) || !(m_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "powerLaw coefficients: A " << A_ << " and m " << m_
            << " must be >= 0 (m < 0 diverges where T = 0)" << nl
            << exit(FatalIOError);
    }
    Info<< "    D = " << A_ << " (1 + x)^" << a_ << " T^" << m_
        << " phi^" << b_ << nl;
}


Foam::tmp<Foam::volScalarField> Foam::diffusivityModels::powerLaw::Dlaw
(
    const label i,
    const volScalarField& T
) const
{
    const volScalarField x(mixture_.coarseFraction());
    const volScalarField phi(mixture_.phiRegularised());
    const volScalarField Tvalue(max(T, dimensionedScalar("s", T.dimensions(), Zero))/dimensionedScalar("s", T.dimensions(), 1));

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
    tD.ref().primitiveFieldRef() =
        A_*pow(1 + x.primitiveField(), a_)*pow(Tvalue.primitiveField(), m_)
       *pow(phi.primitiveField(), b_);
    tD.ref().correctBoundaryConditions();
    return tD;
}


// ************************************************************************* //

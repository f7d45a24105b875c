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
#include "LawFormulas.hpp"
#include "modelCoeffs.H"

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
    diffusivityModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"A", "a", "m", "b"}),
        mixture
    ),
    A_(0),
    // Optional, defaults the seed's eq 15: a 1, m 1, b -1.5 (exponents)
    a_(coeffs_.getOrDefault<scalar>("a", 1)),
    m_(coeffs_.getOrDefault<scalar>("m", 1)),
    b_(coeffs_.getOrDefault<scalar>("b", -1.5))
{
    // A carries the units of the law, [m2/s]/[m2/s2]^m: seconds for the
    // seed's m = 1. Optional, default the seed's 6 (in those units)
    A_ = modelCoeffs::getOrDefault
    (
        coeffs_,
        "A",
        dimArea/dimTime/pow(sqr(dimVelocity), m_),
        6
    ).value();

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
    scalarField& D = tD.ref().primitiveFieldRef();
    forAll(D, celli)
    {
        D[celli] = sdf::fit::formulas::powerLaw
        (
            A_, a_, m_, b_, phi[celli], x[celli], Tvalue[celli]
        );
    }
    tD.ref().correctBoundaryConditions();
    return tD;
}


// ************************************************************************* //

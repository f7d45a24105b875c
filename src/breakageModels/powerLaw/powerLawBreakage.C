/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "powerLawBreakage.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(powerLaw, 0);
    addToRunTimeSelectionTable(breakageModel, powerLaw, dictionary);
}
}


Foam::breakageModels::powerLaw::powerLaw
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    breakageModel
    (
        typeName,
        modelCoeffs::checked
        (
            dict,
            typeName,
            {"k", "dRef", "a", "variable", "XRef", "b"}
        ),
        mixture
    ),
    k_(modelCoeffs::get(coeffs_, "k", inv(dimTime)).value()),
    dRef_(modelCoeffs::get(coeffs_, "dRef", dimLength).value()),
    a_(coeffs_.getOrDefault<scalar>("a", 0)),
    variable_(coeffs_.getOrDefault<word>("variable", "none")),
    XRef_(1),
    b_(coeffs_.getOrDefault<scalar>("b", 1))
{
    checkNonNegative("k", k_);
    if (!(dRef_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Breakage coefficient 'dRef " << dRef_ << "' in "
            << coeffs_.name() << " must be > 0 [m]" << nl
            << exit(FatalIOError);
    }

    if (variable_ == "gammaDot")
    {
        XRef_ = modelCoeffs::get(coeffs_, "XRef", inv(dimTime)).value();
    }
    else if (variable_ == "T")
    {
        XRef_ = modelCoeffs::get(coeffs_, "XRef", sqr(dimVelocity)).value();
    }
    else if (variable_ != "none")
    {
        FatalIOErrorInFunction(coeffs_)
            << "Unknown 'variable " << variable_ << "' in " << coeffs_.name()
            << nl << "    valid: none gammaDot T" << nl
            << exit(FatalIOError);
    }
    if (variable_ != "none" && !(XRef_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Breakage coefficient 'XRef " << XRef_ << "' in "
            << coeffs_.name() << " must be > 0" << nl
            << exit(FatalIOError);
    }
    if (variable_ != "none" && !(b_ >= 0))
    {
        // X = 0 (a stagnant zone) with b < 0 would give an infinite rate
        FatalIOErrorInFunction(coeffs_)
            << "Breakage exponent 'b " << b_ << "' in " << coeffs_.name()
            << " must be >= 0" << nl << exit(FatalIOError);
    }

    Info<< "    S = " << k_ << " (d/" << dRef_ << ")^" << a_;
    if (variable_ != "none")
    {
        Info<< " (" << variable_ << "/" << XRef_ << ")^" << b_;
    }
    Info<< nl;
}


void Foam::breakageModels::powerLaw::calcS
(
    const label j,
    const granularTemperatureModel& granularTemperature,
    volScalarField& S
) const
{
    const scalar Sd = k_*pow(mixture_.d(j)/dRef_, a_);

    if (variable_ == "none")
    {
        S == dimensionedScalar("S", inv(dimTime), Sd);
        return;
    }

    const volScalarField& X =
    (
        variable_ == "T"
      ? granularTemperature.T()
      : granularTemperature.gammaDot()
    );
    scalarField& Sc = S.primitiveFieldRef();
    const scalarField& Xc = X.primitiveField();
    forAll(Sc, celli)
    {
        Sc[celli] = Sd*pow(max(Xc[celli], scalar(0))/XRef_, b_);
    }
}


// ************************************************************************* //

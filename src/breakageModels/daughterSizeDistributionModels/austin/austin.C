/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "austin.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

#include <cmath>
#include <limits>

namespace Foam
{
namespace daughterSizeDistributionModels
{
    defineTypeNameAndDebug(austin, 0);
    addToRunTimeSelectionTable(daughterSizeDistributionModel, austin, dictionary);
}
}


Foam::daughterSizeDistributionModels::austin::austin
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    daughterSizeDistributionModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"phi", "gamma", "beta"}),
        mixture
    ),
    phi_(coeffs_.get<scalar>("phi")),
    gamma_(coeffs_.get<scalar>("gamma")),
    beta_(coeffs_.get<scalar>("beta"))
{
    if (!(phi_ >= 0 && phi_ <= 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'phi " << phi_ << "' in " << coeffs_.name()
            << " must lie in [0, 1]" << nl << exit(FatalIOError);
    }
    if (!(gamma_ > 0) || !(beta_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'gamma " << gamma_ << "' and 'beta " << beta_ << "' in "
            << coeffs_.name() << " must be > 0 (B(x, y) must vanish as"
            << " x -> 0)" << nl << exit(FatalIOError);
    }
}


Foam::scalar Foam::daughterSizeDistributionModels::austin::termNumber
(
    const scalar c,
    const scalar p,
    const scalar a,
    const scalar b,
    const scalar u
)
{
    if (c == 0 || b <= a)
    {
        return 0;
    }
    if (a <= 0 && p <= 1)
    {
        return std::numeric_limits<scalar>::infinity();
    }
    if (a <= 0)
    {
        // p > 1 here (p <= 1 returned above):
        // int_0^b v^(p-2) dv = b^(p-1)/(p - 1)
        return c*p*Foam::pow(u, 1 - p)*Foam::pow(b, p - 1)/(p - 1);
    }
    // (b^(p-1) - a^(p-1))/(p - 1) = a^(p-1) expm1((p - 1) ln(b/a))/(p - 1),
    // without the cancellation of the difference near p = 1 (ln(b/a) at 1)
    const scalar lnRatio = Foam::log(b/a);
    const scalar q = p - 1;
    const scalar integral =
        mag(q*lnRatio) < 1e-12
      ? lnRatio*(1 + 0.5*q*lnRatio)
      : std::expm1(q*lnRatio)/q;
    return c*p*Foam::pow(a/u, q)*integral;
}


Foam::scalar Foam::daughterSizeDistributionModels::austin::volumeFraction
(
    const scalar a,
    const scalar b,
    const scalar u
) const
{
    const scalar pg = gamma_/3;
    const scalar pb = beta_/3;
    return
        phi_*(Foam::pow(b/u, pg) - Foam::pow(a/u, pg))
      + (1 - phi_)*(Foam::pow(b/u, pb) - Foam::pow(a/u, pb));
}


Foam::scalar Foam::daughterSizeDistributionModels::austin::number
(
    const scalar a,
    const scalar b,
    const scalar u
) const
{
    return
        termNumber(phi_, gamma_/3, a, b, u)
      + termNumber(1 - phi_, beta_/3, a, b, u);
}


// ************************************************************************* //

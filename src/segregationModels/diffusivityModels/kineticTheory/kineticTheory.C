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
#include "LawFormulas.hpp"
#include "modelCoeffs.H"

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
    diffusivityModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"e", "phiMax"}),
        mixture
    ),
    e_(coeffs_.get<scalar>("e")),
    // Optional, default 0.63 (random close packing): the solids fraction
    // at which g0 is capped
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
    const volScalarField Tpos(max(T, dimensionedScalar("s", T.dimensions(), Zero)));

    // Savage & Dai: the kinetic-theory law of calibration/fit,
    // C d sqrt(T/3)/(phi g0), with C = sqrt(pi)/(8 (1 + e)) and alpha = 0
    const scalar C = Foam::sqrt(constant::mathematical::pi)/(8*(1 + e_));
    const scalar d = mixture_.d(i);
    tmp<volScalarField> tD(phi*dimensionedScalar("s", dimArea/dimTime, Zero));
    auto law = [&](scalarField& D, const scalarField& p, const scalarField& t)
    {
        forAll(D, facei)
        {
            D[facei] = sdf::fit::formulas::kineticTheoryGroups
            (
                C, 0, p[facei], 0, t[facei], d
            );
        }
    };
    law(tD.ref().primitiveFieldRef(), phi, Tpos);
    forAll(phi.boundaryField(), patchi)
    {
        law
        (
            tD.ref().boundaryFieldRef()[patchi],
            phi.boundaryField()[patchi],
            Tpos.boundaryField()[patchi]
        );
    }
    return tD;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "speciesAdvection.H"
#include "fvm.H"
#include "gaussConvectionScheme.H"
#include "limitedSurfaceInterpolationScheme.H"

namespace Foam
{
    defineTypeNameAndDebug(sharedWeights, 0);
}

const Foam::word Foam::speciesAdvection::schemeName_("div(phi,n)");


Foam::speciesAdvection::speciesAdvection(const granularMixture& mixture)
:
    mixture_(mixture)
{}


void Foam::speciesAdvection::correct(const surfaceScalarField& phi)
{
    weights_.clear();

    const fvMesh& mesh = mixture_.mesh();
    tmp<fv::convectionScheme<scalar>> tscheme
    (
        fv::convectionScheme<scalar>::New
        (
            mesh,
            phi,
            mesh.divScheme(schemeName_)
        )
    );

    const auto* gauss =
        dynamic_cast<const fv::gaussConvectionScheme<scalar>*>(&tscheme());
    if (!gauss)
    {
        return;
    }
    const auto* limited =
        dynamic_cast<const limitedSurfaceInterpolationScheme<scalar>*>
        (
            &gauss->interpScheme()
        );
    if (!limited || mixture_.size() < 2)
    {
        return;
    }

    const PtrList<volScalarField>& n = mixture_.n();
    tmp<surfaceScalarField> tlimiter(limited->limiter(n[0]));
    for (label k = 1; k < n.size(); ++k)
    {
        tlimiter.ref() = min(tlimiter(), limited->limiter(n[k]));
    }

    // Cap at 1 (between central and upwind weights): a TVD limiter may
    // reach 2, i.e. downwind weights, which are TVD for the field they were
    // computed from but anti-diffusive, and with implicit Euler unstable,
    // for the total solids fraction that all species share. Limiters that
    // are 1 at r = 1 (vanLeer, limitedLinear, ...) stay second order.
    tlimiter.ref() = min(tlimiter(), scalar(1));

    weights_.reset
    (
        new surfaceScalarField
        (
            "speciesAdvectionWeights",
            limited->weights(n[0], mesh.surfaceInterpolation::weights(), tlimiter)
        )
    );
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::fvmDiv
(
    const surfaceScalarField& phi,
    const volScalarField& n
) const
{
    if (!weights_.valid())
    {
        return fvm::div(phi, n, schemeName_);
    }

    const fvMesh& mesh = mixture_.mesh();
    return fv::gaussConvectionScheme<scalar>
    (
        mesh,
        phi,
        tmp<surfaceInterpolationScheme<scalar>>
        (
            new sharedWeights(mesh, weights_())
        )
    ).fvmDiv(phi, n);
}


// ************************************************************************* //

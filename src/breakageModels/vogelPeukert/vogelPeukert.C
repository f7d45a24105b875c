/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "vogelPeukert.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "modelCoeffs.H"
#include "LawFormulas.hpp"
#include "BreakageRate.hpp"

#include <cmath>
#include <limits>

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(vogelPeukert, 0);
    addToRunTimeSelectionTable(breakageModel, vogelPeukert, dictionary);
}
}


Foam::breakageModels::vogelPeukert::vogelPeukert
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    breakageModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"fMat", "xWmMin", "phiMax"}),
        mixture
    ),
    fMat_
    (
        modelCoeffs::get(coeffs_, "fMat", sqr(dimTime)/pow3(dimLength))
       .value()
    ),
    xWmMin_
    (
        modelCoeffs::get(coeffs_, "xWmMin", pow3(dimLength)/sqr(dimTime))
       .value()
    ),
    // Optional, default 0.63 (random close packing), as kineticTheory
    phiMax_(coeffs_.getOrDefault<scalar>("phiMax", 0.63))
{
    checkNonNegative("fMat", fMat_);
    checkNonNegative("xWmMin", xWmMin_);
    if (!(phiMax_ > 0 && phiMax_ < 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'phiMax " << phiMax_ << "' in " << coeffs_.name()
            << " must lie in (0, 1)" << nl << exit(FatalIOError);
    }
}


Foam::scalar Foam::breakageModels::vogelPeukert::exponentialSpectrumRate
(
    const scalar fMat,
    const scalar xWmMin,
    const scalar x,
    const scalar impactRate,
    const scalar Wbar
)
{
    if (!std::isfinite(Wbar) || !std::isfinite(impactRate))
    {
        // Not a rate: breakageModel::correct stops naming species and cell
        return Wbar*impactRate*std::numeric_limits<scalar>::quiet_NaN();
    }
    if (!(Wbar > 0) || !(impactRate > 0))
    {
        return 0;
    }
    // The formula the DEM calibration uses (calibration/fit/BreakageRate.hpp):
    // integral_Wmin^inf (W - Wmin) exp(-W/Wbar)/Wbar dW = Wbar exp(-Wmin/Wbar)
    return sdf::fit::breakage::vogelPeukertRateExponentialSpectrum
    (
        sdf::fit::breakage::VogelPeukertMaterial{fMat, xWmMin},
        x,
        impactRate,
        Wbar
    );
}


void Foam::breakageModels::vogelPeukert::calcS
(
    const label j,
    const granularTemperatureModel& granularTemperature,
    volScalarField& S
) const
{
    const scalar pi = constant::mathematical::pi;
    const scalar dj = mixture_.d(j);
    const scalar mj = mixture_.rho(j)*mixture_.particleVolume(j);

    const scalarField& T = granularTemperature.T().primitiveField();
    const scalarField& phi = mixture_.nTotal().primitiveField();
    scalarField& Sc = S.primitiveFieldRef();
    Sc = 0;

    forAll(mixture_.n(), k)
    {
        const scalar dk = mixture_.d(k);
        const scalar vk = mixture_.particleVolume(k);
        const scalar mk = mixture_.rho(k)*vk;
        const scalar sigma = 0.5*(dj + dk);
        const scalar massRatio = mj*mk/sqr(mj + mk);
        const scalarField& nk = mixture_.n()[k].primitiveField();

        forAll(Sc, celli)
        {
            const scalar theta =
                sdf::fit::formulas::perComponentTemperature(max(T[celli], scalar(0)));
            const scalar g0 = sdf::fit::formulas::carnahanStarlingG0
            (
                min(max(phi[celli], scalar(0)), phiMax_)
            );
            const scalar impactRate =
                (max(nk[celli], scalar(0))/vk)*pi*sqr(sigma)*g0
               *4*Foam::sqrt(theta/pi);

            Sc[celli] += exponentialSpectrumRate
            (
                fMat_,
                xWmMin_,
                dj,
                impactRate,
                2*theta*massRatio
            );
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "impactBreakage.H"
#include "modelCoeffs.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include "BreakageRate.hpp"

#include <cmath>

const Foam::Enum<Foam::impactBreakage::impactEnergy>
Foam::impactBreakage::impactEnergyNames
({
    { impactEnergy::total, "total" },
    { impactEnergy::normal, "normal" },
    { impactEnergy::angleFunction, "angleFunction" },
});


const Foam::wordList Foam::impactBreakage::keys
({
    "fMat", "xWmMin", "impactEnergy", "criticalAngle"
});


Foam::impactBreakage::impactBreakage(const dictionary& dict)
:
    fMat_
    (
        modelCoeffs::get(dict, "fMat", sqr(dimTime)/pow3(dimLength)).value()
    ),
    xWmMin_
    (
        modelCoeffs::get(dict, "xWmMin", pow3(dimLength)/sqr(dimTime)).value()
    ),
    energy_(impactEnergy::normal),
    sinCriticalAngle_(1)
{
    modelCoeffs::checkNonNegative(dict, "fMat", fMat_, "Impact breakage");
    modelCoeffs::checkNonNegative(dict, "xWmMin", xWmMin_, "Impact breakage");

    // Required, no default: which energy counts decides the answer
    const word energyName(dict.get<word>("impactEnergy"));
    if (!impactEnergyNames.found(energyName))
    {
        FatalIOErrorInFunction(dict)
            << "Unknown 'impactEnergy " << energyName << "' in "
            << dict.name() << nl << "Valid choices: "
            << impactEnergyNames.sortedToc() << nl << exit(FatalIOError);
    }
    energy_ = impactEnergyNames.get(energyName);

    if (energy_ == impactEnergy::angleFunction)
    {
        const scalar angle = dict.getOrDefault<scalar>("criticalAngle", 50);
        if (!(angle > 0 && angle <= 90))
        {
            FatalIOErrorInFunction(dict)
                << "'criticalAngle " << angle << "' in " << dict.name()
                << " must lie in (0, 90] degrees" << nl << exit(FatalIOError);
        }
        sinCriticalAngle_ = Foam::sin(degToRad(angle));
    }
    else if (dict.found("criticalAngle"))
    {
        FatalIOErrorInFunction(dict)
            << "'criticalAngle' in " << dict.name() << " is read only with"
            << " 'impactEnergy angleFunction' (here "
            << impactEnergyNames[energy_] << ")" << nl << exit(FatalIOError);
    }
}


Foam::impactBreakage::impactBreakage
(
    const scalar fMat,
    const scalar xWmMin,
    const impactEnergy energy,
    const scalar criticalAngleDeg
)
:
    fMat_(fMat),
    xWmMin_(xWmMin),
    energy_(energy),
    sinCriticalAngle_(Foam::sin(degToRad(criticalAngleDeg)))
{}


Foam::scalar Foam::impactBreakage::W(const scalar Un, const scalar Ut) const
{
    const scalar normal2 = sqr(Un);
    const scalar total2 = normal2 + sqr(Ut);
    switch (energy_)
    {
        case impactEnergy::total:
            return 0.5*total2;
        case impactEnergy::normal:
            return 0.5*normal2;
        case impactEnergy::angleFunction:
        {
            if (total2 <= 0)
            {
                return 0;
            }
            // sin^2 alpha = Un^2/(Un^2 + Ut^2)
            const scalar g = min(scalar(1), normal2/total2/sqr(sinCriticalAngle_));
            return 0.5*total2*g;
        }
    }
    return 0;
}


Foam::scalar Foam::impactBreakage::exponent
(
    const scalar x,
    const scalar Un,
    const scalar Ut
) const
{
    return sdf::fit::breakage::impactBreakageExponent
    (
        sdf::fit::breakage::VogelPeukertMaterial{fMat_, xWmMin_},
        x,
        W(Un, Ut)
    );
}


Foam::scalar Foam::impactBreakage::probability
(
    const scalar x,
    const scalar Un,
    const scalar Ut
) const
{
    return -std::expm1(-exponent(x, Un, Ut));
}


// ************************************************************************* //

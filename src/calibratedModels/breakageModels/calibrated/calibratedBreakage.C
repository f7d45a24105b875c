/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibratedBreakage.H"
#include "vogelPeukert.H"
#include "calibrationSettings.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"


#include <string>

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(calibrated, 0);
    addToRunTimeSelectionTable(breakageModel, calibrated, dictionary);
}
}


namespace
{

//- The law of `coefficient` (omega.<s> or Wmean.<s>) from the
//  granularCoefficients dictionary, checked to be present and of one of
//  the valid kinds before calibratedLaw reads it
Foam::calibratedLaw* readBreakageLaw
(
    const Foam::dictionary& coefficients,
    const Foam::word& coefficient,
    const Foam::wordList& validLaws,
    const std::string& meaning,
    const Foam::dictionary& modelDict
)
{
    using namespace Foam;
    if (!coefficients.isDict(coefficient))
    {
        FatalIOErrorInFunction(coefficients)
            << "No calibrated law '" << coefficient << "' (" << meaning.c_str()
            << ") in " << coefficients.name() << nl
            << "    The calibrated breakage model needs omega.<species> and"
            << " Wmean.<species> for every species of the case: run"
            << " calibrateGranularMixture with 'coefficients (.. breakage)'"
            << " (or -fromCase with breakage model calibrated)" << nl
            << exit(FatalIOError);
    }
    const dictionary& lawDict = coefficients.subDict(coefficient);
    const word law(lawDict.get<word>("law"));
    if (!validLaws.found(law))
    {
        FatalIOErrorInFunction(lawDict)
            << "Entry '" << coefficient << "/law " << law << "' in "
            << coefficients.name() << " is not a law of " << meaning.c_str()
            << "; valid: " << validLaws << nl << exit(FatalIOError);
    }
    return new calibratedLaw(coefficients, coefficient, modelDict);
}

} // End anonymous namespace


const Foam::wordList& Foam::breakageModels::calibrated::coeffsKeys()
{
    static const wordList keys({"fMat", "xWmMin", "file", "outsideEnvelope"});
    return keys;
}


Foam::breakageModels::calibrated::calibrated
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    breakageModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, coeffsKeys()),
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
    omega_(mixture.size()),
    Wmean_(mixture.size())
{
    checkNonNegative("fMat", fMat_);
    checkNonNegative("xWmMin", xWmMin_);

    const IOdictionary coefficients
    (
        calibratedLaw::readCoefficients(mixture, coeffs_)
    );
    forAll(mixture.names(), j)
    {
        const word& name = mixture.names()[j];
        omega_.set
        (
            j,
            readBreakageLaw
            (
                coefficients,
                "omega." + name,
                calibrationSettings::validCollisionFrequencyLaws,
                "the collision frequency of one particle of species " + name,
                coeffs_
            )
        );
        Wmean_.set
        (
            j,
            readBreakageLaw
            (
                coefficients,
                "Wmean." + name,
                calibrationSettings::validImpactEnergyLaws,
                "the mean impact energy of one particle of species " + name,
                coeffs_
            )
        );
    }
}


void Foam::breakageModels::calibrated::calcS
(
    const label j,
    const granularTemperatureModel& granularTemperature,
    volScalarField& S
) const
{
    const scalar dj = mixture_.d(j);
    const volScalarField& T = granularTemperature.T();

    const tmp<volScalarField> tomega
    (
        omega_[j].evaluate(mixture_, T, dj, inv(dimTime))
    );
    const tmp<volScalarField> tWmean
    (
        Wmean_[j].evaluate(mixture_, T, dj, sqr(dimVelocity))
    );
    const scalarField& omega = tomega().primitiveField();
    const scalarField& Wmean = tWmean().primitiveField();

    // No agitation, no impacts: S = 0 where T = 0 whatever the envelope
    // policy (clamp would otherwise evaluate a static bed at the lower end
    // of TRange)
    const scalarField& Tc = T.primitiveField();
    scalarField& Sc = S.primitiveFieldRef();
    forAll(Sc, celli)
    {
        Sc[celli] =
            Tc[celli] > 0
          ? vogelPeukert::exponentialSpectrumRate
            (
                fMat_, xWmMin_, dj, omega[celli], Wmean[celli]
            )
          : 0;
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibratedPercolation.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"
#include "surfaceInterpolate.H"
#include "IOdictionary.H"
#include "scratchField.H"
#include "OSspecific.H"
#include "fit/SegregationLaws.hpp"

namespace Foam
{
namespace percolationModels
{
    defineTypeNameAndDebug(calibrated, 0);
    addToRunTimeSelectionTable(percolationModel, calibrated, dictionary);
}
}

const Foam::Enum<Foam::percolationModels::calibrated::outsidePolicy>
Foam::percolationModels::calibrated::outsidePolicyNames
({
    {outsidePolicy::clamp, "clamp"},
    {outsidePolicy::extrapolate, "extrapolate"},
    {outsidePolicy::error, "error"},
});


namespace
{

//- The segregationVelocity sub-dictionary of constant/<file>, or a FatalIOError
//  that says how to make it
Foam::dictionary segregationVelocityDict
(
    const Foam::granularMixture& mixture,
    const Foam::dictionary& coeffs
)
{
    using namespace Foam;
    const word file(coeffs.getOrDefault<word>("file", "granularCoefficients"));
    const word howTo
    (
        "run gravityShearCell at the case's pressures and fitSegregationVelocity on"
        " its -segregation.dat files (docs/user/calibration.md), and put the"
        " segregationVelocity entries it writes into constant/" + file
    );
    // the case's constant/ (in parallel the undecomposed case's), wherever the
    // solver runs from
    IOobject io
    (
        file,
        mixture.mesh().time().constant(),
        mixture.mesh(),
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(false))
    {
        FatalIOErrorInFunction(coeffs)
            << "percolation calibrated: " << io.objectPath() << " not found: there"
            << " is no calibration of the segregation velocity; " << howTo.c_str()
            << nl << exit(FatalIOError);
    }
    const IOdictionary coefficients(io);
    if (!coefficients.isDict("segregationVelocity"))
    {
        FatalIOErrorInFunction(coefficients)
            << "percolation calibrated: constant/" << file << " has no"
            << " segregationVelocity sub-dictionary (it holds "
            << coefficients.toc() << "); " << howTo.c_str()
            << nl << exit(FatalIOError);
    }
    return coefficients.subDict("segregationVelocity");
}


//- The law the dictionary names, or a FatalIOError listing the valid ones
sdf::fit::ConstitutiveLaw lawNamedIn(const Foam::dictionary& dict)
{
    using namespace Foam;
    try
    {
        return sdf::fit::segregationLawFromName(dict.get<word>("law"));
    }
    catch (const std::invalid_argument& e)
    {
        FatalIOErrorInFunction(dict)
            << "segregationVelocity: " << e.what() << nl << exit(FatalIOError);
    }
    return sdf::fit::FanSchlickLaw{};   // not reached
}


Foam::Pair<Foam::scalar> readRange(const Foam::dictionary& dict, const Foam::word& key)
{
    using namespace Foam;
    const Pair<scalar> r(dict.get<Pair<scalar>>(key));
    if (!(r.first() <= r.second()))
    {
        FatalIOErrorInFunction(dict)
            << "'" << key << " (" << r.first() << ' ' << r.second() << ")' is not"
            << " a range (min max)" << nl << exit(FatalIOError);
    }
    return r;
}

} // End anonymous namespace


Foam::percolationModels::calibrated::calibrated
(
    const dictionary& dict,
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
:
    percolationModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {"file", "outsideEnvelope"}),
        mixture
    ),
    bulkFlow_(bulkFlow),
    lawDict_(segregationVelocityDict(mixture, coeffs_)),
    law_(lawNamedIn(lawDict_)),
    parameters_(),
    outside_
    (
        outsidePolicyNames.getOrDefault("outsideEnvelope", coeffs_, outsidePolicy::clamp)
    ),
    gSf_(gravityFaceAreas(mixture)),
    pStar_
    (
        IOobject
        (
            "pStar",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mixture.mesh(),
        dimensionedScalar(dimless, Zero)
    ),
    gammaDotf_(scratchSurfaceField(mixture.mesh(), "calibratedPercolation:gammaDotf", dimless/dimTime)),
    pStarf_(scratchSurfaceField(mixture.mesh(), "calibratedPercolation:pStarf", dimless)),
    xf_(scratchSurfaceField(mixture.mesh(), "calibratedPercolation:xf", dimless))
{
    const dictionary& law = lawDict_;
    const word name(law_.name());
    const std::vector<std::string> names = law_.parameterNames();
    parameters_.resize(label(names.size()));
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (!law.found(names[k]))
        {
            FatalIOErrorInFunction(law)
                << "segregationVelocity: law " << name << " needs the parameter '"
                << names[k].c_str() << "', not found" << nl << exit(FatalIOError);
        }
        parameters_[label(k)] = law.get<scalar>(names[k]);
    }
    const Pair<scalar> pStar(readRange(law, "pStarRange"));
    const Pair<scalar> R(readRange(law, "sizeRatioRange"));
    const Pair<scalar> x(readRange(law, "xRange"));
    pStarMin_ = pStar.first(); pStarMax_ = pStar.second();
    sizeRatioMin_ = R.first(); sizeRatioMax_ = R.second();
    xMin_ = x.first(); xMax_ = x.second();

    // the pressure laws' S = B dMean (R - 1)/(C + p*) is infinite where p* = -C:
    // C must be > 0, so that S stays finite from the free surface (p* 0) down
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        if (names[k] == "C" && !(parameters_[label(k)] > 0))
        {
            FatalIOErrorInFunction(law)
                << "segregationVelocity: law " << name << " with C "
                << parameters_[label(k)] << ": C must be > 0 (S goes as 1/(C + p*),"
                << " p* >= 0)" << nl << exit(FatalIOError);
        }
    }

    Info<< "    percolation calibrated: S = " << law_.formula().c_str() << ',';
    for (std::size_t k = 0; k < names.size(); ++k)
    {
        Info<< ' ' << names[k].c_str() << " = " << parameters_[label(k)];
    }
    Info<< "; fitted over p* " << pStarMin_ << "-" << pStarMax_ << ", R "
        << sizeRatioMin_ << "-" << sizeRatioMax_ << ", x " << xMin_ << "-" << xMax_
        << ", outside: " << outsidePolicyNames[outside_] << "; the pressure: "
        << bulkFlow.pressureSource().c_str() << nl;
}


Foam::scalar Foam::percolationModels::calibrated::percolationLength
(
    const scalar d,
    const scalar R,
    const scalar pStar,
    const scalar x
) const
{
    sdf::fit::Condition c;
    c.d = d;
    if (outside_ == outsidePolicy::clamp)
    {
        c.x = min(max(x, xMin_), xMax_);
        c.pressureNumber = min(max(pStar, pStarMin_), pStarMax_);
        c.sizeRatio = min(max(R, sizeRatioMin_), sizeRatioMax_);
    }
    else
    {
        c.x = min(max(x, scalar(0)), scalar(1));
        c.pressureNumber = pStar;
        c.sizeRatio = R;
    }
    return law_.evaluate(c, parameters_);
}


void Foam::percolationModels::calibrated::checkEnvelope
(
    const volScalarField& pStar,
    const volScalarField& x
) const
{
    const scalarField& phi = mixture_.nTotal().primitiveField();
    const scalar R = mixture_.dMax()/mixture_.dMin();
    if (R < sizeRatioMin_ || R > sizeRatioMax_)
    {
        FatalErrorInFunction
            << "percolation calibrated (outsideEnvelope error): the size ratio "
            << R << " is outside sizeRatioRange (" << sizeRatioMin_ << ' '
            << sizeRatioMax_ << ")" << nl << exit(FatalError);
    }
    forAll(phi, celli)
    {
        if (phi[celli] < mixture_.phiMin()) continue;
        const bool pOut = pStar[celli] < pStarMin_ || pStar[celli] > pStarMax_;
        if (pOut || x[celli] < xMin_ || x[celli] > xMax_)
        {
            FatalErrorInFunction
                << "percolation calibrated (outsideEnvelope error): cell " << celli
                << " at " << mixture_.mesh().C()[celli] << ": "
                << (pOut ? "p* " : "x ") << (pOut ? pStar[celli] : x[celli])
                << " is outside " << (pOut ? "pStarRange (" : "xRange (")
                << (pOut ? pStarMin_ : xMin_) << ' ' << (pOut ? pStarMax_ : xMax_)
                << ")" << nl << exit(FatalError);
        }
    }
}


void Foam::percolationModels::calibrated::correct()
{
    pStar_ =
        bulkFlow_.pressure()
       /(
            mixture_.solidsDensity()
           *dimensionedScalar("g", dimAcceleration, mag(mixture_.gravity()))
           *mixture_.dMean()
        );
    const volScalarField& pStar = pStar_;
    const volScalarField x(mixture_.coarseFraction());
    if (outside_ == outsidePolicy::error)
    {
        checkEnvelope(pStar, x);
    }
    gammaDotf_ = fvc::interpolate(bulkFlow_.gammaDot());
    pStarf_ = fvc::interpolate(pStar);
    xf_ = fvc::interpolate(x);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::percolationModels::calibrated::driftFlux
(
    const label finei,
    const label coarsej
) const
{
    const scalar d = mixture_.d(finei);
    const scalar R = mixture_.d(coarsej)/d;
    tmp<surfaceScalarField> tW(gammaDotf_*gSf_*dimensionedScalar("m", dimLength, 1));
    surfaceScalarField& W = tW.ref();
    scalarField& Wi = W.primitiveFieldRef();
    forAll(Wi, facei)
    {
        Wi[facei] *= percolationLength(d, R, pStarf_[facei], xf_[facei]);
    }
    surfaceScalarField::Boundary& Wb = W.boundaryFieldRef();
    forAll(Wb, patchi)
    {
        const scalarField& pStarp = pStarf_.boundaryField()[patchi];
        const scalarField& xp = xf_.boundaryField()[patchi];
        forAll(Wb[patchi], facei)
        {
            Wb[patchi][facei] *= percolationLength(d, R, pStarp[facei], xp[facei]);
        }
    }
    zeroUncoupledPatches(W);
    return tW;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibratedLaw.H"
#include "zeroGradientFvPatchFields.H"
#include "numberText.H"

#include <cstdio>
#include <string>

const Foam::Enum<Foam::calibratedLaw::outsidePolicy>
Foam::calibratedLaw::outsidePolicyNames
({
    { outsidePolicy::clamp, "clamp" },
    { outsidePolicy::extrapolate, "extrapolate" },
    { outsidePolicy::error, "error" },
    { outsidePolicy::runDEM, "runDEM" },
});


const Foam::Enum<Foam::calibratedLaw::modeType>
Foam::calibratedLaw::modeNames
({
    { modeType::law, "law" },
    { modeType::tabulated, "tabulated" },
});


const Foam::wordList& Foam::calibratedLaw::coeffsKeys()
{
    static const wordList keys
    ({
        "mode", "file", "calibrationFile", "interpolation", "outsideEnvelope",
        "runDEMMargin", "runDEMMaxPhi", "runDEMMinT"
    });
    return keys;
}


namespace
{

Foam::Tuple2<Foam::scalar, Foam::scalar> readRange
(
    const Foam::dictionary& dict,
    const Foam::word& name
)
{
    const Foam::scalarList r(dict.get<Foam::scalarList>(name));
    if (r.size() != 2 || !(r[0] <= r[1]))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << name << "' must be (min max) with min <= max, got "
            << r << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
    return Foam::Tuple2<Foam::scalar, Foam::scalar>(r[0], r[1]);
}

//- Six significant digits in messages, whatever the stream's precision
using Foam::numberText::fmt;

std::string fmt6(const Foam::Tuple2<Foam::scalar, Foam::scalar>& range)
{
    return "(" + fmt(range.first()) + " " + fmt(range.second()) + ")";
}


//- runDEM adds DEM conditions to a table; a fitted law cannot take them
void checkPolicyFitsLaw
(
    const Foam::dictionary& modelDict,
    const Foam::calibratedLaw::outsidePolicy policy
)
{
    if (policy == Foam::calibratedLaw::outsidePolicy::runDEM)
    {
        FatalIOErrorInFunction(modelDict)
            << "'outsideEnvelope runDEM' needs 'mode tabulated' (runDEM adds"
            << " DEM conditions to the table of calibration.h5; a fitted law"
            << " cannot take them); valid with mode law: (clamp extrapolate"
            << " error)" << Foam::nl << Foam::exit(Foam::FatalIOError);
    }
}

} // End anonymous namespace


Foam::calibratedLaw::calibratedLaw
(
    const word& coefficient,
    const dictionary& modelDict
)
:
    coefficient_(coefficient),
    law_(),
    fitted_(),
    parameters_(),
    policy_
    (
        outsidePolicyNames.getOrDefault
        (
            "outsideEnvelope",
            modelDict,
            outsidePolicy::clamp
        )
    )
{}


Foam::calibratedLaw::calibratedLaw
(
    const granularMixture& mixture,
    const word& coefficient,
    const dictionary& modelDict
)
:
    calibratedLaw(coefficient, modelDict)
{
    const modeType mode =
        modeNames.getOrDefault("mode", modelDict, modeType::law);

    if (mode == modeType::law)
    {
        checkPolicyFitsLaw(modelDict, policy_);
        readLaw(readCoefficients(mixture, modelDict));
        return;
    }

    law_ = "tabulated";
    table_.reset(new calibrationTable(mixture, modelDict, coefficient));
    if (policy_ == outsidePolicy::runDEM)
    {
        runner_.reset(new calibrationDEMRunner(mixture, *table_, modelDict));
    }
    Info<< "    calibrated " << coefficient << ": outside the table's grid "
        << fmt6(phiRange()).c_str() << " x " << fmt6(xRange()).c_str()
        << " x " << fmt6(TRange()).c_str() << ": "
        << outsidePolicyNames[policy_] << nl;
}


Foam::calibratedLaw::calibratedLaw
(
    const dictionary& coeffsDict,
    const word& coefficient,
    const dictionary& modelDict
)
:
    calibratedLaw(coefficient, modelDict)
{
    if (modeNames.getOrDefault("mode", modelDict, modeType::law) != modeType::law)
    {
        FatalIOErrorInFunction(modelDict)
            << "mode '" << modelDict.get<word>("mode") << "' needs the"
            << " mixture; this constructor reads laws only (mode law)" << nl
            << exit(FatalIOError);
    }
    checkPolicyFitsLaw(modelDict, policy_);
    readLaw(coeffsDict);
}


void Foam::calibratedLaw::readLaw(const dictionary& coeffsDict)
{
    const word& coefficient = coefficient_;
    if (!coeffsDict.isDict(coefficient))
    {
        FatalIOErrorInFunction(coeffsDict)
            << "No calibrated law for '" << coefficient << "' in "
            << coeffsDict.name() << "; run calibrateGranularMixture with"
            << " this coefficient, or choose another model" << nl
            << exit(FatalIOError);
    }
    const dictionary& dict = coeffsDict.subDict(coefficient);

    law_ = dict.get<word>("law");

    // The fixed power k of d of the sieving laws: an integer, as the fit
    // wrote it
    const scalar diameterPower = dict.getOrDefault<scalar>("diameterPower", 1);
    if (diameterPower != std::round(diameterPower))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'diameterPower " << diameterPower << "' of "
            << coefficient << " must be an integer (the power k of d in"
            << " E d^k ...)" << nl << exit(FatalIOError);
    }
    try
    {
        fitted_.emplace(sdf::fit::lawFromName(law_, int(diameterPower)));
    }
    catch (const std::invalid_argument&)
    {
        wordList valid;
        for (const std::string& name : sdf::fit::lawNames())
        {
            valid.append(name);
        }
        FatalIOErrorInFunction(dict)
            << "Unknown law '" << law_ << "' for " << coefficient
            << "; valid: " << valid << nl << exit(FatalIOError);
    }

    const std::vector<std::string> names(fitted_->parameterNames());
    parameters_.resize(label(names.size()));
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        // OpenFOAM's parser reads `nan` or `inf` as a word: refused here
        // naming the parameter, as a non-finite number would be
        const ITstream& is = dict.lookup(names[i]);
        const bool number = is.size() == 1 && is[0].isNumber();
        const scalar v =
            number ? is[0].number() : std::numeric_limits<scalar>::quiet_NaN();
        if (!std::isfinite(v))
        {
            FatalIOErrorInFunction(dict)
                << "Parameter '" << names[i].c_str() << "' of " << coefficient
                << " is not a finite number:";
            for (const token& tok : is)
            {
                FatalIOError<< ' ' << tok;
            }
            FatalIOError<< nl << exit(FatalIOError);
        }
        parameters_(i) = v;
    }

    phiRange_ = readRange(dict, "phiRange");
    xRange_ = readRange(dict, "xRange");
    TRange_ = readRange(dict, "TRange");

    Info<< "    calibrated " << coefficient << ": " << law_;
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        Info<< ' ' << names[i].c_str() << " = " << parameters_(i);
    }
    Info<< ", outside the envelope: " << outsidePolicyNames[policy_] << nl;
}


Foam::IOdictionary Foam::calibratedLaw::readCoefficients
(
    const granularMixture& mixture,
    const dictionary& modelDict
)
{
    return IOdictionary
    (
        IOobject
        (
            modelDict.getOrDefault<word>("file", "granularCoefficients"),
            mixture.mesh().time().constant(),
            mixture.mesh(),
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
}


Foam::scalar Foam::calibratedLaw::value
(
    const scalar phi,
    const scalar x,
    const scalar T,
    const scalar d
) const
{
    if (table_)
    {
        // The table holds the fines' D (eta: the coarse's) whatever d is
        return table_->value(phi, x, T);
    }

    // No agitation, no transport: every law vanishes with T (and the
    // power law's T^m must not be evaluated at T = 0 for m < 0)
    if (!(T > VSMALL))
    {
        return 0;
    }

    // x is a fraction: round-off below 0 must not reach x^q
    sdf::fit::Condition c;
    c.phi = phi;
    c.x = max(x, scalar(0));
    c.T = T;
    c.d = d;
    return fitted_->evaluate(c, parameters_);
}


Foam::Tuple2<Foam::scalar, Foam::scalar> Foam::calibratedLaw::phiRange() const
{
    return table_ ? table_->phiRange() : phiRange_;
}


Foam::Tuple2<Foam::scalar, Foam::scalar> Foam::calibratedLaw::xRange() const
{
    return table_ ? table_->xRange() : xRange_;
}


Foam::Tuple2<Foam::scalar, Foam::scalar> Foam::calibratedLaw::TRange() const
{
    return table_ ? table_->TRange() : TRange_;
}


Foam::tmp<Foam::volScalarField> Foam::calibratedLaw::evaluate
(
    const granularMixture& mixture,
    const volScalarField& T,
    const scalar d,
    const dimensionSet& dims
) const
{
    const volScalarField phiReg(mixture.phiRegularised());
    const volScalarField x(mixture.coarseFraction());
    const scalarField& phi = mixture.nTotal().primitiveField();

    tmp<volScalarField> tresult
    (
        volScalarField::New
        (
            coefficient_ + "Calibrated",
            mixture.mesh(),
            dimensionedScalar("zero", dims, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    scalarField& result = tresult.ref().primitiveFieldRef();

    auto clampTo = [](scalar v, const Tuple2<scalar, scalar>& r)
    {
        return min(max(v, r.first()), r.second());
    };

    // runDEM: grow the table's grid first to cover every cell holding
    // material (collective in parallel: every rank calls extend)
    if (runner_)
    {
        calibrationDEMRunner::cellRanges ranges
        {
            GREAT, -GREAT, GREAT, -GREAT, GREAT, -GREAT
        };
        forAll(phi, celli)
        {
            if (phi[celli] >= mixture.phiMin())
            {
                ranges.phiMin = min(ranges.phiMin, phiReg[celli]);
                ranges.phiMax = max(ranges.phiMax, phiReg[celli]);
                ranges.xMin = min(ranges.xMin, x[celli]);
                ranges.xMax = max(ranges.xMax, x[celli]);
                ranges.TMin = min(ranges.TMin, T[celli]);
                ranges.TMax = max(ranges.TMax, T[celli]);
            }
        }
        runner_->extend(*table_, ranges);
    }

    const Tuple2<scalar, scalar> phiRange(this->phiRange());
    const Tuple2<scalar, scalar> xRange(this->xRange());
    const Tuple2<scalar, scalar> TRange(this->TRange());

    forAll(result, celli)
    {
        scalar p = phiReg[celli];
        scalar xc = x[celli];
        scalar Tc = T[celli];

        const bool holdsMaterial = phi[celli] >= mixture.phiMin();

        // The table's values in empty cells do not matter (the presence
        // factor removes them) but extrapolating ln(value) far out could
        // overflow: clamp them silently
        const bool clampSilently = table_ && !holdsMaterial;

        if
        (
            clampSilently
         || (holdsMaterial && policy_ != outsidePolicy::extrapolate)
        )
        {
            const scalar pc = clampTo(p, phiRange);
            const scalar xcl = clampTo(xc, xRange);
            const scalar Tcl = clampTo(Tc, TRange);
            if
            (
                !clampSilently && policy_ == outsidePolicy::error
             && (pc != p || xcl != xc || Tcl != Tc)
            )
            {
                FatalErrorInFunction
                    << "Cell " << celli << " (centre "
                    << mixture.mesh().C()[celli] << ") is outside the"
                    << " envelope of the calibrated " << coefficient_
                    << ": phi " << fmt(p).c_str() << " in " << fmt6(phiRange).c_str()
                    << ", x " << fmt(xc).c_str() << " in " << fmt6(xRange).c_str()
                    << ", T " << fmt(Tc).c_str() << " in " << fmt6(TRange).c_str() << nl
                    << "    (outsideEnvelope error; use clamp or extrapolate,"
                    << " or widen the calibration)" << nl << exit(FatalError);
            }
            p = pc;
            xc = xcl;
            Tc = Tcl;
        }
        result[celli] = value(p, xc, Tc, d);
    }

    tresult.ref().correctBoundaryConditions();
    return tresult;
}


// ************************************************************************* //

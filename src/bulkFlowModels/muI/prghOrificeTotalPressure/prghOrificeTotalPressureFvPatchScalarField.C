/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "prghOrificeTotalPressureFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "prghTotalPressureValue.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prghOrificeTotalPressureFvPatchScalarField::
prghOrificeTotalPressureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
    p0_(p.size(), Zero),
    rhoName_("rho"),
    phiName_("phi"),
    UName_("U"),
    openFraction_(p.size(), 1)
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = 1;
}


Foam::prghOrificeTotalPressureFvPatchScalarField::
prghOrificeTotalPressureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF),
    p0_("p0", dict, p.size()),
    rhoName_(dict.getOrDefault<word>("rho", "rho")),
    phiName_(dict.getOrDefault<word>("phi", "phi")),
    UName_(dict.getOrDefault<word>("U", "U")),
    openFraction_(p.size(), 1)
{
    // A restart takes up the written state (the first momentum
    // predictor's snGrad(p_rgh) is then the last step's); a new case is
    // open at the written value or p0
    if (dict.found("refValue") && dict.found("refGradient"))
    {
        refValue() = scalarField("refValue", dict, p.size());
        refGrad() = scalarField("refGradient", dict, p.size());
        valueFraction() =
            dict.found("valueFraction")
          ? scalarField("valueFraction", dict, p.size())
          : scalarField(p.size(), 1);
        fvPatchScalarField::operator=
        (
            dict.found("value")
          ? scalarField("value", dict, p.size())
          : scalarField(refValue())
        );
    }
    else
    {
        refValue() =
            dict.found("value") ? scalarField("value", dict, p.size()) : p0_;
        refGrad() = Zero;
        valueFraction() = 1;
        fvPatchScalarField::operator=(refValue());
    }
}


Foam::prghOrificeTotalPressureFvPatchScalarField::
prghOrificeTotalPressureFvPatchScalarField
(
    const prghOrificeTotalPressureFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    p0_(ptf.p0_, mapper),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    openFraction_(ptf.openFraction_, mapper)
{}


Foam::prghOrificeTotalPressureFvPatchScalarField::
prghOrificeTotalPressureFvPatchScalarField
(
    const prghOrificeTotalPressureFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    p0_(ptf.p0_),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    openFraction_(ptf.openFraction_)
{}


Foam::prghOrificeTotalPressureFvPatchScalarField::
prghOrificeTotalPressureFvPatchScalarField
(
    const prghOrificeTotalPressureFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    p0_(ptf.p0_),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    openFraction_(ptf.openFraction_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::prghOrificeTotalPressureFvPatchScalarField::setOpenFraction
(
    const scalarField& f
)
{
    if (f.size() != openFraction_.size() || min(f) < 0 || max(f) > 1)
    {
        FatalErrorInFunction
            << "Open fractions of patch " << patch().name() << " of "
            << internalField().name() << ": " << f.size()
            << " values in [" << (f.empty() ? 0 : min(f)) << ", "
            << (f.empty() ? 0 : max(f)) << "], expected "
            << openFraction_.size() << " in [0, 1]" << exit(FatalError);
    }
    openFraction_ = f;
    valueFraction() = openFraction_;
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::closeRim
(
    scalarField& phiHbyAp,
    const scalarField& HbyAFluxp,
    const scalarField& rAUfp
)
{
    // A wall's phiHbyA: no HbyA through it (U = 0 there)
    const scalarField phiHbyAWall(phiHbyAp - HbyAFluxp);
    phiHbyAp -= (1 - openFraction_)*HbyAFluxp;

    valueFraction() = openFraction_;
    refValue() =
        prghTotalPressureValue(*this, p0_, rhoName_, phiName_, UName_);
    refGrad() = phiHbyAWall/(patch().magSf()*max(rAUfp, VSMALL));
    mixedFvPatchScalarField::updateCoeffs();
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::zeroClosedFlux
(
    scalarField& phip
) const
{
    forAll(openFraction_, facei)
    {
        if (openFraction_[facei] == 0)
        {
            phip[facei] = 0;
        }
    }
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
    p0_.autoMap(m);
    openFraction_.autoMap(m);
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
    const auto& tiptf =
        refCast<const prghOrificeTotalPressureFvPatchScalarField>(ptf);
    p0_.rmap(tiptf.p0_, addr);
    openFraction_.rmap(tiptf.openFraction_, addr);
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    // The closing gradient is the last closeRim's (the momentum predictor
    // between two correctors sees the last pressure's face values)
    refValue() =
        prghTotalPressureValue(*this, p0_, rhoName_, phiName_, UName_);

    mixedFvPatchScalarField::updateCoeffs();
}


void Foam::prghOrificeTotalPressureFvPatchScalarField::write
(
    Ostream& os
) const
{
    fvPatchScalarField::write(os);
    p0_.writeEntry("p0", os);
    os.writeEntryIfDifferent<word>("rho", "rho", rhoName_);
    os.writeEntryIfDifferent<word>("phi", "phi", phiName_);
    os.writeEntryIfDifferent<word>("U", "U", UName_);
    refValue().writeEntry("refValue", os);
    refGrad().writeEntry("refGradient", os);
    valueFraction().writeEntry("valueFraction", os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        prghOrificeTotalPressureFvPatchScalarField
    );
}

// ************************************************************************* //

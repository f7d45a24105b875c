/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "prghBulkRetainingTotalPressureFvPatchScalarField.H"
#include "addToRunTimeSelectionTable.H"
#include "fvPatchFieldMapper.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "prghTotalPressureValue.H"

// * * * * * * * * * * * * * * * Private Functions * * * * * * * * * * * * * //

Foam::tmp<Foam::scalarField>
Foam::prghBulkRetainingTotalPressureFvPatchScalarField::totalPressure() const
{
    return prghTotalPressureValue(*this, p0_, rhoName_, phiName_, UName_);
}


Foam::boolList
Foam::prghBulkRetainingTotalPressureFvPatchScalarField::cellsHoldBulk() const
{
    const volScalarField& alpha =
        db().lookupObject<volScalarField>(alphaName_);
    const scalarField alphaCells
    (
        alpha.boundaryField()[patch().index()].patchInternalField()
    );

    boolList holdsBulk(alphaCells.size());
    forAll(alphaCells, facei)
    {
        holdsBulk[facei] = alphaCells[facei] > alphaMin_;
    }
    return holdsBulk;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
prghBulkRetainingTotalPressureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(p, iF),
    p0_(p.size(), Zero),
    alphaName_("alpha.granular"),
    rhoName_("rho"),
    phiName_("phi"),
    UName_("U"),
    alphaMin_(1e-6),
    totalPressureFrozen_(false)
{
    refValue() = Zero;
    refGrad() = Zero;
    valueFraction() = 1;
}


Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
prghBulkRetainingTotalPressureFvPatchScalarField
(
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const dictionary& dict
)
:
    mixedFvPatchScalarField(p, iF),
    p0_("p0", dict, p.size()),
    alphaName_(dict.getOrDefault<word>("alpha", "alpha.granular")),
    rhoName_(dict.getOrDefault<word>("rho", "rho")),
    phiName_(dict.getOrDefault<word>("phi", "phi")),
    UName_(dict.getOrDefault<word>("U", "U")),
    alphaMin_(dict.getOrDefault<scalar>("alphaMin", 1e-6)),
    totalPressureFrozen_(false)
{
    // 0 would close faces over cells holding round-off bulk (MULES leaves
    // 1e-20 in the air): the air there could not leave and the planar bin
    // from the brim diverged
    if (!(alphaMin_ > 0 && alphaMin_ < 1))
    {
        FatalIOErrorInFunction(dict)
            << "'alphaMin " << alphaMin_ << "' on patch " << p.name()
            << " of " << iF.name() << " must lie in (0, 1): the bulk"
            << " fraction above which a cell's outflow face is closed"
            << " (default 1e-6)" << nl << exit(FatalIOError);
    }

    // Open, at the written value (a restart: the total pressure, as
    // prghTotalPressure's value, which the first momentum predictor's
    // snGrad(p_rgh) takes); the state is decided at the first pressure
    // corrector
    refValue() =
        dict.found("value") ? scalarField("value", dict, p.size()) : p0_;
    refGrad() = Zero;
    valueFraction() = 1;
    fvPatchScalarField::operator=(refValue());
}


Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
prghBulkRetainingTotalPressureFvPatchScalarField
(
    const prghBulkRetainingTotalPressureFvPatchScalarField& ptf,
    const fvPatch& p,
    const DimensionedField<scalar, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    mixedFvPatchScalarField(ptf, p, iF, mapper),
    p0_(ptf.p0_, mapper),
    alphaName_(ptf.alphaName_),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    alphaMin_(ptf.alphaMin_),
    totalPressureFrozen_(false)
{}


Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
prghBulkRetainingTotalPressureFvPatchScalarField
(
    const prghBulkRetainingTotalPressureFvPatchScalarField& ptf
)
:
    mixedFvPatchScalarField(ptf),
    p0_(ptf.p0_),
    alphaName_(ptf.alphaName_),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    alphaMin_(ptf.alphaMin_),
    totalPressureFrozen_(false)
{}


Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
prghBulkRetainingTotalPressureFvPatchScalarField
(
    const prghBulkRetainingTotalPressureFvPatchScalarField& ptf,
    const DimensionedField<scalar, volMesh>& iF
)
:
    mixedFvPatchScalarField(ptf, iF),
    p0_(ptf.p0_),
    alphaName_(ptf.alphaName_),
    rhoName_(ptf.rhoName_),
    phiName_(ptf.phiName_),
    UName_(ptf.UName_),
    alphaMin_(ptf.alphaMin_),
    totalPressureFrozen_(false)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::prghBulkRetainingTotalPressureFvPatchScalarField::retainBulk
(
    const scalarField& phiHbyAp,
    const scalarField& rAUfp
)
{
    const boolList holdsBulk(cellsHoldBulk());
    const scalarField pCells(patchInternalField());
    const scalarField pTotal(totalPressure());
    const scalarField& magSf = patch().magSf();
    const scalarField& deltaCoeffs = patch().deltaCoeffs();

    scalarField& open = valueFraction();
    label nClosed = 0;
    forAll(open, facei)
    {
        // The flux the face would carry at the total pressure; leaving
        // (> 0) from a cell that holds bulk, the face is a wall
        const scalar phiOpen =
            phiHbyAp[facei]
          - rAUfp[facei]*magSf[facei]*deltaCoeffs[facei]
           *(pTotal[facei] - pCells[facei]);
        const bool closed = holdsBulk[facei] && phiOpen > 0;
        open[facei] = closed ? 0 : 1;
        nClosed += closed;
    }

    // The total pressure stays that of this decision until
    // releaseTotalPressure: the re-solves must answer the question the
    // switches asked
    refValue() = pTotal;
    totalPressureFrozen_ = true;

    // Closed: the gradient that makes phiHbyA - rAUf |Sf| snGrad(p_rgh)
    // zero (fixedFluxPressure's on a wall at rest)
    refGrad() = phiHbyAp/(magSf*max(rAUfp, VSMALL));

    mixedFvPatchScalarField::updateCoeffs();

    return returnReduce(nClosed, sumOp<label>());
}


Foam::label Foam::prghBulkRetainingTotalPressureFvPatchScalarField::switchFaces
(
    const scalarField& phip,
    const bool apply
)
{
    const boolList holdsBulk(cellsHoldBulk());
    // A closed face's pressure from the cell's and the closing gradient
    // (called on the solved pressure, before its relaxation): above the
    // total pressure, opening the face would let the flux out
    const scalarField pClosed
    (
        patchInternalField() + refGrad()/patch().deltaCoeffs()
    );

    scalarField& open = valueFraction();
    label nSwitched = 0;
    forAll(open, facei)
    {
        const bool isOpen = open[facei] > 0.5;
        const bool switches =
            isOpen
          ? phip[facei] > 0 && holdsBulk[facei]
          : pClosed[facei] < refValue()[facei];
        if (switches)
        {
            ++nSwitched;
            if (apply)
            {
                open[facei] = isOpen ? 0 : 1;
            }
        }
    }

    return returnReduce(nSwitched, sumOp<label>());
}


void Foam::prghBulkRetainingTotalPressureFvPatchScalarField::
releaseTotalPressure(scalarField& phip)
{
    totalPressureFrozen_ = false;

    // The closed faces' flux is phiHbyA less its own round-off: exactly
    // zero, so that nothing downstream reads in- or outflow from its sign
    const scalarField& open = valueFraction();
    forAll(open, facei)
    {
        if (open[facei] < 0.5)
        {
            phip[facei] = 0;
        }
    }
}


void Foam::prghBulkRetainingTotalPressureFvPatchScalarField::autoMap
(
    const fvPatchFieldMapper& m
)
{
    mixedFvPatchScalarField::autoMap(m);
    p0_.autoMap(m);
}


void Foam::prghBulkRetainingTotalPressureFvPatchScalarField::rmap
(
    const fvPatchScalarField& ptf,
    const labelList& addr
)
{
    mixedFvPatchScalarField::rmap(ptf, addr);
    p0_.rmap
    (
        refCast<const prghBulkRetainingTotalPressureFvPatchScalarField>
        (
            ptf
        ).p0_,
        addr
    );
}


void Foam::prghBulkRetainingTotalPressureFvPatchScalarField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    if (!totalPressureFrozen_)
    {
        refValue() = totalPressure();
    }

    mixedFvPatchScalarField::updateCoeffs();
}


void Foam::prghBulkRetainingTotalPressureFvPatchScalarField::write
(
    Ostream& os
) const
{
    fvPatchScalarField::write(os);
    p0_.writeEntry("p0", os);
    os.writeEntryIfDifferent<word>("alpha", "alpha.granular", alphaName_);
    os.writeEntryIfDifferent<word>("rho", "rho", rhoName_);
    os.writeEntryIfDifferent<word>("phi", "phi", phiName_);
    os.writeEntryIfDifferent<word>("U", "U", UName_);
    os.writeEntryIfDifferent<scalar>("alphaMin", 1e-6, alphaMin_);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchScalarField,
        prghBulkRetainingTotalPressureFvPatchScalarField
    );
}

// ************************************************************************* //

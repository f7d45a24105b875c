/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "coulombWallFrictionFvPatchVectorField.H"
#include "addToRunTimeSelectionTable.H"
#include "volFields.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coulombWallFrictionFvPatchVectorField::
coulombWallFrictionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF
)
:
    partialSlipFvPatchVectorField(p, iF),
    wallFrictionAngle_(0),
    stickVelocity_(1e-6),
    pName_("p"),
    muEffName_("muEff")
{
    // The wall is at rest: partialSlip's (patch, field) constructor leaves
    // refValue unset
    refValue() = Zero;
}


Foam::coulombWallFrictionFvPatchVectorField::
coulombWallFrictionFvPatchVectorField
(
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const dictionary& dict
)
:
    partialSlipFvPatchVectorField(p, iF),
    wallFrictionAngle_(dict.get<scalar>("wallFrictionAngle")),
    stickVelocity_(dict.getOrDefault<scalar>("stickVelocity", 1e-6)),
    pName_(dict.getOrDefault<word>("p", "p")),
    muEffName_(dict.getOrDefault<word>("muEff", "muEff"))
{
    if (!(wallFrictionAngle_ >= 0 && wallFrictionAngle_ < 90))
    {
        FatalIOErrorInFunction(dict)
            << "'wallFrictionAngle " << wallFrictionAngle_ << "' on patch "
            << p.name() << " of " << iF.name() << " must lie in [0, 90)"
            << " degrees" << nl << exit(FatalIOError);
    }
    if (!(stickVelocity_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "'stickVelocity " << stickVelocity_ << "' on patch "
            << p.name() << " of " << iF.name() << " must be > 0 [m/s]"
            << nl << exit(FatalIOError);
    }

    // The wall is at rest; it sticks until the pressure and viscosity exist,
    // or slides as it did when the field was written (a restart)
    refValue() = Zero;
    valueFraction() =
        dict.found("valueFraction")
      ? scalarField("valueFraction", dict, p.size())
      : scalarField(p.size(), 1.0);
    evaluate();
}


Foam::coulombWallFrictionFvPatchVectorField::
coulombWallFrictionFvPatchVectorField
(
    const coulombWallFrictionFvPatchVectorField& ptf,
    const fvPatch& p,
    const DimensionedField<vector, volMesh>& iF,
    const fvPatchFieldMapper& mapper
)
:
    partialSlipFvPatchVectorField(ptf, p, iF, mapper),
    wallFrictionAngle_(ptf.wallFrictionAngle_),
    stickVelocity_(ptf.stickVelocity_),
    pName_(ptf.pName_),
    muEffName_(ptf.muEffName_)
{}


Foam::coulombWallFrictionFvPatchVectorField::
coulombWallFrictionFvPatchVectorField
(
    const coulombWallFrictionFvPatchVectorField& ptf
)
:
    partialSlipFvPatchVectorField(ptf),
    wallFrictionAngle_(ptf.wallFrictionAngle_),
    stickVelocity_(ptf.stickVelocity_),
    pName_(ptf.pName_),
    muEffName_(ptf.muEffName_)
{}


Foam::coulombWallFrictionFvPatchVectorField::
coulombWallFrictionFvPatchVectorField
(
    const coulombWallFrictionFvPatchVectorField& ptf,
    const DimensionedField<vector, volMesh>& iF
)
:
    partialSlipFvPatchVectorField(ptf, iF),
    wallFrictionAngle_(ptf.wallFrictionAngle_),
    stickVelocity_(ptf.stickVelocity_),
    pName_(ptf.pName_),
    muEffName_(ptf.muEffName_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar
Foam::coulombWallFrictionFvPatchVectorField::frictionCoefficient() const
{
    return std::tan(wallFrictionAngle_*constant::mathematical::pi/180);
}


void Foam::coulombWallFrictionFvPatchVectorField::updateCoeffs()
{
    if (updated())
    {
        return;
    }

    const objectRegistry& db = this->db();
    const bool fieldsFound =
        db.foundObject<volScalarField>(pName_)
     && db.foundObject<volScalarField>(muEffName_);
    if
    (
        !fieldsFound
     && db.time().timeIndex() > db.time().startTimeIndex()
    )
    {
        // Before the first step the bulk model may not have made them yet;
        // later their absence is another bulk model or a misspelt name
        FatalErrorInFunction
            << "coulombWallFriction on patch " << patch().name() << " of "
            << internalField().name() << " needs the fields '" << pName_
            << "' and '" << muEffName_ << "' (bulkFlow muI provides p and"
            << " muEff); found: " << db.sortedNames<volScalarField>()
            << exit(FatalError);
    }
    if (fieldsFound)
    {
        const scalarField& pw =
            patch().lookupPatchField<volScalarField, scalar>(pName_);
        const scalarField& muEffw =
            patch().lookupPatchField<volScalarField, scalar>(muEffName_);

        const vectorField nHat(patch().nf());
        const vectorField Uc(patchInternalField());
        const scalarField magUt(mag(Uc - nHat*(nHat & Uc)));
        const scalarField& deltaCoeffs = patch().deltaCoeffs();
        const scalar muW = frictionCoefficient();

        scalarField& f = valueFraction();
        forAll(f, facei)
        {
            // The no-slip stress resistance muEff deltaCoeffs against the
            // Coulomb limit muW p per unit slip velocity
            const scalar noSlip =
                max(muEffw[facei], VSMALL)*deltaCoeffs[facei]
               *(magUt[facei] + stickVelocity_);
            f[facei] = min(muW*max(pw[facei], scalar(0))/noSlip, scalar(1));
        }
    }

    partialSlipFvPatchVectorField::updateCoeffs();
}


void Foam::coulombWallFrictionFvPatchVectorField::write(Ostream& os) const
{
    fvPatchVectorField::write(os);
    os.writeEntry("wallFrictionAngle", wallFrictionAngle_);
    os.writeEntry("stickVelocity", stickVelocity_);
    os.writeEntryIfDifferent<word>("p", "p", pName_);
    os.writeEntryIfDifferent<word>("muEff", "muEff", muEffName_);
    valueFraction().writeEntry("valueFraction", os);
    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePatchTypeField
    (
        fvPatchVectorField,
        coulombWallFrictionFvPatchVectorField
    );
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "prghTotalPressureValue.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "gravityMeshObject.H"
#include "uniformDimensionedFields.H"

Foam::tmp<Foam::scalarField> Foam::prghTotalPressureValue
(
    const fvPatchScalarField& pf,
    const scalarField& p0,
    const word& rhoName,
    const word& phiName,
    const word& UName
)
{
    const objectRegistry& db = pf.db();
    const uniformDimensionedVectorField& g =
        meshObjects::gravity::New(db.time());
    const scalar hRef =
        db.foundObject<uniformDimensionedScalarField>("hRef")
      ? db.lookupObject<uniformDimensionedScalarField>("hRef").value()
      : 0;
    const scalar magG = mag(g.value());
    const scalar ghRef =
        magG > SMALL ? (g.value() & (cmptMag(g.value())/magG))*hRef : 0;

    if
    (
        !db.foundObject<volScalarField>(rhoName)
     || !db.foundObject<surfaceScalarField>(phiName)
     || !db.foundObject<volVectorField>(UName)
    )
    {
        return tmp<scalarField>::New(p0);
    }

    const fvPatch& patch = pf.patch();
    const scalarField& rhop =
        patch.lookupPatchField<volScalarField, scalar>(rhoName);
    const scalarField& phip =
        patch.lookupPatchField<surfaceScalarField, scalar>(phiName);
    const vectorField& Up =
        patch.lookupPatchField<volVectorField, vector>(UName);

    return
        p0
      - 0.5*rhop*(1.0 - pos0(phip))*magSqr(Up)
      - rhop*((g.value() & patch.Cf()) - ghRef);
}

// ************************************************************************* //

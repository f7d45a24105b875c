/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "bulkFlowModel.H"
#include "modelCoeffs.H"
#include "fvc.H"
#include "wallFvPatch.H"
#include "calculatedFvPatchFields.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "scratchField.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(bulkFlowModel, 0);
    defineRunTimeSelectionTable(bulkFlowModel, dictionary);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkFlowModel::bulkFlowModel
(
    const word& type,
    const dictionary& dict,
    const granularMixture& mixture,
    const bool readU
)
:
    mixture_(mixture),
    coeffs_(modelCoeffs::coeffsDict(dict, type)),
    U_
    (
        IOobject
        (
            "U",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        readU
      ? tmp<volVectorField>
        (
            new volVectorField
            (
                IOobject
                (
                    "U",
                    mixture.mesh().time().timeName(),
                    mixture.mesh(),
                    IOobject::MUST_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                mixture.mesh()
            )
        )
      : volVectorField::New
        (
            "U",
            mixture.mesh(),
            dimensionedVector("v", dimVelocity, Zero),
            calculatedFvPatchVectorField::typeName
        )
    ),
    phi_
    (
        // Written with the results: post-processing (outletComposition
        // with -postProcess) needs the solver's flux, not one rebuilt
        IOobject
        (
            "phi",
            mixture.mesh().time().timeName(),
            mixture.mesh(),
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mixture.mesh(),
        dimensionedScalar("s", dimVolume/dimTime, Zero)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bulkFlowModel::noFluxThroughWalls(surfaceScalarField& flux)
{
    const fvMesh& mesh = flux.mesh();
    forAll(mesh.boundary(), patchi)
    {
        if (isA<wallFvPatch>(mesh.boundary()[patchi]))
        {
            flux.boundaryFieldRef()[patchi] = Zero;
        }
    }
}


void Foam::bulkFlowModel::updateFluxFromU()
{
    phi_ = fvc::flux(U_);
    noFluxThroughWalls(phi_);
}


Foam::tmp<Foam::volScalarField> Foam::bulkFlowModel::gammaDot() const
{
    return sqrt(2.0)*mag(symm(fvc::grad(U_)));
}


Foam::tmp<Foam::volScalarField> Foam::bulkFlowModel::pressure() const
{
    const fvMesh& mesh = mixture_.mesh();
    const vector g = mixture_.gravity();
    const vector up = -g/mag(g);
    // the material's top: the highest point of the cells holding material
    // (phi >= phiMin), so that a silo's descending free surface is followed
    const scalarField& phi = mixture_.nTotal().primitiveField();
    const pointField& points = mesh.points();
    scalar hTop = -GREAT;
    forAll(phi, celli)
    {
        if (phi[celli] < mixture_.phiMin()) continue;
        for (const label pointi : mesh.cellPoints()[celli])
        {
            hTop = max(hTop, points[pointi] & up);
        }
    }
    hTop = returnReduce(hTop, maxOp<scalar>());
    tmp<volScalarField> tp
    (
        scratchField
        (
            mesh,
            "bulkFlowModel:p",
            dimPressure,
            wordList
            (
                mesh.boundary().size(),
                extrapolatedCalculatedFvPatchScalarField::typeName
            )
        )
    );
    volScalarField& p = tp.ref();
    const scalarField h(mesh.C().primitiveField() & up);
    p.primitiveFieldRef() =
        mixture_.nTotal().primitiveField()*mixture_.solidsDensity()().primitiveField()
       *mag(g)*max(hTop - h, scalar(0));
    p.correctBoundaryConditions();
    return tp;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "particlePassFlow.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"
#include "wallFvPatch.H"

namespace Foam
{
namespace bulkFlowModels
{
    defineTypeNameAndDebug(particlePass, 0);
    addToRunTimeSelectionTable(bulkFlowModel, particlePass, dictionary);
}
}


Foam::bulkFlowModels::particlePass::particlePass
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    bulkFlowModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, {}),
        mixture,
        false
    ),
    speciesPhi_(mixture.size())
{
    const fvMesh& mesh = mixture.mesh();

    auto passHeader = [&mesh](const word& name)
    {
        IOobject io
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!io.typeHeaderOk<volScalarField>(false))
        {
            FatalErrorInFunction
                << "bulkFlow particlePass: no file " << io.objectPath()
                << nl << "    Run the particle pass (cloud function object"
                << " particlePass of libsegregationDegradationLagrangian)"
                << " and copy its alphaPass.*, UPass.* and phiPass.* to the"
                << " start time (tutorials/pipeBend/Allrun)"
                << exit(FatalError);
        }
        return io;
    };

    volScalarField alphaSum
    (
        IOobject("alphaPassSum", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    volVectorField alphaU
    (
        IOobject("alphaUPass", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    forAll(mixture.names(), i)
    {
        const word& name = mixture.names()[i];
        const volScalarField alpha(passHeader("alphaPass." + name), mesh);
        const volVectorField Ui(passHeader("UPass." + name), mesh);
        alphaSum += alpha;
        alphaU += alpha*Ui;

        speciesPhi_.set
        (
            i,
            new surfaceScalarField
            (
                IOobject
                (
                    "phi." + name,
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                surfaceScalarField(passHeader("phiPass." + name), mesh)
            )
        );

        // Nothing crosses a wall
        forAll(mesh.boundary(), patchi)
        {
            if (isA<wallFvPatch>(mesh.boundary()[patchi]))
            {
                speciesPhi_[i].boundaryFieldRef()[patchi] = Zero;
            }
        }
    }

    forAll(U_, celli)
    {
        if (alphaSum[celli] > 0)
        {
            U_[celli] = alphaU[celli]/alphaSum[celli];
        }
    }
    U_.correctBoundaryConditions();
    updateFluxFromU();

    Info<< "Bulk flow: particle pass, one face flux per species"
        << " (phi.<species>) from " << mesh.time().timeName() << nl << endl;
}


// ************************************************************************* //

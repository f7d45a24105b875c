/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    kineticSievingTests.C

Description
    Unit tests of the plain kinetic-sieving models: the velocityGradient
    drift on the prescribed shear.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "kineticSievingModel.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(kineticSieving, velocityGradientDrift)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    autoPtr<kineticSievingModel> sieving
    (
        kineticSievingModel::New
        (
            dictOf
            (
                "model velocityGradient;"
                "velocityGradientCoeffs { eta 1e-3; Umin 1e-9; }"
            ),
            *testMixturePtr,
            flow()
        )
    );
    const surfaceScalarField W(sieving->driftFlux(0, 1));

    // U = (2 z, 0, 0): ln|U| = ln(2 z); the fine drifts down the gradient
    const labelUList& own = testMeshPtr->owner();
    const labelUList& nei = testMeshPtr->neighbour();
    const volVectorField& C = testMeshPtr->C();
    const surfaceScalarField& magSf = testMeshPtr->magSf();
    const scalarField& deltaCoeffs = testMeshPtr->deltaCoeffs();
    forAll(W, facei)
    {
        const scalar lnP = Foam::log(gammaDot0*C[own[facei]].z());
        const scalar lnN = Foam::log(gammaDot0*C[nei[facei]].z());
        const scalar expected =
            -1e-3*(lnN - lnP)*deltaCoeffs[facei]*magSf[facei];
        EXPECT_NEAR(W[facei], expected, 1e-14);
    }
}

// ************************************************************************* //

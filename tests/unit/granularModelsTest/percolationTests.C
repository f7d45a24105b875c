/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    percolationTests.C

Description
    Unit tests of the percolation models: Gray-Thornton drift along
    gravity.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "percolationModel.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(percolation, grayThorntonDriftAlongGravity)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    autoPtr<percolationModel> perc
    (
        percolationModel::New
        (
            dictOf("model grayThornton; grayThorntonCoeffs { Sr 0.3; }"),
            *testMixturePtr,
            flow()
        )
    );
    EXPECT_TRUE(perc->active());
    const surfaceScalarField W(perc->driftFlux(0, 1));
    const surfaceVectorField& Sf = testMeshPtr->Sf();
    forAll(W, facei)
    {
        // Sr (g/|g|).Sf with g = (0 0 -1)|g|
        EXPECT_NEAR(W[facei], -0.3*Sf[facei].z(), 1e-15);
    }
    // Walls: no flux
    forAll(W.boundaryField(), patchi)
    {
        EXPECT_EQ(gMax(mag(W.boundaryField()[patchi])), 0);
    }
}

// ************************************************************************* //

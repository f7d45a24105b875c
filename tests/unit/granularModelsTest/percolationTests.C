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
    gravity; the shear-rate drift S gammaDot (g/|g|).Sf of Schlick et al.

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

// The shear-rate percolation on the prescribed shear U = (gammaDot0 z, 0, 0):
// S gammaDot0 (g/|g|).Sf on interior faces, S = C_s d_s ln(d_l/d_s), zero on
// walls; a negative C_s refused
TEST(percolation, shearRateDriftAlongGravity)
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
            dictOf("model shearRate; shearRateCoeffs { C_s 0.26; }"),
            *testMixturePtr,
            flow()
        )
    );
    EXPECT_TRUE(perc->active());
    perc->correct();
    const surfaceScalarField W(perc->driftFlux(0, 1));
    const surfaceVectorField& Sf = testMeshPtr->Sf();
    const scalar S = 0.26*1e-3*Foam::log(2.0);
    label nFaces = 0;
    forAll(W, facei)
    {
        EXPECT_NEAR(W[facei], -S*gammaDot0*Sf[facei].z(), 1e-12*S*gammaDot0*mag(Sf[facei]));
        if (mag(Sf[facei].z()) > 0) ++nFaces;
    }
    EXPECT_GT(nFaces, 0);
    forAll(W.boundaryField(), patchi)
    {
        EXPECT_EQ(gMax(mag(W.boundaryField()[patchi])), 0);
    }

    expectFoamError
    (
        [&]
        {
            percolationModel::New
            (
                dictOf("model shearRate; shearRateCoeffs { C_s -1; }"),
                *testMixturePtr,
                flow()
            );
        },
        {"C_s -1", ">= 0"}
    );
}

// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    segregationFluxTests.C

Description
    Unit tests of the segregation flux: conservation and bounds of the
    exchange fluxes on the closed box, far beyond the Courant limit.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "percolationModel.H"
#include "kineticSievingModel.H"
#include "segregationFlux.H"
#include "Random.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(segregationFlux, conservesAndBoundsOnClosedBox)
{
    granularMixture& mix = *testMixturePtr;

    // Random, partly empty composition
    Random rnd(1234);
    forAll(mix.n()[0], celli)
    {
        const scalar phi = (celli % 7 == 0) ? 0 : 0.6*rnd.sample01<scalar>();
        const scalar c = rnd.sample01<scalar>();
        mix.n()[0][celli] = phi*c;
        mix.n()[1][celli] = phi*(1 - c);
    }
    mix.n()[0].correctBoundaryConditions();
    mix.n()[1].correctBoundaryConditions();
    mix.correct();

    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), mix)
    );
    autoPtr<percolationModel> perc
    (
        percolationModel::New
        (
            dictOf("model grayThornton; grayThorntonCoeffs { Sr 2; }"),
            mix,
            flow()
        )
    );
    autoPtr<kineticSievingModel> sieving
    (
        kineticSievingModel::New
        (
            dictOf("model velocityGradient; velocityGradientCoeffs { eta 0.1; }"),
            mix,
            flow()
        )
    );
    UPtrList<pairwiseDrift> models(2);
    models.set(0, perc.get());
    models.set(1, sieving.get());
    segregationFlux seg(mix, models);
    ASSERT_TRUE(seg.active());
    seg.correctDrift();

    const scalarField& V = testMeshPtr->V();
    const scalar total0 = gSum(mix.n()[0].primitiveField()*V);
    const scalar total1 = gSum(mix.n()[1].primitiveField()*V);
    const scalarField phi0(mix.nTotal().primitiveField());

    // A time step far beyond the Courant limit: the limiter must hold
    const scalar dt = 10/seg.courantNumber(1);
    seg.correctFluxes(dt);

    for (label k = 0; k < 2; ++k)
    {
        volScalarField& n = mix.n()[k];
        n.primitiveFieldRef() -=
            dt*fvc::surfaceIntegrate(seg.flux(k))().primitiveField();
    }
    mix.correct();

    const scalar total0New = gSum(mix.n()[0].primitiveField()*V);
    const scalar total1New = gSum(mix.n()[1].primitiveField()*V);
    EXPECT_NEAR(total0New, total0, 1e-10*total0);
    EXPECT_NEAR(total1New, total1, 1e-10*total1);
    EXPECT_GT(mag(total0New - total0) + gSum(mag(seg.flux(0).primitiveField())), 0);

    forAll(phi0, celli)
    {
        // Exchange fluxes leave the total solids fraction of a cell alone
        EXPECT_NEAR(mix.nTotal()[celli], phi0[celli], 1e-12);
        EXPECT_GE(mix.n()[0][celli], -1e-14);
        EXPECT_GE(mix.n()[1][celli], -1e-14);
    }
}

// ************************************************************************* //

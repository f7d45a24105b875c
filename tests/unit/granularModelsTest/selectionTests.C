/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    selectionTests.C

Description
    Unit tests of the run-time selection of every model family: none
    models add nothing, an unknown model lists the valid names, a missing
    coefficient names the entry.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "diffusivityModel.H"
#include "kineticSievingModel.H"
#include "percolationModel.H"
#include "breakageModel.H"
#include "segregationFlux.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(selection, noneModelsAddNothing)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    EXPECT_FALSE
    (
        percolationModel::New(dictOf("model none;"), *testMixturePtr, flow())
       ->active()
    );
    EXPECT_FALSE
    (
        kineticSievingModel::New(dictOf("model none;"), *testMixturePtr, flow())
       ->active()
    );
    EXPECT_FALSE
    (
        breakageModel::New(dictOf("model none;"), *testMixturePtr)->active()
    );

    // With every mechanism `none` the segregation flux is inactive
    autoPtr<percolationModel> perc
    (
        percolationModel::New(dictOf("model none;"), *testMixturePtr, flow())
    );
    UPtrList<pairwiseDrift> models(1);
    models.set(0, perc.get());
    segregationFlux seg(*testMixturePtr, models);
    EXPECT_FALSE(seg.active());
    EXPECT_EQ(seg.courantNumber(1), 0);

    // granularTemperature none: T stays zero
    autoPtr<granularTemperatureModel> temp
    (
        granularTemperatureModel::New(dictOf("model none;"), *testMixturePtr)
    );
    temp->correct(flow());
    EXPECT_EQ(gMax(mag(temp->T().primitiveField())), 0);
}


// * * * * * * * * * * * * * * Selection errors * * * * * * * * * * * * * * //

TEST(selection, unknownModelListsValidNames)
{
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model fancy;"), *testMixturePtr); },
        {"fancy", "constant", "kineticTheory", "none", "powerLaw"}
    );
    expectFoamError
    (
        []{ bulkFlowModel::New(dictOf("model nope;"), *testMixturePtr); },
        {"nope", "kinematic", "prescribed"}
    );
    expectFoamError
    (
        []{ granularTemperatureModel::New(dictOf("model x;"), *testMixturePtr); },
        {"savageJeffrey", "none"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model x;"), *testMixturePtr); },
        {"none"}
    );
}


TEST(selection, missingCoefficientNamesTheEntry)
{
    expectFoamError
    (
        []
        {
            granularTemperatureModel::New
            (
                dictOf("model savageJeffrey; savageJeffreyCoeffs { }"),
                *testMixturePtr
            );
        },
        {"'R'"}
    );
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model kineticTheory; kineticTheoryCoeffs { e 1.5; }"),
                *testMixturePtr
            );
        },
        {"e 1.5"}
    );
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("diffusion powerLaw;"), *testMixturePtr); },
        {"'model'"}
    );
}

// ************************************************************************* //

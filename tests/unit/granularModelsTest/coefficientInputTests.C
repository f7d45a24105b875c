/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    coefficientInputTests.C

Description
    Unit tests of the reading of model coefficients (modelCoeffs) and of
    the species (granularMixture::readSpecies): a misspelt key is refused
    naming it and the valid keys, in <model>Coeffs and in a mechanism
    dictionary without one; a coefficient given with dimensions must have
    the right ones; the species come in the order written, validated.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "diffusivityModel.H"
#include "kineticSievingModel.H"
#include "percolationModel.H"
#include "modelCoeffs.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * Unknown keys  * * * * * * * * * * * * * * * //

TEST(coefficients, misspeltKeyNamesTheValidKeys)
{
    // In <model>Coeffs
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model powerLaw; powerLawCoeffs { A 6; mm 1; }"),
                *testMixturePtr
            );
        },
        {"'mm'", "powerLawCoeffs", "A a m b"}
    );
    expectFoamError
    (
        []
        {
            granularTemperatureModel::New
            (
                dictOf("model savageJeffrey; savageJeffreyCoeffs { R 1; r 1; }"),
                *testMixturePtr
            );
        },
        {"'r'", "R"}
    );

    // Before a required coefficient is missed: the misspelling is named
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    expectFoamError
    (
        [&flow]
        {
            percolationModel::New
            (
                dictOf("model grayThornton; grayThorntonCoeffs { sr 0.3; }"),
                *testMixturePtr,
                flow()
            );
        },
        {"'sr'", "Sr"}
    );

    // Without <model>Coeffs the mechanism dictionary holds the
    // coefficients, beside `model` and other models' blocks
    autoPtr<diffusivityModel> Dinline
    (
        diffusivityModel::New
        (
            dictOf("model constant; D 2.5e-6; powerLawCoeffs { A 6; }"),
            *testMixturePtr
        )
    );
    setFields(0.48, 0.12);
    EXPECT_NEAR(Dinline->Dmixture(uniformT(1))()[0], 2.5e-6, 1e-20);
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model constant; D 2.5e-6; Dmax 1;"),
                *testMixturePtr
            );
        },
        {"'Dmax'", "D"}
    );

    // `none` reads nothing: a coefficient given to it is refused
    expectFoamError
    (
        [&flow]
        {
            kineticSievingModel::New
            (
                dictOf("model none; eta 1e-4;"),
                *testMixturePtr,
                flow()
            );
        },
        {"'eta'"}
    );
}


// * * * * * * * * * * * * * * * * Dimensions  * * * * * * * * * * * * * * * //

TEST(coefficients, dimensionsMustMatch)
{
    setFields(0.48, 0.12);
    const volScalarField T(uniformT(1));

    // A bare number is in SI units; the right dimensions are accepted
    for (const char* D : {"2.5e-6", "[0 2 -1 0 0 0 0] 2.5e-6", "D [0 2 -1 0 0 0 0] 2.5e-6"})
    {
        autoPtr<diffusivityModel> Dc
        (
            diffusivityModel::New
            (
                dictOf
                (
                    (
                        std::string("model constant; constantCoeffs { D ")
                      + D + "; }"
                    ).c_str()
                ),
                *testMixturePtr
            )
        );
        EXPECT_NEAR(Dc->Dmixture(T)()[0], 2.5e-6, 1e-20) << D;
    }

    // Wrong dimensions: refused naming the entry and the expected ones
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model constant; constantCoeffs { D [0 2 0 0 0 0 0] 1e-3; }"),
                *testMixturePtr
            );
        },
        {"'D'", "constantCoeffs", "[0 2 0 0 0 0 0]", "[0 2 -1 0 0 0 0]"}
    );

    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    expectFoamError
    (
        [&flow]
        {
            kineticSievingModel::New
            (
                dictOf
                (
                    "model velocityGradient;"
                    " velocityGradientCoeffs { eta 1e-4; Umin [0 1 0 0 0 0 0] 1e-6; }"
                ),
                *testMixturePtr,
                flow()
            );
        },
        {"'Umin'", "[0 1 -1 0 0 0 0]"}
    );

    // powerLaw's A carries [m2/s]/[m2/s2]^m: seconds for m = 1
    autoPtr<diffusivityModel> Dp
    (
        diffusivityModel::New
        (
            dictOf("model powerLaw; powerLawCoeffs { A [0 0 1 0 0 0 0] 6; }"),
            *testMixturePtr
        )
    );
    const volScalarField T01(uniformT(0.01));
    const scalar expected = 6*1.2*0.01*Foam::pow(0.6, -1.5);
    EXPECT_NEAR(Dp->Dmixture(T01)()[0], expected, 1e-12*expected);
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model powerLaw; powerLawCoeffs { A [0 2 -1 0 0 0 0] 6; }"),
                *testMixturePtr
            );
        },
        {"'A'", "[0 0 1 0 0 0 0]"}
    );
}


// * * * * * * * * * * * * * * * * * Species * * * * * * * * * * * * * * * * //

TEST(coefficients, speciesReadInOrderAndChecked)
{
    const List<granularSpecies> species
    (
        granularMixture::readSpecies
        (
            dictOf
            (
                "species { large { d 2e-3; rho 2600; }"
                " small { d 1e-3; rho 2500; } }"
            )
        )
    );
    ASSERT_EQ(species.size(), 2);
    EXPECT_EQ(species[0].name, "large");
    EXPECT_EQ(species[0].d, 2e-3);
    EXPECT_EQ(species[0].rho, 2600);
    EXPECT_EQ(species[1].name, "small");
    EXPECT_EQ(species[1].d, 1e-3);

    // The mixture of the test case reads the same way
    EXPECT_EQ(testMixturePtr->names()[1], "coarse");
    EXPECT_EQ(testMixturePtr->d(1), 2e-3);

    const auto expectRefused =
        [](const char* text, std::initializer_list<std::string> fragments)
        {
            expectFoamError
            (
                [text]{ granularMixture::readSpecies(dictOf(text)); },
                fragments
            );
        };
    expectRefused("phiMin 0.05;", {"'species'"});
    expectRefused("species { }", {"no species"});
    expectRefused("species { fine 1; }", {"'fine'", "d and rho"});
    expectRefused("species { fine { d 1e-3; } }", {"'rho'"});
    expectRefused("species { fine { d 0; rho 2500; } }", {"Non-positive diameter", "fine"});
    expectRefused("species { fine { d 1e-3; rho -1; } }", {"Non-positive density", "fine"});
    expectRefused("species { fine { d 1e-3; rho 2500; D 1; } }", {"'D'", "d rho"});

    // d and rho may state their dimensions, which must then match
    const List<granularSpecies> dimensioned
    (
        granularMixture::readSpecies
        (
            dictOf("species { fine { d [0 1 0 0 0 0 0] 1e-3; rho [1 -3 0 0 0 0 0] 2500; } }")
        )
    );
    EXPECT_EQ(dimensioned[0].d, 1e-3);
    EXPECT_EQ(dimensioned[0].rho, 2500);
    expectRefused("species { fine { d [0 2 0 0 0 0 0] 1e-3; rho 2500; } }", {"'d'"});
}


// ************************************************************************* //

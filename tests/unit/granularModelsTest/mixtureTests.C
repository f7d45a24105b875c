/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    mixtureTests.C

Description
    Unit tests of granularMixture: composition, mean diameter, the
    regularisation of empty cells and the check of non-finite values.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include <cmath>
#include <limits>

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(granularMixture, compositionMeanDiameterAndRegularisation)
{
    const granularMixture& mix = *testMixturePtr;
    setFields(0.48, 0.12);

    ASSERT_EQ(mix.size(), 2);
    EXPECT_EQ(mix.names()[0], "fine");
    EXPECT_EQ(mix.coarsest(), 1);

    const volScalarField c0(mix.c(0));
    const volScalarField x(mix.coarseFraction());
    const volScalarField dMean(mix.dMean());
    forAll(c0, celli)
    {
        EXPECT_NEAR(mix.nTotal()[celli], 0.6, 1e-15);
        EXPECT_NEAR(c0[celli], 0.8, 1e-15);
        EXPECT_NEAR(x[celli], 0.2, 1e-15);
        // 0.8*1 mm + 0.2*2 mm
        EXPECT_NEAR(dMean[celli], 1.2e-3, 1e-18);
    }

    // An empty cell: composition 0, presence 0, laws see phiMin
    setFields(0, 0);
    const volScalarField cEmpty(mix.c(0));
    const volScalarField presence(mix.presence());
    const volScalarField phiReg(mix.phiRegularised());
    EXPECT_EQ(cEmpty[0], 0);
    EXPECT_EQ(presence[0], 0);
    EXPECT_NEAR(phiReg[0], 0.05, 1e-15);

    // Half of phiMin: presence 1/2
    setFields(0.02, 0.005);
    EXPECT_NEAR(mix.presence()()[0], 0.5, 1e-14);
}


TEST(granularMixture, nonFiniteValueStopsWithFieldAndCell)
{
    setFields(0.48, 0.12);
    testMixturePtr->n()[1][5] = std::numeric_limits<scalar>::quiet_NaN();
    expectFoamError
    (
        []{ testMixturePtr->checkFinite("in the test"); },
        {"n.coarse", "cell 5", "in the test"}
    );
    setFields(0.48, 0.12);
    EXPECT_NO_THROW(testMixturePtr->checkFinite("in the test"));
}

// ************************************************************************* //

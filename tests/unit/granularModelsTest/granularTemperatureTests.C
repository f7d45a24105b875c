/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    granularTemperatureTests.C

Description
    Unit tests of the granular temperature models: Savage-Jeffrey on
    simple shear.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(granularTemperature, savageJeffreyOnSimpleShear)
{
    setFields(0.48, 0.12);
    const shearWithTemperature shear(0.5);
    const autoPtr<granularTemperatureModel>& temp = shear.temp;

    // T = 3 (dMean gammaDot/R)^2 = 3 (1.2e-3*2/0.5)^2
    const scalar Texpected = 3*sqr(1.2e-3*gammaDot0/0.5);
    forAll(temp->T(), celli)
    {
        EXPECT_NEAR(temp->gammaDot()[celli], gammaDot0, 1e-12);
        EXPECT_NEAR(temp->T()[celli], Texpected, 1e-12*Texpected);
    }
}

// ************************************************************************* //

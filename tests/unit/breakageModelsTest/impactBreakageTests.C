/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    impactBreakageTests.C

Description
    The wall-impact kernel of Vogel & Peukert (impactBreakage): the
    probabilities of one normal impact of a 1 mm particle at 20, 25 and
    30 m/s with fMat = 0.9 kg/(J m), xWmMin = 0.12 J m/kg (0.069, 0.159,
    0.257), two impacts at W equal to one at 2W - Wmin, the three energy
    choices at a 25 degree impact, and the refusals of bad input.

\*---------------------------------------------------------------------------*/

#include "breakageTestFixtures.H"
#include "impactBreakage.H"
#include "breakageModel.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"

using namespace Foam;
using namespace unitTest;

TEST(impactBreakage, vogelPeukertNormalImpacts)
{
    const impactBreakage kernel
    (
        dictOf("fMat 0.9; xWmMin 0.12; impactEnergy normal;")
    );
    const scalar x = 1e-3;
    // P = 1 - exp(-0.9 (1e-3 v^2/2 - 0.12))
    EXPECT_NEAR(kernel.probability(x, 20, 0), 0.069, 1e-3);
    EXPECT_NEAR(kernel.probability(x, 25, 0), 0.159, 1e-3);
    EXPECT_NEAR(kernel.probability(x, 30, 0), 0.257, 1e-3);
    EXPECT_NEAR
    (
        kernel.probability(x, 25, 0),
        -std::expm1(-0.9*(1e-3*0.5*625 - 0.12)),
        1e-14
    );

    // Below the threshold W < Wmin = 120 J/kg (v < 15.49 m/s): nothing
    EXPECT_EQ(kernel.probability(x, 15, 0), 0);
    EXPECT_EQ(kernel.probability(x, 0, 0), 0);
    // The tangential part does not count with `normal`
    EXPECT_EQ(kernel.probability(x, 25, 40), kernel.probability(x, 25, 0));

    // Two impacts at W survive like one at 2W - Wmin
    const scalar Wmin = 0.12/x;
    for (const scalar v : {20.0, 25.0, 30.0})
    {
        const scalar W = 0.5*v*v;
        const scalar P1 = kernel.probability(x, v, 0);
        const scalar twoImpacts = 1 - sqr(1 - P1);
        const scalar vEquivalent = Foam::sqrt(2*(2*W - Wmin));
        EXPECT_NEAR(twoImpacts, kernel.probability(x, vEquivalent, 0), 1e-12)
            << "v = " << v;
    }
}


TEST(impactBreakage, energyChoices)
{
    const scalar x = 1e-3;
    const scalar speed = 30;
    const scalar alpha = degToRad(25.0);
    const scalar Un = speed*Foam::sin(alpha);
    const scalar Ut = speed*Foam::cos(alpha);

    const impactBreakage total(dictOf("fMat 0.9; xWmMin 0.12; impactEnergy total;"));
    const impactBreakage normal(dictOf("fMat 0.9; xWmMin 0.12; impactEnergy normal;"));
    const impactBreakage angle
    (
        dictOf("fMat 0.9; xWmMin 0.12; impactEnergy angleFunction; criticalAngle 50;")
    );

    EXPECT_NEAR(total.W(Un, Ut), 450, 1e-10);
    EXPECT_NEAR(normal.W(Un, Ut), 450*sqr(Foam::sin(alpha)), 1e-10);
    // Below the critical angle: the total energy times (sin a/sin 50)^2
    EXPECT_NEAR
    (
        angle.W(Un, Ut),
        450*sqr(Foam::sin(alpha)/Foam::sin(degToRad(50.0))),
        1e-10
    );
    // Flat from the critical angle to 90 degrees
    for (const scalar deg : {50.0, 60.0, 75.0, 90.0})
    {
        const scalar a = degToRad(deg);
        EXPECT_NEAR(angle.W(speed*Foam::sin(a), speed*Foam::cos(a)), 450, 1e-9)
            << deg << " degrees";
    }
    // Ordered as the energies: normal < angleFunction < total at 25 degrees
    EXPECT_LT(normal.probability(x, Un, Ut), angle.probability(x, Un, Ut));
    EXPECT_LT(angle.probability(x, Un, Ut), total.probability(x, Un, Ut));
}


TEST(impactBreakage, badInputNamesTheEntry)
{
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat -0.9; xWmMin 0.12; impactEnergy normal;")); },
        {"fMat -0.9", ">= 0"}
    );
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat 0.9; xWmMin -0.12; impactEnergy normal;")); },
        {"xWmMin -0.12", ">= 0"}
    );
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat 0.9; xWmMin 0.12; impactEnergy kinetic;")); },
        {"impactEnergy kinetic", "angleFunction", "normal", "total"}
    );
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat 0.9; xWmMin 0.12;")); },
        {"impactEnergy"}
    );
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat 0.9; xWmMin 0.12; impactEnergy angleFunction; criticalAngle 95;")); },
        {"criticalAngle 95", "(0, 90]"}
    );
    expectFoamError
    (
        []{ impactBreakage(dictOf("fMat 0.9; xWmMin 0.12; impactEnergy total; criticalAngle 40;")); },
        {"criticalAngle", "angleFunction"}
    );
}


// ************************************************************************* //


TEST(wallImpactBreakage, badInputNamesTheEntry)
{
    // The kernel's entries are checked before any file is read
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model wallImpact; wallImpactCoeffs { fMat -0.9; xWmMin 0.12; impactEnergy normal; }"), mix()); },
        {"fMat -0.9", ">= 0"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model wallImpact; wallImpactCoeffs { fMat 0.9; xWmMin 0.12; impactEnergy sideways; }"), mix()); },
        {"impactEnergy sideways", "angleFunction", "normal", "total"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model wallImpact; wallImpactCoeffs { fMat 0.9; xWmMin 0.12; impactEnergy normal; impactEnergyy total; }"), mix()); },
        {"impactEnergyy"}
    );
    // No particle pass: the missing impact list is named with the entry
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model wallImpact; wallImpactCoeffs { fMat 0.9; xWmMin 0.12; impactEnergy normal; impacts \"/nonexistent/pass\"; }"), mix()); },
        {"/nonexistent/pass/impacts.", "impacts"}
    );
}

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    breakageSelectionTests.C

Description
    Selection rates: constant and powerLaw values, the Vogel-Peukert rate
    of an exponential impact spectrum by hand and on the kinetic-theory
    state of the test case, and the refusals of bad input (negative rate
    or material parameter, unknown model or variable, missing entry), each
    naming the entry; breakageSource keeps solids plus dust in one implicit
    step, coarse to fine.

\*---------------------------------------------------------------------------*/

#include "breakageTestFixtures.H"
#include "breakageSource.H"
#include "vogelPeukert.H"
#include "mathematicalConstants.H"
#include "fvm.H"

using namespace Foam;
using namespace unitTest;

namespace
{

void setUniform(const scalar value)
{
    forAll(testMixturePtr->n(), i)
    {
        testMixturePtr->n()[i] == dimensionedScalar("n", dimless, value);
    }
    testMixturePtr->correct();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(breakageSelection, constantAndPowerLawRates)
{
    shearWithTemperature state(0.1);
    autoPtr<breakageModel> constant
    (
        breakageModel::New
        (
            dictOf("model constant; constantCoeffs { S { s4 0.5; s2 [0 0 -1 0 0 0 0] 0.25; } }"),
            mix()
        )
    );
    constant->correct(state.temp());
    EXPECT_EQ(constant->S(species("s4"))[0], 0.5);
    EXPECT_EQ(constant->S(species("s2"))[0], 0.25);
    EXPECT_EQ(constant->S(species("s0"))[0], 0);

    autoPtr<breakageModel> powerLaw
    (
        breakageModel::New
        (
            dictOf
            (
                "model powerLaw; powerLawCoeffs"
                "{ k 0.1; dRef 1e-3; a 3; variable gammaDot; XRef 4; b 2; }"
            ),
            mix()
        )
    );
    powerLaw->correct(state.temp());
    const volScalarField& gammaDot = state.temp->gammaDot();
    forAll(gammaDot, celli)
    {
        EXPECT_NEAR
        (
            powerLaw->S(species("s3"))[celli],
            0.1*pow3(2.0)*sqr(gammaDot[celli]/4),
            1e-12
        );
    }
}


TEST(breakageSelection, vogelPeukertRateByHand)
{
    // fMat 2 kg/(J m), x 1 mm, x Wmin 0.05 J m/kg (Wmin 50 J/kg), 10 impacts
    // per second of exponential spectrum, mean 112.5 J/kg (15 m/s):
    // S = fMat x rate Wbar exp(-Wmin/Wbar) = 2e-3*10*112.5*exp(-50/112.5)
    EXPECT_NEAR
    (
        breakageModels::vogelPeukert::exponentialSpectrumRate
        (
            2, 0.05, 1e-3, 10, 112.5
        ),
        2.25*std::exp(-50/112.5),
        1e-12
    );
    EXPECT_EQ
    (
        breakageModels::vogelPeukert::exponentialSpectrumRate
        (
            2, 0.05, 1e-3, 10, 0
        ),
        0
    );
}


TEST(breakageSelection, vogelPeukertOnKineticTheoryState)
{
    setUniform(0.08);
    shearWithTemperature state(0.05);
    autoPtr<breakageModel> vp
    (
        breakageModel::New
        (
            dictOf("model vogelPeukert; vogelPeukertCoeffs { fMat 2; xWmMin 1e-6; }"),
            mix()
        )
    );
    vp->correct(state.temp());

    // By hand in one cell for s2: sum over the partners k of
    //   nu = N_k pi sigma^2 g0 4 sqrt(theta/pi), Wbar = 2 theta m_j m_k/(m_j + m_k)^2
    //   S = fMat x nu Wbar exp(-Wmin/Wbar)
    const scalar pi = constant::mathematical::pi;
    const label j = species("s2");
    const scalar T = state.temp->T()[0];
    ASSERT_GT(T, 0);
    const scalar theta = T/3;
    const scalar phi = 0.08*mix().size();
    const scalar g0 = (1 - phi/2)/pow3(1 - phi);
    const scalar mj = mix().rho(j)*pi*pow3(mix().d(j))/6;
    scalar S = 0;
    forAll(mix().names(), k)
    {
        const scalar vk = pi*pow3(mix().d(k))/6;
        const scalar mk = mix().rho(k)*vk;
        const scalar sigma = 0.5*(mix().d(j) + mix().d(k));
        const scalar nu = (0.08/vk)*pi*sqr(sigma)*g0*4*std::sqrt(theta/pi);
        const scalar Wbar = 2*theta*mj*mk/sqr(mj + mk);
        S += 2*mix().d(j)*nu*Wbar*std::exp(-(1e-6/mix().d(j))/Wbar);
    }
    EXPECT_GT(S, 0);
    EXPECT_NEAR(vp->S(j)[0], S, 1e-10*S);
}


TEST(breakageSelection, badInputNamesTheEntry)
{
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model constant; constantCoeffs { S { s4 -0.1; } }"), mix()); },
        {"S.s4 -0.1", ">= 0"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model constant; constantCoeffs { S { s9 0.1; } }"), mix()); },
        {"s9"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model vogelPeukert; vogelPeukertCoeffs { fMat -2; xWmMin 0.05; }"), mix()); },
        {"fMat -2", ">= 0"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model vogelPeukert; vogelPeukertCoeffs { fMat 2; xWmMin -0.05; }"), mix()); },
        {"xWmMin -0.05", ">= 0"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model powerLaw; powerLawCoeffs { dRef 1e-3; }"), mix()); },
        {"k", "powerLawCoeffs"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model powerLaw; powerLawCoeffs { k 1; dRef 1e-3; variable shear; }"), mix()); },
        {"variable shear", "none gammaDot T"}
    );
    expectFoamError
    (
        []{ breakageModel::New(dictOf("model fancy;"), mix()); },
        {"fancy", "none", "constant", "powerLaw", "vogelPeukert"}
    );
    expectFoamError
    (
        []{ breakageSource(mix(), dictOf("model constant; constantCoeffs { S { s4 1; } }")); },
        {"daughterSizeDistribution"}
    );
    expectFoamError
    (
        []{ breakageSource(mix(), dictOf("model constant; constantCoeffs { S { s4 1; } } daughterSizeDistribution { model uniformBinary; } fines gone;")); },
        {"fines gone", "finestClass", "dust"}
    );
}


TEST(breakageSelection, implicitSweepKeepsSolidsPlusDust)
{
    // One Euler step of ddt(n) = B with S dt = 50 in the largest class,
    // solved coarse to fine: positive, and solids + dust kept to round-off
    setUniform(0.1);
    shearWithTemperature state(0.1);
    breakageSource breakage
    (
        mix(),
        dictOf
        (
            "model powerLaw; powerLawCoeffs { k 1; dRef 1e-3; a 3; }"
            "daughterSizeDistribution { model uniformBinary; } fines dust;"
        )
    );
    breakage.correct(state.temp());

    Time& runTime = *testTimePtr;
    const scalar dt = 50/breakage.selection().S(species("s4"))[0];
    runTime.setDeltaT(dt);
    ++runTime;

    const scalar before = gSum(mix().nTotal().primitiveField());
    for (const label k : mix().sizeOrder())
    {
        volScalarField& n = testMixturePtr->n()[k];
        n.storeOldTime();
        fvScalarMatrix nEqn(fvm::ddt(n) - breakage.source(k, n));
        nEqn.solve(dictOf("solver diagonal;"));
    }
    breakage.accumulate();
    testMixturePtr->correct();

    const scalar after =
        gSum(mix().nTotal().primitiveField())
      + gSum(breakage.dust().primitiveField());
    EXPECT_NEAR(after, before, 1e-13*before);
    forAll(mix().n(), i)
    {
        EXPECT_GT(gMin(mix().n()[i].primitiveField()), 0);
    }
    // Glass (another material, rate s4's (d/1 mm)^3) only loses to dust
    EXPECT_LT(mix().n()[species("glass")][0], 0.1);
}


// ************************************************************************* //

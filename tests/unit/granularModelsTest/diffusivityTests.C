/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    diffusivityTests.C

Description
    Unit tests of the plain diffusivity models: powerLaw (seed eq 15),
    kineticTheory with the Darken mixture value, constant and none.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "diffusivityModel.H"
#include <cmath>

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(diffusivity, powerLawMatchesSeedEq15)
{
    setFields(0.48, 0.12);
    autoPtr<diffusivityModel> D
    (
        diffusivityModel::New(dictOf("model powerLaw;"), *testMixturePtr)
    );
    const volScalarField T(uniformT(0.01));

    // 6 (1 + 0.2) 0.01 0.6^-1.5
    const scalar expected = 6*1.2*0.01*Foam::pow(0.6, -1.5);
    const volScalarField Dmix(D->Dmixture(T));
    EXPECT_NEAR(Dmix[0], expected, 1e-12*expected);

    // Below phiMin: law at phiMin times phi/phiMin (x = 0.2 still)
    setFields(0.016, 0.004);
    const scalar expectedLow = 6*1.2*0.01*Foam::pow(0.05, -1.5)*(0.02/0.05);
    const volScalarField Dlow(D->D(0, T));
    EXPECT_NEAR(Dlow[0], expectedLow, 1e-12*expectedLow);

    // Empty cell: exactly zero and finite
    setFields(0, 0);
    const volScalarField Dempty(D->Dmixture(T));
    EXPECT_EQ(Dempty[0], 0);
    EXPECT_TRUE(std::isfinite(Dempty[0]));
}


TEST(diffusivity, kineticTheoryAndDarkenMixture)
{
    setFields(0.48, 0.12);
    autoPtr<diffusivityModel> D
    (
        diffusivityModel::New
        (
            dictOf("model kineticTheory; kineticTheoryCoeffs { e 1; }"),
            *testMixturePtr
        )
    );
    const scalar Tval = 3e-4;
    const volScalarField T(uniformT(Tval));
    const scalar phi = 0.6;
    const scalar g0 = (1 - phi/2)/pow3(1 - phi);
    const scalar T1 = Tval/3;
    const scalar Dfine = 1e-3*Foam::sqrt(constant::mathematical::pi*T1)/(16*phi*g0);
    const scalar Dcoarse = 2*Dfine;

    EXPECT_NEAR(D->D(0, T)()[0], Dfine, 1e-12*Dfine);
    EXPECT_NEAR(D->D(1, T)()[0], Dcoarse, 1e-12*Dcoarse);

    // Darken: c_coarse D_fine + c_fine D_coarse
    const scalar Dmix = 0.2*Dfine + 0.8*Dcoarse;
    EXPECT_NEAR(D->Dmixture(T)()[0], Dmix, 1e-12*Dmix);
}


TEST(diffusivity, constantAndNone)
{
    setFields(0.48, 0.12);
    const volScalarField T(uniformT(1));
    autoPtr<diffusivityModel> Dc
    (
        diffusivityModel::New
        (
            dictOf("model constant; constantCoeffs { D 2.5e-6; }"),
            *testMixturePtr
        )
    );
    EXPECT_TRUE(Dc->active());
    EXPECT_NEAR(Dc->Dmixture(T)()[0], 2.5e-6, 1e-20);

    autoPtr<diffusivityModel> Dn
    (
        diffusivityModel::New(dictOf("model none;"), *testMixturePtr)
    );
    EXPECT_FALSE(Dn->active());
}

// The shear-rate diffusivity on the prescribed shear U = (gammaDot0 z, 0, 0):
// D = C gammaDot0 dMean^2 for every species and the mixture (dMean = 1.2 mm
// at 20 % coarse by volume of 1 and 2 mm); zero in an empty cell; Dlaw before
// correct(bulkFlow) and a negative C refused
TEST(diffusivity, shearRateLaw)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    autoPtr<diffusivityModel> D
    (
        diffusivityModel::New
        (
            dictOf("model shearRate; shearRateCoeffs { C 0.042; }"),
            *testMixturePtr
        )
    );
    const volScalarField T(uniformT(0.01));
    expectFoamError
    (
        [&]{ D->Dmixture(T); },
        {"shearRate", "correct(bulkFlow)"}
    );

    D->correct(flow());
    const scalar expected = 0.042*gammaDot0*sqr(1.2e-3);
    const volScalarField Dmix(D->Dmixture(T));
    const volScalarField Dfine(D->D(0, T));
    forAll(Dmix, celli)
    {
        EXPECT_NEAR(Dmix[celli], expected, 1e-10*expected);
        EXPECT_NEAR(Dfine[celli], expected, 1e-10*expected);
    }

    setFields(0, 0);
    EXPECT_EQ(gMax(D->Dmixture(T)().primitiveField()), 0);

    expectFoamError
    (
        [&]
        {
            diffusivityModel::New
            (
                dictOf("model shearRate; shearRateCoeffs { C -0.1; }"),
                *testMixturePtr
            );
        },
        {"C -0.1", ">= 0"}
    );
}


// ************************************************************************* //

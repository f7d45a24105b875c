/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    granularModelsTest

Description
    GoogleTest unit tests of the models in src/: values against hand
    calculations, conservation and positivity of the segregation fluxes on
    a closed box, and the errors of bad input. Run in tests/unit/testCase
    (a 4x4x4 closed unit box) after blockMesh:
        granularModelsTest -case <copy of testCase>

\*---------------------------------------------------------------------------*/

#include <gtest/gtest.h>

#include "fvCFD.H"
#include "IStringStream.H"
#include "granularMixture.H"
#include "bulkFlowModel.H"
#include "granularTemperatureModel.H"
#include "diffusivityModel.H"
#include "kineticSievingModel.H"
#include "percolationModel.H"
#include "breakageModel.H"
#include "segregationFlux.H"
#include "savageJeffrey.H"
#include "Random.H"

using namespace Foam;

namespace
{

// The case the tests run in (set up once by main)
Time* testTimePtr = nullptr;
fvMesh* testMeshPtr = nullptr;
granularMixture* testMixturePtr = nullptr;

// Shear rate of the prescribed test flow U = (gammaDot0 z, 0, 0)
constexpr scalar gammaDot0 = 2.0;

dictionary dictOf(const char* text)
{
    return dictionary(IStringStream(text)());
}

// A uniform granular temperature field [m2/s2]
tmp<volScalarField> uniformT(const scalar value)
{
    return volScalarField::New
    (
        "T",
        *testMeshPtr,
        dimensionedScalar("T", sqr(dimVelocity), value)
    );
}

void setFields(const scalar nFine, const scalar nCoarse)
{
    testMixturePtr->n()[0] == dimensionedScalar("n", dimless, nFine);
    testMixturePtr->n()[1] == dimensionedScalar("n", dimless, nCoarse);
    testMixturePtr->correct();
}

// Expect a Foam error whose message contains every given fragment
template<class Action>
void expectFoamError(Action action, std::initializer_list<std::string> fragments)
{
    try
    {
        action();
        ADD_FAILURE() << "no error raised";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        for (const std::string& f : fragments)
        {
            EXPECT_NE(msg.find(f), std::string::npos)
                << "message lacks '" << f << "':\n" << msg;
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Mixture * * * * * * * * * * * * * * * * //

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


// * * * * * * * * * * * * * Temperature and D * * * * * * * * * * * * * * //

TEST(granularTemperature, savageJeffreyOnSimpleShear)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    autoPtr<granularTemperatureModel> temp
    (
        granularTemperatureModel::New
        (
            dictOf("model savageJeffrey; savageJeffreyCoeffs { R 0.5; }"),
            *testMixturePtr
        )
    );
    temp->correct(flow());

    // T = 3 (dMean gammaDot/R)^2 = 3 (1.2e-3*2/0.5)^2
    const scalar Texpected = 3*sqr(1.2e-3*gammaDot0/0.5);
    forAll(temp->T(), celli)
    {
        EXPECT_NEAR(temp->gammaDot()[celli], gammaDot0, 1e-12);
        EXPECT_NEAR(temp->T()[celli], Texpected, 1e-12*Texpected);
    }
}


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


TEST(diffusivity, calibratedLawsAndEnvelope)
{
    setFields(0.48, 0.12);

    // powerLaw with the seed's parameters: the powerLaw model's value
    autoPtr<diffusivityModel> Dcal
    (
        diffusivityModel::New(dictOf("model calibrated;"), *testMixturePtr)
    );
    const volScalarField T(uniformT(0.01));
    const scalar expected = 6*1.2*0.01*Foam::pow(0.6, -1.5);
    // phi = 0.6 is outside phiRange (0.1 0.55): clamped to 0.55
    const scalar expectedClamped = 6*1.2*0.01*Foam::pow(0.55, -1.5);
    EXPECT_NEAR(Dcal->Dmixture(T)()[0], expectedClamped, 1e-12*expected);

    autoPtr<diffusivityModel> Dext
    (
        diffusivityModel::New
        (
            dictOf("model calibrated; calibratedCoeffs { outsideEnvelope extrapolate; }"),
            *testMixturePtr
        )
    );
    EXPECT_NEAR(Dext->Dmixture(T)()[0], expected, 1e-12*expected);

    // T above TRange (0.1): clamped
    const volScalarField Thot(uniformT(1));
    setFields(0.4, 0.1);
    EXPECT_NEAR
    (
        Dcal->Dmixture(Thot)()[0],
        6*1.2*0.1*Foam::pow(0.5, -1.5),
        1e-12
    );

    // error policy names the variable and the envelope
    autoPtr<diffusivityModel> Derr
    (
        diffusivityModel::New
        (
            dictOf("model calibrated; calibratedCoeffs { outsideEnvelope error; }"),
            *testMixturePtr
        )
    );
    expectFoamError([&]{ Derr->Dmixture(Thot); }, {"envelope", "T 1"});

    // kineticTheoryGroups: C d sqrt(T/3)(1 + alpha x)/(phi g0), own diameter
    autoPtr<diffusivityModel> Dkt
    (
        diffusivityModel::New
        (
            dictOf("model calibrated; calibratedCoeffs { file granularCoefficientsKT; }"),
            *testMixturePtr
        )
    );
    const scalar phi = 0.5, x = 0.2;
    const scalar g0 = (1 - phi/2)/pow3(1 - phi);
    const scalar Dfine = 0.15*1e-3*Foam::sqrt(0.01/3)*(1 + 0.8*x)/(phi*g0);
    EXPECT_NEAR(Dkt->D(0, T)()[0], Dfine, 1e-12*Dfine);
    EXPECT_NEAR(Dkt->D(1, T)()[0], 2*Dfine, 1e-12*Dfine);

    // Bad input: unknown mode, unknown policy
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model calibrated; calibratedCoeffs { mode tabulated; }"), *testMixturePtr); },
        {"tabulated", "law"}
    );
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model calibrated; calibratedCoeffs { outsideEnvelope guess; }"), *testMixturePtr); },
        {"guess", "clamp", "extrapolate", "error"}
    );
}


// * * * * * * * * * * * * * Segregation fluxes * * * * * * * * * * * * * * //

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


TEST(kineticSieving, velocityGradientDrift)
{
    setFields(0.48, 0.12);
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    autoPtr<kineticSievingModel> sieving
    (
        kineticSievingModel::New
        (
            dictOf
            (
                "model velocityGradient;"
                "velocityGradientCoeffs { eta 1e-3; Umin 1e-9; }"
            ),
            *testMixturePtr,
            flow()
        )
    );
    const surfaceScalarField W(sieving->driftFlux(0, 1));

    // U = (2 z, 0, 0): ln|U| = ln(2 z); the fine drifts down the gradient
    const labelUList& own = testMeshPtr->owner();
    const labelUList& nei = testMeshPtr->neighbour();
    const volVectorField& C = testMeshPtr->C();
    const surfaceScalarField& magSf = testMeshPtr->magSf();
    const scalarField& deltaCoeffs = testMeshPtr->deltaCoeffs();
    forAll(W, facei)
    {
        const scalar lnP = Foam::log(gammaDot0*C[own[facei]].z());
        const scalar lnN = Foam::log(gammaDot0*C[nei[facei]].z());
        const scalar expected =
            -1e-3*(lnN - lnP)*deltaCoeffs[facei]*magSf[facei];
        EXPECT_NEAR(W[facei], expected, 1e-14);
    }
}


TEST(kineticSieving, calibratedEtaDrift)
{
    setFields(0.32, 0.08);   // phi 0.4, x 0.2
    autoPtr<bulkFlowModel> flow
    (
        bulkFlowModel::New(dictOf("model prescribed;"), *testMixturePtr)
    );
    // Registers T = 3 (dMean gammaDot/R)^2
    autoPtr<granularTemperatureModel> temp
    (
        granularTemperatureModel::New
        (
            dictOf("model savageJeffrey; savageJeffreyCoeffs { R 1; }"),
            *testMixturePtr
        )
    );
    temp->correct(flow());
    autoPtr<kineticSievingModel> sieving
    (
        kineticSievingModel::New
        (
            dictOf("model calibrated; calibratedCoeffs { Umin 1e-9; }"),
            *testMixturePtr,
            flow()
        )
    );
    sieving->correct();
    const surfaceScalarField W(sieving->driftFlux(0, 1));

    // eta = E d_coarse sqrt(T/3) phi^p (1 + beta x), uniform here
    const scalar T = 3*sqr(1.2e-3*gammaDot0);
    const scalar eta =
        0.5*2e-3*Foam::sqrt(T/3)*Foam::pow(0.4, -1.2)*(1 + 2*0.2);

    const labelUList& own = testMeshPtr->owner();
    const labelUList& nei = testMeshPtr->neighbour();
    const volVectorField& C = testMeshPtr->C();
    forAll(W, facei)
    {
        const scalar dLnU =
            Foam::log(C[nei[facei]].z()/C[own[facei]].z());
        const scalar expected =
            -eta*dLnU*testMeshPtr->deltaCoeffs()[facei]
           *testMeshPtr->magSf()[facei];
        EXPECT_NEAR(W[facei], expected, 1e-12*mag(eta) + 1e-18);
    }
}


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


// * * * * * * * * * * * * * * * * * Main * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    ::testing::InitGoogleTest(&argc, argv);

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // The prescribed test flow U = (gammaDot0 z, 0, 0), written for the
    // prescribed bulkFlow model to read
    {
        volVectorField U
        (
            IOobject("U", runTime.timeName(), mesh),
            mesh,
            dimensionedVector("U", dimVelocity, Zero)
        );
        U.primitiveFieldRef() =
            gammaDot0*vector(1, 0, 0)*mesh.C().primitiveField().component(2);
        forAll(U.boundaryField(), patchi)
        {
            U.boundaryFieldRef()[patchi] ==
                gammaDot0*vector(1, 0, 0)
               *mesh.C().boundaryField()[patchi].component(2);
        }
        U.write();
    }

    granularMixture mixture(mesh);

    testTimePtr = &runTime;
    testMeshPtr = &mesh;
    testMixturePtr = &mixture;

    return RUN_ALL_TESTS();
}


// ************************************************************************* //

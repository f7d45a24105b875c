/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    calibratedBreakageTests.C

Description
    Unit tests of the calibrated breakage selection rate
    (breakageModels::calibrated, libcalibratedModels): the closed form of
    an exponential impact spectrum by hand, the rate of each species from a
    hand-written granularCoefficients (omega.<species>, Wmean.<species>)
    against the formulas written out here, the envelope policy, and the
    refusals of bad input, each naming the entry.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "breakageModel.H"
#include "calibratedBreakage.H"
#include "vogelPeukert.H"
#include "vogelPeukert.H"
#include "OFstream.H"

#include <cmath>
#include <string>

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// Hand-written laws: omega = C sqrt(T/3)/d phi g0^b (1 + alpha x),
// Wmean = K (T/3) phi^c
struct handLaws
{
    scalar C[2] = {13.5, 40};
    scalar b[2] = {1, 0.9};
    scalar alpha[2] = {-0.5, 0.2};
    scalar K[2] = {0.4, 0.05};
    scalar c[2] = {-0.2, -1};
};

const char* speciesName[2] = {"fine", "coarse"};


//- constant/<name> with the laws of hand (leaving out the coefficient
//  `skip`, giving omega.fine the law `omegaFineLaw`, phiRange of every
//  law `phiRange`)
void writeCoefficients
(
    const word& name,
    const handLaws& hand,
    const std::string& skip = "",
    const std::string& omegaFineLaw = "collisionFrequencyGroups",
    const std::string& phiRange = "(0.1 0.6)"
)
{
    OFstream os(constantFile(name));
    os  << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object " << name << "; }" << nl;
    const std::string ranges =
        "    phiRange " + phiRange + ";\n"
        "    xRange (0.05 0.95);\n    TRange (1e-6 1);\n";
    for (int s = 0; s < 2; ++s)
    {
        const std::string omega = std::string("omega.") + speciesName[s];
        if (omega != skip)
        {
            os  << omega.c_str() << nl << "{" << nl
                << "    law " << (s == 0 ? omegaFineLaw : "collisionFrequencyGroups").c_str()
                << ";" << nl
                << "    C " << hand.C[s] << "; b " << hand.b[s]
                << "; alpha " << hand.alpha[s] << ";" << nl
                << ranges.c_str() << "}" << nl;
        }
        const std::string W = std::string("Wmean.") + speciesName[s];
        if (W != skip)
        {
            os  << W.c_str() << nl << "{" << nl
                << "    law impactEnergyGroups;" << nl
                << "    K " << hand.K[s] << "; c " << hand.c[s] << ";" << nl
                << ranges.c_str() << "}" << nl;
        }
    }
}


autoPtr<breakageModel> calibratedBreakage(const std::string& coeffs)
{
    return breakageModel::New
    (
        dictOf(("model calibrated; calibratedCoeffs { " + coeffs + " }").c_str()),
        *testMixturePtr
    );
}

} // End anonymous namespace


TEST(calibratedBreakage, closedFormByHand)
{
    // fMat 2 kg/(J m), x 1 mm, xWmMin 0.05 J m/kg (Wmin 50 J/kg), 100
    // impacts per second of mean 112.5 J/kg:
    // S = 2*1e-3*100*112.5*exp(-50/112.5) = 22.5*exp(-4/9) = 14.4265587...
    EXPECT_NEAR
    (
        breakageModels::vogelPeukert::exponentialSpectrumRate(2, 0.05, 1e-3, 100, 112.5),
        14.4265587,
        1e-6
    );
    EXPECT_NEAR
    (
        breakageModels::vogelPeukert::exponentialSpectrumRate(2, 0.05, 1e-3, 100, 112.5),
        22.5*std::exp(-4.0/9.0),
        1e-12
    );
    // No impacts or no energy (T = 0): no breakage
    EXPECT_EQ(breakageModels::vogelPeukert::exponentialSpectrumRate(2, 0.05, 1e-3, 0, 112.5), 0);
    EXPECT_EQ(breakageModels::vogelPeukert::exponentialSpectrumRate(2, 0.05, 1e-3, 100, 0), 0);
}


TEST(calibratedBreakage, ratesFromHandWrittenLaws)
{
    const handLaws hand;
    writeCoefficients("granularCoefficientsBreakage", hand);

    // phi 0.4, coarse fraction 0.25
    setFields(0.3, 0.1);
    shearWithTemperature state(0.05);
    const scalar fMat = 2, xWmMin = 1e-6;
    autoPtr<breakageModel> model
    (
        calibratedBreakage
        (
            "fMat 2; xWmMin 1e-6; file granularCoefficientsBreakage;"
        )
    );
    model->correct(state.temp());

    const scalar phi = 0.4, x = 0.25;
    const scalar g0 = (1 - phi/2)/pow3(1 - phi);
    for (int s = 0; s < 2; ++s)
    {
        const scalar d = testMixturePtr->d(s);
        const volScalarField& S = model->S(s);
        forAll(S, celli)
        {
            const scalar T = state.temp->T()[celli];
            ASSERT_GT(T, 0);
            const scalar omega =
                hand.C[s]*std::sqrt(T/3)/d*phi*std::pow(g0, hand.b[s])
               *(1 + hand.alpha[s]*x);
            const scalar W = hand.K[s]*(T/3)*std::pow(phi, hand.c[s]);
            const scalar expected =
                fMat*d*omega*W*std::exp(-(xWmMin/d)/W);
            EXPECT_GT(expected, 0);
            EXPECT_NEAR(S[celli], expected, 1e-10*expected)
                << speciesName[s] << " cell " << celli;
        }
    }

    // Cell 0 by the numbers (print for the record)
    Info<< "calibrated breakage at phi 0.4, x 0.25, T "
        << state.temp->T()[0] << ": S.fine " << model->S(0)[0]
        << " 1/s, S.coarse " << model->S(1)[0] << " 1/s" << endl;
}


TEST(calibratedBreakage, envelopePolicy)
{
    const handLaws hand;
    // Every law fitted on phi in (0.1 0.3): phi 0.4 is outside
    writeCoefficients
    (
        "granularCoefficientsBreakageNarrow", hand, "",
        "collisionFrequencyGroups", "(0.1 0.3)"
    );
    setFields(0.3, 0.1);
    shearWithTemperature state(0.05);

    // clamp (default): the laws at phi = 0.3
    autoPtr<breakageModel> clamped
    (
        calibratedBreakage
        (
            "fMat 2; xWmMin 1e-6; file granularCoefficientsBreakageNarrow;"
        )
    );
    clamped->correct(state.temp());
    const scalar phi = 0.3, x = 0.25, d = testMixturePtr->d(0);
    const scalar T = state.temp->T()[0];
    const scalar g0 = (1 - phi/2)/pow3(1 - phi);
    const scalar omega =
        hand.C[0]*std::sqrt(T/3)/d*phi*std::pow(g0, hand.b[0])
       *(1 + hand.alpha[0]*x);
    const scalar W = hand.K[0]*(T/3)*std::pow(phi, hand.c[0]);
    const scalar expected = 2*d*omega*W*std::exp(-(1e-6/d)/W);
    EXPECT_NEAR(clamped->S(0)[0], expected, 1e-10*expected);

    // error: names the envelope, the coefficient and phi
    autoPtr<breakageModel> strict
    (
        calibratedBreakage
        (
            "fMat 2; xWmMin 1e-6; file granularCoefficientsBreakageNarrow;"
            " outsideEnvelope error;"
        )
    );
    expectFoamError
    (
        [&]{ strict->correct(state.temp()); },
        {"envelope", "omega.fine", "phi 0.4"}
    );
}


TEST(calibratedBreakage, badInputNamesTheEntry)
{
    const handLaws hand;
    writeCoefficients("granularCoefficientsBreakage", hand);
    writeCoefficients("granularCoefficientsNoWcoarse", hand, "Wmean.coarse");
    writeCoefficients
    (
        "granularCoefficientsWrongLaw", hand, "", "powerLaw"
    );

    expectFoamError
    (
        []{ calibratedBreakage("fMat -2; xWmMin 1e-6; file granularCoefficientsBreakage;"); },
        {"fMat -2", ">= 0"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin -1; file granularCoefficientsBreakage;"); },
        {"xWmMin -1", ">= 0"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("xWmMin 1e-6; file granularCoefficientsBreakage;"); },
        {"fMat"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin 1e-6; file granularCoefficientsNoWcoarse;"); },
        {"Wmean.coarse", "breakage"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin 1e-6; file granularCoefficientsWrongLaw;"); },
        {"omega.fine/law powerLaw", "collisionFrequencyGroups"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin 1e-6; file granularCoefficientsBreakage; outsideEnvelope runDEM;"); },
        {"runDEM", "clamp"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin 1e-6; mode tabulated;"); },
        {"mode", "fMat", "xWmMin", "outsideEnvelope"}
    );
    expectFoamError
    (
        []{ calibratedBreakage("fMat 2; xWmMin 1e-6; file noSuchCoefficients;"); },
        {"noSuchCoefficients"}
    );
}


// ************************************************************************* //

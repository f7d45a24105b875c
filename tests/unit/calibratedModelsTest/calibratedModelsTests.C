/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    calibratedModelsTests.C

Description
    Unit tests of the calibrated models: calibrated diffusivity laws and
    their envelope, the tabulated calibration (calibrationTable) read from
    a synthetic calibration.h5, the tabulated and law eta of the calibrated
    kinetic sieving, and runDEM extending the table.

\*---------------------------------------------------------------------------*/

#include "granularModelsTestFixtures.H"
#include "diffusivityModel.H"
#include "kineticSievingModel.H"
#include "calibrationTable.H"
#include "io/Hdf5File.hpp"
#include "fit/SievingNormalisation.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace Foam;
using namespace unitTest;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// A calibration.h5 as calibrateGranularMixture writes it, on the grid
// phi x x x T x seeds, with measured T = targetT and the given D of the
// fines and eta (engine units) of the coarse. A seed's replica is scaled by
// 1 + replicaSpread (seed 1) or 1 - replicaSpread (seed 2): the average is
// the given value.
struct syntheticTable
{
    std::vector<double> phi{0.2, 0.35, 0.5};
    std::vector<double> x{0.2, 0.4};
    std::vector<double> T{0.001, 0.005, 0.02};
    std::vector<int> seeds{1, 2};
    double replicaSpread = 0.1;
    std::function<double(double, double, double)> D;
    std::function<double(double, double, double)> eta;
    std::string content = "calibrateGranularMixture conditions";
    std::string skip;   // a condition name (without seed) left out

    static std::string fmt(double v)
    {
        char buf[64];
        std::snprintf(buf, sizeof(buf), "%.6g", v);
        return buf;
    }

    void write(const fileName& path) const
    {
        sdf::io::File f = sdf::io::File::create(path);
        const sdf::io::Group root = f.root();
        root.setAttribute("content", content);
        root.setAttribute("fineSpecies", "fine");
        root.setAttribute("coarseSpecies", "coarse");
        for (const double p : phi)
        for (const double xc : x)
        for (const double t : T)
        {
            const std::string point =
                "phi" + fmt(p) + "_x" + fmt(xc) + "_T" + fmt(t);
            if (point == skip) continue;
            for (const int seed : seeds)
            {
                const double scale =
                    seeds.size() == 1 ? 1
                  : seed == 1 ? 1 + replicaSpread : 1 - replicaSpread;
                const sdf::io::Group g = root.createGroup
                (
                    "conditions/" + point + "_seed" + std::to_string(seed)
                );
                g.setAttribute("phi", p);
                g.setAttribute("x", xc);
                g.setAttribute("targetT", t);
                g.setAttribute("seed", std::int64_t(seed));
                g.setAttribute("T", t);
                g.setAttribute("settingsKey", "synthetic");
                const sdf::io::Group fine = g.createGroup("species/fine");
                fine.setAttribute("D", scale*D(p, xc, t));
                fine.setAttribute("DError", 0.01*D(p, xc, t));
                const sdf::io::Group coarse = g.createGroup("species/coarse");
                coarse.setAttribute("D", 0.5*D(p, xc, t));
                coarse.setAttribute("eta", eta ? scale*eta(p, xc, t) : 0.0);
                coarse.setAttribute("etaError", 0.0);
            }
        }
    }
};



//- Engine eta (positive, kg^2 m s^-3 scale) of the tabulated-eta tests
double etaEngine(double phi, double x, double T)
{
    return 1e-9*x*std::sqrt(T)*phi;
}

//- A calibration table with constant D and etaEngine, in constant/<name>
void writeEtaTable(const word& name)
{
    syntheticTable table;
    table.D = [](double, double, double) { return 1e-5; };
    table.eta = etaEngine;
    table.write(constantFile(name));
}

} // End anonymous namespace


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

    // Bad input: unknown mode, unknown policy, runDEM with a law
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model calibrated; calibratedCoeffs { mode guess; }"), *testMixturePtr); },
        {"guess", "tabulated", "law"}
    );
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model calibrated; calibratedCoeffs { outsideEnvelope runDEM; }"), *testMixturePtr); },
        {"runDEM", "mode tabulated"}
    );
    expectFoamError
    (
        []{ diffusivityModel::New(dictOf("model calibrated; calibratedCoeffs { outsideEnvelope guess; }"), *testMixturePtr); },
        {"guess", "clamp", "extrapolate", "error"}
    );
}


TEST(diffusivity, tabulatedReproducesPowerLaw)
{
    // D = A T^m phi^b exp(c x): linear in ln(T), ln(phi) and x after ln, so
    // the table's interpolation reproduces it exactly, on and between the
    // grid points (replicas average to it)
    const auto Dexact = [](double phi, double x, double T)
    {
        return 2e-4*std::pow(T, 0.9)*std::pow(phi, -1.2)*std::exp(0.5*x);
    };
    syntheticTable table;
    table.D = Dexact;
    table.write(constantFile("calibrationPowerLaw.h5"));

    for (const word interpolation : {"linear", "steffen"})
    {
        autoPtr<diffusivityModel> Dtab
        (
            diffusivityModel::New
            (
                dictOf
                (
                    (
                        "model calibrated; calibratedCoeffs { mode tabulated;"
                        " calibrationFile calibrationPowerLaw.h5;"
                        " interpolation " + interpolation + "; }"
                    ).c_str()
                ),
                *testMixturePtr
            )
        );

        // A grid point: phi 0.35, x 0.4, T 0.005
        setFields(0.35*0.6, 0.35*0.4);
        const volScalarField T1(uniformT(0.005));
        const scalar onGrid = Dexact(0.35, 0.4, 0.005);
        EXPECT_NEAR(Dtab->D(0, T1)()[0], onGrid, 1e-12*onGrid) << interpolation;
        // The fine D is used for every species (docs/user/calibration.md)
        EXPECT_NEAR(Dtab->D(1, T1)()[0], onGrid, 1e-12*onGrid) << interpolation;

        // Between grid points on every axis
        setFields(0.27*0.7, 0.27*0.3);
        const volScalarField T2(uniformT(0.0031));
        const scalar between = Dexact(0.27, 0.3, 0.0031);
        EXPECT_NEAR(Dtab->D(0, T2)()[0], between, 1e-10*between) << interpolation;
    }
}


TEST(diffusivity, tabulatedSinglePointAxesAreConstant)
{
    // One x and one T: the table is constant along them (even when
    // extrapolating), ln-linear in phi
    const auto Dexact = [](double phi, double, double)
    {
        return 1e-4*std::pow(phi, -1.5);
    };
    syntheticTable table;
    table.x = {0.3};
    table.T = {0.01};
    table.D = Dexact;
    table.write(constantFile("calibrationSinglePoint.h5"));
    autoPtr<diffusivityModel> Dtab
    (
        diffusivityModel::New
        (
            dictOf
            (
                "model calibrated; calibratedCoeffs { mode tabulated;"
                " calibrationFile calibrationSinglePoint.h5;"
                " outsideEnvelope extrapolate; }"
            ),
            *testMixturePtr
        )
    );
    setFields(0.3*0.9, 0.3*0.1);   // phi 0.3, x 0.1
    const scalar expected = Dexact(0.3, 0, 0);
    for (const scalar T : {0.001, 0.01, 0.05})
    {
        EXPECT_NEAR(Dtab->D(0, uniformT(T))()[0], expected, 1e-10*expected)
            << "T " << T;
    }
}


TEST(diffusivity, tabulatedOutsideTheGrid)
{
    const auto Dexact = [](double phi, double x, double T)
    {
        return 3e-4*T*std::pow(phi, -1.5)*std::exp(0.3*x);
    };
    syntheticTable table;
    table.D = Dexact;
    table.write(constantFile("calibrationOutside.h5"));
    const std::string coeffs =
        "model calibrated; calibratedCoeffs { mode tabulated;"
        " calibrationFile calibrationOutside.h5; outsideEnvelope ";

    // phi 0.6 above the grid's 0.5, T 0.04 above its 0.02
    setFields(0.6*0.7, 0.6*0.3);
    const volScalarField T(uniformT(0.04));

    autoPtr<diffusivityModel> Dclamp
    (
        diffusivityModel::New(dictOf((coeffs + "clamp; }").c_str()), *testMixturePtr)
    );
    const scalar clamped = Dexact(0.5, 0.3, 0.02);
    EXPECT_NEAR(Dclamp->D(0, T)()[0], clamped, 1e-10*clamped);

    // The end intervals' lines in ln-ln extend a power law exactly
    autoPtr<diffusivityModel> Dext
    (
        diffusivityModel::New(dictOf((coeffs + "extrapolate; }").c_str()), *testMixturePtr)
    );
    const scalar extrapolated = Dexact(0.6, 0.3, 0.04);
    EXPECT_NEAR(Dext->D(0, T)()[0], extrapolated, 1e-10*extrapolated);
    EXPECT_GT(extrapolated, 1.1*clamped);

    autoPtr<diffusivityModel> Derr
    (
        diffusivityModel::New(dictOf((coeffs + "error; }").c_str()), *testMixturePtr)
    );
    expectFoamError([&]{ Derr->D(0, T); }, {"envelope", "phi 0.6", "T 0.04"});

    // Inside the grid the error policy is silent
    setFields(0.3*0.7, 0.3*0.3);
    const volScalarField Tin(uniformT(0.01));
    const scalar inside = Dexact(0.3, 0.3, 0.01);
    EXPECT_NEAR(Derr->D(0, Tin)()[0], inside, 1e-10*inside);
}


TEST(diffusivity, tabulatedRefusesIncompleteOrForeignFiles)
{
    const auto D = [](double phi, double x, double T) { return T/phi + x; };

    // Selecting the tabulated diffusivity of file (plus more coefficients)
    const auto selectTabulated =
        [](const std::string& file, const std::string& more = "")
        {
            return [file, more]
            {
                const std::string text
                (
                    "model calibrated; calibratedCoeffs { mode tabulated;"
                    " calibrationFile " + file + "; " + more + "}"
                );
                diffusivityModel::New(dictOf(text.c_str()), *testMixturePtr);
            };
        };

    // A grid point missing (both seeds): named with the file
    syntheticTable incomplete;
    incomplete.D = D;
    incomplete.skip = "phi0.35_x0.4_T0.005";
    incomplete.write(constantFile("calibrationIncomplete.h5"));
    expectFoamError
    (
        selectTabulated("calibrationIncomplete.h5"),
        {"calibrationIncomplete.h5", "phi0.35_x0.4_T0.005", "missing"}
    );

    // Ours, but another content (e.g. a periodicDEM result)
    syntheticTable foreign;
    foreign.D = D;
    foreign.content = "periodicDEM result";
    foreign.write(constantFile("calibrationForeign.h5"));
    expectFoamError
    (
        selectTabulated("calibrationForeign.h5"),
        {"calibrationForeign.h5", "content"}
    );

    // Not HDF5 at all, and no file
    {
        OFstream os(constantFile("calibrationText.h5"));
        os << "not an HDF5 file" << nl;
    }
    for (const char* name : {"calibrationText.h5", "calibrationMissing.h5"})
    {
        expectFoamError(selectTabulated(name), {name});
    }

    // An unknown interpolation lists the valid ones
    syntheticTable good;
    good.D = D;
    good.write(constantFile("calibrationGood.h5"));
    expectFoamError
    (
        selectTabulated("calibrationGood.h5", "interpolation cubic; "),
        {"cubic", "linear", "steffen"}
    );
}


TEST(kineticSieving, tabulatedEtaInKinematicUnits)
{
    // Engine eta, positive: the table holds eta converted to m2/s at each
    // condition (its phi, x, measured T) with the mixture's d and rho
    writeEtaTable("calibrationEta.h5");

    const calibrationTable eta
    (
        *testMixturePtr,
        dictOf("calibrationFile calibrationEta.h5;"),
        "eta"
    );
    const sdf::fit::SphereSpecies fine{1e-3, 2500}, coarse{2e-3, 2500};
    const double expected = sdf::fit::kinematicSievingCoefficient
    (
        etaEngine(0.35, 0.2, 0.02), 0.35, 0.2, 0.02, fine, coarse
    );
    EXPECT_GT(expected, 0);
    EXPECT_NEAR(eta.value(0.35, 0.2, 0.02), expected, 1e-12*expected);
    EXPECT_EQ(eta.nConditions(), 3*2*3*2);
    EXPECT_EQ(eta.phiRange().second(), 0.5);
    EXPECT_EQ(eta.TRange().first(), 0.001);
}


TEST(kineticSieving, tabulatedEtaDrift)
{
    // The calibrated sieving model in mode tabulated: the drift flux uses
    // the table's eta of the coarse at the cell's state
    writeEtaTable("calibrationEtaDrift.h5");

    setFields(0.32, 0.08);   // phi 0.4, x 0.2
    const shearWithTemperature shear(1);
    const autoPtr<bulkFlowModel>& flow = shear.flow;
    autoPtr<kineticSievingModel> sieving
    (
        kineticSievingModel::New
        (
            dictOf
            (
                "model calibrated; calibratedCoeffs { Umin 1e-9;"
                " mode tabulated; calibrationFile calibrationEtaDrift.h5;"
                " outsideEnvelope extrapolate; }"
            ),
            *testMixturePtr,
            flow()
        )
    );
    sieving->correct();
    const surfaceScalarField W(sieving->driftFlux(0, 1));

    const calibrationTable etaTable
    (
        *testMixturePtr,
        dictOf("calibrationFile calibrationEtaDrift.h5;"),
        "eta"
    );
    const scalar T = 3*sqr(1.2e-3*gammaDot0);
    const scalar eta = etaTable.value(0.4, 0.2, T);
    EXPECT_GT(eta, 0);

    expectSievingDrift(W, eta, 1e-10);
}


TEST(diffusivity, tabulatedRunDEMExtendsTheGrid)
{
    // A 2 x 2 x 2 grid; the cells reach phi 0.42 > 0.35: runDEM runs the
    // new slice phi 0.42 x (x 0.2, 0.4) x (T 0.005, 0.02) with the tiny DEM
    // settings below (one replica) and stores it in the file
    syntheticTable table;
    table.phi = {0.2, 0.35};
    table.T = {0.005, 0.02};
    table.seeds = {1};
    table.D = [](double phi, double x, double T) { return 1e-3*T/phi*(1 + x); };
    const fileName h5(constantFile("calibrationRunDEM.h5"));
    table.write(h5);
    // Tiny DEM settings, unless the caller put a calibrationDict in place
    // (the shell test dem/calibratedRunDEM uses the tutorial's)
    const fileName calibrationDict
    (
        testTimePtr->globalPath()/"system"/"calibrationDict"
    );
    if (!isFile(calibrationDict))
    {
        OFstream os(calibrationDict);
        os  << "FoamFile { version 2.0; format ascii; class dictionary;"
            << " object calibrationDict; }" << nl
            << "replicas (1); particles 100; mode thermostatted;" << nl
            << "contact { model linearSpringDashpot; restitution 0.9;"
            << " friction 0.3; normalStiffness 2e3; }" << nl
            << "equilibrationTime 0.001; maxEquilibrationTime 0.002;"
            << " samplingTime 0.002; threads 1;" << nl;
    }

    autoPtr<diffusivityModel> Drun
    (
        diffusivityModel::New
        (
            dictOf
            (
                "model calibrated; calibratedCoeffs { mode tabulated;"
                " calibrationFile calibrationRunDEM.h5;"
                " outsideEnvelope runDEM; runDEMMargin 0; }"
            ),
            *testMixturePtr
        )
    );

    const auto storedNames = [&h5]()
    {
        sdf::io::File f = sdf::io::File::openReadOnly(h5);
        return f.root().openGroup("conditions").childNames();
    };
    ASSERT_EQ(storedNames().size(), 8u);

    setFields(0.42*0.8, 0.42*0.2);   // phi 0.42, x 0.2
    const volScalarField T(uniformT(0.005));
    const scalar D = Drun->D(0, T)()[0];

    const std::vector<std::string> names = storedNames();
    ASSERT_EQ(names.size(), 12u);
    for (const char* added :
    {
        "phi0.42_x0.2_T0.005_seed1", "phi0.42_x0.2_T0.02_seed1",
        "phi0.42_x0.4_T0.005_seed1", "phi0.42_x0.4_T0.02_seed1"
    })
    {
        EXPECT_NE(std::find(names.begin(), names.end(), added), names.end())
            << added << " not stored";
    }

    // The cell sits on the new grid point: its D is the DEM's
    sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group g =
        f.root().openGroup("conditions/phi0.42_x0.2_T0.005_seed1");
    EXPECT_EQ(g.readDouble("phi"), 0.42);
    EXPECT_GT(g.readDouble("T"), 0);
    const double Ddem = g.openGroup("species/fine").readDouble("D");
    EXPECT_GT(Ddem, 0);
    EXPECT_NEAR(D, Ddem, 1e-9*Ddem);

    // Inside the grown grid nothing runs again
    Drun->D(0, T);
    EXPECT_EQ(storedNames().size(), 12u);

    // Nor with the default margin for cells on the grid's edges (phi 0.42,
    // x 0.2, T 0.005): the margin widens new values, it does not trigger
    autoPtr<diffusivityModel> DrunMargin
    (
        diffusivityModel::New
        (
            dictOf
            (
                "model calibrated; calibratedCoeffs { mode tabulated;"
                " calibrationFile calibrationRunDEM.h5;"
                " outsideEnvelope runDEM; }"
            ),
            *testMixturePtr
        )
    );
    DrunMargin->D(0, T);
    EXPECT_EQ(storedNames().size(), 12u);
}


TEST(diffusivity, tabulatedRunDEMBadLimits)
{
    syntheticTable table;
    table.D = [](double, double, double) { return 1e-5; };
    table.write(constantFile("calibrationRunDEMLimits.h5"));
    for (const char* bad :
        {"runDEMMaxPhi 0.7;", "runDEMMinT 0;", "runDEMMargin -1;"})
    {
        expectFoamError
        (
            [bad]
            {
                diffusivityModel::New
                (
                    dictOf
                    (
                        (
                            std::string
                            (
                                "model calibrated; calibratedCoeffs"
                                " { mode tabulated; outsideEnvelope runDEM;"
                                " calibrationFile calibrationRunDEMLimits.h5; "
                            ) + bad + " }"
                        ).c_str()
                    ),
                    *testMixturePtr
                );
            },
            {"runDEMMaxPhi", "runDEMMinT", "runDEMMargin"}
        );
    }
}


TEST(kineticSieving, calibratedEtaDrift)
{
    setFields(0.32, 0.08);   // phi 0.4, x 0.2
    const shearWithTemperature shear(1);
    const autoPtr<bulkFlowModel>& flow = shear.flow;
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

    expectSievingDrift(W, eta, 1e-12);
}

TEST(calibrated, misspeltCoefficientIsRefused)
{
    // A misspelt key of calibratedCoeffs stops with the valid keys listed
    expectFoamError
    (
        []
        {
            diffusivityModel::New
            (
                dictOf("model calibrated; calibratedCoeffs { outsideEnvelop clamp; }"),
                *testMixturePtr
            );
        },
        {"outsideEnvelop", "outsideEnvelope", "calibrationFile"}
    );

    const shearWithTemperature shear(1);
    expectFoamError
    (
        [&shear]
        {
            kineticSievingModel::New
            (
                dictOf("model calibrated; calibratedCoeffs { Umn 1e-9; }"),
                *testMixturePtr,
                shear.flow()
            );
        },
        {"Umn", "Umin"}
    );

    // Umin carries velocity dimensions when it states them
    expectFoamError
    (
        [&shear]
        {
            kineticSievingModel::New
            (
                dictOf("model calibrated; calibratedCoeffs { Umin [0 2 -1 0 0 0 0] 1e-9; }"),
                *testMixturePtr,
                shear.flow()
            );
        },
        {"Umin"}
    );
}

// ************************************************************************* //

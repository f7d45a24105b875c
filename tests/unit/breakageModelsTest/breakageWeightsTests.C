/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
File
    breakageWeightsTests.C

Description
    Where the fragments go: for every parent class, including the two
    finest, the fixed-pivot weights keep the parent's volume and the number
    of fragments per event (uniform binary: 2; Austin with exponents above
    1 in volume: c p/(p - 1) per term), to round-off; a hand-computed
    two-class case; the class grid keeps to one material; the table's bad
    input names the entry.

\*---------------------------------------------------------------------------*/

#include "breakageTestFixtures.H"
#include "daughterSizeDistributionModel.H"
#include "breakageSource.H"
#include "mathematicalConstants.H"

using namespace Foam;
using namespace unitTest;

namespace
{

scalar volumeOf(const word& name)
{
    return mix().particleVolume(species(name));
}

//- Volume and number balance of every parent for one daughter model
void expectConserving
(
    const char* daughterDict,
    const bool dust,
    const scalar fragmentsPerEvent
)
{
    autoPtr<daughterSizeDistributionModel> daughters
    (
        daughterSizeDistributionModel::New(dictOf(daughterDict), mix())
    );
    forAll(mix().names(), j)
    {
        const labelList grid
        (
            daughterSizeDistributionModel::classGrid(mix(), j)
        );
        const breakageWeights w = daughters->weights(j, grid, dust);
        SCOPED_TRACE(std::string(mix().names()[j]) + " " + daughterDict);

        // Volume: fragments on the grid plus dust = the parent, to round-off
        EXPECT_NEAR(w.volumeBalance(), 1, 1e-13);

        // Number: with the dust sink every fragment is counted
        if (dust)
        {
            EXPECT_NEAR
            (
                w.numberOnGrid() + w.dustNumber,
                fragmentsPerEvent,
                1e-12*fragmentsPerEvent
            );
        }
        EXPECT_NEAR(w.fragmentsPerEvent, fragmentsPerEvent, 1e-12*fragmentsPerEvent);

        // Volume is number times the class's particle volume
        forAll(w.volume, i)
        {
            EXPECT_GE(w.volume[i], 0);
            EXPECT_NEAR
            (
                w.volume[i],
                w.number[i]*mix().particleVolume(i)
               /mix().particleVolume(j),
                1e-14
            );
            // Only the parent's material receives fragments
            if (w.volume[i] > 0)
            {
                EXPECT_EQ(mix().rho(i), mix().rho(j));
                EXPECT_LE(mix().d(i), mix().d(j));
            }
        }
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

TEST(breakageWeights, classGridIsOneMaterialByIncreasingSize)
{
    const labelList grid
    (
        daughterSizeDistributionModel::classGrid(mix(), species("s3"))
    );
    ASSERT_EQ(grid.size(), 4);
    EXPECT_EQ(grid[0], species("s0"));
    EXPECT_EQ(grid[1], species("s1"));
    EXPECT_EQ(grid[2], species("s2"));
    EXPECT_EQ(grid[3], species("s3"));

    const labelList glassGrid
    (
        daughterSizeDistributionModel::classGrid(mix(), species("glass"))
    );
    ASSERT_EQ(glassGrid.size(), 1);
    EXPECT_EQ(glassGrid[0], species("glass"));
}


TEST(breakageWeights, uniformBinaryConservesVolumeAndNumber)
{
    expectConserving("model uniformBinary;", true, 2);
    expectConserving("model uniformBinary;", false, 2);
}


TEST(breakageWeights, austinConservesVolumeAndNumber)
{
    // gamma/3 = 1.5, beta/3 = 2: c p/(p - 1) = 0.4*3 + 0.6*2 = 2.4
    expectConserving
    (
        "model austin; austinCoeffs { phi 0.4; gamma 4.5; beta 6; }",
        true,
        2.4
    );
    // gamma/3 <= 1: infinitely many fines, volume still kept to round-off
    autoPtr<daughterSizeDistributionModel> daughters
    (
        daughterSizeDistributionModel::New
        (
            dictOf("model austin; austinCoeffs { phi 0.4; gamma 0.9; beta 4; }"),
            mix()
        )
    );
    forAll(mix().names(), j)
    {
        const breakageWeights w = daughters->weights
        (
            j,
            daughterSizeDistributionModel::classGrid(mix(), j),
            true
        );
        EXPECT_NEAR(w.volumeBalance(), 1, 1e-13);
        EXPECT_TRUE(std::isinf(w.dustNumber) || w.dustVolume == 0);
        EXPECT_TRUE(std::isfinite(w.numberOnGrid()));
    }
}


TEST(breakageWeights, austinIsContinuousThroughExponentOne)
{
    // gamma = 3 is p = 1 in volume (a logarithm in the number integral);
    // just beside it the general form must give the same weights
    autoPtr<daughterSizeDistributionModel> at
    (
        daughterSizeDistributionModel::New
        (
            dictOf("model austin; austinCoeffs { phi 0.5; gamma 3; beta 6; }"),
            mix()
        )
    );
    autoPtr<daughterSizeDistributionModel> beside
    (
        daughterSizeDistributionModel::New
        (
            dictOf("model austin; austinCoeffs { phi 0.5; gamma 3.000000003; beta 6; }"),
            mix()
        )
    );
    const label p = species("s4");
    const labelList grid(daughterSizeDistributionModel::classGrid(mix(), p));
    const breakageWeights w1 = at->weights(p, grid, true);
    const breakageWeights w2 = beside->weights(p, grid, true);
    EXPECT_NEAR(w1.volumeBalance(), 1, 1e-13);
    EXPECT_TRUE(std::isinf(w1.dustNumber));
    forAll(w1.number, i)
    {
        EXPECT_TRUE(std::isfinite(w1.number[i]));
        EXPECT_NEAR(w1.number[i], w2.number[i], 1e-8*(1 + w1.number[i]));
    }
}


TEST(breakageWeights, fixedPivotByHandOnTwoClasses)
{
    // Parent s1 (x1) over s0 (x0), uniform binary b = 2/x1:
    //   retained  N_1 = int_x0^x1 (v - x0)/(x1 - x0) 2/x1 dv = (x1 - x0)/x1
    //   to s0     N_0 = int_x0^x1 (x1 - v)/(x1 - x0) 2/x1 dv = (x1 - x0)/x1
    //   dust      2 x0/x1 fragments, volume fraction (x0/x1)^2
    // With fines finestClass the dust volume joins s0 as (x0/x1)^2 x1/x0
    // = x0/x1 particles
    const scalar x0 = volumeOf("s0");
    const scalar x1 = volumeOf("s1");
    autoPtr<daughterSizeDistributionModel> daughters
    (
        daughterSizeDistributionModel::New(dictOf("model uniformBinary;"), mix())
    );
    const label p = species("s1");
    const labelList grid(daughterSizeDistributionModel::classGrid(mix(), p));

    const breakageWeights dust = daughters->weights(p, grid, true);
    EXPECT_NEAR(dust.number[p], (x1 - x0)/x1, 1e-14);
    EXPECT_NEAR(dust.number[species("s0")], (x1 - x0)/x1, 1e-14);
    EXPECT_NEAR(dust.dustNumber, 2*x0/x1, 1e-14);
    EXPECT_NEAR(dust.dustVolume, sqr(x0/x1), 1e-14);

    const breakageWeights fines = daughters->weights(p, grid, false);
    EXPECT_NEAR(fines.number[species("s0")], (x1 - x0)/x1 + x0/x1, 1e-14);
    EXPECT_EQ(fines.dustVolume, 0);

    // The finest class: everything to dust, or nothing happens
    const label f = species("s0");
    const labelList finest(daughterSizeDistributionModel::classGrid(mix(), f));
    EXPECT_NEAR(daughters->weights(f, finest, true).dustVolume, 1, 1e-15);
    EXPECT_NEAR(daughters->weights(f, finest, false).volume[f], 1, 1e-15);
}


TEST(breakageWeights, tableGivesSpeciesFractions)
{
    autoPtr<daughterSizeDistributionModel> daughters
    (
        daughterSizeDistributionModel::New
        (
            dictOf
            (
                "model table; tableCoeffs"
                "{ s4 { s3 0.5; s1 0.3; dust 0.2; } s2 { s0 1; } }"
            ),
            mix()
        )
    );
    const label p = species("s4");
    const breakageWeights w = daughters->weights
    (
        p,
        daughterSizeDistributionModel::classGrid(mix(), p),
        true
    );
    EXPECT_EQ(w.volume[species("s3")], 0.5);
    EXPECT_EQ(w.volume[species("s1")], 0.3);
    EXPECT_EQ(w.dustVolume, 0.2);
    EXPECT_NEAR(w.number[species("s3")], 0.5*volumeOf("s4")/volumeOf("s3"), 1e-14);
    EXPECT_NEAR(w.volumeBalance(), 1, 1e-15);

    // Not listed: does not break
    const label q = species("s3");
    EXPECT_EQ
    (
        daughters->weights
        (
            q,
            daughterSizeDistributionModel::classGrid(mix(), q),
            true
        ).volume[q],
        1
    );
}


TEST(breakageWeights, tableRefusesBadFragments)
{
    auto weightsOf = [](const char* text, const word& parent, bool dust)
    {
        autoPtr<daughterSizeDistributionModel> daughters
        (
            daughterSizeDistributionModel::New(dictOf(text), mix())
        );
        const label p = species(parent);
        daughters->weights
        (
            p,
            daughterSizeDistributionModel::classGrid(mix(), p),
            dust
        );
    };

    // Fragment weights that do not conserve volume
    expectFoamError
    (
        [&]{ weightsOf("model table; tableCoeffs { s4 { s3 0.5; s1 0.4; } }", "s4", false); },
        {"s4", "sum to 0.9", "must sum to 1"}
    );
    // A species breaking into a coarser one
    expectFoamError
    (
        [&]{ weightsOf("model table; tableCoeffs { s1 { s3 1; } }", "s1", false); },
        {"'s3'", "not finer than the parent s1", "valid: 1(s0)"}
    );
    // Into another material
    expectFoamError
    (
        [&]{ weightsOf("model table; tableCoeffs { s2 { glass 1; } }", "s2", false); },
        {"'glass'", "another material"}
    );
    // Dust without the dust sink
    expectFoamError
    (
        [&]{ weightsOf("model table; tableCoeffs { s1 { s0 0.5; dust 0.5; } }", "s1", false); },
        {"'dust'", "fines dust"}
    );
    // Negative fraction
    expectFoamError
    (
        [&]{ weightsOf("model table; tableCoeffs { s2 { s1 1.5; s0 -0.5; } }", "s2", false); },
        {"'s0 -0.5'", ">= 0"}
    );
    // Unknown parent species
    expectFoamError
    (
        []{ daughterSizeDistributionModel::New(dictOf("model table; tableCoeffs { s9 { s0 1; } }"), mix()); },
        {"s9"}
    );
}


TEST(breakageWeights, unknownDaughterModelListsTheValidNames)
{
    expectFoamError
    (
        []{ daughterSizeDistributionModel::New(dictOf("model fancy;"), mix()); },
        {"fancy", "uniformBinary", "austin", "table"}
    );
    expectFoamError
    (
        []{ daughterSizeDistributionModel::New(dictOf("model austin; austinCoeffs { phi 0.4; gamma 1; }"), mix()); },
        {"beta"}
    );
    expectFoamError
    (
        []{ daughterSizeDistributionModel::New(dictOf("model austin; austinCoeffs { phi 1.4; gamma 1; beta 3; }"), mix()); },
        {"'phi 1.", "austinCoeffs", "[0, 1]"}
    );
}


// ************************************************************************* //

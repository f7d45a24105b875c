// The calibration store: a condition written and read back, the layout
// (root attributes, condition names), the settings fingerprint, refusal of
// foreign, corrupt and truncated files, atomic writes.
#include "store/Store.hpp"
#include "StoreTestData.hpp"

#include "io/Hdf5File.hpp"
#include "io/tests/TemporaryDirectory.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace sdf::store;
using sdf::io::test::TemporaryDirectory;
using sdf::store::test::inputs;
using sdf::store::test::shearedInputs;
using sdf::store::test::syntheticResult;

namespace
{

//- Expects statement to throw StoreError naming file; returns its message.
template<class F>
std::string expectStoreError(F statement, const std::string& file)
{
    try
    {
        statement();
    }
    catch (const StoreError& e)
    {
        EXPECT_EQ(e.file(), file);
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
        return e.message();
    }
    catch (const std::exception& e)
    {
        ADD_FAILURE() << "not a StoreError: " << e.what();
        return "";
    }
    ADD_FAILURE() << "no exception";
    return "";
}

} // namespace


TEST(store, conditionNamesUseSixSignificantDigits)
{
    EXPECT_EQ(conditionName(0.3, 0.4, 0.01, 1), "phi0.3_x0.4_T0.01_seed1");
    EXPECT_EQ(conditionName(0.123456789, 0.5, 1e-4, 12), "phi0.123457_x0.5_T0.0001_seed12");
}


TEST(store, shearedConditionsCarryTheirShearRateAndR)
{
    EXPECT_EQ(shearedConditionName(0.5, 0.4, 20, 1), "phi0.5_x0.4_gammaDot20_seed1");
    EXPECT_EQ(sizedConditionName(conditionName(0.3, 0.4, 0.01, 1), 300), "phi0.3_x0.4_T0.01_seed1_N300");

    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    sdf::dem::CellRunResult r = syntheticResult();
    r.savageJeffreyR = 1.7;
    const std::string key = settingsKey(r.settings, "linearSpringDashpot");
    appendCondition(h5, "small", "large", key, shearedInputs(0.5, 0.4, 20, 1), r);
    appendCondition(h5, "small", "large", key, inputs(0.5, 0.4, 0.01, 1), r);

    const StoreContents contents = readStore(h5);
    ASSERT_EQ(contents.conditions.size(), 2u);
    const ConditionRecord& driven = contents.conditions[0];    // sorted by name: _T before _g
    const ConditionRecord& sheared = contents.conditions[1];
    EXPECT_EQ(sheared.name, "phi0.5_x0.4_gammaDot20_seed1");
    ASSERT_TRUE(sheared.gammaDot);
    EXPECT_EQ(*sheared.gammaDot, 20.0);
    ASSERT_TRUE(sheared.savageJeffreyR);
    EXPECT_EQ(*sheared.savageJeffreyR, 1.7);
    EXPECT_EQ(sheared.targetT, 0.0);
    EXPECT_EQ(sheared.T, r.temperature);
    // a driven condition has no shear rate and no R
    EXPECT_FALSE(driven.gammaDot);
    EXPECT_FALSE(driven.savageJeffreyR);
    EXPECT_EQ(driven.targetT, 0.01);
    // the layout: gammaDot instead of targetT
    const sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group g = f.root().openGroup("conditions/" + sheared.name);
    EXPECT_TRUE(g.hasAttribute("gammaDot"));
    EXPECT_FALSE(g.hasAttribute("targetT"));
}


TEST(store, writesAndReadsBackACondition)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const sdf::dem::CellRunResult r = syntheticResult();
    const std::string key = settingsKey(r.settings, "linearSpringDashpot");

    appendCondition(h5, "small", "large", key, inputs(0.3, 0.4, 0.01, 1), r);
    appendCondition(h5, "small", "large", key, inputs(0.2, 0.4, 0.01, 1), syntheticResult(2));

    const StoreContents contents = readStore(h5);
    EXPECT_EQ(contents.fineSpecies, "small");
    EXPECT_EQ(contents.coarseSpecies, "large");
    ASSERT_EQ(contents.conditions.size(), 2u);
    const ConditionRecord& c = contents.conditions[1];   // sorted by name
    EXPECT_EQ(c.name, "phi0.3_x0.4_T0.01_seed1");
    EXPECT_EQ(c.phi, 0.3);
    EXPECT_EQ(c.x, 0.4);
    EXPECT_EQ(c.targetT, 0.01);
    EXPECT_EQ(c.particles, 200);
    EXPECT_EQ(c.T, r.temperature);
    EXPECT_EQ(c.fine.D, r.species[0].greenKubo.integral.value);
    EXPECT_EQ(*c.fine.DError, r.species[0].greenKubo.integral.standardError);
    EXPECT_EQ(*c.coarse.eta, r.kineticSieving[1].value);
    EXPECT_EQ(*c.coarse.etaError, r.kineticSieving[1].standardError);
    EXPECT_EQ(*c.coarse.etaWithCrossTerms, r.kineticSievingWithCrossTerms[1].value);
    EXPECT_EQ(*c.coarse.etaWithCrossTermsError, r.kineticSievingWithCrossTerms[1].standardError);
    EXPECT_EQ(contents.conditions[0].fine.D, 2*r.species[0].greenKubo.integral.value);
    // the diffusive-regime check read back: the fines converged, the coarse not
    EXPECT_EQ(*c.fine.DMsd, r.species[0].diffusivityMsd.value);
    EXPECT_EQ(*c.fine.DMsdError, r.species[0].diffusivityMsd.standardError);
    ASSERT_TRUE(c.fine.DConverged);
    EXPECT_TRUE(*c.fine.DConverged);
    EXPECT_EQ(c.fine.DVerdict, "diffusive");
    ASSERT_TRUE(c.coarse.DConverged);
    EXPECT_FALSE(*c.coarse.DConverged);
    EXPECT_EQ(c.coarse.DSlopeChange, 3e-7);
    EXPECT_EQ(c.coarse.DDrift, -2e-8);
    EXPECT_NE(c.coarse.DVerdict.find("MSD slope not flat"), std::string::npos) << c.coarse.DVerdict;

    const auto keys = storedSettingsKeys(h5);
    ASSERT_EQ(keys.size(), 2u);
    EXPECT_EQ(keys.at(c.name), key);

    // The layout the other readers (h5dump, h5py, docs) rely on
    const sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group root = f.root();
    EXPECT_EQ(root.readString("content"), contentName);
    const sdf::io::Group g = root.openGroup("conditions/" + c.name);
    EXPECT_EQ(g.readInt64("seed"), 1);
    EXPECT_EQ(g.readInt64("particles"), 200);
    EXPECT_EQ(g.readInt64("equilibrated"), 1);
    EXPECT_EQ(g.readInt64("steps"), 12345);
    EXPECT_EQ(g.openGroup("species/small").readString("role"), "fine");
    EXPECT_EQ(g.openGroup("species/large").readString("role"), "coarse");
    EXPECT_EQ(g.openGroup("species/large").readDouble("d"), 2e-3);
    EXPECT_EQ(g.openGroup("species/large").readInt64("DPlateauFound"), 1);
    EXPECT_EQ(g.openGroup("species/large").readDouble("DMsd"), r.species[1].diffusivityMsd.value);
    EXPECT_EQ(g.openGroup("timing").readDouble("wallSeconds"), 1.5);
}


TEST(store, segregationCellsAreReadBackBesideTransportConditions)
{
    // a sheared cell under gravity beside a transport condition: its record read back
    // attribute by attribute, no species or T asked of it, the transport one as before
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const sdf::dem::CellRunResult r = syntheticResult();
    appendCondition(h5, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), r);

    sdf::dem::GravityShearRunResult g;
    g.settings.walls.normalStress = 368;
    g.settings.walls.wallSpeed = 0.4;
    g.settings.cell.particles = 3000;
    sdf::dem::SegregationMeasurement& m = g.segregation;
    m.fineDiameter = 1e-3; m.sizeRatio = 2; m.meanDiameter = 1.5e-3; m.solidsFraction = 0.62;
    m.pressureNumber = 13.8; m.inertialNumber = 0.058;
    m.early = {5.8e-5, 8.7e-6, 5}; m.earlyCoarseShare = 0.5; m.earlyShearRate = 17;
    m.balance = {7.3e-5, 5.5e-6, 5}; m.coarseShare = 0.52;
    m.shearRate = {17.7, 0.3, 5}; m.diffusivity = {1.9e-6, 1e-7, 5};
    m.shearRateDiffusivity = {0.049, 0.0034, 5}; m.diffusiveShare = 0.058; m.topWallLoad = 1.0004;
    ConditionInputs in;
    in.name = segregationConditionName(368, 0.5, 1);
    in.phi = 0.55;
    in.x = 0.5;
    in.normalStress = 368;
    in.seed = 1;
    appendSegregationCondition(h5, "small", "large", "gk", in, g);

    const StoreContents contents = readStore(h5);
    ASSERT_EQ(contents.conditions.size(), 2u);
    const ConditionRecord& t = contents.conditions[0];   // sorted by name: phi... < segregation...
    const ConditionRecord& c = contents.conditions[1];
    EXPECT_EQ(t.name, "phi0.3_x0.4_T0.01_seed1");
    EXPECT_FALSE(t.segregation);
    EXPECT_EQ(t.fine.D, r.species[0].greenKubo.integral.value);
    EXPECT_EQ(c.name, "segregation_sigma368_x0.5_seed1");
    ASSERT_TRUE(c.segregation);
    EXPECT_EQ(c.particles, 3000);
    const SegregationRecord& s = *c.segregation;
    EXPECT_EQ(s.normalStress, 368);
    EXPECT_EQ(s.wallSpeed, 0.4);
    EXPECT_EQ(s.pressureNumber, 13.8);
    EXPECT_EQ(s.inertialNumber, 0.058);
    EXPECT_EQ(s.early, 5.8e-5);
    EXPECT_EQ(s.earlyError, 8.7e-6);
    EXPECT_EQ(s.earlyShearRate, 17);
    EXPECT_EQ(s.balance, 7.3e-5);
    EXPECT_EQ(s.balanceError, 5.5e-6);
    EXPECT_EQ(s.coarseShare, 0.52);
    EXPECT_EQ(s.shearRate, 17.7);
    EXPECT_EQ(s.diffusivityError, 1e-7);
    EXPECT_EQ(s.shearRateDiffusivity, 0.049);
    EXPECT_EQ(s.shearRateDiffusivityError, 0.0034);
    EXPECT_EQ(s.diffusiveShare, 0.058);
    EXPECT_EQ(s.topWallLoad, 1.0004);
    EXPECT_EQ(storedSettingsKeys(h5).at(c.name), "gk");
    // the layout: the group and the load on the condition
    const sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group cg = f.root().openGroup("conditions/" + c.name);
    EXPECT_EQ(cg.readDouble("normalStress"), 368);
    EXPECT_EQ(cg.openGroup("segregation").readDouble("percolationLengthBalance"), 7.3e-5);
    EXPECT_FALSE(cg.hasGroup("species/small"));
}


TEST(store, writesAndReadsBackTheCollisionStatistics)
{
    // Collision counts and impact-energy histograms per species pair (breakage rates):
    // read back exactly, either pair order, frequencies per particle as the engine's
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const sdf::dem::CellRunResult r = syntheticResult();
    appendCondition(h5, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), r);

    const StoreContents contents = readStore(h5);
    ASSERT_EQ(contents.conditions.size(), 1u);
    const ConditionRecord& c = contents.conditions[0];
    ASSERT_TRUE(c.collisions.has_value());
    const CollisionRecord& col = *c.collisions;
    EXPECT_EQ(col.elapsedTime, r.collisions.elapsedTime);
    EXPECT_EQ(col.binEdges, r.collisions.binEdges);
    ASSERT_EQ(col.pairs.size(), 3u);
    const std::vector<std::string> names{"small", "large"};
    for (int a = 0; a < 2; ++a)
    {
        for (int b = 0; b < 2; ++b)
        {
            const int k = sdf::dem::speciesPairIndex(a, b, 2);
            const PairCollisionRecord* p = col.pair(names[a], names[b]);
            ASSERT_NE(p, nullptr) << names[a] << "/" << names[b];
            EXPECT_EQ(p->count, r.collisions.counts[k]);
            EXPECT_EQ(p->energySum, r.collisions.energySum[k]);
            EXPECT_EQ
            (
                p->histogram,
                std::vector<std::int64_t>(r.collisions.histogram[k].begin(), r.collisions.histogram[k].end())
            );
            ASSERT_TRUE(c.fine.count.has_value());
            const std::vector<int> speciesCounts{int(*c.fine.count), int(*c.coarse.count)};
            EXPECT_EQ
            (
                col.frequencyPerParticle(names[a], names[b], speciesCounts[a]),
                r.collisions.frequencyPerParticle(a, b, speciesCounts)
            );
        }
    }
    // stored in species order: (small, large), not (large, small)
    EXPECT_EQ(col.pair("large", "small")->first, "small");
    EXPECT_EQ(col.pair("small", "medium"), nullptr);
    EXPECT_THROW(col.frequencyPerParticle("small", "medium", 100), std::invalid_argument);
    EXPECT_THROW(col.frequencyPerParticle("small", "large", 0), std::invalid_argument);

    // The layout: integer counts and histograms (exact), the bin edges as doubles
    const sdf::io::File f = sdf::io::File::openReadOnly(h5);
    const sdf::io::Group g = f.root().openGroup("conditions/" + c.name + "/collisions");
    EXPECT_EQ(g.readDouble("elapsedTime"), 0.25);
    EXPECT_EQ(g.openGroup("small/large").readInt64("count"), r.collisions.counts[1]);
    EXPECT_TRUE(g.openGroup("large/large").isIntegerDataset("histogram"));
    EXPECT_FALSE(g.hasGroup("large/small"));

    // A condition stored before the collisions were (no group) reads as absent,
    // under the same settings key
    sdf::dem::CellRunResult old = syntheticResult(2);
    old.collisions = sdf::dem::CollisionStatistics();
    appendCondition(h5, "small", "large", "k", inputs(0.2, 0.4, 0.01, 1), old);
    const StoreContents both = readStore(h5);
    ASSERT_EQ(both.conditions.size(), 2u);
    EXPECT_FALSE(both.conditions[0].collisions.has_value());
    EXPECT_TRUE(both.conditions[1].collisions.has_value());
    EXPECT_EQ(storedSettingsKeys(h5).at(both.conditions[0].name), "k");
}


TEST(store, settingsKeyFingerprintsEveryDEMSetting)
{
    const sdf::dem::CellRunSettings base = syntheticResult().settings;
    const std::string key = settingsKey(base, "linearSpringDashpot");
    // the key of stores written before it was generated from the settings' table
    EXPECT_EQ
    (
        key,
        "species small:0.001:2500 large:0.002:2500; particles 200; contact linearSpringDashpot"
        " e 0.9 mu 0.5 kn 200000 kt/kn 0.2857142857 gt/gn 0.5 E 10000000 nu 0.3; timeStep 0;"
        " thermostatTime 0; equilibrationTime 0; maxEquilibrationTime 0; samplingTime 0;"
        " sampleEvery 10; blocks 8; mode nve; Green-Kubo within the MSD's lags"
    );
    EXPECT_EQ(settingsKey(base, "linearSpringDashpot"), key);
    EXPECT_NE(settingsKey(base, "hertzMindlin"), key);

    auto changed = [&](auto change)
    {
        sdf::dem::CellRunSettings s = base;
        change(s);
        return settingsKey(s, "linearSpringDashpot");
    };
    EXPECT_NE(changed([](auto& s) { s.particles = 201; }), key);
    EXPECT_NE(changed([](auto& s) { s.species[1].diameter = 2.1e-3; }), key);
    EXPECT_NE(changed([](auto& s) { s.simulation.contact.restitution = 0.8; }), key);
    EXPECT_NE(changed([](auto& s) { s.simulation.timeStep = 1e-6; }), key);
    EXPECT_NE(changed([](auto& s) { s.samplingTime = 0.02; }), key);
    EXPECT_NE(changed([](auto& s) { s.blocks = 4; }), key);
    // The condition is not part of the fingerprint
    EXPECT_EQ(changed([](auto& s) { s.solidsFraction = 0.45; s.seed = 7; }), key);

    // Per-pair constants are, in a canonical order: the same pairs given in another
    // order (or with a pair's names swapped) make the same key
    const auto pair = [](const char* a, const char* b, double e)
    {
        sdf::dem::PairContactSettings p;
        p.first = a;
        p.second = b;
        p.restitution = e;
        return p;
    };
    const std::string withPairs = changed([&](auto& s)
    {
        s.simulation.contact.pairs = {pair("small", "large", 0.7), pair("large", "large", 0.5)};
    });
    EXPECT_NE(withPairs, key);
    EXPECT_NE(withPairs.find("; pair large/large: e 0.5; pair large/small: e 0.7"), std::string::npos)
        << withPairs;
    EXPECT_EQ(changed([&](auto& s)
    {
        s.simulation.contact.pairs = {pair("large", "large", 0.5), pair("large", "small", 0.7)};
    }), withPairs);
    EXPECT_NE(changed([&](auto& s)
    {
        s.simulation.contact.pairs = {pair("small", "large", 0.6), pair("large", "large", 0.5)};
    }), withPairs);
}


TEST(store, conditionWithOtherSettingsIsRefused)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const sdf::dem::CellRunResult r = syntheticResult();
    const std::string key = settingsKey(r.settings, "linearSpringDashpot");
    const ConditionInputs c = inputs(0.3, 0.4, 0.01, 1);
    appendCondition(h5, "small", "large", key, c, r);

    const auto stored = storedSettingsKeys(h5);
    EXPECT_TRUE(isStored(h5, stored, c.name, key));
    EXPECT_FALSE(isStored(h5, stored, conditionName(0.3, 0.4, 0.01, 2), key));

    sdf::dem::CellRunSettings other = r.settings;
    other.particles = 500;
    const std::string otherKey = settingsKey(other, "linearSpringDashpot");
    try
    {
        isStored(h5, stored, c.name, otherKey);
        ADD_FAILURE() << "a condition run with other settings was accepted";
    }
    catch (const SettingsMismatch& e)
    {
        EXPECT_EQ(e.storedKey(), key);
        EXPECT_EQ(e.currentKey(), otherKey);
        EXPECT_NE(e.message().find(c.name), std::string::npos) << e.message();
        EXPECT_NE(e.message().find("particles 500"), std::string::npos) << e.message();
        EXPECT_EQ(e.addedSinceStored(), "");
    }
    // a store written before the Green-Kubo reading changed: its key is the current one
    // without the tag; refused, and the message names what the current key adds
    const std::string tag = "; Green-Kubo within the MSD's lags";
    ASSERT_EQ(key.substr(key.size() - tag.size()), tag);
    std::map<std::string, std::string> older = stored;
    older[c.name] = key.substr(0, key.size() - tag.size());
    try
    {
        isStored(h5, older, c.name, key);
        ADD_FAILURE() << "a condition stored before the measurement changed was accepted";
    }
    catch (const SettingsMismatch& e)
    {
        EXPECT_EQ(e.addedSinceStored(), tag);
        EXPECT_NE(e.message().find("move the store away"), std::string::npos) << e.message();
    }
}


TEST(store, foreignCorruptTruncatedAndMissingFilesAreRefused)
{
    const TemporaryDirectory dir;

    // Ours, but another content (e.g. a periodicDEM result)
    const std::string periodic = dir.file("periodicDEM.h5");
    sdf::io::File::create(periodic).root().setAttribute("content", "periodicDEM cell");
    EXPECT_NE
    (
        expectStoreError([&] { storedSettingsKeys(periodic); }, periodic)
            .find("not a calibration store"),
        std::string::npos
    );
    expectStoreError([&] { readStore(periodic); }, periodic);
    const auto sizeBefore = std::filesystem::file_size(periodic);
    expectStoreError
    (
        [&]
        {
            appendCondition
            (
                periodic, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), syntheticResult()
            );
        },
        periodic
    );
    EXPECT_EQ(std::filesystem::file_size(periodic), sizeBefore);   // untouched

    // Not HDF5 at all
    const std::string text = dir.file("text.h5");
    std::ofstream(text) << "not an HDF5 file\n";
    expectStoreError([&] { storedSettingsKeys(text); }, text);

    // A store cut short (a copy interrupted, a full disk)
    const std::string h5 = dir.file("calibration.h5");
    appendCondition(h5, "small", "large", "k", inputs(0.3, 0.4, 0.01, 1), syntheticResult());
    const auto size = std::filesystem::file_size(h5);
    std::filesystem::resize_file(h5, size/2);
    expectStoreError([&] { storedSettingsKeys(h5); }, h5);
    expectStoreError([&] { readStore(h5); }, h5);

    // Missing: no conditions for the index, an error for a reader
    EXPECT_TRUE(storedSettingsKeys(dir.file("none.h5")).empty());
    expectStoreError([&] { readStore(dir.file("none.h5")); }, dir.file("none.h5"));
}


TEST(store, failedAppendLeavesTheStoreAsItWas)
{
    const TemporaryDirectory dir;
    const std::string h5 = dir.file("calibration.h5");
    const ConditionInputs c = inputs(0.3, 0.4, 0.01, 1);
    appendCondition(h5, "small", "large", "k", c, syntheticResult());

    // The same condition again: the group exists, the append fails midway
    const std::string message = expectStoreError
    (
        [&] { appendCondition(h5, "small", "large", "k", c, syntheticResult(3)); }, h5
    );
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
    EXPECT_FALSE(std::filesystem::exists(h5 + ".tmp"));
    const StoreContents contents = readStore(h5);
    ASSERT_EQ(contents.conditions.size(), 1u);
    EXPECT_EQ(contents.conditions[0].fine.D, syntheticResult().species[0].greenKubo.integral.value);
}


TEST(store, textFilesAreWrittenAtomically)
{
    const TemporaryDirectory dir;
    const std::string file = dir.file("granularCoefficients");
    writeTextAtomically(file, "first\n");
    writeTextAtomically(file, "second\n");
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "second");
    EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));

    const std::string nowhere = dir.file("missing/granularCoefficients");
    expectStoreError([&] { writeTextAtomically(nowhere, "x"); }, nowhere);
}

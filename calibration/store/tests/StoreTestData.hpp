// Test helper: a finished DEM condition as the engine returns it (values
// chosen, no run), so that the store's layout can be written and read back.
#ifndef sdf_store_tests_StoreTestData_hpp
#define sdf_store_tests_StoreTestData_hpp

#include "store/Store.hpp"

#include <string>
#include <vector>

namespace sdf::store::test
{

inline dem::CellRunResult syntheticResult(double scale = 1)
{
    dem::CellRunResult r;
    r.settings.species = {{"small", 1e-3, 2500}, {"large", 2e-3, 2500}};
    r.settings.particles = 200;
    r.temperature = 0.01*scale;
    r.temperatureError = 1e-4*scale;
    r.equilibrated = true;
    r.equilibrationTime = 0.002;
    r.timeStep = 1e-6;
    r.boxLength = 0.0123;
    r.steps = 12345;
    for (const auto& sp : r.settings.species)
    {
        dem::SpeciesTransport st;
        st.name = sp.name;
        st.count = 100;
        st.temperature = 0.0101*scale;
        st.greenKubo.integral.value = 1.234567890123e-5*scale*sp.diameter/1e-3;
        st.greenKubo.integral.standardError = 1e-7*scale;
        st.greenKubo.plateauFound = true;
        st.diffusivityMsd.value = 1.2e-5*scale;
        st.diffusivityMsd.standardError = 2e-7*scale;
        // the fines pass the diffusive-regime check, the coarse fail on the slope
        auto& check = st.diffusiveRegime;
        check.correlationTime = 1e-3;
        check.fitStart = 5e-3;
        check.fitEnd = 2e-2;
        check.measured = check.windowPastDecay = check.greenKuboAgrees = check.plateauFound = true;
        check.stationary = true;
        check.slopeFlat = sp.name != "large";
        check.slopeChange = {check.slopeFlat ? 1e-8 : 3e-7, 1e-7, 8};
        check.drift = {-2e-8, 1e-7, 8};
        r.species.push_back(st);
    }
    r.kineticSieving = {{3e-9*scale, 1e-10*scale, 0}, {7e-9*scale, 2e-10*scale, 0}};
    r.kineticSievingWithCrossTerms = {{4e-9*scale, 1.5e-10*scale, 0}, {9e-9*scale, 3e-10*scale, 0}};
    // collisions: 3 log bins, pairs (small, small), (small, large), (large, large);
    // each pair's histogram (under, bins, over) adds up to its count
    r.collisions.reset(2, 1e-9*scale, 1e-6*scale, 3);
    r.collisions.elapsedTime = 0.25;
    for (int k = 0; k < 3; ++k)
    {
        r.collisions.histogram[k] = {k, 10 + k, 20*(k + 1), 5, 1};
        r.collisions.counts[k] = 0;
        for (long c : r.collisions.histogram[k]) r.collisions.counts[k] += c;
        r.collisions.energySum[k] = 1.0123456789e-7*scale*(k + 1);
    }
    r.wallSeconds = 1.5;
    r.cpuSeconds = 1.4;
    r.particleStepsPerSecond = 1e6;
    return r;
}

inline ConditionInputs inputs(double phi, double x, double T, std::int64_t seed)
{
    ConditionInputs in;
    in.name = conditionName(phi, x, T, seed);
    in.phi = phi;
    in.x = x;
    in.targetT = T;
    in.seed = seed;
    return in;
}

inline ConditionInputs shearedInputs(double phi, double x, double gammaDot, std::int64_t seed)
{
    ConditionInputs in = inputs(phi, x, 0, seed);
    in.name = shearedConditionName(phi, x, gammaDot, seed);
    in.gammaDot = gammaDot;
    return in;
}

} // namespace sdf::store::test

#endif

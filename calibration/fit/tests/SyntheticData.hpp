// DEM-free synthetic tables for the fit tests: a seed-like envelope
// (phi 0.1..0.5, x in {0.2, 0.4}, T over two decades, a few diameters) and
// values from a known law with multiplicative Gaussian noise, sigma being the
// relative error times the measured value (what a Green-Kubo run reports).
#ifndef sdf_fit_tests_SyntheticData_hpp
#define sdf_fit_tests_SyntheticData_hpp

#include "fit/ConstitutiveLaw.hpp"
#include "fit/FitData.hpp"
#include "fit/Laws.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace sdf::fit::test
{

inline std::vector<Condition> seedLikeEnvelope()
{
    std::vector<Condition> conditions;
    for (const double phi : {0.1, 0.2, 0.3, 0.4, 0.5})
    {
        for (const double x : {0.2, 0.4})
        {
            for (const double T : {1e-3, 4.6e-3, 2.2e-2, 1e-1})
            {
                for (const double d : {1e-3, 2e-3, 4e-3})
                {
                    conditions.push_back(Condition{phi, x, T, d, std::nullopt, std::nullopt});
                }
            }
        }
    }
    return conditions;
}

inline std::vector<Observation> synthetic
(
    const ConstitutiveLaw& law,
    const Eigen::VectorXd& trueParameters,
    const std::vector<Condition>& conditions,
    double relativeNoise,
    std::mt19937_64& engine
)
{
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Observation> data;
    for (const Condition& c : conditions)
    {
        const double exact = law.evaluate(c, trueParameters);
        const double measured = exact * (1.0 + relativeNoise * normal(engine));
        data.push_back(Observation{c, measured, relativeNoise * std::abs(measured)});
    }
    return data;
}

//- The seed's values of SeedPowerLaw (its eq 15): D = 6 (1 + x) T phi^-1.5.
inline Eigen::VectorXd seedPowerLawValues()
{
    Eigen::VectorXd values(4);
    values << 6.0, 1.0, 1.0, -1.5;
    return values;
}

//- A table from SeedPowerLaw with the seed's values over the seed-like envelope, 3 %
//  noise drawn from a generator seeded with seed.
inline std::vector<Observation> seedPowerLawData(std::uint64_t seed)
{
    std::mt19937_64 engine(seed);
    return synthetic(SeedPowerLaw{}, seedPowerLawValues(), seedLikeEnvelope(), 0.03, engine);
}

} // namespace sdf::fit::test

#endif

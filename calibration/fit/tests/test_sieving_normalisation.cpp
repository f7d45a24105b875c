// The engine's Green-Kubo eta (kg^2 m s^-3) to m2/s: hand values of the bulk
// density, the number-mean particle mass and the conversion; bad input named.
#include "fit/SievingNormalisation.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace sdf::fit;

TEST(SievingNormalisation, MeanParticleMassOfTheSeedMixture)
{
    const SphereSpecies fine{1e-3, 2500}, coarse{2e-3, 2500};
    const double vf = M_PI * 1e-9 / 6, vc = 8 * vf;
    // 40 % coarse by solids volume: number fractions from 0.6/vf and 0.4/vc
    const double expected = (0.6 * 2500 + 0.4 * 2500) / (0.6 / vf + 0.4 / vc);
    EXPECT_NEAR(meanParticleMass(0.4, fine, coarse) / expected, 1.0, 1e-14);
    // one species only: its particle mass
    EXPECT_NEAR(meanParticleMass(0.0, fine, coarse) / (2500 * vf), 1.0, 1e-14);
    EXPECT_NEAR(meanParticleMass(1.0, fine, coarse) / (2500 * vc), 1.0, 1e-14);
}

TEST(SievingNormalisation, KinematicCoefficientHandValue)
{
    const SphereSpecies fine{1e-3, 2500}, coarse{2e-3, 3000};
    const double phi = 0.5, x = 0.3, T = 0.03, eta = 2e-9;
    const double rhoBulk = 0.5 * (0.7 * 2500 + 0.3 * 3000);
    const double mMean = meanParticleMass(x, fine, coarse);
    EXPECT_NEAR
    (
        kinematicSievingCoefficient(eta, phi, x, T, fine, coarse)
      / (eta / (rhoBulk * mMean * 0.01)),
        1.0, 1e-14
    );
    // linear in eta (errors convert with the same factor)
    EXPECT_NEAR
    (
        kinematicSievingCoefficient(3 * eta, phi, x, T, fine, coarse)
      / kinematicSievingCoefficient(eta, phi, x, T, fine, coarse),
        3.0, 1e-14
    );
}

TEST(SievingNormalisation, BadInputIsNamed)
{
    const SphereSpecies fine{1e-3, 2500}, coarse{2e-3, 2500};
    EXPECT_THROW(kinematicSievingCoefficient(1, 0.0, 0.4, 0.01, fine, coarse), std::invalid_argument);
    EXPECT_THROW(kinematicSievingCoefficient(1, 0.5, 0.4, -1, fine, coarse), std::invalid_argument);
    EXPECT_THROW(kinematicSievingCoefficient(1, 0.5, 1.4, 0.01, fine, coarse), std::invalid_argument);
    EXPECT_THROW
    (
        kinematicSievingCoefficient(1, 0.5, 0.4, 0.01, SphereSpecies{0, 2500}, coarse),
        std::invalid_argument
    );
    try
    {
        kinematicSievingCoefficient(1, 0.5, 0.4, 0.0, fine, coarse);
        FAIL() << "T = 0 accepted";
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("T > 0"), std::string::npos) << e.what();
    }
}

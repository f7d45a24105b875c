// Lees-Edwards simple shear of an inelastic frictional bidisperse cell: linear mean
// velocity profile (R^2 > 0.99), momentum conserved, no particle lost, steady T.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

TEST(LeesEdwards, LinearProfileMomentumAndSteadyTemperature)
{
    const auto species = test::binary(2.0);
    const double shearRate = 100.0;
    Packing packing = test::packedCell(species, {400, 50}, 0.45, 0.0, shearRate, 5);
    const SimulationSettings s = test::shearedCell(shearRate, 0.7, 0.3);
    Simulation sim(species, s, packing.particles, packing.box);
    const std::size_t n0 = sim.particles().size();
    const double ly = sim.box().ly;

    auto peculiarMomentum = [&](const Simulation& x)
    {
        const Particles& p = x.particles();
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            m += p.mass[i]*x.fluctuatingVelocity(int(i));
        }
        return m;
    };
    double totalMass = 0;
    for (double m : sim.particles().mass) totalMass += m;
    const double momentumScale = totalMass*shearRate*ly;
    const Eigen::Vector3d m0 = peculiarMomentum(sim);

    const int nSlabs = 8;
    std::vector<double> slabSum(nSlabs, 0.0), slabCount(nSlabs, 0.0);
    std::vector<double> temperatures;
    double maxMomentumError = 0;
    bool allInside = true;

    // strain 8 in total: 3 to reach the steady state, then sample
    const double dt = sim.timeStep();
    const long steps = std::lround(8.0/shearRate/dt);
    const long warmup = std::lround(3.0/shearRate/dt);
    long step = 0;
    sim.run(steps, [&](const Simulation& x)
    {
        step += 50;
        const Particles& p = x.particles();
        maxMomentumError = std::max(maxMomentumError, (peculiarMomentum(x) - m0).norm()/momentumScale);
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            if (p.x[i] < 0 || p.x[i] >= x.box().lx || p.y[i] < 0 || p.y[i] >= ly
             || p.z[i] < 0 || p.z[i] >= x.box().lz)
            {
                allInside = false;
            }
        }
        temperatures.push_back(x.temperature());
        if (step < warmup) return;
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const int slab = std::min(nSlabs - 1, int(p.y[i]/ly*nSlabs));
            slabSum[slab] += p.vx[i];
            slabCount[slab] += 1;
        }
    }, 50);

    EXPECT_EQ(sim.particles().size(), n0);
    EXPECT_TRUE(allInside);
    EXPECT_LT(maxMomentumError, 1e-12) << "peculiar momentum not conserved";

    // linear fit of the slab mean velocity against the slab centre
    std::vector<double> yc(nSlabs), u(nSlabs);
    for (int k = 0; k < nSlabs; ++k)
    {
        yc[k] = (k + 0.5)*ly/nSlabs;
        u[k] = slabSum[k]/slabCount[k];
    }
    double my = 0, mu = 0;
    for (int k = 0; k < nSlabs; ++k) { my += yc[k]/nSlabs; mu += u[k]/nSlabs; }
    double sxy = 0, sxx = 0, syy = 0;
    for (int k = 0; k < nSlabs; ++k)
    {
        sxy += (yc[k] - my)*(u[k] - mu);
        sxx += (yc[k] - my)*(yc[k] - my);
        syy += (u[k] - mu)*(u[k] - mu);
    }
    const double r2 = sxy*sxy/(sxx*syy);
    const double slope = sxy/sxx;
    std::cout << "profile R^2 = " << r2 << ", slope/gammaDot = " << slope/shearRate << "\n";
    EXPECT_GT(r2, 0.99);
    EXPECT_NEAR(slope/shearRate, 1.0, 0.1);

    // steady state: mean T over strain 3-5.5 and 5.5-8 agree within 15 %
    const std::size_t n = temperatures.size();
    const std::size_t a = std::size_t(n*3.0/8), b = std::size_t(n*5.5/8);
    double t1 = 0, t2 = 0;
    for (std::size_t k = a; k < b; ++k) t1 += temperatures[k]/(b - a);
    for (std::size_t k = b; k < n; ++k) t2 += temperatures[k]/(n - b);
    const double dMean = 1.1e-3;
    std::cout << "T/(gammaDot d)^2: " << t1/std::pow(shearRate*dMean, 2) << ", "
              << t2/std::pow(shearRate*dMean, 2) << "\n";
    EXPECT_GT(t1, 0);
    EXPECT_NEAR(t2/t1, 1.0, 0.15);
}

TEST(LeesEdwards, ImageVelocityShiftMakesStreamingPairsRelativelyAtRest)
{
    // two particles in the streaming profile across the y boundary: their relative
    // velocity through the image must be zero (the ghost velocity is shifted)
    PeriodicBox box;
    box.lx = box.ly = box.lz = 0.01;
    box.shearRate = 20;
    box.offset = 0.0037;
    const double yTop = 0.0099, yBottom = 0.0001;
    double dx = 0.002 - 0.003, dy = yTop - yBottom, dz = 0;
    double dvx = box.streamingVelocity(yTop) - box.streamingVelocity(yBottom);
    box.minimumImage(dx, dy, dz, dvx);
    EXPECT_NEAR(dy, -0.0002, 1e-15);
    EXPECT_NEAR(dvx, box.shearRate*dy, 1e-12);
}

TEST(LeesEdwards, MillionStepsKeepEveryParticleAndMomentum)
{
    // acceptance: no particle lost over 1e6 steps (strain 100), momentum conserved
    const auto species = test::binary(2.0);
    const double shearRate = 100.0;
    Packing packing = test::packedCell(species, {130, 16}, 0.45, 0.0, shearRate, 23);
    SimulationSettings s = test::shearedCell(shearRate, 0.7, 0.5);
    s.timeStep = 1e-6;
    Simulation sim(species, s, packing.particles, packing.box);
    const std::size_t n0 = sim.particles().size();
    auto peculiarMomentum = [](const Simulation& x)
    {
        Eigen::Vector3d m = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < x.particles().size(); ++i)
        {
            m += x.particles().mass[i]*x.fluctuatingVelocity(int(i));
        }
        return m;
    };
    double totalMass = 0;
    for (double m : sim.particles().mass) totalMass += m;
    const double scale = totalMass*shearRate*sim.box().ly;
    const Eigen::Vector3d m0 = peculiarMomentum(sim);
    bool inside = true;
    double maxError = 0, tSum = 0;
    long samples = 0;
    sim.run(1000000, [&](const Simulation& x)
    {
        const Particles& p = x.particles();
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            inside = inside && p.x[i] >= 0 && p.x[i] < x.box().lx && p.y[i] >= 0
                && p.y[i] < x.box().ly && p.z[i] >= 0 && p.z[i] < x.box().lz;
        }
        maxError = std::max(maxError, (peculiarMomentum(x) - m0).norm()/scale);
        tSum += x.temperature();
        ++samples;
    }, 10000);
    EXPECT_EQ(sim.stepCount(), 1000000);
    EXPECT_EQ(sim.particles().size(), n0);
    EXPECT_TRUE(inside);
    EXPECT_LT(maxError, 1e-11);
    const double dMean = 1.3e-3;
    const double reduced = tSum/samples/std::pow(shearRate*dMean, 2);
    std::cout << "1e6 steps: momentum error " << maxError << ", T/(gammaDot d)^2 = " << reduced << "\n";
    EXPECT_GT(reduced, 0.05);
    EXPECT_LT(reduced, 20);
}

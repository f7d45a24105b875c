// Initial states: growing radii reaches phi up to 0.6 without large overlaps, for size
// ratios 2 and 4; composition helpers.
#include "TestCells.hpp"

#include <gtest/gtest.h>

using namespace sdf::dem;

namespace
{

double solidsFraction(const Packing& p)
{
    double v = 0;
    for (std::size_t i = 0; i < p.particles.size(); ++i)
    {
        const double r = p.particles.radius[i];
        v += 4.0/3.0*M_PI*r*r*r;
    }
    return v/p.box.volume();
}

// brute-force maximum overlap / smaller diameter over all pairs (minimum image)
double bruteForceMaxOverlap(const Packing& p)
{
    double worst = 0;
    const Particles& q = p.particles;
    for (std::size_t i = 0; i < q.size(); ++i)
    {
        for (std::size_t j = i + 1; j < q.size(); ++j)
        {
            double dx = q.x[i] - q.x[j], dy = q.y[i] - q.y[j], dz = q.z[i] - q.z[j], dvx = 0;
            p.box.minimumImage(dx, dy, dz, dvx);
            const double ov = q.radius[i] + q.radius[j] - std::sqrt(dx*dx + dy*dy + dz*dz);
            worst = std::max(worst, ov/(2*std::min(q.radius[i], q.radius[j])));
        }
    }
    return worst;
}

//- n particles of the binary mixture of this size ratio and these solids volume fractions
//  packed at phi: checks phi and the overlaps.
Packing checkedBinaryPacking
(
    double ratio,
    const std::vector<double>& volumeFractions,
    int n,
    double phi,
    std::uint64_t seed
)
{
    const auto species = test::binary(ratio);
    PackingSettings ps;
    ps.solidsFraction = phi;
    ps.counts = countsFromVolumeFractions(species, volumeFractions, n);
    ps.seed = seed;
    const Packing p = makePacking(species, ps);
    EXPECT_NEAR(solidsFraction(p), phi, 1e-12);
    EXPECT_LT(bruteForceMaxOverlap(p), ps.overlapTolerance*1.0001);
    EXPECT_EQ(int(p.particles.size()), ps.counts[0] + ps.counts[1]);
    return p;
}

} // namespace

TEST(Packing, BinaryTwoToOneAtPhi060)
{
    const Packing p = checkedBinaryPacking(2.0, {0.6, 0.4}, 400, 0.6, 3);
    std::cout << "phi 0.6, 2:1, N = " << p.particles.size() << ": " << p.relaxationSteps
              << " relaxation steps, max overlap " << 100*bruteForceMaxOverlap(p) << " %\n";
}

TEST(Packing, BinaryFourToOneAtPhi050)
{
    const Packing p = checkedBinaryPacking(4.0, {0.5, 0.5}, 700, 0.5, 5);
    std::cout << "phi 0.5, 4:1, N = " << p.particles.size() << ": " << p.relaxationSteps
              << " relaxation steps\n";
}

TEST(Packing, CountsFromVolumeFractions)
{
    const auto species = test::binary(2.0);
    // equal solids volume: 8 fines per coarse
    const auto counts = countsFromVolumeFractions(species, {0.5, 0.5}, 900);
    EXPECT_EQ(counts[0] + counts[1], 900);
    EXPECT_EQ(counts[0], 800);
    EXPECT_EQ(counts[1], 100);
}

TEST(Packing, VelocitiesHaveRequestedTemperatureAndNoMomentum)
{
    const auto species = test::binary(2.0);
    Packing p = test::packedCell(species, {200, 25}, 0.3, 4e-3);
    double sum = 0, px = 0, py = 0, pz = 0;
    const Particles& q = p.particles;
    for (std::size_t i = 0; i < q.size(); ++i)
    {
        sum += q.vx[i]*q.vx[i] + q.vy[i]*q.vy[i] + q.vz[i]*q.vz[i];
        px += q.mass[i]*q.vx[i]; py += q.mass[i]*q.vy[i]; pz += q.mass[i]*q.vz[i];
    }
    EXPECT_NEAR(sum/q.size(), 4e-3, 1e-12);
    EXPECT_NEAR(px, 0, 1e-18);
    EXPECT_NEAR(py, 0, 1e-18);
    EXPECT_NEAR(pz, 0, 1e-18);
}

TEST(Packing, EquipartitionGivesEachSpeciesItsShareExactly)
{
    // each species' <|c|^2> inversely proportional to its mass (coarse 8 times heavier:
    // T_fine = 8 T_coarse), the number average T exact, no momentum; a species of one
    // particle stays at rest and the others carry T
    const auto species = std::vector<Species>{{"fine", 1e-3, 2500}, {"coarse", 2e-3, 2500},
                                              {"lone", 3e-3, 2500}};
    for (const std::vector<int>& counts : {std::vector<int>{200, 25, 0}, std::vector<int>{200, 25, 1}})
    {
        PackingSettings ps;
        ps.solidsFraction = 0.2;
        ps.counts = counts;
        Packing p = makePacking(species, ps);
        assignVelocities(p.particles, p.box, 4e-3, 0, 5, VelocityPartition::equipartition);
        const Particles& q = p.particles;
        std::vector<double> sum(3, 0);
        double all = 0;
        Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
        for (std::size_t i = 0; i < q.size(); ++i)
        {
            const double c2 = q.vx[i]*q.vx[i] + q.vy[i]*q.vy[i] + q.vz[i]*q.vz[i];
            sum[q.species[i]] += c2;
            all += c2;
            momentum += q.mass[i]*Eigen::Vector3d(q.vx[i], q.vy[i], q.vz[i]);
        }
        EXPECT_NEAR(all/q.size(), 4e-3, 1e-15);
        EXPECT_NEAR((sum[0]/counts[0])/(sum[1]/counts[1]), 8.0, 1e-12);
        EXPECT_EQ(sum[2], 0.0);
        EXPECT_LT(momentum.norm(), 1e-18);
    }
}

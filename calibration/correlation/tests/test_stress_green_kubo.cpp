#include "correlation/StressGreenKubo.hpp"
#include "OrnsteinUhlenbeck.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace sdf::correlation;
using sdf::correlation::test::OuParameters;
using sdf::correlation::test::makeOuTrajectory;

// Three stress parts built from independent Ornstein-Uhlenbeck series a, b, c
// (each integral D0 = variance tau): J1 = 2a, J2 = b, J12 = c + 0.3 J1. Exact:
// I11 = 4 D0, I22 = D0, I33 = 1.36 D0, I13 = I31 = 1.2 D0, other cross terms 0.
class StressGreenKubo : public ::testing::Test
{
protected:
    void SetUp() override
    {
        ou_.particles = 1;
        ou_.samples = 200000;
        ou_.seed = 99;
        const auto trajectory = makeOuTrajectory(ou_);
        parts_.assign(3, std::vector<double>(ou_.samples));
        for (std::size_t t = 0; t < ou_.samples; ++t)
        {
            const Eigen::RowVector3d abc = trajectory.velocities[t].row(0);
            parts_[0][t] = 2.0 * abc(0);
            parts_[1][t] = abc(1);
            parts_[2][t] = abc(2) + 0.3 * parts_[0][t];
        }
    }

    double exact(std::size_t i, std::size_t j) const
    {
        const double table[3][3] = {{4.0, 0.0, 1.2}, {0.0, 1.0, 0.0}, {1.2, 0.0, 1.36}};
        return table[i][j] * ou_.sampledDiffusivity();
    }

    OuParameters ou_;
    std::vector<std::vector<double>> parts_;
};

TEST_F(StressGreenKubo, NineProductIntegralsRatioAndSeedRule)
{
    const std::size_t blockCount = 10, maxLag = 400;
    std::vector<SeriesProductCorrelations> blocks;
    for (std::size_t b = 0; b < blockCount; ++b)
    {
        const IndexRange range = blockRange(ou_.samples, blockCount, b);
        std::vector<std::vector<double>> slice;
        for (const auto& p : parts_)
        {
            slice.emplace_back(p.begin() + range.begin, p.begin() + range.end);
        }
        blocks.push_back(seriesProductCorrelations(slice, maxLag));
    }
    const StressProductIntegrals r = stressProductIntegrals(uniformTimes(maxLag + 1, ou_.dt), blocks);
    const double d0 = ou_.sampledDiffusivity();
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            const Estimate& e = r.term(i, j).integral;
            EXPECT_NEAR(e.value, exact(i, j), 3.5 * e.standardError) << "term " << i << j;
            EXPECT_LT(e.standardError, 0.1 * std::max(std::abs(exact(i, j)), d0)) << "term " << i << j;
        }
    }
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            sum += exact(i, j);
        }
    }
    EXPECT_NEAR(r.total.integral.value, sum, 3.5 * r.total.integral.standardError);
    EXPECT_NEAR(r.crossToProductRatio, 2.4 / 6.36, 0.04);

    const std::vector<Estimate> eta = kineticSievingCoefficients(r, {0.3, 0.7});
    ASSERT_EQ(eta.size(), 2u);
    EXPECT_NEAR(eta[0].value, (4.0 + 0.3 * 1.36) * d0, 3.5 * eta[0].standardError);
    EXPECT_NEAR(eta[1].value, (1.0 + 0.7 * 1.36) * d0, 3.5 * eta[1].standardError);
    EXPECT_THROW(kineticSievingCoefficients(r, {1.0}), std::invalid_argument);

    // Cross terms kept: shares (1, 0, 0.3) and (0, 1, 0.7) of (J1, J2, J12):
    // eta_1 = I11 + 0.3 I33 + 1.3 I13 = 5.968 D0, eta_2 = I22 + 0.7 I33 + 0.7 I13 = 2.792 D0,
    // summing to the whole autocorrelation's 8.76 D0
    const std::vector<Estimate> kept = kineticSievingCoefficientsWithCrossTerms(r, {0.3, 0.7});
    ASSERT_EQ(kept.size(), 2u);
    EXPECT_NEAR(kept[0].value, 5.968 * d0, 3.5 * kept[0].standardError);
    EXPECT_NEAR(kept[1].value, 2.792 * d0, 3.5 * kept[1].standardError);
    EXPECT_THROW(kineticSievingCoefficientsWithCrossTerms(r, {1.0}), std::invalid_argument);
    std::cout << "[ figures  ] I11 " << r.term(0, 0).integral.value << " +- " << r.term(0, 0).integral.standardError
              << " (exact " << exact(0, 0) << "), I13 " << r.term(0, 2).integral.value << " +- "
              << r.term(0, 2).integral.standardError << " (exact " << exact(0, 2) << "), cross/product "
              << r.crossToProductRatio << " (exact " << 2.4 / 6.36 << ")\n";

    // The streaming correlator gives the same integrals within their errors.
    SeriesProductCorrelator streaming(3);
    const std::size_t blockLength = ou_.samples / blockCount;
    for (std::size_t t = 0; t < ou_.samples; ++t)
    {
        streaming.add(Eigen::Vector3d(parts_[0][t], parts_[1][t], parts_[2][t]));
        if ((t + 1) % blockLength == 0)
        {
            streaming.closeBlock();
        }
    }
    const StressProductIntegrals s = stressProductIntegrals(streaming.blocks(), ou_.dt, 3);
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            const double combined = std::hypot(s.term(i, j).integral.standardError, r.term(i, j).integral.standardError);
            EXPECT_NEAR(s.term(i, j).integral.value, r.term(i, j).integral.value, 3.0 * combined) << i << j;
        }
    }
    EXPECT_NEAR(s.total.integral.value, r.total.integral.value,
                3.0 * std::hypot(s.total.integral.standardError, r.total.integral.standardError));
    EXPECT_THROW(stressProductIntegrals(streaming.blocks(), ou_.dt, 2), std::invalid_argument);
}


TEST(StressAttribution, CrossTermsKeptSumToTheWholeAndReduceToTheSeedsRule)
{
    // Integrals set by hand: with the cross terms zero the two rules agree
    // exactly; with them the kept rule's eta sum to sum_ab I_ab
    auto integrals = [](const double table[3][3])
    {
        StressProductIntegrals r;
        r.seriesCount = 3;
        r.terms.resize(9);
        for (std::size_t i = 0; i < 9; ++i)
        {
            // an error only where there is a value: a zero term of the
            // diagonal table is exactly zero
            const double v = table[i / 3][i % 3];
            r.terms[i].integral = Estimate{v, v != 0.0 ? 0.01 : 0.0, 100};
        }
        return r;
    };
    const double diagonal[3][3] = {{2.0, 0.0, 0.0}, {0.0, 0.5, 0.0}, {0.0, 0.0, 0.8}};
    const std::vector<double> c = {0.8, 0.2};
    const auto seed = kineticSievingCoefficients(integrals(diagonal), c);
    const auto kept = kineticSievingCoefficientsWithCrossTerms(integrals(diagonal), c);
    for (std::size_t s = 0; s < 2; ++s)
    {
        EXPECT_DOUBLE_EQ(kept[s].value, seed[s].value);
        EXPECT_DOUBLE_EQ(kept[s].standardError, seed[s].standardError);
    }
    const double full[3][3] = {{2.0, -0.4, 0.6}, {-0.4, 0.5, 0.3}, {0.6, 0.3, 0.8}};
    const auto withCross = kineticSievingCoefficientsWithCrossTerms(integrals(full), c);
    double sum = 0.0;
    for (const auto& row : full) for (const double v : row) sum += v;
    EXPECT_NEAR(withCross[0].value + withCross[1].value, sum, 1e-14);
    // eta_1 = 2 + 0.8*0.8 + 2*(-0.4)*(1+0)/2 + 2*0.6*(1+0.8)/2 + 2*0.3*(0+0.8)/2 = 3.56
    EXPECT_NEAR(withCross[0].value, 3.56, 1e-14);
}

// A sheared cell's shear stress has a mean: the same three parts with constant offsets
// (m = 3, -2 and 1 standard deviations of J1, J2 and J12's OU part). Correlated raw, every
// product tends to m_i m_j and its running integral grows without a plateau; about the
// run's means (each block's own in the linear terms) the integrals are those of the
// fluctuations alone, within the errors the offsets' edge noise raises.
TEST_F(StressGreenKubo, ProductsAboutTheRunsMeansRemoveAMeanStress)
{
    const std::size_t blockCount = 10;
    const std::size_t blockLength = ou_.samples / blockCount;
    const double sigma = std::sqrt(ou_.variance);
    const Eigen::Vector3d offset(3.0 * 2.0 * sigma, -2.0 * sigma, 1.0 * sigma);
    SeriesProductCorrelator plain(3), shifted(3);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero(), blockSum = Eigen::Vector3d::Zero();
    std::vector<std::vector<double>> blockMeans;
    for (std::size_t t = 0; t < ou_.samples; ++t)
    {
        const Eigen::Vector3d s(parts_[0][t], parts_[1][t], parts_[2][t]);
        plain.add(s);
        shifted.add(s + offset);
        sum += s + offset;
        blockSum += s + offset;
        if ((t + 1) % blockLength == 0)
        {
            plain.closeBlock();
            shifted.closeBlock();
            const Eigen::Vector3d m = blockSum / double(blockLength);
            blockMeans.push_back({m(0), m(1), m(2)});
            blockSum.setZero();
        }
    }
    const Eigen::Vector3d mean = sum / double(ou_.samples);
    const StressProductIntegrals reference = stressProductIntegrals(plain.blocks(), ou_.dt, 3);
    const StressProductIntegrals raw = stressProductIntegrals(shifted.blocks(), ou_.dt, 3);
    const StressProductIntegrals about = stressProductIntegrals
    (
        aboutMeans(shifted.blocks(), blockMeans, {mean(0), mean(1), mean(2)}), ou_.dt, 3
    );
    for (std::size_t i = 0; i < 3; ++i)
    {
        for (std::size_t j = 0; j < 3; ++j)
        {
            // the two share the fluctuations; the offsets add their own noise (the blocks'
            // edges: a lag's origins span the block less the lag), which the errors carry
            const Estimate& a = about.term(i, j).integral;
            const Estimate& r = reference.term(i, j).integral;
            EXPECT_NEAR(a.value, r.value, 2.0 * a.standardError) << "term " << i << j;
            EXPECT_LT(a.standardError, 0.1 * exact(0, 0)) << "term " << i << j;
        }
    }
    // raw: the offsets' products (m_0^2 = 36 variances of the OU part) swamp the integral
    EXPECT_GT(std::abs(raw.term(0, 0).integral.value - reference.term(0, 0).integral.value),
              10.0 * exact(0, 0));
    std::cout << "[ figures  ] I11 about the run's means " << about.term(0, 0).integral.value << " +- "
              << about.term(0, 0).integral.standardError << ", without offsets "
              << reference.term(0, 0).integral.value << " +- " << reference.term(0, 0).integral.standardError
              << ", raw with offsets " << raw.term(0, 0).integral.value << "\n";
    EXPECT_THROW(aboutMeans(shifted.blocks(), blockMeans, {mean(0), mean(1)}), std::invalid_argument);
    std::vector<std::vector<double>> tooFew(blockMeans.begin(), blockMeans.end() - 1);
    EXPECT_THROW(aboutMeans(shifted.blocks(), tooFew, {mean(0), mean(1), mean(2)}), std::invalid_argument);
}

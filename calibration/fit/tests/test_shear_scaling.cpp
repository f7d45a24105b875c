// The dimensionless groups of a sheared calibration (fit/ShearScaling.hpp):
// C = D/(gammaDot dMean^2) and R = dMean gammaDot sqrt(3/T) per row, their
// weighted mean and power law in phi, against values constructed exactly.
#include "fit/ShearScaling.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include <cmath>
#include <stdexcept>
#include <string>

using namespace sdf::fit;

namespace
{

//- Rows with D = C0 phi^b gammaDot dMean^2 and T = 3 (dMean gammaDot/R(phi))^2,
//  R = R0 phi^r, over 3 phi x 2 x x 2 gammaDot
std::vector<ShearedObservation> exactRows(double C0, double b, double R0, double r)
{
    std::vector<ShearedObservation> rows;
    for (const double phi : {0.45, 0.5, 0.55})
    {
        for (const double x : {0.2, 0.4})
        {
            for (const double gammaDot : {5.0, 20.0})
            {
                ShearedObservation o;
                o.phi = phi;
                o.x = x;
                o.gammaDot = gammaDot;
                o.dMean = volumeMeanDiameter(x, 1e-3, 2e-3);
                const double R = R0*std::pow(phi, r);
                o.T = 3.0*std::pow(o.dMean*gammaDot/R, 2);
                o.D = C0*std::pow(phi, b)*gammaDot*o.dMean*o.dMean;
                o.DError = 0.03*o.D;
                rows.push_back(o);
            }
        }
    }
    return rows;
}

} // namespace


TEST(shear_scaling, recoversExactGroupsAndPowerLaws)
{
    const ShearScaling s = shearScaling(exactRows(0.02, -1.5, 1.2, 0.8));
    ASSERT_EQ(s.C.size(), 12u);
    for (std::size_t i = 0; i < s.C.size(); ++i)
    {
        EXPECT_NEAR(s.CError[i]/s.C[i], 0.03, 1e-12);
    }
    ASSERT_TRUE(s.CLaw.fitted);
    EXPECT_NEAR(s.CLaw.A, 0.02, 1e-10);
    EXPECT_NEAR(s.CLaw.b, -1.5, 1e-10);
    EXPECT_LT(s.CLaw.reducedChiSquare, 1e-16);
    ASSERT_TRUE(s.RLaw.fitted);
    EXPECT_NEAR(s.RLaw.A, 1.2, 1e-10);
    EXPECT_NEAR(s.RLaw.b, 0.8, 1e-10);
    EXPECT_EQ(s.gammaDot.min, 5.0);
    EXPECT_EQ(s.gammaDot.max, 20.0);
    EXPECT_EQ(s.phi.min, 0.45);
    EXPECT_EQ(s.x.max, 0.4);
    // C varies with phi: its mean scatters beyond the 3 % errors
    EXPECT_GT(s.meanC.reducedChiSquare, 1.0);
}


TEST(shear_scaling, weightedMeanOfConstantC)
{
    // phi-independent C: the mean is C0 with error C0 0.03/sqrt(12), chi2 0
    const ShearScaling s = shearScaling(exactRows(0.042, 0.0, 1.0, 0.0));
    EXPECT_NEAR(s.meanC.value, 0.042, 1e-14);
    EXPECT_NEAR(s.meanC.error, 0.042*0.03/std::sqrt(12.0), 1e-12);
    EXPECT_LT(s.meanC.reducedChiSquare, 1e-20);
    EXPECT_NEAR(s.CLaw.b, 0.0, 1e-10);
    EXPECT_NEAR(s.meanR, 1.0, 1e-12);
    EXPECT_LT(s.spreadR, 1e-12);

    // Two values of unequal weight: (1/1 + 4/4)/(1 + 1/4) ... by hand
    std::vector<ShearedObservation> two = exactRows(0.042, 0.0, 1.0, 0.0);
    two.resize(2);
    two[0].D = 1.0*two[0].gammaDot*two[0].dMean*two[0].dMean;
    two[0].DError = 0.1*two[0].gammaDot*two[0].dMean*two[0].dMean;
    two[1].D = 2.0*two[1].gammaDot*two[1].dMean*two[1].dMean;
    two[1].DError = 0.2*two[1].gammaDot*two[1].dMean*two[1].dMean;
    const ShearScaling m = shearScaling(two);
    // weights 100 and 25: (100*1 + 25*2)/125 = 1.2; chi2 = 100*0.04 + 25*0.64 = 20
    EXPECT_NEAR(m.meanC.value, 1.2, 1e-12);
    EXPECT_NEAR(m.meanC.reducedChiSquare, 20.0, 1e-9);
    EXPECT_NEAR(m.meanC.error, std::sqrt(1.0/125.0)*std::sqrt(20.0), 1e-12);
    EXPECT_FALSE(m.CLaw.fitted);   // two rows: no power law
}


TEST(shear_scaling, rLawErrorsComeFromItsScatter)
{
    // R = 1.2 phi^0.8 exactly but one row 10 % high: the unit-weight fit's errors
    // scale with the scatter of ln R (0 for exact rows)
    std::vector<ShearedObservation> rows = exactRows(0.02, -1.5, 1.2, 0.8);
    const ShearScaling exact = shearScaling(rows);
    EXPECT_LT(exact.RLaw.bError, 1e-9);
    rows[5].T /= 1.1*1.1;    // R grows by 1.1
    const ShearScaling off = shearScaling(rows);
    EXPECT_NEAR(off.R[5], 1.1*exact.R[5], 1e-12);
    EXPECT_GT(off.RLaw.bError, 0.01);
    EXPECT_GT(off.RLaw.reducedChiSquare, 1e-4);   // variance of ln R ~ (ln 1.1)^2 (11/12)/10
    EXPECT_LT(off.RLaw.reducedChiSquare, std::log(1.1)*std::log(1.1));
}


TEST(shear_scaling, refusesBadRowsNamingThem)
{
    EXPECT_THROW(shearScaling({}), std::invalid_argument);
    std::vector<ShearedObservation> rows = exactRows(0.042, 0.0, 1.0, 0.0);
    rows[3].gammaDot = 0;
    try
    {
        shearScaling(rows);
        ADD_FAILURE() << "no exception";
    }
    catch (const std::invalid_argument& err)
    {
        const std::string m = err.what();
        // the condition by its row and its phi, x and gammaDot
        std::ostringstream named;
        named << "condition 3 (phi " << rows[3].phi << ", x " << rows[3].x << ", gammaDot 0): gammaDot = 0";
        EXPECT_NE(m.find(named.str()), std::string::npos) << m;
    }
    rows = exactRows(0.042, 0.0, 1.0, 0.0);
    rows[1].T = std::nan("");
    try
    {
        shearScaling(rows);
        ADD_FAILURE() << "no exception";
    }
    catch (const std::invalid_argument& err)
    {
        const std::string m = err.what();
        EXPECT_NE(m.find("): T = nan is not finite"), std::string::npos) << m;
        EXPECT_NE(m.find("condition 1 (phi "), std::string::npos) << m;
    }
    rows = exactRows(0.042, 0.0, 1.0, 0.0);
    rows[0].DError = 0;
    EXPECT_THROW(shearScaling(rows), std::invalid_argument);
}

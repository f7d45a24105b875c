// Gravity-driven size segregation in dense shear as laws of the percolation length S
// in w_coarse = S gammaDot (1 - c) (the coarse species' drift against gravity relative
// to the mixture, c its share of the solids), fitted to the sheared cell under gravity
// (apps/gravityShearCell), and the fit that turns such cells into the solver's
// segregationVelocity coefficients. A row's condition: d the fine diameter, x = c, R
// (sizeRatio) and p* = p/(rho_s g dMean) (pressureNumber); dMean = d (1 - c + c R), the
// solids-volume mean.
//
//  - fanSchlick (Fan et al. 2014, J. Fluid Mech. 741, 252; Schlick et al. 2015, J. Fluid
//    Mech. 765, 632): S = C_s d ln R, independent of the pressure;
//  - trewhela (the pressure scaling of Trewhela, Ancey & Gray 2021, J. Fluid Mech. 916,
//    A55: the flux goes as gammaDot dMean^2/(C dMean + p/(rho g)), linear in R - 1 for
//    a large intruder): S = B dMean (R - 1)/(C + p*);
//  - trewhelaAsymmetric: the same times 1 + E c (R - 1), the form Trewhela et al. give
//    for the size ratio's effect growing as the coarse become the matrix (faster fines
//    among many coarse: van der Vaart et al. 2015, Phys. Rev. Lett. 114, 238001).
// The forms are the papers'; their constants are not used (they are fitted here).
// Fits are in linear space with relative sigma (the block errors, scaled by the reduced
// chi-square), compared by AIC.
#ifndef sdf_fit_SegregationLaws_hpp
#define sdf_fit_SegregationLaws_hpp

#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"

#include <string>
#include <vector>

namespace sdf::fit
{

struct FanSchlickLaw
{
    std::string name() const { return "fanSchlick"; }
    std::string formula() const { return "C_s*d*ln(R)"; }
    std::vector<std::string> parameterNames() const { return {"C_s"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

struct TrewhelaLaw
{
    std::string name() const { return "trewhela"; }
    std::string formula() const { return "B*dMean*(R - 1)/(C + pStar), dMean = d*(1 - x + x*R)"; }
    std::vector<std::string> parameterNames() const { return {"B", "C"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

struct TrewhelaAsymmetricLaw
{
    std::string name() const { return "trewhelaAsymmetric"; }
    std::string formula() const
    {
        return "B*dMean*(R - 1)*(1 + E*x*(R - 1))/(C + pStar), dMean = d*(1 - x + x*R)";
    }
    std::vector<std::string> parameterNames() const { return {"B", "C", "E"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- The law of that name (fanSchlick, trewhela, trewhelaAsymmetric), for the solver to
//  evaluate what the fit wrote; throws std::invalid_argument naming the valid ones.
ConstitutiveLaw segregationLawFromName(const std::string& name);

//- One cell's interior: its percolation length with its standard error, the conditions
//  it was measured at and its shear-rate diffusivity along gravity.
struct SegregationPoint
{
    double fineDiameter = 0;            // d [m]
    double sizeRatio = 0;               // R = d_coarse/d_fine
    double coarseShare = 0;             // c
    double solidsFraction = 0;          // phi
    double pressureNumber = 0;          // p*
    double inertialNumber = 0;          // I
    double shearRate = 0;               // gammaDot [1/s]
    double percolationLength = 0, percolationLengthError = 0;   // S [m]
    //- C = D/(gammaDot dMean^2) of the cell's diffusivity along gravity (0: not measured)
    double shearRateDiffusivity = 0, shearRateDiffusivityError = 0;
};

//- The fits with their model choice, the shear-rate diffusivity C = D/(gammaDot dMean^2)
//  (weighted mean over the cells, standard error from the scatter when larger) and the
//  envelope the laws were fitted over.
struct SegregationFit
{
    std::vector<FitResult> fits;        // fanSchlick, trewhela, trewhelaAsymmetric (if it could be fitted)
    ModelSelection selection;
    double diffusivityCoefficient = 0, diffusivityCoefficientError = 0;
    Range pressureNumbers, inertialNumbers, sizeRatios, coarseShares;
    const FitResult& best() const;
};

//- Fits (at least 3 cells; trewhelaAsymmetric from 4 cells over c spanning 0.1 or more than one R
//  on); throws std::invalid_argument naming what is wrong with a point (S error <= 0,
//  R < 1, c outside [0, 1], p* <= 0, d <= 0) or the table (too few cells) and
//  FitFailure when no law converges.
SegregationFit fitSegregation(const std::vector<SegregationPoint>& points);

//- One line per law (parameters, errors, reduced chi-square, AIC), the model choice
//  and C; a warning with fewer than 6 cells.
std::string segregationFitSummary(const SegregationFit& fit);

//- The body of constant/granularCoefficients' segregationVelocity sub-dictionary: the
//  chosen law, its parameters and errors, the envelope and the AIC differences; and of
//  shearRateDiffusivity (C).
std::string segregationVelocityEntries(const SegregationFit& fit);

} // namespace sdf::fit

#endif

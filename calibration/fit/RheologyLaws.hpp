// The dense granular rheology as constitutive laws of the inertial number I (the row's
// Condition::inertialNumber), fitted to pressure-controlled sheared DEM cells
// (transport/CellRun.hpp, RheologyResult), and the fit that turns such cells into the
// solver's muI coefficients.
//
//  - muI (Jop, Forterre & Pouliquen 2006, Nature 441, 727): mu = mu_s + (mu_d - mu_s)/(I_0/I + 1),
//    the form the solver's muI bulk flow takes (mu_s, mu_d, I_0);
//  - muIPower: mu = mu_s + a I^n, the alternative the model choice weighs it against (a
//    power law above the quasi-static limit, as DeGiuli, McElwaine & Wyart 2016 find for
//    frictional spheres, mu - mu_s ~ I^(1 - 2b) with b ~ 0.2; no saturation at mu_d);
//  - phiILinear (da Cruz et al. 2005, Phys. Rev. E 72, 021309): phi = phi_c - a I;
//  - phiIPower: phi = phi_c - a I^n.
// Fits are in linear space (mu and phi are O(1) with absolute block errors), the errors
// scaled by the reduced chi-square (relative sigma: model error widens them).
#ifndef sdf_fit_RheologyLaws_hpp
#define sdf_fit_RheologyLaws_hpp

#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"

#include <string>
#include <vector>

namespace sdf::fit
{

//- The row's I; throws std::invalid_argument if the row has none.
double inertialNumberOf(const Condition& c);

struct JopMuILaw
{
    std::string name() const { return "muI"; }
    std::string formula() const { return "mu_s + (mu_d - mu_s)/(I_0/I + 1)"; }
    std::vector<std::string> parameterNames() const { return {"mu_s", "mu_d", "I_0"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- mu_s the smallest mu, mu_d 1.5 x the largest minus half the smallest, I_0 the
    //  geometric mean of the I
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

struct PowerMuILaw
{
    std::string name() const { return "muIPower"; }
    std::string formula() const { return "mu_s + a*I^n"; }
    std::vector<std::string> parameterNames() const { return {"mu_s", "a", "n"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

struct LinearPhiILaw
{
    std::string name() const { return "phiILinear"; }
    std::string formula() const { return "phi_c - a*I"; }
    std::vector<std::string> parameterNames() const { return {"phi_c", "a"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

struct PowerPhiILaw
{
    std::string name() const { return "phiIPower"; }
    std::string formula() const { return "phi_c - a*I^n"; }
    std::vector<std::string> parameterNames() const { return {"phi_c", "a", "n"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- One steady dense cell: its I, mu and phi with their standard errors, the mean
//  diameter and the granular temperature (the table's other entries).
struct RheologyPoint
{
    double inertialNumber = 0;
    double stressRatio = 0, stressRatioError = 0;
    double solidsFraction = 0, solidsFractionError = 0;
    double meanDiameter = 0;
    double temperature = 0;
};

//- The fits of mu(I) and phi(I) with their model choices (AIC); the muI and phiILinear
//  fits are what the solver's muI model takes (mu_s, mu_d, I_0; packedFraction = phi_c).
struct RheologyFit
{
    std::vector<FitResult> muFits;     // muI, muIPower
    ModelSelection muSelection;
    std::vector<FitResult> phiFits;    // phiILinear, phiIPower
    ModelSelection phiSelection;
    Range inertialNumbers;             // the I the laws were fitted over
    const FitResult& muI() const { return muFits.front(); }
    const FitResult& phiILinear() const { return phiFits.front(); }
};

//- Fits (needs at least 4 points for the three-parameter laws); throws
//  std::invalid_argument for a table the fits cannot take (fewer points, I <= 0, an
//  error <= 0) and FitFailure when the muI or phiILinear fit fails.
RheologyFit fitRheology(const std::vector<RheologyPoint>& points);

//- What the fits say, one line each: every law with its parameters, standard errors,
//  reduced chi-square and AIC; the model choices with the other law's AIC difference;
//  with fewer than 6 points, a warning that the errors rest on few degrees of freedom.
std::string rheologyFitSummary(const RheologyFit& fit);

//- The muI model's coefficients as OpenFOAM dictionary entries (a muICoeffs body:
//  mu_s, mu_d, I_0, packedFraction, each with its standard error in a comment).
std::string muICoefficientEntries(const RheologyFit& fit);

} // namespace sdf::fit

#endif

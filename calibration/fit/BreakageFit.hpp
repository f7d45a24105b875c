// The Vogel-Peukert constants of a material from its impact tests, by maximum likelihood
// of the binomial counts (BreakageRate.hpp has the law):
//     P(broken) = 1 - exp(-fMat k (x W - xWmMin)+)
// for particles of size x suffering k impacts of mass-specific energy W. The counts b of
// n tested are binomial with that P, so the log-likelihood is
//     sum_i b_i ln P_i - (n_i - b_i) fMat k_i (x_i W_i - xWmMin)+ .
// It is maximised over fMat for each threshold xWmMin (a concave problem in fMat), and
// that profile over xWmMin in [0, the smallest x W at which anything broke); standard
// errors and the correlation come from the observed information (the analytic Hessian of
// the log-likelihood at the maximum). The fit's check: the deviance against chi-squared
// with (rows above the fitted threshold) - 2 degrees of freedom, and the Pearson
// residuals by particle size.
#ifndef sdf_fit_BreakageFit_hpp
#define sdf_fit_BreakageFit_hpp

#include "BreakageRate.hpp"
#include "ImpactTests.hpp"

#include <string>
#include <vector>

namespace sdf::fit::breakage
{

//- The mean Pearson residual of the rows of one particle size.
struct SizeResidual
{
    double size = 0;           // [m]
    int rows = 0;
    double meanResidual = 0;   // mean of (b - n P)/sqrt(n P (1 - P))
};

struct BreakageFitResult
{
    VogelPeukertMaterial material;   // the estimates
    double fMatError = 0;            // standard errors [kg/(J m)], [J m/kg] (NaN: none)
    double xWmMinError = 0;
    double correlation = 0;          // of the two estimates
    bool thresholdAtZero = false;    // the likelihood is largest at xWmMin = 0 (a bound)
    double logLikelihood = 0;        // without the binomial coefficients
    double deviance = 0;             // G^2 against the saturated model
    int degreesOfFreedom = 0;        // rows above the fitted threshold - 2
    double pValue = 1;               // P(chi2_dof > deviance)
    std::vector<double> probability;       // fitted P per row
    std::vector<double> pearsonResidual;   // per row
    std::vector<SizeResidual> bySize;      // over the rows above the threshold
};

//- The breakage probability of a row under material (the law above).
double breakageProbability(const VogelPeukertMaterial& material, const ImpactTest& test);

//- Fits fMat and xWmMin to the tests. Throws std::invalid_argument, with the reason and
//  what to test, when the constants cannot be identified: fewer than two distinct x W
//  (one velocity for one size: fMat and the threshold trade off), breakage at one x W
//  only, nothing broken in any test (the threshold lies above them all), or every
//  particle broken in every row at or above the lowest x W that broke any (fMat has no
//  upper bound). At the bound xWmMin = 0 (thresholdAtZero) xWmMinError and the
//  correlation are NaN and fMatError is fMat's at xWmMin = 0.
BreakageFitResult fitVogelPeukert(const std::vector<ImpactTest>& tests);

} // namespace sdf::fit::breakage

#endif

// A straight line y = intercept + slope x fitted by weighted least squares (GSL's
// gsl_fit_wlinear), for the fits that are linear in their parameters (the finite-size
// extrapolation, the power laws of fit/ShearScaling in log space).
#ifndef sdf_fit_WeightedLine_hpp
#define sdf_fit_WeightedLine_hpp

#include <vector>

namespace sdf::fit
{

//- How the parameters' errors are scaled by the scatter about the line.
enum class LineErrors
{
    widenWhenScattered,   // weights 1/sigma^2: x max(1, sqrt(reduced chi2))
    fromScatter           // unit weights: x sqrt(reduced chi2) (the errors from the scatter alone)
};

struct WeightedLine
{
    double intercept = 0, interceptError = 0;
    double slope = 0, slopeError = 0;
    //- chi2 / (n - 2); 0 for two points. With unit weights: the variance about the line.
    double reducedChiSquare = 0;
};

//- x, y, weights of equal length >= 2 (the caller checks the values).
WeightedLine weightedLine
(
    const std::vector<double>& x,
    const std::vector<double>& y,
    const std::vector<double>& weights,
    LineErrors errors
);

} // namespace sdf::fit

#endif

#include "fit/WeightedLine.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>

namespace sdf::fit
{

WeightedLine weightedLine
(
    const std::vector<double>& x,
    const std::vector<double>& y,
    const std::vector<double>& weights,
    LineErrors errors
)
{
    const std::size_t n = x.size();
    double c0, c1, cov00, cov01, cov11, chi2;
    gsl_fit_wlinear(x.data(), 1, weights.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &chi2);
    WeightedLine line;
    line.reducedChiSquare = n > 2 ? chi2/double(n - 2) : 0;
    const double scale =
        errors == LineErrors::fromScatter
      ? std::sqrt(line.reducedChiSquare)
      : std::max(1.0, std::sqrt(line.reducedChiSquare));
    line.intercept = c0;
    line.interceptError = std::sqrt(cov00)*scale;
    line.slope = c1;
    line.slopeError = std::sqrt(cov11)*scale;
    return line;
}

} // namespace sdf::fit

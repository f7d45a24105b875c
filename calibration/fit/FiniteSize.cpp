#include "fit/FiniteSize.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace sdf::fit
{

FiniteSizeExtrapolation extrapolateInverseCubeRoot(const std::vector<SizedValue>& rows)
{
    std::set<double> sizes;
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        const SizedValue& r = rows[i];
        if (!(r.particles > 0) || !std::isfinite(r.value) || !(r.sigma > 0) || !std::isfinite(r.sigma))
        {
            throw std::invalid_argument
            (
                "finite-size extrapolation: row " + std::to_string(i) + " (N "
              + std::to_string(r.particles) + ", value " + std::to_string(r.value)
              + ", sigma " + std::to_string(r.sigma)
              + "): N and sigma must be > 0 and the value finite"
            );
        }
        sizes.insert(r.particles);
    }
    if (sizes.size() < 2)
    {
        throw std::invalid_argument
        (
            "finite-size extrapolation: needs cells of at least two sizes, got "
          + std::to_string(sizes.size())
        );
    }
    const std::size_t n = rows.size();
    std::vector<double> u(n), y(n), w(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        u[i] = std::cbrt(1.0/rows[i].particles);
        y[i] = rows[i].value;
        w[i] = 1.0/(rows[i].sigma*rows[i].sigma);
    }
    double c0, c1, cov00, cov01, cov11, chi2;
    gsl_fit_wlinear(u.data(), 1, w.data(), 1, y.data(), 1, n, &c0, &c1, &cov00, &cov01, &cov11, &chi2);
    FiniteSizeExtrapolation e;
    e.sizes = sizes.size();
    e.reducedChiSquare = n > 2 ? chi2/double(n - 2) : 0;
    const double widen = std::max(1.0, std::sqrt(e.reducedChiSquare));
    e.value = c0;
    e.error = std::sqrt(cov00)*widen;
    e.slope = -c1;
    e.slopeError = std::sqrt(cov11)*widen;
    return e;
}

} // namespace sdf::fit

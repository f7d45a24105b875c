#include "fit/FiniteSize.hpp"

#include "fit/WeightedLine.hpp"

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
    const WeightedLine line = weightedLine(u, y, w, LineErrors::widenWhenScattered);
    FiniteSizeExtrapolation e;
    e.sizes = sizes.size();
    e.reducedChiSquare = line.reducedChiSquare;
    e.value = line.intercept;
    e.error = line.interceptError;
    e.slope = -line.slope;
    e.slopeError = line.slopeError;
    return e;
}

} // namespace sdf::fit

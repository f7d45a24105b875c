#include "fit/ShearScaling.hpp"

#include "fit/LawFormulas.hpp"
#include "fit/WeightedLine.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace sdf::fit
{

namespace
{

//- Names the condition by its row and its phi, x and gammaDot (the store's names
//  carry the same three)
void check
(
    bool ok,
    std::size_t row,
    const ShearedObservation& o,
    const char* entry,
    double value,
    const char* what
)
{
    if (!ok)
    {
        std::ostringstream msg;
        msg << "shear scaling: condition " << row << " (phi " << o.phi << ", x " << o.x
            << ", gammaDot " << o.gammaDot << "): " << entry << " = " << value << " " << what;
        throw std::invalid_argument(msg.str());
    }
}

//- ln y = ln A + b ln phi, weights 1/sigma_ln^2 (sigma_ln = sigma/y)
PhiPowerLaw phiPowerLaw
(
    const std::vector<double>& phi,
    const std::vector<double>& y,
    const std::vector<double>& sigma,
    LineErrors errors
)
{
    PhiPowerLaw law;
    const std::set<double> distinct(phi.begin(), phi.end());
    if (phi.size() < 3 || distinct.size() < 2)
    {
        return law;
    }
    const std::size_t n = phi.size();
    std::vector<double> lx(n), ly(n), w(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        lx[i] = std::log(phi[i]);
        ly[i] = std::log(y[i]);
        const double s = sigma[i]/y[i];
        w[i] = 1.0/(s*s);
    }
    const WeightedLine line = weightedLine(lx, ly, w, errors);
    law.reducedChiSquare = line.reducedChiSquare;
    law.A = std::exp(line.intercept);
    law.AError = law.A*line.interceptError;
    law.b = line.slope;
    law.bError = line.slopeError;
    law.fitted = true;
    return law;
}

Range rangeOf(const std::vector<ShearedObservation>& rows, double ShearedObservation::*member)
{
    Range r{rows.front().*member, rows.front().*member};
    for (const ShearedObservation& o : rows)
    {
        r.min = std::min(r.min, o.*member);
        r.max = std::max(r.max, o.*member);
    }
    return r;
}

} // namespace


double volumeMeanDiameter(double x, double dFine, double dCoarse)
{
    return (1.0 - x)*dFine + x*dCoarse;
}


ShearScaling shearScaling(const std::vector<ShearedObservation>& rows)
{
    if (rows.empty())
    {
        throw std::invalid_argument("shear scaling: no sheared conditions");
    }
    const std::size_t n = rows.size();
    ShearScaling s;
    std::vector<double> phi(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        const ShearedObservation& o = rows[i];
        const std::pair<const char*, double> entries[] =
        {
            {"phi", o.phi}, {"x", o.x}, {"gammaDot", o.gammaDot}, {"T", o.T},
            {"dMean", o.dMean}, {"D", o.D}, {"DError", o.DError}
        };
        for (const auto& e : entries)
        {
            check(std::isfinite(e.second), i, o, e.first, e.second, "is not finite");
        }
        check(o.phi > 0 && o.phi < 1, i, o, "phi", o.phi, "must be in (0, 1)");
        check(o.x >= 0 && o.x <= 1, i, o, "x", o.x, "must be in [0, 1]");
        check(o.gammaDot > 0, i, o, "gammaDot", o.gammaDot, "must be > 0 [1/s]");
        check(o.T > 0, i, o, "T", o.T, "must be > 0 [m2/s2]");
        check(o.dMean > 0, i, o, "dMean", o.dMean, "must be > 0 [m]");
        check(o.D > 0, i, o, "D", o.D, "must be > 0 [m2/s]");
        check(o.DError > 0, i, o, "DError", o.DError, "must be > 0 [m2/s]");
        const double scale = o.gammaDot*o.dMean*o.dMean;
        s.C.push_back(o.D/scale);
        s.CError.push_back(o.DError/scale);
        s.R.push_back(formulas::savageJeffreyR(o.dMean, o.gammaDot, o.T));
        phi[i] = o.phi;
    }

    // Weighted mean of C
    double sw = 0, swc = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double w = 1.0/(s.CError[i]*s.CError[i]);
        sw += w;
        swc += w*s.C[i];
    }
    s.meanC.value = swc/sw;
    double chi2 = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double r = (s.C[i] - s.meanC.value)/s.CError[i];
        chi2 += r*r;
    }
    s.meanC.reducedChiSquare = n > 1 ? chi2/double(n - 1) : 0;
    s.meanC.error = std::sqrt(1.0/sw)*std::max(1.0, std::sqrt(s.meanC.reducedChiSquare));
    s.CLaw = phiPowerLaw(phi, s.C, s.CError, LineErrors::widenWhenScattered);

    // R: unweighted (the error of T is a fraction of a percent)
    double sum = 0, sum2 = 0;
    for (const double r : s.R)
    {
        sum += r;
        sum2 += r*r;
    }
    s.meanR = sum/double(n);
    s.spreadR = n > 1 ? std::sqrt(std::max(0.0, (sum2 - n*s.meanR*s.meanR)/double(n - 1))) : 0;
    // unit relative weights (sigma_ln = 1): the errors come from the scatter alone
    s.RLaw = phiPowerLaw(phi, s.R, s.R, LineErrors::fromScatter);

    s.phi = rangeOf(rows, &ShearedObservation::phi);
    s.x = rangeOf(rows, &ShearedObservation::x);
    s.gammaDot = rangeOf(rows, &ShearedObservation::gammaDot);
    return s;
}

} // namespace sdf::fit

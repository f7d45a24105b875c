#include "fit/RheologyLaws.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

double inertialNumberOf(const Condition& c)
{
    if (!c.inertialNumber)
    {
        throw std::invalid_argument("a rheology law needs the row's inertialNumber");
    }
    return *c.inertialNumber;
}

namespace
{

struct Span { double minY, maxY, minI, maxI, geometricMeanI; };

Span spanOf(const std::vector<Observation>& data)
{
    Span s{INFINITY, -INFINITY, INFINITY, -INFINITY, 0};
    double lnSum = 0;
    for (const Observation& o : data)
    {
        const double I = inertialNumberOf(o.condition);
        s.minY = std::min(s.minY, o.value);
        s.maxY = std::max(s.maxY, o.value);
        s.minI = std::min(s.minI, I);
        s.maxI = std::max(s.maxI, I);
        lnSum += std::log(I);
    }
    s.geometricMeanI = std::exp(lnSum/double(data.size()));
    return s;
}

} // namespace

// ---------------------------------------------------------------- mu(I)

double JopMuILaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    const double I = inertialNumberOf(c);
    return p[0] + (p[1] - p[0])*I/(p[2] + I);
}

Eigen::VectorXd JopMuILaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double I = inertialNumberOf(c);
    const double w = I/(p[2] + I);
    Eigen::VectorXd g(3);
    g << 1 - w, w, -(p[1] - p[0])*I/((p[2] + I)*(p[2] + I));
    return g;
}

Eigen::VectorXd JopMuILaw::initialParameters(const std::vector<Observation>& data) const
{
    const Span s = spanOf(data);
    Eigen::VectorXd p(3);
    p << s.minY, 1.5*s.maxY - 0.5*s.minY, s.geometricMeanI;
    return p;
}

double PowerMuILaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0] + p[1]*std::pow(inertialNumberOf(c), p[2]);
}

Eigen::VectorXd PowerMuILaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double I = inertialNumberOf(c);
    const double In = std::pow(I, p[2]);
    Eigen::VectorXd g(3);
    g << 1, In, p[1]*In*std::log(I);
    return g;
}

Eigen::VectorXd PowerMuILaw::initialParameters(const std::vector<Observation>& data) const
{
    const Span s = spanOf(data);
    Eigen::VectorXd p(3);
    // mu_s just below the smallest, n 0.6 (1 - 2b, b ~ 0.2), a through the largest
    p << 0.9*s.minY, (s.maxY - 0.9*s.minY)/std::pow(s.maxI, 0.6), 0.6;
    return p;
}

// ---------------------------------------------------------------- phi(I)

double LinearPhiILaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0] - p[1]*inertialNumberOf(c);
}

Eigen::VectorXd LinearPhiILaw::gradient(const Condition& c, const Eigen::VectorXd&) const
{
    Eigen::VectorXd g(2);
    g << 1, -inertialNumberOf(c);
    return g;
}

Eigen::VectorXd LinearPhiILaw::initialParameters(const std::vector<Observation>& data) const
{
    const Span s = spanOf(data);
    Eigen::VectorXd p(2);
    p << s.maxY, (s.maxY - s.minY)/std::max(s.maxI - s.minI, 1e-12);
    return p;
}

double PowerPhiILaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0] - p[1]*std::pow(inertialNumberOf(c), p[2]);
}

Eigen::VectorXd PowerPhiILaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double I = inertialNumberOf(c);
    const double In = std::pow(I, p[2]);
    Eigen::VectorXd g(3);
    g << 1, -In, -p[1]*In*std::log(I);
    return g;
}

Eigen::VectorXd PowerPhiILaw::initialParameters(const std::vector<Observation>& data) const
{
    const Span s = spanOf(data);
    Eigen::VectorXd p(3);
    p << s.maxY, (s.maxY - s.minY)/std::max(s.maxI, 1e-12), 1.0;
    return p;
}

// ---------------------------------------------------------------- the fit

RheologyFit fitRheology(const std::vector<RheologyPoint>& points)
{
    if (points.size() < 4)
    {
        throw std::invalid_argument
        (
            "rheology fit: " + std::to_string(points.size()) + " steady dense cells; mu(I)"
            " has three parameters and needs at least 4 (give more inertial numbers)"
        );
    }
    std::vector<Observation> mu, phi;
    for (const RheologyPoint& q : points)
    {
        Condition c;
        c.phi = q.solidsFraction;
        c.x = 0;
        c.T = q.temperature;
        c.d = q.meanDiameter;
        c.inertialNumber = q.inertialNumber;
        mu.push_back({c, q.stressRatio, q.stressRatioError});
        phi.push_back({c, q.solidsFraction, q.solidsFractionError});
    }
    FitOptions options;
    options.space = FitSpace::linear;
    options.sigmaMeaning = SigmaMeaning::relative;
    RheologyFit fit;
    fit.inertialNumbers = {INFINITY, -INFINITY};
    for (const RheologyPoint& q : points)
    {
        fit.inertialNumbers.min = std::min(fit.inertialNumbers.min, q.inertialNumber);
        fit.inertialNumbers.max = std::max(fit.inertialNumbers.max, q.inertialNumber);
    }
    fit.muFits = {fitLaw(JopMuILaw{}, mu, options), fitLaw(PowerMuILaw{}, mu, options)};
    fit.phiFits = {fitLaw(LinearPhiILaw{}, phi, options), fitLaw(PowerPhiILaw{}, phi, options)};
    fit.muI().throwIfFailed();
    fit.phiILinear().throwIfFailed();
    fit.muSelection = selectModel(fit.muFits);
    fit.phiSelection = selectModel(fit.phiFits);
    return fit;
}

std::string rheologyFitSummary(const RheologyFit& fit)
{
    std::string out;
    char text[400];
    for (const auto* fits : {&fit.muFits, &fit.phiFits})
    {
        for (const FitResult& f : *fits)
        {
            out += f.law.name() + " = " + f.law.formula() + ":";
            for (const FittedParameter& q : f.parameters)
            {
                std::snprintf(text, sizeof text, " %s %.5g +- %.2g", q.name.c_str(), q.value,
                              q.standardError);
                out += text;
            }
            std::snprintf(text, sizeof text, " (reduced chi2 %.3g, AIC %.2f)\n",
                          f.reducedChiSquare, f.aic);
            out += text;
        }
    }
    std::snprintf
    (
        text, sizeof text,
        "model choice (AIC): mu(I) %s (delta of the other %.2f), phi(I) %s (delta %.2f)\n",
        fit.muSelection.best().law.c_str(), fit.muSelection.ranking.back().delta,
        fit.phiSelection.best().law.c_str(), fit.phiSelection.ranking.back().delta
    );
    out += text;
    const std::size_t points = fit.muI().points;
    if (points < 6)
    {
        // relative sigma: the errors come from the scatter about the law, with
        // points - 3 degrees of freedom
        std::snprintf
        (
            text, sizeof text,
            "warning: %zu cells for three parameters: the errors rest on %zu degrees of"
            " freedom; mu_d and I_0 are extrapolated unless I reaches well past I_0"
            " (give 6 or more cells, up to I 0.5-1)\n", points, points - 3
        );
        out += text;
    }
    return out;
}


std::string muICoefficientEntries(const RheologyFit& fit)
{
    std::ostringstream out;
    char line[200];
    const auto entry = [&](const char* name, const FittedParameter& p)
    {
        std::snprintf(line, sizeof line, "    %-16s%.6g;   // +- %.2g (standard error)\n",
                      name, p.value, p.standardError);
        out << line;
    };
    const FitResult& mu = fit.muI();
    const FitResult& phi = fit.phiILinear();
    out << "    // mu(I) = " << mu.law.formula() << ", phi(I) = " << phi.law.formula()
        << ", fitted on " << mu.points << " DEM cells over I " << fit.inertialNumbers.min
        << " - " << fit.inertialNumbers.max << "\n";
    entry("mu_s", mu.parameter("mu_s"));
    entry("mu_d", mu.parameter("mu_d"));
    entry("I_0", mu.parameter("I_0"));
    entry("packedFraction", phi.parameter("phi_c"));
    return out.str();
}

} // namespace sdf::fit

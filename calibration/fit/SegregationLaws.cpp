#include "fit/SegregationLaws.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

namespace
{

double sizeRatioOf(const Condition& c)
{
    if (!c.sizeRatio) throw std::invalid_argument("a segregation law needs the row's sizeRatio");
    return *c.sizeRatio;
}

double pressureNumberOf(const Condition& c)
{
    if (!c.pressureNumber) throw std::invalid_argument("a segregation law needs the row's pressureNumber");
    return *c.pressureNumber;
}

//- dMean (R - 1)/(C + p*): the trewhela law per unit B
double trewhelaShape(const Condition& c, double C)
{
    const double R = sizeRatioOf(c);
    return c.d*(1 - c.x + c.x*R)*(R - 1)/(C + pressureNumberOf(c));
}

//- The weighted least-squares factor of y = k f: sum w y f / sum w f^2 (0 if f vanishes)
template<class Shape>
double scaleFactor(const std::vector<Observation>& data, Shape shape)
{
    double yf = 0, ff = 0;
    for (const Observation& o : data)
    {
        const double f = shape(o.condition), w = 1/(o.sigma*o.sigma);
        yf += w*o.value*f;
        ff += w*f*f;
    }
    return ff > 0 ? yf/ff : 0;
}

} // namespace

// ---------------------------------------------------------------- fanSchlick

double FanSchlickLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0]*c.d*std::log(sizeRatioOf(c));
}

Eigen::VectorXd FanSchlickLaw::gradient(const Condition& c, const Eigen::VectorXd&) const
{
    Eigen::VectorXd g(1);
    g << c.d*std::log(sizeRatioOf(c));
    return g;
}

Eigen::VectorXd FanSchlickLaw::initialParameters(const std::vector<Observation>& data) const
{
    Eigen::VectorXd p(1);
    p << scaleFactor(data, [](const Condition& c) { return c.d*std::log(sizeRatioOf(c)); });
    return p;
}

// ---------------------------------------------------------------- trewhela

double TrewhelaLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0]*trewhelaShape(c, p[1]);
}

Eigen::VectorXd TrewhelaLaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double f = trewhelaShape(c, p[1]);
    Eigen::VectorXd g(2);
    g << f, -p[0]*f/(p[1] + pressureNumberOf(c));
    return g;
}

Eigen::VectorXd TrewhelaLaw::initialParameters(const std::vector<Observation>& data) const
{
    // C of order one (a grain's weight against the overburden), B by least squares
    Eigen::VectorXd p(2);
    p << scaleFactor(data, [](const Condition& c) { return trewhelaShape(c, 1.0); }), 1.0;
    return p;
}

// ---------------------------------------------------------------- trewhelaAsymmetric

double TrewhelaAsymmetricLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return p[0]*trewhelaShape(c, p[1])*(1 + p[2]*c.x*(sizeRatioOf(c) - 1));
}

Eigen::VectorXd TrewhelaAsymmetricLaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double f = trewhelaShape(c, p[1]);
    const double a = c.x*(sizeRatioOf(c) - 1);
    const double asymmetry = 1 + p[2]*a;
    Eigen::VectorXd g(3);
    g << f*asymmetry, -p[0]*f*asymmetry/(p[1] + pressureNumberOf(c)), p[0]*f*a;
    return g;
}

Eigen::VectorXd TrewhelaAsymmetricLaw::initialParameters(const std::vector<Observation>& data) const
{
    const Eigen::VectorXd symmetric = TrewhelaLaw{}.initialParameters(data);
    Eigen::VectorXd p(3);
    p << symmetric[0], symmetric[1], 0.0;
    return p;
}

ConstitutiveLaw segregationLawFromName(const std::string& name)
{
    if (name == "fanSchlick") return FanSchlickLaw{};
    if (name == "trewhela") return TrewhelaLaw{};
    if (name == "trewhelaAsymmetric") return TrewhelaAsymmetricLaw{};
    throw std::invalid_argument
    (
        "unknown segregation law '" + name + "' (valid: fanSchlick, trewhela, trewhelaAsymmetric)"
    );
}

// ---------------------------------------------------------------- the fit

const FitResult& SegregationFit::best() const
{
    return fits.at(selection.best().index);
}

SegregationFit fitSegregation(const std::vector<SegregationPoint>& points)
{
    if (points.size() < 3)
    {
        throw std::invalid_argument
        (
            "segregation fit: " + std::to_string(points.size()) + " cells; the pressure law has"
            " two parameters and needs at least 3 (give more normal stresses)"
        );
    }
    std::vector<Observation> data;
    SegregationFit fit;
    const auto include = [](Range& r, double v, bool first)
    {
        r.min = first ? v : std::min(r.min, v);
        r.max = first ? v : std::max(r.max, v);
    };
    double cWeighted = 0, weights = 0;
    std::vector<double> cs;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
        const SegregationPoint& q = points[i];
        const auto reject = [&](const std::string& entry, double v, const std::string& rule)
        {
            std::ostringstream m;
            m << "segregation fit: cell " << i << ": " << entry << " " << v << " " << rule;
            throw std::invalid_argument(m.str());
        };
        if (!(q.fineDiameter > 0)) reject("fineDiameter", q.fineDiameter, "must be > 0 [m]");
        if (!(q.sizeRatio >= 1)) reject("sizeRatio", q.sizeRatio, "must be >= 1");
        if (!(q.coarseShare >= 0 && q.coarseShare <= 1)) reject("coarseShare", q.coarseShare, "must lie in [0, 1]");
        if (!(q.pressureNumber > 0)) reject("pressureNumber", q.pressureNumber, "must be > 0");
        if (!(q.percolationLengthError > 0)) reject("percolationLengthError", q.percolationLengthError, "must be > 0");
        if (!(q.shearRate > 0)) reject("shearRate", q.shearRate, "must be > 0 (an unsheared cell measures nothing)");
        Condition c;
        c.phi = q.solidsFraction;
        c.x = q.coarseShare;
        c.d = q.fineDiameter;
        c.gammaDot = q.shearRate;
        c.inertialNumber = q.inertialNumber;
        c.pressureNumber = q.pressureNumber;
        c.sizeRatio = q.sizeRatio;
        data.push_back({c, q.percolationLength, q.percolationLengthError});
        const bool first = i == 0;
        include(fit.pressureNumbers, q.pressureNumber, first);
        include(fit.inertialNumbers, q.inertialNumber, first);
        include(fit.sizeRatios, q.sizeRatio, first);
        include(fit.coarseShares, q.coarseShare, first);
        if (q.shearRateDiffusivity > 0 && q.shearRateDiffusivityError > 0)
        {
            const double e = q.shearRateDiffusivityError;
            cWeighted += q.shearRateDiffusivity/(e*e);
            weights += 1/(e*e);
            cs.push_back(q.shearRateDiffusivity);
        }
    }
    FitOptions options;
    options.space = FitSpace::linear;
    options.sigmaMeaning = SigmaMeaning::relative;
    fit.fits = {fitLaw(FanSchlickLaw{}, data, options), fitLaw(TrewhelaLaw{}, data, options)};
    // the asymmetry in c cannot be told from B unless c (by 0.1 at least) or R varies
    const bool variesBeyondPressure =
        fit.coarseShares.max - fit.coarseShares.min >= 0.1 || fit.sizeRatios.max > fit.sizeRatios.min;
    if (points.size() >= 4 && variesBeyondPressure)
    {
        fit.fits.push_back(fitLaw(TrewhelaAsymmetricLaw{}, data, options));
    }
    fit.selection = selectModel(fit.fits);
    if (weights > 0)
    {
        fit.diffusivityCoefficient = cWeighted/weights;
        double scatter = 0;
        for (double c : cs) scatter += (c - fit.diffusivityCoefficient)*(c - fit.diffusivityCoefficient);
        const double fromErrors = std::sqrt(1/weights);
        const double fromScatter = cs.size() > 1 ? std::sqrt(scatter/double(cs.size() - 1)/double(cs.size())) : 0;
        fit.diffusivityCoefficientError = std::max(fromErrors, fromScatter);
    }
    return fit;
}

std::string segregationFitSummary(const SegregationFit& fit)
{
    std::string out;
    char text[400];
    for (const FitResult& f : fit.fits)
    {
        out += f.law.name() + " = " + f.law.formula() + ":";
        if (!f.converged())
        {
            out += " not fitted (" + f.message + ")\n";
            continue;
        }
        for (const FittedParameter& q : f.parameters)
        {
            std::snprintf(text, sizeof text, " %s %.5g +- %.2g", q.name.c_str(), q.value, q.standardError);
            out += text;
        }
        std::snprintf(text, sizeof text, " (reduced chi2 %.3g, AIC %.2f)\n", f.reducedChiSquare, f.aic);
        out += text;
    }
    out += "model choice (AIC): " + fit.selection.best().law;
    for (const RankedLaw& r : fit.selection.ranking)
    {
        if (r.delta > 0)
        {
            std::snprintf(text, sizeof text, ", %s delta %.2f", r.law.c_str(), r.delta);
            out += text;
        }
    }
    std::snprintf
    (
        text, sizeof text,
        "\nshear-rate diffusivity C = D/(gammaDot dMean^2) %.4g +- %.2g\n",
        fit.diffusivityCoefficient, fit.diffusivityCoefficientError
    );
    out += text;
    if (fit.fits.front().points < 6)
    {
        std::snprintf
        (
            text, sizeof text,
            "warning: %zu cells: the errors rest on few degrees of freedom (give 6 or more,"
            " over the p* the case visits)\n", fit.fits.front().points
        );
        out += text;
    }
    return out;
}

std::string segregationVelocityEntries(const SegregationFit& fit)
{
    std::ostringstream out;
    char line[240];
    const FitResult& best = fit.best();
    const auto range = [&](const char* name, const Range& r)
    {
        std::snprintf(line, sizeof line, "    %-16s(%.6g %.6g);\n", name, r.min, r.max);
        out << line;
    };
    out << "segregationVelocity\n{\n"
        << "    // w_coarse = S gammaDot (1 - c); S [m] fitted on " << best.points
        << " sheared cells under gravity (transport/GravityShearRun)\n"
        << "    law             " << best.law.name() << ";\n"
        << "    formula         \"" << best.law.formula() << "\";\n";
    for (const FittedParameter& p : best.parameters)
    {
        std::snprintf(line, sizeof line, "    %-16s%.10g;\n", p.name.c_str(), p.value);
        out << line;
    }
    out << "    errors\n    {\n";
    for (const FittedParameter& p : best.parameters)
    {
        std::snprintf(line, sizeof line, "        %-12s%.4g;\n", p.name.c_str(), p.standardError);
        out << line;
    }
    out << "    }\n";
    std::snprintf(line, sizeof line, "    reducedChi2     %.6g;\n    points          %zu;\n",
                  best.reducedChiSquare, best.points);
    out << line;
    range("pStarRange", fit.pressureNumbers);
    range("IRange", fit.inertialNumbers);
    range("sizeRatioRange", fit.sizeRatios);
    range("xRange", fit.coarseShares);
    out << "    selection\n    {\n        criterion       AIC;\n";
    for (const RankedLaw& r : fit.selection.ranking)
    {
        std::snprintf(line, sizeof line, "        %-24s%.6g;\n", r.law.c_str(), r.delta);
        out << line;
    }
    out << "    }\n}\n\nshearRateDiffusivity\n{\n"
        << "    // D = C gammaDot dMean^2 along gravity, from the same cells' displacements\n";
    std::snprintf(line, sizeof line, "    C               %.6g;   // +- %.2g (standard error)\n",
                  fit.diffusivityCoefficient, fit.diffusivityCoefficientError);
    out << line << "}\n";
    return out.str();
}

} // namespace sdf::fit

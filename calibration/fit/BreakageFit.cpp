#include "BreakageFit.hpp"

#include "ColumnTable.hpp"

#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

namespace sdf::fit::breakage
{

namespace
{

// x W of a row [J m/kg]: the law depends on size and energy only through it
double sizeTimesEnergy(const ImpactTest& t) { return t.size*t.energy; }

// The exponent lambda = fMat k (x W - xWmMin)+ of a row
double exponent(double fMat, double xWmMin, const ImpactTest& t)
{
    const double excess = sizeTimesEnergy(t) - xWmMin;
    return excess > 0 ? fMat*t.impacts*excess : 0.0;
}

// Log-likelihood (without the binomial coefficients); -inf when a row broke where the
// law says it cannot
double logLikelihood(double fMat, double xWmMin, const std::vector<ImpactTest>& tests)
{
    double sum = 0;
    for (const ImpactTest& t : tests)
    {
        const double lambda = exponent(fMat, xWmMin, t);
        if (t.broken > 0)
        {
            if (lambda <= 0) return -std::numeric_limits<double>::infinity();
            sum += double(t.broken)*std::log(-std::expm1(-lambda));
        }
        sum -= double(t.tested - t.broken)*lambda;
    }
    return sum;
}

// d/dfMat of the log-likelihood at fixed xWmMin: sum a (b/(e^(fMat a) - 1) - (n - b)),
// a = k (x W - xWmMin)+; decreasing in fMat
double scoreFMat(double fMat, double xWmMin, const std::vector<ImpactTest>& tests)
{
    double sum = 0;
    for (const ImpactTest& t : tests)
    {
        const double a = exponent(1.0, xWmMin, t);
        if (a <= 0) continue;
        sum += a*(double(t.broken)/std::expm1(fMat*a) - double(t.tested - t.broken));
    }
    return sum;
}

// The fMat that maximises the likelihood at fixed xWmMin (bisection on the score in
// log fMat: the score falls from +inf at 0 to -sum (n - b) a)
double bestFMat(double xWmMin, const std::vector<ImpactTest>& tests)
{
    double lo = 1e-12, hi = 1.0;
    while (scoreFMat(hi, xWmMin, tests) > 0 && hi < 1e15) hi *= 4;
    while (scoreFMat(lo, xWmMin, tests) < 0 && lo > 1e-300) lo /= 4;
    for (int i = 0; i < 200 && hi/lo > 1 + 1e-14; ++i)
    {
        const double mid = std::sqrt(lo*hi);
        (scoreFMat(mid, xWmMin, tests) > 0 ? lo : hi) = mid;
    }
    return std::sqrt(lo*hi);
}

double profile(double xWmMin, const std::vector<ImpactTest>& tests)
{
    return logLikelihood(bestFMat(xWmMin, tests), xWmMin, tests);
}

// The threshold that maximises the profile on [0, cMax): a grid, then golden sections
// about its best point
double bestThreshold(double cMax, const std::vector<ImpactTest>& tests)
{
    constexpr int n = 200;
    // (a row counts as above the threshold from c (1 + 1e-9) on: every breaking row does)
    const double top = cMax*(1 - 1e-6);
    int best = 0;
    double bestValue = -std::numeric_limits<double>::infinity();
    for (int i = 0; i <= n; ++i)
    {
        const double value = profile(top*i/n, tests);
        if (value > bestValue) { bestValue = value; best = i; }
    }
    double a = top*std::max(0, best - 1)/n, b = top*std::min(n, best + 1)/n;
    const double g = 0.5*(std::sqrt(5.0) - 1);
    double c = b - g*(b - a), d = a + g*(b - a);
    double fc = profile(c, tests), fd = profile(d, tests);
    for (int i = 0; i < 200 && b - a > 1e-13*std::max(1.0, cMax); ++i)
    {
        if (fc > fd) { b = d; d = c; fd = fc; c = b - g*(b - a); fc = profile(c, tests); }
        else { a = c; c = d; fc = fd; d = a + g*(b - a); fd = profile(d, tests); }
    }
    const double mid = 0.5*(a + b);
    // the bound itself when the likelihood is largest there
    return profile(0.0, tests) >= profile(mid, tests) ? 0.0 : mid;
}

} // namespace

double breakageProbability(const VogelPeukertMaterial& material, const ImpactTest& test)
{
    return -std::expm1(-exponent(material.fMat, material.xWmMin, test));
}

BreakageFitResult fitVogelPeukert(const std::vector<ImpactTest>& tests)
{
    if (tests.empty()) throw std::invalid_argument("fitVogelPeukert: no impact tests");
    // x W: the smallest and largest tested, the smallest that broke anything (cMax)
    double lowest = std::numeric_limits<double>::infinity(), highest = 0;
    double cMax = std::numeric_limits<double>::infinity();
    long broken = 0, survived = 0;
    for (const ImpactTest& t : tests)
    {
        lowest = std::min(lowest, sizeTimesEnergy(t));
        highest = std::max(highest, sizeTimesEnergy(t));
        if (t.broken > 0) cMax = std::min(cMax, sizeTimesEnergy(t));
        broken += t.broken;
        survived += t.tested - t.broken;
    }
    if (highest - lowest <= 1e-12*highest)
    {
        throw std::invalid_argument
        (
            "impact tests: every row has the same size times impact energy x W = "
            + numberText(lowest) + " J m/kg, so fMat and xWmMin are not identifiable "
            "(a steeper law with a higher threshold breaks as many): test at two or more "
            "impact velocities"
        );
    }
    if (broken == 0)
    {
        throw std::invalid_argument
        (
            "impact tests: no particle broke in any test, so the threshold xWmMin lies above "
            "every x W tested (largest " + numberText(highest) + " J m/kg) and fMat "
            "cannot be fitted: test at higher impact velocities"
        );
    }
    // the breaking rows (x W from cMax to highest) must span two x W: at one, only
    // fMat (x W - xWmMin) is fixed
    if (highest - cMax <= 1e-12*highest)
    {
        throw std::invalid_argument
        (
            "impact tests: particles broke only at x W = " + numberText(cMax) + " J m/kg (every "
            "row at or above it has that x W), so fMat and xWmMin are not identifiable: test "
            "at a higher impact velocity too"
        );
    }
    // every particle broke wherever the law lets it: fMat grows without bound
    bool saturated = true;
    for (const ImpactTest& t : tests)
    {
        if (sizeTimesEnergy(t) >= cMax && t.broken < t.tested) saturated = false;
    }
    if (saturated || survived == 0)
    {
        throw std::invalid_argument
        (
            "impact tests: every particle broke in every test at or above the lowest x W "
            "that broke any (" + numberText(cMax) + " J m/kg), so fMat has no upper bound: test "
            "at lower impact velocities, where some particles survive"
        );
    }

    BreakageFitResult r;
    const double c = bestThreshold(cMax, tests);
    const double f = bestFMat(c, tests);
    r.material.fMat = f;
    r.material.xWmMin = c;
    r.thresholdAtZero = c == 0.0;
    r.logLikelihood = logLikelihood(f, c, tests);

    // Rows at the threshold (to round-off: the search may stop on a tested x W, a corner
    // of the likelihood) or below it are certain, P = 0: they take no part in the
    // curvature, the degrees of freedom or the residuals
    auto above = [c](const ImpactTest& t) { return sizeTimesEnergy(t) > c*(1 + 1e-9) + 1e-300; };

    // Observed information: lambda = f k (u - c) above the threshold, with
    // dl/dlambda = b/(e^lambda - 1) - (n - b),
    // d2l/dlambda2 = -b e^lambda/(e^lambda - 1)^2 = -b e^-lambda/(1 - e^-lambda)^2
    double hff = 0, hfc = 0, hcc = 0;
    for (const ImpactTest& t : tests)
    {
        if (!above(t)) continue;
        const double a = exponent(1.0, c, t);
        const double k = t.impacts, lambda = f*a;
        const double d1 = double(t.broken)/std::expm1(lambda) - double(t.tested - t.broken);
        const double m = std::expm1(-lambda);
        const double d2 = -double(t.broken)*std::exp(-lambda)/(m*m);
        hff += d2*a*a;
        hfc += d2*a*(-f*k) + d1*(-k);
        hcc += d2*f*f*k*k;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.fMatError = r.xWmMinError = r.correlation = nan;
    if (r.thresholdAtZero)
    {
        // at the bound the threshold's score is not zero: fMat's error at xWmMin = 0
        if (hff < 0) r.fMatError = std::sqrt(-1/hff);
    }
    else
    {
        // covariance = (-H)^-1
        const double det = hff*hcc - hfc*hfc;
        if (det > 0 && hff < 0)
        {
            r.fMatError = std::sqrt(-hcc/det);
            r.xWmMinError = std::sqrt(-hff/det);
            r.correlation = (hfc/det)/(r.fMatError*r.xWmMinError);
        }
    }

    // The check: deviance, Pearson residuals (1 - P as e^-lambda: P rounds to 1 first)
    std::map<double, SizeResidual> bySize;
    int informative = 0;
    for (const ImpactTest& t : tests)
    {
        const double lambda = exponent(f, c, t);
        const double P = -std::expm1(-lambda), Q = std::exp(-lambda);
        const double n = double(t.tested), b = double(t.broken);
        auto term = [](double observed, double expected)
        {
            return observed > 0 ? observed*std::log(observed/expected) : 0.0;
        };
        r.deviance += 2*(term(b, n*P) + term(n - b, n*Q));
        const double var = n*P*Q;
        const double residual = var > 0 ? (b - n*P)/std::sqrt(var) : 0.0;
        r.probability.push_back(P);
        r.pearsonResidual.push_back(residual);
        if (!above(t)) continue;
        ++informative;
        SizeResidual& s = bySize[t.size];
        s.size = t.size;
        ++s.rows;
        s.meanResidual += residual;
    }
    for (auto& [size, s] : bySize)
    {
        s.meanResidual /= s.rows;
        r.bySize.push_back(s);
    }
    // the degrees of freedom: the rows above the threshold less the two constants
    r.degreesOfFreedom = informative - 2;
    r.pValue = r.degreesOfFreedom > 0 ? gsl_cdf_chisq_Q(r.deviance, r.degreesOfFreedom) : 1.0;
    return r;
}

} // namespace sdf::fit::breakage

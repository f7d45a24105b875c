#include "FragmentSieving.hpp"

#include "ColumnTable.hpp"

#include <Eigen/Dense>
#include <gsl/gsl_multimin.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace sdf::fit::breakage
{

std::vector<SieveFraction> readFragmentSieving(std::istream& stream, const std::string& source)
{
    const ColumnTable table = readColumnTable(stream, source, {"size", "sieve", "mass"});
    for (const char* name : {"size", "sieve", "mass"})
    {
        if (table.column(name) < 0)
        {
            refuseAt(source, table.headerLine, std::string("no column '") + name + "' (the columns: size, sieve, mass)");
        }
    }
    if (table.rows.empty()) refuseAt(source, table.headerLine, "no rows after the header");
    std::vector<SieveFraction> out;
    std::set<std::pair<double, double>> seen;
    std::map<double, double> total;
    std::map<double, int> lastLine;
    for (std::size_t r = 0; r < table.rows.size(); ++r)
    {
        const auto& row = table.rows[r];
        SieveFraction f;
        f.line = table.lines[r];
        f.parentSize = row[std::size_t(table.column("size"))];
        f.sieve = row[std::size_t(table.column("sieve"))];
        f.mass = row[std::size_t(table.column("mass"))];
        if (!(f.parentSize > 0)) refuseAt(source, f.line, "column 'size': " + numberText(f.parentSize) + " must be > 0 [m]");
        if (f.sieve < 0 || f.sieve >= f.parentSize)
        {
            refuseAt(source, f.line, "column 'sieve': " + numberText(f.sieve) + " must be >= 0 (0: the pan) and below "
                     "the parent size " + numberText(f.parentSize) + " m");
        }
        if (f.mass < 0) refuseAt(source, f.line, "column 'mass': " + numberText(f.mass) + " must be >= 0");
        if (!seen.insert({f.parentSize, f.sieve}).second)
        {
            refuseAt(source, f.line, "sieve " + numberText(f.sieve) + " m given twice for parents of " + numberText(f.parentSize) + " m");
        }
        total[f.parentSize] += f.mass;
        lastLine[f.parentSize] = f.line;
        out.push_back(f);
    }
    for (const auto& [size, mass] : total)
    {
        if (!(mass > 0)) refuseAt(source, lastLine[size], "the fragments of parents of " + numberText(size) + " m weigh nothing");
    }
    return out;
}

std::vector<SieveFraction> readFragmentSieving(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::invalid_argument("cannot open fragment sieving '" + path + "'");
    return readFragmentSieving(in, path);
}

std::vector<FinerFraction> finerFractions(const std::vector<SieveFraction>& sieving)
{
    std::map<double, std::vector<const SieveFraction*>> byParent;
    for (const SieveFraction& f : sieving) byParent[f.parentSize].push_back(&f);
    std::vector<FinerFraction> out;
    for (auto& [size, rows] : byParent)
    {
        std::sort(rows.begin(), rows.end(), [](auto a, auto b) { return a->sieve < b->sieve; });
        double total = 0;
        for (const SieveFraction* f : rows) total += f->mass;
        double below = 0;
        for (const SieveFraction* f : rows)
        {
            // finer than this sieve: what passed it (the pan and the finer sieves)
            if (f->sieve > 0) out.push_back({size, f->sieve/size, below/total});
            below += f->mass;
        }
    }
    return out;
}

double austinFiner(double phi, double gamma, double beta, double ratio)
{
    return phi*std::pow(ratio, gamma) + (1 - phi)*std::pow(ratio, beta);
}

namespace
{

struct Problem
{
    std::vector<FinerFraction> points;
};

// For fixed exponents B is linear in phi: its least-squares value, kept in [0, 1]
double bestPhi(const Problem& p, double gamma, double beta)
{
    double num = 0, den = 0;
    for (const FinerFraction& q : p.points)
    {
        const double g = std::pow(q.ratio, gamma), b = std::pow(q.ratio, beta);
        num += (q.finer - b)*(g - b);
        den += (g - b)*(g - b);
    }
    return den > 0 ? std::clamp(num/den, 0.0, 1.0) : 0.5;
}

double sumOfSquares(const Problem& p, double phi, double gamma, double beta)
{
    double s = 0;
    for (const FinerFraction& q : p.points)
    {
        const double r = austinFiner(phi, gamma, beta, q.ratio) - q.finer;
        s += r*r;
    }
    return s;
}

// The profile over the exponents' logarithms (positive exponents by construction)
double profileOfLogs(const gsl_vector* v, void* params)
{
    const Problem& p = *static_cast<const Problem*>(params);
    const double gamma = std::exp(gsl_vector_get(v, 0)), beta = std::exp(gsl_vector_get(v, 1));
    if (!std::isfinite(gamma) || !std::isfinite(beta) || gamma > 1e3 || beta > 1e3) return 1e300;
    return sumOfSquares(p, bestPhi(p, gamma, beta), gamma, beta);
}

} // namespace

AustinFitResult fitAustin(const std::vector<SieveFraction>& sieving)
{
    Problem p{finerFractions(sieving)};
    std::set<double> ratios;
    for (const FinerFraction& q : p.points) ratios.insert(q.ratio);
    if (p.points.size() < 4 || ratios.size() < 3)
    {
        throw std::invalid_argument
        (
            "fragment sieving: " + std::to_string(p.points.size()) + " cumulative fractions at "
            + std::to_string(ratios.size()) + " distinct sieve/parent ratios cannot determine "
            "Austin's phi, gamma and beta: sieve the fragments on three or more sieves (and "
            "four or more fractions in all)"
        );
    }
    // a grid of the exponents, then the simplex from its best point
    double best = std::numeric_limits<double>::infinity(), g0 = 1, b0 = 3;
    for (int i = 0; i <= 30; ++i)
    {
        for (int j = 0; j <= 30; ++j)
        {
            const double gamma = 0.1*std::pow(200.0, i/30.0), beta = 0.1*std::pow(200.0, j/30.0);
            const double s = sumOfSquares(p, bestPhi(p, gamma, beta), gamma, beta);
            if (s < best) { best = s; g0 = gamma; b0 = beta; }
        }
    }
    gsl_multimin_function fn{&profileOfLogs, 2, &p};
    gsl_vector* x = gsl_vector_alloc(2);
    gsl_vector* step = gsl_vector_alloc(2);
    gsl_vector_set(x, 0, std::log(g0));
    gsl_vector_set(x, 1, std::log(b0));
    gsl_vector_set_all(step, 0.1);
    gsl_multimin_fminimizer* m = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2);
    gsl_multimin_fminimizer_set(m, &fn, x, step);
    for (int it = 0; it < 2000; ++it)
    {
        if (gsl_multimin_fminimizer_iterate(m)) break;
        if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(m), 1e-12) == GSL_SUCCESS) break;
    }
    double gamma = std::exp(gsl_vector_get(m->x, 0)), beta = std::exp(gsl_vector_get(m->x, 1));
    gsl_multimin_fminimizer_free(m);
    gsl_vector_free(step);
    gsl_vector_free(x);
    double phi = bestPhi(p, gamma, beta);
    // the same function with the terms swapped: phi weighs the finer (smaller) exponent
    if (gamma > beta) { std::swap(gamma, beta); phi = 1 - phi; }

    AustinFitResult r;
    r.phi = phi; r.gamma = gamma; r.beta = beta;
    r.points = int(p.points.size());
    const double ss = sumOfSquares(p, phi, gamma, beta);
    r.rms = std::sqrt(ss/r.points);
    // standard errors: s^2 (J^T J)^-1, J the residuals' derivatives in (phi, gamma, beta)
    Eigen::MatrixXd J(r.points, 3);
    for (int i = 0; i < r.points; ++i)
    {
        const double q = p.points[std::size_t(i)].ratio, lq = std::log(q);
        const double g = std::pow(q, gamma), b = std::pow(q, beta);
        J(i, 0) = g - b;
        J(i, 1) = phi*g*lq;
        J(i, 2) = (1 - phi)*b*lq;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.phiError = r.gammaError = r.betaError = nan;
    const bool interior = phi > 0 && phi < 1;
    const Eigen::Matrix3d JtJ = J.transpose()*J;
    Eigen::FullPivLU<Eigen::Matrix3d> lu(JtJ);
    if (interior && r.points > 3 && lu.isInvertible())
    {
        const Eigen::Matrix3d cov = (ss/(r.points - 3))*lu.inverse();
        r.phiError = std::sqrt(cov(0, 0));
        r.gammaError = std::sqrt(cov(1, 1));
        r.betaError = std::sqrt(cov(2, 2));
    }
    return r;
}

} // namespace sdf::fit::breakage

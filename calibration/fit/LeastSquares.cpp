#include "fit/LeastSquares.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

namespace sdf::fit
{

namespace
{

//- Residual of a trial point where the law is not positive (log space) or
//  not finite: large but finite, so GSL rejects the step and shrinks the
//  trust region instead of stopping on a NaN.
constexpr double penaltyResidual = 1e10;

struct Problem
{
    const ConstitutiveLaw& law;
    const std::vector<Observation>& data;
    FitSpace space;
    //- Set by the Jacobian callback when the law's gradient is not finite
    //  (the callback then stops GSL with an error status).
    std::optional<std::size_t> nonFiniteGradientRow;
};

//- Normalised residual r_i; false when the law is unusable at this row.
bool residual(const Problem& problem, std::size_t i, const Eigen::VectorXd& p, double& r)
{
    const Observation& o = problem.data[i];
    const double f = problem.law.evaluate(o.condition, p);
    if (problem.space == FitSpace::logarithmic)
    {
        if (!(f > 0.0) || !std::isfinite(f))
        {
            r = penaltyResidual;
            return false;
        }
        r = (std::log(o.value) - std::log(f)) / (o.sigma / o.value);
    }
    else
    {
        if (!std::isfinite(f))
        {
            r = penaltyResidual;
            return false;
        }
        r = (o.value - f) / o.sigma;
    }
    return true;
}

//- Row i of the Jacobian dr_i/dp (zero where the law is unusable: such a
//  point is never accepted, see penaltyResidual).
Eigen::RowVectorXd jacobianRow(const Problem& problem, std::size_t i, const Eigen::VectorXd& p)
{
    const Observation& o = problem.data[i];
    const Eigen::VectorXd g = problem.law.gradient(o.condition, p);
    if (problem.space == FitSpace::logarithmic)
    {
        const double f = problem.law.evaluate(o.condition, p);
        if (!(f > 0.0) || !std::isfinite(f))
        {
            return Eigen::RowVectorXd::Zero(p.size());
        }
        return -(g.transpose() / f) / (o.sigma / o.value);
    }
    return -g.transpose() / o.sigma;
}

Eigen::VectorXd toEigen(const gsl_vector* v)
{
    Eigen::VectorXd e(v->size);
    for (std::size_t j = 0; j < v->size; ++j)
    {
        e(j) = gsl_vector_get(v, j);
    }
    return e;
}

// GSL calls these through C frames: no exception may cross them.
int gslResiduals(const gsl_vector* x, void* params, gsl_vector* f)
{
    try
    {
        const Problem& problem = *static_cast<const Problem*>(params);
        const Eigen::VectorXd p = toEigen(x);
        for (std::size_t i = 0; i < problem.data.size(); ++i)
        {
            double r = 0.0;
            residual(problem, i, p, r);
            gsl_vector_set(f, i, r);
        }
        return GSL_SUCCESS;
    }
    catch (...)
    {
        return GSL_EBADFUNC;
    }
}

int gslJacobian(const gsl_vector* x, void* params, gsl_matrix* J)
{
    try
    {
        Problem& problem = *static_cast<Problem*>(params);
        const Eigen::VectorXd p = toEigen(x);
        for (std::size_t i = 0; i < problem.data.size(); ++i)
        {
            const Eigen::RowVectorXd row = jacobianRow(problem, i, p);
            if (!row.allFinite())
            {
                problem.nonFiniteGradientRow = i;
                return GSL_EBADFUNC;
            }
            for (Eigen::Index j = 0; j < row.size(); ++j)
            {
                gsl_matrix_set(J, i, j, row(j));
            }
        }
        return GSL_SUCCESS;
    }
    catch (...)
    {
        return GSL_EBADFUNC;
    }
}

struct WorkspaceDeleter
{
    void operator()(gsl_multifit_nlinear_workspace* w) const { gsl_multifit_nlinear_free(w); }
};

std::string describe(const ConstitutiveLaw& law, std::size_t rows)
{
    std::ostringstream s;
    s << "fit of law '" << law.name() << "' to " << rows << " rows";
    return s.str();
}

//- The parameters that dominate a null direction of the Jacobian.
std::string nullDirection
(
    const std::vector<std::string>& names,
    const Eigen::VectorXd& direction
)
{
    const double largest = direction.cwiseAbs().maxCoeff();
    std::string list;
    for (Eigen::Index j = 0; j < direction.size(); ++j)
    {
        if (std::abs(direction(j)) >= 0.1 * largest)
        {
            list += (list.empty() ? "" : ", ") + names[j];
        }
    }
    return list;
}

} // namespace

std::string toString(FitStatus status)
{
    switch (status)
    {
        case FitStatus::converged: return "converged";
        case FitStatus::maxIterationsReached: return "maximum iterations reached";
        case FitStatus::noProgress: return "no progress";
        case FitStatus::singularCovariance: return "singular covariance";
        case FitStatus::nonFiniteResult: return "non-finite result";
        case FitStatus::invalidLaw: return "law not usable on the data";
        case FitStatus::solverError: return "solver error";
    }
    return "unknown";
}

void FitResult::throwIfFailed() const
{
    if (!converged())
    {
        throw FitFailure(message);
    }
}

Eigen::VectorXd FitResult::values() const
{
    Eigen::VectorXd v(parameters.size());
    for (std::size_t j = 0; j < parameters.size(); ++j)
    {
        v(j) = parameters[j].value;
    }
    return v;
}

const FittedParameter& FitResult::parameter(const std::string& name) const
{
    for (const FittedParameter& p : parameters)
    {
        if (p.name == name)
        {
            return p;
        }
    }
    throw std::out_of_range("law '" + law.name() + "' has no parameter '" + name + "'");
}

double FitResult::evaluate(const Condition& c) const
{
    return law.evaluate(c, values());
}

FitResult fitLaw
(
    const ConstitutiveLaw& law,
    const std::vector<Observation>& data,
    const FitOptions& options
)
{
    const std::size_t k = law.parameterCount();
    const std::string context = describe(law, data.size());
    validateObservations(data, k, options.space == FitSpace::logarithmic, context);

    Eigen::VectorXd start = options.initialParameters
                          ? *options.initialParameters
                          : law.initialParameters(data);
    if (std::size_t(start.size()) != k)
    {
        std::ostringstream m;
        m << context << ": initial parameters have " << start.size()
          << " entries, the law has " << k;
        throw std::invalid_argument(m.str());
    }
    if (!start.allFinite())
    {
        throw std::invalid_argument(context + ": initial parameters are not finite");
    }
    if (options.maxIterations == 0)
    {
        throw std::invalid_argument(context + ": maxIterations must be >= 1");
    }

    FitResult result(law);
    result.space = options.space;
    result.sigmaMeaning = options.sigmaMeaning;
    result.points = data.size();
    result.envelope = envelopeOf(data);
    const std::vector<std::string> names = law.parameterNames();
    const auto fail = [&](FitStatus status, const std::string& reason)
    {
        result.status = status;
        result.message = context + " failed (" + toString(status) + "): " + reason;
    };

    Problem problem{law, data, options.space, std::nullopt};
    // The start is checked here, not left to GSL: a law that is unusable, has
    // a non-finite gradient, or does not depend on a parameter at the start
    // would otherwise reach GSL's own checks, whose default handler aborts.
    Eigen::MatrixXd startJacobian(data.size(), k);
    for (std::size_t i = 0; i < data.size(); ++i)
    {
        double r = 0.0;
        std::ostringstream m;
        if (!residual(problem, i, start, r))
        {
            m << "the law at the initial parameters is not "
              << (options.space == FitSpace::logarithmic ? "positive and finite" : "finite")
              << " at row " << i;
            fail(FitStatus::invalidLaw, m.str());
            return result;
        }
        startJacobian.row(i) = jacobianRow(problem, i, start);
        if (!startJacobian.row(i).allFinite())
        {
            m << "the law's gradient is not finite at row " << i << " at the initial parameters";
            fail(FitStatus::nonFiniteResult, m.str());
            return result;
        }
    }
    for (std::size_t j = 0; j < k; ++j)
    {
        if (startJacobian.col(j).isZero(0.0))
        {
            fail
            (
                FitStatus::singularCovariance,
                "parameters not identifiable from these data (unidentified direction: "
              + names[j] + " (the data do not depend on it))"
            );
            return result;
        }
    }

    // ---- GSL trust region (Levenberg-Marquardt steps, More scaling)
    gsl_multifit_nlinear_parameters parameters = gsl_multifit_nlinear_default_parameters();
    parameters.trs = gsl_multifit_nlinear_trs_lm;
    gsl_multifit_nlinear_fdf fdf;
    fdf.f = gslResiduals;
    fdf.df = gslJacobian;
    fdf.fvv = nullptr;
    fdf.n = data.size();
    fdf.p = k;
    fdf.params = &problem;

    std::unique_ptr<gsl_multifit_nlinear_workspace, WorkspaceDeleter> workspace
    (
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &parameters, data.size(), k)
    );
    if (!workspace)
    {
        fail(FitStatus::solverError, "could not allocate the GSL workspace");
        return result;
    }
    gsl_vector_view startView = gsl_vector_view_array(start.data(), k);
    // Iterated here rather than by gsl_multifit_nlinear_driver, which reports
    // a start that is already the minimum (no step can reduce the cost: the
    // log-space power laws start at their linearised, exact answer) as
    // "maximum iterations reached"; such a stall is judged below by the size
    // of the remaining Gauss-Newton step instead.
    int solverStatus = gsl_multifit_nlinear_init(&startView.vector, &fdf, workspace.get());
    int info = 0;
    bool testsPassed = false;
    bool stalled = false;
    for
    (
        std::size_t iteration = 0;
        solverStatus == GSL_SUCCESS && iteration < options.maxIterations;
        ++iteration
    )
    {
        const int step = gsl_multifit_nlinear_iterate(workspace.get());
        stalled = step == GSL_ENOPROG;
        if (stalled)
        {
            // GSL resets its damping after a stall; once at the first
            // iteration there is nothing to reset, as in GSL's driver.
            if (iteration == 0)
            {
                break;
            }
            continue;
        }
        if (step != GSL_SUCCESS)
        {
            solverStatus = step;
            break;
        }
        if
        (
            gsl_multifit_nlinear_test
            (
                options.xtol, options.gtol, options.ftol, &info, workspace.get()
            ) == GSL_SUCCESS
        )
        {
            testsPassed = true;
            break;
        }
    }
    result.iterations = gsl_multifit_nlinear_niter(workspace.get());
    const Eigen::VectorXd p = toEigen(gsl_multifit_nlinear_position(workspace.get()));

    // ---- Results at the final point (computed here, not taken from GSL, so
    // every number below is consistent with the law and the data).
    result.parameters.resize(k);
    for (std::size_t j = 0; j < k; ++j)
    {
        result.parameters[j] = FittedParameter{names[j], p(j), NAN};
    }
    const std::size_t n = data.size();
    Eigen::MatrixXd J(n, k);
    double weightSum = 0.0, weightedMean = 0.0;
    std::vector<double> z(n), w(n);
    result.fitted.resize(n);
    result.residuals.resize(n);
    result.normalisedResiduals.resize(n);
    std::optional<std::size_t> unusableRow;
    result.chiSquare = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const Observation& o = data[i];
        double r = 0.0;
        if (!residual(problem, i, p, r) && !unusableRow)
        {
            unusableRow = i;
        }
        result.fitted[i] = law.evaluate(o.condition, p);
        result.residuals[i] = o.value - result.fitted[i];
        result.normalisedResiduals[i] = r;
        result.chiSquare += r * r;
        J.row(i) = jacobianRow(problem, i, p);
        const bool logSpace = options.space == FitSpace::logarithmic;
        z[i] = logSpace ? std::log(o.value) : o.value;
        const double s = logSpace ? o.sigma / o.value : o.sigma;
        w[i] = 1.0 / (s * s);
        weightSum += w[i];
        weightedMean += w[i] * z[i];
    }
    weightedMean /= weightSum;
    double totalSum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
        totalSum += w[i] * (z[i] - weightedMean) * (z[i] - weightedMean);
    }
    const double dof = double(n - k);
    result.reducedChiSquare = result.chiSquare / dof;
    result.rSquared = totalSum > 0.0 ? 1.0 - result.chiSquare / totalSum : NAN;
    if (options.sigmaMeaning == SigmaMeaning::absolute)
    {
        result.aic = result.chiSquare + 2.0 * k;
        result.bic = result.chiSquare + k * std::log(double(n));
    }
    else
    {
        // Floor: a noise-free table would give ln 0.
        const double meanSquare = std::max(result.chiSquare / n, DBL_MIN);
        result.aic = n * std::log(meanSquare) + 2.0 * (k + 1);
        result.bic = n * std::log(meanSquare) + (k + 1) * std::log(double(n));
    }

    // ---- Covariance from the column-equilibrated Jacobian: the rank test is
    // then independent of the parameters' units.
    Eigen::VectorXd columnNorm = J.colwise().norm().transpose();
    bool singular = false;
    std::string singularDirection;
    double remainingStepInErrors = INFINITY;
    for (std::size_t j = 0; j < k; ++j)
    {
        if (!(columnNorm(j) > 0.0) || !std::isfinite(columnNorm(j)))
        {
            singular = true;
            singularDirection = names[j] + " (the data do not depend on it)";
            columnNorm(j) = 1.0;
        }
    }
    // (A Jacobian with NaN or inf is reported below; no SVD of it.)
    if (J.allFinite())
    {
        const Eigen::MatrixXd equilibrated = J * columnNorm.cwiseInverse().asDiagonal();
        Eigen::JacobiSVD<Eigen::MatrixXd> svd
        (
            equilibrated, Eigen::ComputeThinU | Eigen::ComputeThinV
        );
        const Eigen::VectorXd singularValues = svd.singularValues();
        if (!singular
            && singularValues(k - 1) < options.rankTolerance * singularValues(0))
        {
            singular = true;
            singularDirection = nullDirection(names, svd.matrixV().col(k - 1));
        }
        if (!singular)
        {
            const Eigen::VectorXd inverseSquares = singularValues.array().square().inverse();
            const Eigen::MatrixXd V = svd.matrixV();
            const Eigen::MatrixXd equilibratedCovariance =
                V * inverseSquares.asDiagonal() * V.transpose();
            const Eigen::VectorXd inverseNorm = columnNorm.cwiseInverse();
            const Eigen::MatrixXd covariance =
                inverseNorm.asDiagonal() * equilibratedCovariance * inverseNorm.asDiagonal();
            // Symmetric to the last bit (rounding leaves ~1e-20 asymmetries).
            result.covariance = 0.5 * (covariance + covariance.transpose());
            // Remaining Gauss-Newton step, in units of the (unscaled) errors.
            Eigen::VectorXd r(n);
            for (std::size_t i = 0; i < n; ++i)
            {
                r(i) = result.normalisedResiduals[i];
            }
            const Eigen::VectorXd equilibratedStep =
                V * (singularValues.cwiseInverse().asDiagonal() * (svd.matrixU().transpose() * r));
            const Eigen::VectorXd step = -(inverseNorm.asDiagonal() * equilibratedStep);
            remainingStepInErrors =
                (step.array().abs() / result.covariance.diagonal().array().sqrt()).maxCoeff();
            if (options.sigmaMeaning == SigmaMeaning::relative)
            {
                result.covariance *= result.reducedChiSquare;
            }
            for (std::size_t j = 0; j < k; ++j)
            {
                result.parameters[j].standardError = std::sqrt(result.covariance(j, j));
            }
        }
    }

    // ---- Verdict: the first reason found, in order of what the user must fix.
    // A stall counts as converged only where the remaining Gauss-Newton step
    // is negligible against the parameters' errors: then no step can reduce
    // the cost because the point is the minimum to rounding.
    constexpr double negligibleStep = 1e-6;
    const bool atMinimum = stalled && remainingStepInErrors <= negligibleStep;
    std::ostringstream how;
    if (problem.nonFiniteGradientRow)
    {
        how << "the law's gradient is not finite at row " << *problem.nonFiniteGradientRow
            << " (after " << result.iterations << " iterations)";
        fail(FitStatus::nonFiniteResult, how.str());
    }
    else if (solverStatus != GSL_SUCCESS)
    {
        fail(FitStatus::solverError, std::string("GSL: ") + gsl_strerror(solverStatus));
    }
    else if (!p.allFinite())
    {
        fail(FitStatus::nonFiniteResult, "parameters are not finite");
    }
    else if (unusableRow)
    {
        how << "the fitted law is not "
            << (options.space == FitSpace::logarithmic ? "positive and finite" : "finite")
            << " at row " << *unusableRow;
        fail(FitStatus::invalidLaw, how.str());
    }
    else if (!J.allFinite() || !std::isfinite(result.chiSquare))
    {
        fail(FitStatus::nonFiniteResult, "residuals or Jacobian are not finite");
    }
    else if (singular)
    {
        // Before the convergence verdict: an unidentifiable direction is what
        // the user must fix (more conditions, fewer parameters), and it is
        // also why a solver stalls in a valley.
        fail
        (
            FitStatus::singularCovariance,
            "parameters not identifiable from these data (unidentified direction: "
          + singularDirection + ")"
        );
    }
    else if (stalled && !atMinimum)
    {
        how << "the trust region could not reduce the cost after " << result.iterations
            << " iterations, away from a minimum (bad start, or law unusable near it)";
        fail(FitStatus::noProgress, how.str());
    }
    else if (!testsPassed && !atMinimum)
    {
        how << "not converged after " << result.iterations << " iterations (maxIterations "
            << options.maxIterations << ")";
        fail(FitStatus::maxIterationsReached, how.str());
    }
    else if (!result.covariance.allFinite())
    {
        fail(FitStatus::nonFiniteResult, "standard errors are not finite");
    }
    else
    {
        result.status = FitStatus::converged;
        how << context << ": converged in " << result.iterations << " iterations ("
            << (atMinimum ? "no step reduces the cost: at the minimum"
                : info == 1 ? "small step" : info == 2 ? "small gradient" : "small cost change")
            << ")";
        result.message = how.str();
    }
    return result;
}

FitResult fitLawOrThrow
(
    const ConstitutiveLaw& law,
    const std::vector<Observation>& data,
    const FitOptions& options
)
{
    FitResult result = fitLaw(law, data, options);
    result.throwIfFailed();
    return result;
}

} // namespace sdf::fit

// Weighted nonlinear least squares of a ConstitutiveLaw to a table of DEM
// results with GSL's trust-region solver (gsl_multifit_nlinear, Levenberg-
// Marquardt steps), with parameter errors, goodness of fit and information
// criteria. A fit that did not converge, whose covariance is singular (a
// parameter the data cannot identify) or whose result is not finite comes
// back with a failed status and a message naming the law and the reason:
// never as if good (fitLawOrThrow and the dictionary writer refuse it).
#ifndef sdf_fit_LeastSquares_hpp
#define sdf_fit_LeastSquares_hpp

#include "fit/ConstitutiveLaw.hpp"
#include "fit/FitData.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sdf::fit
{

//- Where the residuals are measured.
//  logarithmic (default): r_i = (ln y_i - ln f_i)/(sigma_i/y_i). DEM transport
//    coefficients span decades over the envelope (T over two decades, phi
//    from dilute to dense) and their Green-Kubo errors are relative (a few %
//    of the value), so log space weighs every condition by its relative
//    error, the noise is close to Gaussian there, and the power laws become
//    linear in (ln A, a, m, b): a convex problem with one minimum. Needs y > 0.
//  linear: r_i = (y_i - f_i)/sigma_i, for values that may be <= 0 (a noisy eta
//    near zero) or absolute Gaussian errors.
enum class FitSpace
{
    logarithmic,
    linear
};

//- What the given sigma mean.
//  relative (default): only their ratios are trusted; the covariance is scaled
//    by the reduced chi-square (as scipy's curve_fit with absolute_sigma =
//    False). Then a law that misses the data (model error, which DEM data
//    always have to some degree) gets wider, honest errors, and Green-Kubo
//    errors that are off by a common factor do not matter.
//  absolute: the sigma are true standard errors; covariance (J^T W J)^-1
//    unscaled, and reducedChiSquare is then a test of the law (~1 if it fits).
enum class SigmaMeaning
{
    relative,
    absolute
};

struct FitOptions
{
    FitSpace space = FitSpace::logarithmic;
    SigmaMeaning sigmaMeaning = SigmaMeaning::relative;
    std::size_t maxIterations = 200;
    //- GSL convergence tests: relative step size and scaled gradient.
    double xtol = 1e-10;
    double gtol = 1e-10;
    double ftol = 0.0;
    //- Start; the law's initialParameters(data) when absent.
    std::optional<Eigen::VectorXd> initialParameters;
    //- The covariance is singular when the smallest singular value of the
    //  column-equilibrated Jacobian is below this times the largest (the fit
    //  then says which parameters form the unidentifiable direction).
    double rankTolerance = 1e-10;
};

enum class FitStatus
{
    converged,
    maxIterationsReached,
    noProgress,            // the trust region could not reduce the cost
    singularCovariance,    // some parameter combination is not identified by the data
    nonFiniteResult,       // parameters, residuals or errors not finite
    invalidLaw,            // the law is not positive (log space) or not finite on the data
    solverError            // any other GSL status
};

std::string toString(FitStatus status);

struct FittedParameter
{
    std::string name;
    double value = 0.0;
    double standardError = 0.0;
};

struct FitResult
{
    explicit FitResult(ConstitutiveLaw fittedLaw) : law(std::move(fittedLaw)) {}

    ConstitutiveLaw law;
    FitSpace space = FitSpace::logarithmic;
    SigmaMeaning sigmaMeaning = SigmaMeaning::relative;

    FitStatus status = FitStatus::solverError;
    //- Why the fit failed (names the law), or how it converged.
    std::string message;
    bool converged() const { return status == FitStatus::converged; }
    //- Throws FitFailure with the message unless converged.
    void throwIfFailed() const;

    std::vector<FittedParameter> parameters;
    Eigen::VectorXd values() const;
    const FittedParameter& parameter(const std::string& name) const;
    //- Parameter covariance (scaled by reducedChiSquare for relative sigma).
    Eigen::MatrixXd covariance;

    std::size_t points = 0;
    std::size_t iterations = 0;
    //- Sums in the fit space: chiSquare = sum r_i^2, reducedChiSquare =
    //  chiSquare/(points - parameters).
    double chiSquare = 0.0;
    double reducedChiSquare = 0.0;
    //- Weighted coefficient of determination in the fit space (of ln y for a
    //  log-space fit): 1 - chiSquare / sum w_i (z_i - zbar_w)^2.
    double rSquared = 0.0;
    //- Gaussian likelihood in the fit space, constants dropped (they are the
    //  same for every law fitted to the same table): absolute sigma
    //  AIC = chi2 + 2k, BIC = chi2 + k ln n; relative sigma (common scale
    //  estimated, one more parameter) AIC = n ln(chi2/n) + 2(k+1),
    //  BIC = n ln(chi2/n) + (k+1) ln n.
    double aic = 0.0;
    double bic = 0.0;

    //- Per row: the law's value, y - f, and the normalised fit-space residual r_i.
    std::vector<double> fitted;
    std::vector<double> residuals;
    std::vector<double> normalisedResiduals;

    Envelope envelope;

    //- The fitted law at a condition.
    double evaluate(const Condition& c) const;
};

//- A failed fit (the what() names the law and the reason).
class FitFailure : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

//- Fits; bad input throws std::invalid_argument (validateObservations; also a
//  start of the wrong size), a failed fit is reported in the result's status.
FitResult fitLaw
(
    const ConstitutiveLaw& law,
    const std::vector<Observation>& data,
    const FitOptions& options = FitOptions()
);

//- fitLaw, throwing FitFailure unless it converged.
FitResult fitLawOrThrow
(
    const ConstitutiveLaw& law,
    const std::vector<Observation>& data,
    const FitOptions& options = FitOptions()
);

} // namespace sdf::fit

#endif

#include "fit/Laws.hpp"
#include "fit/LawFormulas.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <stdexcept>

namespace sdf::fit
{

namespace
{

//- Weighted least squares of ln y on the columns that `regressors` writes
//  for each row, over the rows with y > 0 (weights (y/sigma)^2: the inverse
//  variance of ln y). Returns an empty vector when too few rows qualify, so
//  the caller falls back to its default start.
Eigen::VectorXd logRegression
(
    const std::vector<Observation>& data,
    int columns,
    const std::function<void(const Condition&, Eigen::RowVectorXd&)>& regressors,
    const std::function<double(const Condition&)>& knownFactor
)
{
    std::vector<const Observation*> usable;
    for (const Observation& o : data)
    {
        const double known = knownFactor(o.condition);
        if (o.value > 0.0 && o.sigma > 0.0 && known > 0.0 && std::isfinite(known))
        {
            usable.push_back(&o);
        }
    }
    if (usable.size() < std::size_t(columns))
    {
        return Eigen::VectorXd();
    }
    Eigen::MatrixXd design(usable.size(), columns);
    Eigen::VectorXd target(usable.size());
    for (std::size_t i = 0; i < usable.size(); ++i)
    {
        const Observation& o = *usable[i];
        const double weight = o.value / o.sigma;   // 1 / (standard error of ln y)
        Eigen::RowVectorXd row(columns);
        regressors(o.condition, row);
        design.row(i) = weight * row;
        target(i) = weight * std::log(o.value / knownFactor(o.condition));
    }
    // Rank-revealing: degenerate data (e.g. one x only) still give a start;
    // the fit itself then reports the parameters as not identifiable.
    Eigen::VectorXd solution = design.colPivHouseholderQr().solve(target);
    return solution.allFinite() ? solution : Eigen::VectorXd();
}

// A law's start from logRegression over its first `columns` parameters, parameter 0
// being the prefactor (regressed as its logarithm): the fallback's values for the
// parameters the regression does not give, and for all of them when it gives none.
Eigen::VectorXd logRegressionStart
(
    const std::vector<Observation>& data,
    int columns,
    const std::function<void(const Condition&, Eigen::RowVectorXd&)>& regressors,
    const std::function<double(const Condition&)>& knownFactor,
    Eigen::VectorXd fallback
)
{
    const Eigen::VectorXd solution = logRegression(data, columns, regressors, knownFactor);
    if (solution.size() != columns)
    {
        return fallback;
    }
    fallback(0) = std::exp(solution(0));
    fallback.segment(1, columns - 1) = solution.tail(columns - 1);
    return fallback;
}

} // namespace

double carnahanStarlingG0(double phi)
{
    return formulas::carnahanStarlingG0(phi);
}

// ---------------------------------------------------------------- powerLaw

double SeedPowerLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::powerLaw(p(0), p(1), p(2), p(3), c.phi, c.x, c.T);
}

Eigen::VectorXd SeedPowerLaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    // Shape without A, so dD/dA is right at A = 0 too.
    const double shape = std::pow(1.0 + c.x, p(1)) * std::pow(c.T, p(2)) * std::pow(c.phi, p(3));
    const double value = p(0) * shape;
    Eigen::VectorXd g(4);
    g << shape, value * std::log1p(c.x), value * std::log(c.T), value * std::log(c.phi);
    return g;
}

Eigen::VectorXd SeedPowerLaw::initialParameters(const std::vector<Observation>& data) const
{
    Eigen::VectorXd papersValues(4);
    papersValues << 6.0, 1.0, 1.0, -1.5;
    return logRegressionStart
    (
        data, 4,
        [](const Condition& c, Eigen::RowVectorXd& row)
        {
            row << 1.0, std::log1p(c.x), std::log(c.T), std::log(c.phi);
        },
        [](const Condition&) { return 1.0; },
        papersValues
    );
}

// ----------------------------------------------------- kineticTheoryGroups

namespace
{
double kineticShape(const Condition& c)
{
    return formulas::kineticShape(c.phi, c.T, c.d);
}
} // namespace

double KineticTheoryGroupsLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::kineticTheoryGroups(p(0), p(1), c.phi, c.x, c.T, c.d);
}

Eigen::VectorXd KineticTheoryGroupsLaw::gradient
(
    const Condition& c,
    const Eigen::VectorXd& p
) const
{
    const double shape = kineticShape(c);
    Eigen::VectorXd g(2);
    g << shape * (1.0 + p(1) * c.x), p(0) * shape * c.x;
    return g;
}

Eigen::VectorXd KineticTheoryGroupsLaw::initialParameters
(
    const std::vector<Observation>& data
) const
{
    Eigen::VectorXd fallback(2);
    fallback << std::sqrt(M_PI) / 16.0, 0.0;
    return logRegressionStart
    (
        data, 1,
        [](const Condition&, Eigen::RowVectorXd& row) { row << 1.0; },
        kineticShape,
        fallback
    );
}

// ------------------------------------------------------------ sieving laws

double SievingLawBase::kineticScale(const Condition& c) const
{
    return formulas::sievingScale(diameterPower, c.T, c.d);
}

// --------------------------------------------------------- sievingPowerLaw

double SievingPowerLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::sievingPowerLaw(p(0), diameterPower, p(1), p(2), c.phi, c.x, c.T, c.d);
}

Eigen::VectorXd SievingPowerLaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double scale = kineticScale(c) * std::pow(c.phi, p(1));
    const double composition = 1.0 + p(2) * c.x;
    Eigen::VectorXd g(3);
    g << scale * composition,
         p(0) * scale * composition * std::log(c.phi),
         p(0) * scale * c.x;
    return g;
}

Eigen::VectorXd SievingPowerLaw::initialParameters(const std::vector<Observation>& data) const
{
    Eigen::VectorXd fallback(3);
    fallback << 1.0, 0.0, 0.0;
    return logRegressionStart
    (
        data, 2,
        [](const Condition& c, Eigen::RowVectorXd& row)
        {
            row << 1.0, std::log(c.phi);
        },
        [this](const Condition& c) { return kineticScale(c); },
        fallback
    );
}

// ---------------------------------------------- sievingCompositionPowerLaw

double SievingCompositionPowerLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::sievingCompositionPowerLaw(p(0), diameterPower, p(1), p(2), c.phi, c.x, c.T, c.d);
}

Eigen::VectorXd SievingCompositionPowerLaw::gradient
(
    const Condition& c,
    const Eigen::VectorXd& p
) const
{
    const double value = evaluate(c, p);
    Eigen::VectorXd g(3);
    g << value / p(0), value * std::log(c.phi), value * std::log(c.x);
    return g;
}

Eigen::VectorXd SievingCompositionPowerLaw::initialParameters
(
    const std::vector<Observation>& data
) const
{
    Eigen::VectorXd fallback(3);
    fallback << 1.0, 0.0, 1.0;
    return logRegressionStart
    (
        data, 3,
        [](const Condition& c, Eigen::RowVectorXd& row)
        {
            row << 1.0, std::log(c.phi), std::log(c.x);
        },
        [this](const Condition& c) { return kineticScale(c); },
        fallback
    );
}

// ------------------------------------------------- collisionFrequencyGroups

double CollisionFrequencyGroupsLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::collisionFrequencyGroups(p(0), p(1), p(2), c.phi, c.x, c.T, c.d);
}

Eigen::VectorXd CollisionFrequencyGroupsLaw::gradient
(
    const Condition& c,
    const Eigen::VectorXd& p
) const
{
    // Shape without C, so the derivative in C is right at C = 0 too.
    const double g0 = formulas::carnahanStarlingG0(c.phi);
    const double base = formulas::collisionScale(c.T, c.d)*c.phi*std::pow(g0, p(1));
    const double composition = 1.0 + p(2)*c.x;
    Eigen::VectorXd g(3);
    g << base*composition,
         p(0)*base*composition*std::log(g0),
         p(0)*base*c.x;
    return g;
}

Eigen::VectorXd CollisionFrequencyGroupsLaw::initialParameters
(
    const std::vector<Observation>& data
) const
{
    Eigen::VectorXd enskog(3);
    enskog << 24.0/std::sqrt(M_PI), 1.0, 0.0;
    return logRegressionStart
    (
        data, 2,
        [](const Condition& c, Eigen::RowVectorXd& row)
        {
            row << 1.0, std::log(formulas::carnahanStarlingG0(c.phi));
        },
        [](const Condition& c) { return formulas::collisionScale(c.T, c.d)*c.phi; },
        enskog
    );
}

// ------------------------------------------------------- impactEnergyGroups

double ImpactEnergyGroupsLaw::evaluate(const Condition& c, const Eigen::VectorXd& p) const
{
    return formulas::impactEnergyGroups(p(0), p(1), c.phi, c.T);
}

Eigen::VectorXd ImpactEnergyGroupsLaw::gradient(const Condition& c, const Eigen::VectorXd& p) const
{
    const double shape = formulas::impactEnergyGroups(1.0, p(1), c.phi, c.T);
    Eigen::VectorXd g(2);
    g << shape, p(0)*shape*std::log(c.phi);
    return g;
}

Eigen::VectorXd ImpactEnergyGroupsLaw::initialParameters(const std::vector<Observation>& data) const
{
    Eigen::VectorXd maxwellBoltzmann(2);
    maxwellBoltzmann << 0.5, 0.0;
    return logRegressionStart
    (
        data, 2,
        [](const Condition& c, Eigen::RowVectorXd& row)
        {
            row << 1.0, std::log(c.phi);
        },
        [](const Condition& c) { return formulas::perComponentTemperature(c.T); },
        maxwellBoltzmann
    );
}

// ----------------------------------------------------------- by name

const std::vector<std::string>& lawNames()
{
    static const std::vector<std::string> names
    {
        "collisionFrequencyGroups", "impactEnergyGroups", "kineticTheoryGroups", "powerLaw",
        "sievingCompositionPowerLaw", "sievingPowerLaw"
    };
    return names;
}

ConstitutiveLaw lawFromName(const std::string& name, int diameterPower)
{
    if (name == "powerLaw")
    {
        return SeedPowerLaw{};
    }
    if (name == "kineticTheoryGroups")
    {
        return KineticTheoryGroupsLaw{};
    }
    if (name == "sievingPowerLaw")
    {
        return SievingPowerLaw(diameterPower);
    }
    if (name == "sievingCompositionPowerLaw")
    {
        return SievingCompositionPowerLaw(diameterPower);
    }
    if (name == "collisionFrequencyGroups")
    {
        return CollisionFrequencyGroupsLaw{};
    }
    if (name == "impactEnergyGroups")
    {
        return ImpactEnergyGroupsLaw{};
    }
    std::string valid;
    for (const std::string& n : lawNames())
    {
        valid += (valid.empty() ? "" : " ") + n;
    }
    throw std::invalid_argument("unknown law '" + name + "'; valid laws: (" + valid + ")");
}

} // namespace sdf::fit

// The constitutive laws fitted to DEM transport coefficients. Each is a small
// value type with the interface of ConstitutiveLaw.hpp; parameters are in the
// order of parameterNames(). T is the sum of the three components (m2/s2),
// T1 = T/3 the per-component value of kinetic theory (docs/developer/equations.md).
#ifndef sdf_fit_Laws_hpp
#define sdf_fit_Laws_hpp

#include "fit/ConstitutiveLaw.hpp"
#include "fit/FitData.hpp"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace sdf::fit
{

//- Carnahan-Starling radial distribution at contact, g0 = (1 - phi/2)/(1 - phi)^3.
double carnahanStarlingG0(double phi);

//- The seed's eq 15 generalised: D = A (1 + x)^a T^m phi^b, parameters
//  (A, a, m, b); the paper reports A = 6, a = 1, m = 1, b = -1.5. Not
//  dimensionally homogeneous (A carries units that depend on m): it holds for
//  the particles it was fitted to. Law name `powerLaw`, as the solver's
//  diffusivity model with the same parameter names.
struct SeedPowerLaw
{
    std::string name() const { return "powerLaw"; }
    std::string formula() const { return "A*(1 + x)^a*T^m*phi^b"; }
    std::vector<std::string> parameterNames() const { return {"A", "a", "m", "b"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- Weighted linear regression of ln y on (1, ln(1+x), ln T, ln phi): the
    //  exact log-space answer for noise-free data, so the solver starts close.
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- Kinetic theory in dimensionless groups:
//    D = C d sqrt(T1) f(phi, x),  f = (1 + alpha x)/(phi g0(phi)),  T1 = T/3,
//  parameters (C, alpha), C and alpha dimensionless, so a calibration on one
//  particle size transfers to another. Chapman-Enskog for elastic spheres
//  (validation item 11) is C = sqrt(pi)/16 ~ 0.1108, alpha = 0; Savage & Dai's
//  restitution correction is C = sqrt(pi)/(8 (1 + e)). alpha carries the
//  composition dependence the seed found ((1 + x) in eq 15); 1 + alpha x must
//  stay > 0 (alpha > -1 on x <= 1). Law name `kineticTheoryGroups`.
struct KineticTheoryGroupsLaw
{
    std::string name() const { return "kineticTheoryGroups"; }
    std::string formula() const
    {
        return "C*d*sqrt(T/3)*(1 + alpha*x)/(phi*g0(phi)), g0 = (1 - phi/2)/(1 - phi)^3";
    }
    std::vector<std::string> parameterNames() const { return {"C", "alpha"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- alpha = 0 and C the weighted geometric mean of y/(d sqrt(T1)/(phi g0)).
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- What the laws for the kinetic sieving coefficient share: the fixed power k
//  of the diameter (written to the dictionary, not fitted) and the kinetic
//  scale d^k sqrt(T1) that makes E dimensionless for k = 1 (eta in m2/s).
struct SievingLawBase
{
    explicit SievingLawBase(int diameterPower) : diameterPower(diameterPower) {}

    std::vector<std::pair<std::string, double>> fixedEntries() const
    {
        return {{"diameterPower", double(diameterPower)}};
    }
    //- d^k sqrt(T1)
    double kineticScale(const Condition& c) const;

    int diameterPower;
};

//- A first law for the kinetic sieving coefficient of the coarse species:
//    eta = E d^k sqrt(T1) phi^p (1 + beta x),  T1 = T/3,
//  fitted parameters (E, p, beta), k = diameterPower fixed (not fitted).
//  With k = 1 (default) eta is in m2/s with E dimensionless: the units the
//  solver's kinetic-sieving flux needs (docs/developer/equations.md). k = 2 is the form
//  E d^2 sqrt(T1), dimensionally consistent only if eta is measured per unit
//  length (m3/s) or E carries 1/m: choose it to match how the Green-Kubo eta
//  is normalised. Law name `sievingPowerLaw`; k is written to the dictionary.
struct SievingPowerLaw : SievingLawBase
{
    explicit SievingPowerLaw(int diameterPower = 1) : SievingLawBase(diameterPower) {}

    std::string name() const { return "sievingPowerLaw"; }
    std::string formula() const
    {
        return "E*d^diameterPower*sqrt(T/3)*phi^p*(1 + beta*x)";
    }
    std::vector<std::string> parameterNames() const { return {"E", "p", "beta"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- beta = 0, (E, p) from a weighted regression of ln(y/(d^k sqrt(T1))) on ln phi.
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
};

//- Kinetic sieving coefficient of the coarse species with a power of the
//  composition:
//    eta = E d^k sqrt(T1) phi^p x^q,  T1 = T/3,
//  fitted parameters (E, p, q), k = diameterPower fixed. eta in m2/s (the
//  engine's Green-Kubo eta converted by kinematicSievingCoefficient,
//  SievingNormalisation.hpp) with E dimensionless for k = 1. The coarse's share
//  of the stress autocorrelation grows faster than linearly with the number of
//  coarse particles (about tenfold from x = 0.2 to 0.4 in the engine), which
//  (1 + beta x) cannot follow; x^q can, and vanishes with the coarse as it
//  should. Linear in log space, so the fit always has a unique optimum. Law name
//  `sievingCompositionPowerLaw`.
struct SievingCompositionPowerLaw : SievingLawBase
{
    explicit SievingCompositionPowerLaw(int diameterPower = 1) : SievingLawBase(diameterPower) {}

    std::string name() const { return "sievingCompositionPowerLaw"; }
    std::string formula() const
    {
        return "E*d^diameterPower*sqrt(T/3)*phi^p*x^q";
    }
    std::vector<std::string> parameterNames() const { return {"E", "p", "q"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- Weighted regression of ln(y/(d^k sqrt(T1))) on (1, ln phi, ln x).
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
};

//- Collision frequency per particle, in dimensionless groups (for breakage rates,
//  fit/BreakageRate.hpp):
//    omega = C (sqrt(T1)/d) phi g0(phi)^b (1 + alpha x),  T1 = T/3,  [1/s]
//  parameters (C, b, alpha), all dimensionless; d is the diameter of the species whose
//  particles' collisions are counted. Enskog's monodisperse elastic gas is
//  C = 24/sqrt(pi) ~ 13.54, b = 1, alpha = 0. Law name `collisionFrequencyGroups`.
struct CollisionFrequencyGroupsLaw
{
    std::string name() const { return "collisionFrequencyGroups"; }
    std::string formula() const
    {
        return "C*sqrt(T/3)/d*phi*g0(phi)^b*(1 + alpha*x), g0 = (1 - phi/2)/(1 - phi)^3";
    }
    std::vector<std::string> parameterNames() const { return {"C", "b", "alpha"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- alpha = 0, (C, b) from a weighted regression of ln(y/(sqrt(T1) phi/d)) on
    //  (1, ln g0).
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- Mean mass-specific impact energy of a particle's impacts, W = E/(m_i + m_j) with E
//  = 0.5 m* g_n^2 the DEM's pair impact energy (fit/BreakageRate.hpp):
//    Wmean = K T1 phi^c,  T1 = T/3,  [J/kg]
//  parameters (K, c), dimensionless. An elastic gas at equilibrium (Maxwell-Boltzmann)
//  has K = 1/2, c = 0; inelastic and sheared cells depart from it. Law name
//  `impactEnergyGroups`.
struct ImpactEnergyGroupsLaw
{
    std::string name() const { return "impactEnergyGroups"; }
    std::string formula() const { return "K*(T/3)*phi^c"; }
    std::vector<std::string> parameterNames() const { return {"K", "c"}; }
    double evaluate(const Condition& c, const Eigen::VectorXd& p) const;
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const;
    //- Weighted regression of ln(y/T1) on (1, ln phi): exact for noise-free data.
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const;
    std::vector<std::pair<std::string, double>> fixedEntries() const { return {}; }
};

//- The law whose dictionary name (`law` entry) is `name`: powerLaw,
//  kineticTheoryGroups, sievingPowerLaw, sievingCompositionPowerLaw,
//  collisionFrequencyGroups or impactEnergyGroups;
//  diameterPower is the fixed k of the sieving laws (ignored by the others).
//  Throws std::invalid_argument naming the law and the valid names.
ConstitutiveLaw lawFromName(const std::string& name, int diameterPower = 1);

//- The names lawFromName knows, sorted
const std::vector<std::string>& lawNames();

} // namespace sdf::fit

#endif

// The constitutive laws of the transport coefficients (and of the collision
// statistics the breakage rates need) as plain formulas:
// inline functions of doubles, no Eigen, no library to link, so that the fit
// library (Laws.cpp), the calibrated models and the solver's plain diffusivity
// models (powerLaw, kineticTheory) evaluate one definition of each law.
//
// Conventions (docs/developer/equations.md): T is the granular temperature as
// the SUM of the three components' mean square fluctuation velocity [m2/s2];
// laws from kinetic theory use the per-component T1 = T/3. x is the coarse
// fraction of the solids, phi the total solids fraction, d the diameter [m] of
// the species the value is for.
#ifndef sdf_fit_LawFormulas_hpp
#define sdf_fit_LawFormulas_hpp

#include <cmath>

namespace sdf::fit::formulas
{

//- Per-component granular temperature T1 = T/3 of kinetic theory
inline double perComponentTemperature(double T)
{
    return T/3.0;
}

//- Carnahan-Starling radial distribution at contact, g0 = (1 - phi/2)/(1 - phi)^3
inline double carnahanStarlingG0(double phi)
{
    const double oneMinus = 1.0 - phi;
    return (1.0 - 0.5*phi)/(oneMinus*oneMinus*oneMinus);
}

//- The Savage-Jeffrey parameter of a sheared cell, the seed's eq 7 solved for R:
//  R = dMean gammaDot sqrt(3/T) (the solver's savageJeffrey model inverts it)
inline double savageJeffreyR(double dMean, double gammaDot, double T)
{
    return dMean*gammaDot*std::sqrt(3.0/T);
}

//- The seed's eq 15 generalised: D = A (1 + x)^a T^m phi^b
inline double powerLaw(double A, double a, double m, double b, double phi, double x, double T)
{
    return A*std::pow(1.0 + x, a)*std::pow(T, m)*std::pow(phi, b);
}

//- The kinetic-theory shape d sqrt(T1)/(phi g0(phi))
inline double kineticShape(double phi, double T, double d)
{
    return d*std::sqrt(perComponentTemperature(T))/(phi*carnahanStarlingG0(phi));
}

//- Kinetic theory in dimensionless groups: D = C d sqrt(T1) (1 + alpha x)/(phi g0)
//  (Savage & Dai's elastic-sphere diffusivity is C = sqrt(pi)/(8 (1 + e)),
//  alpha = 0)
inline double kineticTheoryGroups(double C, double alpha, double phi, double x, double T, double d)
{
    return C*kineticShape(phi, T, d)*(1.0 + alpha*x);
}

//- The kinetic scale of the sieving laws, d^k sqrt(T1)
inline double sievingScale(double diameterPower, double T, double d)
{
    return std::pow(d, diameterPower)*std::sqrt(perComponentTemperature(T));
}

//- eta = E d^k sqrt(T1) phi^p (1 + beta x)
inline double sievingPowerLaw
(
    double E, double diameterPower, double p, double beta,
    double phi, double x, double T, double d
)
{
    return E*sievingScale(diameterPower, T, d)*std::pow(phi, p)*(1.0 + beta*x);
}

//- eta = E d^k sqrt(T1) phi^p x^q
inline double sievingCompositionPowerLaw
(
    double E, double diameterPower, double p, double q,
    double phi, double x, double T, double d
)
{
    return E*sievingScale(diameterPower, T, d)*std::pow(phi, p)*std::pow(x, q);
}

//- The kinetic collision rate sqrt(T1)/d [1/s]
inline double collisionScale(double T, double d)
{
    return std::sqrt(perComponentTemperature(T))/d;
}

//- Collisions per unit time of one particle (breakage rates, fit/BreakageRate.hpp):
//    omega = C (sqrt(T1)/d) phi g0(phi)^b (1 + alpha x)
//  Enskog for a monodisperse elastic gas is omega = 4 n d^2 g0 sqrt(pi T1) =
//  (24/sqrt(pi)) (sqrt(T1)/d) phi g0: C = 24/sqrt(pi) ~ 13.54, b = 1, alpha = 0.
//  b lets dense or inelastic cells depart from Carnahan-Starling's g0, alpha takes the
//  composition dependence of a species' partners.
inline double collisionFrequencyGroups
(
    double C, double b, double alpha, double phi, double x, double T, double d
)
{
    return C*collisionScale(T, d)*phi*std::pow(carnahanStarlingG0(phi), b)*(1.0 + alpha*x);
}

//- Mean mass-specific impact energy W = E/(m_i + m_j) of a particle's impacts [J/kg]
//  (fit/BreakageRate.hpp):  Wmean = K T1 phi^c.
//  An elastic gas at equilibrium (Maxwell-Boltzmann, dem.impact_energy) has
//  <E> = m T1 for equal grains, so Wmean = T1/2: K = 1/2, c = 0.
inline double impactEnergyGroups(double K, double c, double phi, double T)
{
    return K*perComponentTemperature(T)*std::pow(phi, c);
}

} // namespace sdf::fit::formulas

#endif

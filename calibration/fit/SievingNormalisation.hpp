// Conversion of the engine's kinetic sieving coefficient into the m2/s the
// solver's kinetic-sieving flux needs (docs/developer/calibration-fit.md, "eta units").
//
// The engine returns, per species i, the seed's eta_i (eqs 8-13): the
// Green-Kubo integral of the autocorrelation of the xy component of
// J^i/sqrt(V) (plus the composition share of J^12), in kg^2 m s^-3. Green-Kubo
// for a shear viscosity reads mu = V/(k T) int <sigma_xy sigma_xy> dt with
// sigma = J/V; the granular analogue of k T is the mean particle mass times the
// per-component granular temperature, m_mean T/3. Dividing by the bulk density
// rho_b = phi sum_s x_s rho_s gives a kinematic viscosity:
//
//     nu_i = eta_i / (rho_b m_mean T/3)   [m2/s]
//
// nu_i is species i's contribution to the mixture's kinematic viscosity; the
// seed identifies it with the kinetic sieving coefficient of eq 6. Header only,
// so the OpenFOAM side can use it without linking sdf_fit.
#ifndef sdf_fit_SievingNormalisation_hpp
#define sdf_fit_SievingNormalisation_hpp

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

//- One species of a binary mixture: diameter [m], material density [kg/m3].
struct SphereSpecies
{
    double diameter;
    double density;
};

//- Number-mean particle mass of a binary mixture with coarse solids-volume
//  fraction x: m_mean = sum_s x_s rho_s / sum_s (x_s / V_s).
inline double meanParticleMass
(
    double coarseFraction,
    const SphereSpecies& fine,
    const SphereSpecies& coarse
)
{
    const double pi = 3.14159265358979323846;
    const double vFine = pi*std::pow(fine.diameter, 3)/6;
    const double vCoarse = pi*std::pow(coarse.diameter, 3)/6;
    const double xf = 1 - coarseFraction, xc = coarseFraction;
    return (xf*fine.density + xc*coarse.density)/(xf/vFine + xc/vCoarse);
}

//- nu = eta_engine / (rho_b m_mean T/3) in m2/s; T is the sum of the three
//  components of the granular temperature (m2/s2). Also converts a standard
//  error (the factor is exact, so errors scale the same way).
inline double kinematicSievingCoefficient
(
    double etaEngine,
    double phi,
    double coarseFraction,
    double T,
    const SphereSpecies& fine,
    const SphereSpecies& coarse
)
{
    if
    (
        !(phi > 0) || !(T > 0) || !(coarseFraction >= 0 && coarseFraction <= 1)
     || !(fine.diameter > 0) || !(coarse.diameter > 0)
     || !(fine.density > 0) || !(coarse.density > 0)
    )
    {
        std::ostringstream msg;
        msg << "kinematicSievingCoefficient: needs phi > 0 (" << phi << "), T > 0 ("
            << T << "), x in [0, 1] (" << coarseFraction
            << ") and positive diameters and densities";
        throw std::invalid_argument(msg.str());
    }
    const double bulkDensity =
        phi*((1 - coarseFraction)*fine.density + coarseFraction*coarse.density);
    return etaEngine
        /(bulkDensity*meanParticleMass(coarseFraction, fine, coarse)*T/3);
}

} // namespace sdf::fit

#endif

// The table a constitutive law is fitted to: one row per DEM condition with
// the measured transport coefficient and its standard error.
//
// Conventions (docs/developer/equations.md): T is the granular temperature as the SUM
// of the three components' mean square fluctuation velocity [m2/s2]; laws
// from kinetic theory use T1 = T/3. x is the coarse fraction of the solids.
#ifndef sdf_fit_FitData_hpp
#define sdf_fit_FitData_hpp

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sdf::fit
{

//- One DEM condition.
struct Condition
{
    double phi = 0.0;   // total solids fraction, 0 < phi < 1
    double x = 0.0;     // coarse fraction of the solids, 0 <= x <= 1
    double T = 0.0;     // granular temperature (sum of 3 components) [m2/s2], > 0
    double d = 0.0;     // diameter of the species the value belongs to [m], > 0
    //- Shear rate [1/s] of a sheared (Lees-Edwards) run; absent for driven runs.
    //  No law here uses it yet; it is carried into the validity envelope.
    std::optional<double> gammaDot;
    //- Inertial number I = gammaDot d/sqrt(p/rho_s) of a rheology row (the mu(I) and
    //  phi(I) laws of RheologyLaws.hpp read it); absent otherwise.
    std::optional<double> inertialNumber;
    //- p* = p/(rho_s g dMean) and the size ratio R = d_coarse/d_fine of a segregation
    //  row (the laws of SegregationLaws.hpp read them, d being the fine diameter);
    //  absent otherwise.
    std::optional<double> pressureNumber;
    std::optional<double> sizeRatio;
};

//- A measured value (e.g. D_i [m2/s] or eta [m2/s]) at a condition, with its
//  standard error (weight 1/sigma^2).
struct Observation
{
    Condition condition;
    double value = 0.0;
    double sigma = 0.0;
};

struct Range
{
    double min = 0.0;
    double max = 0.0;
};

//- The box of conditions a law was fitted on: where it may be trusted.
struct Envelope
{
    Range phi, x, T, d;
    //- Only when every row carries a shear rate.
    std::optional<Range> gammaDot;
};

//- Throws std::invalid_argument naming `context` (e.g. the law) and the
//  offending row (0-based) and entry when: the table is empty; it has no more
//  rows than parameterCount (a fit needs at least one degree of freedom to be
//  judged); any number is not finite; phi <= 0 or phi >= 1; x outside [0, 1];
//  T <= 0; d <= 0; gammaDot < 0; inertialNumber <= 0; sigma <= 0; or, with positiveValues (fits in
//  log space), value <= 0.
void validateObservations
(
    const std::vector<Observation>& data,
    std::size_t parameterCount,
    bool positiveValues,
    const std::string& context
);

//- Ranges of the conditions (data must be non-empty).
Envelope envelopeOf(const std::vector<Observation>& data);

} // namespace sdf::fit

#endif

#ifndef sdf_dem_ContactLaw_hpp
#define sdf_dem_ContactLaw_hpp

// Contact laws for soft spheres: their settings and the coefficient tables of all species
// pairs (the laws themselves: ContactModels.hpp, one contact's evaluation: ContactForce.hpp).
//
//  - linear spring-dashpot (normal) + Coulomb-limited linear tangential spring with history;
//    the normal dashpot is derived from the restitution coefficient e so that an isolated
//    binary collision rebounds with exactly e (the dashpot is not clipped, contact ends at
//    zero overlap, as in the analytic solution);
//  - Hertz-Mindlin: F_n = (4/3) E* sqrt(R*) delta^{3/2}, Tsuji-type dashpot
//    alpha sqrt(m* K) delta^{1/4}, with alpha(e) found by solving the dimensionless
//    collision ODE (e does not depend on the impact velocity for this dashpot), the normal
//    force clipped at zero; Mindlin tangential stiffness 8 G* a with the tangential
//    *force* kept as history (incremental form, no spurious energy when a grows);
//  - either with rolling resistance (off by default): LAMMPS pair granular's `rolling sds`,
//    a spring-dashpot on the rolling displacement whose force is capped at mu_r |F_n|
//    (ContactForce.hpp), the established shape proxy of sheared spheres (Estrada, Azema,
//    Radjai & Taboada 2011, arXiv 1105.4418).

#include "Species.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace sdf::dem
{

enum class ContactModel { linearSpringDashpot, hertzMindlin };

ContactModel contactModelFromName(const std::string& name);
std::string contactModelName(ContactModel model);

//- The constants of one species pair that differ from the single values of
//  ContactSettings, as DEM users set them per material pair (LAMMPS pair_coeff per type
//  pair; the interaction tables of commercial DEM). An unset value takes the single one.
struct PairContactSettings
{
    std::string first, second;              // species names, in either order
    std::optional<double> restitution;      // e of the pair
    std::optional<double> friction;         // mu of the pair
    std::optional<double> normalStiffness;  // k_n [N/m] (linear law only)
    std::optional<double> rollingFriction;  // mu_r of the pair
};

//- "fine/coarse: e 0.7, mu 0.4, kn 3000" (the values set), for reports and keys.
std::string pairContactText(const PairContactSettings& pair);

struct ContactSettings
{
    ContactModel model = ContactModel::linearSpringDashpot;
    double restitution = 0.9;          // e in (0, 1]
    double friction = 0.5;             // Coulomb coefficient mu >= 0 (0: frictionless)

    // linear spring-dashpot
    double normalStiffness = 2.0e5;                // k_n [N/m]
    double tangentialStiffnessRatio = 2.0/7.0;     // k_t / k_n
    double tangentialDampingRatio = 0.5;           // gamma_t / gamma_n

    // Hertz-Mindlin (same material for all species and walls)
    double youngsModulus = 1.0e7;                  // E [Pa]
    double poissonRatio = 0.3;                     // nu

    // rolling resistance, LAMMPS `rolling sds k_r gamma_r mu_r` (0: off)
    double rollingFriction = 0.0;                  // mu_r >= 0: torque cap mu_r R* |F_n|
    double rollingStiffness = 0.0;                 // k_r [N/m]; 0: the pair's k_t (linear law)
    double rollingDamping = 0.0;                   // gamma_r [kg/s]; 0: the pair's gamma_t (linear law)

    //- Per species pair (walls keep the single values); at most one entry per pair.
    std::vector<PairContactSettings> pairs;
};

//- Throws std::invalid_argument naming the offending entry.
void validateContactSettings(const ContactSettings& settings);

//- Rolling resistance on anywhere: the single rollingFriction or a pair's is > 0.
bool hasRollingResistance(const ContactSettings& settings);

//- Dimensionless Tsuji damping factor alpha for Hertz contacts with restitution e
//  (x'' = -x^{3/2} - alpha x^{1/4} x', normal force clipped at zero).
double hertzDampingFactor(double restitution);

//- Restitution of the dimensionless Hertz-Tsuji collision for a given alpha.
double hertzRestitution(double alpha);

//- Pre-computed coefficients of one species pair (or species-wall when the partner is a wall).
struct PairCoefficients
{
    double effectiveMass = 0.0;        // m* = m_i m_j / (m_i + m_j)
    double effectiveRadius = 0.0;      // R* = R_i R_j / (R_i + R_j)
    // linear
    double kn = 0.0, kt = 0.0, gammaN = 0.0, gammaT = 0.0;
    // Hertz: F_n = hertzK delta^{3/2}; S_t = mindlinK sqrt(delta); dashpots
    //   gamma_n = hertzDamp delta^{1/4},  gamma_t = mindlinDamp delta^{1/4}
    double hertzK = 0.0, mindlinK = 0.0, hertzDamp = 0.0, mindlinDamp = 0.0;
    double friction = 0.0;
    double restitution = 1.0;          // the e the dashpots were made for
    // rolling resistance (rollingFriction 0: off)
    double rollingFriction = 0.0, rollingStiffness = 0.0, rollingDamping = 0.0;
};

//- Coefficient tables for all species pairs and species-wall contacts.
class ContactLaw
{
public:
    ContactLaw(const ContactSettings& settings, const std::vector<Species>& species);

    const ContactSettings& settings() const { return settings_; }
    ContactModel model() const { return settings_.model; }
    int numberOfSpecies() const { return nSpecies_; }

    const PairCoefficients& pair(int a, int b) const
    {
        return pairs_[a*nSpecies_ + b];
    }
    const PairCoefficients& wall(int a) const { return walls_[a]; }

    //- Duration of a binary collision of the lightest pair at impact speed vImpact
    //  (linear: independent of speed).
    double contactDuration(double vImpact) const;

    //- Largest admissible time step: t_c/50 (linear) or 0.2 Rayleigh time (Hertz).
    double maximumTimeStep() const;

    //- The step a run takes at timeStep 0: half the largest admissible.
    double defaultTimeStep() const { return 0.5*maximumTimeStep(); }

    //- How maximumTimeStep() and the default step, half of it, follow from the law,
    //  for what a run prints: "t_c/50" and "t_c/100" (linear), "0.2 Rayleigh times"
    //  and "0.1 Rayleigh times" (Hertz). Kept here so that they change with it.
    std::string maximumTimeStepRule() const;
    std::string defaultTimeStepRule() const;

    //- Elastic energy stored in a contact with overlap delta (for NVE checks).
    double normalElasticEnergy(const PairCoefficients& c, double delta) const;

    //- Tangential stiffness at overlap delta > 0 (elastic energy of the tangential spring).
    double tangentialStiffness(const PairCoefficients& c, double delta) const;

    //- The stiffest pair's normal stiffness dF_n/d delta [N/m] at the contact force
    //  `force` (linear: k_n; Hertz: 1.5 K^{2/3} F^{1/3}); what a packing's compressibility
    //  scales with (Barostat's automatic relaxation time)
    double normalStiffnessAtForce(double force) const;

private:
    //- The constants of one contact: the single ones, or a pair's values where set.
    struct PairConstants
    {
        double restitution, friction, normalStiffness, rollingFriction;
    };
    PairConstants constantsOf(int a, int b) const;

    PairCoefficients makeCoefficients
    (
        double mi, double ri, double mj, double rj, bool wall, const PairConstants& constants
    ) const;

    ContactSettings settings_;
    int nSpecies_;
    std::vector<Species> species_;
    std::vector<PairCoefficients> pairs_;
    std::vector<PairCoefficients> walls_;
};

} // namespace sdf::dem

#endif

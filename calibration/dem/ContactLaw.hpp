#ifndef sdf_dem_ContactLaw_hpp
#define sdf_dem_ContactLaw_hpp

// Contact laws for soft spheres:
//  - linear spring-dashpot (normal) + Coulomb-limited linear tangential spring with history;
//    the normal dashpot is derived from the restitution coefficient e so that an isolated
//    binary collision rebounds with exactly e (the dashpot is not clipped, contact ends at
//    zero overlap, as in the analytic solution);
//  - Hertz-Mindlin: F_n = (4/3) E* sqrt(R*) delta^{3/2}, Tsuji-type dashpot
//    alpha sqrt(m* K) delta^{1/4}, with alpha(e) found by solving the dimensionless
//    collision ODE (e does not depend on the impact velocity for this dashpot), the normal
//    force clipped at zero; Mindlin tangential stiffness 8 G* a with the tangential
//    *force* kept as history (incremental form, no spurious energy when a grows).
//
// The tangential history is advanced with the half-step relative velocity projected on the
// half-step contact plane and then rotated onto the full-step plane (the synchronised
// velocity-Verlet remedy of Vyas et al. 2025, Comput. Phys. Commun. 310:109524); damping
// forces use the synchronised full-step velocity estimate v^{n+1/2} + dt/2 a^n.

#include "Species.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace sdf::dem
{

enum class ContactModel { linearSpringDashpot, hertzMindlin };

ContactModel contactModelFromName(const std::string& name);
std::string contactModelName(ContactModel model);

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
};

//- Throws std::invalid_argument naming the offending entry.
void validateContactSettings(const ContactSettings& settings);

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

    //- Elastic energy stored in a contact with overlap delta (for NVE checks).
    double normalElasticEnergy(const PairCoefficients& c, double delta) const
    {
        if (delta <= 0) return 0;
        if (settings_.model == ContactModel::linearSpringDashpot) return 0.5*c.kn*delta*delta;
        return 0.4*c.hertzK*delta*delta*std::sqrt(delta);
    }

private:
    PairCoefficients makeCoefficients(double mi, double ri, double mj, double rj, bool wall) const;

    ContactSettings settings_;
    int nSpecies_;
    std::vector<Species> species_;
    std::vector<PairCoefficients> pairs_;
    std::vector<PairCoefficients> walls_;
    double hertzAlpha_ = 0.0;
};

//- State carried by one contact between steps.
struct ContactHistory
{
    double ft[3] = {0, 0, 0};      // elastic tangential force on particle i (lab frame)
    double n[3] = {0, 0, 0};       // contact normal at the last evaluation (j -> i)
    bool touching = false;
};

//- Kinematics of one contact at the force evaluation of step n+1.
struct ContactKinematics
{
    double r[3];            // x_i - x_j (minimum image), full step
    double radiusI, radiusJ; // radii used as branch lengths (radiusJ = 0 for a wall)
    double dvHalf[3];       // v_i - v_j, half-step velocities (incl. Lees-Edwards shift)
    double dvSync[3];       // v_i - v_j, synchronised full-step estimates
    double wHalfI[3], wHalfJ[3];
    double wSyncI[3], wSyncJ[3];
};

struct ContactResult
{
    double force[3] = {0, 0, 0};     // force on i
    double nCrossFt[3] = {0, 0, 0};  // n x F_t: torque on i = -R_i nCrossFt, on j = -R_j nCrossFt
    double overlap = 0;              // delta (<= 0: no contact)
    double normalVelocity = 0;       // v_n (sync), negative when approaching
    bool newContact = false;
};

namespace detail
{
inline double dot3(const double* a, const double* b) { return a[0]*b[0] + a[1]*b[1] + a[2]*b[2]; }
inline void cross3(const double* a, const double* b, double* c)
{
    c[0] = a[1]*b[2] - a[2]*b[1];
    c[1] = a[2]*b[0] - a[0]*b[2];
    c[2] = a[0]*b[1] - a[1]*b[0];
}
// Removes the component of v along unit n and restores the magnitude of v.
inline void rotateOntoPlane(double* v, const double* n)
{
    const double mag2 = dot3(v, v);
    if (mag2 == 0) return;
    const double vn = dot3(v, n);
    double p[3] = {v[0] - vn*n[0], v[1] - vn*n[1], v[2] - vn*n[2]};
    const double p2 = dot3(p, p);
    if (p2 <= 0) { v[0] = v[1] = v[2] = 0; return; }
    const double s = std::sqrt(mag2/p2);
    v[0] = p[0]*s; v[1] = p[1]*s; v[2] = p[2]*s;
}
// Relative velocity of the contact points, v_i - v_j - (R_i w_i + R_j w_j) x n.
inline void contactVelocity(const double* dv, const double* wi, const double* wj,
                            double ri, double rj, const double* n, double* out)
{
    const double w[3] = {ri*wi[0] + rj*wj[0], ri*wi[1] + rj*wj[1], ri*wi[2] + rj*wj[2]};
    double wxn[3];
    cross3(w, n, wxn);
    out[0] = dv[0] - wxn[0]; out[1] = dv[1] - wxn[1]; out[2] = dv[2] - wxn[2];
}
} // namespace detail

#if defined(__GNUC__)
#define SDF_DEM_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SDF_DEM_ALWAYS_INLINE inline
#endif

//- Evaluates one contact; updates the history. Always inlined: this is the hot loop.
SDF_DEM_ALWAYS_INLINE ContactResult evaluateContact
(
    ContactModel model,
    const PairCoefficients& c,
    const ContactKinematics& k,
    ContactHistory& h,
    double dt
)
{
    using namespace detail;
    ContactResult out;
    const double dist2 = dot3(k.r, k.r);
    const double contactDist = k.radiusI + k.radiusJ;
    if (dist2 >= contactDist*contactDist || dist2 == 0)
    {
        h.touching = false;
        h.ft[0] = h.ft[1] = h.ft[2] = 0;
        out.overlap = contactDist - std::sqrt(dist2);
        return out;
    }
    const double dist = std::sqrt(dist2);
    const double delta = contactDist - dist;
    const double n[3] = {k.r[0]/dist, k.r[1]/dist, k.r[2]/dist};

    out.newContact = !h.touching;
    if (out.newContact)
    {
        h.ft[0] = h.ft[1] = h.ft[2] = 0;
        h.n[0] = n[0]; h.n[1] = n[1]; h.n[2] = n[2];
    }

    // Normal and tangential stiffness/damping at this overlap
    double fnElastic, gn, kt, gt;
    if (model == ContactModel::linearSpringDashpot)
    {
        fnElastic = c.kn*delta;
        gn = c.gammaN;
        kt = c.kt;
        gt = c.gammaT;
    }
    else
    {
        const double sd = std::sqrt(delta);
        const double qd = std::sqrt(sd);
        fnElastic = c.hertzK*delta*sd;
        gn = c.hertzDamp*qd;
        kt = c.mindlinK*sd;
        gt = c.mindlinDamp*qd;
    }

    // 1. tangential history on the half-step plane with the half-step velocity
    double nh[3] = {h.n[0] + n[0], h.n[1] + n[1], h.n[2] + n[2]};
    {
        const double l = std::sqrt(dot3(nh, nh));
        if (l > 1e-12) { nh[0] /= l; nh[1] /= l; nh[2] /= l; }
        else { nh[0] = n[0]; nh[1] = n[1]; nh[2] = n[2]; }
    }
    if (c.friction > 0)
    {
        rotateOntoPlane(h.ft, nh);
        double vh[3];
        contactVelocity(k.dvHalf, k.wHalfI, k.wHalfJ, k.radiusI, k.radiusJ, nh, vh);
        const double vhn = dot3(vh, nh);
        const double vth[3] = {vh[0] - vhn*nh[0], vh[1] - vhn*nh[1], vh[2] - vhn*nh[2]};
        h.ft[0] -= kt*vth[0]*dt;
        h.ft[1] -= kt*vth[1]*dt;
        h.ft[2] -= kt*vth[2]*dt;
        // 2. onto the full-step plane
        rotateOntoPlane(h.ft, n);
    }
    h.n[0] = n[0]; h.n[1] = n[1]; h.n[2] = n[2];
    h.touching = true;

    // 3. forces with the synchronised velocity
    double vs[3];
    contactVelocity(k.dvSync, k.wSyncI, k.wSyncJ, k.radiusI, k.radiusJ, n, vs);
    const double vn = dot3(vs, n);
    double fn = fnElastic - gn*vn;
    if (model == ContactModel::hertzMindlin && fn < 0) fn = 0;

    double ftot[3] = {0, 0, 0};
    if (c.friction > 0)
    {
        const double vt[3] = {vs[0] - vn*n[0], vs[1] - vn*n[1], vs[2] - vn*n[2]};
        ftot[0] = h.ft[0] - gt*vt[0];
        ftot[1] = h.ft[1] - gt*vt[1];
        ftot[2] = h.ft[2] - gt*vt[2];
        // Coulomb limit on the magnitude of the total normal force, as LAMMPS' pair
        // granular: the linear dashpot makes it tensile at the end of a contact, where
        // mu max(fn, 0) (no friction) gave a 4-8 % lower D_yy of a sheared cell than
        // LAMMPS (docs/dem.md, "Contact laws"); Hertz-Mindlin's fn is clamped at 0
        const double limit = c.friction*std::abs(fn);
        const double mag2 = dot3(ftot, ftot);
        if (mag2 > limit*limit)
        {
            // sliding: cap the total tangential force, keep the elastic part consistent
            const double s = mag2 > 0 ? limit/std::sqrt(mag2) : 0.0;
            ftot[0] *= s; ftot[1] *= s; ftot[2] *= s;
            h.ft[0] = ftot[0] + gt*vt[0];
            h.ft[1] = ftot[1] + gt*vt[1];
            h.ft[2] = ftot[2] + gt*vt[2];
        }
    }

    out.force[0] = fn*n[0] + ftot[0];
    out.force[1] = fn*n[1] + ftot[1];
    out.force[2] = fn*n[2] + ftot[2];
    cross3(n, ftot, out.nCrossFt);
    out.overlap = delta;
    out.normalVelocity = vn;
    return out;
}

} // namespace sdf::dem

#endif

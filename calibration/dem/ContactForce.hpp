#ifndef sdf_dem_ContactForce_hpp
#define sdf_dem_ContactForce_hpp

// One contact's force and torque from its kinematics and history, written once for all
// contact laws (the law-specific parts come from a policy, ContactModels.hpp).
//
// The tangential history is advanced with the half-step relative velocity projected on the
// half-step contact plane and then rotated onto the full-step plane (the synchronised
// velocity-Verlet remedy of Vyas et al. 2025, Comput. Phys. Commun. 310:109524); damping
// forces use the synchronised full-step velocity estimate v^{n+1/2} + dt/2 a^n.

#include "ContactModels.hpp"

#include <cmath>

namespace sdf::dem
{

//- State carried by one contact between steps.
struct ContactHistory
{
    double ft[3] = {0, 0, 0};      // elastic tangential force on particle i (lab frame)
    double n[3] = {0, 0, 0};       // contact normal at the last evaluation (j -> i)
    double xr[3] = {0, 0, 0};      // rolling displacement (rolling resistance; lab frame)
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
    //- What i's and j's torque sums take (the torque is -R times the sum): n x F_t, and
    //  with rolling resistance -/+ R* (n x F_r)/R_i,j (rolling torque R* n x F_r on i,
    //  the opposite on j); equal to nCrossFt without it
    double torqueSumI[3] = {0, 0, 0};
    double torqueSumJ[3] = {0, 0, 0};
    double rollingTorque[3] = {0, 0, 0};   // R* n x F_r: rolling torque on i (walls)
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

//- Evaluates one contact with the contact law Law (ContactModels.hpp); updates the history.
//  Always inlined: this is the hot loop.
template<class Law>
SDF_DEM_ALWAYS_INLINE ContactResult evaluateContact
(
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
        h.xr[0] = h.xr[1] = h.xr[2] = 0;
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
        h.xr[0] = h.xr[1] = h.xr[2] = 0;
        h.n[0] = n[0]; h.n[1] = n[1]; h.n[2] = n[2];
    }

    // Normal and tangential stiffness/damping at this overlap
    const ContactStiffness stiffness = Law::at(c, delta);
    const double fnElastic = stiffness.normalElasticForce;
    const double gn = stiffness.normalDamping;
    const double kt = stiffness.tangentialStiffness;
    const double gt = stiffness.tangentialDamping;

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
    const double fn = Law::limitNormalForce(fnElastic - gn*vn);

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
        // LAMMPS (docs/developer/dem-engine.md, "Contact laws"); Hertz-Mindlin's fn is clamped at 0
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
    for (int d = 0; d < 3; ++d) out.torqueSumI[d] = out.torqueSumJ[d] = out.nCrossFt[d];

    // 4. rolling resistance (LAMMPS `rolling sds`): rolling velocity
    //    v_r = R* (w_i - w_j) x n (Wang et al. 2015, eq. 31, as LAMMPS), its displacement
    //    advanced on the half-step plane with the half-step spins and rotated onto the
    //    full-step plane as the tangential history; F_r = -k_r xi_r - gamma_r v_r (synchronised
    //    spins), capped at mu_r |F_n| (on slip the spring is reset to the cap, as LAMMPS);
    //    torque R* n x F_r on i, the opposite on j (no force)
    if (c.rollingFriction > 0)
    {
        const double rs = c.effectiveRadius;
        const double dwh[3] = {k.wHalfI[0] - k.wHalfJ[0], k.wHalfI[1] - k.wHalfJ[1], k.wHalfI[2] - k.wHalfJ[2]};
        double vrh[3];
        cross3(dwh, nh, vrh);
        rotateOntoPlane(h.xr, nh);
        h.xr[0] += rs*vrh[0]*dt;
        h.xr[1] += rs*vrh[1]*dt;
        h.xr[2] += rs*vrh[2]*dt;
        rotateOntoPlane(h.xr, n);
        const double dws[3] = {k.wSyncI[0] - k.wSyncJ[0], k.wSyncI[1] - k.wSyncJ[1], k.wSyncI[2] - k.wSyncJ[2]};
        double vr[3];
        cross3(dws, n, vr);
        vr[0] *= rs; vr[1] *= rs; vr[2] *= rs;
        const double kr = c.rollingStiffness, gr = c.rollingDamping;
        double fr[3] = {-kr*h.xr[0] - gr*vr[0], -kr*h.xr[1] - gr*vr[1], -kr*h.xr[2] - gr*vr[2]};
        const double limit = c.rollingFriction*std::abs(fn);
        const double mag2 = dot3(fr, fr);
        if (mag2 > limit*limit)
        {
            const double s = mag2 > 0 ? limit/std::sqrt(mag2) : 0.0;
            fr[0] *= s; fr[1] *= s; fr[2] *= s;
            h.xr[0] = -(fr[0] + gr*vr[0])/kr;
            h.xr[1] = -(fr[1] + gr*vr[1])/kr;
            h.xr[2] = -(fr[2] + gr*vr[2])/kr;
        }
        double nxfr[3];
        cross3(n, fr, nxfr);
        // torque on i = -R_i torqueSumI: rolling torque R* n x F_r enters as -R* nxfr/R_i
        const double si = k.radiusI > 0 ? rs/k.radiusI : 0.0;
        const double sj = k.radiusJ > 0 ? rs/k.radiusJ : 0.0;
        for (int d = 0; d < 3; ++d)
        {
            out.rollingTorque[d] = rs*nxfr[d];
            out.torqueSumI[d] -= si*nxfr[d];
            out.torqueSumJ[d] += sj*nxfr[d];
        }
    }
    out.overlap = delta;
    out.normalVelocity = vn;
    return out;
}

//- The same with the law picked at run time (single contacts, tests; not for pair loops).
inline ContactResult evaluateContact
(
    ContactModel model,
    const PairCoefficients& c,
    const ContactKinematics& k,
    ContactHistory& h,
    double dt
)
{
    return withContactModel
    (
        model,
        [&](auto law) { return evaluateContact<decltype(law)>(c, k, h, dt); }
    );
}

} // namespace sdf::dem

#endif

// The batched contact loop (ContactBatch.hpp). Every line below has its twin in
// evaluateContact (ContactForce.hpp), in the same order of operations: a branch there is
// a selection here, both sides computed (a lane's discarded side may divide by zero; no
// trap is enabled). Kept bitwise equal by test_contactBatch (every branch, both laws)
// and by the engine's reproducibility tests.

#include "ContactBatch.hpp"
#include "ContactModels.hpp"
#include "VectorClones.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

void ContactBatch::reserveFor(int n)
{
    if (n <= capacity_) return;
    particleI.resize(std::size_t(n));
    particleJ.resize(std::size_t(n));
    for (auto* a :
         {&rx, &ry, &rz, &shiftVx, &radiusI, &radiusJ,
          &dvHalfX, &dvHalfY, &dvHalfZ, &dvSyncX, &dvSyncY, &dvSyncZ,
          &wHalfIX, &wHalfIY, &wHalfIZ, &wHalfJX, &wHalfJY, &wHalfJZ,
          &wSyncIX, &wSyncIY, &wSyncIZ, &wSyncJX, &wSyncJY, &wSyncJZ,
          &constant0, &constant1, &constant2, &constant3, &friction, &touching,
          &ftX, &ftY, &ftZ, &nX, &nY, &nZ,
          &forceX, &forceY, &forceZ, &nCrossFtX, &nCrossFtY, &nCrossFtZ,
          &overlap, &overlapFraction, &normalVelocity})
    {
        a->resize(std::size_t(n));
    }
    capacity_ = n;
}

namespace
{

// detail::rotateOntoPlane with selections: v's component along unit n removed and |v|
// restored; v unchanged when it is zero, zero when it lies along n
inline void rotateOntoPlane(double& x, double& y, double& z, double nx, double ny, double nz)
{
    const double mag2 = x*x + y*y + z*z;
    const double vn = x*nx + y*ny + z*nz;
    const double px = x - vn*nx, py = y - vn*ny, pz = z - vn*nz;
    const double p2 = px*px + py*py + pz*pz;
    const double s = std::sqrt(mag2/p2);
    const bool alongN = p2 <= 0;
    const double rx = alongN ? 0.0 : px*s, ry = alongN ? 0.0 : py*s, rz = alongN ? 0.0 : pz*s;
    const bool zero = mag2 == 0;
    x = zero ? x : rx; y = zero ? y : ry; z = zero ? z : rz;
}

template<class Law>
inline __attribute__((always_inline)) void evaluate(ContactBatch& b, int n, double dt)
{
    const double* __restrict rxs = b.rx.data();
    const double* __restrict rys = b.ry.data();
    const double* __restrict rzs = b.rz.data();
    const double* __restrict ris = b.radiusI.data();
    const double* __restrict rjs = b.radiusJ.data();
    const double* __restrict dvhx = b.dvHalfX.data();
    const double* __restrict dvhy = b.dvHalfY.data();
    const double* __restrict dvhz = b.dvHalfZ.data();
    const double* __restrict dvsx = b.dvSyncX.data();
    const double* __restrict dvsy = b.dvSyncY.data();
    const double* __restrict dvsz = b.dvSyncZ.data();
    const double* __restrict whix = b.wHalfIX.data();
    const double* __restrict whiy = b.wHalfIY.data();
    const double* __restrict whiz = b.wHalfIZ.data();
    const double* __restrict whjx = b.wHalfJX.data();
    const double* __restrict whjy = b.wHalfJY.data();
    const double* __restrict whjz = b.wHalfJZ.data();
    const double* __restrict wsix = b.wSyncIX.data();
    const double* __restrict wsiy = b.wSyncIY.data();
    const double* __restrict wsiz = b.wSyncIZ.data();
    const double* __restrict wsjx = b.wSyncJX.data();
    const double* __restrict wsjy = b.wSyncJY.data();
    const double* __restrict wsjz = b.wSyncJZ.data();
    const double* __restrict k0 = b.constant0.data();
    const double* __restrict k1 = b.constant1.data();
    const double* __restrict k2 = b.constant2.data();
    const double* __restrict k3 = b.constant3.data();
    const double* __restrict mus = b.friction.data();
    const double* __restrict touching = b.touching.data();
    double* __restrict ftx = b.ftX.data();
    double* __restrict fty = b.ftY.data();
    double* __restrict ftz = b.ftZ.data();
    double* __restrict hnx = b.nX.data();
    double* __restrict hny = b.nY.data();
    double* __restrict hnz = b.nZ.data();
    double* __restrict fx = b.forceX.data();
    double* __restrict fy = b.forceY.data();
    double* __restrict fz = b.forceZ.data();
    double* __restrict cx = b.nCrossFtX.data();
    double* __restrict cy = b.nCrossFtY.data();
    double* __restrict cz = b.nCrossFtZ.data();
    double* __restrict overlaps = b.overlap.data();
    double* __restrict overlapFractions = b.overlapFraction.data();
    double* __restrict normalVelocities = b.normalVelocity.data();

    // the arrays are distinct (restrict does not reach GCC's dependence analysis here)
    #pragma GCC ivdep
    for (int c = 0; c < n; ++c)
    {
        const double r0 = rxs[c], r1 = rys[c], r2 = rzs[c];
        const double ri = ris[c], rj = rjs[c];
        const double dist2 = r0*r0 + r1*r1 + r2*r2;
        const double contactDist = ri + rj;
        const double dist = std::sqrt(dist2);
        const double delta = contactDist - dist;
        const double n0 = r0/dist, n1 = r1/dist, n2 = r2/dist;

        // a new contact starts from no tangential force and its own normal
        const bool old = touching[c] != 0;
        double ft0 = old ? ftx[c] : 0.0, ft1 = old ? fty[c] : 0.0, ft2 = old ? ftz[c] : 0.0;
        const double hn0 = old ? hnx[c] : n0, hn1 = old ? hny[c] : n1, hn2 = old ? hnz[c] : n2;

        const ContactStiffness stiffness = Law::at(std::array<double, 4>{k0[c], k1[c], k2[c], k3[c]}, delta);
        const double fnElastic = stiffness.normalElasticForce;
        const double gn = stiffness.normalDamping;
        const double kt = stiffness.tangentialStiffness;
        const double gt = stiffness.tangentialDamping;
        const double mu = mus[c];
        const bool frictional = mu > 0;

        // 1. the half-step plane
        double nh0 = hn0 + n0, nh1 = hn1 + n1, nh2 = hn2 + n2;
        {
            const double l = std::sqrt(nh0*nh0 + nh1*nh1 + nh2*nh2);
            const double q0 = nh0/l, q1 = nh1/l, q2 = nh2/l;
            const bool longer = l > 1e-12;
            nh0 = longer ? q0 : n0; nh1 = longer ? q1 : n1; nh2 = longer ? q2 : n2;
        }
        double u0 = ft0, u1 = ft1, u2 = ft2;
        rotateOntoPlane(u0, u1, u2, nh0, nh1, nh2);
        {
            const double w0 = ri*whix[c] + rj*whjx[c];
            const double w1 = ri*whiy[c] + rj*whjy[c];
            const double w2 = ri*whiz[c] + rj*whjz[c];
            const double vh0 = dvhx[c] - (w1*nh2 - w2*nh1);
            const double vh1 = dvhy[c] - (w2*nh0 - w0*nh2);
            const double vh2 = dvhz[c] - (w0*nh1 - w1*nh0);
            const double vhn = vh0*nh0 + vh1*nh1 + vh2*nh2;
            const double vth0 = vh0 - vhn*nh0, vth1 = vh1 - vhn*nh1, vth2 = vh2 - vhn*nh2;
            u0 -= kt*vth0*dt;
            u1 -= kt*vth1*dt;
            u2 -= kt*vth2*dt;
        }
        // 2. onto the full-step plane
        rotateOntoPlane(u0, u1, u2, n0, n1, n2);
        ft0 = frictional ? u0 : ft0; ft1 = frictional ? u1 : ft1; ft2 = frictional ? u2 : ft2;

        // 3. forces with the synchronised velocity
        const double w0 = ri*wsix[c] + rj*wsjx[c];
        const double w1 = ri*wsiy[c] + rj*wsjy[c];
        const double w2 = ri*wsiz[c] + rj*wsjz[c];
        const double vs0 = dvsx[c] - (w1*n2 - w2*n1);
        const double vs1 = dvsy[c] - (w2*n0 - w0*n2);
        const double vs2 = dvsz[c] - (w0*n1 - w1*n0);
        const double vn = vs0*n0 + vs1*n1 + vs2*n2;
        const double fn = Law::limitNormalForce(fnElastic - gn*vn);

        const double vt0 = vs0 - vn*n0, vt1 = vs1 - vn*n1, vt2 = vs2 - vn*n2;
        double ftot0 = frictional ? ft0 - gt*vt0 : 0.0;
        double ftot1 = frictional ? ft1 - gt*vt1 : 0.0;
        double ftot2 = frictional ? ft2 - gt*vt2 : 0.0;
        // the Coulomb limit on |F_n| (no friction: ftot and the limit are zero, no slip)
        const double limit = mu*std::abs(fn);
        const double mag2 = ftot0*ftot0 + ftot1*ftot1 + ftot2*ftot2;
        const bool sliding = mag2 > limit*limit;
        const double s = limit/std::sqrt(mag2);
        ftot0 = sliding ? ftot0*s : ftot0;
        ftot1 = sliding ? ftot1*s : ftot1;
        ftot2 = sliding ? ftot2*s : ftot2;
        ft0 = sliding ? ftot0 + gt*vt0 : ft0;
        ft1 = sliding ? ftot1 + gt*vt1 : ft1;
        ft2 = sliding ? ftot2 + gt*vt2 : ft2;

        fx[c] = fn*n0 + ftot0;
        fy[c] = fn*n1 + ftot1;
        fz[c] = fn*n2 + ftot2;
        cx[c] = n1*ftot2 - n2*ftot1;
        cy[c] = n2*ftot0 - n0*ftot2;
        cz[c] = n0*ftot1 - n1*ftot0;
        ftx[c] = ft0; fty[c] = ft1; ftz[c] = ft2;
        hnx[c] = n0; hny[c] = n1; hnz[c] = n2;
        overlaps[c] = delta;
        overlapFractions[c] = delta/(2*std::min(ri, rj));
        normalVelocities[c] = vn;
    }
}

} // namespace

SDF_DEM_VECTOR_CLONES
static void evaluateLinear(ContactBatch& b, int n, double dt)
{
    evaluate<LinearSpringDashpot>(b, n, dt);
}

SDF_DEM_VECTOR_CLONES
static void evaluateHertz(ContactBatch& b, int n, double dt)
{
    evaluate<HertzMindlin>(b, n, dt);
}

void evaluateContactBatch(ContactModel model, ContactBatch& batch, int n, double dt)
{
    switch (model)
    {
        case ContactModel::linearSpringDashpot: evaluateLinear(batch, n, dt); return;
        case ContactModel::hertzMindlin: evaluateHertz(batch, n, dt); return;
        default: break;
    }
    throw std::logic_error
    (
        "evaluateContactBatch: contact model " + contactModelName(model)
      + " has no batched loop (hasBatchedLoop)"
    );
}

} // namespace sdf::dem

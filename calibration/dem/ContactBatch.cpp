// The batched contact loop (ContactBatch.hpp). Every line below has its twin in
// evaluateContact (ContactForce.hpp), in the same order of operations: a branch there is
// a selection here between values computed before it. A lane's discarded side may divide
// zero by zero (a new contact's spring, a frictionless pair's Coulomb limit): the loop
// runs with floating-point traps held off and the flags it raised dropped
// (evaluateContactBatch), since OpenFOAM runs with traps on (FOAM_SIGFPE) and OpenMP's
// worker threads keep them. Kept bitwise equal by dem.contact_batch (every branch, both
// laws, with and without rolling resistance) and by the engine's reproducibility tests.

#include "ContactBatch.hpp"
#include "ContactModels.hpp"
#include "VectorClones.hpp"

#include <algorithm>
#include <array>
#include <cfenv>
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
          &rollingFriction, &rollingStiffness, &rollingDamping, &effectiveRadius,
          &xrX, &xrY, &xrZ,
          &torqueSumIX, &torqueSumIY, &torqueSumIZ, &torqueSumJX, &torqueSumJY, &torqueSumJZ,
          &forceX, &forceY, &forceZ, &nCrossFtX, &nCrossFtY, &nCrossFtZ,
          &overlapFraction, &normalVelocity})
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
    const bool alongN = p2 <= 0;
    const double s = std::sqrt(mag2/p2);
    const double psx = px*s, psy = py*s, psz = pz*s;
    const double rx = alongN ? 0.0 : psx, ry = alongN ? 0.0 : psy, rz = alongN ? 0.0 : psz;
    const bool zero = mag2 == 0;
    x = zero ? x : rx; y = zero ? y : ry; z = zero ? z : rz;
}

template<class Law, bool Rolling>
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
    const double* __restrict muRs = b.rollingFriction.data();
    const double* __restrict krs = b.rollingStiffness.data();
    const double* __restrict grs = b.rollingDamping.data();
    const double* __restrict rss = b.effectiveRadius.data();
    double* __restrict xrx = b.xrX.data();
    double* __restrict xry = b.xrY.data();
    double* __restrict xrz = b.xrZ.data();
    double* __restrict tix = b.torqueSumIX.data();
    double* __restrict tiy = b.torqueSumIY.data();
    double* __restrict tiz = b.torqueSumIZ.data();
    double* __restrict tjx = b.torqueSumJX.data();
    double* __restrict tjy = b.torqueSumJY.data();
    double* __restrict tjz = b.torqueSumJZ.data();
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
        const double ftIn0 = ftx[c], ftIn1 = fty[c], ftIn2 = ftz[c];
        const double hnIn0 = hnx[c], hnIn1 = hny[c], hnIn2 = hnz[c];
        double ft0 = old ? ftIn0 : 0.0, ft1 = old ? ftIn1 : 0.0, ft2 = old ? ftIn2 : 0.0;
        const double hn0 = old ? hnIn0 : n0, hn1 = old ? hnIn1 : n1, hn2 = old ? hnIn2 : n2;

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
            const bool longer = l > 1e-12;
            const double q0 = nh0/l, q1 = nh1/l, q2 = nh2/l;
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
        const double ftd0 = ft0 - gt*vt0, ftd1 = ft1 - gt*vt1, ftd2 = ft2 - gt*vt2;
        double ftot0 = frictional ? ftd0 : 0.0;
        double ftot1 = frictional ? ftd1 : 0.0;
        double ftot2 = frictional ? ftd2 : 0.0;
        // the Coulomb limit on |F_n| (no friction: ftot and the limit are zero, no slip)
        const double limit = mu*std::abs(fn);
        const double mag2 = ftot0*ftot0 + ftot1*ftot1 + ftot2*ftot2;
        const bool sliding = mag2 > limit*limit;
        const double s = limit/std::sqrt(mag2);
        const double ftCapped0 = ftot0*s, ftCapped1 = ftot1*s, ftCapped2 = ftot2*s;
        ftot0 = sliding ? ftCapped0 : ftot0;
        ftot1 = sliding ? ftCapped1 : ftot1;
        ftot2 = sliding ? ftCapped2 : ftot2;
        const double ftSpring0 = ftot0 + gt*vt0, ftSpring1 = ftot1 + gt*vt1, ftSpring2 = ftot2 + gt*vt2;
        ft0 = sliding ? ftSpring0 : ft0;
        ft1 = sliding ? ftSpring1 : ft1;
        ft2 = sliding ? ftSpring2 : ft2;

        fx[c] = fn*n0 + ftot0;
        fy[c] = fn*n1 + ftot1;
        fz[c] = fn*n2 + ftot2;
        const double nxft0 = n1*ftot2 - n2*ftot1;
        const double nxft1 = n2*ftot0 - n0*ftot2;
        const double nxft2 = n0*ftot1 - n1*ftot0;
        cx[c] = nxft0; cy[c] = nxft1; cz[c] = nxft2;

        // 4. rolling resistance (evaluateContact's step 4)
        if constexpr (Rolling)
        {
            const double rs = rss[c];
            const double xrIn0 = xrx[c], xrIn1 = xry[c], xrIn2 = xrz[c];
            const double x0 = old ? xrIn0 : 0.0, x1 = old ? xrIn1 : 0.0, x2 = old ? xrIn2 : 0.0;
            double u0 = x0, u1 = x1, u2 = x2;
            const double dwh0 = whix[c] - whjx[c], dwh1 = whiy[c] - whjy[c], dwh2 = whiz[c] - whjz[c];
            const double vrh0 = dwh1*nh2 - dwh2*nh1;
            const double vrh1 = dwh2*nh0 - dwh0*nh2;
            const double vrh2 = dwh0*nh1 - dwh1*nh0;
            rotateOntoPlane(u0, u1, u2, nh0, nh1, nh2);
            u0 += rs*vrh0*dt;
            u1 += rs*vrh1*dt;
            u2 += rs*vrh2*dt;
            rotateOntoPlane(u0, u1, u2, n0, n1, n2);
            const double dws0 = wsix[c] - wsjx[c], dws1 = wsiy[c] - wsjy[c], dws2 = wsiz[c] - wsjz[c];
            double vr0 = dws1*n2 - dws2*n1;
            double vr1 = dws2*n0 - dws0*n2;
            double vr2 = dws0*n1 - dws1*n0;
            vr0 *= rs; vr1 *= rs; vr2 *= rs;
            const double kr = krs[c], gr = grs[c];
            double fr0 = -kr*u0 - gr*vr0, fr1 = -kr*u1 - gr*vr1, fr2 = -kr*u2 - gr*vr2;
            const double rollingLimit = muRs[c]*std::abs(fn);
            const double frMag2 = fr0*fr0 + fr1*fr1 + fr2*fr2;
            const bool rollingSlides = frMag2 > rollingLimit*rollingLimit;
            const double sr = rollingLimit/std::sqrt(frMag2);
            // a pair without rolling resistance keeps no rolling displacement and no couple
            const bool rolls = muRs[c] > 0;
            const double frCapped0 = fr0*sr, frCapped1 = fr1*sr, frCapped2 = fr2*sr;
            fr0 = rollingSlides ? frCapped0 : fr0;
            fr1 = rollingSlides ? frCapped1 : fr1;
            fr2 = rollingSlides ? frCapped2 : fr2;
            const double xrSpring0 = -(fr0 + gr*vr0)/kr;
            const double xrSpring1 = -(fr1 + gr*vr1)/kr;
            const double xrSpring2 = -(fr2 + gr*vr2)/kr;
            u0 = rollingSlides ? xrSpring0 : u0;
            u1 = rollingSlides ? xrSpring1 : u1;
            u2 = rollingSlides ? xrSpring2 : u2;
            const double nxfr0 = n1*fr2 - n2*fr1;
            const double nxfr1 = n2*fr0 - n0*fr2;
            const double nxfr2 = n0*fr1 - n1*fr0;
            // (evaluateContact's si, sj: R*/R of a particle, 0 for a wall; the batch has
            // no walls)
            const double si = rs/ri, sj = rs/rj;
            xrx[c] = rolls ? u0 : x0; xry[c] = rolls ? u1 : x1; xrz[c] = rolls ? u2 : x2;
            const double ti0 = nxft0 - si*nxfr0, ti1 = nxft1 - si*nxfr1, ti2 = nxft2 - si*nxfr2;
            const double tj0 = nxft0 + sj*nxfr0, tj1 = nxft1 + sj*nxfr1, tj2 = nxft2 + sj*nxfr2;
            tix[c] = rolls ? ti0 : nxft0; tiy[c] = rolls ? ti1 : nxft1; tiz[c] = rolls ? ti2 : nxft2;
            tjx[c] = rolls ? tj0 : nxft0; tjy[c] = rolls ? tj1 : nxft1; tjz[c] = rolls ? tj2 : nxft2;
        }
        ftx[c] = ft0; fty[c] = ft1; ftz[c] = ft2;
        hnx[c] = n0; hny[c] = n1; hnz[c] = n2;
        overlapFractions[c] = delta/(2*std::min(ri, rj));
        normalVelocities[c] = vn;
    }
}

} // namespace

SDF_DEM_VECTOR_CLONES
static void evaluateLinear(ContactBatch& b, int n, double dt)
{
    evaluate<LinearSpringDashpot, false>(b, n, dt);
}

SDF_DEM_VECTOR_CLONES
static void evaluateLinearRolling(ContactBatch& b, int n, double dt)
{
    evaluate<LinearSpringDashpot, true>(b, n, dt);
}

SDF_DEM_VECTOR_CLONES
static void evaluateHertz(ContactBatch& b, int n, double dt)
{
    evaluate<HertzMindlin, false>(b, n, dt);
}

SDF_DEM_VECTOR_CLONES
static void evaluateHertzRolling(ContactBatch& b, int n, double dt)
{
    evaluate<HertzMindlin, true>(b, n, dt);
}

void evaluateContactBatch(ContactModel model, bool rolling, ContactBatch& batch, int n, double dt)
{
    void (*loop)(ContactBatch&, int, double) = nullptr;
    switch (model)
    {
        case ContactModel::linearSpringDashpot:
            loop = rolling ? evaluateLinearRolling : evaluateLinear;
            break;
        case ContactModel::hertzMindlin:
            loop = rolling ? evaluateHertzRolling : evaluateHertz;
            break;
        default: break;
    }
    if (loop)
    {
        // the discarded lanes' 0/0: no trap, and the caller's flags as they were
        std::fenv_t callers;
        std::feholdexcept(&callers);
        loop(batch, n, dt);
        std::fesetenv(&callers);
        return;
    }
    throw std::logic_error
    (
        "evaluateContactBatch: contact model " + contactModelName(model)
      + " has no batched loop (hasBatchedLoop)"
    );
}

} // namespace sdf::dem

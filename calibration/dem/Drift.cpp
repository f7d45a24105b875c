// The kick and drift of a particle range (Drift.hpp).

#include "Drift.hpp"
#include "VectorClones.hpp"

namespace sdf::dem
{

namespace
{

SDF_DEM_VECTOR_CLONES
void kickAndDrift
(
    Particles& p, int begin, int end, double dt, double shearRate, double yMid,
    const double* __restrict uBuildX, const double* __restrict uBuildY,
    const double* __restrict uBuildZ, double* __restrict step2, double* __restrict disp2
)
{
    const double h = 0.5*dt;
    double* __restrict x = p.x.data();
    double* __restrict y = p.y.data();
    double* __restrict z = p.z.data();
    double* __restrict vx = p.vx.data();
    double* __restrict vy = p.vy.data();
    double* __restrict vz = p.vz.data();
    double* __restrict wx = p.wx.data();
    double* __restrict wy = p.wy.data();
    double* __restrict wz = p.wz.data();
    double* __restrict ux = p.ux.data();
    double* __restrict uy = p.uy.data();
    double* __restrict uz = p.uz.data();
    const double* __restrict fx = p.fx.data();
    const double* __restrict fy = p.fy.data();
    const double* __restrict fz = p.fz.data();
    const double* __restrict tx = p.tx.data();
    const double* __restrict ty = p.ty.data();
    const double* __restrict tz = p.tz.data();
    const double* __restrict invMass = p.invMass.data();
    const double* __restrict invInertia = p.invInertia.data();
    // the arrays are distinct (restrict does not reach GCC's dependence analysis here)
    #pragma GCC ivdep
    for (int i = begin; i < end; ++i)
    {
        const double im = invMass[i], ii = invInertia[i];
        const double fxm = h*fx[i]*im, fym = h*fy[i]*im, fzm = h*fz[i]*im;
        const double txi = h*tx[i]*ii, tyi = h*ty[i]*ii, tzi = h*tz[i]*ii;
        vx[i] += fxm; vy[i] += fym; vz[i] += fzm;
        wx[i] += txi; wy[i] += tyi; wz[i] += tzi;

        const double ddx = dt*vx[i], ddy = dt*vy[i], ddz = dt*vz[i];
        const double peculiarDdx = ddx - dt*shearRate*(y[i] - yMid);
        step2[i] = peculiarDdx*peculiarDdx + ddy*ddy + ddz*ddz;
        // u: peculiar (x without the streaming), so u - u at the list build is the
        // displacement the Verlet criterion needs (no separate array written)
        ux[i] += peculiarDdx; uy[i] += ddy; uz[i] += ddz;
        const double ex = ux[i] - uBuildX[i], ey = uy[i] - uBuildY[i], ez = uz[i] - uBuildZ[i];
        disp2[i] = ex*ex + ey*ey + ez*ez;
        x[i] += ddx; y[i] += ddy; z[i] += ddz;
    }
}

} // namespace

void driftRange
(
    Particles& p, int begin, int end, double dt, const PeriodicBox& box,
    const ParticleArray& uBuildX, const ParticleArray& uBuildY, const ParticleArray& uBuildZ,
    ParticleArray& step2, ParticleArray& disp2, double& maxDisp2, double& maxStep2
)
{
    kickAndDrift
    (
        p, begin, end, dt, box.shearRate, 0.5*box.ly, uBuildX.data(), uBuildY.data(),
        uBuildZ.data(), step2.data(), disp2.data()
    );
    double disp2Max = maxDisp2, step2Max = maxStep2;
    for (int i = begin; i < end; ++i)
    {
        if (step2[i] > step2Max) step2Max = step2[i];
        if (disp2[i] > disp2Max) disp2Max = disp2[i];
        box.wrap(p.x[i], p.y[i], p.z[i], p.vx[i]);
    }
    maxDisp2 = disp2Max;
    maxStep2 = step2Max;
}

} // namespace sdf::dem

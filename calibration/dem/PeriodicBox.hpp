#ifndef sdf_dem_PeriodicBox_hpp
#define sdf_dem_PeriodicBox_hpp

// Periodic box [0,lx) x [0,ly) x [0,lz) with optional Lees-Edwards simple shear:
// streaming velocity u_x = shearRate (y - ly/2); the image above (y + ly) is displaced by
// +offset in x and moves with +shearRate ly in x (positions AND velocities are shifted).

#include <cmath>

namespace sdf::dem
{

struct PeriodicBox
{
    double lx = 1, ly = 1, lz = 1;
    double shearRate = 0;   // gammaDot = du_x/dy [1/s]
    double offset = 0;      // x displacement of the upper image, kept in [0, lx)

    double volume() const { return lx*ly*lz; }
    double streamingVelocity(double py) const { return shearRate*(py - 0.5*ly); }

    //- Minimum image of r = x_i - x_j and of dvx = v_i - v_j (x component).
    void minimumImage(double& dx, double& dy, double& dz, double& dvx) const
    {
        if (dy > 0.5*ly)
        {
            dy -= ly; dx -= offset; dvx -= shearRate*ly;
        }
        else if (dy < -0.5*ly)
        {
            dy += ly; dx += offset; dvx += shearRate*ly;
        }
        // |dx| < 2 lx (wrapped positions plus an offset in [0, lx)), |dz| < lz:
        // branches instead of floor (a library call without SSE4.1)
        const double hx = 0.5*lx, hz = 0.5*lz;
        if (dx > hx) { dx -= lx; if (dx > hx) dx -= lx; }
        else if (dx < -hx) { dx += lx; if (dx < -hx) dx += lx; }
        if (dz > hz) dz -= lz;
        else if (dz < -hz) dz += lz;
    }

    //- Wraps a particle into the box (Lees-Edwards shifts x and vx when crossing y).
    void wrap(double& px, double& py, double& pz, double& pvx) const
    {
        if (py >= ly)
        {
            py -= ly; px -= offset; pvx -= shearRate*ly;
        }
        else if (py < 0)
        {
            py += ly; px += offset; pvx += shearRate*ly;
        }
        if (py >= ly || py < 0) { py -= ly*std::floor(py/ly); }  // pathological: far out
        // within one period (every step but the pathological): the same result as
        // p - l floor(p/l) without the division and the floor library call
        if (px >= lx) { px = px < 2*lx ? px - lx : px - lx*std::floor(px/lx); }
        else if (px < 0) { px = px >= -lx ? px + lx : px - lx*std::floor(px/lx); }
        if (pz >= lz) { pz = pz < 2*lz ? pz - lz : pz - lz*std::floor(pz/lz); }
        else if (pz < 0) { pz = pz >= -lz ? pz + lz : pz - lz*std::floor(pz/lz); }
        // floor of a value just below 0 can give exactly lx
        if (px >= lx) px -= lx;
        if (pz >= lz) pz -= lz;
        if (py >= ly) py -= ly;
    }

    void advanceShear(double dt)
    {
        if (shearRate == 0) return;
        offset += shearRate*ly*dt;
        offset -= lx*std::floor(offset/lx);
    }
};

} // namespace sdf::dem

#endif

#ifndef sdf_dem_Walls_hpp
#define sdf_dem_Walls_hpp

// Flat frictional walls (infinitely heavy) in a cell, with the contact history of every
// particle at every wall. Serial: walls serve single-impact tests, not the periodic cells.

#include "ContactForce.hpp"
#include "Particles.hpp"

#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace sdf::dem
{

//- Flat frictional wall (infinitely heavy): point on the plane and unit normal into the domain.
struct Wall
{
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

class Walls
{
public:
    bool empty() const { return walls_.empty(); }
    std::size_t size() const { return walls_.size(); }
    const Wall& operator[](std::size_t w) const { return walls_[w]; }

    //- Adds a wall (normal normalised) for nParticles particles.
    void add(const Wall& wall, std::size_t nParticles);
    //- Forgets every contact (after a checkpoint import).
    void clearHistories(std::size_t nParticles);

    //- Adds the wall forces and torques to the particles (torques are final: the force
    //  pass has finished them); fPrev, tPrev: F^n and torques^n for the synchronised
    //  velocities. Returns the largest overlap fraction delta/(2 r).
    template<class Law>
    double addForces
    (
        Particles& p,
        const ContactLaw& law,
        const ParticleArray& fPrevX, const ParticleArray& fPrevY, const ParticleArray& fPrevZ,
        const ParticleArray& tPrevX, const ParticleArray& tPrevY, const ParticleArray& tPrevZ,
        double dt
    );

    //- Adds the elastic energy of the normal springs at the walls to e, term by term.
    void addElasticEnergy(const Particles& p, const ContactLaw& law, double& e) const;

private:
    std::vector<Wall> walls_;
    std::vector<std::vector<ContactHistory>> history_;    // per wall, per particle
};

template<class Law>
double Walls::addForces
(
    Particles& p,
    const ContactLaw& law,
    const ParticleArray& fPrevX, const ParticleArray& fPrevY, const ParticleArray& fPrevZ,
    const ParticleArray& tPrevX, const ParticleArray& tPrevY, const ParticleArray& tPrevZ,
    double dt
)
{
    double maxOverlap = 0;
    const int n = int(p.size());
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        const Wall& wall = walls_[w];
        for (int i = 0; i < n; ++i)
        {
            const double s =
                (p.x[i] - wall.point.x())*wall.normal.x()
              + (p.y[i] - wall.point.y())*wall.normal.y()
              + (p.z[i] - wall.point.z())*wall.normal.z();
            ContactHistory& h = history_[w][i];
            if (s >= p.radius[i])
            {
                h.touching = false;
                h.ft[0] = h.ft[1] = h.ft[2] = 0;
                h.xr[0] = h.xr[1] = h.xr[2] = 0;
                continue;
            }
            ContactKinematics kin;
            for (int a = 0; a < 3; ++a) kin.r[a] = s*wall.normal[a];
            kin.radiusI = p.radius[i]; kin.radiusJ = 0;
            kin.dvHalf[0] = p.vx[i]; kin.dvHalf[1] = p.vy[i]; kin.dvHalf[2] = p.vz[i];
            const double im = p.invMass[i], ii = p.invInertia[i];
            kin.dvSync[0] = p.vx[i] + 0.5*dt*fPrevX[i]*im;
            kin.dvSync[1] = p.vy[i] + 0.5*dt*fPrevY[i]*im;
            kin.dvSync[2] = p.vz[i] + 0.5*dt*fPrevZ[i]*im;
            kin.wHalfI[0] = p.wx[i]; kin.wHalfI[1] = p.wy[i]; kin.wHalfI[2] = p.wz[i];
            kin.wSyncI[0] = p.wx[i] + 0.5*dt*tPrevX[i]*ii;
            kin.wSyncI[1] = p.wy[i] + 0.5*dt*tPrevY[i]*ii;
            kin.wSyncI[2] = p.wz[i] + 0.5*dt*tPrevZ[i]*ii;
            for (int a = 0; a < 3; ++a) kin.wHalfJ[a] = kin.wSyncJ[a] = 0;
            const ContactResult res = evaluateContact<Law>(law.wall(p.species[i]), kin, h, dt);
            p.fx[i] += res.force[0]; p.fy[i] += res.force[1]; p.fz[i] += res.force[2];
            const double r = p.radius[i];
            p.tx[i] -= r*res.nCrossFt[0]; p.ty[i] -= r*res.nCrossFt[1]; p.tz[i] -= r*res.nCrossFt[2];
            if (law.wall(p.species[i]).rollingFriction > 0)
            {
                p.tx[i] += res.rollingTorque[0]; p.ty[i] += res.rollingTorque[1]; p.tz[i] += res.rollingTorque[2];
            }
            maxOverlap = std::max(maxOverlap, res.overlap/(2*r));
        }
    }
    return maxOverlap;
}

} // namespace sdf::dem

#endif

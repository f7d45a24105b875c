#include "GravityShear.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

WallBoundedCell cutWallBoundedCell
(
    Particles particles,
    const PeriodicBox& periodicBox,
    double wallThickness,
    double emptyGap
)
{
    if (!std::isfinite(wallThickness) || !(wallThickness > 0) || !(2*wallThickness < periodicBox.ly))
    {
        throw std::invalid_argument
        (
            "entry 'wallThickness' must be positive and leave room for a flowing layer"
            " (the packing is " + std::to_string(periodicBox.ly) + " m tall), got "
          + std::to_string(wallThickness) + " m"
        );
    }
    if (!std::isfinite(emptyGap) || !(emptyGap > 0))
    {
        throw std::invalid_argument("the empty gap above the top wall must be positive, got " + std::to_string(emptyGap));
    }
    WallBoundedCell cell;
    cell.box = periodicBox;
    cell.bottomPlane = wallThickness;
    cell.topPlane = periodicBox.ly - wallThickness;
    cell.box.ly = periodicBox.ly + emptyGap;
    cell.box.shearRate = 0;
    cell.box.offset = 0;
    cell.roleById.assign(particles.size(), GrainRole::flowing);
    // numbered afresh, as the Simulation built on the cell numbers them (id = index)
    particles.id.resize(particles.size());
    long counts[3] = {0, 0, 0};
    for (std::size_t i = 0; i < particles.size(); ++i)
    {
        particles.id[i] = int(i);
        GrainRole role = GrainRole::flowing;
        if (particles.y[i] < cell.bottomPlane) role = GrainRole::bottomWall;
        else if (particles.y[i] >= cell.topPlane) role = GrainRole::topWall;
        cell.roleById[std::size_t(particles.id[i])] = role;
        ++counts[int(role)];
        if (role != GrainRole::flowing)
        {
            particles.invMass[i] = 0;
            particles.invInertia[i] = 0;
            particles.vx[i] = particles.vy[i] = particles.vz[i] = 0;
            particles.wx[i] = particles.wy[i] = particles.wz[i] = 0;
        }
    }
    if (counts[0] == 0 || counts[1] == 0 || counts[2] == 0)
    {
        throw std::invalid_argument
        (
            "entry 'wallThickness': the cut leaves " + std::to_string(counts[1]) + " grains in the"
            " bottom wall, " + std::to_string(counts[2]) + " in the top wall and "
          + std::to_string(counts[0]) + " flowing: each needs some"
        );
    }
    cell.particles = std::move(particles);
    return cell;
}

void validateGravityShearSettings(const GravityShearSettings& settings, double timeStep)
{
    if (!std::isfinite(settings.gravity) || !(settings.gravity > 0))
    {
        throw std::invalid_argument
        (
            "entry 'gravity' must be finite and positive [m/s^2] (it acts along -y, normal"
            " to the walls), got " + std::to_string(settings.gravity)
        );
    }
    if (!std::isfinite(settings.normalStress) || !(settings.normalStress > 0))
    {
        throw std::invalid_argument
        (
            "entry 'normalStress' must be a stress > 0 Pa (the top wall's load), got "
          + std::to_string(settings.normalStress)
        );
    }
    if (!std::isfinite(settings.wallSpeed) || settings.wallSpeed < 0)
    {
        throw std::invalid_argument("entry 'wallSpeed' must be finite and >= 0 [m/s], got " + std::to_string(settings.wallSpeed));
    }
    const double tauU = settings.profileRelaxationTime;
    if (!std::isfinite(tauU) || tauU < 0 || (tauU > 0 && timeStep > 0 && tauU < 10*timeStep))
    {
        throw std::invalid_argument
        (
            "entry 'profileRelaxationTime' must be 0 (off) or at least 10 time steps ("
          + std::to_string(10*timeStep) + " s), got " + std::to_string(tauU)
        );
    }
}

GravityShear::GravityShear
(
    const GravityShearSettings& settings,
    const WallBoundedCell& cell,
    double dMin,
    double timeStep
)
:
    settings_(settings),
    roleById_(cell.roleById),
    area_(cell.box.lx*cell.box.lz),
    bottomPlane_(cell.bottomPlane),
    topPlane_(cell.topPlane),
    boxHeight_(cell.box.ly),
    dMin_(dMin),
    timeStep_(timeStep)
{
    validateGravityShearSettings(settings, timeStep);
    if (!(timeStep > 0) || !(dMin > 0))
    {
        throw std::invalid_argument("gravityShear: time step and smallest diameter must be positive");
    }
    for (std::size_t i = 0; i < cell.particles.size(); ++i)
    {
        if (roleById_[std::size_t(cell.particles.id[i])] == GrainRole::topWall) wallMass_ += cell.particles.mass[i];
    }
}

double GravityShear::velocityScale() const
{
    return std::max(settings_.wallSpeed, std::sqrt(settings_.gravity*gap()));
}

void GravityShear::afterStep(Particles& p, int)
{
    const int n = int(p.size());
    // the wall has moved by its velocity in this step's drift
    topPlane_ += wallVelocityY_*timeStep_;

    double topForce = 0, bottomForce = 0;
    for (int i = 0; i < n; ++i)
    {
        const GrainRole r = roleById_[std::size_t(p.id[i])];
        if (r == GrainRole::topWall) topForce += p.fy[i];
        else if (r == GrainRole::bottomWall) bottomForce -= p.fy[i];
    }
    topForceSum_ += topForce;
    bottomForceSum_ += bottomForce;
    ++forceSteps_;

    // the top wall is a body of the mass of its grains under the load sigma_N A, as a
    // LAMMPS rigid body under fix addforce: its mean velocity vanishing, the grains' mean
    // force on it is sigma_N A exactly (three first-order servos tried before biased the
    // mean load by -40 to +27 % in shear, or followed a compacting bed too slowly)
    wallVelocityY_ += timeStep_*(topForce - settings_.normalStress*area_)/wallMass_;
    if (topForce > 0.5*settings_.normalStress*area_) landed_ = true;
    if (landed_) slidingTime_ += timeStep_;

    // the top wall slides once it has landed, its speed ramped up over one strain gap/U
    // (a wall set sliding at once hits the grains at rest beside it at U)
    const double rampTime = settings_.wallSpeed > 0 ? gap()/settings_.wallSpeed : 0;
    const double wallSpeed =
        slidingTime_ >= rampTime ? settings_.wallSpeed : settings_.wallSpeed*slidingTime_/rampTime;

    const double dvGravity = settings_.gravity*timeStep_;
    const double tauU = settings_.profileRelaxationTime;
    const double a = tauU > 0 ? timeStep_/tauU : 0;
    const double gapNow = gap();
    // a flowing grain centred in the upper half of the empty gap has left the layer
    // (through the bottom wall, wrapped by the periodic box, or over the top wall)
    const double lostAbove = 0.5*(topPlane_ + boxHeight_);
    for (int i = 0; i < n; ++i)
    {
        switch (roleById_[std::size_t(p.id[i])])
        {
            case GrainRole::flowing:
                if (p.y[i] > lostAbove)
                {
                    throw std::runtime_error
                    (
                        "gravityShear: a flowing grain (id " + std::to_string(p.id[i]) + ") left the layer"
                        " between the walls (y " + std::to_string(p.y[i]) + " m, top wall at "
                      + std::to_string(topPlane_) + " m): through a wall (make wallThickness larger)"
                        " or over the top wall (a normalStress too small for wallSpeed)"
                    );
                }
                p.vy[i] -= dvGravity;
                if (a > 0)
                {
                    const double s = std::clamp((p.y[i] - bottomPlane_)/gapNow, 0.0, 1.0);
                    p.vx[i] += a*(wallSpeed*s - p.vx[i]);
                }
                break;
            case GrainRole::topWall:
                p.vx[i] = wallSpeed;
                p.vy[i] = wallVelocityY_;
                p.vz[i] = 0;
                break;
            case GrainRole::bottomWall:
                break;
        }
    }
}

std::vector<double> GravityShear::exportState() const
{
    return
    {
        topPlane_, wallVelocityY_, topForceSum_, bottomForceSum_, double(forceSteps_),
        landed_ ? 1.0 : 0.0, slidingTime_
    };
}

void GravityShear::importState(const std::vector<double>& state)
{
    if (state.size() != 7)
    {
        throw std::invalid_argument("gravityShear: a driving state of 7 values expected, got " + std::to_string(state.size()));
    }
    topPlane_ = state[0];
    wallVelocityY_ = state[1];
    topForceSum_ = state[2];
    bottomForceSum_ = state[3];
    forceSteps_ = long(state[4]);
    landed_ = state[5] != 0;
    slidingTime_ = state[6];
}

double GravityShear::meanTopWallStress() const
{
    return forceSteps_ > 0 ? topForceSum_/forceSteps_/area_ : 0;
}

double GravityShear::meanBottomWallStress() const
{
    return forceSteps_ > 0 ? bottomForceSum_/forceSteps_/area_ : 0;
}

void GravityShear::resetWallStresses()
{
    topForceSum_ = bottomForceSum_ = 0;
    forceSteps_ = 0;
}

} // namespace sdf::dem

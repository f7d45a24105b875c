#ifndef sdf_dem_GravityShear_hpp
#define sdf_dem_GravityShear_hpp

// Plane shear under gravity between two rough walls: the cell in which gravity-driven
// size segregation is measured (apps/gravityShearCell.cpp). Periodic along the flow (x)
// and the vorticity (z); along y, gravity (-y) and two walls made of frozen grains cut
// from the same random packing as the flowing grains, so that the walls are as rough as
// the bed. The bottom wall is at rest; the top wall slides along x at wallSpeed and
// moves along y under the load normalStress (a rigid body of its grains' mass, below).
// It starts sliding once it has landed on the grains (carried half its load), its speed
// ramped up over one strain gap/U: set sliding at once it would hit the grains at rest
// beside it at U (with soft contacts, overlaps of a quarter diameter). Above the top
// wall the periodic box carries an empty gap, so no grain meets
// the bottom wall's periodic image.
//
// Frozen grains carry invMass = invInertia = 0: the integrator's kicks leave their
// velocities alone and its drift moves them rigidly with the velocity set here. The
// flowing grains get gravity as a velocity increment -g dt after each step (a constant
// force: the time average of the momentum balance is exact, so the lithostatic stress
// gradient is a check of the cell, not an input).
//
// The top wall is a rigid body of its grains' mass M under the load sigma_N A (as a LAMMPS
// rigid body under fix addforce, the peer of benchmarks/gravityShearVsLammps):
//     M dV_y/dt = F_y - sigma_N A,
// F_y the grains' force on it this step. Its mean velocity vanishing, the grains' mean
// force on it is sigma_N A exactly; it lands on the grains under the load and rides on
// them, its bounces damped by their inelastic contacts. (First-order servos, V_y
// proportional to the load's error, biased the mean load by -40 to +27 % in shear: capped,
// gated by the load, or too slow to follow a compacting bed.)//
// Optionally each flowing grain's x velocity is relaxed toward the linear profile
// U (y - y_b)/(y_t - y_b) over profileRelaxationTime tau_u (a body force holding the
// shear rate uniform, where gravity would otherwise concentrate the shear under the
// top wall); 0: off, the shear profile is an output.
//
// Not selectable by name: hand it to a Simulation built with mode nve (setDriving).

#include "Driving.hpp"
#include "Particles.hpp"
#include "PeriodicBox.hpp"

#include <string>
#include <vector>

namespace sdf::dem
{

struct GravityShearSettings
{
    double gravity = 9.81;                //- g [m/s^2], along -y, on the flowing grains
    double wallSpeed = 0;                 //- U: the top wall's velocity along x [m/s]
    double normalStress = 0;              //- sigma_N the top wall holds [Pa] (> 0)
    double profileRelaxationTime = 0;     //- tau_u [s]; 0: no profile-holding force
};

//- Throws std::invalid_argument naming the entry: gravity finite and > 0, normalStress > 0,
//  wallSpeed finite and >= 0, profileRelaxationTime >= 0, the profile time
//  at least 10 time steps (not checked while timeStep is 0: not yet known).
void validateGravityShearSettings(const GravityShearSettings& settings, double timeStep);

//- What a particle is in the wall-bounded cell.
enum class GrainRole : unsigned char { flowing, bottomWall, topWall };

//- The cell cut from a periodic packing: the grains whose centres lie below
//  wallThickness form the bottom wall, those above ly - wallThickness the top wall; the
//  box is then heightened by emptyGap (the top wall's periodic image stays out of reach).
struct WallBoundedCell
{
    Particles particles;                  //- frozen grains with invMass = invInertia = 0
    PeriodicBox box;
    std::vector<GrainRole> roleById;      //- by Particles::id
    double bottomPlane = 0;               //- y_b: the flowing layer's lower bound [m]
    double topPlane = 0;                  //- y_t: its upper bound at the start [m]
};

//- Throws std::invalid_argument naming the entry: wallThickness and emptyGap > 0, each
//  wall and the flowing layer non-empty.
WallBoundedCell cutWallBoundedCell
(
    Particles particles,
    const PeriodicBox& periodicBox,
    double wallThickness,
    double emptyGap
);

class GravityShear : public Driving
{
public:
    //- Throws std::invalid_argument naming the entry (validateGravityShearSettings; time
    //  step and dMin > 0).
    GravityShear
    (
        const GravityShearSettings& settings,
        const WallBoundedCell& cell,
        double dMin,
        double timeStep
    );

    std::string name() const override { return "gravityShear"; }
    double velocityScale() const override;
    void afterStep(Particles& particles, int nThreads) override;
    std::vector<double> exportState() const override;
    void importState(const std::vector<double>& state) override;

    const GravityShearSettings& settings() const { return settings_; }
    //- M, the top wall's mass [kg]
    double wallMass() const { return wallMass_; }
    GrainRole role(const Particles& p, int i) const { return roleById_[std::size_t(p.id[i])]; }
    double bottomPlane() const { return bottomPlane_; }
    double topPlane() const { return topPlane_; }
    double gap() const { return topPlane_ - bottomPlane_; }
    double area() const { return area_; }

    //- The grains' mean force along y on the top and on the bottom wall per unit area
    //  since the last reset [Pa] (the top's holds sigma_N; the bottom's adds the flowing
    //  grains' weight per area: the cell's momentum balance)
    double meanTopWallStress() const;
    double meanBottomWallStress() const;
    void resetWallStresses();
    //- The steps the means since the last reset are over
    long wallStressSteps() const { return forceSteps_; }
    //- The time since the top wall landed [s] (0 before; its speed ramps up over one
    //  strain gap/U from then)
    double slidingTime() const { return slidingTime_; }

private:
    GravityShearSettings settings_;
    std::vector<GrainRole> roleById_;
    double area_;
    double bottomPlane_;
    double topPlane_;
    double boxHeight_;
    double dMin_;
    double timeStep_;
    double wallMass_ = 0;         // M: the top wall's grains' mass [kg]
    double wallVelocityY_ = 0;
    bool landed_ = false;         // the wall has carried half its load once
    double slidingTime_ = 0;      // since it landed [s] (its speed ramps over one strain)
    double topForceSum_ = 0, bottomForceSum_ = 0;
    long forceSteps_ = 0;
};

} // namespace sdf::dem

#endif

#ifndef sdf_dem_Drift_hpp
#define sdf_dem_Drift_hpp

// The first half of a velocity-Verlet step over a particle range: the half kick with the
// forces F^n, the drift, the Lees-Edwards wrap, and the largest peculiar displacements.
// The kick and drift run as one vectorised loop (VectorClones.hpp), the wrap and the
// maxima after it; the same bits as one scalar loop.

#include "Particles.hpp"
#include "PeriodicBox.hpp"

namespace sdf::dem
{

//- Particles [begin, end): half kick, drift, wrap (box: with the offset at the new time);
//  their peculiar displacements in this step and since the list build (uBuild) raise
//  maxStep2 and maxDisp2. step2 and disp2 are scratch arrays indexed like the particles.
void driftRange
(
    Particles& p, int begin, int end, double dt, const PeriodicBox& box,
    const ParticleArray& uBuildX, const ParticleArray& uBuildY, const ParticleArray& uBuildZ,
    ParticleArray& step2, ParticleArray& disp2, double& maxDisp2, double& maxStep2
);

} // namespace sdf::dem

#endif

#ifndef sdf_dem_ContactBatch_hpp
#define sdf_dem_ContactBatch_hpp

// The force pass's touching pairs evaluated in batches, structure of arrays: the pass
// gathers each contact's kinematics, coefficients and history into the batch, one loop
// evaluates all of them (the contact law of ContactForce.hpp without a branch, so that
// the compiler vectorises it over contacts), and the pass scatters the results in its
// own order. The loop makes the same operations on the same operands in the same order
// as evaluateContact, and IEEE-754 vector instructions round as the scalar ones do, so
// the results are bitwise those of evaluateContact (the file is compiled without
// floating-point contraction into fused multiply-adds, which would round otherwise).
// With rolling resistance the loop carries its part too (a second instantiation, so that
// cells without it do not pay for it). A law without a batched loop (hasBatchedLoop)
// runs contact by contact.

#include "ContactForce.hpp"
#include "ContactLaw.hpp"
#include "ContactModels.hpp"

#include <vector>

namespace sdf::dem
{

struct ContactBatch
{
    // inputs, per contact: x_i - x_j, radii, the half-step and synchronised relative
    // velocities and spins (as ContactKinematics), the law's four constants (the
    // policy's stiffnessConstants), the friction coefficient, the history
    std::vector<int> particleI, particleJ;                // the pair (not read by the loop)
    std::vector<double> rx, ry, rz, shiftVx, radiusI, radiusJ;
    std::vector<double> dvHalfX, dvHalfY, dvHalfZ, dvSyncX, dvSyncY, dvSyncZ;
    std::vector<double> wHalfIX, wHalfIY, wHalfIZ, wHalfJX, wHalfJY, wHalfJZ;
    std::vector<double> wSyncIX, wSyncIY, wSyncIZ, wSyncJX, wSyncJY, wSyncJZ;
    std::vector<double> constant0, constant1, constant2, constant3, friction;
    std::vector<double> touching;                         // 1: the contact touched at the last step
    // history in and out: the elastic tangential force and the contact normal
    std::vector<double> ftX, ftY, ftZ, nX, nY, nZ;
    // rolling resistance (the rolling loop only): the pair's mu_r, k_r, gamma_r and R*;
    // the rolling displacement in and out; the torque sums out (ContactResult)
    std::vector<double> rollingFriction, rollingStiffness, rollingDamping, effectiveRadius;
    std::vector<double> xrX, xrY, xrZ;
    std::vector<double> torqueSumIX, torqueSumIY, torqueSumIZ, torqueSumJX, torqueSumJY, torqueSumJZ;
    // outputs: force on i, n x F_t, the overlap over the smaller diameter, the normal
    // velocity (sync)
    std::vector<double> forceX, forceY, forceZ, nCrossFtX, nCrossFtY, nCrossFtZ;
    std::vector<double> overlapFraction, normalVelocity;

    // the contacts the loop does not take (coincident centres, |r| = 0) and their
    // history before the step: evaluated contact by contact after it
    std::vector<int> unbatched;
    std::vector<ContactHistory> unbatchedHistory;

    //- Room for n contacts (grows only).
    void reserveFor(int n);

private:
    int capacity_ = 0;
};

//- Evaluates contacts [0, n) of the batch with the contact law `model` (the batch's
//  inputs must be touching pairs, |r| > 0); rolling: with the rolling resistance's part
//  (its inputs set; without it the rolling arrays are neither read nor written).
void evaluateContactBatch(ContactModel model, bool rolling, ContactBatch& batch, int n, double dt);

//- The laws with a batched loop (a case in evaluateContactBatch). A law without one runs
//  contact by contact, unchanged otherwise.
template<class Law> constexpr bool hasBatchedLoop = false;
template<> constexpr bool hasBatchedLoop<LinearSpringDashpot> = true;
template<> constexpr bool hasBatchedLoop<HertzMindlin> = true;

} // namespace sdf::dem

#endif

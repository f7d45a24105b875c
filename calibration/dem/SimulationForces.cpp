// The force pass of Simulation: contact forces of all listed pairs (one instantiation per
// contact law, picked once per pass), walls, the finish of the step's velocities, collision
// statistics and the overlap check.
//
// Reproducibility. Block b owns particles [P_b, P_b+1) and the pairs whose first particle
// it owns; pairs are (i, j)-ordered with i < j, so block b's pairs read particles >= P_b
// only. Every particle sums its incident pairs in DEcreasing pair order, starting from zero,
// whatever the blocks and threads (bitwise reproducible, independent of the thread count
// and of the block boundaries):
//  - a block adds its contacts' forces from the last pair to the first, each to i and,
//    when j is its own, to j (the law itself may run in any order: ContactBatch): its own
//    pairs are the highest-numbered pairs of all its particles, so they come first;
//  - contacts whose j lies in a higher block ("cross" contacts, listed per block in the
//    same decreasing order) come from lower-numbered pairs: after a barrier, the thread
//    whose finish range holds j adds them, block b-1's first, down to block 0's, and only
//    then finishes the particle (torque, second half kick).
// Slots of touching pairs are always written: stress sampling reads them.

#include "Simulation.hpp"
#include "ThreadTeam.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

void Simulation::computeForces(bool checkDisplacements, bool halfKick)
{
    if (!listValid_ || (checkDisplacements && neighbourListExpired())) rebuildNeighbourList();
    // F^n and the torques move to fPrev/tPrev (pointer swaps; the pass writes the new ones
    // in the other buffers): the dashpots use the synchronised velocities
    // v^{n+1/2} + dt/2 F^n/m formed from them once per particle at the pass's start
    // (synchronisedVelocities; the drift writes no such array). Without the half kick (a
    // refresh) they are the current velocities.
    {
        Particles& q = particles_;
        q.fx.swap(fPrevX_); q.fy.swap(fPrevY_); q.fz.swap(fPrevZ_);
        q.tx.swap(tPrevX_); q.ty.swap(tPrevY_); q.tz.swap(tPrevZ_);
        if (q.fx.size() != q.size())
        {
            for (auto* a : {&q.fx, &q.fy, &q.fz, &q.tx, &q.ty, &q.tz}) a->assign(q.size(), 0.0);
        }
        if (vSyncX_.size() != q.size())
        {
            for (auto* a : {&vSyncX_, &vSyncY_, &vSyncZ_, &wSyncX_, &wSyncY_, &wSyncZ_})
            {
                a->assign(q.size(), 0.0);
            }
        }
        if (!halfKick)
        {
            for (auto* a : {&fPrevX_, &fPrevY_, &fPrevZ_, &tPrevX_, &tPrevY_, &tPrevZ_})
            {
                std::fill(a->begin(), a->end(), 0.0);
            }
        }
    }
    // outside step() positions may have been edited: rebuild the near list
    if (checkDisplacements || nearDrift_ + 2*nearRadiusGrowth_ >= nearSkin_) nearValid_ = false;
    const bool rebuildNear = !nearValid_;

    Particles& p = particles_;
    const int n = int(p.size());
    // with walls the kick follows their forces, after the pass
    const bool kickHere = halfKick && walls_.empty();
    const bool finishSums = driving_->beginForcePass(n, kickHere);

    // the one dispatch on the contact law: everything below runs with Law fixed
    const double maxOverlap = withContactModel
    (
        law_.model(),
        [&](auto law)
        {
            using Law = decltype(law);
            const double pairs = pairForcePass<Law>(rebuildNear, kickHere, finishSums);
            if (walls_.empty()) return pairs;
            const double walls = walls_.addForces<Law>
            (
                p, law_, fPrevX_, fPrevY_, fPrevZ_, tPrevX_, tPrevY_, tPrevZ_, dt_
            );
            return std::max(pairs, walls);
        }
    );

    if (rebuildNear)
    {
        nearValid_ = true;
        nearDrift_ = 0;
        nearRadiusGrowth_ = 0;
    }

    if (halfKick && !kickHere)
    {
        const double h = 0.5*dt_;
        for (int i = 0; i < n; ++i)
        {
            const double im = p.invMass[i], ii = p.invInertia[i];
            p.vx[i] += h*p.fx[i]*im; p.vy[i] += h*p.fy[i]*im; p.vz[i] += h*p.fz[i]*im;
            p.wx[i] += h*p.tx[i]*ii; p.wy[i] += h*p.ty[i]*ii; p.wz[i] += h*p.tz[i]*ii;
        }
    }

    if (collisionsEnabled_) gatherCollisions();

    lastMaxOverlapFraction_ = maxOverlap;
    if (settings_.maxOverlapFraction > 0 && maxOverlap > settings_.maxOverlapFraction)
    {
        overlapFailure(maxOverlap);
    }
}

template<class Law>
double Simulation::pairForcePass(bool rebuildNear, bool kickHere, bool finishSums)
{
    const int nBlocks = int(blockParticle_.size()) - 1;
    // busy times for the block shares (only when there is more than one block)
    const bool balance = nBlocks > 1;
    const double forceStart = balance ? wallSeconds() : 0;
    const double maxOverlap = maxOverThreads<1>
    (
        nThreads_, 0.0,
        [&](int thread, int team, std::array<double, 1>& localMax)
        {
            for (int b = thread; b < nBlocks; b += team)
            {
                const double busyStart = balance ? wallSeconds() : 0;
                synchronisedVelocities(blockParticle_[b], blockParticle_[b + 1]);
                if (balance) forceBalance_.busy[b] += wallSeconds() - busyStart;
            }
            if (nBlocks > 1)
            {
                #pragma omp barrier
            }
            for (int b = thread; b < nBlocks; b += team)
            {
                const double busyStart = balance ? wallSeconds() : 0;
                const int nContacts = findTouchingPairs(b, rebuildNear);
                const double blockOverlap = evaluateTouchingPairs<Law>(b, nContacts);
                if (blockOverlap > localMax[0]) localMax[0] = blockOverlap;
                // one block is complete: finish it now (else after the barrier, in
                // parallel with the higher blocks adding their cross contacts)
                if (nBlocks == 1)
                {
                    finishParticles(blockParticle_[b], blockParticle_[b + 1], kickHere, finishSums);
                }
                if (balance) forceBalance_.busy[b] += wallSeconds() - busyStart;
            }

            if (nBlocks > 1)
            {
                #pragma omp barrier
            }

            // the particles' sums are complete once the lower blocks' cross contacts are
            // added; this phase has its own particle ranges
            for (int b = thread; b < nBlocks && nBlocks > 1; b += team)
            {
                const double busyStart = wallSeconds();
                const int begin = finishBegin_[b], end = finishBegin_[b + 1];
                addCrossContacts(begin, end);
                finishParticles(begin, end, kickHere, finishSums);
                finishBalance_.busy[b] += wallSeconds() - busyStart;
            }
        }
    )[0];
    if (balance) forceBalance_.totalWall += wallSeconds() - forceStart;
    return maxOverlap;
}

int Simulation::findTouchingPairs(int b, bool rebuildNear)
{
    Particles& p = particles_;
    const int* first = list_.first().data();
    const int* second = list_.second().data();
    const int* blockPair = blockPair_.data();
    const PeriodicBox box = box_;
    const double nearSkin = nearSkin_;

    if (collisionsEnabled_)
    {
        const int nHist = int(collisions_.binEdges.size()) + 1;
        blockHist_[b].assign(std::size_t(numberOfSpeciesPairs(int(species_.size())))*nHist, 0);
        blockImpacts_[b].clear();
    }
    for (int i = blockParticle_[b]; i < blockParticle_[b + 1]; ++i)
    {
        p.fx[i] = p.fy[i] = p.fz[i] = 0;
        p.tx[i] = p.ty[i] = p.tz[i] = 0;   // sum of n x F_t until finishParticles
    }

    // a short loop without the contact law, the touching pairs compacted in pair order
    // without a branch (over the near list; over all listed pairs when it is rebuilt)
    std::vector<int>& contacts = blockContacts_[b];
    std::vector<ContactSeparation>& separations = blockSeparations_[b];
    std::vector<int>& near = nearPairs_[b];
    const int nListed = blockPair[b + 1] - blockPair[b];
    // sized once per list (no shrinking: growing again would fill it with zeros)
    if (contacts.size() < std::size_t(nListed))
    {
        contacts.resize(std::size_t(nListed));
        separations.resize(std::size_t(nListed));
    }
    int nContacts = 0, nNear = 0;
    if (rebuildNear) near.resize(std::size_t(nListed));
    const int nScan = rebuildNear ? nListed : int(near.size());
    for (int m = 0; m < nScan; ++m)
    {
        const int k = rebuildNear ? blockPair[b] + m : near[m];
        const int i = first[k], j = second[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
        double shiftVx = 0;
        box.minimumImage(dx, dy, dz, shiftVx);
        const double reach = p.radius[i] + p.radius[j];
        const double dist2 = dx*dx + dy*dy + dz*dz;
        const bool touching = dist2 < reach*reach;
        contacts[nContacts] = k;
        separations[nContacts] = {dx, dy, dz, shiftVx};
        nContacts += touching;
        if (rebuildNear)
        {
            const double nearReach = reach + nearSkin;
            near[nNear] = k;
            nNear += dist2 < nearReach*nearReach;
        }
        if (!touching && active_[k])
        {
            // a contact ended: slots and history are cleared once
            active_[k] = 0;
            history_[k].touching = false;
            history_[k].ft[0] = history_[k].ft[1] = history_[k].ft[2] = 0;
            history_[k].xr[0] = history_[k].xr[1] = history_[k].xr[2] = 0;
            pfx_[k] = pfy_[k] = pfz_[k] = 0;
            pcx_[k] = pcy_[k] = pcz_[k] = 0;
        }
    }
    if (rebuildNear) near.resize(std::size_t(nNear));
    return nContacts;
}

SDF_DEM_ALWAYS_INLINE ContactKinematics Simulation::contactKinematics
(
    int i, int j, const ContactSeparation& r
) const
{
    const Particles& p = particles_;
    const double shiftVx = r.shiftVx;
    ContactKinematics kin;
    kin.r[0] = r.dx; kin.r[1] = r.dy; kin.r[2] = r.dz;
    kin.radiusI = p.radius[i]; kin.radiusJ = p.radius[j];
    kin.dvHalf[0] = p.vx[i] - p.vx[j] + shiftVx;
    kin.dvHalf[1] = p.vy[i] - p.vy[j];
    kin.dvHalf[2] = p.vz[i] - p.vz[j];
    kin.dvSync[0] = vSyncX_[i] - vSyncX_[j] + shiftVx;
    kin.dvSync[1] = vSyncY_[i] - vSyncY_[j];
    kin.dvSync[2] = vSyncZ_[i] - vSyncZ_[j];
    kin.wHalfI[0] = p.wx[i]; kin.wHalfI[1] = p.wy[i]; kin.wHalfI[2] = p.wz[i];
    kin.wHalfJ[0] = p.wx[j]; kin.wHalfJ[1] = p.wy[j]; kin.wHalfJ[2] = p.wz[j];
    kin.wSyncI[0] = wSyncX_[i]; kin.wSyncI[1] = wSyncY_[i]; kin.wSyncI[2] = wSyncZ_[i];
    kin.wSyncJ[0] = wSyncX_[j]; kin.wSyncJ[1] = wSyncY_[j]; kin.wSyncJ[2] = wSyncZ_[j];
    return kin;
}

void Simulation::synchronisedVelocities(int begin, int end)
{
    // v^{n+1/2} + dt/2 F^n/m and the spins' likewise, once per particle (a contact reads
    // them for both of its particles)
    const Particles& p = particles_;
    const double h = 0.5*dt_;
    for (int i = begin; i < end; ++i)
    {
        const double im = p.invMass[i], ii = p.invInertia[i];
        vSyncX_[i] = p.vx[i] + h*fPrevX_[i]*im;
        vSyncY_[i] = p.vy[i] + h*fPrevY_[i]*im;
        vSyncZ_[i] = p.vz[i] + h*fPrevZ_[i]*im;
        wSyncX_[i] = p.wx[i] + h*tPrevX_[i]*ii;
        wSyncY_[i] = p.wy[i] + h*tPrevY_[i]*ii;
        wSyncZ_[i] = p.wz[i] + h*tPrevZ_[i]*ii;
    }
}

template<class Law>
void Simulation::gatherContactBatch(int b, int nContacts)
{
    // contactKinematics' values, gathered in short loops (each with few streams, so that
    // their pointers stay in registers)
    const Particles& p = particles_;
    ContactBatch& batch = blockBatches_[b];
    batch.reserveFor(nContacts);
    batch.unbatched.clear();
    batch.unbatchedHistory.clear();
    int* __restrict ci = batch.particleI.data();
    int* __restrict cj = batch.particleJ.data();
    {
        const int* __restrict first = list_.first().data();
        const int* __restrict second = list_.second().data();
        const int* __restrict contacts = blockContacts_[b].data();
        const ContactSeparation* __restrict separations = blockSeparations_[b].data();
        const double* __restrict radius = p.radius.data();
        double* __restrict rx = batch.rx.data();
        double* __restrict ry = batch.ry.data();
        double* __restrict rz = batch.rz.data();
        double* __restrict shift = batch.shiftVx.data();
        double* __restrict radiusI = batch.radiusI.data();
        double* __restrict radiusJ = batch.radiusJ.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const int k = contacts[c];
            const int i = first[k], j = second[k];
            ci[c] = i; cj[c] = j;
            rx[c] = separations[c].dx; ry[c] = separations[c].dy; rz[c] = separations[c].dz;
            if (rx[c]*rx[c] + ry[c]*ry[c] + rz[c]*rz[c] == 0)
            {
                // coincident centres: no normal; left to evaluateContact, its history
                // kept as it is now
                batch.unbatched.push_back(c);
                batch.unbatchedHistory.push_back(history_[k]);
            }
            shift[c] = separations[c].shiftVx;
            radiusI[c] = radius[i]; radiusJ[c] = radius[j];
        }
    }
    // relative velocities: (v_i - v_j) + the Lees-Edwards shift
    const auto relative = [&](const ParticleArray& v, std::vector<double>& out, bool shifted)
    {
        const double* __restrict a = v.data();
        const double* __restrict shift = batch.shiftVx.data();
        double* __restrict o = out.data();
        if (shifted) for (int c = 0; c < nContacts; ++c) o[c] = a[ci[c]] - a[cj[c]] + shift[c];
        else for (int c = 0; c < nContacts; ++c) o[c] = a[ci[c]] - a[cj[c]];
    };
    relative(p.vx, batch.dvHalfX, true);
    relative(p.vy, batch.dvHalfY, false);
    relative(p.vz, batch.dvHalfZ, false);
    relative(vSyncX_, batch.dvSyncX, true);
    relative(vSyncY_, batch.dvSyncY, false);
    relative(vSyncZ_, batch.dvSyncZ, false);
    // spins of both particles
    const auto both = [&](const ParticleArray& w, std::vector<double>& outI, std::vector<double>& outJ)
    {
        const double* __restrict a = w.data();
        double* __restrict oi = outI.data();
        double* __restrict oj = outJ.data();
        for (int c = 0; c < nContacts; ++c) { oi[c] = a[ci[c]]; oj[c] = a[cj[c]]; }
    };
    both(p.wx, batch.wHalfIX, batch.wHalfJX);
    both(p.wy, batch.wHalfIY, batch.wHalfJY);
    both(p.wz, batch.wHalfIZ, batch.wHalfJZ);
    both(wSyncX_, batch.wSyncIX, batch.wSyncJX);
    both(wSyncY_, batch.wSyncIY, batch.wSyncJY);
    both(wSyncZ_, batch.wSyncIZ, batch.wSyncJZ);
    // the pair's constants
    {
        const int* __restrict species = p.species.data();
        double* __restrict k0 = batch.constant0.data();
        double* __restrict k1 = batch.constant1.data();
        double* __restrict k2 = batch.constant2.data();
        double* __restrict k3 = batch.constant3.data();
        double* __restrict mu = batch.friction.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const PairCoefficients& coeffs = law_.pair(species[ci[c]], species[cj[c]]);
            const std::array<double, 4> constants = Law::stiffnessConstants(coeffs);
            k0[c] = constants[0]; k1[c] = constants[1]; k2[c] = constants[2]; k3[c] = constants[3];
            mu[c] = coeffs.friction;
        }
    }
    if (rollingResistance_)
    {
        const int* __restrict species = p.species.data();
        const int* __restrict contacts = blockContacts_[b].data();
        const ContactHistory* __restrict history = history_.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const PairCoefficients& coeffs = law_.pair(species[ci[c]], species[cj[c]]);
            batch.rollingFriction[c] = coeffs.rollingFriction;
            batch.rollingStiffness[c] = coeffs.rollingStiffness;
            batch.rollingDamping[c] = coeffs.rollingDamping;
            batch.effectiveRadius[c] = coeffs.effectiveRadius;
            const ContactHistory& h = history[contacts[c]];
            batch.xrX[c] = h.xr[0]; batch.xrY[c] = h.xr[1]; batch.xrZ[c] = h.xr[2];
        }
    }
    // the history
    {
        const int* __restrict contacts = blockContacts_[b].data();
        const ContactHistory* __restrict history = history_.data();
        double* __restrict touching = batch.touching.data();
        double* __restrict ftx = batch.ftX.data();
        double* __restrict fty = batch.ftY.data();
        double* __restrict ftz = batch.ftZ.data();
        double* __restrict nx = batch.nX.data();
        double* __restrict ny = batch.nY.data();
        double* __restrict nz = batch.nZ.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const ContactHistory& h = history[contacts[c]];
            touching[c] = h.touching ? 1.0 : 0.0;
            ftx[c] = h.ft[0]; fty[c] = h.ft[1]; ftz[c] = h.ft[2];
            nx[c] = h.n[0]; ny[c] = h.n[1]; nz[c] = h.n[2];
        }
    }
}

template<class Law>
double Simulation::evaluateTouchingPairs(int b, int nContacts)
{
    blockCross_[b].clear();
    // the contact law over the block's contacts at once (ContactBatch.hpp: the same bits
    // as contact by contact)
    if constexpr (hasBatchedLoop<Law>)
    {
        if (batchedContacts_) return evaluateContactsInBatch<Law>(b, nContacts);
    }
    return evaluateContactsOneByOne<Law>(b, nContacts);
}

SDF_DEM_ALWAYS_INLINE void Simulation::addContact
(
    int b, int i, int j, const double* force, const double* torqueSumI, const double* torqueSumJ
)
{
    Particles& p = particles_;
    p.fx[i] += force[0]; p.fy[i] += force[1]; p.fz[i] += force[2];
    p.tx[i] += torqueSumI[0]; p.ty[i] += torqueSumI[1]; p.tz[i] += torqueSumI[2];
    if (j < blockParticle_[b + 1])
    {
        p.fx[j] -= force[0]; p.fy[j] -= force[1]; p.fz[j] -= force[2];
        p.tx[j] += torqueSumJ[0]; p.ty[j] += torqueSumJ[1]; p.tz[j] += torqueSumJ[2];
    }
    else
    {
        blockCross_[b].push_back
        ({
            j,
            {force[0], force[1], force[2]},
            {torqueSumJ[0], torqueSumJ[1], torqueSumJ[2]}
        });
    }
}

SDF_DEM_ALWAYS_INLINE void Simulation::recordImpact
(
    int b, int i, int j, double normalVelocity
)
{
    const Particles& p = particles_;
    const int si = p.species[i], sj = p.species[j];
    const int sp = speciesPairIndex(si, sj, int(species_.size()));
    const double e = 0.5*law_.pair(si, sj).effectiveMass*normalVelocity*normalVelocity;
    blockImpacts_[b].push_back({sp, e});
    ++blockHist_[b][sp*(int(collisions_.binEdges.size()) + 1) + collisions_.bin(e)];
}

template<class Law>
double Simulation::evaluateContactsOneByOne(int b, int nContacts)
{
    const Particles& p = particles_;
    const int* first = list_.first().data();
    const int* second = list_.second().data();
    const std::vector<int>& contacts = blockContacts_[b];
    const std::vector<ContactSeparation>& separations = blockSeparations_[b];
    double maxOverlap = 0;
    for (int c = nContacts - 1; c >= 0; --c)
    {
        const int k = contacts[c];
        const int i = first[k], j = second[k];
        active_[k] = 1;
        const PairCoefficients& coeffs = law_.pair(p.species[i], p.species[j]);
        const ContactResult res = evaluateContact<Law>
        (
            coeffs, contactKinematics(i, j, separations[c]), history_[k], dt_
        );
        pfx_[k] = res.force[0]; pfy_[k] = res.force[1]; pfz_[k] = res.force[2];
        pcx_[k] = res.nCrossFt[0]; pcy_[k] = res.nCrossFt[1]; pcz_[k] = res.nCrossFt[2];
        addContact(b, i, j, res.force, res.torqueSumI, res.torqueSumJ);
        const double frac = res.overlap/(2*std::min(p.radius[i], p.radius[j]));
        if (frac > maxOverlap) maxOverlap = frac;
        if (collisionsEnabled_ && res.newContact) recordImpact(b, i, j, res.normalVelocity);
    }
    return maxOverlap;
}

template<class Law>
double Simulation::evaluateContactsInBatch(int b, int nContacts)
{
    // in short loops, each with few streams (their pointers stay in registers)
    gatherContactBatch<Law>(b, nContacts);
    ContactBatch& batch = blockBatches_[b];
    evaluateContactBatch(Law::model, rollingResistance_, batch, nContacts, dt_);
    const int* __restrict contacts = blockContacts_[b].data();
    // the history (a pair is listed once)
    {
        const double* __restrict touching = batch.touching.data();
        const double* __restrict ftx = batch.ftX.data();
        const double* __restrict fty = batch.ftY.data();
        const double* __restrict ftz = batch.ftZ.data();
        const double* __restrict nx = batch.nX.data();
        const double* __restrict ny = batch.nY.data();
        const double* __restrict nz = batch.nZ.data();
        unsigned char* __restrict active = active_.data();
        ContactHistory* __restrict history = history_.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const int k = contacts[c];
            active[k] = 1;
            ContactHistory& h = history[k];
            if (touching[c] == 0) h.xr[0] = h.xr[1] = h.xr[2] = 0;   // (rolling: below)
            h.ft[0] = ftx[c]; h.ft[1] = fty[c]; h.ft[2] = ftz[c];
            h.n[0] = nx[c]; h.n[1] = ny[c]; h.n[2] = nz[c];
            h.touching = true;
        }
    }
    if (rollingResistance_)
    {
        for (int c = 0; c < nContacts; ++c)
        {
            ContactHistory& h = history_[contacts[c]];
            h.xr[0] = batch.xrX[c]; h.xr[1] = batch.xrY[c]; h.xr[2] = batch.xrZ[c];
        }
    }
    // what the batch does not take: contact by contact, over the batch's results
    for (std::size_t u = 0; u < batch.unbatched.size(); ++u)
    {
        const int c = batch.unbatched[u];
        const int k = contacts[c];
        const int i = batch.particleI[c], j = batch.particleJ[c];
        ContactHistory& h = history_[k];
        h = batch.unbatchedHistory[u];
        const ContactResult res = evaluateContact<Law>
        (
            law_.pair(particles_.species[i], particles_.species[j]),
            contactKinematics(i, j, blockSeparations_[b][c]), h, dt_
        );
        batch.forceX[c] = res.force[0]; batch.forceY[c] = res.force[1]; batch.forceZ[c] = res.force[2];
        batch.nCrossFtX[c] = res.nCrossFt[0];
        batch.nCrossFtY[c] = res.nCrossFt[1];
        batch.nCrossFtZ[c] = res.nCrossFt[2];
        batch.overlapFraction[c] = res.overlap/(2*std::min(particles_.radius[i], particles_.radius[j]));
        batch.normalVelocity[c] = res.normalVelocity;
        batch.touching[c] = res.newContact ? 0.0 : 1.0;   // from here: "not a new contact"
        batch.torqueSumIX[c] = res.torqueSumI[0];
        batch.torqueSumIY[c] = res.torqueSumI[1];
        batch.torqueSumIZ[c] = res.torqueSumI[2];
        batch.torqueSumJX[c] = res.torqueSumJ[0];
        batch.torqueSumJY[c] = res.torqueSumJ[1];
        batch.torqueSumJZ[c] = res.torqueSumJ[2];
    }
    // the slots the stress sampling reads
    {
        const double* __restrict fx = batch.forceX.data();
        const double* __restrict fy = batch.forceY.data();
        const double* __restrict fz = batch.forceZ.data();
        const double* __restrict cx = batch.nCrossFtX.data();
        const double* __restrict cy = batch.nCrossFtY.data();
        const double* __restrict cz = batch.nCrossFtZ.data();
        for (int c = 0; c < nContacts; ++c)
        {
            const int k = contacts[c];
            pfx_[k] = fx[c]; pfy_[k] = fy[c]; pfz_[k] = fz[c];
            pcx_[k] = cx[c]; pcy_[k] = cy[c]; pcz_[k] = cz[c];
        }
    }
    // the particles' sums, in decreasing pair order
    {
        const int* __restrict ci = batch.particleI.data();
        const int* __restrict cj = batch.particleJ.data();
        const double* __restrict fx = batch.forceX.data();
        const double* __restrict fy = batch.forceY.data();
        const double* __restrict fz = batch.forceZ.data();
        // with the rolling couple i's and j's torque sums differ; without it both are n x F_t
        const bool rolling = rollingResistance_;
        const double* __restrict tix = rolling ? batch.torqueSumIX.data() : batch.nCrossFtX.data();
        const double* __restrict tiy = rolling ? batch.torqueSumIY.data() : batch.nCrossFtY.data();
        const double* __restrict tiz = rolling ? batch.torqueSumIZ.data() : batch.nCrossFtZ.data();
        const double* __restrict tjx = rolling ? batch.torqueSumJX.data() : batch.nCrossFtX.data();
        const double* __restrict tjy = rolling ? batch.torqueSumJY.data() : batch.nCrossFtY.data();
        const double* __restrict tjz = rolling ? batch.torqueSumJZ.data() : batch.nCrossFtZ.data();
        for (int c = nContacts - 1; c >= 0; --c)
        {
            const double force[3] = {fx[c], fy[c], fz[c]};
            const double torqueSumI[3] = {tix[c], tiy[c], tiz[c]};
            const double torqueSumJ[3] = {tjx[c], tjy[c], tjz[c]};
            addContact(b, ci[c], cj[c], force, torqueSumI, torqueSumJ);
        }
    }
    double maxOverlap = 0;
    {
        const double* __restrict fraction = batch.overlapFraction.data();
        for (int c = 0; c < nContacts; ++c) maxOverlap = std::max(maxOverlap, fraction[c]);
    }
    if (collisionsEnabled_)
    {
        for (int c = nContacts - 1; c >= 0; --c)
        {
            if (batch.touching[c] == 0)
            {
                recordImpact(b, batch.particleI[c], batch.particleJ[c], batch.normalVelocity[c]);
            }
        }
    }
    return maxOverlap;
}

void Simulation::addCrossContacts(int begin, int end)
{
    // in decreasing pair order: the higher blocks' lists first
    Particles& p = particles_;
    const int nBlocks = int(blockParticle_.size()) - 1;
    for (int lower = nBlocks - 2; lower >= 0; --lower)
    {
        if (blockParticle_[lower + 1] >= end) continue;   // its j lie below this range
        for (const CrossContact& c : blockCross_[lower])
        {
            const int j = c.j;
            if (j < begin || j >= end) continue;
            p.fx[j] -= c.force[0]; p.fy[j] -= c.force[1]; p.fz[j] -= c.force[2];
            p.tx[j] += c.torqueSum[0]; p.ty[j] += c.torqueSum[1]; p.tz[j] += c.torqueSum[2];
        }
    }
}

void Simulation::finishParticles(int begin, int end, bool kick, bool finishSums)
{
    Particles& p = particles_;
    if (!kick)
    {
        for (int i = begin; i < end; ++i)
        {
            const double r = p.radius[i];
            p.tx[i] = -r*p.tx[i]; p.ty[i] = -r*p.ty[i]; p.tz[i] = -r*p.tz[i];
        }
        return;
    }
    // one pass: torque, then the kick
    const double h = 0.5*dt_;
    for (int i = begin; i < end; ++i)
    {
        const double r = p.radius[i];
        p.tx[i] = -r*p.tx[i]; p.ty[i] = -r*p.ty[i]; p.tz[i] = -r*p.tz[i];
        const double im = p.invMass[i], ii = p.invInertia[i];
        p.vx[i] += h*p.fx[i]*im; p.vy[i] += h*p.fy[i]*im; p.vz[i] += h*p.fz[i]*im;
        p.wx[i] += h*p.tx[i]*ii; p.wy[i] += h*p.ty[i]*ii; p.wz[i] += h*p.tz[i]*ii;
    }
    // the driving's sums over the final velocities while they are in cache
    if (finishSums) driving_->finishRange(p, begin, end);
}

void Simulation::gatherCollisions()
{
    // impact energies summed in pair order (blocks in order, each block's records
    // reversed): the same sums whatever the threads and block boundaries
    const int nBlocks = int(blockParticle_.size()) - 1;
    const int nSpeciesPairs = numberOfSpeciesPairs(int(species_.size()));
    const int nHist = int(collisions_.binEdges.size()) + 1;
    for (int b = 0; b < nBlocks; ++b)
    {
        const std::vector<CollisionRecord>& impacts = blockImpacts_[b];
        for (auto r = impacts.rbegin(); r != impacts.rend(); ++r)
        {
            ++collisions_.counts[r->speciesPair];
            collisions_.energySum[r->speciesPair] += r->energy;
        }
        for (int sp = 0; sp < nSpeciesPairs; ++sp)
        {
            for (int bin = 0; bin < nHist; ++bin)
            {
                collisions_.histogram[sp][bin] += blockHist_[b][sp*nHist + bin];
            }
        }
    }
}

void Simulation::overlapFailure(double maxOverlap) const
{
    // diagnosis: find the worst pair (serial rescan, only on failure)
    const Particles& p = particles_;
    const std::vector<int>& first = list_.first();
    const std::vector<int>& second = list_.second();
    int worstI = -1, worstJ = -1;
    double worst = 0;
    for (std::size_t k = 0; k < list_.size(); ++k)
    {
        const int i = first[k], j = second[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
        box_.minimumImage(dx, dy, dz, dvx);
        const double ov = p.radius[i] + p.radius[j] - std::sqrt(dx*dx + dy*dy + dz*dz);
        const double frac = ov/(2*std::min(p.radius[i], p.radius[j]));
        if (frac > worst) { worst = frac; worstI = i; worstJ = j; }
    }
    std::ostringstream msg;
    msg << "unstable run stopped at step " << stepCount_ << " (t = " << time_
        << " s): overlap " << 100*maxOverlap << " % of the smaller diameter exceeds "
        << 100*settings_.maxOverlapFraction << " %";
    if (worstI >= 0)
    {
        msg << " (particles " << worstI << " and " << worstJ << ")";
    }
    msg << "; the contacts are too soft for the impact speeds or dt = " << dt_
        << " s is too large (recommended maximum " << law_.maximumTimeStep() << " s)";
    throw std::runtime_error(msg.str());
}

} // namespace sdf::dem

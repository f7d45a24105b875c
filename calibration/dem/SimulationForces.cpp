// The force pass of Simulation: contact forces of all listed pairs (one instantiation per
// contact law, picked once per pass), walls, the finish of the step's velocities, collision
// statistics and the overlap check.
//
// Reproducibility. Block b owns particles [P_b, P_b+1) and the pairs whose first particle
// it owns; pairs are (i, j)-ordered with i < j, so block b's pairs read particles >= P_b
// only. Every particle sums its incident pairs in DEcreasing pair order, starting from zero,
// whatever the blocks and threads (bitwise reproducible, independent of the thread count
// and of the block boundaries):
//  - a block evaluates its contacts from the last to the first and adds each to i and,
//    when j is its own, to j: its own pairs are the highest-numbered pairs of all its
//    particles, so they come first;
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
    // v^{n+1/2} + dt/2 F^n/m formed from them, pair by pair (no per-particle arrays written
    // in the drift). Without the half kick (a refresh) they are the current velocities.
    {
        Particles& q = particles_;
        q.fx.swap(fPrevX_); q.fy.swap(fPrevY_); q.fz.swap(fPrevZ_);
        q.tx.swap(tPrevX_); q.ty.swap(tPrevY_); q.tz.swap(tPrevZ_);
        if (q.fx.size() != q.size())
        {
            for (auto* a : {&q.fx, &q.fy, &q.fz, &q.tx, &q.ty, &q.tz}) a->assign(q.size(), 0.0);
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

template<class Law>
double Simulation::evaluateTouchingPairs(int b, int nContacts)
{
    Particles& p = particles_;
    const int* first = list_.first().data();
    const int* second = list_.second().data();
    const int nSpecies = int(species_.size());
    const double dt = dt_;
    const double h = 0.5*dt_;
    const double* fPrevX = fPrevX_.data();
    const double* fPrevY = fPrevY_.data();
    const double* fPrevZ = fPrevZ_.data();
    const double* tPrevX = tPrevX_.data();
    const double* tPrevY = tPrevY_.data();
    const double* tPrevZ = tPrevZ_.data();
    const int nHist = collisionsEnabled_ ? int(collisions_.binEdges.size()) + 1 : 0;
    std::vector<long>& hist = blockHist_[b];
    std::vector<CollisionRecord>& impacts = blockImpacts_[b];
    const std::vector<int>& contacts = blockContacts_[b];
    const std::vector<ContactSeparation>& separations = blockSeparations_[b];
    const int ownEnd = blockParticle_[b + 1];
    std::vector<CrossContact>& cross = blockCross_[b];
    cross.clear();
    double maxOverlap = 0;
    for (int c = nContacts - 1; c >= 0; --c)
    {
        const int k = contacts[c];
        const int i = first[k], j = second[k];
        const ContactSeparation& r = separations[c];
        const double shiftVx = r.shiftVx;
        const double ri = p.radius[i], rj = p.radius[j];
        active_[k] = 1;
        ContactKinematics kin;
        kin.r[0] = r.dx; kin.r[1] = r.dy; kin.r[2] = r.dz;
        kin.radiusI = ri; kin.radiusJ = rj;
        kin.dvHalf[0] = p.vx[i] - p.vx[j] + shiftVx;
        kin.dvHalf[1] = p.vy[i] - p.vy[j];
        kin.dvHalf[2] = p.vz[i] - p.vz[j];
        const double imi = p.invMass[i], imj = p.invMass[j];
        const double iii = p.invInertia[i], iij = p.invInertia[j];
        kin.dvSync[0] = (p.vx[i] + h*fPrevX[i]*imi) - (p.vx[j] + h*fPrevX[j]*imj) + shiftVx;
        kin.dvSync[1] = (p.vy[i] + h*fPrevY[i]*imi) - (p.vy[j] + h*fPrevY[j]*imj);
        kin.dvSync[2] = (p.vz[i] + h*fPrevZ[i]*imi) - (p.vz[j] + h*fPrevZ[j]*imj);
        kin.wHalfI[0] = p.wx[i]; kin.wHalfI[1] = p.wy[i]; kin.wHalfI[2] = p.wz[i];
        kin.wHalfJ[0] = p.wx[j]; kin.wHalfJ[1] = p.wy[j]; kin.wHalfJ[2] = p.wz[j];
        kin.wSyncI[0] = p.wx[i] + h*tPrevX[i]*iii;
        kin.wSyncI[1] = p.wy[i] + h*tPrevY[i]*iii;
        kin.wSyncI[2] = p.wz[i] + h*tPrevZ[i]*iii;
        kin.wSyncJ[0] = p.wx[j] + h*tPrevX[j]*iij;
        kin.wSyncJ[1] = p.wy[j] + h*tPrevY[j]*iij;
        kin.wSyncJ[2] = p.wz[j] + h*tPrevZ[j]*iij;

        const int si = p.species[i], sj = p.species[j];
        const PairCoefficients& coeffs = law_.pair(si, sj);
        const ContactResult res = evaluateContact<Law>(coeffs, kin, history_[k], dt);

        pfx_[k] = res.force[0]; pfy_[k] = res.force[1]; pfz_[k] = res.force[2];
        pcx_[k] = res.nCrossFt[0]; pcy_[k] = res.nCrossFt[1]; pcz_[k] = res.nCrossFt[2];
        p.fx[i] += res.force[0]; p.fy[i] += res.force[1]; p.fz[i] += res.force[2];
        p.tx[i] += res.torqueSumI[0]; p.ty[i] += res.torqueSumI[1]; p.tz[i] += res.torqueSumI[2];
        if (j < ownEnd)
        {
            p.fx[j] -= res.force[0]; p.fy[j] -= res.force[1]; p.fz[j] -= res.force[2];
            p.tx[j] += res.torqueSumJ[0]; p.ty[j] += res.torqueSumJ[1]; p.tz[j] += res.torqueSumJ[2];
        }
        else
        {
            cross.push_back
            ({
                j,
                {res.force[0], res.force[1], res.force[2]},
                {res.torqueSumJ[0], res.torqueSumJ[1], res.torqueSumJ[2]}
            });
        }

        const double frac = res.overlap/(2*std::min(ri, rj));
        if (frac > maxOverlap) maxOverlap = frac;

        if (collisionsEnabled_ && res.newContact)
        {
            const int sp = speciesPairIndex(si, sj, nSpecies);
            const double e = 0.5*coeffs.effectiveMass*res.normalVelocity*res.normalVelocity;
            impacts.push_back({sp, e});
            ++hist[sp*nHist + collisions_.bin(e)];
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

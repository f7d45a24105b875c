// The neighbour list of a Simulation: when it expires, its rebuild (with the spatial
// renumbering and the contact histories carried over), the particle ids, and the split of
// particles and pairs into one block per thread.

#include "Renumbering.hpp"
#include "Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sdf::dem
{

bool Simulation::neighbourListExpired() const
{
    const std::size_t n = particles_.size();
    double max2 = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double dx = particles_.ux[i] - uBuildX_[i];
        const double dy = particles_.uy[i] - uBuildY_[i];
        const double dz = particles_.uz[i] - uBuildZ_[i];
        max2 = std::max(max2, dx*dx + dy*dy + dz*dz);
    }
    // relative displacement of any pair: two peculiar displacements plus the relative
    // streaming across at most one cutoff in y
    const double shearDrift = (std::abs(box_.shearRate)*timeSinceBuild_ + dilationSinceBuild_)
                             *(list_.cutoff() + skin_);
    return 2*std::sqrt(max2) + shearDrift + 2*radiusGrowthSinceBuild_ >= skin_;
}

void Simulation::indexIds()
{
    const int n = int(particles_.size());
    indexOfId_.assign(std::size_t(n), -1);
    for (int i = 0; i < n; ++i)
    {
        const int id = particles_.id[i];
        if (id < 0 || id >= n || indexOfId_[id] >= 0)
        {
            throw std::invalid_argument
            (
                "particle ids must be a permutation of 0.." + std::to_string(n - 1)
              + " (particle " + std::to_string(i) + " has id " + std::to_string(id) + ")"
            );
        }
        indexOfId_[id] = i;
    }
}

void Simulation::rebuildNeighbourList()
{
    const double start = wallSeconds();
    // the contact histories to carry over: those of touching pairs
    std::vector<CarriedContact> carried =
        touchingContacts(list_.first(), list_.second(), history_);
    if (renumberPending_)
    {
        renumberPending_ = false;
        const std::vector<int> newIndex = renumberInY(particles_);
        indexIds();
        renumberContacts(carried, newIndex);
    }

    list_.build(particles_, box_, skin_, nThreads_);

    // carry the histories over: both lists are sorted by (i, j)
    const std::size_t nPairs = list_.size();
    history_ = carryHistories(carried, list_.first(), list_.second());
    for (auto* a : {&pfx_, &pfy_, &pfz_, &pcx_, &pcy_, &pcz_}) a->assign(nPairs, 0.0);
    // the pair loop that follows every rebuild fills the slots of touching pairs
    active_.assign(nPairs, 0);
    for (std::size_t k = 0; k < nPairs; ++k) active_[k] = history_[k].touching ? 1 : 0;
    partitionWork();
    nearValid_ = false;
    uBuildX_ = particles_.ux;
    uBuildY_ = particles_.uy;
    uBuildZ_ = particles_.uz;
    timeSinceBuild_ = 0;
    radiusGrowthSinceBuild_ = 0;
    dilationSinceBuild_ = 0;
    listValid_ = true;
    ++rebuildTimings_.count;
    rebuildTimings_.wallSeconds += wallSeconds() - start;
}

void Simulation::partitionWork()
{
    const int n = int(particles_.size());
    const int nPairs = int(list_.size());
    const int nBlocks = std::max(1, nThreads_);

    // Each phase of a step (drift, force pass up to the barrier, cross contacts + finish
    // after it) splits the particles into one contiguous range per thread. Work model of
    // the force pass: a listed pair (nearly all of them are not touching: distance test
    // only) costs 1, a particle about 0.5 (measured on the sheared N 3000 cell); in the
    // other phases every particle costs 1. The shares start equal and then follow each phase's
    // measured busy times since the last partition, halfway at each list rebuild: the
    // higher blocks add the lower blocks' cross contacts, and their particles' cache lines
    // are shared with the block below, so equal work is not equal time. The boundaries do
    // not change any result: every particle sums its pairs in decreasing pair order
    // whatever the blocks (see computeForces).
    constexpr double particleCost = 0.5;
    if (int(forceBalance_.share.size()) != nBlocks)
    {
        forceBalance_.reset(nBlocks);
        driftBalance_.reset(nBlocks);
        finishBalance_.reset(nBlocks);
    }
    else
    {
        forceBalance_.update();
        driftBalance_.update();
        finishBalance_.update();
    }
    // ranges start at cache-line multiples (no line of a particle array written by two
    // threads in one phase), the finish's at whole chunks of the driving's sums
    static_assert(Driving::finishChunk % particlesPerCacheLine == 0);
    driftBegin_ = driftBalance_.splitParticles(n, particlesPerCacheLine);
    finishBegin_ = finishBalance_.splitParticles(n, Driving::finishChunk);

    blockParticle_.assign(nBlocks + 1, n);
    blockPair_.assign(nBlocks + 1, nPairs);
    std::vector<double>& work = forceBalance_.work;
    work.assign(nBlocks, 0.0);
    blockParticle_[0] = 0;
    blockPair_[0] = 0;
    {
        const std::vector<int>& first = list_.first();
        const double total = nPairs + particleCost*n;
        double done = 0, boundary = forceBalance_.share[0]*total;
        int k = 0, block = 0;
        for (int i = 0; i < n; ++i)
        {
            while (done >= boundary && block < nBlocks - 1 && i % particlesPerCacheLine == 0)
            {
                ++block;
                blockParticle_[block] = i;
                blockPair_[block] = k;
                boundary += forceBalance_.share[block]*total;
            }
            const int k0 = k;
            while (k < nPairs && first[k] == i) ++k;
            const double w = (k - k0) + particleCost;
            done += w;
            work[block] += w;
        }
    }
    blockHist_.resize(nBlocks);
    blockImpacts_.resize(nBlocks);
    blockContacts_.resize(nBlocks);
    blockSeparations_.resize(nBlocks);
    blockBatches_.resize(nBlocks);
    blockCross_.resize(nBlocks);
    nearPairs_.resize(nBlocks);
}

} // namespace sdf::dem

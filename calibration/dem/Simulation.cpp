#include "Simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

namespace
{

//- Wall-clock seconds for the busy times that balance the force-pass blocks.
double wallSeconds()
{
#ifdef _OPENMP
    return omp_get_wtime();
#else
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
#endif
}

//- Adds the thermostat's sums over particles [begin, end) to sum: mass, mass x velocity,
//  velocity, |velocity|^2 (Simulation::ThermostatSum).
void addThermostatSums(const Particles& p, int begin, int end, double* sum)
{
    for (int i = begin; i < end; ++i)
    {
        const double m = p.mass[i], vx = p.vx[i], vy = p.vy[i], vz = p.vz[i];
        sum[0] += m; sum[1] += m*vx; sum[2] += m*vy; sum[3] += m*vz;
        sum[4] += vx; sum[5] += vy; sum[6] += vz; sum[7] += vx*vx + vy*vy + vz*vz;
    }
}

//- The first half of a velocity Verlet step for particles [begin, end): half kick with
//  their forces F^n, drift, Lees-Edwards wrap (box: with the offset at the new time); their
//  peculiar displacements in this step and since the list build (uBuild) raise maxStep2
//  and maxDisp2.
void driftRange
(
    Particles& p, int begin, int end, double dt, const PeriodicBox& boxNow,
    const ParticleArray& uBuildXs, const ParticleArray& uBuildYs, const ParticleArray& uBuildZs,
    double& maxDisp2, double& maxStep2
)
{
    // locals and restrict pointers: the particle stores cannot alias the constants or the
    // maxima, so they stay in registers
    const PeriodicBox box = boxNow;
    const double h = 0.5*dt, shearRate = box.shearRate, yMid = 0.5*box.ly;
    double disp2Max = maxDisp2, step2Max = maxStep2;
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
    const double* __restrict uBuildX = uBuildXs.data();
    const double* __restrict uBuildY = uBuildYs.data();
    const double* __restrict uBuildZ = uBuildZs.data();
    for (int i = begin; i < end; ++i)
    {
        const double im = invMass[i], ii = invInertia[i];
        const double fxm = h*fx[i]*im, fym = h*fy[i]*im, fzm = h*fz[i]*im;
        const double txi = h*tx[i]*ii, tyi = h*ty[i]*ii, tzi = h*tz[i]*ii;
        vx[i] += fxm; vy[i] += fym; vz[i] += fzm;
        wx[i] += txi; wy[i] += tyi; wz[i] += tzi;

        const double ddx = dt*vx[i], ddy = dt*vy[i], ddz = dt*vz[i];
        const double peculiarDdx = ddx - dt*shearRate*(y[i] - yMid);
        const double step2 = peculiarDdx*peculiarDdx + ddy*ddy + ddz*ddz;
        if (step2 > step2Max) step2Max = step2;
        // u: peculiar (x without the streaming), so u - u at the list build is the
        // displacement the Verlet criterion needs (no separate array written)
        ux[i] += peculiarDdx; uy[i] += ddy; uz[i] += ddz;
        const double ex = ux[i] - uBuildX[i], ey = uy[i] - uBuildY[i], ez = uz[i] - uBuildZ[i];
        const double d2 = ex*ex + ey*ey + ez*ez;
        if (d2 > disp2Max) disp2Max = d2;
        x[i] += ddx; y[i] += ddy; z[i] += ddz;

        box.wrap(x[i], y[i], z[i], vx[i]);
    }
    maxDisp2 = disp2Max;
    maxStep2 = step2Max;
}

} // namespace

CellMode cellModeFromName(const std::string& name)
{
    if (name == "nve") return CellMode::nve;
    if (name == "thermostatted" || name == "driven") return CellMode::thermostatted;
    if (name == "leesEdwards" || name == "shear") return CellMode::leesEdwards;
    throw std::invalid_argument
    (
        "cell mode '" + name + "' unknown; valid: nve, thermostatted, leesEdwards"
    );
}

std::string cellModeName(CellMode mode)
{
    switch (mode)
    {
        case CellMode::nve: return "nve";
        case CellMode::thermostatted: return "thermostatted";
        case CellMode::leesEdwards: return "leesEdwards";
    }
    return "unknown";
}

// ---------------------------------------------------------------- StressSplit

Eigen::Matrix3d StressSplit::speciesStress(int s) const
{
    return kinetic[s] + configurational[speciesPairIndex(s, s, nSpecies)];
}

Eigen::Matrix3d StressSplit::crossStress(int s, int t) const
{
    return configurational[speciesPairIndex(s, t, nSpecies)];
}

Eigen::Matrix3d StressSplit::sum() const
{
    Eigen::Matrix3d total = Eigen::Matrix3d::Zero();
    for (int s = 0; s < nSpecies; ++s) total += speciesStress(s);
    for (int s = 0; s < nSpecies; ++s)
    {
        for (int t = s + 1; t < nSpecies; ++t) total += crossStress(s, t);
    }
    return total;
}

// ---------------------------------------------------------------- CollisionStatistics

void CollisionStatistics::reset(int n, double eMin, double eMax, int nBins)
{
    if (!(eMin > 0 && eMax > eMin && nBins > 0))
    {
        throw std::invalid_argument("collision histogram: need 0 < eMin < eMax and nBins > 0");
    }
    nSpecies = n;
    binEdges.resize(nBins + 1);
    for (int b = 0; b <= nBins; ++b)
    {
        binEdges[b] = eMin*std::pow(eMax/eMin, double(b)/nBins);
    }
    clearCounts();
}

void CollisionStatistics::clearCounts()
{
    const int nPairs = numberOfSpeciesPairs(nSpecies);
    counts.assign(nPairs, 0);
    energySum.assign(nPairs, 0.0);
    histogram.assign(nPairs, std::vector<long>(binEdges.empty() ? 0 : binEdges.size() + 1, 0));
    elapsedTime = 0;
}

double CollisionStatistics::frequencyPerParticle
(
    int s, int t, const std::vector<int>& speciesCounts
) const
{
    if (elapsedTime <= 0 || speciesCounts[s] == 0) return 0;
    const double c = double(counts[speciesPairIndex(s, t, nSpecies)]);
    // a collision within species s involves two particles of s
    const double involved = (s == t) ? 2*c : c;
    return involved/(elapsedTime*speciesCounts[s]);
}

// ---------------------------------------------------------------- Simulation

Simulation::Simulation
(
    std::vector<Species> species,
    SimulationSettings settings,
    Particles particles,
    PeriodicBox box
)
:
    species_(std::move(species)),
    settings_(settings),
    law_(settings_.contact, species_),
    particles_(std::move(particles)),
    box_(box)
{
    const int n = int(particles_.size());
    const int nSpecies = int(species_.size());
    for (int i = 0; i < n; ++i)
    {
        if (particles_.species[i] < 0 || particles_.species[i] >= nSpecies)
        {
            throw std::invalid_argument("particle " + std::to_string(i) + ": species id out of range");
        }
        if (!(particles_.radius[i] > 0))
        {
            throw std::invalid_argument("particle " + std::to_string(i) + ": radius must be positive");
        }
    }
    if (!(box_.lx > 0 && box_.ly > 0 && box_.lz > 0))
    {
        throw std::invalid_argument("box lengths must be positive");
    }

    const double dtMax = law_.maximumTimeStep();
    dt_ = settings_.timeStep > 0 ? settings_.timeStep : 0.5*dtMax;
    if (!(settings_.timeStep >= 0) || !std::isfinite(settings_.timeStep))
    {
        throw std::invalid_argument("timeStep must be positive");
    }
    if (settings_.checkTimeStep && dt_ > dtMax*(1 + 1e-12))
    {
        std::ostringstream msg;
        msg << "timeStep dt = " << dt_ << " s exceeds the recommended maximum "
            << dtMax << " s ("
            << (law_.model() == ContactModel::linearSpringDashpot
                ? "t_c/50 of the lightest pair, t_c = " + std::to_string(law_.contactDuration(1.0)) + " s"
                : "0.2 x Rayleigh time of the smallest species")
            << ")";
        throw std::invalid_argument(msg.str());
    }

    if (settings_.mode == CellMode::thermostatted && !(settings_.targetTemperature > 0))
    {
        throw std::invalid_argument("thermostatted cell: targetTemperature must be positive");
    }
    if (settings_.mode == CellMode::leesEdwards && !std::isfinite(settings_.shearRate))
    {
        throw std::invalid_argument("leesEdwards cell: shearRate must be finite");
    }
    box_.shearRate = settings_.mode == CellMode::leesEdwards ? settings_.shearRate : 0.0;
    if (settings_.thermostatTime <= 0) settings_.thermostatTime = 50*dt_;

    double dMin = species_[0].diameter;
    for (const Species& s : species_) dMin = std::min(dMin, s.diameter);
    skin_ = settings_.skin >= 0 ? settings_.skin : 0.3*dMin;
    // near-list skin: on the sheared N 3000 cell of benchmarks/demVsLammps (skin 0.3 d)
    // 0.05-0.1 of the skin was fastest (at 0.1: rebuilt every ~27 steps, holding ~1/3 of
    // the listed pairs); 0.2 of it was 4 % slower, 0.5 of it 12 %
    nearSkin_ = 0.1*skin_;

#ifdef _OPENMP
    nThreads_ = settings_.threads > 0 ? settings_.threads : omp_get_max_threads();
#else
    nThreads_ = 1;
#endif

    for (int i = 0; i < n; ++i)
    {
        box_.wrap(particles_.x[i], particles_.y[i], particles_.z[i], particles_.vx[i]);
    }
    // ids: the particles' indices now
    particles_.id.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) particles_.id[i] = i;
    indexIds();
    for (auto* a : {&fPrevX_, &fPrevY_, &fPrevZ_, &tPrevX_, &tPrevY_, &tPrevZ_, &uBuildX_, &uBuildY_, &uBuildZ_})
    {
        a->assign(n, 0.0);
    }

    refreshForces();

    // reference for the blow-up check
    double massSum = 0, vMax2 = 0;
    for (int i = 0; i < n; ++i)
    {
        massSum += particles_.mass[i];
        vMax2 = std::max(vMax2, fluctuatingVelocity(i).squaredNorm());
    }
    const double shearScale = box_.shearRate*box_.ly;
    referenceEnergy_ = std::max
    ({
        translationalKineticEnergy() + rotationalKineticEnergy(),
        0.5*massSum*settings_.targetTemperature,
        0.5*massSum*shearScale*shearScale,
        0.5*massSum*vMax2,
        1e-300
    });
}

std::vector<int> Simulation::speciesCounts() const
{
    std::vector<int> counts(species_.size(), 0);
    for (const int s : particles_.species) ++counts[s];
    return counts;
}

void Simulation::addWall(const Wall& wall)
{
    Wall w = wall;
    w.normal.normalize();
    walls_.push_back(w);
    wallHistory_.emplace_back(particles_.size());
    refreshForces();
}

SimulationState Simulation::exportState() const
{
    SimulationState st;
    st.particles = particles_;
    st.time = time_;
    st.stepCount = stepCount_;
    st.shearOffset = box_.offset;
    st.pairFirst = list_.first();
    st.pairSecond = list_.second();
    st.history = history_;
    const std::size_t n = list_.size();
    st.pairForce.resize(3*n);
    st.pairNCrossFt.resize(3*n);
    for (std::size_t k = 0; k < n; ++k)
    {
        st.pairForce[3*k] = pfx_[k]; st.pairForce[3*k + 1] = pfy_[k]; st.pairForce[3*k + 2] = pfz_[k];
        st.pairNCrossFt[3*k] = pcx_[k]; st.pairNCrossFt[3*k + 1] = pcy_[k]; st.pairNCrossFt[3*k + 2] = pcz_[k];
    }
    return st;
}

void Simulation::importState(const SimulationState& st)
{
    const std::size_t n = st.particles.size();
    const std::size_t nPairs = st.pairFirst.size();
    if (n != particles_.size())
    {
        throw std::invalid_argument
        (
            "checkpoint holds " + std::to_string(n) + " particles, the simulation "
          + std::to_string(particles_.size())
        );
    }
    if (st.pairSecond.size() != nPairs || st.history.size() != nPairs
     || st.pairForce.size() != 3*nPairs || st.pairNCrossFt.size() != 3*nPairs)
    {
        throw std::invalid_argument("checkpoint: inconsistent pair arrays");
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        if (st.particles.species[i] < 0 || st.particles.species[i] >= int(species_.size()))
        {
            throw std::invalid_argument("checkpoint: species id out of range");
        }
    }
    particles_ = st.particles;
    if (particles_.id.size() != n)
    {
        // a checkpoint without ids (written before they existed): never renumbered
        particles_.id.resize(n);
        for (std::size_t i = 0; i < n; ++i) particles_.id[i] = int(i);
    }
    indexIds();
    time_ = st.time;
    stepCount_ = st.stepCount;
    box_.offset = st.shearOffset;
    list_.restorePairs(st.pairFirst, st.pairSecond);
    history_ = st.history;
    for (auto* a : {&pfx_, &pfy_, &pfz_, &pcx_, &pcy_, &pcz_}) a->assign(nPairs, 0.0);
    active_.assign(nPairs, 0);
    for (std::size_t k = 0; k < nPairs; ++k)
    {
        active_[k] = history_[k].touching ? 1 : 0;
        pfx_[k] = st.pairForce[3*k]; pfy_[k] = st.pairForce[3*k + 1]; pfz_[k] = st.pairForce[3*k + 2];
        pcx_[k] = st.pairNCrossFt[3*k]; pcy_[k] = st.pairNCrossFt[3*k + 1]; pcz_[k] = st.pairNCrossFt[3*k + 2];
    }
    for (auto* a : {&fPrevX_, &fPrevY_, &fPrevZ_, &tPrevX_, &tPrevY_, &tPrevZ_, &uBuildX_, &uBuildY_, &uBuildZ_})
    {
        a->assign(n, 0.0);
    }
    for (auto& w : wallHistory_) w.assign(n, ContactHistory());
    timeSinceBuild_ = 0;
    radiusGrowthSinceBuild_ = 0;
    // forces F^n come from the checkpoint; the list is rebuilt (histories carried over)
    // at the next force evaluation
    listValid_ = false;
}

void Simulation::refreshForces()
{
    // halfKick false: the synchronised velocities are the current ones
    computeForces();
}

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
    const double shearDrift = std::abs(box_.shearRate)*timeSinceBuild_*(list_.cutoff() + skin_);
    return 2*std::sqrt(max2) + shearDrift + 2*radiusGrowthSinceBuild_ >= skin_;
}

void Simulation::scaleRadii(double factor)
{
    if (!(factor > 0)) throw std::invalid_argument("scaleRadii: factor must be positive");
    double rMax = 0;
    for (double& r : particles_.radius)
    {
        r *= factor;
        rMax = std::max(rMax, r);
    }
    if (factor > 1)
    {
        radiusGrowthSinceBuild_ += rMax*(1 - 1/factor);
        nearRadiusGrowth_ += rMax*(1 - 1/factor);
    }
    else listValid_ = false;
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

std::vector<int> Simulation::renumberParticles()
{
    Particles& p = particles_;
    const int n = int(p.size());
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[i] = i;
    std::sort
    (
        order.begin(), order.end(),
        [&p](int a, int b) { return p.y[a] < p.y[b] || (p.y[a] == p.y[b] && p.id[a] < p.id[b]); }
    );
    // (the forces F^n travel with the particles: the force pass after this rebuild forms
    // the synchronised velocities from them)
    p.reorder(order);
    std::vector<int> newIndex(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) newIndex[order[k]] = k;
    indexIds();
    return newIndex;
}

void Simulation::rebuildNeighbourList()
{
    const double start = wallSeconds();
    // the contact histories to carry over: those of touching pairs (the others hold no
    // state: a contact that ends is cleared)
    struct Carried { int i, j; ContactHistory history; };
    std::vector<Carried> carried;
    {
        const std::vector<int>& f = list_.first();
        const std::vector<int>& s = list_.second();
        for (std::size_t k = 0; k < history_.size() && k < f.size(); ++k)
        {
            if (history_[k].touching) carried.push_back({f[k], s[k], history_[k]});
        }
    }
    if (renumberPending_)
    {
        renumberPending_ = false;
        const std::vector<int> newIndex = renumberParticles();
        for (Carried& c : carried)
        {
            int a = newIndex[c.i], b = newIndex[c.j];
            if (a > b)
            {
                // i and j swap roles: the tangential force on (the new) i and the normal
                // j -> i change sign
                std::swap(a, b);
                for (int d = 0; d < 3; ++d)
                {
                    c.history.ft[d] = -c.history.ft[d];
                    c.history.n[d] = -c.history.n[d];
                }
            }
            c.i = a;
            c.j = b;
        }
        std::sort
        (
            carried.begin(), carried.end(),
            [](const Carried& x, const Carried& y) { return x.i < y.i || (x.i == y.i && x.j < y.j); }
        );
    }

    list_.build(particles_, box_, skin_, nThreads_);

    // carry the histories over: both lists are sorted by (i, j)
    const std::size_t nPairs = list_.size();
    history_.assign(nPairs, ContactHistory());
    std::size_t o = 0;
    const std::vector<int>& f = list_.first();
    const std::vector<int>& s = list_.second();
    for (std::size_t k = 0; k < nPairs && o < carried.size(); ++k)
    {
        while (o < carried.size() && (carried[o].i < f[k] || (carried[o].i == f[k] && carried[o].j < s[k])))
        {
            ++o;
        }
        if (o < carried.size() && carried[o].i == f[k] && carried[o].j == s[k])
        {
            history_[k] = carried[o].history;
        }
    }
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
    listValid_ = true;
    ++rebuildTimings_.count;
    rebuildTimings_.wallSeconds += wallSeconds() - start;
}

void BlockBalance::reset(int nBlocks)
{
    share.assign(nBlocks, 1.0/nBlocks);
    work.assign(nBlocks, 0.0);
    busy.assign(nBlocks, 0.0);
    totalBusy.assign(nBlocks, 0.0);
    totalWall = 0;
}

void BlockBalance::update()
{
    const int nBlocks = int(share.size());
    bool measured = nBlocks > 1;
    for (int b = 0; b < nBlocks; ++b)
    {
        totalBusy[b] += busy[b];
        measured = measured && busy[b] > 0 && work[b] > 0;
    }
    if (measured)
    {
        std::vector<double> speed(nBlocks);
        double speedSum = 0;
        for (int b = 0; b < nBlocks; ++b)
        {
            speed[b] = work[b]/busy[b];
            speedSum += speed[b];
        }
        for (int b = 0; b < nBlocks; ++b)
        {
            // halfway, and bounded, so that one disturbed interval cannot starve a block
            const double target = std::clamp(speed[b]/speedSum, 0.25/nBlocks, 1.75/nBlocks);
            share[b] = 0.5*(share[b] + target);
        }
    }
    busy.assign(nBlocks, 0.0);
}

std::vector<int> BlockBalance::splitParticles(int n, int align)
{
    const int nBlocks = int(share.size());
    std::vector<int> begin(nBlocks + 1, n);
    begin[0] = 0;
    double cumulative = 0;
    for (int b = 1; b < nBlocks; ++b)
    {
        cumulative += share[b - 1];
        const int aligned = align*int(std::lround(cumulative*n/align));
        begin[b] = std::clamp(aligned, begin[b - 1], n);
    }
    for (int b = 0; b < nBlocks; ++b) work[b] = begin[b + 1] - begin[b];
    return begin;
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
    // threads in one phase), the finish's at whole thermostat chunks
    static_assert(thermostatChunk % particlesPerCacheLine == 0);
    driftBegin_ = driftBalance_.splitParticles(n, particlesPerCacheLine);
    finishBegin_ = finishBalance_.splitParticles(n, thermostatChunk);

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
    blockCross_.resize(nBlocks);
    nearPairs_.resize(nBlocks);
}

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
    const double nearSkin = nearSkin_;

    Particles& p = particles_;
    const int n = int(p.size());
    const int nPairs = int(list_.size());
    const int* first = list_.first().data();
    const int* second = list_.second().data();
    const ContactModel model = law_.model();
    const int nSpecies = int(species_.size());
    const double dt = dt_;
    const double h = 0.5*dt_;
    const PeriodicBox box = box_;
    const bool kickHere = halfKick && walls_.empty();
    const double* fPrevX = fPrevX_.data();
    const double* fPrevY = fPrevY_.data();
    const double* fPrevZ = fPrevZ_.data();
    const double* tPrevX = tPrevX_.data();
    const double* tPrevY = tPrevY_.data();
    const double* tPrevZ = tPrevZ_.data();
    // the thermostat that follows this pass needs sums over the final velocities
    const bool thermostatSums = kickHere && settings_.mode == CellMode::thermostatted;
    if (thermostatSums)
    {
        thermostatChunkSums_.resize(std::size_t((n + thermostatChunk - 1)/thermostatChunk));
    }
    thermostatSumsReady_ = thermostatSums;

    const int nSpeciesPairs = numberOfSpeciesPairs(nSpecies);
    const int nHist = collisionsEnabled_ ? int(collisions_.binEdges.size()) + 1 : 0;
    const int nBlocks = int(blockParticle_.size()) - 1;
    const int* blockParticle = blockParticle_.data();
    const int* blockPair = blockPair_.data();
    // busy times for the block shares (only when there is more than one block)
    const bool balance = nBlocks > 1;

    double maxOverlap = 0;

    const double forceStart = balance ? wallSeconds() : 0;
    // Force pass. Block b owns particles [P_b, P_b+1) and the pairs whose first particle it
    // owns; pairs are (i, j)-ordered with i < j, so block b's pairs read particles >= P_b
    // only. Every particle sums its incident pairs in DEcreasing pair order, starting from
    // zero, whatever the blocks and threads (bitwise reproducible, independent of the
    // thread count and of the block boundaries):
    //  - a block evaluates its contacts from the last to the first and adds each to i and,
    //    when j is its own, to j: its own pairs are the highest-numbered pairs of all its
    //    particles, so they come first;
    //  - contacts whose j lies in a higher block ("cross" contacts, listed per block in the
    //    same decreasing order) come from lower-numbered pairs: after a barrier, the
    //    thread whose finish range holds j adds them, block b-1's first, down to block
    //    0's, and only then finishes the particle (torque, second half kick).
    // Slots of touching pairs are always written: stress sampling reads them.
    #pragma omp parallel num_threads(nThreads_) reduction(max:maxOverlap)
    {
        int tid = 0, team = 1;
#ifdef _OPENMP
        tid = omp_get_thread_num();
        team = omp_get_num_threads();
#endif
        // torque from the sum of n x F_t, then the second half kick
        auto finish = [&](int begin, int end)
        {
            if (!kickHere)
            {
                for (int i = begin; i < end; ++i)
                {
                    const double r = p.radius[i];
                    p.tx[i] = -r*p.tx[i]; p.ty[i] = -r*p.ty[i]; p.tz[i] = -r*p.tz[i];
                }
                return;
            }
            // one pass: torque, then the kick
            for (int i = begin; i < end; ++i)
            {
                const double r = p.radius[i];
                p.tx[i] = -r*p.tx[i]; p.ty[i] = -r*p.ty[i]; p.tz[i] = -r*p.tz[i];
                const double im = p.invMass[i], ii = p.invInertia[i];
                p.vx[i] += h*p.fx[i]*im; p.vy[i] += h*p.fy[i]*im; p.vz[i] += h*p.fz[i]*im;
                p.wx[i] += h*p.tx[i]*ii; p.wy[i] += h*p.ty[i]*ii; p.wz[i] += h*p.tz[i]*ii;
            }
            if (!thermostatSums) return;
            // the thermostat's sums over the final velocities, per fixed chunk (the ranges
            // are whole chunks), while they are in cache
            for (int c0 = begin; c0 < end; c0 += thermostatChunk)
            {
                double sum[ThermostatSum::size] = {};
                addThermostatSums(p, c0, std::min(end, c0 + thermostatChunk), sum);
                std::copy(sum, sum + ThermostatSum::size, thermostatChunkSums_[c0/thermostatChunk].value);
            }
        };

        for (int b = tid; b < nBlocks; b += team)
        {
            const double busyStart = balance ? wallSeconds() : 0;
            std::vector<long>& hist = blockHist_[b];
            std::vector<CollisionRecord>& impacts = blockImpacts_[b];
            if (collisionsEnabled_)
            {
                hist.assign(std::size_t(nSpeciesPairs)*nHist, 0);
                impacts.clear();
            }
            const int ownBegin = blockParticle[b], ownEnd = blockParticle[b + 1];
            for (int i = ownBegin; i < ownEnd; ++i)
            {
                p.fx[i] = p.fy[i] = p.fz[i] = 0;
                p.tx[i] = p.ty[i] = p.tz[i] = 0;   // sum of n x F_t until finish()
            }

            // 1. which listed pairs touch (most do not): a short loop without the
            //    contact law, the touching ones compacted in pair order without a branch
            //    (over the near list; over all listed pairs when it is rebuilt)
            std::vector<int>& contacts = blockContacts_[b];
            std::vector<int>& near = nearPairs_[b];
            const int nListed = blockPair[b + 1] - blockPair[b];
            // sized once per list (no shrinking: growing again would fill it with zeros)
            if (contacts.size() < std::size_t(nListed)) contacts.resize(std::size_t(nListed));
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
                    pfx_[k] = pfy_[k] = pfz_[k] = 0;
                    pcx_[k] = pcy_[k] = pcz_[k] = 0;
                }
            }
            if (rebuildNear) near.resize(std::size_t(nNear));

            // 2. the contact law on the touching pairs, from the last to the first
            std::vector<CrossContact>& cross = blockCross_[b];
            cross.clear();
            for (int c = nContacts - 1; c >= 0; --c)
            {
                const int k = contacts[c];
                const int i = first[k], j = second[k];
                double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j];
                double shiftVx = 0;
                box.minimumImage(dx, dy, dz, shiftVx);
                const double ri = p.radius[i], rj = p.radius[j];
                active_[k] = 1;
                ContactKinematics kin;
                kin.r[0] = dx; kin.r[1] = dy; kin.r[2] = dz;
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
                const ContactResult res = evaluateContact(model, coeffs, kin, history_[k], dt);

                pfx_[k] = res.force[0]; pfy_[k] = res.force[1]; pfz_[k] = res.force[2];
                pcx_[k] = res.nCrossFt[0]; pcy_[k] = res.nCrossFt[1]; pcz_[k] = res.nCrossFt[2];
                p.fx[i] += res.force[0]; p.fy[i] += res.force[1]; p.fz[i] += res.force[2];
                p.tx[i] += res.nCrossFt[0]; p.ty[i] += res.nCrossFt[1]; p.tz[i] += res.nCrossFt[2];
                if (j < ownEnd)
                {
                    p.fx[j] -= res.force[0]; p.fy[j] -= res.force[1]; p.fz[j] -= res.force[2];
                    p.tx[j] += res.nCrossFt[0]; p.ty[j] += res.nCrossFt[1]; p.tz[j] += res.nCrossFt[2];
                }
                else
                {
                    cross.push_back
                    ({
                        j,
                        {res.force[0], res.force[1], res.force[2]},
                        {res.nCrossFt[0], res.nCrossFt[1], res.nCrossFt[2]}
                    });
                }

                const double frac = res.overlap/(2*std::min(ri, rj));
                if (frac > maxOverlap) maxOverlap = frac;

                if (collisionsEnabled_ && res.newContact)
                {
                    const int sp = speciesPairIndex(si, sj, nSpecies);
                    const double e = 0.5*coeffs.effectiveMass*res.normalVelocity*res.normalVelocity;
                    impacts.push_back({sp, e});
                    const std::vector<double>& edges = collisions_.binEdges;
                    int bin;
                    if (e < edges.front()) bin = 0;
                    else if (e >= edges.back()) bin = nHist - 1;
                    else bin = int(std::upper_bound(edges.begin(), edges.end(), e) - edges.begin());
                    ++hist[sp*nHist + bin];
                }
            }

            // one block is complete: finish it now (else after the barrier, in parallel with
            // the higher blocks adding their cross contacts)
            if (nBlocks == 1) finish(ownBegin, ownEnd);
            if (balance) forceBalance_.busy[b] += wallSeconds() - busyStart;
        }

        if (nBlocks > 1)
        {
            #pragma omp barrier
        }

        // the particles' sums are complete once the lower blocks' cross contacts are added
        // (in decreasing pair order: the higher blocks' lists first); this phase has its
        // own particle ranges
        for (int b = tid; b < nBlocks && nBlocks > 1; b += team)
        {
            const double busyStart = wallSeconds();
            const int begin = finishBegin_[b], end = finishBegin_[b + 1];
            for (int lower = nBlocks - 2; lower >= 0; --lower)
            {
                if (blockParticle[lower + 1] >= end) continue;   // its j lie below this range
                for (const CrossContact& c : blockCross_[lower])
                {
                    const int j = c.j;
                    if (j < begin || j >= end) continue;
                    p.fx[j] -= c.force[0]; p.fy[j] -= c.force[1]; p.fz[j] -= c.force[2];
                    p.tx[j] += c.nCrossFt[0]; p.ty[j] += c.nCrossFt[1]; p.tz[j] += c.nCrossFt[2];
                }
            }
            finish(begin, end);
            finishBalance_.busy[b] += wallSeconds() - busyStart;
        }
    }

    if (balance) forceBalance_.totalWall += wallSeconds() - forceStart;

    // walls (serial: only used for single-impact tests)
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        const Wall& wall = walls_[w];
        for (int i = 0; i < n; ++i)
        {
            const double s =
                (p.x[i] - wall.point.x())*wall.normal.x()
              + (p.y[i] - wall.point.y())*wall.normal.y()
              + (p.z[i] - wall.point.z())*wall.normal.z();
            ContactHistory& h = wallHistory_[w][i];
            if (s >= p.radius[i])
            {
                h.touching = false;
                h.ft[0] = h.ft[1] = h.ft[2] = 0;
                continue;
            }
            ContactKinematics kin;
            for (int a = 0; a < 3; ++a) kin.r[a] = s*wall.normal[a];
            kin.radiusI = p.radius[i]; kin.radiusJ = 0;
            kin.dvHalf[0] = p.vx[i]; kin.dvHalf[1] = p.vy[i]; kin.dvHalf[2] = p.vz[i];
            const double im = p.invMass[i], ii = p.invInertia[i];
            kin.dvSync[0] = p.vx[i] + 0.5*dt_*fPrevX_[i]*im;
            kin.dvSync[1] = p.vy[i] + 0.5*dt_*fPrevY_[i]*im;
            kin.dvSync[2] = p.vz[i] + 0.5*dt_*fPrevZ_[i]*im;
            kin.wHalfI[0] = p.wx[i]; kin.wHalfI[1] = p.wy[i]; kin.wHalfI[2] = p.wz[i];
            kin.wSyncI[0] = p.wx[i] + 0.5*dt_*tPrevX_[i]*ii;
            kin.wSyncI[1] = p.wy[i] + 0.5*dt_*tPrevY_[i]*ii;
            kin.wSyncI[2] = p.wz[i] + 0.5*dt_*tPrevZ_[i]*ii;
            for (int a = 0; a < 3; ++a) kin.wHalfJ[a] = kin.wSyncJ[a] = 0;
            const ContactResult res =
                evaluateContact(model, law_.wall(p.species[i]), kin, h, dt);
            p.fx[i] += res.force[0]; p.fy[i] += res.force[1]; p.fz[i] += res.force[2];
            const double r = p.radius[i];
            p.tx[i] -= r*res.nCrossFt[0]; p.ty[i] -= r*res.nCrossFt[1]; p.tz[i] -= r*res.nCrossFt[2];
            maxOverlap = std::max(maxOverlap, res.overlap/(2*r));
        }
    }

    if (rebuildNear)
    {
        nearValid_ = true;
        nearDrift_ = 0;
        nearRadiusGrowth_ = 0;
    }

    if (halfKick && !kickHere)
    {
        for (int i = 0; i < n; ++i)
        {
            const double im = p.invMass[i], ii = p.invInertia[i];
            p.vx[i] += h*p.fx[i]*im; p.vy[i] += h*p.fy[i]*im; p.vz[i] += h*p.fz[i]*im;
            p.wx[i] += h*p.tx[i]*ii; p.wy[i] += h*p.ty[i]*ii; p.wz[i] += h*p.tz[i]*ii;
        }
    }

    if (collisionsEnabled_)
    {
        // impact energies summed in pair order (blocks in order, each block's records
        // reversed): the same sums whatever the threads and block boundaries
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

    lastMaxOverlapFraction_ = maxOverlap;
    if (settings_.maxOverlapFraction > 0 && maxOverlap > settings_.maxOverlapFraction)
    {
        // diagnosis: find the worst pair (serial rescan, only on failure)
        int worstI = -1, worstJ = -1;
        double worst = 0;
        for (int k = 0; k < nPairs; ++k)
        {
            const int i = first[k], j = second[k];
            double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
            box.minimumImage(dx, dy, dz, dvx);
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
}

void Simulation::step()
{
    Particles& p = particles_;
    const int n = int(p.size());
    const double dt = dt_;

    // the first half of the step: kick, drift, Lees-Edwards wrap (with the offset at the
    // new time), largest peculiar displacement since the last build and in this step
    box_.advanceShear(dt);
    double maxDisp2 = 0, maxStep2 = 0;
    if (blockParticle_.size() < 2 || blockParticle_.back() != n) partitionWork();
    const int nBlocks = int(driftBegin_.size()) - 1;
    const int* blockParticle = driftBegin_.data();
    const bool balance = nBlocks > 1;
    const double driftStart = balance ? wallSeconds() : 0;
    #pragma omp parallel num_threads(nThreads_) reduction(max:maxDisp2, maxStep2)
    {
        int tid = 0, team = 1;
#ifdef _OPENMP
        tid = omp_get_thread_num();
        team = omp_get_num_threads();
#endif
        for (int b = tid; b < nBlocks; b += team)
        {
            const double busyStart = balance ? wallSeconds() : 0;
            driftRange
            (
                p, blockParticle[b], blockParticle[b + 1], dt, box_,
                uBuildX_, uBuildY_, uBuildZ_, maxDisp2, maxStep2
            );
            if (balance) driftBalance_.busy[b] += wallSeconds() - busyStart;
        }
    }
    if (balance) driftBalance_.totalWall += wallSeconds() - driftStart;
    time_ += dt;
    timeSinceBuild_ += dt;
    if (collisionsEnabled_) collisions_.elapsedTime += dt;

    // bound on the relative displacement of any listed pair this step (as for the
    // Verlet list: two peculiar displacements plus the streaming across one cutoff)
    nearDrift_ += 2*std::sqrt(maxStep2) + std::abs(box_.shearRate)*dt*(list_.cutoff() + skin_);
    {
        const double shearDrift = std::abs(box_.shearRate)*timeSinceBuild_*(list_.cutoff() + skin_);
        if (2*std::sqrt(maxDisp2) + shearDrift + 2*radiusGrowthSinceBuild_ >= skin_)
        {
            listValid_ = false;
        }
    }
    if (settings_.renumberEvery > 0 && walls_.empty() && (stepCount_ + 1) % settings_.renumberEvery == 0)
    {
        renumberPending_ = true;
        listValid_ = false;
    }
    // forces F^{n+1} and the second half kick
    computeForces(false, true);

    if (settings_.mode == CellMode::thermostatted) applyThermostat();

    ++stepCount_;
    if (stepCount_ % 100 == 0) checkEnergy();
}

void Simulation::applyThermostat()
{
    // Weak-coupling (Berendsen-type) rescaling of the fluctuating translational velocity
    // of all particles by one factor: T relaxes to the target over tau_T while inelastic
    // collisions keep removing energy; the mean velocity and the species' temperature
    // ratio (non-equipartition) are left to the dynamics.
    // Sums per fixed chunk of particles (filled by the force pass's finish, or here),
    // added in chunk order: the same T whatever the threads.
    Particles& p = particles_;
    const int n = int(p.size());
    const int nChunks = (n + thermostatChunk - 1)/thermostatChunk;
    if (!thermostatSumsReady_)
    {
        thermostatChunkSums_.resize(std::size_t(nChunks));
        for (int c = 0; c < nChunks; ++c)
        {
            double* sum = thermostatChunkSums_[c].value;
            std::fill(sum, sum + ThermostatSum::size, 0.0);
            addThermostatSums(p, c*thermostatChunk, std::min(n, (c + 1)*thermostatChunk), sum);
        }
    }
    thermostatSumsReady_ = false;
    double total[ThermostatSum::size] = {};
    for (int c = 0; c < nChunks; ++c)
    {
        for (int k = 0; k < ThermostatSum::size; ++k) total[k] += thermostatChunkSums_[c].value[k];
    }
    if (!(total[0] > 0)) return;
    // mass-weighted mean velocity u; sum |v - u|^2 = sum |v|^2 - 2 u . sum v + n |u|^2
    const double ux = total[1]/total[0], uy = total[2]/total[0], uz = total[3]/total[0];
    const double sumC2 =
        total[7] - 2*(ux*total[4] + uy*total[5] + uz*total[6]) + n*(ux*ux + uy*uy + uz*uz);
    const double T = sumC2/n;
    if (!(T > 0)) return;
    const double ratio = settings_.targetTemperature/T;
    const double lambda = std::sqrt(std::max(0.0, 1.0 + dt_/settings_.thermostatTime*(ratio - 1.0)));
    #pragma omp parallel for num_threads(nThreads_) schedule(static) if(nThreads_ > 1)
    for (int i = 0; i < n; ++i)
    {
        p.vx[i] = ux + lambda*(p.vx[i] - ux);
        p.vy[i] = uy + lambda*(p.vy[i] - uy);
        p.vz[i] = uz + lambda*(p.vz[i] - uz);
    }
}

void Simulation::checkEnergy() const
{
    const Particles& p = particles_;
    const int n = int(p.size());
    double e = 0;
    for (int i = 0; i < n; ++i)
    {
        e += 0.5*p.mass[i]*fluctuatingVelocity(i).squaredNorm()
           + 0.5*p.inertia[i]*(p.wx[i]*p.wx[i] + p.wy[i]*p.wy[i] + p.wz[i]*p.wz[i]);
    }
    if (!std::isfinite(e) || e > settings_.energyBlowUpFactor*referenceEnergy_)
    {
        std::ostringstream msg;
        msg << "unstable run stopped at step " << stepCount_ << " (t = " << time_
            << " s): fluctuating kinetic energy " << e << " J exceeds "
            << settings_.energyBlowUpFactor << " x the reference " << referenceEnergy_
            << " J (energy blow-up); reduce dt = " << dt_ << " s (recommended maximum "
            << law_.maximumTimeStep() << " s) or check the contact stiffness";
        throw std::runtime_error(msg.str());
    }
}

void Simulation::run
(
    long nSteps,
    const std::function<void(const Simulation&)>& observer,
    long observeEvery,
    long progressEvery,
    const std::string& label
)
{
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    for (long s = 1; s <= nSteps; ++s)
    {
        step();
        if (observer && observeEvery > 0 && s % observeEvery == 0) observer(*this);
        if (progressEvery > 0 && (s % progressEvery == 0 || s == nSteps))
        {
            const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
            const double eta = elapsed/s*(nSteps - s);
            std::printf
            (
                "%s: step %ld/%ld  time %.6g s  T %.6g m2/s2  max overlap %.3g %%  ETA %.1f s\n",
                label.c_str(), s, nSteps, time_, temperature(),
                100*lastMaxOverlapFraction_, eta
            );
            std::fflush(stdout);
        }
    }
}

// ---------------------------------------------------------------- measurements

Eigen::Vector3d Simulation::meanVelocity() const
{
    const Particles& p = particles_;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
    double mass = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        momentum += p.mass[i]*Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
        mass += p.mass[i];
    }
    return mass > 0 ? Eigen::Vector3d(momentum/mass) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d Simulation::fluctuatingVelocity(int i) const
{
    const Particles& p = particles_;
    Eigen::Vector3d c(p.vx[i], p.vy[i], p.vz[i]);
    if (settings_.mode == CellMode::leesEdwards)
    {
        c.x() -= box_.streamingVelocity(p.y[i]);
    }
    return c;
}

std::vector<double> Simulation::speciesTemperatures() const
{
    const int nSpecies = int(species_.size());
    std::vector<double> sum(nSpecies, 0.0);
    std::vector<int> count(nSpecies, 0);
    const Eigen::Vector3d mean =
        settings_.mode == CellMode::leesEdwards ? Eigen::Vector3d::Zero() : meanVelocity();
    for (std::size_t i = 0; i < particles_.size(); ++i)
    {
        const int s = particles_.species[i];
        sum[s] += (fluctuatingVelocity(int(i)) - mean).squaredNorm();
        ++count[s];
    }
    for (int s = 0; s < nSpecies; ++s) sum[s] = count[s] ? sum[s]/count[s] : 0.0;
    return sum;
}

double Simulation::temperature() const
{
    const Eigen::Vector3d mean =
        settings_.mode == CellMode::leesEdwards ? Eigen::Vector3d::Zero() : meanVelocity();
    double sum = 0;
    for (std::size_t i = 0; i < particles_.size(); ++i)
    {
        sum += (fluctuatingVelocity(int(i)) - mean).squaredNorm();
    }
    return particles_.size() ? sum/particles_.size() : 0.0;
}

double Simulation::translationalKineticEnergy() const
{
    const Particles& p = particles_;
    double e = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        e += 0.5*p.mass[i]*(p.vx[i]*p.vx[i] + p.vy[i]*p.vy[i] + p.vz[i]*p.vz[i]);
    }
    return e;
}

double Simulation::rotationalKineticEnergy() const
{
    const Particles& p = particles_;
    double e = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        e += 0.5*p.inertia[i]*(p.wx[i]*p.wx[i] + p.wy[i]*p.wy[i] + p.wz[i]*p.wz[i]);
    }
    return e;
}

double Simulation::elasticEnergy() const
{
    const Particles& p = particles_;
    double e = 0;
    const std::vector<int>& f = list_.first();
    const std::vector<int>& s = list_.second();
    for (std::size_t k = 0; k < list_.size(); ++k)
    {
        if (!history_[k].touching) continue;
        const int i = f[k], j = s[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
        box_.minimumImage(dx, dy, dz, dvx);
        const double delta = p.radius[i] + p.radius[j] - std::sqrt(dx*dx + dy*dy + dz*dz);
        const PairCoefficients& c = law_.pair(p.species[i], p.species[j]);
        e += law_.normalElasticEnergy(c, delta);
        const double ft2 = history_[k].ft[0]*history_[k].ft[0]
            + history_[k].ft[1]*history_[k].ft[1] + history_[k].ft[2]*history_[k].ft[2];
        if (ft2 > 0 && delta > 0)
        {
            const double kt = law_.model() == ContactModel::linearSpringDashpot
                ? c.kt : c.mindlinK*std::sqrt(delta);
            e += 0.5*ft2/kt;
        }
    }
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const double sd = (Eigen::Vector3d(p.x[i], p.y[i], p.z[i]) - walls_[w].point)
                .dot(walls_[w].normal);
            e += law_.normalElasticEnergy(law_.wall(p.species[i]), p.radius[i] - sd);
        }
    }
    return e;
}

Eigen::Vector3d Simulation::totalMomentum() const
{
    const Particles& p = particles_;
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        m += p.mass[i]*Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    }
    return m;
}

StressSplit Simulation::stressSplit() const
{
    const Particles& p = particles_;
    const int nSpecies = int(species_.size());
    StressSplit J;
    J.nSpecies = nSpecies;
    J.kinetic.assign(nSpecies, Eigen::Matrix3d::Zero());
    J.configurational.assign(numberOfSpeciesPairs(nSpecies), Eigen::Matrix3d::Zero());
    const Eigen::Vector3d mean =
        settings_.mode == CellMode::leesEdwards ? Eigen::Vector3d::Zero() : meanVelocity();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Eigen::Vector3d c = fluctuatingVelocity(int(i)) - mean;
        J.kinetic[p.species[i]] += p.mass[i]*c*c.transpose();
    }
    const std::vector<int>& f = list_.first();
    const std::vector<int>& s = list_.second();
    for (std::size_t k = 0; k < list_.size(); ++k)
    {
        if (!history_[k].touching) continue;
        const int i = f[k], j = s[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
        box_.minimumImage(dx, dy, dz, dvx);
        const Eigen::Vector3d F(pfx_[k], pfy_[k], pfz_[k]);
        const Eigen::Vector3d r(dx, dy, dz);
        J.configurational[speciesPairIndex(p.species[i], p.species[j], nSpecies)] += F*r.transpose();
    }
    return J;
}

Eigen::Matrix3d Simulation::totalStress() const
{
    const Particles& p = particles_;
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    const Eigen::Vector3d mean =
        settings_.mode == CellMode::leesEdwards ? Eigen::Vector3d::Zero() : meanVelocity();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Eigen::Vector3d c = fluctuatingVelocity(int(i)) - mean;
        J += p.mass[i]*c*c.transpose();
    }
    const std::vector<int>& f = list_.first();
    const std::vector<int>& s = list_.second();
    for (std::size_t k = 0; k < list_.size(); ++k)
    {
        if (!history_[k].touching) continue;
        const int i = f[k], j = s[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
        box_.minimumImage(dx, dy, dz, dvx);
        J += Eigen::Vector3d(pfx_[k], pfy_[k], pfz_[k])*Eigen::Vector3d(dx, dy, dz).transpose();
    }
    return J;
}

void Simulation::enableCollisionStatistics(double eMin, double eMax, int nBins)
{
    collisions_.reset(int(species_.size()), eMin, eMax, nBins);
    collisionsEnabled_ = true;
}

} // namespace sdf::dem

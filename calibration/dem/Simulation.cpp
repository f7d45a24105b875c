// Simulation: construction, the velocity-Verlet step (kick, drift, Lees-Edwards wrap; the
// force pass with the second half kick: SimulationForces.cpp; the driving's hook), runs,
// checkpoint state and the stability checks.

#include "Simulation.hpp"
#include "Drift.hpp"
#include "ThreadTeam.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace sdf::dem
{

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
    batchedContacts_ = settings_.batchedContacts;
    rollingResistance_ = hasRollingResistance(settings_.contact);
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
    dt_ = settings_.timeStep > 0 ? settings_.timeStep : law_.defaultTimeStep();
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
                ? "t_c/50 of the shortest contact over the species pairs, t_c = " + std::to_string(law_.contactDuration(1.0)) + " s"
                : "0.2 x Rayleigh time of the smallest species")
            << ")";
        throw std::invalid_argument(msg.str());
    }

    if (settings_.thermostatTime <= 0)
    {
        // the stochastic kicks' amplitude is steered slowly (a white noise of nearly
        // constant strength), the rescaling thermostat's factor quickly
        settings_.thermostatTime = (settings_.mode == CellMode::stochastic ? 1000 : 50)*dt_;
    }
    driving_ = Driving::New
    (
        settings_.mode, settings_.targetTemperature, settings_.thermostatTime,
        settings_.shearRate, dt_, settings_.seed
    );
    box_.shearRate = driving_->shearRate();
    double dMin = species_[0].diameter;
    for (const Species& s : species_) dMin = std::min(dMin, s.diameter);
    skin_ = settings_.skin >= 0 ? settings_.skin : 0.3*dMin;
    // near-list skin: on the sheared N 3000 cell of benchmarks/demVsLammps (skin 0.3 d)
    // 0.05-0.1 of the skin was fastest (at 0.1: rebuilt every ~27 steps, holding ~1/3 of
    // the listed pairs); 0.2 of it was 4 % slower, 0.5 of it 12 %
    nearSkin_ = 0.1*skin_;

    if (settings_.targetPressure != 0)
    {
        if (settings_.mode != CellMode::leesEdwards)
        {
            throw std::invalid_argument
            (
                "targetPressure: pressure control is for a sheared cell (mode leesEdwards"
                " with a shearRate), not mode " + cellModeName(settings_.mode)
              + "; 0: volume-controlled"
            );
        }
        if (!(settings_.barostatTime >= 0) || !std::isfinite(settings_.barostatTime))
        {
            throw std::invalid_argument
            (
                "barostatTime must be >= 0 s (0: automatic), not "
              + std::to_string(settings_.barostatTime)
            );
        }
        double dMax = dMin;
        for (const Species& s : species_) dMax = std::max(dMax, s.diameter);
        // the Barostat refuses a pressure <= 0 (before it is used for the automatic time)
        const double tau = settings_.barostatTime > 0 || !(settings_.targetPressure > 0)
            ? settings_.barostatTime
            : Barostat::automaticRelaxationTime
              (
                  law_.normalStiffnessAtForce(settings_.targetPressure*dMax*dMax), dMin,
                  settings_.targetPressure, dt_
              );
        barostat_ = std::make_unique<Barostat>(settings_.targetPressure, tau, dt_);
        settings_.barostatTime = tau;
    }

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
    // a pressure-controlled cell: the inertial speed sqrt(p/rho) of its pressure (a loose
    // start compressed under a slow shear gains that much kinetic energy)
    const double pressureSpeed2 = barostat_
        ? barostat_->targetPressure()*solidsFraction()*box_.volume()/massSum : 0.0;
    referenceEnergy_ = std::max
    ({
        0.5*massSum*pressureSpeed2,
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
    if (barostat_)
    {
        throw std::invalid_argument
        (
            "addWall: a pressure-controlled cell (targetPressure) dilates its gradient"
            " extent and cannot hold walls"
        );
    }
    walls_.add(wall, particles_.size());
    refreshForces();
}

void Simulation::setDriving(std::unique_ptr<Driving> driving)
{
    if (!driving)
    {
        throw std::invalid_argument
        (
            "setDriving: the driving is null; pass an object derived from Driving"
        );
    }
    // after a step the driving's sums (and the thermostat's history in the velocities)
    // belong to the old driving, and a checkpoint would not say which driving made it
    if (stepCount_ > 0)
    {
        throw std::invalid_argument
        (
            "setDriving('" + driving->name() + "'): the run has started (step "
          + std::to_string(stepCount_) + "); set the driving before the first step"
        );
    }
    // the box's streaming profile went into the wrap of the initial particles and their
    // first forces; the same rate keeps the start exactly as if built with this driving
    if (driving->shearRate() != box_.shearRate)
    {
        std::ostringstream msg;
        msg << "setDriving('" << driving->name() << "'): its shear rate "
            << driving->shearRate() << " 1/s differs from the cell's " << box_.shearRate
            << " 1/s (settings mode " << cellModeName(settings_.mode) << "); build the"
            << " Simulation with mode leesEdwards and shearRate " << driving->shearRate();
        throw std::invalid_argument(msg.str());
    }
    driving_ = std::move(driving);
    // the blow-up check's reference: also the driving's own speed
    double massSum = 0;
    for (double m : particles_.mass) massSum += m;
    const double scale = driving_->velocityScale();
    referenceEnergy_ = std::max(referenceEnergy_, 0.5*massSum*scale*scale);
}

SimulationState Simulation::exportState() const
{
    SimulationState st;
    st.particles = particles_;
    st.time = time_;
    st.stepCount = stepCount_;
    st.shearOffset = box_.offset;
    st.boxLengthY = box_.ly;
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
    st.driving = driving_->exportState();
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
    driving_->importState(st.driving);
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
    if (st.boxLengthY > 0) box_.ly = st.boxLengthY;
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
    walls_.clearHistories(n);
    timeSinceBuild_ = 0;
    radiusGrowthSinceBuild_ = 0;
    dilationSinceBuild_ = 0;
    // forces F^n come from the checkpoint; the list is rebuilt (histories carried over)
    // at the next force evaluation
    listValid_ = false;
}

void Simulation::refreshForces()
{
    // halfKick false: the synchronised velocities are the current ones
    computeForces();
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

void Simulation::step()
{
    Particles& p = particles_;
    const int n = int(p.size());
    const double dt = dt_;

    // the first half of the step: kick, drift, Lees-Edwards wrap (with the offset at the
    // new time), largest peculiar displacement since the last build and in this step
    box_.advanceShear(dt);
    if (blockParticle_.size() < 2 || blockParticle_.back() != n) partitionWork();
    const int nBlocks = int(driftBegin_.size()) - 1;
    const int* blockParticle = driftBegin_.data();
    const bool balance = nBlocks > 1;
    const double driftStart = balance ? wallSeconds() : 0;
    if (driftStep2_.size() != std::size_t(n))
    {
        driftStep2_.assign(std::size_t(n), 0.0);
        driftDisp2_.assign(std::size_t(n), 0.0);
    }
    const std::array<double, 2> maxima = maxOverThreads<2>
    (
        nThreads_, 0.0,
        [&](int thread, int team, std::array<double, 2>& local)
        {
            for (int b = thread; b < nBlocks; b += team)
            {
                const double busyStart = balance ? wallSeconds() : 0;
                driftRange
                (
                    p, blockParticle[b], blockParticle[b + 1], dt, box_,
                    uBuildX_, uBuildY_, uBuildZ_, driftStep2_, driftDisp2_, local[0], local[1]
                );
                if (balance) driftBalance_.busy[b] += wallSeconds() - busyStart;
            }
        }
    );
    const double maxDisp2 = maxima[0], maxStep2 = maxima[1];
    if (balance) driftBalance_.totalWall += wallSeconds() - driftStart;
    time_ += dt;
    timeSinceBuild_ += dt;
    if (collisionsEnabled_) collisions_.elapsedTime += dt;

    // bound on the relative displacement of any listed pair this step (as for the
    // Verlet list: two peculiar displacements plus the streaming across one cutoff)
    nearDrift_ += 2*std::sqrt(maxStep2) + std::abs(box_.shearRate)*dt*(list_.cutoff() + skin_);
    {
        const double shearDrift = (std::abs(box_.shearRate)*timeSinceBuild_ + dilationSinceBuild_)
                                 *(list_.cutoff() + skin_);
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

    if (driving_->wantsElasticEnergy())
    {
        driving_->setElasticEnergy(elasticEnergy());
    }
    driving_->afterStep(particles_, nThreads_);
    if (barostat_ && (stepCount_ + 1) % Barostat::every == 0) applyBarostat();

    ++stepCount_;
    if (stepCount_ % 100 == 0) checkEnergy();
}

void Simulation::applyBarostat()
{
    lastBarostatStress_ = totalStress()(1, 1)/box_.volume();
    const double factor = barostat_->dilation(lastBarostatStress_);
    // the neighbour list's own limit (its cutoff: 2 R_max + skin; radii do not change
    // during a run)
    const double thinnest = 2*list_.cutoff();
    if (box_.ly*factor < thinnest)
    {
        std::ostringstream msg;
        msg << "pressure control failed at step " << stepCount_ + 1 << ": targetPressure "
            << barostat_->targetPressure() << " Pa compresses the cell's height to "
            << box_.ly*factor << " m, below the " << thinnest << " m (2 (2 R_max + skin))"
            << " its " << particles_.size() << " particles need at solids fraction "
            << solidsFraction() << "; use more particles";
        throw std::runtime_error(msg.str());
    }
    dilateGradientExtent(factor);
    // a target below what the shear's agitation alone exerts: the cell expands without end
    const double phi = solidsFraction();
    if (phi < 0.01)
    {
        std::ostringstream msg;
        msg << "pressure control failed at step " << stepCount_ + 1 << " (t = " << time_
            << " s): the cell expanded to solids fraction " << phi << " and sigma_yy is still "
            << lastBarostatStress_ << " Pa against targetPressure "
            << barostat_->targetPressure() << " Pa; at shearRate " << box_.shearRate
            << " 1/s the grains' agitation alone exceeds the target (a gas, not a dense"
            << " flow): raise targetPressure or lower shearRate";
        throw std::runtime_error(msg.str());
    }
}

void Simulation::dilateGradientExtent(double factor)
{
    if (factor == 1) return;
    for (double& y : particles_.y) y *= factor;
    box_.ly *= factor;
    const double strain = std::abs(std::log(factor));
    dilationSinceBuild_ += strain;
    nearDrift_ += strain*(list_.cutoff() + skin_);
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

} // namespace sdf::dem

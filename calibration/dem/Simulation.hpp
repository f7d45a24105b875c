#ifndef sdf_dem_Simulation_hpp
#define sdf_dem_Simulation_hpp

// Periodic-cell DEM: velocity-Verlet integration of soft spheres in a (possibly
// Lees-Edwards sheared) periodic box, with optional flat walls and a thermostat that
// holds the granular temperature of a homogeneous cell.
//
// Reproducibility: every particle sums the forces of its pairs in decreasing pair order
// (the pair list is ordered (i, j)), whatever the threads and their particle ranges. No
// floating-point atomics, so a run is bitwise reproducible for a given seed; the
// trajectories do not even depend on the number of threads (computeForces explains how).

#include "ContactLaw.hpp"
#include "NeighbourList.hpp"
#include "Particles.hpp"
#include "PeriodicBox.hpp"
#include "Species.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sdf::dem
{

enum class CellMode
{
    nve,            // plain Newtonian dynamics (energy conserved if elastic and frictionless)
    thermostatted,  // homogeneous cell held at a target granular temperature
    leesEdwards     // simple shear at a prescribed rate, T is an output
};

CellMode cellModeFromName(const std::string& name);
std::string cellModeName(CellMode mode);

struct SimulationSettings
{
    ContactSettings contact;
    double timeStep = 0;                   // dt [s]; 0: use 0.5 x the maximum
    double skin = -1;                      // Verlet skin [m]; < 0: 0.3 x smallest diameter
    CellMode mode = CellMode::nve;
    double targetTemperature = 0;          // T = <|c|^2> (sum of 3 components) [m^2/s^2]
    double thermostatTime = 0;             // relaxation time tau_T [s]; 0: 50 dt
    double shearRate = 0;                  // gammaDot [1/s] for Lees-Edwards
    double maxOverlapFraction = 0.1;       // stop when delta/d_min exceeds this (<= 0: off)
    double energyBlowUpFactor = 1e3;       // stop when E_kin > factor x reference
    bool checkTimeStep = true;             // refuse dt above the recommended maximum
    int threads = 0;                       // OpenMP threads; 0: runtime default
    //- Steps between spatial renumberings of the particles (in order of y, the threads'
    //  ranges then stay slabs although the particles diffuse; Particles::id is kept);
    //  0: never. On a fixed step schedule, so a resumed run renumbers where the
    //  uninterrupted one did (bitwise resume). Not with walls.
    long renumberEvery = 0;
};

//- Flat frictional wall (infinitely heavy): point on the plane and unit normal into the domain.
struct Wall
{
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

//- Per-species microscopic stress J (seed eqs 9-13, not divided by volume):
//  kinetic[s] = sum_{i in s} m_i c_i c_i^T
//  configurational[pair(s,t)] = sum_{contacts (i,j), species {s,t}} F_ij r_ij^T
//  (entry (a,b) = F_a r_b; F_ij on i from j, r_ij = x_i - x_j; repulsion gives J_aa > 0)
struct StressSplit
{
    int nSpecies = 0;
    std::vector<Eigen::Matrix3d> kinetic;
    std::vector<Eigen::Matrix3d> configurational;

    //- J^s = kinetic[s] + configurational[(s,s)]
    Eigen::Matrix3d speciesStress(int s) const;
    //- J^{st}, s != t (configurational only)
    Eigen::Matrix3d crossStress(int s, int t) const;
    //- Sum of all parts (eq 13)
    Eigen::Matrix3d sum() const;
};

//- Collision counts and impact-energy histograms per unordered species pair.
//  Impact energy: 0.5 m* v_n^2 at the first step of a contact (normal, centre-of-mass frame).
struct CollisionStatistics
{
    int nSpecies = 0;
    std::vector<double> binEdges;            // nBins + 1 edges [J], log-spaced
    std::vector<long> counts;                // per species pair
    std::vector<std::vector<long>> histogram;// per species pair: nBins + 2 (under, bins, over)
    std::vector<double> energySum;           // per species pair [J]
    double elapsedTime = 0;                  // [s] time over which collisions were counted

    void reset(int nSpecies, double eMin, double eMax, int nBins);
    void clearCounts();
    //- Collisions per unit time of one particle of species s with particles of species t.
    double frequencyPerParticle(int s, int t, const std::vector<int>& speciesCounts) const;
};

//- Everything needed to continue a run bit for bit (walls and collision counts excluded).
struct SimulationState
{
    Particles particles;
    double time = 0;
    long stepCount = 0;
    double shearOffset = 0;
    std::vector<int> pairFirst, pairSecond;
    std::vector<ContactHistory> history;
    // per-pair force on i and n x F_t of the last evaluation (stress measurements)
    std::vector<double> pairForce, pairNCrossFt;   // 3 per pair
};

//- One phase's split of the work among threads: shares of a work model that follow the
//  measured busy times (work per busy second) halfway at each update.
struct BlockBalance
{
    std::vector<double> share;   // fraction of the work model per block
    std::vector<double> work;    // work-model units per block at the last split
    std::vector<double> busy;    // busy seconds per block since the last split
    std::vector<double> totalBusy;   // busy seconds per block up to the last split
    double totalWall = 0;            // wall-clock seconds of the phase since the start
                                     // (force pass: up to the barrier and after it)
    //- Busy seconds of block b since the start.
    double busySeconds(int b) const { return totalBusy[b] + busy[b]; }

    void reset(int nBlocks);
    void update();
    //- Contiguous particle ranges (begin of each block, then n) by share; particles cost 1.
    //  Boundaries are multiples of align (but the last).
    std::vector<int> splitParticles(int n, int align = 1);
};

class Simulation
{
public:
    Simulation
    (
        std::vector<Species> species,
        SimulationSettings settings,
        Particles particles,
        PeriodicBox box
    );

    // --- running
    void step();
    //- Runs n steps; calls observer(*this) every observeEvery steps (0: never); prints
    //  progress (step, time, T, ETA) every progressEvery steps (0: never).
    void run
    (
        long nSteps,
        const std::function<void(const Simulation&)>& observer = {},
        long observeEvery = 0,
        long progressEvery = 0,
        const std::string& label = "dem"
    );

    void addWall(const Wall& wall);

    //- State for checkpoints; importState continues bitwise as if never interrupted
    //  (the per-particle force sums do not depend on which non-touching pairs are listed).
    SimulationState exportState() const;
    void importState(const SimulationState& state);

    //- Forces a neighbour-list rebuild at the next force evaluation (after changing radii).
    void invalidateNeighbourList() { listValid_ = false; }
    //- Recomputes forces at the current state (e.g. after editing positions).
    void refreshForces();
    //- Multiplies all radii by factor (masses unchanged: used to grow packings).
    void scaleRadii(double factor);

    // --- state
    const Particles& particles() const { return particles_; }
    Particles& particles() { return particles_; }
    const PeriodicBox& box() const { return box_; }
    const std::vector<Species>& species() const { return species_; }
    const ContactLaw& contactLaw() const { return law_; }
    const SimulationSettings& settings() const { return settings_; }
    double time() const { return time_; }
    long stepCount() const { return stepCount_; }
    double timeStep() const { return dt_; }
    const NeighbourList& neighbourList() const { return list_; }
    std::vector<int> speciesCounts() const;
    //- Current index of the particle with this id (Particles::id).
    int indexOfId(int id) const { return indexOfId_[id]; }
    void setTargetTemperature(double T) { settings_.targetTemperature = T; }
    void setMode(CellMode mode) { settings_.mode = mode; }

    // --- measurements
    //- Fluctuating velocity of particle i (minus streaming or mean velocity).
    Eigen::Vector3d fluctuatingVelocity(int i) const;
    //- Granular temperature per species: T_s = <|c|^2> over species s (sum of 3 components).
    std::vector<double> speciesTemperatures() const;
    //- Number-averaged mixture temperature <|c|^2> over all particles.
    double temperature() const;
    double translationalKineticEnergy() const;   // of the full (lab) velocities
    double rotationalKineticEnergy() const;
    double elasticEnergy() const;                // normal springs + tangential springs
    Eigen::Vector3d totalMomentum() const;
    double maximumOverlapFraction() const { return lastMaxOverlapFraction_; }

    StressSplit stressSplit() const;
    //- Total stress J computed in one pass over all particles and contacts (reference for
    //  the split).
    Eigen::Matrix3d totalStress() const;

    void enableCollisionStatistics(double eMin, double eMax, int nBins);
    const CollisionStatistics& collisionStatistics() const { return collisions_; }
    void resetCollisionStatistics() { collisions_.clearCounts(); }
    //- Restores counts from a checkpoint (statistics must be enabled with the same bins).
    void setCollisionStatistics(const CollisionStatistics& c) { collisions_ = c; collisionsEnabled_ = true; }

    //- Where the time of a multi-threaded run goes, per phase of a step (drift, force pass
    //  up to the barrier, cross contacts + finish): per thread busy seconds and the
    //  phase's wall-clock seconds (empty on one thread).
    const BlockBalance& driftTimings() const { return driftBalance_; }
    const BlockBalance& forceTimings() const { return forceBalance_; }
    const BlockBalance& finishTimings() const { return finishBalance_; }

    //- Neighbour-list rebuilds so far (renumbering, list, histories carried, blocks) and
    //  their wall-clock seconds.
    struct RebuildTimings { long count = 0; double wallSeconds = 0; };
    const RebuildTimings& rebuildTimings() const { return rebuildTimings_; }

    //- Mass-weighted mean velocity of all particles.
    Eigen::Vector3d meanVelocity() const;

private:
    //- checkDisplacements: test the list's validity from the displacements (step() has
    //  done that already in its drift loop); halfKick: finish the step with the second
    //  half kick v += dt/2 F/m (fused into the force pass, particle by particle)
    void computeForces(bool checkDisplacements = true, bool halfKick = false);
    void rebuildNeighbourList();
    //- Renumbers the particles in order of y (ties by id); returns the old -> new index map.
    std::vector<int> renumberParticles();
    //- Rebuilds indexOfId_ from particles_.id; throws if the ids are not a permutation.
    void indexIds();
    //- Splits particles (and their pairs as first particle) into one contiguous block per
    //  thread for the force pass (see computeForces).
    void partitionWork();
    bool neighbourListExpired() const;
    void applyThermostat();
    void checkEnergy() const;

    std::vector<Species> species_;
    SimulationSettings settings_;
    ContactLaw law_;
    Particles particles_;
    PeriodicBox box_;
    std::vector<Wall> walls_;

    double dt_ = 0;
    double skin_ = 0;
    double time_ = 0;
    long stepCount_ = 0;
    int nThreads_ = 1;

    std::vector<int> indexOfId_;
    bool renumberPending_ = false;   // renumber at the next list build (renumberEvery)

    NeighbourList list_;
    bool listValid_ = false;
    std::vector<ContactHistory> history_;
    std::vector<double> pfx_, pfy_, pfz_, pcx_, pcy_, pcz_;   // per-pair force on i, n x F_t
    std::vector<unsigned char> active_;   // per pair: force slots hold a contact (else zero)
    // force-pass blocks: block b owns particles [blockParticle_[b], blockParticle_[b+1]) and
    // the pairs [blockPair_[b], blockPair_[b+1]) whose first particle it owns
    std::vector<int> blockParticle_, blockPair_;
    // each phase's split among the threads, following measured busy times: the force
    // pass up to the barrier (blockParticle_, blockPair_), the drift (driftBegin_) and
    // the cross contacts + finish after the barrier (finishBegin_): particle ranges
    BlockBalance forceBalance_, driftBalance_, finishBalance_;
    std::vector<int> driftBegin_, finishBegin_;
    // per block: impact histogram, and the impacts (species pair, energy) in reverse pair
    // order, so energies are summed in pair order whatever the blocks
    struct CollisionRecord { int speciesPair; double energy; };
    std::vector<CacheLinePadded<std::vector<long>>> blockHist_;
    std::vector<CacheLinePadded<std::vector<CollisionRecord>>> blockImpacts_;
    // Near list: per block, the listed pairs (ascending) whose gap was below nearSkin_ at
    // its build; no other listed pair can touch while the relative displacement bound
    // nearDrift_ (+ radius growth) stays below nearSkin_, so the per-step distance test
    // runs over these only. Rebuilt from the Verlet list (a pass over all its pairs).
    std::vector<CacheLinePadded<std::vector<int>>> nearPairs_;
    bool nearValid_ = false;
    double nearSkin_ = 0;
    double nearDrift_ = 0;
    double nearRadiusGrowth_ = 0;
    std::vector<CacheLinePadded<std::vector<int>>> blockContacts_;   // per block: touching pairs this step, in pair order
    // per block: its touching pairs whose second particle j lies in a higher block, in
    // decreasing pair order, with their force on i and n x F_t (added by j's owner after
    // the barrier; a compact copy, so few cache lines cross between the cores)
    struct CrossContact { int j; double force[3]; double nCrossFt[3]; };
    std::vector<CacheLinePadded<std::vector<CrossContact>>> blockCross_;
    std::vector<std::vector<ContactHistory>> wallHistory_;    // per wall, per particle

    // forces and torques of the previous evaluation (F^n) during a force pass, for the
    // synchronised velocity estimates v^{n+1/2} + dt/2 F^n/m (swapped with Particles::fx..tz)
    ParticleArray fPrevX_, fPrevY_, fPrevZ_, tPrevX_, tPrevY_, tPrevZ_;
    // Particles::u at the last list build (u - uBuild: the peculiar displacement since,
    // for the rebuild criterion)
    ParticleArray uBuildX_, uBuildY_, uBuildZ_;
    RebuildTimings rebuildTimings_;
    double timeSinceBuild_ = 0;
    double radiusGrowthSinceBuild_ = 0;

    // thermostat sums per chunk of thermostatChunk particles: mass, mass x velocity,
    // velocity, |velocity|^2 (filled by the force pass's finish when it is thermostatted)
    static constexpr int thermostatChunk = 64;
    struct ThermostatSum { static constexpr int size = 8; double value[size]; };
    std::vector<ThermostatSum> thermostatChunkSums_;
    bool thermostatSumsReady_ = false;

    double lastMaxOverlapFraction_ = 0;
    double referenceEnergy_ = 0;

    bool collisionsEnabled_ = false;
    CollisionStatistics collisions_;
};

} // namespace sdf::dem

#endif

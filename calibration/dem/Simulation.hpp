#ifndef sdf_dem_Simulation_hpp
#define sdf_dem_Simulation_hpp

// Periodic-cell DEM: velocity-Verlet integration of soft spheres in a (possibly
// Lees-Edwards sheared) periodic box, with optional flat walls and a thermostat that
// holds the granular temperature of a homogeneous cell.
//
// Where things are: the step and the state in Simulation.cpp; the force pass (pair loop,
// one instantiation per contact law) in SimulationForces.cpp; the neighbour list, its
// rebuilds, the spatial renumbering and the thread ranges in SimulationNeighbours.cpp;
// temperatures, energies and stresses in SimulationMeasurements.cpp. The parts it is
// built from: contact laws (ContactLaw, ContactModels, ContactForce; ContactBatch: the
// law over a block's contacts at once), the drift (Drift), driving
// (Driving: thermostat, Lees-Edwards; StochasticDriving), walls (Walls), renumbering (Renumbering), thread
// balancing (BlockBalance), statistics (CellStatistics).
//
// Reproducibility: every particle sums the forces of its pairs in decreasing pair order
// (the pair list is ordered (i, j)), whatever the threads and their particle ranges. No
// floating-point atomics, so a run is bitwise reproducible for a given seed; the
// trajectories do not even depend on the number of threads (computeForces explains how).

#include "Barostat.hpp"
#include "BlockBalance.hpp"
#include "CellStatistics.hpp"
#include "ContactBatch.hpp"
#include "ContactForce.hpp"
#include "ContactLaw.hpp"
#include "Driving.hpp"
#include "NeighbourList.hpp"
#include "Particles.hpp"
#include "PeriodicBox.hpp"
#include "Species.hpp"
#include "Walls.hpp"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sdf::dem
{

struct SimulationSettings
{
    ContactSettings contact;
    double timeStep = 0;                   // dt [s]; 0: use 0.5 x the maximum
    double skin = -1;                      // Verlet skin [m]; < 0: 0.3 x smallest diameter
    CellMode mode = CellMode::nve;          // built-in driving (Simulation::setDriving: another)
    double targetTemperature = 0;          // T = <|c|^2> (sum of 3 components) [m^2/s^2]
    double thermostatTime = 0;             // relaxation time tau_T [s]; 0: 50 dt (stochastic:
                                           // the kicks' steering time; 0: 1000 dt)
    std::uint64_t seed = 1;                // the stochastic driving's random numbers
    double shearRate = 0;                  // gammaDot [1/s] for Lees-Edwards
    //- Pressure control of a Lees-Edwards cell (Barostat.hpp): sigma_yy held at this
    //  pressure [Pa] by dilating the gradient extent; 0: volume-controlled
    double targetPressure = 0;
    double barostatTime = 0;               // tau_p [s]; 0: automatic (Barostat.hpp)
    double maxOverlapFraction = 0.1;       // stop when delta/d_min exceeds this (<= 0: off)
    //- Evaluate the touching pairs as one batch (ContactBatch.hpp; not for a law without a
    //  batched loop); false: contact by contact, the reference the batch is tested
    //  against. The results are the same bits either way.
    bool batchedContacts = true;
    double energyBlowUpFactor = 1e3;       // stop when E_kin > factor x reference
    bool checkTimeStep = true;             // refuse dt above the recommended maximum
    int threads = 0;                       // OpenMP threads; 0: runtime default
    //- Steps between spatial renumberings of the particles (in order of y, the threads'
    //  ranges then stay slabs although the particles diffuse; Particles::id is kept);
    //  0: never. On a fixed step schedule, so a resumed run renumbers where the
    //  uninterrupted one did (bitwise resume). Not with walls.
    long renumberEvery = 0;
};

//- Everything needed to continue a run bit for bit (walls and collision counts excluded).
struct SimulationState
{
    Particles particles;
    double time = 0;
    long stepCount = 0;
    double shearOffset = 0;
    double boxLengthY = 0;                         // ly (pressure control changes it); 0: as built
    std::vector<int> pairFirst, pairSecond;
    std::vector<ContactHistory> history;
    // per-pair force on i and n x F_t of the last evaluation (stress measurements)
    std::vector<double> pairForce, pairNCrossFt;   // 3 per pair
    std::vector<double> driving;                   // the driving's own state (Driving::exportState)
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

    //- Replaces the driving built from settings().mode by one of any type derived from
    //  Driving (e.g. written outside the library), before the first step (also before
    //  importState of a resumed run). Its shearRate() must be the cell's, box().shearRate:
    //  the streaming profile is fixed when the Simulation is built (a sheared driving of
    //  your own: build with mode leesEdwards at that rate). Throws std::invalid_argument
    //  for a null driving, once the run has started, or for another shear rate.
    void setDriving(std::unique_ptr<Driving> driving);

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
    const Driving& driving() const { return *driving_; }

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
    //- The contacts' part of the stress per slab of y, J = sum f r^T (f the force on i,
    //  r = x_i - x_j; not yet divided by a volume): slab l is [y0 + l h, y0 + (l+1) h), and
    //  each contact's f r^T is shared among the slabs its branch vector crosses in
    //  proportion to the length in each (the slab form of Irving & Kirkwood's stress:
    //  the slabs' stresses then balance the body forces exactly, so a lithostatic
    //  gradient is measured, not assumed); the part outside the slabs is dropped.
    std::vector<Eigen::Matrix3d> contactStressBySlab(double y0, double h, int slabs) const;
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

    //- Solids volume over the box's volume.
    double solidsFraction() const;

    //- The touching pairs now, in one pass over them: their number (the coordination
    //  number is 2 contacts / N), mean overlap over the pair's mean diameter, and
    //  bondOrderQ6, Steinhardt's global bond-orientational order Q6 of their directions
    //  (Steinhardt, Nelson & Ronchetti 1983): sqrt(4 pi/13 sum_m |<Y_6m>|^2), the mean
    //  over the bonds. 0.5745 for the contacts of a face-centred cubic packing, 0.4848
    //  hexagonal close packed; a disordered packing of n bonds about 1/sqrt(n). A cell
    //  that crystallises (one size at low friction) reads high: its mu and phi are an
    //  ordered packing's, not the bulk's. 0 without contacts.
    struct ContactSummary
    {
        long contacts = 0;
        double meanOverlapFraction = 0;
        double bondOrderQ6 = 0;
    };
    ContactSummary contactSummary() const;

    //- The pressure control (null: volume-controlled cell) and sigma_yy at its last
    //  update [Pa].
    const Barostat* barostat() const { return barostat_.get(); }
    double lastBarostatStress() const { return lastBarostatStress_; }

private:
    //- checkDisplacements: test the list's validity from the displacements (step() has
    //  done that already in its drift loop); halfKick: finish the step with the second
    //  half kick v += dt/2 F/m (fused into the force pass, particle by particle)
    void computeForces(bool checkDisplacements = true, bool halfKick = false);
    //- The force pass with contact law Law over the listed pairs (all blocks, threads),
    //  with the torques finished and, if kickHere, the second half kick; returns the
    //  largest overlap fraction.
    template<class Law>
    double pairForcePass(bool rebuildNear, bool kickHere, bool finishSums);
    //- One block's pairs that touch (over the near list, or all its listed pairs when
    //  rebuildNear); clears the pairs whose contact ended. Returns their number.
    int findTouchingPairs(int block, bool rebuildNear);
    //- One block's touching pairs through the contact law, their forces added from the
    //  last pair to the first.
    template<class Law>
    double evaluateTouchingPairs(int block, int nContacts);
    //- The same with the block's ContactBatch.
    template<class Law>
    double evaluateContactsInBatch(int block, int nContacts);
    //- The same contact by contact (the batch's reference; a law without a batched loop).
    template<class Law>
    double evaluateContactsOneByOne(int block, int nContacts);
    //- One block's touching pairs' kinematics, constants and history into its ContactBatch.
    template<class Law>
    void gatherContactBatch(int block, int nContacts);
    //- Adds one contact's force and torque sums to i and to j (or j's to the cross list).
    void addContact(int block, int i, int j, const double* force, const double* torqueSumI,
                    const double* torqueSumJ);
    //- Counts a new contact's impact energy in the block's collision statistics.
    void recordImpact(int block, int i, int j, double normalVelocity);
    struct ContactSeparation;
    //- v^{n+1/2} + dt/2 F^n/m and the spins' likewise for particles [begin, end).
    void synchronisedVelocities(int begin, int end);
    //- The kinematics of pair (i, j) at this force evaluation.
    ContactKinematics contactKinematics(int i, int j, const ContactSeparation& r) const;
    //- Adds the lower blocks' cross contacts to the particles [begin, end).
    void addCrossContacts(int begin, int end);
    //- Torque from the sum of n x F_t and, if kick, the second half kick, for particles
    //  [begin, end); finishSums: hands them on to the driving.
    void finishParticles(int begin, int end, bool kick, bool finishSums);
    //- Adds the blocks' impacts to the collision statistics, in pair order.
    void gatherCollisions();
    //- Throws the unstable-run error naming the worst pair.
    [[noreturn]] void overlapFailure(double maxOverlap) const;
    //- Velocity the temperatures and stresses are taken about (zero about the streaming).
    Eigen::Vector3d referenceMeanVelocity() const;
    //- visit(i, c) for each particle i, in index order, with its velocity c about
    //  referenceMeanVelocity() (the measurements' kinetic parts; defined, like the next,
    //  in SimulationMeasurements.cpp, their only user).
    template<class Visit>
    void forEachFluctuation(Visit visit) const;
    //- visit(k, i, j, r) for each listed pair k = (i, j) in contact, in pair order, with
    //  r = x_i - x_j (minimum image) (the measurements' contact parts).
    template<class Visit>
    void forEachContact(Visit visit) const;
    void rebuildNeighbourList();
    //- Rebuilds indexOfId_ from particles_.id; throws if the ids are not a permutation.
    void indexIds();
    //- Splits particles (and their pairs as first particle) into one contiguous block per
    //  thread for the force pass (see computeForces).
    void partitionWork();
    bool neighbourListExpired() const;
    void checkEnergy() const;
    //- The barostat's update: sigma_yy now, the gradient extent dilated (throws when the
    //  cell has expanded into a dilute gas without reaching the target)
    void applyBarostat();
    //- Positions y and ly scaled by factor (affine; velocities kept)
    void dilateGradientExtent(double factor);

    std::vector<Species> species_;
    SimulationSettings settings_;
    ContactLaw law_;
    std::unique_ptr<Driving> driving_;
    Particles particles_;
    PeriodicBox box_;
    Walls walls_;

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
    // per block: the touching pairs' minimum-image separation x_i - x_j and Lees-Edwards
    // velocity shift, kept from the touching test (the force pass does not redo the
    // image's branches)
    struct ContactSeparation { double dx, dy, dz, shiftVx; };
    std::vector<CacheLinePadded<std::vector<ContactSeparation>>> blockSeparations_;
    // per block: its touching pairs as a batch for the contact law (without rolling resistance)
    std::vector<CacheLinePadded<ContactBatch>> blockBatches_;
    bool batchedContacts_ = true;     // false: contact by contact (SimulationSettings)
    bool rollingResistance_ = false;  // on for some pair: the batch carries its part
    // per block: its touching pairs whose second particle j lies in a higher block, in
    // decreasing pair order, with their force on i and j's torque sum (n x F_t, and the
    // rolling part; ContactResult::torqueSumJ) (added by j's owner after
    // the barrier; a compact copy, so few cache lines cross between the cores)
    struct CrossContact { int j; double force[3]; double torqueSum[3]; };
    std::vector<CacheLinePadded<std::vector<CrossContact>>> blockCross_;

    // forces and torques of the previous evaluation (F^n) during a force pass, for the
    // synchronised velocity estimates v^{n+1/2} + dt/2 F^n/m (swapped with Particles::fx..tz)
    ParticleArray fPrevX_, fPrevY_, fPrevZ_, tPrevX_, tPrevY_, tPrevZ_;
    // the synchronised velocities and spins formed from them, per particle, for the pass
    ParticleArray vSyncX_, vSyncY_, vSyncZ_, wSyncX_, wSyncY_, wSyncZ_;
    // the drift's per-particle displacements (Drift.hpp), before their maxima
    ParticleArray driftStep2_, driftDisp2_;
    // Particles::u at the last list build (u - uBuild: the peculiar displacement since,
    // for the rebuild criterion)
    ParticleArray uBuildX_, uBuildY_, uBuildZ_;
    RebuildTimings rebuildTimings_;
    double timeSinceBuild_ = 0;
    double radiusGrowthSinceBuild_ = 0;

    double lastMaxOverlapFraction_ = 0;
    double referenceEnergy_ = 0;

    std::unique_ptr<Barostat> barostat_;
    double lastBarostatStress_ = 0;
    // sum of |ln s| of the dilations since the list build: a listed pair's distance has
    // changed by at most that times (cutoff + skin)
    double dilationSinceBuild_ = 0;

    bool collisionsEnabled_ = false;
    CollisionStatistics collisions_;
};

} // namespace sdf::dem

#endif

#ifndef sdf_dem_Measurements_hpp
#define sdf_dem_Measurements_hpp

// The measurements of a cell run (interface: Measurement.hpp): granular temperature,
// velocity autocorrelation (Green-Kubo D), mean-square displacement (Einstein D), the
// stress autocorrelations of the per-species stress split (eta), collision and
// impact-energy statistics.

#include "Measurement.hpp"

#include "correlation/MeanSquareDisplacement.hpp"
#include "correlation/MultipleTauCorrelator.hpp"

namespace sdf::dem
{

//- Particle ids of each species, in increasing id (the same on resume, whatever the
//  particles' current order).
std::vector<std::vector<int>> speciesMembers(const Simulation& simulation);

//- Mixture temperature per sample (block average and error; the Savage-Jeffrey R of a
//  sheared cell) and, if perSpecies, each species' mean temperature.
class TemperatureMeasurement : public Measurement
{
public:
    TemperatureMeasurement(int nSpecies, int blocks, bool perSpecies);
    void sample(const Simulation& simulation, long index) override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    int blocks_;
    bool perSpecies_;
    std::vector<double> mixture_;
    std::vector<std::vector<double>> species_;
};

//- The rheology of a sheared cell (RheologyResult): per sample sigma_yy, sigma_xy, the
//  solids fraction, the contacts, their mean overlap and their bond order Q6.
class RheologyMeasurement : public Measurement
{
public:
    explicit RheologyMeasurement(int blocks);
    void sample(const Simulation& simulation, long index) override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    int blocks_;
    // per sample: sigma_yy, sigma_xy [Pa], phi, Z, mean overlap fraction, Q6
    std::vector<double> normal_, shear_, phi_, coordination_, overlap_, bondOrder_;
};

//- Samples between the MSD's position frames (at most maxFrames per run), its longest
//  lag in frames (half a block of them) and in seconds. The Green-Kubo D is read within
//  the same lags.
long msdFramesEvery(const SamplingPlan& plan, int maxFrames);
std::size_t msdLongestLagFrames(std::size_t frames, int blocks);
double longestMsdLag(const SamplingPlan& plan, int maxFrames);

//- Per-species velocity autocorrelation (multiple-tau, many time origins, in blocks) and
//  its Green-Kubo integral D, read past the VACF's decay and within the MSD's lags.
class VelocityAutocorrelation : public Measurement
{
public:
    VelocityAutocorrelation
    (
        std::vector<std::vector<int>> members,
        const SamplingPlan& plan,
        int maxMsdFrames
    );
    void sample(const Simulation& simulation, long index) override;
    void closeBlock() override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    std::vector<std::vector<int>> members_;
    SamplingPlan plan_;
    double longestMsdLag_;   // [s]
    std::vector<correlation::MultipleTauCorrelator> correlators_;
};

//- Per-species mean-square displacement from stored position frames (at most maxFrames)
//  and its Einstein slope D (y for sheared cells, x+y+z otherwise).
class MeanSquareDisplacementMeasurement : public Measurement
{
public:
    MeanSquareDisplacementMeasurement
    (
        std::vector<std::vector<int>> members,
        const SamplingPlan& plan,
        int maxFrames
    );
    void sample(const Simulation& simulation, long index) override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    std::vector<std::vector<int>> members_;
    SamplingPlan plan_;
    long framesEvery_;    // samples between frames
    std::vector<correlation::VectorFrames> frames_;
};

//- The xy stress split J^s, J^{st} per sample: time means and the product
//  autocorrelations, integrated (seed eqs 8-13) to the kinetic-sieving coefficients eta
//  of a binary mixture.
class StressAutocorrelation : public Measurement
{
public:
    //- Series names: the species parts, then the cross parts.
    static std::vector<std::string> seriesNames(const std::vector<Species>& species);

    StressAutocorrelation
    (
        const std::vector<Species>& species,
        double volume,
        const SamplingPlan& plan
    );
    void sample(const Simulation& simulation, long index) override;
    void closeBlock() override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    std::vector<std::pair<int, int>> parts_;
    double volume_;
    SamplingPlan plan_;
    correlation::SeriesProductCorrelator correlator_;
    std::vector<double> stressSum_;    // sum over samples of J_xy^k / V
    //- The open block's sums of the series J_xy^k/sqrt(V) and its sample count, the closed
    //  blocks' means: the products are correlated about them (a sheared cell's mean stress)
    std::vector<double> blockSum_;
    long blockSamples_ = 0;
    std::vector<std::vector<double>> blockMeans_;
};

//- Collective motion: the kinetic energy in the longest-wavelength modes of the momentum
//  density against equipartition. j_a(k) = sum_i m_i c_ia exp(-i k.r_i) (c the fluctuating
//  velocity) for the three wavevectors k = 2 pi / L along x, y and z; for velocities
//  uncorrelated between particles <|j_a(k)|^2> = <sum_i m_i^2 c_ia^2>, so the ratio of the
//  two is 1 (equipartition) and grows with collective motion (shear modes, vortices: the
//  transverse components a != k; sound: the longitudinal one). Per sample the four sums
//  (transverse and longitudinal, modes and equipartition); ratios of the block sums with
//  their block error.
class CollectiveMotionMeasurement : public Measurement
{
public:
    explicit CollectiveMotionMeasurement(int blocks);
    void sample(const Simulation& simulation, long index) override;
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    int blocks_;
    //- per sample: transverse modes, transverse equipartition, longitudinal modes,
    //  longitudinal equipartition
    std::vector<double> sums_[4];
};

//- Collision counts and impact-energy histograms, counted by the Simulation's force pass
//  (enabled here: 56 log bins from 1e-4 to 1e3 x the energy scale).
class CollisionMeasurement : public Measurement
{
public:
    CollisionMeasurement(Simulation& simulation, double energyScale);
    void sample(const Simulation&, long) override {}
    void save(io::Checkpoint& checkpoint) const override;
    void load(const io::Checkpoint& checkpoint, const std::string& source) override;
    void finish(CellRunResult& result, long samples) const override;

private:
    Simulation& simulation_;
};

} // namespace sdf::dem

#endif

// Streaming multiple-tau correlator (Ramirez, Sukumaran, Vorselaars and
// Likhtman, J. Chem. Phys. 133, 154103 (2010); Frenkel & Smit's block
// correlator): bounded memory and O(1) work per sample however long the run.
//
// Level 0 correlates the raw samples at lags 0 .. p-1. Every m samples of
// level l are averaged into one sample of level l+1, which correlates lags
// j m^(l+1) for j = p/m .. p-1. So lags cover 0 .. ~p m^(L-1) samples
// log-spaced, with per-level cost and memory p. The averaging smooths the
// function over a window of at most lag/(p/m) (1/8 of the lag for p = 16,
// m = 2): negligible for Green-Kubo integrals of smoothly decaying functions.
//
// One correlator handles many channels at once (particles) and several
// components (x, y, z; or several series products); the result is averaged
// over channels and time origins, per component, with the same convention as
// FftCorrelator.hpp: C(k) = < a(t) b(t+k) >.
#ifndef sdf_correlation_MultipleTauCorrelator_hpp
#define sdf_correlation_MultipleTauCorrelator_hpp

#include <Eigen/Dense>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sdf::correlation
{

struct MultipleTauSettings
{
    std::size_t pointsPerLevel = 16;   // p: even, a multiple of averagingFactor
    std::size_t averagingFactor = 2;   // m
    std::size_t levels = 20;           // L: max lag ~ p m^(L-1) samples
};

//- Correlation on a (log-spaced) lag grid, per component.
struct LaggedCorrelation
{
    std::vector<std::size_t> lags;     // in samples
    Eigen::ArrayXXd values;            // lags.size() x components
    std::vector<std::uint64_t> pairs;  // time-origin pairs averaged, per lag (x channels)

    //- Lag times for a sample interval dt.
    std::vector<double> times(double sampleInterval) const;
    //- Column c as a plain vector.
    std::vector<double> column(Eigen::Index c) const;
    //- Mean of the columns (isotropic part of a vector correlation).
    std::vector<double> columnMean() const;
};

//- Everything a correlator has accumulated, as two flat arrays that fit a
//  checkpoint (sdf::io::Checkpoint vectors / integerVectors).
struct MultipleTauState
{
    std::vector<double> reals;
    std::vector<std::int64_t> integers;
};

class MultipleTauCorrelator
{
public:
    //- channels x components data per sample. crossCorrelation = false:
    //  autocorrelation of the stream a; true: C_ab with separate streams.
    MultipleTauCorrelator
    (
        std::size_t channels,
        std::size_t components,
        const MultipleTauSettings& settings = MultipleTauSettings(),
        bool crossCorrelation = false
    );

    std::size_t channels() const { return channels_; }
    std::size_t components() const { return components_; }
    const MultipleTauSettings& settings() const { return settings_; }
    bool isCrossCorrelation() const { return cross_; }
    std::uint64_t samplesAdded() const { return samplesAdded_; }

    //- Autocorrelation mode: one sample (channels x components).
    void add(const Eigen::Ref<const Eigen::ArrayXXd>& a);

    //- Cross mode: one sample of each stream; C(k) = < a(t) b(t+k) >.
    void add
    (
        const Eigen::Ref<const Eigen::ArrayXXd>& a,
        const Eigen::Ref<const Eigen::ArrayXXd>& b
    );

    //- Everything accumulated since construction.
    LaggedCorrelation result() const;

    //- Ends a block: the pairs accumulated since the previous closeBlock()
    //  (or the start) become one block estimate. Consecutive blocks much
    //  longer than the correlation time are nearly independent, which gives
    //  the Green-Kubo statistical error of a long streaming run.
    void closeBlock();
    const std::vector<LaggedCorrelation>& blocks() const { return blocks_; }

    //- For checkpoints: a correlator restored with importState() and fed the
    //  rest of the samples gives bit for bit the result of one never stopped.
    MultipleTauState exportState() const;
    //- Throws std::invalid_argument unless the state comes from a correlator
    //  with the same channels, components, settings and mode.
    void importState(const MultipleTauState& state);

private:
    struct Level
    {
        std::vector<Eigen::ArrayXXd> historyA;   // circular, p slots
        std::vector<Eigen::ArrayXXd> historyB;   // cross mode only
        std::size_t head = 0;                    // newest slot
        std::size_t filled = 0;
        Eigen::ArrayXXd sums;                    // p x components
        std::vector<std::uint64_t> counts;       // p
        Eigen::ArrayXXd accumulatorA, accumulatorB;
        std::size_t accumulated = 0;
    };

    void push
    (
        std::size_t level,
        const Eigen::Ref<const Eigen::ArrayXXd>& a,
        const Eigen::Ref<const Eigen::ArrayXXd>& b
    );
    void checkShape(const Eigen::Ref<const Eigen::ArrayXXd>& x) const;
    // Unnormalised sums and pair counts on the full lag grid (zero counts
    // included), so that block estimates are differences of two snapshots.
    struct RawGrid
    {
        std::vector<std::size_t> lags;
        Eigen::ArrayXXd sums;
        std::vector<std::uint64_t> counts;
    };
    RawGrid rawGrid() const;
    LaggedCorrelation normalise
    (
        const RawGrid& grid,
        const Eigen::ArrayXXd& subtractSums,
        const std::vector<std::uint64_t>& subtractCounts
    ) const;

    std::size_t channels_;
    std::size_t components_;
    MultipleTauSettings settings_;
    bool cross_;
    std::uint64_t samplesAdded_ = 0;
    std::vector<Level> levels_;

    Eigen::ArrayXXd blockStartSums_;
    std::vector<std::uint64_t> blockStartCounts_;
    std::vector<LaggedCorrelation> blocks_;
};

//- Streaming version of seriesProductCorrelations(): S scalar series fed one
//  sample (a vector of S values) at a time; all S*S products C_{ij}(k) =
//  < s_i(0) s_j(k) > from one cross correlator with S*S components.
class SeriesProductCorrelator
{
public:
    explicit SeriesProductCorrelator
    (
        std::size_t seriesCount,
        const MultipleTauSettings& settings = MultipleTauSettings()
    );

    std::size_t seriesCount() const { return seriesCount_; }
    MultipleTauState exportState() const { return correlator_.exportState(); }
    void importState(const MultipleTauState& state) { correlator_.importState(state); }
    void add(const Eigen::Ref<const Eigen::VectorXd>& sample);
    void closeBlock() { correlator_.closeBlock(); }

    //- values column i*S + j holds C_{ij}.
    LaggedCorrelation result() const { return correlator_.result(); }
    const std::vector<LaggedCorrelation>& blocks() const { return correlator_.blocks(); }
    static std::size_t column(std::size_t i, std::size_t j, std::size_t seriesCount)
    {
        return i * seriesCount + j;
    }

private:
    std::size_t seriesCount_;
    MultipleTauCorrelator correlator_;
    Eigen::ArrayXXd left_, right_;
};

} // namespace sdf::correlation

#endif

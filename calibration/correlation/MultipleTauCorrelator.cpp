#include "correlation/MultipleTauCorrelator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sdf::correlation
{

std::vector<double> LaggedCorrelation::times(double sampleInterval) const
{
    std::vector<double> t(lags.size());
    for (std::size_t i = 0; i < lags.size(); ++i)
    {
        t[i] = sampleInterval * static_cast<double>(lags[i]);
    }
    return t;
}

std::vector<double> LaggedCorrelation::column(Eigen::Index c) const
{
    std::vector<double> v(static_cast<std::size_t>(values.rows()));
    for (Eigen::Index i = 0; i < values.rows(); ++i)
    {
        v[i] = values(i, c);
    }
    return v;
}

std::vector<double> LaggedCorrelation::columnMean() const
{
    std::vector<double> v(static_cast<std::size_t>(values.rows()));
    for (Eigen::Index i = 0; i < values.rows(); ++i)
    {
        v[i] = values.row(i).mean();
    }
    return v;
}


MultipleTauCorrelator::MultipleTauCorrelator
(
    std::size_t channels,
    std::size_t components,
    const MultipleTauSettings& settings,
    bool crossCorrelation
)
:
    channels_(channels),
    components_(components),
    settings_(settings),
    cross_(crossCorrelation)
{
    const std::size_t p = settings.pointsPerLevel;
    const std::size_t m = settings.averagingFactor;
    if (channels == 0 || components == 0)
    {
        throw std::invalid_argument("MultipleTauCorrelator: needs >= 1 channel and component");
    }
    if (m < 2 || p < 2 || p % m != 0 || settings.levels == 0)
    {
        throw std::invalid_argument
        (
            "MultipleTauCorrelator: pointsPerLevel " + std::to_string(p)
          + " must be a multiple of averagingFactor " + std::to_string(m)
          + " (>= 2), with >= 1 level"
        );
    }
    const Eigen::Index rows = static_cast<Eigen::Index>(channels);
    const Eigen::Index cols = static_cast<Eigen::Index>(components);
    levels_.resize(settings.levels);
    for (Level& level : levels_)
    {
        level.historyA.assign(p, Eigen::ArrayXXd::Zero(rows, cols));
        if (cross_)
        {
            level.historyB.assign(p, Eigen::ArrayXXd::Zero(rows, cols));
        }
        level.sums = Eigen::ArrayXXd::Zero(static_cast<Eigen::Index>(p), cols);
        level.counts.assign(p, 0);
        level.accumulatorA = Eigen::ArrayXXd::Zero(rows, cols);
        if (cross_)
        {
            level.accumulatorB = Eigen::ArrayXXd::Zero(rows, cols);
        }
    }
    const RawGrid grid = rawGrid();
    blockStartSums_ = Eigen::ArrayXXd::Zero(grid.sums.rows(), grid.sums.cols());
    blockStartCounts_.assign(grid.counts.size(), 0);
}

void MultipleTauCorrelator::checkShape(const Eigen::Ref<const Eigen::ArrayXXd>& x) const
{
    if (x.rows() != static_cast<Eigen::Index>(channels_)
     || x.cols() != static_cast<Eigen::Index>(components_))
    {
        throw std::invalid_argument
        (
            "MultipleTauCorrelator: sample is " + std::to_string(x.rows()) + " x "
          + std::to_string(x.cols()) + ", expected " + std::to_string(channels_)
          + " x " + std::to_string(components_)
        );
    }
}

void MultipleTauCorrelator::add(const Eigen::Ref<const Eigen::ArrayXXd>& a)
{
    if (cross_)
    {
        throw std::logic_error("MultipleTauCorrelator: cross mode needs add(a, b)");
    }
    checkShape(a);
    push(0, a, a);
    ++samplesAdded_;
}

void MultipleTauCorrelator::add
(
    const Eigen::Ref<const Eigen::ArrayXXd>& a,
    const Eigen::Ref<const Eigen::ArrayXXd>& b
)
{
    if (!cross_)
    {
        throw std::logic_error("MultipleTauCorrelator: autocorrelation mode needs add(a)");
    }
    checkShape(a);
    checkShape(b);
    push(0, a, b);
    ++samplesAdded_;
}

void MultipleTauCorrelator::push
(
    std::size_t levelIndex,
    const Eigen::Ref<const Eigen::ArrayXXd>& a,
    const Eigen::Ref<const Eigen::ArrayXXd>& b
)
{
    const std::size_t p = settings_.pointsPerLevel;
    const std::size_t m = settings_.averagingFactor;
    Level& level = levels_[levelIndex];

    level.head = (level.head + p - 1) % p;
    level.historyA[level.head] = a;
    if (cross_)
    {
        level.historyB[level.head] = b;
    }
    if (level.filled < p)
    {
        ++level.filled;
    }

    // Lags below p/m on levels > 0 are already covered, at finer resolution,
    // by the level below.
    const std::size_t firstLag = levelIndex == 0 ? 0 : p / m;
    for (std::size_t j = firstLag; j < level.filled; ++j)
    {
        // The a-value j samples before the newest b-value: a(t) b(t + j).
        const Eigen::ArrayXXd& earlierA = level.historyA[(level.head + j) % p];
        level.sums.row(static_cast<Eigen::Index>(j)) += (earlierA * b).colwise().sum();
        ++level.counts[j];
    }

    level.accumulatorA += a;
    if (cross_)
    {
        level.accumulatorB += b;
    }
    ++level.accumulated;
    if (level.accumulated == m)
    {
        const double inverse = 1.0 / static_cast<double>(m);
        if (levelIndex + 1 < levels_.size())
        {
            // Copies: the next level's push may not alias this accumulator.
            const Eigen::ArrayXXd meanA = level.accumulatorA * inverse;
            if (cross_)
            {
                const Eigen::ArrayXXd meanB = level.accumulatorB * inverse;
                push(levelIndex + 1, meanA, meanB);
            }
            else
            {
                push(levelIndex + 1, meanA, meanA);
            }
        }
        level.accumulatorA.setZero();
        if (cross_)
        {
            level.accumulatorB.setZero();
        }
        level.accumulated = 0;
    }
}

MultipleTauCorrelator::RawGrid MultipleTauCorrelator::rawGrid() const
{
    const std::size_t p = settings_.pointsPerLevel;
    const std::size_t m = settings_.averagingFactor;
    RawGrid grid;
    std::vector<Eigen::ArrayXd> rows;
    std::size_t spacing = 1;
    for (std::size_t l = 0; l < levels_.size(); ++l)
    {
        const std::size_t firstLag = l == 0 ? 0 : p / m;
        for (std::size_t j = firstLag; j < p; ++j)
        {
            grid.lags.push_back(j * spacing);
            grid.counts.push_back(levels_[l].counts[j]);
            rows.push_back(levels_[l].sums.row(static_cast<Eigen::Index>(j)).transpose());
        }
        spacing *= m;
    }
    grid.sums.resize(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(components_));
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
        grid.sums.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
    }
    return grid;
}

LaggedCorrelation MultipleTauCorrelator::normalise
(
    const RawGrid& grid,
    const Eigen::ArrayXXd& subtractSums,
    const std::vector<std::uint64_t>& subtractCounts
) const
{
    LaggedCorrelation result;
    std::vector<Eigen::Index> kept;
    for (std::size_t i = 0; i < grid.lags.size(); ++i)
    {
        if (grid.counts[i] > subtractCounts[i])
        {
            kept.push_back(static_cast<Eigen::Index>(i));
        }
    }
    result.values.resize(static_cast<Eigen::Index>(kept.size()), static_cast<Eigen::Index>(components_));
    for (std::size_t r = 0; r < kept.size(); ++r)
    {
        const Eigen::Index i = kept[r];
        const std::uint64_t pairs = grid.counts[i] - subtractCounts[i];
        result.lags.push_back(grid.lags[i]);
        result.pairs.push_back(pairs * channels_);
        result.values.row(static_cast<Eigen::Index>(r)) =
            (grid.sums.row(i) - subtractSums.row(i))
          / (static_cast<double>(pairs) * static_cast<double>(channels_));
    }
    return result;
}

LaggedCorrelation MultipleTauCorrelator::result() const
{
    const RawGrid grid = rawGrid();
    return normalise
    (
        grid,
        Eigen::ArrayXXd::Zero(grid.sums.rows(), grid.sums.cols()),
        std::vector<std::uint64_t>(grid.counts.size(), 0)
    );
}

void MultipleTauCorrelator::closeBlock()
{
    RawGrid grid = rawGrid();
    blocks_.push_back(normalise(grid, blockStartSums_, blockStartCounts_));
    blockStartSums_ = std::move(grid.sums);
    blockStartCounts_ = std::move(grid.counts);
}


namespace
{

constexpr std::int64_t stateLayoutVersion = 1;

void appendArray(std::vector<double>& reals, const Eigen::ArrayXXd& a)
{
    reals.insert(reals.end(), a.data(), a.data() + a.size());
}

// Reads the flat state back in the order exportState wrote it.
class StateReader
{
public:
    explicit StateReader(const MultipleTauState& state) : state_(state) {}

    std::int64_t integer()
    {
        if (nextInteger_ >= state_.integers.size())
        {
            throw std::invalid_argument("MultipleTauCorrelator::importState: state too short");
        }
        return state_.integers[nextInteger_++];
    }
    std::size_t size() { return static_cast<std::size_t>(integer()); }
    void array(Eigen::ArrayXXd& a)
    {
        const std::size_t n = static_cast<std::size_t>(a.size());
        if (nextReal_ + n > state_.reals.size())
        {
            throw std::invalid_argument("MultipleTauCorrelator::importState: state too short");
        }
        std::copy(state_.reals.begin() + nextReal_, state_.reals.begin() + nextReal_ + n, a.data());
        nextReal_ += n;
    }
    bool finished() const
    {
        return nextInteger_ == state_.integers.size() && nextReal_ == state_.reals.size();
    }

private:
    const MultipleTauState& state_;
    std::size_t nextInteger_ = 0;
    std::size_t nextReal_ = 0;
};

} // namespace

MultipleTauState MultipleTauCorrelator::exportState() const
{
    MultipleTauState state;
    auto put = [&](std::uint64_t v) { state.integers.push_back(static_cast<std::int64_t>(v)); };
    put(stateLayoutVersion);
    put(channels_);
    put(components_);
    put(settings_.pointsPerLevel);
    put(settings_.averagingFactor);
    put(settings_.levels);
    put(cross_ ? 1 : 0);
    put(samplesAdded_);
    for (const Level& level : levels_)
    {
        put(level.head);
        put(level.filled);
        put(level.accumulated);
        for (std::uint64_t count : level.counts)
        {
            put(count);
        }
        for (const Eigen::ArrayXXd& slot : level.historyA)
        {
            appendArray(state.reals, slot);
        }
        for (const Eigen::ArrayXXd& slot : level.historyB)
        {
            appendArray(state.reals, slot);
        }
        appendArray(state.reals, level.sums);
        appendArray(state.reals, level.accumulatorA);
        if (cross_)
        {
            appendArray(state.reals, level.accumulatorB);
        }
    }
    for (std::uint64_t count : blockStartCounts_)
    {
        put(count);
    }
    appendArray(state.reals, blockStartSums_);
    put(blocks_.size());
    for (const LaggedCorrelation& block : blocks_)
    {
        put(block.lags.size());
        for (std::size_t i = 0; i < block.lags.size(); ++i)
        {
            put(block.lags[i]);
            put(block.pairs[i]);
        }
        appendArray(state.reals, block.values);
    }
    return state;
}

void MultipleTauCorrelator::importState(const MultipleTauState& state)
{
    StateReader in(state);
    const bool matches =
        in.integer() == stateLayoutVersion
     && in.size() == channels_
     && in.size() == components_
     && in.size() == settings_.pointsPerLevel
     && in.size() == settings_.averagingFactor
     && in.size() == settings_.levels
     && (in.integer() != 0) == cross_;
    if (!matches)
    {
        throw std::invalid_argument
        (
            "MultipleTauCorrelator::importState: the state comes from a correlator "
            "with other channels, components, settings or mode"
        );
    }
    // Fill a copy, so that a bad state leaves this correlator untouched.
    MultipleTauCorrelator restored(*this);
    restored.samplesAdded_ = static_cast<std::uint64_t>(in.integer());
    for (Level& level : restored.levels_)
    {
        level.head = in.size();
        level.filled = in.size();
        level.accumulated = in.size();
        for (std::uint64_t& count : level.counts)
        {
            count = static_cast<std::uint64_t>(in.integer());
        }
        for (Eigen::ArrayXXd& slot : level.historyA)
        {
            in.array(slot);
        }
        for (Eigen::ArrayXXd& slot : level.historyB)
        {
            in.array(slot);
        }
        in.array(level.sums);
        in.array(level.accumulatorA);
        if (cross_)
        {
            in.array(level.accumulatorB);
        }
    }
    for (std::uint64_t& count : restored.blockStartCounts_)
    {
        count = static_cast<std::uint64_t>(in.integer());
    }
    in.array(restored.blockStartSums_);
    restored.blocks_.assign(in.size(), LaggedCorrelation());
    for (LaggedCorrelation& block : restored.blocks_)
    {
        const std::size_t lags = in.size();
        for (std::size_t i = 0; i < lags; ++i)
        {
            block.lags.push_back(in.size());
            block.pairs.push_back(static_cast<std::uint64_t>(in.integer()));
        }
        block.values.resize(static_cast<Eigen::Index>(lags), static_cast<Eigen::Index>(components_));
        in.array(block.values);
    }
    if (!in.finished())
    {
        throw std::invalid_argument("MultipleTauCorrelator::importState: state too long");
    }
    *this = std::move(restored);
}


SeriesProductCorrelator::SeriesProductCorrelator
(
    std::size_t seriesCount,
    const MultipleTauSettings& settings
)
:
    seriesCount_(seriesCount),
    correlator_(1, seriesCount * seriesCount, settings, true),
    left_(1, seriesCount * seriesCount),
    right_(1, seriesCount * seriesCount)
{}

void SeriesProductCorrelator::add(const Eigen::Ref<const Eigen::VectorXd>& sample)
{
    if (sample.size() != static_cast<Eigen::Index>(seriesCount_))
    {
        throw std::invalid_argument
        (
            "SeriesProductCorrelator: sample has " + std::to_string(sample.size())
          + " values, expected " + std::to_string(seriesCount_)
        );
    }
    // Column i*S + j pairs s_i (earlier) with s_j (later).
    for (std::size_t i = 0; i < seriesCount_; ++i)
    {
        for (std::size_t j = 0; j < seriesCount_; ++j)
        {
            const Eigen::Index c = static_cast<Eigen::Index>(column(i, j, seriesCount_));
            left_(0, c) = sample(static_cast<Eigen::Index>(i));
            right_(0, c) = sample(static_cast<Eigen::Index>(j));
        }
    }
    correlator_.add(left_, right_);
}

} // namespace sdf::correlation

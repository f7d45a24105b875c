#include "Measurements.hpp"

#include "correlation/DiffusiveRegime.hpp"
#include "correlation/GreenKubo.hpp"
#include "correlation/Statistics.hpp"
#include "fit/LawFormulas.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <stdexcept>

namespace sdf::dem
{

namespace
{

correlation::MultipleTauSettings correlatorSettings()
{
    correlation::MultipleTauSettings m;
    m.pointsPerLevel = 16;
    m.averagingFactor = 2;
    m.levels = 24;
    return m;
}

correlation::PlateauSettings plateauSettings(const SamplingPlan& plan)
{
    correlation::PlateauSettings plateau;
    plateau.earliestTime = plan.sampleInterval;
    return plateau;
}

template<class Map>
const typename Map::mapped_type& entry(const Map& map, const std::string& key, const std::string& source)
{
    const auto it = map.find(key);
    if (it == map.end()) throw std::runtime_error("checkpoint '" + source + "': missing " + key);
    return it->second;
}

//- A multiple-tau correlator's state as the checkpoint entries <key>Reals<suffix> and
//  <key>Integers<suffix>, and back.
template<class Correlator>
void saveCorrelator
(
    io::Checkpoint& c,
    const std::string& key,
    const std::string& suffix,
    const Correlator& correlator
)
{
    const correlation::MultipleTauState state = correlator.exportState();
    c.vectors[key + "Reals" + suffix] = state.reals;
    c.integerVectors[key + "Integers" + suffix] = state.integers;
}

template<class Correlator>
void loadCorrelator
(
    const io::Checkpoint& c,
    const std::string& key,
    const std::string& suffix,
    const std::string& source,
    Correlator& correlator
)
{
    correlation::MultipleTauState state;
    state.reals = entry(c.vectors, key + "Reals" + suffix, source);
    state.integers = entry(c.integerVectors, key + "Integers" + suffix, source);
    correlator.importState(state);
}

} // namespace

SamplingPlan::SamplingPlan(const CellRunSettings& settings, double dt)
:
    totalSteps(std::max(1L, std::lround(settings.samplingTime/dt))),
    samples(std::max(1L, totalSteps/settings.sampleEvery)),
    samplesPerBlock(std::max(1L, samples/settings.blocks)),
    sampleInterval(settings.sampleEvery*dt),
    blocks(settings.blocks),
    diffusionComponent(settings.simulation.mode == CellMode::leesEdwards ? 1 : -1)
{}

std::vector<std::vector<int>> speciesMembers(const Simulation& sim)
{
    std::vector<std::vector<int>> members(sim.species().size());
    for (int id = 0; id < int(sim.particles().size()); ++id)
    {
        members[sim.particles().species[sim.indexOfId(id)]].push_back(id);
    }
    return members;
}

// ---------------------------------------------------------------- temperature

TemperatureMeasurement::TemperatureMeasurement(int nSpecies, int blocks, bool perSpecies)
:
    blocks_(blocks),
    perSpecies_(perSpecies),
    species_(perSpecies ? nSpecies : 0)
{}

void TemperatureMeasurement::sample(const Simulation& x, long)
{
    mixture_.push_back(x.temperature());
    if (!perSpecies_) return;
    const std::vector<double> ts = x.speciesTemperatures();
    for (std::size_t s = 0; s < species_.size(); ++s) species_[s].push_back(ts[s]);
}

void TemperatureMeasurement::save(io::Checkpoint& c) const
{
    c.vectors["cellRun_temperature"] = mixture_;
    for (std::size_t s = 0; s < species_.size(); ++s)
    {
        c.vectors["cellRun_speciesT" + std::to_string(s)] = species_[s];
    }
}

void TemperatureMeasurement::load(const io::Checkpoint& c, const std::string& f)
{
    mixture_ = entry(c.vectors, "cellRun_temperature", f);
    for (std::size_t s = 0; s < species_.size(); ++s)
    {
        species_[s] = entry(c.vectors, "cellRun_speciesT" + std::to_string(s), f);
    }
}

void TemperatureMeasurement::finish(CellRunResult& result, long) const
{
    const correlation::Estimate T = correlation::blockAverage(mixture_, blocks_);
    result.temperature = T.value;
    result.temperatureError = T.standardError;
    const SimulationSettings& sim = result.settings.simulation;
    if (sim.mode == CellMode::leesEdwards && T.value > 0)
    {
        result.savageJeffreyR =
            fit::formulas::savageJeffreyR(result.meanDiameter, std::abs(sim.shearRate), T.value);
    }
    for (std::size_t s = 0; s < species_.size(); ++s)
    {
        double sumT = 0;
        for (double v : species_[s]) sumT += v;
        result.species[s].temperature = species_[s].empty() ? 0 : sumT/species_[s].size();
        if (species_[s].size() >= std::size_t(std::max(2, blocks_)))
        {
            result.species[s].temperatureError =
                correlation::blockAverage(species_[s], blocks_).standardError;
        }
    }
}

// ---------------------------------------------------------------- rheology

RheologyMeasurement::RheologyMeasurement(int blocks)
:
    blocks_(blocks)
{}

void RheologyMeasurement::sample(const Simulation& x, long)
{
    const Eigen::Matrix3d J = x.totalStress();
    const double volume = x.box().volume();
    const Simulation::ContactSummary contacts = x.contactSummary();
    normal_.push_back(J(1, 1)/volume);
    shear_.push_back(J(0, 1)/volume);
    phi_.push_back(x.solidsFraction());
    coordination_.push_back(2.0*double(contacts.contacts)/double(x.particles().size()));
    overlap_.push_back(contacts.meanOverlapFraction);
    bondOrder_.push_back(contacts.bondOrderQ6);
}

void RheologyMeasurement::save(io::Checkpoint& c) const
{
    c.vectors["cellRun_rheologyNormal"] = normal_;
    c.vectors["cellRun_rheologyShear"] = shear_;
    c.vectors["cellRun_rheologyPhi"] = phi_;
    c.vectors["cellRun_rheologyCoordination"] = coordination_;
    c.vectors["cellRun_rheologyOverlap"] = overlap_;
    c.vectors["cellRun_rheologyBondOrder"] = bondOrder_;
}

void RheologyMeasurement::load(const io::Checkpoint& c, const std::string& f)
{
    normal_ = entry(c.vectors, "cellRun_rheologyNormal", f);
    shear_ = entry(c.vectors, "cellRun_rheologyShear", f);
    phi_ = entry(c.vectors, "cellRun_rheologyPhi", f);
    coordination_ = entry(c.vectors, "cellRun_rheologyCoordination", f);
    overlap_ = entry(c.vectors, "cellRun_rheologyOverlap", f);
    bondOrder_ = entry(c.vectors, "cellRun_rheologyBondOrder", f);
}

void RheologyMeasurement::finish(CellRunResult& result, long) const
{
    RheologyResult& r = result.rheology;
    const CellRunSettings& settings = result.settings;
    r.measured = true;
    r.pressureControlled = settings.simulation.targetPressure > 0;
    r.targetPressure = settings.simulation.targetPressure;
    r.meanDiameter = result.meanDiameter;
    r.solidsDensity = solidsDensity(settings);
    const double gammaDot = std::abs(settings.simulation.shearRate);

    // per block: the means, and mu and I from them (ratios of means, not means of ratios)
    struct Block { double p, tau, mu, I, phi, Z, overlap, Q6; };
    const auto mean = [](const std::vector<double>& v, std::size_t b, std::size_t e)
    {
        double sum = 0;
        for (std::size_t k = b; k < e; ++k) sum += v[k];
        return e > b ? sum/double(e - b) : 0.0;
    };
    const std::vector<Block> blocks = correlation::forEachBlock
    (
        normal_.size(), std::size_t(blocks_),
        [&](std::size_t b, std::size_t e)
        {
            Block k;
            k.p = mean(normal_, b, e);
            k.tau = std::abs(mean(shear_, b, e));
            k.mu = k.p > 0 ? k.tau/k.p : 0.0;
            k.I = k.p > 0 ? gammaDot*r.meanDiameter/std::sqrt(k.p/r.solidsDensity) : 0.0;
            k.phi = mean(phi_, b, e);
            k.Z = mean(coordination_, b, e);
            k.overlap = mean(overlap_, b, e);
            k.Q6 = mean(bondOrder_, b, e);
            return k;
        }
    );
    const auto estimate = [&](double Block::*field, std::size_t from, std::size_t to)
    {
        std::vector<double> values;
        for (std::size_t b = from; b < to; ++b) values.push_back(blocks[b].*field);
        return correlation::meanAndStandardError(values);
    };
    const std::size_t nb = blocks.size();
    std::size_t tensileBlocks = 0;
    for (const Block& k : blocks) tensileBlocks += k.p > 0 ? 0 : 1;
    r.pressure = estimate(&Block::p, 0, nb);
    r.shearStress = estimate(&Block::tau, 0, nb);
    r.stressRatio = estimate(&Block::mu, 0, nb);
    r.inertialNumber = estimate(&Block::I, 0, nb);
    r.solidsFraction = estimate(&Block::phi, 0, nb);
    r.coordinationNumber = estimate(&Block::Z, 0, nb);
    r.meanOverlapFraction = estimate(&Block::overlap, 0, nb);
    r.bondOrder = estimate(&Block::Q6, 0, nb);

    // steady: the halves of the sampling agree (a drift of phi or mu shows as a difference)
    std::ostringstream check;
    r.steady = nb >= 4;
    if (nb < 4) check << "needs blocks >= 4 (2 per half), has " << nb;
    // a difference below `floor` is steady whatever its errors (immaterial for a law, and
    // slow fluctuations in a small cell can make it a few block errors)
    for (const auto& [name, field, floor] :
         {std::tuple{"phi", &Block::phi, 1e-3}, std::tuple{"mu", &Block::mu, 5e-3}})
    {
        if (nb < 4) break;
        const correlation::Estimate first = estimate(field, 0, nb/2);
        const correlation::Estimate second = estimate(field, nb - nb/2, nb);
        const double combined = std::hypot(first.standardError, second.standardError);
        const double difference = second.value - first.value;
        const double sigmas = combined > 0 ? std::abs(difference)/combined
                                           : (difference == 0 ? 0.0 : HUGE_VAL);
        if (sigmas > 3 && std::abs(difference) > floor) r.steady = false;
        check << (name == std::string("phi") ? "" : "; ") << name << " second half - first "
              << difference << " (" << sigmas << " combined standard errors)";
    }
    r.steadyCheck = check.str();

    const double I = r.inertialNumber.value, Z = r.coordinationNumber.value;
    const double maxBondOrder = RheologyResult::maximumBondOrder(Z, result.settings.particles);
    std::ostringstream why;
    if (tensileBlocks > 0)
    {
        // mu and I have no meaning there (their blocks were counted as 0)
        r.regime = "gas";
        r.steady = false;
        why << "sigma_yy <= 0 in " << tensileBlocks << " of " << nb << " blocks: no dense"
            << " rheology";
    }
    else if (I < RheologyResult::minimumInertialNumber)
    {
        r.regime = "jammed";
        why << "I = " << I << " < " << RheologyResult::minimumInertialNumber
            << ": quasi-static, no inertial rheology to measure";
    }
    else if (I > RheologyResult::maximumInertialNumber || Z < 1)
    {
        r.regime = "gas";
        why << "I = " << I << ", Z = " << Z << ": outside the dense regime (I <= "
            << RheologyResult::maximumInertialNumber << " and Z >= 1)";
    }
    else if (r.bondOrder.value > maxBondOrder)
    {
        // one size at low friction orders into layers that slide over each other: a
        // steady flow, but of a crystal, whose mu and phi are not the bulk's
        r.regime = "ordered";
        why << "bond order Q6 = " << r.bondOrder.value << " > " << maxBondOrder << " (phi "
            << r.solidsFraction.value
            << "): the grains crystallised into ordered layers, not a disordered bulk's"
            << " rheology (a size spread or more friction keeps a packing disordered)";
    }
    else
    {
        r.regime = "dense flow";
        why << "I = " << I << ", Z = " << Z << ", Q6 = " << r.bondOrder.value;
    }
    r.regimeReason = why.str();
}

// ---------------------------------------------------------------- velocity autocorrelation

long msdFramesEvery(const SamplingPlan& plan, int maxFrames)
{
    return std::max(1L, (plan.samples + maxFrames - 1)/maxFrames);
}

std::size_t msdLongestLagFrames(std::size_t frames, int blocks)
{
    return frames/std::size_t(std::max(1, blocks))/2;
}

double longestMsdLag(const SamplingPlan& plan, int maxFrames)
{
    // the frames MeanSquareDisplacementMeasurement takes: the sample indices that are
    // multiples of framesEvery
    const long every = msdFramesEvery(plan, maxFrames);
    const std::size_t frames = std::size_t((plan.samples + every - 1)/every);
    return double(msdLongestLagFrames(frames, plan.blocks)*every)*plan.sampleInterval;
}

VelocityAutocorrelation::VelocityAutocorrelation
(
    std::vector<std::vector<int>> members,
    const SamplingPlan& plan,
    int maxMsdFrames
)
:
    members_(std::move(members)),
    plan_(plan),
    longestMsdLag_(longestMsdLag(plan, maxMsdFrames))
{
    for (const std::vector<int>& m : members_)
    {
        correlators_.emplace_back(std::max<std::size_t>(1, m.size()), 3, correlatorSettings());
    }
}

void VelocityAutocorrelation::sample(const Simulation& x, long)
{
    for (std::size_t s = 0; s < members_.size(); ++s)
    {
        const std::vector<int>& m = members_[s];
        if (m.empty()) continue;
        Eigen::ArrayXXd v(m.size(), 3);
        for (std::size_t k = 0; k < m.size(); ++k)
        {
            const Eigen::Vector3d c = x.fluctuatingVelocity(x.indexOfId(m[k]));
            v(k, 0) = c.x(); v(k, 1) = c.y(); v(k, 2) = c.z();
        }
        correlators_[s].add(v);
    }
}

void VelocityAutocorrelation::closeBlock()
{
    for (auto& c : correlators_) c.closeBlock();
}

void VelocityAutocorrelation::save(io::Checkpoint& c) const
{
    for (std::size_t s = 0; s < correlators_.size(); ++s)
    {
        saveCorrelator(c, "cellRun_vacf", std::to_string(s), correlators_[s]);
    }
}

void VelocityAutocorrelation::load(const io::Checkpoint& c, const std::string& f)
{
    for (std::size_t s = 0; s < correlators_.size(); ++s)
    {
        loadCorrelator(c, "cellRun_vacf", std::to_string(s), f, correlators_[s]);
    }
}

void VelocityAutocorrelation::finish(CellRunResult& result, long) const
{
    for (std::size_t s = 0; s < correlators_.size(); ++s)
    {
        if (members_[s].empty() || correlators_[s].blocks().size() < 2) continue;
        // The plateau is searched from the Einstein window's start, past the VACF's
        // decay: an earlier plateau would stop before a slow tail is integrated
        // (DiffusiveRegime.hpp); the MSD finish takes the window from the same tau_v.
        const correlation::GreenKuboResult first = correlation::greenKubo
        (
            correlators_[s].blocks(), plan_.sampleInterval, plan_.diffusionComponent,
            plateauSettings(plan_)
        );
        // tau_v from lags up to half a block, the MSD's longest
        const double tauV = correlation::velocityCorrelationTime(first, longestMsdLag_);
        // ... and the plateau read within the MSD's lags: Green-Kubo and the Einstein
        // fit then measure the same stretch of the VACF, and differ only if it has not
        // decayed there (the check's item 3 then says so). Like the Einstein window, a
        // plateau window ending at the MSD's longest lag may span 1.5 instead of 2.
        const correlation::DiffusiveRegimeSettings regime;
        correlation::PlateauSettings pastDecay = plateauSettings(plan_);
        pastDecay.earliestTime = std::max
        (
            pastDecay.earliestTime, regime.windowStartCorrelationTimes*tauV
        );
        pastDecay.latestTime = longestMsdLag_;
        pastDecay.clippedWindowRatio = regime.minimumWindowRatio;
        SpeciesTransport& st = result.species[s];
        st.greenKubo = correlation::greenKubo
        (
            correlators_[s].blocks(), plan_.sampleInterval, plan_.diffusionComponent,
            pastDecay
        );
        // what the MSD's finish starts from (and all a species without an MSD gets)
        st.diffusiveRegime.correlationTime = tauV;
        st.diffusiveRegime.plateauFound = st.greenKubo.plateauFound;
    }
}

// ---------------------------------------------------------------- mean-square displacement

MeanSquareDisplacementMeasurement::MeanSquareDisplacementMeasurement
(
    std::vector<std::vector<int>> members,
    const SamplingPlan& plan,
    int maxFrames
)
:
    members_(std::move(members)),
    plan_(plan),
    framesEvery_(msdFramesEvery(plan, maxFrames)),
    frames_(members_.size())
{}

void MeanSquareDisplacementMeasurement::sample(const Simulation& x, long index)
{
    if (index % framesEvery_ != 0) return;
    const Particles& p = x.particles();
    for (std::size_t s = 0; s < members_.size(); ++s)
    {
        const std::vector<int>& m = members_[s];
        if (m.empty()) continue;
        Eigen::MatrixX3d pos(m.size(), 3);
        for (std::size_t k = 0; k < m.size(); ++k)
        {
            const int i = x.indexOfId(m[k]);
            pos(k, 0) = p.ux[i]; pos(k, 1) = p.uy[i]; pos(k, 2) = p.uz[i];
        }
        frames_[s].push_back(pos);
    }
}

void MeanSquareDisplacementMeasurement::save(io::Checkpoint& c) const
{
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        std::vector<double> v;
        for (const Eigen::MatrixX3d& m : frames_[s])
        {
            for (Eigen::Index r = 0; r < m.rows(); ++r)
            {
                v.push_back(m(r, 0)); v.push_back(m(r, 1)); v.push_back(m(r, 2));
            }
        }
        c.vectors["cellRun_frames" + std::to_string(s)] = v;
    }
}

void MeanSquareDisplacementMeasurement::load(const io::Checkpoint& c, const std::string& f)
{
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        const std::vector<double>& fl = entry(c.vectors, "cellRun_frames" + std::to_string(s), f);
        const std::size_t rows = members_[s].size();
        frames_[s].clear();
        if (rows == 0) continue;
        for (std::size_t off = 0; off + 3*rows <= fl.size(); off += 3*rows)
        {
            Eigen::MatrixX3d m(rows, 3);
            for (std::size_t r = 0; r < rows; ++r)
            {
                m(r, 0) = fl[off + 3*r]; m(r, 1) = fl[off + 3*r + 1]; m(r, 2) = fl[off + 3*r + 2];
            }
            frames_[s].push_back(m);
        }
    }
}

void MeanSquareDisplacementMeasurement::finish(CellRunResult& result, long) const
{
    // Einstein: MSD of y (sheared) or x+y+z (homogeneous) per block, fitted from
    // windowStartCorrelationTimes tau_v (from the VACF's Green-Kubo, finished before
    // this) to the longest lag, half a block; then the diffusive-regime check
    const int comp = plan_.diffusionComponent;
    const std::size_t nBlocks = std::size_t(plan_.blocks);
    for (std::size_t s = 0; s < frames_.size(); ++s)
    {
        const std::size_t nFrames = frames_[s].size();
        if (members_[s].empty() || nFrames < 8*nBlocks) continue;
        const std::size_t maxLag = msdLongestLagFrames(nFrames, plan_.blocks);
        const auto blockMsd = correlation::blockEstimates
        (
            correlation::meanSquareDisplacement, frames_[s], maxLag, nBlocks
        );
        const double frameInterval = framesEvery_*plan_.sampleInterval;
        std::vector<double> times(maxLag + 1);
        for (std::size_t k = 0; k <= maxLag; ++k) times[k] = k*frameInterval;
        std::vector<std::vector<double>> series;
        for (const Eigen::MatrixX3d& b : blockMsd)
        {
            std::vector<double> v(maxLag + 1);
            for (std::size_t k = 0; k <= maxLag; ++k)
            {
                v[k] = comp == 1 ? b(k, 1) : b(k, 0) + b(k, 1) + b(k, 2);
            }
            series.push_back(v);
        }
        SpeciesTransport& st = result.species[s];
        const double tauV = st.diffusiveRegime.correlationTime;
        const correlation::EinsteinWindow window =
            correlation::diffusiveWindow(tauV, times, comp == 1 ? 1 : 3);
        const auto einstein = correlation::einsteinDiffusivity(times, series, window);
        st.diffusivityMsd = einstein.diffusivity;
        st.diffusiveRegime = correlation::checkDiffusiveRegime
        (
            times, series, window, einstein, st.greenKubo, tauV
        );
        st.msdTimes = times;
        st.msd = einstein.meanMsd;
    }
}

// ---------------------------------------------------------------- stress

std::vector<std::string> StressAutocorrelation::seriesNames(const std::vector<Species>& species)
{
    std::vector<std::string> names;
    const std::size_t n = species.size();
    for (std::size_t s = 0; s < n; ++s) names.push_back("J_" + species[s].name);
    for (std::size_t s = 0; s < n; ++s)
    {
        for (std::size_t t = s + 1; t < n; ++t)
        {
            names.push_back("J_" + species[s].name + "_" + species[t].name);
        }
    }
    return names;
}

namespace
{

std::vector<std::pair<int, int>> stressParts(int nSpecies)
{
    std::vector<std::pair<int, int>> parts;
    for (int s = 0; s < nSpecies; ++s) parts.push_back({s, s});
    for (int s = 0; s < nSpecies; ++s)
    {
        for (int t = s + 1; t < nSpecies; ++t) parts.push_back({s, t});
    }
    return parts;
}

} // namespace

StressAutocorrelation::StressAutocorrelation
(
    const std::vector<Species>& species,
    double volume,
    const SamplingPlan& plan
)
:
    parts_(stressParts(int(species.size()))),
    volume_(volume),
    plan_(plan),
    correlator_(parts_.size(), correlatorSettings()),
    stressSum_(parts_.size(), 0.0),
    blockSum_(parts_.size(), 0.0)
{}

void StressAutocorrelation::sample(const Simulation& x, long)
{
    const double sqrtV = std::sqrt(volume_);
    const StressSplit J = x.stressSplit();
    Eigen::VectorXd series(parts_.size());
    for (std::size_t k = 0; k < parts_.size(); ++k)
    {
        const auto [a, b] = parts_[k];
        const Eigen::Matrix3d Jk = a == b ? J.speciesStress(a) : J.crossStress(a, b);
        series[k] = Jk(0, 1)/sqrtV;
        stressSum_[k] += Jk(0, 1)/volume_;
        blockSum_[k] += series[k];
    }
    ++blockSamples_;
    correlator_.add(series);
}

void StressAutocorrelation::closeBlock()
{
    correlator_.closeBlock();
    std::vector<double> mean = blockSum_;
    for (double& m : mean) m /= std::max(1L, blockSamples_);
    blockMeans_.push_back(mean);
    std::fill(blockSum_.begin(), blockSum_.end(), 0.0);
    blockSamples_ = 0;
}

void StressAutocorrelation::save(io::Checkpoint& c) const
{
    c.vectors["cellRun_meanStress"] = stressSum_;
    // the open block's sums, its sample count last; the closed blocks' means in a row
    std::vector<double> open = blockSum_;
    open.push_back(double(blockSamples_));
    c.vectors["cellRun_stressBlockSum"] = open;
    std::vector<double> closed;
    for (const std::vector<double>& m : blockMeans_) closed.insert(closed.end(), m.begin(), m.end());
    c.vectors["cellRun_stressBlockMeans"] = closed;
    saveCorrelator(c, "cellRun_stress", "", correlator_);
}

void StressAutocorrelation::load(const io::Checkpoint& c, const std::string& f)
{
    stressSum_ = entry(c.vectors, "cellRun_meanStress", f);
    const std::vector<double>& open = entry(c.vectors, "cellRun_stressBlockSum", f);
    const std::vector<double>& closed = entry(c.vectors, "cellRun_stressBlockMeans", f);
    const std::size_t n = parts_.size();
    if (open.size() != n + 1 || closed.size() % n != 0)
    {
        throw std::invalid_argument
        (
            "checkpoint '" + f + "': the stress block sums do not match " + std::to_string(n)
          + " stress series"
        );
    }
    blockSum_.assign(open.begin(), open.end() - 1);
    blockSamples_ = long(open.back());
    blockMeans_.clear();
    for (std::size_t b = 0; b < closed.size()/n; ++b)
    {
        blockMeans_.emplace_back(closed.begin() + long(b*n), closed.begin() + long((b + 1)*n));
    }
    loadCorrelator(c, "cellRun_stress", "", f, correlator_);
    if (blockMeans_.size() != correlator_.blocks().size())
    {
        throw std::invalid_argument
        (
            "checkpoint '" + f + "': " + std::to_string(blockMeans_.size()) + " stress block means"
            " for " + std::to_string(correlator_.blocks().size()) + " correlator blocks"
        );
    }
}

void StressAutocorrelation::finish(CellRunResult& result, long samples) const
{
    result.meanStress = stressSum_;
    for (double& m : result.meanStress) m /= std::max(1L, samples);
    if (correlator_.blocks().size() < 2) return;
    // about the means (a sheared cell's shear stress has one): the run's, in the series'
    // units J/sqrt(V), with each block's own in the linear terms
    std::vector<double> runMean = result.meanStress;
    for (double& m : runMean) m *= std::sqrt(volume_);
    result.stressIntegrals = correlation::stressProductIntegrals
    (
        correlation::aboutMeans(correlator_.blocks(), blockMeans_, runMean),
        plan_.sampleInterval, parts_.size(), plateauSettings(plan_)
    );
    if (result.settings.species.size() == 2)
    {
        result.kineticSieving = correlation::kineticSievingCoefficients
        (
            result.stressIntegrals, result.settings.volumeFractions
        );
        result.kineticSievingWithCrossTerms =
            correlation::kineticSievingCoefficientsWithCrossTerms
            (
                result.stressIntegrals, result.settings.volumeFractions
            );
    }
}

// ---------------------------------------------------------------- collective motion

CollectiveMotionMeasurement::CollectiveMotionMeasurement(int blocks)
:
    blocks_(blocks)
{}

void CollectiveMotionMeasurement::sample(const Simulation& x, long)
{
    const Particles& p = x.particles();
    const PeriodicBox& box = x.box();
    const double twoPi = 2*M_PI;
    const double k[3] = {twoPi/box.lx, twoPi/box.ly, twoPi/box.lz};
    // j[b][a]: component a of the momentum density's mode along axis b (re, im)
    double re[3][3] = {}, im[3][3] = {}, equipartition[3] = {};
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Eigen::Vector3d c = x.fluctuatingVelocity(int(i));
        const double position[3] = {p.x[i], p.y[i], p.z[i]};
        const double m = p.mass[i];
        for (int b = 0; b < 3; ++b)
        {
            const double phase = k[b]*position[b];
            const double cs = std::cos(phase), sn = std::sin(phase);
            for (int a = 0; a < 3; ++a)
            {
                re[b][a] += m*c[a]*cs;
                im[b][a] -= m*c[a]*sn;
            }
        }
        for (int a = 0; a < 3; ++a) equipartition[a] += m*m*c[a]*c[a];
    }
    double modes[2] = {}, expected[2] = {};   // transverse, longitudinal
    for (int b = 0; b < 3; ++b)
    {
        for (int a = 0; a < 3; ++a)
        {
            const int part = a == b ? 1 : 0;
            modes[part] += re[b][a]*re[b][a] + im[b][a]*im[b][a];
            expected[part] += equipartition[a];
        }
    }
    sums_[0].push_back(modes[0]);
    sums_[1].push_back(expected[0]);
    sums_[2].push_back(modes[1]);
    sums_[3].push_back(expected[1]);
}

void CollectiveMotionMeasurement::save(io::Checkpoint& c) const
{
    for (int k = 0; k < 4; ++k) c.vectors["cellRun_collectiveMotion" + std::to_string(k)] = sums_[k];
}

void CollectiveMotionMeasurement::load(const io::Checkpoint& c, const std::string& f)
{
    for (int k = 0; k < 4; ++k)
    {
        sums_[k] = entry(c.vectors, "cellRun_collectiveMotion" + std::to_string(k), f);
    }
}

void CollectiveMotionMeasurement::finish(CellRunResult& result, long) const
{
    const std::size_t n = sums_[0].size();
    if (n < std::size_t(blocks_) || blocks_ < 2) return;
    const auto ratios = [&](int modes)
    {
        return correlation::forEachBlock
        (
            n, std::size_t(blocks_), [&](std::size_t begin, std::size_t end)
            {
                double num = 0, den = 0;
                for (std::size_t i = begin; i < end; ++i)
                {
                    num += sums_[modes][i];
                    den += sums_[modes + 1][i];
                }
                return den > 0 ? num/den : 0.0;
            }
        );
    };
    result.collectiveMotionTransverse = correlation::meanAndStandardError(ratios(0));
    result.collectiveMotionLongitudinal = correlation::meanAndStandardError(ratios(2));
}

// ---------------------------------------------------------------- collisions

CollisionMeasurement::CollisionMeasurement(Simulation& simulation, double energyScale)
:
    simulation_(simulation)
{
    simulation_.enableCollisionStatistics(1e-4*energyScale, 1e3*energyScale, 56);
}

void CollisionMeasurement::save(io::Checkpoint& c) const
{
    const CollisionStatistics& col = simulation_.collisionStatistics();
    c.scalars["cellRun_collisionTime"] = col.elapsedTime;
    c.vectors["cellRun_collisionEnergy"] = col.energySum;
    c.integerVectors["cellRun_collisionCounts"].assign(col.counts.begin(), col.counts.end());
    std::vector<std::int64_t> hist;
    for (const auto& h : col.histogram) hist.insert(hist.end(), h.begin(), h.end());
    c.integerVectors["cellRun_collisionHistogram"] = hist;
}

void CollisionMeasurement::load(const io::Checkpoint& c, const std::string& f)
{
    CollisionStatistics col = simulation_.collisionStatistics();
    col.elapsedTime = entry(c.scalars, "cellRun_collisionTime", f);
    col.energySum = entry(c.vectors, "cellRun_collisionEnergy", f);
    const auto& counts = entry(c.integerVectors, "cellRun_collisionCounts", f);
    col.counts.assign(counts.begin(), counts.end());
    const auto& hist = entry(c.integerVectors, "cellRun_collisionHistogram", f);
    const std::size_t nb = col.histogram.empty() ? 0 : col.histogram[0].size();
    if (hist.size() != nb*col.histogram.size())
    {
        throw std::runtime_error("checkpoint '" + f + "': collision histogram does not fit");
    }
    for (std::size_t a = 0; a < col.histogram.size(); ++a)
    {
        for (std::size_t b = 0; b < nb; ++b) col.histogram[a][b] = hist[a*nb + b];
    }
    simulation_.setCollisionStatistics(col);
}

void CollisionMeasurement::finish(CellRunResult& result, long) const
{
    result.collisions = simulation_.collisionStatistics();
}

} // namespace sdf::dem

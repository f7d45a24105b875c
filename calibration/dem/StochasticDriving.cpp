#include "StochasticDriving.hpp"
#include "ThreadTeam.hpp"

#include <Random123/boxmuller.hpp>
#include <Random123/philox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

namespace
{

//- The key's second word: the stream of the driving's kicks (another use of the same seed
//  would take another constant).
constexpr std::uint64_t kickStream = 0x5344462d6b69636bULL;   // "SDF-kick"

} // namespace

StochasticDriving::StochasticDriving
(
    double targetTemperature,
    double steeringTime,
    double timeStep,
    std::uint64_t seed
)
:
    targetTemperature_(targetTemperature),
    steeringTime_(steeringTime),
    timeStep_(timeStep),
    seed_(seed)
{
    if (!(targetTemperature > 0) || !std::isfinite(targetTemperature))
    {
        throw std::invalid_argument
        (
            "stochastic cell: targetTemperature (temperature) must be positive, got "
          + std::to_string(targetTemperature)
        );
    }
    if (!(timeStep > 0) || !(steeringTime > timeStep) || !std::isfinite(steeringTime))
    {
        throw std::invalid_argument
        (
            "stochastic cell: thermostatTime (the kicks' steering time) must exceed the time"
            " step " + std::to_string(timeStep) + " s, got " + std::to_string(steeringTime)
        );
    }
}

void StochasticDriving::normals
(
    std::uint64_t seed,
    std::uint64_t kick,
    std::uint64_t id,
    double out[3]
)
{
    using Philox = r123::Philox4x64;
    const Philox::ctr_type counter = {{kick, id, 0, 0}};
    const Philox::key_type key = {{seed, kickStream}};
    const Philox::ctr_type bits = Philox()(counter, key);
    const r123::double2 a = r123::boxmuller(bits[0], bits[1]);
    const r123::double2 b = r123::boxmuller(bits[2], bits[3]);
    out[0] = a.x;
    out[1] = a.y;
    out[2] = b.x;
}

bool StochasticDriving::beginForcePass(int nParticles, bool endsStep)
{
    // the velocity totals are read on kick steps only
    return sums_.begin(nParticles, endsStep && kicksThisStep());
}

void StochasticDriving::finishRange(const Particles& p, int begin, int end)
{
    sums_.addRange(p, begin, end);
}

bool StochasticDriving::kicksThisStep() const
{
    return (step_ + 1) % kickInterval == 0;
}

bool StochasticDriving::wantsElasticEnergy() const
{
    return kicksThisStep();
}

void StochasticDriving::afterStep(Particles& p, int nThreads)
{
    const int n = int(p.size());
    if (n < 2) return;
    const bool kicks = kicksThisStep();
    const std::uint64_t step = step_++;
    if (!kicks) return;
    const std::uint64_t kick = step/kickInterval;
    // Theta = T (1 + E_el/K): T with the contacts' elastic energy counted in, at the
    // present ratio T/K (K the peculiar kinetic energy)
    const auto held = [this](double T, const VelocityChunkSums::Totals& totals)
    {
        const double K = kineticEnergyAboutMean(totals);
        return K > 0 ? T*(1 + elasticEnergy_/K) : T;
    };
    double u[3];
    const VelocityChunkSums::Totals before = sums_.totals(p);
    const double T = temperatureAboutMean(before, n, u);
    // Steering: the collisions' dissipation per step, L (the fall of Theta over the kick
    // interval, per step), is taken as c T^(3/2) (a hard-sphere gas's), c = <L>/<T^(3/2)>
    // averaged over all intervals so far and then exponentially over tau; the kicks put
    // back c T0^(3/2) a step plus a relaxation of T towards T0 over tau. At steady state
    // T = T0 whatever the true dependence on T (c is measured at that state), and T
    // follows its error at the rate of its own dissipation: no slow integral loop
    // (putting back <L> itself recovered from the start-up's transient with a root of
    // only (dt/tau)^2/(dt dL/dT) per step: T 4.5 % low after 16 tau at phi 0.5)
    const double w = timeStep_/steeringTime_;
    if (heldAfterKick_ >= 0)
    {
        const double weight = std::min
        (
            1.0, std::max(kickInterval*w, 1.0/double(std::max<std::uint64_t>(kick, 1)))
        );
        // (T can come out a rounding error below 0 in a cell at rest)
        const double loss = (heldAfterKick_ - held(T, before))/kickInterval;
        dissipation_ += weight*(loss - dissipation_);
        // T^(3/2) averaged over the interval, T falling about linearly from its value after
        // the last kicks to T now (as when it was averaged over every step; T now alone is
        // the sawtooth's low point)
        const double meanT = T + 0.5*kickInterval*loss;
        temperaturePower_ += weight*(std::pow(std::max(meanT, 0.0), 1.5) - temperaturePower_);
    }
    const double restore = temperaturePower_ > 0
        ? dissipation_/temperaturePower_*std::pow(targetTemperature_, 1.5)
        : dissipation_;

    // The kicks' standard normals, and per fixed chunk (summed in chunk order below: the
    // same totals whatever the threads, and in a resumed run) the mass, its square and
    // the normals' momentum
    normalX_.resize(std::size_t(n));
    normalY_.resize(std::size_t(n));
    normalZ_.resize(std::size_t(n));
    const int nChunks = (n + finishChunk - 1)/finishChunk;
    std::vector<std::array<double, 5>> chunkSums(static_cast<std::size_t>(nChunks));
    forEachIndex(nThreads, nChunks, [&](int c)
    {
        std::array<double, 5> sum{};
        for (int i = c*finishChunk; i < std::min(n, (c + 1)*finishChunk); ++i)
        {
            double xi[3];
            normals(seed_, kick, std::uint64_t(p.id[i]), xi);
            normalX_[i] = xi[0];
            normalY_[i] = xi[1];
            normalZ_[i] = xi[2];
            const double m = p.mass[i];
            sum[0] += m; sum[1] += m*m;
            sum[2] += m*xi[0]; sum[3] += m*xi[1]; sum[4] += m*xi[2];
        }
        chunkSums[std::size_t(c)] = sum;
    });
    std::array<double, 5> total{};
    for (const auto& sum : chunkSums)
    {
        for (int k = 0; k < 5; ++k) total[k] += sum[k];
    }
    if (!(total[0] > 0)) return;

    // Removing the kicks' mass-weighted mean U leaves sum_i |kick_i - U|^2/n =
    // 3 a2 (1 - 2/n + sum m^2/M^2) on average: divided out (1/n of T at equal masses)
    const double kept = 1 - 2.0/n + total[1]/(total[0]*total[0]);
    kickVariance_ =
        std::max(0.0, kickInterval*(restore + w*(targetTemperature_ - T)))/(3.0*kept);
    const double amplitude = std::sqrt(kickVariance_);
    const double ux = amplitude*total[2]/total[0];
    const double uy = amplitude*total[3]/total[0];
    const double uz = amplitude*total[4]/total[0];
    forEachIndex(nThreads, n, [&](int i)
    {
        p.vx[i] += amplitude*normalX_[i] - ux;
        p.vy[i] += amplitude*normalY_[i] - uy;
        p.vz[i] += amplitude*normalZ_[i] - uz;
    });
    const VelocityChunkSums::Totals after = VelocityChunkSums::sum(p);
    heldAfterKick_ = held(temperatureAboutMean(after, n, u), after);
}

std::vector<double> StochasticDriving::exportState() const
{
    // the step count as a double: exact below 2^53 steps; the seed in two exact halves
    // (a resume with another seed would change the kicks unnoticed); the format last
    return
    {
        double(step_), dissipation_, temperaturePower_, heldAfterKick_, kickVariance_,
        double(seed_ >> 32), double(seed_ & 0xffffffffULL), double(stateFormat)
    };
}

void StochasticDriving::importState(const std::vector<double>& state)
{
    if (state.size() == 7)
    {
        // format 1 held T after the kicks where format 2 holds Theta: resumed, the first
        // interval would be steered on a wrong loss and the run not continued bitwise
        throw std::invalid_argument
        (
            "stochastic driving: the checkpoint's driving state is of the engine before its"
            " steering counted the contacts' elastic energy (7 values): run the condition"
            " again from its start (delete the checkpoint)"
        );
    }
    if (state.size() != 8 || state[7] != double(stateFormat))
    {
        throw std::invalid_argument
        (
            "stochastic driving: a checkpoint's driving state holds 8 values (step,"
            " dissipation, <T^1.5>, Theta after the kicks (T with the elastic energy), kick"
            " variance, seed in two halves, format " + std::to_string(stateFormat) + "), got "
          + std::to_string(state.size())
        );
    }
    const std::uint64_t seed = (std::uint64_t(state[5]) << 32) | std::uint64_t(state[6]);
    if (seed != seed_)
    {
        throw std::invalid_argument
        (
            "stochastic driving: the checkpoint was run with seed " + std::to_string(seed)
          + ", this run has seed " + std::to_string(seed_) + " (entry 'seed')"
        );
    }
    step_ = std::uint64_t(state[0]);
    dissipation_ = state[1];
    temperaturePower_ = state[2];
    heldAfterKick_ = state[3];
    kickVariance_ = state[4];
}

} // namespace sdf::dem

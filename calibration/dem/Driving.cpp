#include "Driving.hpp"
#include "ThreadTeam.hpp"
#include "StochasticDriving.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sdf::dem
{

CellMode cellModeFromName(const std::string& name)
{
    if (name == "nve") return CellMode::nve;
    if (name == "thermostatted" || name == "driven") return CellMode::thermostatted;
    if (name == "leesEdwards" || name == "shear") return CellMode::leesEdwards;
    if (name == "stochastic") return CellMode::stochastic;
    throw std::invalid_argument
    (
        "cell mode '" + name + "' unknown; valid: nve, thermostatted, leesEdwards, stochastic"
    );
}

std::string cellModeName(CellMode mode)
{
    switch (mode)
    {
        case CellMode::nve: return "nve";
        case CellMode::thermostatted: return "thermostatted";
        case CellMode::leesEdwards: return "leesEdwards";
        case CellMode::stochastic: return "stochastic";
    }
    return "unknown";
}

std::unique_ptr<Driving> Driving::New
(
    CellMode mode,
    double targetTemperature,
    double thermostatTime,
    double shearRate,
    double timeStep,
    std::uint64_t seed
)
{
    switch (mode)
    {
        case CellMode::nve:
            return std::make_unique<NoDriving>();
        case CellMode::thermostatted:
            if (!(targetTemperature > 0))
            {
                throw std::invalid_argument("thermostatted cell: targetTemperature must be positive");
            }
            return std::make_unique<VelocityRescalingThermostat>
            (
                targetTemperature, thermostatTime, timeStep
            );
        case CellMode::leesEdwards:
            if (!std::isfinite(shearRate))
            {
                throw std::invalid_argument("leesEdwards cell: shearRate must be finite");
            }
            return std::make_unique<LeesEdwardsShear>(shearRate);
        case CellMode::stochastic:
            return std::make_unique<StochasticDriving>
            (
                targetTemperature, thermostatTime, timeStep, seed
            );
    }
    throw std::invalid_argument
    (
        "cell mode unknown; valid: nve, thermostatted, leesEdwards, stochastic"
    );
}

void Driving::importState(const std::vector<double>& state)
{
    if (!state.empty())
    {
        throw std::invalid_argument
        (
            "driving '" + name() + "' keeps no state, but the checkpoint holds "
          + std::to_string(state.size()) + " values of one"
        );
    }
}

// ---------------------------------------------------------------- chunk sums

namespace
{

//- Adds the sums over particles [begin, end) to sum: mass, mass x velocity, velocity,
//  |velocity|^2, mass x |velocity|^2.
void addVelocitySums(const Particles& p, int begin, int end, double* sum)
{
    for (int i = begin; i < end; ++i)
    {
        const double m = p.mass[i], vx = p.vx[i], vy = p.vy[i], vz = p.vz[i];
        sum[0] += m; sum[1] += m*vx; sum[2] += m*vy; sum[3] += m*vz;
        const double v2 = vx*vx + vy*vy + vz*vz;
        sum[4] += vx; sum[5] += vy; sum[6] += vz; sum[7] += v2; sum[8] += m*v2;
    }
}

} // namespace

bool VelocityChunkSums::begin(int nParticles, bool endsStep)
{
    if (endsStep)
    {
        chunks_.resize(std::size_t((nParticles + Driving::finishChunk - 1)/Driving::finishChunk));
    }
    ready_ = endsStep;
    return endsStep;
}

void VelocityChunkSums::addRange(const Particles& p, int begin, int end)
{
    // per fixed chunk (the ranges are whole chunks), while the velocities are in cache
    for (int c0 = begin; c0 < end; c0 += Driving::finishChunk)
    {
        Totals& sum = chunks_[std::size_t(c0/Driving::finishChunk)];
        sum.fill(0.0);
        addVelocitySums(p, c0, std::min(end, c0 + Driving::finishChunk), sum.data());
    }
}

VelocityChunkSums::Totals VelocityChunkSums::totals(const Particles& p)
{
    if (!ready_) return sum(p);
    ready_ = false;
    Totals total{};
    for (const Totals& chunk : chunks_)
    {
        for (int k = 0; k < size; ++k) total[k] += chunk[k];
    }
    return total;
}

VelocityChunkSums::Totals VelocityChunkSums::sum(const Particles& p)
{
    // the same chunks, in the same order, as the force pass's finish
    const int n = int(p.size());
    Totals total{};
    for (int c0 = 0; c0 < n; c0 += Driving::finishChunk)
    {
        Totals chunk{};
        addVelocitySums(p, c0, std::min(n, c0 + Driving::finishChunk), chunk.data());
        for (int k = 0; k < size; ++k) total[k] += chunk[k];
    }
    return total;
}

double temperatureAboutMean(const VelocityChunkSums::Totals& total, int n, double u[3])
{
    u[0] = u[1] = u[2] = 0;
    if (!(total[0] > 0) || n < 1) return 0;
    // mass-weighted mean velocity u; sum |v - u|^2 = sum |v|^2 - 2 u . sum v + n |u|^2
    u[0] = total[1]/total[0]; u[1] = total[2]/total[0]; u[2] = total[3]/total[0];
    const double sumC2 =
        total[7] - 2*(u[0]*total[4] + u[1]*total[5] + u[2]*total[6])
      + n*(u[0]*u[0] + u[1]*u[1] + u[2]*u[2]);
    return sumC2/n;
}

double kineticEnergyAboutMean(const VelocityChunkSums::Totals& total)
{
    if (!(total[0] > 0)) return 0;
    // sum m |v - u|^2 = sum m |v|^2 - |sum m v|^2/M
    const double p2 = total[1]*total[1] + total[2]*total[2] + total[3]*total[3];
    return 0.5*std::max(0.0, total[8] - p2/total[0]);
}

// ---------------------------------------------------------------- thermostat

VelocityRescalingThermostat::VelocityRescalingThermostat
(
    double targetTemperature,
    double relaxationTime,
    double timeStep
)
:
    targetTemperature_(targetTemperature),
    relaxationTime_(relaxationTime),
    timeStep_(timeStep)
{}

bool VelocityRescalingThermostat::beginForcePass(int nParticles, bool endsStep)
{
    return sums_.begin(nParticles, endsStep);
}

void VelocityRescalingThermostat::finishRange(const Particles& p, int begin, int end)
{
    sums_.addRange(p, begin, end);
}

void VelocityRescalingThermostat::afterStep(Particles& p, int nThreads)
{
    const int n = int(p.size());
    double u[3];
    const double T = temperatureAboutMean(sums_.totals(p), n, u);
    if (!(T > 0)) return;
    const double ux = u[0], uy = u[1], uz = u[2];
    const double ratio = targetTemperature_/T;
    const double lambda =
        std::sqrt(std::max(0.0, 1.0 + timeStep_/relaxationTime_*(ratio - 1.0)));
    forEachIndex(nThreads, n, [&](int i)
    {
        p.vx[i] = ux + lambda*(p.vx[i] - ux);
        p.vy[i] = uy + lambda*(p.vy[i] - uy);
        p.vz[i] = uz + lambda*(p.vz[i] - uz);
    });
}

} // namespace sdf::dem

#include "Driving.hpp"

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

std::unique_ptr<Driving> Driving::New
(
    CellMode mode,
    double targetTemperature,
    double thermostatTime,
    double shearRate,
    double timeStep
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
    }
    throw std::invalid_argument("cell mode unknown; valid: nve, thermostatted, leesEdwards");
}

// ---------------------------------------------------------------- thermostat

namespace
{

//- Adds the thermostat's sums over particles [begin, end) to sum: mass, mass x velocity,
//  velocity, |velocity|^2.
void addThermostatSums(const Particles& p, int begin, int end, double* sum)
{
    for (int i = begin; i < end; ++i)
    {
        const double m = p.mass[i], vx = p.vx[i], vy = p.vy[i], vz = p.vz[i];
        sum[0] += m; sum[1] += m*vx; sum[2] += m*vy; sum[3] += m*vz;
        sum[4] += vx; sum[5] += vy; sum[6] += vz; sum[7] += vx*vx + vy*vy + vz*vz;
    }
}

} // namespace

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
    if (endsStep)
    {
        chunkSums_.resize(std::size_t((nParticles + finishChunk - 1)/finishChunk));
    }
    sumsReady_ = endsStep;
    return endsStep;
}

void VelocityRescalingThermostat::finishRange(const Particles& p, int begin, int end)
{
    // per fixed chunk (the ranges are whole chunks), while the velocities are in cache
    for (int c0 = begin; c0 < end; c0 += finishChunk)
    {
        double sum[ChunkSums::size] = {};
        addThermostatSums(p, c0, std::min(end, c0 + finishChunk), sum);
        std::copy(sum, sum + ChunkSums::size, chunkSums_[c0/finishChunk].value);
    }
}

void VelocityRescalingThermostat::afterStep(Particles& p, int nThreads)
{
    // sums per fixed chunk of particles (filled by the force pass's finish, or here), added
    // in chunk order: the same T whatever the threads
    const int n = int(p.size());
    const int nChunks = (n + finishChunk - 1)/finishChunk;
    if (!sumsReady_)
    {
        chunkSums_.resize(std::size_t(nChunks));
        for (int c = 0; c < nChunks; ++c)
        {
            double* sum = chunkSums_[c].value;
            std::fill(sum, sum + ChunkSums::size, 0.0);
            addThermostatSums(p, c*finishChunk, std::min(n, (c + 1)*finishChunk), sum);
        }
    }
    sumsReady_ = false;
    double total[ChunkSums::size] = {};
    for (int c = 0; c < nChunks; ++c)
    {
        for (int k = 0; k < ChunkSums::size; ++k) total[k] += chunkSums_[c].value[k];
    }
    if (!(total[0] > 0)) return;
    // mass-weighted mean velocity u; sum |v - u|^2 = sum |v|^2 - 2 u . sum v + n |u|^2
    const double ux = total[1]/total[0], uy = total[2]/total[0], uz = total[3]/total[0];
    const double sumC2 =
        total[7] - 2*(ux*total[4] + uy*total[5] + uz*total[6]) + n*(ux*ux + uy*uy + uz*uz);
    const double T = sumC2/n;
    if (!(T > 0)) return;
    const double ratio = targetTemperature_/T;
    const double lambda =
        std::sqrt(std::max(0.0, 1.0 + timeStep_/relaxationTime_*(ratio - 1.0)));
    #pragma omp parallel for num_threads(nThreads) schedule(static) if(nThreads > 1)
    for (int i = 0; i < n; ++i)
    {
        p.vx[i] = ux + lambda*(p.vx[i] - ux);
        p.vy[i] = uy + lambda*(p.vy[i] - uy);
        p.vz[i] = uz + lambda*(p.vz[i] - uz);
    }
}

} // namespace sdf::dem

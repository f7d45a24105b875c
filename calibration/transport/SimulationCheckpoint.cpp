#include "SimulationCheckpoint.hpp"

#include "io/Checkpoint.hpp"

#include <stdexcept>

namespace sdf::dem
{

namespace
{

const std::vector<ParticleArray Particles::*>& particleArrays()
{
    static const std::vector<ParticleArray Particles::*> arrays =
    {
        &Particles::x, &Particles::y, &Particles::z, &Particles::ux, &Particles::uy,
        &Particles::uz, &Particles::vx, &Particles::vy, &Particles::vz, &Particles::wx,
        &Particles::wy, &Particles::wz, &Particles::fx, &Particles::fy, &Particles::fz,
        &Particles::tx, &Particles::ty, &Particles::tz, &Particles::radius, &Particles::mass,
        &Particles::inertia, &Particles::invMass, &Particles::invInertia
    };
    return arrays;
}

const std::vector<std::string>& particleArrayNames()
{
    static const std::vector<std::string> names =
    {
        "x", "y", "z", "ux", "uy", "uz", "vx", "vy", "vz", "wx", "wy", "wz",
        "fx", "fy", "fz", "tx", "ty", "tz", "radius", "mass", "inertia", "invMass", "invInertia"
    };
    return names;
}

} // namespace

void writeSimulationCheckpoint(const std::string& path, const Simulation& simulation)
{
    io::Checkpoint flat;
    addSimulationState(flat, simulation);
    io::writeCheckpoint(path, flat);
}

void addSimulationState(io::Checkpoint& out, const Simulation& simulation)
{
    const SimulationState st = simulation.exportState();
    io::Checkpoint c;
    c.scalars["time"] = st.time;
    c.scalars["shearOffset"] = st.shearOffset;
    c.scalars["boxLengthY"] = st.boxLengthY;
    c.integers["stepCount"] = st.stepCount;
    c.strings["format"] = "sdf_dem SimulationState 1";
    for (std::size_t a = 0; a < particleArrays().size(); ++a)
    {
        const ParticleArray& values = st.particles.*particleArrays()[a];
        c.vectors["particles/" + particleArrayNames()[a]].assign(values.begin(), values.end());
    }
    c.integerVectors["particles/species"].assign(st.particles.species.begin(), st.particles.species.end());
    c.integerVectors["particles/id"].assign(st.particles.id.begin(), st.particles.id.end());
    c.integerVectors["pairs/first"].assign(st.pairFirst.begin(), st.pairFirst.end());
    c.integerVectors["pairs/second"].assign(st.pairSecond.begin(), st.pairSecond.end());
    const std::size_t n = st.history.size();
    std::vector<double> ft(3*n), normal(3*n), rolling(3*n);
    std::vector<std::int64_t> touching(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        for (int d = 0; d < 3; ++d)
        {
            ft[3*k + d] = st.history[k].ft[d];
            normal[3*k + d] = st.history[k].n[d];
            rolling[3*k + d] = st.history[k].xr[d];
        }
        touching[k] = st.history[k].touching ? 1 : 0;
    }
    c.vectors["pairs/tangentialForce"] = ft;
    c.vectors["pairs/normal"] = normal;
    c.vectors["pairs/rollingDisplacement"] = rolling;
    c.integerVectors["pairs/touching"] = touching;
    c.vectors["pairs/force"] = st.pairForce;
    c.vectors["pairs/nCrossFt"] = st.pairNCrossFt;
    c.vectors["driving/state"] = st.driving;
    // flat names: io::Checkpoint keys are dataset names, no groups
    for (auto& [k, v] : c.scalars) out.scalars[k] = v;
    for (auto& [k, v] : c.integers) out.integers[k] = v;
    for (auto& [k, v] : c.strings) out.strings[k] = v;
    for (auto& [k, v] : c.vectors) { std::string key = k; for (char& ch : key) if (ch == '/') ch = '_'; out.vectors[key] = v; }
    for (auto& [k, v] : c.integerVectors) { std::string key = k; for (char& ch : key) if (ch == '/') ch = '_'; out.integerVectors[key] = v; }
}

void readSimulationCheckpoint(const std::string& path, Simulation& simulation)
{
    loadSimulationState(io::readCheckpoint(path), simulation, path);
}

void loadSimulationState(const io::Checkpoint& c, Simulation& simulation, const std::string& path)
{
    auto vec = [&](const std::string& key) -> const std::vector<double>&
    {
        const auto it = c.vectors.find(key);
        if (it == c.vectors.end()) throw std::runtime_error("checkpoint '" + path + "': missing " + key);
        return it->second;
    };
    auto ivec = [&](const std::string& key) -> const std::vector<std::int64_t>&
    {
        const auto it = c.integerVectors.find(key);
        if (it == c.integerVectors.end()) throw std::runtime_error("checkpoint '" + path + "': missing " + key);
        return it->second;
    };
    if (!c.strings.count("format") || c.strings.at("format") != "sdf_dem SimulationState 1")
    {
        throw std::runtime_error("checkpoint '" + path + "': not an sdf_dem simulation state");
    }
    SimulationState st;
    for (std::size_t a = 0; a < particleArrays().size(); ++a)
    {
        const std::vector<double>& values = vec("particles_" + particleArrayNames()[a]);
        (st.particles.*particleArrays()[a]).assign(values.begin(), values.end());
    }
    const auto& species = ivec("particles_species");
    st.particles.species.assign(species.begin(), species.end());
    // ids (absent in checkpoints of engines that never renumbered: the indices)
    if (c.integerVectors.count("particles_id"))
    {
        const auto& id = ivec("particles_id");
        st.particles.id.assign(id.begin(), id.end());
    }
    const auto& first = ivec("pairs_first");
    const auto& second = ivec("pairs_second");
    st.pairFirst.assign(first.begin(), first.end());
    st.pairSecond.assign(second.begin(), second.end());
    const auto& ft = vec("pairs_tangentialForce");
    const auto& normal = vec("pairs_normal");
    const std::vector<double> rolling = c.vectors.count("pairs_rollingDisplacement")
        ? c.vectors.at("pairs_rollingDisplacement") : std::vector<double>();
    const auto& touching = ivec("pairs_touching");
    const std::size_t n = touching.size();
    if (ft.size() != 3*n || normal.size() != 3*n)
    {
        throw std::runtime_error("checkpoint '" + path + "': inconsistent contact history");
    }
    st.history.resize(n);
    for (std::size_t k = 0; k < n; ++k)
    {
        for (int d = 0; d < 3; ++d) { st.history[k].ft[d] = ft[3*k + d]; st.history[k].n[d] = normal[3*k + d]; }
        // absent in checkpoints written before rolling resistance: none
        if (rolling.size() == 3*n) for (int d = 0; d < 3; ++d) st.history[k].xr[d] = rolling[3*k + d];
        st.history[k].touching = touching[k] != 0;
    }
    st.pairForce = vec("pairs_force");
    st.pairNCrossFt = vec("pairs_nCrossFt");
    // the driving's own state (absent in checkpoints of drivings that keep none)
    if (c.vectors.count("driving_state")) st.driving = vec("driving_state");
    st.time = c.scalars.at("time");
    st.shearOffset = c.scalars.at("shearOffset");
    // absent in checkpoints written before pressure control: ly as built
    if (c.scalars.count("boxLengthY")) st.boxLengthY = c.scalars.at("boxLengthY");
    st.stepCount = long(c.integers.at("stepCount"));
    simulation.importState(st);
}

} // namespace sdf::dem

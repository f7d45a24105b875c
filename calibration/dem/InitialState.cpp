#include "InitialState.hpp"
#include "Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

namespace sdf::dem
{

double RandomStream::normal()
{
    if (hasSpare_) { hasSpare_ = false; return spare_; }
    double u1;
    do { u1 = uniform(); } while (u1 <= 0);
    const double u2 = uniform();
    const double r = std::sqrt(-2*std::log(u1));
    spare_ = r*std::sin(2*M_PI*u2);
    hasSpare_ = true;
    return r*std::cos(2*M_PI*u2);
}

void validatePackingSettings(const std::vector<Species>& species, const PackingSettings& s)
{
    validateSpecies(species);
    if (!(s.solidsFraction > 0) || s.solidsFraction > jammingSolidsFraction)
    {
        throw std::invalid_argument
        (
            "solidsFraction phi = " + std::to_string(s.solidsFraction)
          + " outside (0, " + std::to_string(jammingSolidsFraction)
          + "]: above the jamming range (random close packing) or not positive"
        );
    }
    if (s.counts.size() != species.size())
    {
        throw std::invalid_argument("counts: one particle count per species required");
    }
    long total = 0;
    for (const int c : s.counts)
    {
        if (c < 0) throw std::invalid_argument("counts: negative particle count");
        total += c;
    }
    if (total < 2) throw std::invalid_argument("counts: at least two particles required");
    if (!std::isfinite(s.heightRatio) || !(s.heightRatio > 0))
    {
        throw std::invalid_argument("heightRatio ly/lx must be finite and positive, got " + std::to_string(s.heightRatio));
    }
}

std::vector<int> countsFromVolumeFractions
(
    const std::vector<Species>& species,
    const std::vector<double>& fractions,
    int nTotal
)
{
    validateSpecies(species);
    if (fractions.size() != species.size())
    {
        throw std::invalid_argument("volume fractions: one per species required");
    }
    double sum = 0;
    for (const double f : fractions)
    {
        if (f < 0) throw std::invalid_argument("volume fractions must be >= 0");
        sum += f;
    }
    if (!(sum > 0)) throw std::invalid_argument("volume fractions sum to zero");
    // number fraction of species s ~ f_s / V_s
    std::vector<double> w(species.size());
    double wSum = 0;
    for (std::size_t s = 0; s < species.size(); ++s)
    {
        w[s] = fractions[s]/sum/species[s].volume();
        wSum += w[s];
    }
    std::vector<int> counts(species.size());
    int assigned = 0;
    for (std::size_t s = 0; s < species.size(); ++s)
    {
        counts[s] = int(std::lround(nTotal*w[s]/wSum));
        assigned += counts[s];
    }
    // put the rounding remainder on the most numerous species
    const std::size_t big = std::max_element(counts.begin(), counts.end()) - counts.begin();
    counts[big] += nTotal - assigned;
    return counts;
}

Packing makePacking(const std::vector<Species>& species, const PackingSettings& settings)
{
    validatePackingSettings(species, settings);
    const double phi = settings.solidsFraction;

    double solidVolume = 0;
    for (std::size_t s = 0; s < species.size(); ++s)
    {
        solidVolume += settings.counts[s]*species[s].volume();
    }
    const double L = std::cbrt(solidVolume/(phi*settings.heightRatio));
    const double height = settings.heightRatio*L;

    Packing packing;
    packing.box.lx = packing.box.lz = L;
    packing.box.ly = height;

    // random insertion at a dilute start fraction
    const double phiStart = std::min(0.5*phi, 0.1);
    double scale = std::cbrt(phiStart/phi);
    RandomStream random(settings.seed);
    Particles& p = packing.particles;
    for (std::size_t s = 0; s < species.size(); ++s)
    {
        for (int k = 0; k < settings.counts[s]; ++k)
        {
            const double x = L*random.uniform(), y = height*random.uniform(), z = L*random.uniform();
            p.add(x, y, z, species[s].radius(), species[s].mass(), int(s));
        }
    }
    // shuffle-free: species are stored in blocks, which keeps per-species loops simple
    for (double& r : p.radius) r *= scale;

    // damped frictionless relaxation with soft springs; the stiffness only sets the
    // time unit of the relaxation
    double mMin = species[0].mass();
    for (const Species& s : species) mMin = std::min(mMin, s.mass());
    SimulationSettings relax;
    relax.contact.model = ContactModel::linearSpringDashpot;
    relax.contact.restitution = 0.3;
    relax.contact.friction = 0.0;
    relax.contact.normalStiffness = mMin;   // t_c ~ 2.3 s
    relax.mode = CellMode::nve;
    relax.maxOverlapFraction = 0;
    relax.energyBlowUpFactor = 1e300;
    relax.threads = 1;
    double dMin = species[0].diameter;
    for (const Species& s : species) dMin = std::min(dMin, s.diameter);
    relax.skin = 0.3*dMin;
    {
        ContactLaw law(relax.contact, species);
        relax.timeStep = law.maximumTimeStep();
    }

    Simulation sim(species, relax, std::move(p), packing.box);
    long steps = 0;
    double overlap = sim.maximumOverlapFraction();
    while (true)
    {
        sim.step();
        ++steps;
        Particles& q = sim.particles();
        // extra velocity damping: the relaxation should go downhill, not oscillate
        for (std::size_t i = 0; i < q.size(); ++i)
        {
            q.vx[i] *= 0.9; q.vy[i] *= 0.9; q.vz[i] *= 0.9;
            q.wx[i] = q.wy[i] = q.wz[i] = 0;
        }
        overlap = sim.maximumOverlapFraction();
        if (scale < 1)
        {
            double growth = 0;
            if (overlap < 0.005) growth = 2e-3;
            else if (overlap < 0.02) growth = 5e-4;
            if (growth > 0)
            {
                const double next = std::min(1.0, scale*(1 + growth));
                sim.scaleRadii(next/scale);
                scale = next;
            }
        }
        else if (overlap < settings.overlapTolerance)
        {
            break;
        }
        if (settings.verbose && steps % 2000 == 0)
        {
            std::printf
            (
                "packing: step %ld  phi %.4f  max overlap %.3g %%\n",
                steps, phi*scale*scale*scale, 100*overlap
            );
        }
        if (steps >= settings.maxSteps)
        {
            throw std::runtime_error
            (
                "packing: could not reach phi = " + std::to_string(phi)
              + " with overlaps below " + std::to_string(100*settings.overlapTolerance)
              + " % of the diameter in " + std::to_string(settings.maxSteps)
              + " relaxation steps (reached phi = "
              + std::to_string(phi*scale*scale*scale) + ")"
            );
        }
    }

    packing.particles = sim.particles();
    Particles& out = packing.particles;
    // exact species radii (undo the accumulated rounding of the growth factors)
    for (std::size_t i = 0; i < out.size(); ++i)
    {
        out.setRadius(i, species[out.species[i]].radius(), species[out.species[i]].density);
        out.vx[i] = out.vy[i] = out.vz[i] = 0;
        out.wx[i] = out.wy[i] = out.wz[i] = 0;
        out.fx[i] = out.fy[i] = out.fz[i] = 0;
        out.tx[i] = out.ty[i] = out.tz[i] = 0;
        out.ux[i] = out.uy[i] = out.uz[i] = 0;
    }
    // Number the particles in slabs of y (the Lees-Edwards gradient direction, which the
    // shear does not mix): the force pass gives each thread a contiguous index range, so
    // with this order a thread's neighbours are mostly its own particles and few cache
    // lines cross between cores at every step (docs/developer/dem-engine.md, "Parallelism and performance")
    std::vector<int> order(out.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort
    (
        order.begin(), order.end(),
        [&out](int a, int b) { return out.y[a] < out.y[b]; }
    );
    out.reorder(order);
    packing.relaxationSteps = steps;
    packing.maxOverlapFraction = overlap;
    return packing;
}

namespace
{

//- Per species: its mean velocity removed (so the total momentum stays 0) and its
//  <|c|^2> set to lambda/m_s, lambda such that the number average over all particles is
//  T (the particle of a one-particle species stays at rest).
void equipartitionExactly(Particles& p, double temperature)
{
    const std::size_t n = p.size();
    int nSpecies = 0;
    for (int s : p.species) nSpecies = std::max(nSpecies, s + 1);
    std::vector<double> count(nSpecies, 0), mass(nSpecies, 0), sum2(nSpecies, 0);
    std::vector<Eigen::Vector3d> mean(nSpecies, Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < n; ++i)
    {
        const int s = p.species[i];
        count[s] += 1;
        mass[s] += p.mass[i];
        mean[s] += Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    }
    for (int s = 0; s < nSpecies; ++s)
    {
        if (count[s] > 0) mean[s] /= count[s];
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        const Eigen::Vector3d& m = mean[p.species[i]];
        p.vx[i] -= m.x(); p.vy[i] -= m.y(); p.vz[i] -= m.z();
        sum2[p.species[i]] += p.vx[i]*p.vx[i] + p.vy[i]*p.vy[i] + p.vz[i]*p.vz[i];
    }
    // sum_s n_s/m_s over the species that can move (a species of one particle has no
    // fluctuation about its own mean: it stays at rest and T is shared by the others)
    double inverseMassSum = 0;
    for (int s = 0; s < nSpecies; ++s)
    {
        if (sum2[s] > 0) inverseMassSum += count[s]*count[s]/mass[s];
    }
    if (!(inverseMassSum > 0))
    {
        if (temperature > 0)
        {
            throw std::invalid_argument
            (
                "assignVelocities: no species with two or more particles to carry the"
                " temperature at equipartition"
            );
        }
        return;
    }
    const double lambda = temperature*double(n)/inverseMassSum;
    std::vector<double> scale(nSpecies, 0);
    for (int s = 0; s < nSpecies; ++s)
    {
        const double target = sum2[s] > 0 ? lambda*count[s]/mass[s] : 0;   // T_s
        scale[s] = sum2[s] > 0 ? std::sqrt(target*count[s]/sum2[s]) : 0;
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        const double f = scale[p.species[i]];
        p.vx[i] *= f; p.vy[i] *= f; p.vz[i] *= f;
    }
}

} // namespace

void assignVelocities
(
    Particles& p,
    const PeriodicBox& box,
    double temperature,
    double shearRate,
    std::uint64_t seed,
    VelocityPartition partition
)
{
    if (!(temperature >= 0)) throw std::invalid_argument("temperature must be >= 0");
    RandomStream random(seed ^ 0x9e3779b97f4a7c15ULL);
    const std::size_t n = p.size();
    double meanMass = 0;
    for (std::size_t i = 0; i < n; ++i) meanMass += p.mass[i]/double(n);
    double mx = 0, my = 0, mz = 0, mass = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        const double sigma = partition == VelocityPartition::equipartition
            ? std::sqrt(temperature/3.0*meanMass/p.mass[i]) : std::sqrt(temperature/3.0);
        p.vx[i] = sigma*random.normal();
        p.vy[i] = sigma*random.normal();
        p.vz[i] = sigma*random.normal();
        p.wx[i] = p.wy[i] = p.wz[i] = 0;
        mx += p.mass[i]*p.vx[i]; my += p.mass[i]*p.vy[i]; mz += p.mass[i]*p.vz[i];
        mass += p.mass[i];
    }
    mx /= mass; my /= mass; mz /= mass;
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
        p.vx[i] -= mx; p.vy[i] -= my; p.vz[i] -= mz;
        sum += p.vx[i]*p.vx[i] + p.vy[i]*p.vy[i] + p.vz[i]*p.vz[i];
    }
    if (partition == VelocityPartition::equipartition)
    {
        // each species exactly at its share, T_s = lambda/m_s with the number average T:
        // a species of a few dozen particles would otherwise start up to 20 % off it by
        // chance, and the energy it then gives away or takes moves T
        equipartitionExactly(p, temperature);
    }
    else
    {
        // exact requested temperature
        const double s = (sum > 0 && temperature > 0) ? std::sqrt(temperature*n/sum) : 0.0;
        for (std::size_t i = 0; i < n; ++i)
        {
            p.vx[i] *= s; p.vy[i] *= s; p.vz[i] *= s;
        }
    }
    for (std::size_t i = 0; i < n; ++i)
    {
        p.vx[i] += shearRate*(p.y[i] - 0.5*box.ly);
    }
}

} // namespace sdf::dem

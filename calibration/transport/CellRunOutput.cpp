// Text outputs of a cell run: the LAMMPS data file of its initial state and the
// human-readable summary of its result.

#include "CellRun.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sdf::dem
{

void writeLammpsData
(
    const std::string& path,
    const Particles& p,
    const PeriodicBox& box,
    const std::vector<Species>& species,
    double streamingShift
)
{
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write LAMMPS data file '" + path + "'");
    out.precision(17);
    out << "LAMMPS data file written by sdf_dem (SI units)\n\n"
        << p.size() << " atoms\n" << species.size() << " atom types\n\n"
        << "0 " << box.lx << " xlo xhi\n0 " << box.ly << " ylo yhi\n0 " << box.lz << " zlo zhi\n"
        << box.offset << " 0 0 xy xz yz\n\nAtoms # sphere\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const Species& s = species[p.species[i]];
        out << i + 1 << " " << p.species[i] + 1 << " " << 2*p.radius[i] << " " << s.density
            << " " << p.x[i] << " " << p.y[i] << " " << p.z[i] << "\n";
    }
    out << "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        out << i + 1 << " " << p.vx[i] + streamingShift << " " << p.vy[i] << " " << p.vz[i] << " "
            << p.wx[i] << " " << p.wy[i] << " " << p.wz[i] << "\n";
    }
}

std::string summary(const CellRunResult& r)
{
    std::ostringstream out;
    const auto& s = r.settings;
    out << "periodic cell: " << cellModeName(s.simulation.mode) << ", N = " << s.particles
        << ", phi = " << s.solidsFraction << ", box " << r.boxLength << " m, dt = "
        << r.timeStep << " s, " << contactModelName(s.simulation.contact.model)
        << ", e = " << s.simulation.contact.restitution << ", mu = "
        << s.simulation.contact.friction << "\n";
    for (const PairContactSettings& p : s.simulation.contact.pairs)
    {
        out << "  pair " << pairContactText(p) << "\n";
    }
    out << "  equilibrated: " << (r.equilibrated ? "yes" : "NO") << " after "
        << r.equilibrationTime << " s\n";
    out << "  T = " << r.temperature << " +- " << r.temperatureError
        << " m2/s2 (sum of 3 components; T1 = T/3)\n";
    if (s.simulation.mode == CellMode::leesEdwards)
    {
        out << "  gammaDot = " << s.simulation.shearRate << " 1/s, Savage-Jeffrey R = "
            << r.savageJeffreyR << "\n";
    }
    if (const RheologyResult& h = r.rheology; h.measured)
    {
        const auto pm = [&](const correlation::Estimate& e)
        {
            std::ostringstream t;
            t << e.value << " +- " << e.standardError;
            return t.str();
        };
        out << "  rheology (" << (h.pressureControlled ? "pressure" : "volume")
            << "-controlled";
        if (h.pressureControlled)
        {
            out << ", targetPressure " << h.targetPressure << " Pa, barostatTime "
                << h.barostatTime << " s";
        }
        out << "): sigma_yy = " << pm(h.pressure) << " Pa, mu = " << pm(h.stressRatio)
            << ", I = " << pm(h.inertialNumber) << " (d " << h.meanDiameter << " m, rho_s "
            << h.solidsDensity << " kg/m3), phi = " << pm(h.solidsFraction) << ", Z = "
            << pm(h.coordinationNumber) << ", mean overlap " << 100*h.meanOverlapFraction.value
            << " % of d, bond order Q6 = " << pm(h.bondOrder) << "\n";
        out << "    steady: " << (h.steady ? "yes" : "NO") << " (" << h.steadyCheck
            << "); regime: " << h.regime << " (" << h.regimeReason << ")\n";
    }
    if (r.collectiveMotionTransverse.samples > 0)
    {
        out << "  longest-wavelength momentum modes / equipartition: transverse "
            << r.collectiveMotionTransverse.value << " +- "
            << r.collectiveMotionTransverse.standardError << ", longitudinal "
            << r.collectiveMotionLongitudinal.value << " +- "
            << r.collectiveMotionLongitudinal.standardError
            << " (1: no collective motion)\n";
    }
    if (r.settings.throughputOnly)
    {
        out << "  throughput " << r.particleStepsPerSecond << " particle-steps/s ("
            << r.steps << " steps, " << r.wallSeconds << " s, CPU use "
            << 100*r.cpuSeconds/r.wallSeconds << " %)\n";
        if (!r.threadScaling.empty())
        {
            std::vector<double> speedUps;
            for (const auto& rates : r.threadScaling) speedUps.push_back(rates[1]/rates[0]);
            std::sort(speedUps.begin(), speedUps.end());
            const std::size_t m = speedUps.size();
            const double median = m % 2 ? speedUps[m/2] : 0.5*(speedUps[m/2 - 1] + speedUps[m/2]);
            out << "  thread scaling (" << m << " rounds, same state): speed-up on "
                << r.scalingThreads << " threads: median " << median << ", min "
                << speedUps.front() << ", max " << speedUps.back() << "\n";
            for (const auto& rates : r.threadScaling)
            {
                out << "    1 thread " << rates[0] << ", " << r.scalingThreads << " threads "
                    << rates[1] << " particle-steps/s\n";
            }
        }
        return out.str();
    }
    for (const SpeciesTransport& st : r.species)
    {
        out << "  " << st.name << " (" << st.count << "): T = " << st.temperature
            << " +- " << st.temperatureError << ", D_GK = " << st.greenKubo.integral.value << " +- "
            << st.greenKubo.integral.standardError << " m2/s"
            << (st.greenKubo.plateauFound ? "" : " (no plateau)")
            << ", D_MSD = " << st.diffusivityMsd.value << " +- "
            << st.diffusivityMsd.standardError << " m2/s\n";
        const correlation::DiffusiveRegimeCheck& c = st.diffusiveRegime;
        if (c.correlationTime <= 0) continue;
        if (!c.measured)
        {
            out << "    diffusive regime: NO, " << c.verdict() << " (tau_v = "
                << c.correlationTime << " s)\n";
            continue;
        }
        out << "    diffusive regime: " << (c.converged() ? "yes" : "NO, ")
            << (c.converged() ? "" : c.verdict()) << " (" << c.figures()
            << "; tau_v = " << c.correlationTime
            << " s, MSD window " << c.fitStart << " - " << c.fitEnd << " s";
        if (r.settings.simulation.mode == CellMode::leesEdwards)
        {
            const double g = std::abs(r.settings.simulation.shearRate);
            out << " = strain " << g*c.fitStart << " - " << g*c.fitEnd;
        }
        out << ")\n";
    }
    for (std::size_t k = 0; k < r.kineticSieving.size(); ++k)
    {
        out << "  eta_" << r.species[k].name << " = " << r.kineticSieving[k].value << " +- "
            << r.kineticSieving[k].standardError;
        if (k < r.kineticSievingWithCrossTerms.size())
        {
            out << " (cross terms kept: " << r.kineticSievingWithCrossTerms[k].value << " +- "
                << r.kineticSievingWithCrossTerms[k].standardError << ")";
        }
        out << "\n";
    }
    if (!r.stressIntegrals.terms.empty())
    {
        out << "  stress ACF cross/product ratio = " << r.stressIntegrals.crossToProductRatio << "\n";
    }
    const int n = int(r.species.size());
    for (int a = 0; a < n; ++a)
    {
        for (int b = a; b < n; ++b)
        {
            out << "  collisions " << r.species[a].name << "-" << r.species[b].name << ": "
                << r.collisions.counts[speciesPairIndex(a, b, n)] << ", per "
                << r.species[a].name << " particle "
                << r.collisions.frequencyPerParticle(a, b, r.speciesCounts) << " 1/s\n";
        }
    }
    out << "  throughput " << r.particleStepsPerSecond << " particle-steps/s ("
        << r.steps << " steps, " << r.wallSeconds << " s, CPU use "
        << 100*r.cpuSeconds/r.wallSeconds << " %)\n";
    return out.str();
}

} // namespace sdf::dem

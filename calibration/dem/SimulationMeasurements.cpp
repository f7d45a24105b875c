// Measurements of a Simulation's state: velocities about the driving's reference,
// temperatures, energies, momentum and the microscopic stress (total and per species).

#include "Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace sdf::dem
{

namespace
{

//- sum_i 1/2 m_i |v_i|^2 of one kind of motion: mass and velocity, or inertia and
//  angular velocity.
double kineticEnergy
(
    const ParticleArray& m,
    const ParticleArray& vx,
    const ParticleArray& vy,
    const ParticleArray& vz
)
{
    double e = 0;
    for (std::size_t i = 0; i < m.size(); ++i)
    {
        e += 0.5*m[i]*(vx[i]*vx[i] + vy[i]*vy[i] + vz[i]*vz[i]);
    }
    return e;
}

//- The sums over bond directions n of Steinhardt's Y_6m(n), m = 0..6 (|<Y_6,-m>| =
//  |<Y_6m>|): Y_6m(n) = K_m (x + i y)^m d^m P_6/dz^m (z) for the unit bond n = (x, y, z),
//  up to a sign, with K_m^2 = 13/(4 pi) (6 - m)!/(6 + m)!
struct BondOrderSum
{
    std::complex<double> sum[7] = {};

    void add(const Eigen::Vector3d& n)
    {
        const double z = n.z(), z2 = z*z;
        // the derivatives of P_6 = (231 z^6 - 315 z^4 + 105 z^2 - 5)/16
        const double dP[7] =
        {
            ((231*z2 - 315)*z2 + 105)*z2 - 5,
            ((1386*z2 - 1260)*z2 + 210)*z,
            (6930*z2 - 3780)*z2 + 210,
            (27720*z2 - 7560)*z,
            83160*z2 - 7560,
            166320*z,
            166320
        };
        const std::complex<double> w(n.x(), n.y());
        std::complex<double> wm(1, 0);
        for (int m = 0; m <= 6; ++m)
        {
            sum[m] += wm*(dP[m]/16);
            wm *= w;
        }
    }

    //- Q6 = sqrt(4 pi/13 sum_m |<Y_6m>|^2) over `bonds` added bonds
    double q6(long bonds) const
    {
        constexpr double factorialRatio[7] =   // (6 - m)!/(6 + m)!
        {
            1.0, 1.0/42, 1.0/1680, 1.0/60480, 1.0/1814400, 1.0/39916800, 1.0/479001600
        };
        double q = 0;
        for (int m = 0; m <= 6; ++m)
        {
            const double K2 = 13/(4*M_PI)*factorialRatio[m];
            q += (m == 0 ? 1 : 2)*K2*std::norm(sum[m]);
        }
        return std::sqrt(4*M_PI/13*q)/double(bonds);
    }
};

} // namespace

Eigen::Vector3d Simulation::meanVelocity() const
{
    double mass = 0;
    for (const double m : particles_.mass) mass += m;
    return mass > 0 ? Eigen::Vector3d(totalMomentum()/mass) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d Simulation::referenceMeanVelocity() const
{
    return driving_->aboutStreamingVelocity() ? Eigen::Vector3d::Zero() : meanVelocity();
}

Eigen::Vector3d Simulation::fluctuatingVelocity(int i) const
{
    const Particles& p = particles_;
    Eigen::Vector3d c(p.vx[i], p.vy[i], p.vz[i]);
    if (driving_->aboutStreamingVelocity())
    {
        c.x() -= box_.streamingVelocity(p.y[i]);
    }
    return c;
}

template<class Visit>
void Simulation::forEachFluctuation(Visit visit) const
{
    const Eigen::Vector3d mean = referenceMeanVelocity();
    for (std::size_t i = 0; i < particles_.size(); ++i)
    {
        const Eigen::Vector3d c = fluctuatingVelocity(int(i)) - mean;
        visit(i, c);
    }
}

template<class Visit>
void Simulation::forEachContact(Visit visit) const
{
    const Particles& p = particles_;
    const std::vector<int>& f = list_.first();
    const std::vector<int>& s = list_.second();
    for (std::size_t k = 0; k < list_.size(); ++k)
    {
        if (!history_[k].touching) continue;
        const int i = f[k], j = s[k];
        double dx = p.x[i] - p.x[j], dy = p.y[i] - p.y[j], dz = p.z[i] - p.z[j], dvx = 0;
        box_.minimumImage(dx, dy, dz, dvx);
        visit(k, i, j, Eigen::Vector3d(dx, dy, dz));
    }
}

std::vector<double> Simulation::speciesTemperatures() const
{
    const int nSpecies = int(species_.size());
    std::vector<double> sum(nSpecies, 0.0);
    std::vector<int> count(nSpecies, 0);
    forEachFluctuation
    (
        [&](std::size_t i, const Eigen::Vector3d& c)
        {
            const int s = particles_.species[i];
            sum[s] += c.squaredNorm();
            ++count[s];
        }
    );
    for (int s = 0; s < nSpecies; ++s) sum[s] = count[s] ? sum[s]/count[s] : 0.0;
    return sum;
}

double Simulation::temperature() const
{
    double sum = 0;
    forEachFluctuation([&](std::size_t, const Eigen::Vector3d& c) { sum += c.squaredNorm(); });
    return particles_.size() ? sum/particles_.size() : 0.0;
}

double Simulation::translationalKineticEnergy() const
{
    const Particles& p = particles_;
    return kineticEnergy(p.mass, p.vx, p.vy, p.vz);
}

double Simulation::rotationalKineticEnergy() const
{
    const Particles& p = particles_;
    return kineticEnergy(p.inertia, p.wx, p.wy, p.wz);
}

double Simulation::elasticEnergy() const
{
    const Particles& p = particles_;
    double e = 0;
    forEachContact
    (
        [&](std::size_t k, int i, int j, const Eigen::Vector3d& r)
        {
            const double delta = p.radius[i] + p.radius[j]
                - std::sqrt(r.x()*r.x() + r.y()*r.y() + r.z()*r.z());
            const PairCoefficients& c = law_.pair(p.species[i], p.species[j]);
            e += law_.normalElasticEnergy(c, delta);
            const double ft2 = history_[k].ft[0]*history_[k].ft[0]
                + history_[k].ft[1]*history_[k].ft[1] + history_[k].ft[2]*history_[k].ft[2];
            if (ft2 > 0 && delta > 0)
            {
                e += 0.5*ft2/law_.tangentialStiffness(c, delta);
            }
        }
    );
    walls_.addElasticEnergy(p, law_, e);
    return e;
}

Eigen::Vector3d Simulation::totalMomentum() const
{
    const Particles& p = particles_;
    Eigen::Vector3d m = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        m += p.mass[i]*Eigen::Vector3d(p.vx[i], p.vy[i], p.vz[i]);
    }
    return m;
}

StressSplit Simulation::stressSplit() const
{
    const Particles& p = particles_;
    const int nSpecies = int(species_.size());
    StressSplit J;
    J.nSpecies = nSpecies;
    J.kinetic.assign(nSpecies, Eigen::Matrix3d::Zero());
    J.configurational.assign(numberOfSpeciesPairs(nSpecies), Eigen::Matrix3d::Zero());
    forEachFluctuation
    (
        [&](std::size_t i, const Eigen::Vector3d& c)
        {
            J.kinetic[p.species[i]] += p.mass[i]*c*c.transpose();
        }
    );
    forEachContact
    (
        [&](std::size_t k, int i, int j, const Eigen::Vector3d& r)
        {
            const Eigen::Vector3d F(pfx_[k], pfy_[k], pfz_[k]);
            J.configurational[speciesPairIndex(p.species[i], p.species[j], nSpecies)]
                += F*r.transpose();
        }
    );
    return J;
}

Eigen::Matrix3d Simulation::totalStress() const
{
    const Particles& p = particles_;
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    forEachFluctuation
    (
        [&](std::size_t i, const Eigen::Vector3d& c) { J += p.mass[i]*c*c.transpose(); }
    );
    forEachContact
    (
        [&](std::size_t k, int, int, const Eigen::Vector3d& r)
        {
            J += Eigen::Vector3d(pfx_[k], pfy_[k], pfz_[k])*r.transpose();
        }
    );
    return J;
}

std::vector<Eigen::Matrix3d> Simulation::contactStressBySlab(double y0, double h, int slabs) const
{
    std::vector<Eigen::Matrix3d> J(std::size_t(std::max(slabs, 0)), Eigen::Matrix3d::Zero());
    if (slabs <= 0 || !(h > 0)) return J;
    const Particles& p = particles_;
    forEachContact
    (
        [&](std::size_t k, int i, int, const Eigen::Vector3d& r)
        {
            const Eigen::Matrix3d fr = Eigen::Vector3d(pfx_[k], pfy_[k], pfz_[k])*r.transpose();
            // the branch vector runs from y_i - r_y to y_i, in slab units from y0
            const double top = (p.y[i] - y0)/h;
            const double bottom = top - r.y()/h;
            const double lo = std::min(top, bottom), hi = std::max(top, bottom);
            if (hi - lo < 1e-12)
            {
                const int l = int(std::floor(lo));
                if (l >= 0 && l < slabs) J[std::size_t(l)] += fr;
                return;
            }
            const int first = std::max(0, int(std::floor(lo)));
            const int last = std::min(slabs - 1, int(std::floor(hi)));
            for (int l = first; l <= last; ++l)
            {
                const double inside = std::min(hi, double(l + 1)) - std::max(lo, double(l));
                if (inside > 0) J[std::size_t(l)] += inside/(hi - lo)*fr;
            }
        }
    );
    return J;
}

double Simulation::solidsFraction() const
{
    double volume = 0;
    for (double r : particles_.radius) volume += r*r*r;
    return 4.0/3.0*M_PI*volume/box_.volume();
}

Simulation::ContactSummary Simulation::contactSummary() const
{
    const Particles& p = particles_;
    ContactSummary summary;
    double overlapSum = 0;
    BondOrderSum order;
    forEachContact
    (
        [&](std::size_t, int i, int j, const Eigen::Vector3d& r)
        {
            const double contact = p.radius[i] + p.radius[j];
            const double distance = r.norm();
            const double delta = contact - distance;
            if (delta <= 0) return;
            ++summary.contacts;
            overlapSum += delta/contact;
            order.add(r/distance);
        }
    );
    if (summary.contacts > 0)
    {
        summary.meanOverlapFraction = overlapSum/summary.contacts;
        summary.bondOrderQ6 = order.q6(summary.contacts);
    }
    return summary;
}

void Simulation::enableCollisionStatistics(double eMin, double eMax, int nBins)
{
    collisions_.reset(int(species_.size()), eMin, eMax, nBins);
    collisionsEnabled_ = true;
}

} // namespace sdf::dem

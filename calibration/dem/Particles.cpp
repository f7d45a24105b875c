#include "Particles.hpp"

#include <cmath>

namespace sdf::dem
{

void Particles::resize(std::size_t n)
{
    for (auto* a : {&x, &y, &z, &ux, &uy, &uz, &vx, &vy, &vz, &wx, &wy, &wz,
                    &fx, &fy, &fz, &tx, &ty, &tz, &radius, &mass, &inertia,
                    &invMass, &invInertia})
    {
        a->resize(n, 0.0);
    }
    species.resize(n, 0);
    const std::size_t old = id.size();
    id.resize(n);
    for (std::size_t k = old; k < n; ++k) id[k] = int(k);
}

void Particles::reorder(const std::vector<int>& order)
{
    const std::size_t n = size();
    ParticleArray buffer(n);
    for (auto* a : {&x, &y, &z, &ux, &uy, &uz, &vx, &vy, &vz, &wx, &wy, &wz,
                    &fx, &fy, &fz, &tx, &ty, &tz, &radius, &mass, &inertia,
                    &invMass, &invInertia})
    {
        for (std::size_t k = 0; k < n; ++k) buffer[k] = (*a)[order[k]];
        a->swap(buffer);
    }
    std::vector<int> speciesBuffer(n);
    for (std::size_t k = 0; k < n; ++k) speciesBuffer[k] = species[order[k]];
    species.swap(speciesBuffer);
    for (std::size_t k = 0; k < n; ++k) speciesBuffer[k] = id[order[k]];
    id.swap(speciesBuffer);
}

void Particles::add(double px, double py, double pz, double r, double m, int speciesId)
{
    const std::size_t i = size();
    resize(i + 1);
    x[i] = px; y[i] = py; z[i] = pz;
    radius[i] = r;
    mass[i] = m;
    inertia[i] = 0.4*m*r*r;
    invMass[i] = 1.0/m;
    invInertia[i] = 1.0/inertia[i];
    species[i] = speciesId;
}

void Particles::setRadius(std::size_t i, double r, double density)
{
    radius[i] = r;
    mass[i] = density*M_PI*4.0/3.0*r*r*r;
    inertia[i] = 0.4*mass[i]*r*r;
    invMass[i] = 1.0/mass[i];
    invInertia[i] = 1.0/inertia[i];
}

} // namespace sdf::dem

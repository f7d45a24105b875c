#include "Walls.hpp"

namespace sdf::dem
{

void Walls::add(const Wall& wall, std::size_t nParticles)
{
    Wall w = wall;
    w.normal.normalize();
    walls_.push_back(w);
    history_.emplace_back(nParticles);
}

void Walls::clearHistories(std::size_t nParticles)
{
    for (auto& h : history_) h.assign(nParticles, ContactHistory());
}

void Walls::addElasticEnergy(const Particles& p, const ContactLaw& law, double& e) const
{
    for (std::size_t w = 0; w < walls_.size(); ++w)
    {
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const double sd = (Eigen::Vector3d(p.x[i], p.y[i], p.z[i]) - walls_[w].point)
                .dot(walls_[w].normal);
            e += law.normalElasticEnergy(law.wall(p.species[i]), p.radius[i] - sd);
        }
    }
}

} // namespace sdf::dem

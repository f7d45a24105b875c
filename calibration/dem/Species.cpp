#include "Species.hpp"

#include <cmath>
#include <stdexcept>

namespace sdf::dem
{

double Species::volume() const
{
    return M_PI*diameter*diameter*diameter/6.0;
}

void validateSpecies(const std::vector<Species>& species)
{
    if (species.empty())
    {
        throw std::invalid_argument("species: at least one species is required");
    }
    for (const Species& s : species)
    {
        if (!(s.diameter > 0) || !std::isfinite(s.diameter))
        {
            throw std::invalid_argument
            (
                "species '" + s.name + "': diameter must be positive (got "
              + std::to_string(s.diameter) + ")"
            );
        }
        if (!(s.density > 0) || !std::isfinite(s.density))
        {
            throw std::invalid_argument
            (
                "species '" + s.name + "': density must be positive (got "
              + std::to_string(s.density) + ")"
            );
        }
    }
}

} // namespace sdf::dem

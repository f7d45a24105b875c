#ifndef sdf_dem_Species_hpp
#define sdf_dem_Species_hpp

#include <string>
#include <vector>

namespace sdf::dem
{

//- A particle class of the mixture: one diameter, one solid density (SI units).
struct Species
{
    std::string name;
    double diameter = 0.0;   // [m]
    double density = 0.0;    // [kg/m^3]

    double radius() const { return 0.5*diameter; }
    double volume() const;   // [m^3]
    double mass() const { return density*volume(); }
};

//- Throws std::invalid_argument naming the species if diameter or density is not positive.
void validateSpecies(const std::vector<Species>& species);

//- Index of the unordered species pair (a, b) in an upper-triangular table of
//  nSpecies*(nSpecies+1)/2 entries: (0,0),(0,1),..,(0,n-1),(1,1),...
inline int speciesPairIndex(int a, int b, int nSpecies)
{
    if (a > b) { const int t = a; a = b; b = t; }
    return a*nSpecies - (a*(a - 1))/2 + (b - a);
}

inline int numberOfSpeciesPairs(int nSpecies) { return nSpecies*(nSpecies + 1)/2; }

} // namespace sdf::dem

#endif

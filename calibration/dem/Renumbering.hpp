#ifndef sdf_dem_Renumbering_hpp
#define sdf_dem_Renumbering_hpp

// Spatial renumbering of the particles (in order of y, so that the threads' contiguous
// particle ranges stay slabs although the particles diffuse) and the contact histories
// that travel with them through a neighbour-list rebuild.

#include "ContactForce.hpp"
#include "Particles.hpp"

#include <vector>

namespace sdf::dem
{

//- A touching pair's history kept through a list rebuild (pair (i, j), i < j).
struct CarriedContact
{
    int i, j;
    ContactHistory history;
};

//- The touching pairs of the list (first, second) with their histories, in pair order.
std::vector<CarriedContact> touchingContacts
(
    const std::vector<int>& first,
    const std::vector<int>& second,
    const std::vector<ContactHistory>& history
);

//- Renumbers the particles in order of y (ties by id); returns the old -> new index map.
std::vector<int> renumberInY(Particles& particles);

//- Moves the carried contacts to the new indices (a pair whose i and j swap roles turns
//  round: its tangential force and normal change sign) and sorts them by (i, j).
void renumberContacts(std::vector<CarriedContact>& contacts, const std::vector<int>& newIndex);

//- Histories of the new list (first, second): the carried one of each pair that was
//  touching, else empty. Both lists are sorted by (i, j).
std::vector<ContactHistory> carryHistories
(
    const std::vector<CarriedContact>& carried,
    const std::vector<int>& first,
    const std::vector<int>& second
);

} // namespace sdf::dem

#endif

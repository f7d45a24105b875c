#include "Renumbering.hpp"

#include <algorithm>
#include <utility>

namespace sdf::dem
{

std::vector<CarriedContact> touchingContacts
(
    const std::vector<int>& first,
    const std::vector<int>& second,
    const std::vector<ContactHistory>& history
)
{
    // only touching pairs hold state: a contact that ends is cleared
    std::vector<CarriedContact> carried;
    for (std::size_t k = 0; k < history.size() && k < first.size(); ++k)
    {
        if (history[k].touching) carried.push_back({first[k], second[k], history[k]});
    }
    return carried;
}

std::vector<int> renumberInY(Particles& p)
{
    const int n = int(p.size());
    std::vector<int> order(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) order[i] = i;
    std::sort
    (
        order.begin(), order.end(),
        [&p](int a, int b) { return p.y[a] < p.y[b] || (p.y[a] == p.y[b] && p.id[a] < p.id[b]); }
    );
    // (the forces F^n travel with the particles: the force pass after the rebuild forms
    // the synchronised velocities from them)
    p.reorder(order);
    std::vector<int> newIndex(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) newIndex[order[k]] = k;
    return newIndex;
}

void renumberContacts(std::vector<CarriedContact>& contacts, const std::vector<int>& newIndex)
{
    for (CarriedContact& c : contacts)
    {
        int a = newIndex[c.i], b = newIndex[c.j];
        if (a > b)
        {
            // i and j swap roles: the tangential force on (the new) i and the normal
            // j -> i change sign
            std::swap(a, b);
            for (int d = 0; d < 3; ++d)
            {
                c.history.ft[d] = -c.history.ft[d];
                c.history.n[d] = -c.history.n[d];
            }
        }
        c.i = a;
        c.j = b;
    }
    std::sort
    (
        contacts.begin(), contacts.end(),
        [](const CarriedContact& x, const CarriedContact& y)
        {
            return x.i < y.i || (x.i == y.i && x.j < y.j);
        }
    );
}

std::vector<ContactHistory> carryHistories
(
    const std::vector<CarriedContact>& carried,
    const std::vector<int>& f,
    const std::vector<int>& s
)
{
    const std::size_t nPairs = f.size();
    std::vector<ContactHistory> history(nPairs, ContactHistory());
    std::size_t o = 0;
    for (std::size_t k = 0; k < nPairs && o < carried.size(); ++k)
    {
        while (o < carried.size() && (carried[o].i < f[k] || (carried[o].i == f[k] && carried[o].j < s[k])))
        {
            ++o;
        }
        if (o < carried.size() && carried[o].i == f[k] && carried[o].j == s[k])
        {
            history[k] = carried[o].history;
        }
    }
    return history;
}

} // namespace sdf::dem

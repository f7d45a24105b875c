#ifndef sdf_dem_ContactModels_hpp
#define sdf_dem_ContactModels_hpp

// The contact laws as policies: what differs between the linear spring-dashpot and the
// Hertz-Mindlin law at a given overlap (stiffnesses and dashpots, the normal-force clip,
// the stored elastic energy). evaluateContact<Law> (ContactForce.hpp) is written once for
// all laws; the force pass is instantiated per law and withContactModel picks the law once
// per pass, so the pair loop holds no branch on the model.
//
// A new law: a policy with the same static members, an enumerator in ContactModel (and
// its name in contactModelFromName/contactModelName), its coefficients in PairCoefficients
// (ContactLaw::makeCoefficients), its time step (ContactLaw::contactDuration,
// maximumTimeStep), its settings check (validateContactSettings) and one case in
// withContactModel. It then runs contact by contact; to run it in the force pass's
// vectorised batch (optional), give it stiffnessConstants() and at(constants, delta) as
// the two laws here, a case in evaluateContactBatch (ContactBatch.cpp) and set
// hasBatchedLoop (ContactBatch.hpp).

#include "ContactLaw.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace sdf::dem
{

//- Stiffnesses and dashpots of one contact at its current overlap.
struct ContactStiffness
{
    double normalElasticForce;      // elastic part of F_n [N]
    double normalDamping;           // gamma_n [kg/s]
    double tangentialStiffness;     // k_t [N/m]
    double tangentialDamping;       // gamma_t [kg/s]
};

//- Linear spring-dashpot: constant k_n, k_t, gamma_n, gamma_t; the normal force is not
//  clipped (the dashpot turns it tensile at the end of a contact, as in the analytic
//  solution that fixes gamma_n from e).
struct LinearSpringDashpot
{
    static constexpr ContactModel model = ContactModel::linearSpringDashpot;

    //- The four constants at() reads, carried per contact by a ContactBatch.
    static std::array<double, 4> stiffnessConstants(const PairCoefficients& c)
    {
        return {c.kn, c.gammaN, c.kt, c.gammaT};
    }

    static ContactStiffness at(const std::array<double, 4>& k, double delta)
    {
        return {k[0]*delta, k[1], k[2], k[3]};
    }

    static ContactStiffness at(const PairCoefficients& c, double delta)
    {
        return at(stiffnessConstants(c), delta);
    }

    static double limitNormalForce(double fn) { return fn; }

    static double normalElasticEnergy(const PairCoefficients& c, double delta)
    {
        return 0.5*c.kn*delta*delta;
    }

    static double tangentialStiffness(const PairCoefficients& c, double /*delta*/)
    {
        return c.kt;
    }
};

//- Hertz-Mindlin: F_n = K delta^{3/2}, Mindlin S_t = mindlinK sqrt(delta), Tsuji dashpots
//  ~ delta^{1/4}; the normal force is clipped at zero (no attraction).
struct HertzMindlin
{
    static constexpr ContactModel model = ContactModel::hertzMindlin;

    static std::array<double, 4> stiffnessConstants(const PairCoefficients& c)
    {
        return {c.hertzK, c.hertzDamp, c.mindlinK, c.mindlinDamp};
    }

    static ContactStiffness at(const std::array<double, 4>& k, double delta)
    {
        const double sd = std::sqrt(delta);
        const double qd = std::sqrt(sd);
        return {k[0]*delta*sd, k[1]*qd, k[2]*sd, k[3]*qd};
    }

    static ContactStiffness at(const PairCoefficients& c, double delta)
    {
        return at(stiffnessConstants(c), delta);
    }

    static double limitNormalForce(double fn) { return fn < 0 ? 0 : fn; }

    static double normalElasticEnergy(const PairCoefficients& c, double delta)
    {
        return 0.4*c.hertzK*delta*delta*std::sqrt(delta);
    }

    static double tangentialStiffness(const PairCoefficients& c, double delta)
    {
        return c.mindlinK*std::sqrt(delta);
    }
};

//- Calls f(Law{}) with the policy of model: the one run-time dispatch on the contact law
//  (once per force pass, outside every loop over pairs).
template<class Function>
decltype(auto) withContactModel(ContactModel model, Function&& f)
{
    switch (model)
    {
        case ContactModel::linearSpringDashpot: return f(LinearSpringDashpot{});
        case ContactModel::hertzMindlin: return f(HertzMindlin{});
    }
    throw std::logic_error("withContactModel: contact model without a policy");
}

} // namespace sdf::dem

#endif

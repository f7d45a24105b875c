#include "ContactLaw.hpp"
#include "ContactModels.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace sdf::dem
{

ContactModel contactModelFromName(const std::string& name)
{
    if (name == "linear" || name == "linearSpringDashpot" || name == "hooke")
    {
        return ContactModel::linearSpringDashpot;
    }
    if (name == "hertz" || name == "hertzMindlin")
    {
        return ContactModel::hertzMindlin;
    }
    throw std::invalid_argument
    (
        "contact model '" + name + "' unknown; valid: linearSpringDashpot, hertzMindlin"
    );
}

std::string contactModelName(ContactModel model)
{
    return model == ContactModel::linearSpringDashpot ? "linearSpringDashpot" : "hertzMindlin";
}

std::string pairContactText(const PairContactSettings& p)
{
    std::string text = p.first + "/" + p.second + ":";
    const auto add = [&text](const char* key, const std::optional<double>& v)
    {
        if (!v) return;
        char buf[64];
        std::snprintf(buf, sizeof buf, " %s %.10g", key, *v);
        text += (text.back() == ':' ? "" : ",") + std::string(buf);
    };
    add("e", p.restitution);
    add("mu", p.friction);
    add("kn", p.normalStiffness);
    add("mu_r", p.rollingFriction);
    return text;
}

namespace
{

//- The checks of one contact's constants; `where` prefixes the message (a pair's entry).
void validateConstants
(
    const std::string& where,
    double restitution,
    double friction,
    const std::optional<double>& normalStiffness,
    double rollingFriction
)
{
    if (!(rollingFriction >= 0.0) || !std::isfinite(rollingFriction))
    {
        throw std::invalid_argument
        (
            where + "rollingFriction must be >= 0 (0: no rolling resistance; got "
          + std::to_string(rollingFriction) + ")"
        );
    }
    if (!(restitution > 0.0 && restitution <= 1.0))
    {
        throw std::invalid_argument
        (
            where + "restitution e = " + std::to_string(restitution) + " outside (0, 1]"
        );
    }
    if (!(friction >= 0.0) || !std::isfinite(friction))
    {
        throw std::invalid_argument
        (
            where + "friction must be >= 0 (got " + std::to_string(friction) + ")"
        );
    }
    if (normalStiffness && (!(*normalStiffness > 0) || !std::isfinite(*normalStiffness)))
    {
        throw std::invalid_argument(where + "normalStiffness must be positive");
    }
}

} // namespace

void validateContactSettings(const ContactSettings& s)
{
    const bool linear = s.model == ContactModel::linearSpringDashpot;
    validateConstants
    (
        "", s.restitution, s.friction,
        linear ? std::optional<double>(s.normalStiffness) : std::nullopt,
        s.rollingFriction
    );
    for (const auto& [name, value] :
         {std::pair{"rollingStiffness", s.rollingStiffness}, std::pair{"rollingDamping", s.rollingDamping}})
    {
        if (!(value >= 0) || !std::isfinite(value))
        {
            throw std::invalid_argument
            (
                std::string(name) + " must be >= 0 (0: the pair's tangential value, linear"
                " law; got " + std::to_string(value) + ")"
            );
        }
    }
    if (hasRollingResistance(s) && !linear && !(s.rollingStiffness > 0 && s.rollingDamping > 0))
    {
        throw std::invalid_argument
        (
            "rollingFriction with the hertzMindlin law needs rollingStiffness > 0 and"
            " rollingDamping > 0 (their defaults are the linear law's k_t and gamma_t)"
        );
    }
    if (linear)
    {
        if (!(s.tangentialStiffnessRatio > 0))
        {
            throw std::invalid_argument("tangentialStiffnessRatio must be positive");
        }
        if (!(s.tangentialDampingRatio >= 0))
        {
            throw std::invalid_argument("tangentialDampingRatio must be >= 0");
        }
    }
    else
    {
        if (!(s.youngsModulus > 0) || !std::isfinite(s.youngsModulus))
        {
            throw std::invalid_argument("youngsModulus must be positive");
        }
        if (!(s.poissonRatio > -1.0 && s.poissonRatio < 0.5))
        {
            throw std::invalid_argument("poissonRatio must be in (-1, 0.5)");
        }
    }
    // the pairs after the single values, so a message names a pair only for its own
    // entries
    for (const PairContactSettings& p : s.pairs)
    {
        const std::string where = "pair " + p.first + "/" + p.second + ": ";
        validateConstants
        (
            where, p.restitution.value_or(s.restitution), p.friction.value_or(s.friction),
            p.normalStiffness, p.rollingFriction.value_or(s.rollingFriction)
        );
        if (p.normalStiffness && s.model != ContactModel::linearSpringDashpot)
        {
            throw std::invalid_argument
            (
                where + "normalStiffness applies to the linearSpringDashpot law only"
                " (hertzMindlin: youngsModulus and poissonRatio, one material)"
            );
        }
    }
}

bool hasRollingResistance(const ContactSettings& s)
{
    bool rolling = s.rollingFriction > 0;
    for (const PairContactSettings& p : s.pairs) rolling = rolling || p.rollingFriction.value_or(0) > 0;
    return rolling;
}

double hertzRestitution(double alpha)
{
    // x'' = -x^{3/2} - alpha x^{1/4} x', x(0) = 0, x'(0) = 1; force clipped at zero.
    // RK4 with a small fixed step; the contact lasts about 3.2 time units.
    const double h = 2e-3;
    double x = 0, v = 1;
    auto acc = [alpha](double xx, double vv)
    {
        if (xx <= 0) return 0.0;
        const double sx = std::sqrt(xx);
        const double a = -xx*sx - alpha*std::sqrt(sx)*vv;
        return std::min(a, 0.0);
    };
    for (int step = 0; step < 2000000; ++step)
    {
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5*h*k1v, k2v = acc(x + 0.5*h*k1x, v + 0.5*h*k1v);
        const double k3x = v + 0.5*h*k2v, k3v = acc(x + 0.5*h*k2x, v + 0.5*h*k2v);
        const double k4x = v + h*k3v, k4v = acc(x + h*k3x, v + h*k3v);
        const double xn = x + h/6*(k1x + 2*k2x + 2*k3x + k4x);
        const double vn = v + h/6*(k1v + 2*k2v + 2*k3v + k4v);
        if (xn <= 0 && step > 0)
        {
            return -vn;
        }
        x = xn;
        v = vn;
        if (v >= 0 && x <= 0) return 0;
    }
    return -v;
}

double hertzDampingFactor(double e)
{
    if (e >= 1.0) return 0.0;
    // e(alpha) decreases monotonically: bracket, then safeguarded secant (regula falsi,
    // Illinois variant) on e(alpha) - e
    double lo = 0.0, hi = 1.0;
    double fLo = 1.0 - e;
    double fHi = hertzRestitution(hi) - e;
    while (fHi > 0) { lo = hi; fLo = fHi; hi *= 2; fHi = hertzRestitution(hi) - e; }
    int side = 0;
    for (int it = 0; it < 100; ++it)
    {
        const double mid = (lo*fHi - hi*fLo)/(fHi - fLo);
        const double fMid = hertzRestitution(mid) - e;
        if (std::abs(fMid) < 1e-12 || hi - lo < 1e-12*hi) return mid;
        if (fMid > 0)
        {
            lo = mid; fLo = fMid;
            if (side == -1) fHi *= 0.5;
            side = -1;
        }
        else
        {
            hi = mid; fHi = fMid;
            if (side == 1) fLo *= 0.5;
            side = 1;
        }
    }
    return 0.5*(lo + hi);
}

ContactLaw::ContactLaw(const ContactSettings& settings, const std::vector<Species>& species)
:
    settings_(settings),
    nSpecies_(int(species.size())),
    species_(species)
{
    validateContactSettings(settings_);
    validateSpecies(species_);
    // every pair entry names two species of the cell, and each pair once
    const auto index = [&](const std::string& name, const PairContactSettings& p)
    {
        for (int a = 0; a < nSpecies_; ++a)
        {
            if (species_[a].name == name) return a;
        }
        std::string valid;
        for (const Species& sp : species_) valid += " " + sp.name;
        throw std::invalid_argument
        (
            "pair " + p.first + "/" + p.second + ": unknown species '" + name
          + "'; valid:" + valid
        );
    };
    std::vector<int> seen(nSpecies_*nSpecies_, 0);
    for (const PairContactSettings& p : settings_.pairs)
    {
        const int a = index(p.first, p), b = index(p.second, p);
        if (seen[a*nSpecies_ + b]++)
        {
            throw std::invalid_argument
            (
                "pair " + p.first + "/" + p.second + " given more than once"
            );
        }
        if (a != b) seen[b*nSpecies_ + a]++;
    }
    pairs_.resize(nSpecies_*nSpecies_);
    walls_.resize(nSpecies_);
    for (int a = 0; a < nSpecies_; ++a)
    {
        for (int b = 0; b < nSpecies_; ++b)
        {
            pairs_[a*nSpecies_ + b] = makeCoefficients
            (
                species_[a].mass(), species_[a].radius(),
                species_[b].mass(), species_[b].radius(), false, constantsOf(a, b)
            );
        }
        walls_[a] = makeCoefficients
        (
            species_[a].mass(), species_[a].radius(), 0, 0, true,
            {settings_.restitution, settings_.friction, settings_.normalStiffness,
             settings_.rollingFriction}
        );
    }
}

ContactLaw::PairConstants ContactLaw::constantsOf(int a, int b) const
{
    PairConstants k
    {
        settings_.restitution, settings_.friction, settings_.normalStiffness,
        settings_.rollingFriction
    };
    for (const PairContactSettings& p : settings_.pairs)
    {
        const bool match =
            (p.first == species_[a].name && p.second == species_[b].name)
         || (p.first == species_[b].name && p.second == species_[a].name);
        if (!match) continue;
        k.restitution = p.restitution.value_or(k.restitution);
        k.friction = p.friction.value_or(k.friction);
        k.normalStiffness = p.normalStiffness.value_or(k.normalStiffness);
        k.rollingFriction = p.rollingFriction.value_or(k.rollingFriction);
    }
    return k;
}

PairCoefficients ContactLaw::makeCoefficients
(
    double mi, double ri, double mj, double rj, bool wall, const PairConstants& constants
) const
{
    PairCoefficients c;
    c.effectiveMass = wall ? mi : mi*mj/(mi + mj);
    c.effectiveRadius = wall ? ri : ri*rj/(ri + rj);
    c.friction = constants.friction;
    c.restitution = constants.restitution;
    const double e = constants.restitution;
    const double lnE = std::log(e);
    if (settings_.model == ContactModel::linearSpringDashpot)
    {
        c.kn = constants.normalStiffness;
        c.kt = settings_.tangentialStiffnessRatio*c.kn;
        // exact restitution of the damped oscillator m x'' + gamma x' + k x = 0
        c.gammaN = -2.0*lnE*std::sqrt(c.effectiveMass*c.kn)/std::sqrt(M_PI*M_PI + lnE*lnE);
        c.gammaT = settings_.tangentialDampingRatio*c.gammaN;
    }
    else
    {
        const double E = settings_.youngsModulus, nu = settings_.poissonRatio;
        const double G = E/(2*(1 + nu));
        // same material on both sides (a wall is the same material too)
        const double eStar = E/(2*(1 - nu*nu));
        const double gStar = G/(2*(2 - nu));
        const double sqrtR = std::sqrt(c.effectiveRadius);
        c.hertzK = 4.0/3.0*eStar*sqrtR;
        c.mindlinK = 8.0*gStar*sqrtR;
        // Tsuji: gamma_n = alpha sqrt(m* K) delta^{1/4}
        const double alpha = hertzDampingFactor(e);
        c.hertzDamp = alpha*std::sqrt(c.effectiveMass*c.hertzK);
        // same form for the tangential dashpot, with the Mindlin stiffness
        // S_t = mindlinK sqrt(delta) in place of dF_n/d delta = 1.5 K sqrt(delta)
        c.mindlinDamp = alpha*std::sqrt(c.effectiveMass*c.mindlinK/1.5);
    }
    c.rollingFriction = constants.rollingFriction;
    if (c.rollingFriction > 0)
    {
        c.rollingStiffness = settings_.rollingStiffness > 0 ? settings_.rollingStiffness : c.kt;
        c.rollingDamping = settings_.rollingDamping > 0 ? settings_.rollingDamping : c.gammaT;
    }
    return c;
}

double ContactLaw::contactDuration(double vImpact) const
{
    double shortest = std::numeric_limits<double>::max();
    for (const PairCoefficients& c : pairs_)
    {
        double tc;
        if (settings_.model == ContactModel::linearSpringDashpot)
        {
            const double lnE = std::log(c.restitution);
            const double omega0 = std::sqrt(c.kn/c.effectiveMass);
            tc = std::sqrt(M_PI*M_PI + lnE*lnE)/omega0;
        }
        else
        {
            // elastic Hertz duration 2.87 (m*^2/(R* E*^2 v))^{1/5}, with K = 4/3 E* sqrt(R*)
            const double eStar = 0.75*c.hertzK/std::sqrt(c.effectiveRadius);
            tc = 2.868*std::pow
            (
                c.effectiveMass*c.effectiveMass
               /(c.effectiveRadius*eStar*eStar*std::max(vImpact, 1e-300)),
                0.2
            );
        }
        shortest = std::min(shortest, tc);
    }
    return shortest;
}

double ContactLaw::normalElasticEnergy(const PairCoefficients& c, double delta) const
{
    if (delta <= 0) return 0;
    return withContactModel
    (
        model(), [&](auto law) { return decltype(law)::normalElasticEnergy(c, delta); }
    );
}

double ContactLaw::tangentialStiffness(const PairCoefficients& c, double delta) const
{
    return withContactModel
    (
        model(), [&](auto law) { return decltype(law)::tangentialStiffness(c, delta); }
    );
}

double ContactLaw::normalStiffnessAtForce(double force) const
{
    double k = 0;
    for (const PairCoefficients& c : pairs_)
    {
        k = std::max
        (
            k,
            settings_.model == ContactModel::linearSpringDashpot
          ? c.kn : 1.5*std::pow(c.hertzK, 2.0/3.0)*std::cbrt(std::max(force, 0.0))
        );
    }
    return k;
}

double ContactLaw::maximumTimeStep() const
{
    if (settings_.model == ContactModel::linearSpringDashpot)
    {
        return contactDuration(1.0)/50.0;
    }
    // Rayleigh time of the smallest-r*sqrt(rho) species
    const double E = settings_.youngsModulus, nu = settings_.poissonRatio;
    const double G = E/(2*(1 + nu));
    double tR = std::numeric_limits<double>::max();
    for (const Species& s : species_)
    {
        tR = std::min
        (
            tR,
            M_PI*s.radius()*std::sqrt(s.density/G)/(0.1631*nu + 0.8766)
        );
    }
    return 0.2*tR;
}

std::string ContactLaw::maximumTimeStepRule() const
{
    return settings_.model == ContactModel::linearSpringDashpot
        ? "t_c/50" : "0.2 Rayleigh times";
}

std::string ContactLaw::defaultTimeStepRule() const
{
    return settings_.model == ContactModel::linearSpringDashpot
        ? "t_c/100" : "0.1 Rayleigh times";
}

} // namespace sdf::dem

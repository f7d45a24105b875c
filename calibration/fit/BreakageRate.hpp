// Breakage rate of a particle from the impacts it suffers: Vogel & Peukert (2003,
// Powder Technol. 129, 101-110), applied to the impact-energy spectra of the DEM cells
// (dem/CellStatistics.hpp). Header-only and plain doubles, like LawFormulas.hpp, so the
// solver's breakage models can evaluate the same definitions without linking sdf_fit.
//
// Vogel & Peukert: a particle of size x [m] that suffers k impacts of mass-specific
// energy W [J/kg] survives them with probability
//     exp(-fMat x k (W - Wmin)+),   Wmin = xWmMin / x,
// with two material constants: fMat [kg/(J m)] and xWmMin = x Wmin [J m/kg] (the size
// times the threshold energy, a constant of the material). The per-impact survival
// exp(-fMat x (W - Wmin)+) composes by multiplication over independent impacts, so a
// population suffering impacts at frequencies f_b [1/s] of energies W_b keeps its parent
// (unbroken) fraction as exp(-S t) with the rate (selection function)
//     S = fMat x sum_b f_b (W_b - Wmin)+   [1/s]:
// first-order kinetics dn/dt = -S n, exactly (no small-probability linearisation).
//
// Decision: the mass-specific energy of a pair impact. The DEM records a pair's impact
// energy E = 0.5 m* g_n^2 (m* = m_i m_j/(m_i + m_j), g_n the normal relative speed: the
// kinetic energy of the normal relative motion in the centre-of-mass frame, all of it
// what the contact has to store or dissipate). We use
//     W = E / (m_i + m_j)        for either partner,
// the energy per unit mass of the colliding pair. For equal grains (m* = m/2) it is
// g_n^2/8 = (g_n/2)^2/2: the v^2/2 of the equivalent normal wall impact at speed g_n/2,
// which is what each grain does in the centre-of-mass frame (a symmetric head-on impact
// is a wall impact of each grain at half the closing speed), so Vogel & Peukert's
// constants, measured in wall-impact tests (W = v^2/2), apply unchanged. For unequal
// grains it gives both partners the same W (the pair's energy is shared by mass); a
// species-resolved split (e.g. by contact stiffness) would need a contact model the
// engine does not have.
#ifndef sdf_fit_BreakageRate_hpp
#define sdf_fit_BreakageRate_hpp

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace sdf::fit::breakage
{

namespace detail
{
//- Throws std::invalid_argument naming the parameter unless value is finite and >= 0
//  (> 0 when strictlyPositive).
inline void requireNonNegative(const char* name, double value, bool strictlyPositive = false)
{
    if (!std::isfinite(value) || value < 0 || (strictlyPositive && value == 0))
    {
        throw std::invalid_argument
        (
            std::string("breakage rate: ") + name + " = " + std::to_string(value)
          + (strictlyPositive ? " must be finite and > 0" : " must be finite and >= 0")
        );
    }
}
} // namespace detail

//- The two material constants of Vogel & Peukert.
struct VogelPeukertMaterial
{
    double fMat = 0;     // [kg/(J m)]
    double xWmMin = 0;   // size times threshold mass-specific energy [J m/kg]

    //- Throws std::invalid_argument naming fMat or xWmMin when negative or not finite.
    void validate() const
    {
        detail::requireNonNegative("fMat", fMat);
        detail::requireNonNegative("xWmMin", xWmMin);
    }
};

//- Mass-specific impact energy W [J/kg] of a pair impact of energy E = 0.5 m* g_n^2 [J]
//  between grains of masses mi and mj [kg]: W = E/(mi + mj) (header comment: the
//  equivalent wall impact at half the closing speed for equal grains).
inline double massSpecificImpactEnergy(double pairEnergy, double mi, double mj)
{
    detail::requireNonNegative("impact energy", pairEnergy);
    detail::requireNonNegative("mi", mi, true);
    detail::requireNonNegative("mj", mj, true);
    return pairEnergy/(mi + mj);
}

//- Threshold Wmin = xWmMin/x [J/kg] of a particle of size x [m].
inline double thresholdEnergy(const VogelPeukertMaterial& material, double x)
{
    material.validate();
    detail::requireNonNegative("x (particle size)", x, true);
    return material.xWmMin/x;
}

//- -ln(survival) of one impact: fMat x (W - Wmin)+ (dimensionless).
inline double impactBreakageExponent(const VogelPeukertMaterial& material, double x, double W)
{
    detail::requireNonNegative("W (mass-specific impact energy)", W);
    const double excess = W - thresholdEnergy(material, x);
    return excess > 0 ? material.fMat*x*excess : 0.0;
}

//- Probability that one impact of energy W breaks a particle of size x:
//  1 - exp(-fMat x (W - Wmin)+).
inline double impactBreakageProbability(const VogelPeukertMaterial& material, double x, double W)
{
    return -std::expm1(-impactBreakageExponent(material, x, W));
}

//- The impacts one particle suffers per unit time, binned by mass-specific energy.
struct ImpactSpectrum
{
    std::vector<double> energy;      // W of each bin [J/kg] (representative value)
    std::vector<double> frequency;   // impacts per second per particle in the bin [1/s]
};

//- Breakage rate S = fMat x sum_b f_b (W_b - Wmin)+ [1/s] of a particle of size x [m]
//  under the impacts of spectrum. Throws std::invalid_argument naming the entry for a
//  negative or non-finite material constant, size, energy or frequency, or bins of
//  unequal number.
inline double vogelPeukertBreakageRate
(
    const VogelPeukertMaterial& material,
    double x,
    const ImpactSpectrum& spectrum
)
{
    if (spectrum.energy.size() != spectrum.frequency.size())
    {
        throw std::invalid_argument
        (
            "breakage rate: impact spectrum has " + std::to_string(spectrum.energy.size())
          + " energies and " + std::to_string(spectrum.frequency.size()) + " frequencies"
        );
    }
    material.validate();
    detail::requireNonNegative("x (particle size)", x, true);
    double rate = 0;
    for (std::size_t b = 0; b < spectrum.energy.size(); ++b)
    {
        detail::requireNonNegative("impact frequency", spectrum.frequency[b]);
        rate += spectrum.frequency[b]*impactBreakageExponent(material, x, spectrum.energy[b]);
    }
    return rate;
}

//- Fraction of the parent particles left unbroken after time t [s] at rate S [1/s]:
//  exp(-S t).
inline double parentFraction(double rate, double time)
{
    detail::requireNonNegative("breakage rate", rate);
    detail::requireNonNegative("time", time);
    return std::exp(-rate*time);
}

//- S for an exponential impact-energy spectrum (the Maxwell-Boltzmann spectrum of a gas
//  at equilibrium, dem.impact_energy), impacts at frequency omega [1/s] of mean
//  mass-specific energy Wmean [J/kg]: omega int (W - Wmin)+ exp(-W/Wmean) dW/Wmean =
//      S = fMat x omega Wmean exp(-Wmin/Wmean).
//  What a solver evaluates from the fitted collision-frequency and impact-energy laws.
inline double vogelPeukertRateExponentialSpectrum
(
    const VogelPeukertMaterial& material,
    double x,
    double omega,
    double Wmean
)
{
    detail::requireNonNegative("impact frequency", omega);
    detail::requireNonNegative("mean impact energy", Wmean, true);
    const double Wmin = thresholdEnergy(material, x);
    return material.fMat*x*omega*Wmean*std::exp(-Wmin/Wmean);
}

//- The impact spectrum of one particle of species s with partners of species t from a
//  collision histogram of the DEM (dem::CollisionStatistics of the pair (s, t), pair
//  energies E [J]): binEdges (nBins + 1, increasing), counts (nBins + 2: under, bins,
//  over) counted over elapsedTime [s] among particlesOfS particles of species s; a
//  collision within s (sameSpecies) involves two of them. Masses ms, mt [kg] convert E
//  to W = E/(ms + mt). Representative energy of a bin: its arithmetic midpoint (for bins
//  wholly above the threshold S is linear in W, so the midpoint is exact for a spectrum
//  flat within the bin); the underflow slot at half the first edge; the overflow slot
//  at the last edge (a lower bound: keep the top edge far above the energies that
//  matter, as CellRun's 1e3 x 0.5 m T does).
inline ImpactSpectrum impactSpectrumFromHistogram
(
    const std::vector<double>& binEdges,
    const std::vector<long>& counts,
    double elapsedTime,
    int particlesOfS,
    bool sameSpecies,
    double ms,
    double mt
)
{
    if (binEdges.size() < 2 || counts.size() != binEdges.size() + 1)
    {
        throw std::invalid_argument
        (
            "impact spectrum: need nBins + 1 >= 2 bin edges and nBins + 2 counts, got "
          + std::to_string(binEdges.size()) + " edges and " + std::to_string(counts.size())
          + " counts"
        );
    }
    detail::requireNonNegative("elapsedTime", elapsedTime, true);
    detail::requireNonNegative("particlesOfS", particlesOfS, true);
    const double perCount = (sameSpecies ? 2.0 : 1.0)/(elapsedTime*particlesOfS);
    const std::size_t nBins = binEdges.size() - 1;
    ImpactSpectrum spectrum;
    spectrum.energy.resize(nBins + 2);
    spectrum.frequency.resize(nBins + 2);
    for (std::size_t k = 0; k < nBins + 2; ++k)
    {
        if (counts[k] < 0)
        {
            throw std::invalid_argument("impact spectrum: count of slot "
                                        + std::to_string(k) + " is negative");
        }
        const double E =
            k == 0 ? 0.5*binEdges.front()
          : k == nBins + 1 ? binEdges.back()
          : 0.5*(binEdges[k - 1] + binEdges[k]);
        spectrum.energy[k] = massSpecificImpactEnergy(E, ms, mt);
        spectrum.frequency[k] = perCount*double(counts[k]);
    }
    return spectrum;
}

} // namespace sdf::fit::breakage

#endif

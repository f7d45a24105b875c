// Green-Kubo integrals of the nine stress products of a binary mixture and
// the seed's kinetic sieving rule (seed eqs 8-13):
//   J = J^1 + J^2 + J^12,   <J(0) J(t)> = sum_{i,j} <J^i(0) J^j(t)>,
//   eta_1 = int <J^1 J^1> + c_1 int <J^12 J^12>,
//   eta_2 = int <J^2 J^2> + c_2 int <J^12 J^12>   (cross terms neglected),
// with crossToProductRatio reported so that the neglect is checked, not assumed,
// and a rule that keeps the cross terms (kineticSievingCoefficientsWithCrossTerms).
#ifndef sdf_correlation_StressGreenKubo_hpp
#define sdf_correlation_StressGreenKubo_hpp

#include "correlation/FftCorrelator.hpp"
#include "correlation/GreenKubo.hpp"
#include "correlation/MultipleTauCorrelator.hpp"

#include <vector>

namespace sdf::correlation
{

struct StressProductIntegrals
{
    std::size_t seriesCount = 0;
    //- Green-Kubo of C_ij = <s_i(0) s_j(t)>, index i * seriesCount + j.
    std::vector<GreenKuboResult> terms;
    //- Green-Kubo of the autocorrelation of the total (sum of all terms).
    GreenKuboResult total;
    //- sum_{i != j} |int C_ij| / sum_i |int C_ii| (plateau values).
    double crossToProductRatio = 0.0;

    const GreenKuboResult& term(std::size_t i, std::size_t j) const
    {
        return terms.at(i * seriesCount + j);
    }
};

//- From per-block FFT product correlations on the uniform grid `times`.
StressProductIntegrals stressProductIntegrals
(
    const std::vector<double>& times,
    const std::vector<SeriesProductCorrelations>& blocks,
    const PlateauSettings& settings = PlateauSettings()
);

//- From the blocks of a SeriesProductCorrelator (column i*S + j).
StressProductIntegrals stressProductIntegrals
(
    const std::vector<LaggedCorrelation>& blocks,
    double sampleInterval,
    std::size_t seriesCount,
    const PlateauSettings& settings = PlateauSettings()
);

//- The blocks' product correlations about the series' means. A sheared cell's shear
//  stress has a mean (its rheology): correlated raw, <s_i(0) s_j(t)> tends to m_i m_j,
//  not to zero, and the Green-Kubo integral grows with t instead of reaching a plateau.
//  With a = m_i + da, b = m_j + db, a block's raw product is m_i m_j + m_i <db> +
//  m_j <da> + <da db>: the run's mean m-hat (runMeans) removes the constant, each block's
//  own means mb (blockMeans[block]) the linear terms, whose block-to-block noise m <d>
//  would otherwise swamp the errors:
//      C_ij(t) - m-hat_i mb_j - mb_i m-hat_j + m-hat_i m-hat_j.
//  Left: terms of second order in the run mean's error and in the blocks' edges (the
//  origins of lag t span the block less t). Subtracting each block's mean outright would
//  lower the running integral by about 2 I t/T_block instead. Throws
//  std::invalid_argument when the counts of blocks or series do not match.
std::vector<LaggedCorrelation> aboutMeans
(
    std::vector<LaggedCorrelation> blocks,
    const std::vector<std::vector<double>>& blockMeans,
    const std::vector<double>& runMeans
);

//- The seed's rule for a binary mixture, series ordered (J^1, J^2, J^12):
//  eta_i = I_ii + composition_i I_{12,12}. composition: the two species'
//  shares of the solids (volume fractions of the solids, summing to 1).
//  The errors add the two terms' errors in quadrature (their covariance is
//  neglected).
std::vector<Estimate> kineticSievingCoefficients
(
    const StressProductIntegrals& integrals,
    const std::vector<double>& composition
);

//- The same split with the cross terms kept (docs/developer/calibration-fit.md,
//  "Kinetic sieving: attributing the cross terms"): each series is owned by the
//  species it belongs to, J^12 by both in the proportions of composition
//  (w_i(J^i) = 1, w_i(J^other) = 0, w_i(J^12) = composition_i), and each product
//  integral I_ab is split between the species by the mean of its two factors'
//  shares: eta_i = sum_ab (w_i(a) + w_i(b))/2 I_ab. The two eta sum to the
//  integral of the whole stress autocorrelation, sum_ab I_ab, for any cross
//  terms; with the cross terms zero it is the seed's rule above. Errors: the
//  terms' errors times their weights, in quadrature (covariances neglected).
std::vector<Estimate> kineticSievingCoefficientsWithCrossTerms
(
    const StressProductIntegrals& integrals,
    const std::vector<double>& composition
);

} // namespace sdf::correlation

#endif

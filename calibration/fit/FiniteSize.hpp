// Finite-size extrapolation of a transport coefficient measured in periodic cells of
// several sizes. In a periodic cell the hydrodynamic self-interaction of a particle
// with its images lowers the self-diffusivity by an amount proportional to 1/L
// (Duenweg and Kremer 1993; Yeh and Hummer 2004, J. Phys. Chem. B 108, 15873):
//
//   D(N) = D_inf - a N^(-1/3)          (L ~ N^(1/3) at fixed solids fraction)
//
// which the stochastically driven dense cells of the seed's mixture follow
// (docs/validation.md, "DEM driving": phi 0.3, N 300-2400, reduced chi2 0.92 for
// the MSD's D, 0.36 for Green-Kubo's).
// D_inf and a are fitted by weighted least squares in u = N^(-1/3) (GSL's
// gsl_fit_wlinear): two rows give the line through both points with the errors
// propagated; three or more rows give the reduced chi2, and a scatter beyond the errors
// widens the reported errors by sqrt(chi2/dof).
#ifndef sdf_fit_FiniteSize_hpp
#define sdf_fit_FiniteSize_hpp

#include <vector>

namespace sdf::fit
{

//- One cell size.
struct SizedValue
{
    double particles = 0;   // N > 0
    double value = 0;
    double sigma = 0;       // standard error, > 0
};

struct FiniteSizeExtrapolation
{
    double value = 0, error = 0;   // the infinite-cell limit
    double slope = 0, slopeError = 0;   // a of value(N) = value_inf - a N^(-1/3)
    double reducedChiSquare = 0;   // 0 with two sizes
    std::size_t sizes = 0;
};

//- Throws std::invalid_argument (naming the row and entry) for fewer than two
//  distinct sizes, N <= 0, sigma <= 0 or values that are not finite.
FiniteSizeExtrapolation extrapolateInverseCubeRoot(const std::vector<SizedValue>& rows);

} // namespace sdf::fit

#endif

// The fragments of broken particles sieved, and the Austin breakage function fitted to
// them: the `austin` daughter size distribution of the solver's breakage models,
//     B(x, y) = phi (x/y)^gamma + (1 - phi) (x/y)^beta,
// the cumulative mass fraction of a parent's (size y) fragments finer than x (Austin &
// Luckie 1972; King 2001, Modeling and Simulation of Mineral Processing Systems, ch. 5).
//
// The table (ColumnTable's form): columns size (the parents' size y [m]), sieve (the
// aperture [m] the mass was retained on; 0 for the pan) and mass (retained, any one
// unit), one row per parent size and sieve. Per parent size the fraction finer than each
// sieve is the mass below it (the pan and the finer sieves) over all the fragments'.
#ifndef sdf_fit_FragmentSieving_hpp
#define sdf_fit_FragmentSieving_hpp

#include <iosfwd>
#include <string>
#include <vector>

namespace sdf::fit::breakage
{

struct SieveFraction
{
    double parentSize = 0;   // y [m]
    double sieve = 0;        // aperture [m] (0: the pan)
    double mass = 0;         // retained on it
    int line = 0;
};

//- Reads a sieve analysis. Throws std::invalid_argument naming the source, line and
//  column for: the table's form (ColumnTable), a missing column, a parent size <= 0, a
//  sieve < 0 or not below its parent size, a negative mass, a sieve given twice for one
//  parent size, a parent size whose fragments weigh nothing, no rows.
std::vector<SieveFraction> readFragmentSieving(std::istream& stream, const std::string& source);
std::vector<SieveFraction> readFragmentSieving(const std::string& path);

//- One point of a cumulative distribution: the fraction of a parent's fragments finer
//  than ratio = sieve/parent size.
struct FinerFraction
{
    double parentSize = 0;
    double ratio = 0;
    double finer = 0;
};

//- The cumulative fractions finer than every sieve above the pan, per parent size.
std::vector<FinerFraction> finerFractions(const std::vector<SieveFraction>& sieving);

struct AustinFitResult
{
    double phi = 0, gamma = 0, beta = 0;            // gamma <= beta: phi weighs the fine term
    double phiError = 0, gammaError = 0, betaError = 0;   // standard errors (NaN: none)
    double rms = 0;                                 // of B - finer over the points
    int points = 0;
};

//- B(x, y) at ratio = x/y.
double austinFiner(double phi, double gamma, double beta, double ratio);

//- Least squares of B against the cumulative fractions; standard errors from the
//  Jacobian with the residuals' variance (points - 3 degrees of freedom). Throws
//  std::invalid_argument when fewer than four points or fewer than three distinct ratios
//  leave the three constants undetermined.
AustinFitResult fitAustin(const std::vector<SieveFraction>& sieving);

} // namespace sdf::fit::breakage

#endif

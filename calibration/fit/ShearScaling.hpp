// The dimensionless groups of a sheared calibration (Lees-Edwards cells at a
// prescribed shear rate gammaDot, granular temperature measured):
//
//   C = D/(gammaDot dMean^2)      the shear-induced diffusivity in units of the
//                                 mean grain and the shear rate; the closure of
//                                 the Lueptow group is C = 0.042 (Fan et al. 2014,
//                                 J. Fluid Mech. 741, 252; Schlick et al. 2015,
//                                 J. Fluid Mech. 765, 632), used by the solver's
//                                 diffusivity model shearRate
//   R = dMean gammaDot sqrt(3/T)  the Savage-Jeffrey parameter (the seed's eq 7
//                                 solved for R), used by the solver's
//                                 granularTemperature model savageJeffrey
//
// dMean is the solids-volume weighted mean diameter (1 - x) d_fine + x d_coarse,
// as the solver's shearRate and savageJeffrey models take it. Both groups are
// summarised as a weighted mean and as a power law in phi, C = C0 phi^b, fitted in
// log space with GSL's weighted linear least squares; a scatter beyond the
// errors (reduced chi2 > 1) widens the reported errors by sqrt(chi2/dof).
#ifndef sdf_fit_ShearScaling_hpp
#define sdf_fit_ShearScaling_hpp

#include "fit/FitData.hpp"

#include <vector>

namespace sdf::fit
{

//- One sheared condition.
struct ShearedObservation
{
    double phi = 0;
    double x = 0;
    double gammaDot = 0;   // imposed shear rate [1/s], > 0
    double T = 0;          // measured granular temperature (sum of 3 components) [m2/s2], > 0
    double dMean = 0;      // solids-volume weighted mean diameter [m], > 0
    double D = 0;          // diffusivity across the shear (yy) [m2/s], > 0
    double DError = 0;     // its standard error, > 0
};

//- A weighted mean with its error (widened by sqrt(chi2/dof) when that exceeds 1).
struct WeightedMean
{
    double value = 0;
    double error = 0;
    double reducedChiSquare = 0;   // about the mean; 0 for a single value
};

//- y = A phi^b fitted as ln y = ln A + b ln phi.
struct PhiPowerLaw
{
    double A = 0, AError = 0;
    double b = 0, bError = 0;
    double reducedChiSquare = 0;
    bool fitted = false;           // needs at least 3 rows and 2 distinct phi
};

struct ShearScaling
{
    //- Per row: C = D/(gammaDot dMean^2) with its error, R = dMean gammaDot sqrt(3/T)
    std::vector<double> C, CError, R;
    WeightedMean meanC;
    PhiPowerLaw CLaw;
    //- R has no error of its own here (T's is small): unweighted mean and standard
    //  deviation of the rows; and its power law in phi (unit weights: its
    //  reducedChiSquare is the variance of ln R about the law, not a chi2)
    double meanR = 0, spreadR = 0;
    PhiPowerLaw RLaw;
    Range phi, x, gammaDot;
};

//- Throws std::invalid_argument naming the row and the entry when the table is
//  empty or a value is not finite or out of range (phi in (0, 1), x in [0, 1],
//  gammaDot, T, dMean, D, DError > 0).
ShearScaling shearScaling(const std::vector<ShearedObservation>& rows);

//- The solids-volume weighted mean diameter (1 - x) dFine + x dCoarse.
double volumeMeanDiameter(double x, double dFine, double dCoarse);

} // namespace sdf::fit

#endif

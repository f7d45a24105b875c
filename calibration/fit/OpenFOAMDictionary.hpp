// Writer of constant/granularCoefficients: the chosen law of each calibrated
// coefficient as an OpenFOAM dictionary, read by the solver's `calibrated`
// models. Format with an example: docs/developer/calibration-fit.md.
#ifndef sdf_fit_OpenFOAMDictionary_hpp
#define sdf_fit_OpenFOAMDictionary_hpp

#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace sdf::fit
{

//- One coefficient (sub-dictionary name, e.g. "D" or "eta"), the fit chosen
//  for it and, optionally, the model selection it came out of (written as
//  the criterion differences of all candidates).
struct CalibratedCoefficient
{
    std::string coefficient;
    FitResult fit;
    std::optional<ModelSelection> selection;
};

//- Writes the FoamFile header and one sub-dictionary per coefficient.
//  Throws std::invalid_argument for an empty list, a coefficient name that is
//  not an OpenFOAM word or appears twice, and FitFailure for a fit that did
//  not converge (a failed fit is never written as if good).
void writeOpenFOAMDictionary
(
    std::ostream& os,
    const std::vector<CalibratedCoefficient>& coefficients
);

} // namespace sdf::fit

#endif

// Writer of constant/granularCoefficients: the chosen law of each calibrated
// coefficient as an OpenFOAM dictionary, read by the solver's `calibrated`
// models. Format with an example: docs/developer/calibration-fit.md.
#ifndef sdf_fit_OpenFOAMDictionary_hpp
#define sdf_fit_OpenFOAMDictionary_hpp

#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"
#include "fit/ShearScaling.hpp"

#include <optional>
#include <ostream>
#include <string>
#include <utility>
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
    //- Choices the coefficient depends on beyond its law and data, written as
    //  `key value;` (eta: sievingAttribution seed|crossTerms)
    std::vector<std::pair<std::string, std::string>> provenance{};
};

//- The banner and FoamFile header of constant/granularCoefficients (object
//  granularCoefficients, location constant), ending with its closing brace's line.
std::string coefficientsFileHeader();

//- Writes the FoamFile header and one sub-dictionary per coefficient, and for
//  a sheared calibration (shear not null) the sub-dictionary shearScaling: the
//  mean C = D/(gammaDot dMean^2) of the fines (the solver's shearRate
//  diffusivity), the mean Savage-Jeffrey R (its savageJeffrey temperature) and
//  their power laws in phi, with errors and envelope.
//  Throws std::invalid_argument for an empty list, a coefficient name that is
//  not an OpenFOAM word or appears twice, and FitFailure for a fit that did
//  not converge (a failed fit is never written as if good).
void writeOpenFOAMDictionary
(
    std::ostream& os,
    const std::vector<CalibratedCoefficient>& coefficients,
    const ShearScaling* shear = nullptr
);

} // namespace sdf::fit

#endif

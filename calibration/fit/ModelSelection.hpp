// Ranking of laws fitted to the same table by an information criterion.
// Differences of AIC (or BIC) between laws fitted to the same data in the
// same space are meaningful; the absolute values are not (constants dropped).
// Rule of thumb (Burnham & Anderson): delta < 2 the laws are equally
// supported, delta > 10 the worse law has essentially no support.
#ifndef sdf_fit_ModelSelection_hpp
#define sdf_fit_ModelSelection_hpp

#include "fit/LeastSquares.hpp"

#include <string>
#include <vector>

namespace sdf::fit
{

enum class InformationCriterion
{
    AIC,
    BIC
};

std::string toString(InformationCriterion criterion);

struct RankedLaw
{
    std::string law;
    std::size_t index = 0;   // position in the fits given to selectModel
    double criterion = 0.0;  // AIC or BIC
    double delta = 0.0;      // criterion - best criterion (>= 0)
    double weight = 0.0;     // exp(-delta/2) normalised over the ranked laws
};

struct ModelSelection
{
    InformationCriterion criterion = InformationCriterion::AIC;
    //- Converged fits, best first.
    std::vector<RankedLaw> ranking;
    //- Fits that failed: (law name, message). They take no part in the ranking.
    std::vector<std::pair<std::string, std::string>> failed;

    const RankedLaw& best() const { return ranking.front(); }
};

//- Throws std::invalid_argument when there are no fits or they are not
//  comparable (different number of points, fit space or sigma meaning), and
//  FitFailure when none converged.
ModelSelection selectModel
(
    const std::vector<FitResult>& fits,
    InformationCriterion criterion = InformationCriterion::AIC
);

} // namespace sdf::fit

#endif

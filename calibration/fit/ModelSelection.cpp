#include "fit/ModelSelection.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

std::string toString(InformationCriterion criterion)
{
    return criterion == InformationCriterion::AIC ? "AIC" : "BIC";
}

ModelSelection selectModel
(
    const std::vector<FitResult>& fits,
    InformationCriterion criterion
)
{
    if (fits.empty())
    {
        throw std::invalid_argument("selectModel: no fits given");
    }
    const FitResult& first = fits.front();
    for (std::size_t i = 1; i < fits.size(); ++i)
    {
        const FitResult& f = fits[i];
        if (f.points != first.points || f.space != first.space
            || f.sigmaMeaning != first.sigmaMeaning)
        {
            std::ostringstream m;
            m << "selectModel: fit " << i << " (law '" << f.law.name()
              << "') is not comparable with fit 0 (law '" << first.law.name()
              << "'): information criteria compare laws fitted to the same table"
                 " in the same space with the same meaning of sigma";
            throw std::invalid_argument(m.str());
        }
    }

    ModelSelection selection;
    selection.criterion = criterion;
    for (std::size_t i = 0; i < fits.size(); ++i)
    {
        const FitResult& f = fits[i];
        if (!f.converged())
        {
            selection.failed.emplace_back(f.law.name(), f.message);
            continue;
        }
        RankedLaw r;
        r.law = f.law.name();
        r.index = i;
        r.criterion = criterion == InformationCriterion::AIC ? f.aic : f.bic;
        selection.ranking.push_back(r);
    }
    if (selection.ranking.empty())
    {
        std::string reasons;
        for (const auto& [law, message] : selection.failed)
        {
            reasons += "\n  " + message;
        }
        throw FitFailure("selectModel: no fit converged:" + reasons);
    }
    std::stable_sort
    (
        selection.ranking.begin(), selection.ranking.end(),
        [](const RankedLaw& a, const RankedLaw& b) { return a.criterion < b.criterion; }
    );
    double weightSum = 0.0;
    for (RankedLaw& r : selection.ranking)
    {
        r.delta = r.criterion - selection.ranking.front().criterion;
        r.weight = std::exp(-0.5 * r.delta);
        weightSum += r.weight;
    }
    for (RankedLaw& r : selection.ranking)
    {
        r.weight /= weightSum;
    }
    return selection;
}

} // namespace sdf::fit

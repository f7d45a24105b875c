// A constitutive law y = f(condition; p) as a value: any type with the
// interface below (see Laws.hpp) is wrapped so that fits, model selection and
// the dictionary writer can hold different laws side by side. The wrapped law
// is immutable, so copies share it.
//
// Interface a law type L provides:
//   std::string name() const;                          // dictionary `law` word
//   std::string formula() const;                       // human-readable form
//   std::vector<std::string> parameterNames() const;
//   double evaluate(const Condition&, const Eigen::VectorXd& p) const;
//   Eigen::VectorXd gradient(const Condition&, const Eigen::VectorXd& p) const;  // df/dp
//   Eigen::VectorXd initialParameters(const std::vector<Observation>&) const;
//   std::vector<std::pair<std::string, double>> fixedEntries() const;  // constants, not fitted
#ifndef sdf_fit_ConstitutiveLaw_hpp
#define sdf_fit_ConstitutiveLaw_hpp

#include "fit/FitData.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace sdf::fit
{

class ConstitutiveLaw
{
public:
    template
    <
        class Law,
        class = std::enable_if_t<!std::is_same_v<std::decay_t<Law>, ConstitutiveLaw>>
    >
    ConstitutiveLaw(Law law)   // implicit on purpose: fitLaw(SeedPowerLaw{}, data)
    :
        self_(std::make_shared<const Model<Law>>(std::move(law)))
    {}

    std::string name() const { return self_->name(); }
    std::string formula() const { return self_->formula(); }
    std::vector<std::string> parameterNames() const { return self_->parameterNames(); }
    std::size_t parameterCount() const { return self_->parameterNames().size(); }

    double evaluate(const Condition& c, const Eigen::VectorXd& p) const
    {
        return self_->evaluate(c, p);
    }
    Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const
    {
        return self_->gradient(c, p);
    }
    Eigen::VectorXd initialParameters(const std::vector<Observation>& data) const
    {
        return self_->initialParameters(data);
    }
    std::vector<std::pair<std::string, double>> fixedEntries() const
    {
        return self_->fixedEntries();
    }

private:
    struct Concept
    {
        virtual ~Concept() = default;
        virtual std::string name() const = 0;
        virtual std::string formula() const = 0;
        virtual std::vector<std::string> parameterNames() const = 0;
        virtual double evaluate(const Condition&, const Eigen::VectorXd&) const = 0;
        virtual Eigen::VectorXd gradient(const Condition&, const Eigen::VectorXd&) const = 0;
        virtual Eigen::VectorXd initialParameters(const std::vector<Observation>&) const = 0;
        virtual std::vector<std::pair<std::string, double>> fixedEntries() const = 0;
    };

    template<class Law>
    struct Model final : Concept
    {
        explicit Model(Law l) : law(std::move(l)) {}
        std::string name() const override { return law.name(); }
        std::string formula() const override { return law.formula(); }
        std::vector<std::string> parameterNames() const override { return law.parameterNames(); }
        double evaluate(const Condition& c, const Eigen::VectorXd& p) const override
        {
            return law.evaluate(c, p);
        }
        Eigen::VectorXd gradient(const Condition& c, const Eigen::VectorXd& p) const override
        {
            return law.gradient(c, p);
        }
        Eigen::VectorXd initialParameters(const std::vector<Observation>& d) const override
        {
            return law.initialParameters(d);
        }
        std::vector<std::pair<std::string, double>> fixedEntries() const override
        {
            return law.fixedEntries();
        }
        Law law;
    };

    std::shared_ptr<const Concept> self_;
};

} // namespace sdf::fit

#endif

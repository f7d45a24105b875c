#include "fit/FitData.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace sdf::fit
{

namespace
{

[[noreturn]] void rejectRow
(
    const std::string& context,
    std::size_t row,
    const std::string& entry,
    double value,
    const std::string& requirement
)
{
    std::ostringstream message;
    message << context << ": row " << row << ": " << entry << " = " << value
            << " " << requirement;
    throw std::invalid_argument(message.str());
}

Range include(Range r, double v)
{
    return Range{std::min(r.min, v), std::max(r.max, v)};
}

} // namespace

void validateObservations
(
    const std::vector<Observation>& data,
    std::size_t parameterCount,
    bool positiveValues,
    const std::string& context
)
{
    if (data.empty())
    {
        throw std::invalid_argument(context + ": no data (empty table)");
    }
    if (data.size() <= parameterCount)
    {
        std::ostringstream message;
        message << context << ": " << data.size() << " rows for " << parameterCount
                << " parameters; a fit needs more rows than parameters";
        throw std::invalid_argument(message.str());
    }
    for (std::size_t row = 0; row < data.size(); ++row)
    {
        const Condition& c = data[row].condition;
        const auto finite = [&](const char* entry, double v)
        {
            if (!std::isfinite(v))
            {
                rejectRow(context, row, entry, v, "is not finite");
            }
        };
        finite("phi", c.phi);
        finite("x", c.x);
        finite("T", c.T);
        finite("d", c.d);
        finite("value", data[row].value);
        finite("sigma", data[row].sigma);
        if (c.phi <= 0.0 || c.phi >= 1.0)
        {
            rejectRow(context, row, "phi", c.phi, "must lie in (0, 1)");
        }
        if (c.x < 0.0 || c.x > 1.0)
        {
            rejectRow(context, row, "x", c.x, "must lie in [0, 1]");
        }
        // a segregation row (p* given) has no granular temperature: its laws do not read it
        if (c.T <= 0.0 && !c.pressureNumber)
        {
            rejectRow(context, row, "T", c.T, "must be > 0 [m2/s2]");
        }
        if (c.d <= 0.0)
        {
            rejectRow(context, row, "d", c.d, "must be > 0 [m]");
        }
        if (c.gammaDot)
        {
            finite("gammaDot", *c.gammaDot);
            if (*c.gammaDot < 0.0)
            {
                rejectRow(context, row, "gammaDot", *c.gammaDot, "must be >= 0 [1/s]");
            }
        }
        if (c.inertialNumber)
        {
            finite("inertialNumber", *c.inertialNumber);
            if (!(*c.inertialNumber > 0.0))
            {
                rejectRow(context, row, "inertialNumber", *c.inertialNumber, "must be > 0");
            }
        }
        if (c.pressureNumber)
        {
            finite("pressureNumber", *c.pressureNumber);
            if (!(*c.pressureNumber > 0.0))
            {
                rejectRow(context, row, "pressureNumber", *c.pressureNumber, "must be > 0");
            }
        }
        if (c.sizeRatio)
        {
            finite("sizeRatio", *c.sizeRatio);
            if (!(*c.sizeRatio >= 1.0))
            {
                rejectRow(context, row, "sizeRatio", *c.sizeRatio, "must be >= 1 (d_coarse/d_fine)");
            }
        }
        if (data[row].sigma <= 0.0)
        {
            rejectRow(context, row, "sigma", data[row].sigma, "must be > 0");
        }
        if (positiveValues && data[row].value <= 0.0)
        {
            rejectRow
            (
                context, row, "value", data[row].value,
                "must be > 0 for a fit in log space (fit in linear space instead)"
            );
        }
    }
}

Envelope envelopeOf(const std::vector<Observation>& data)
{
    if (data.empty())
    {
        throw std::invalid_argument("envelopeOf: no data (empty table)");
    }
    const Condition& first = data.front().condition;
    Envelope e;
    e.phi = {first.phi, first.phi};
    e.x = {first.x, first.x};
    e.T = {first.T, first.T};
    e.d = {first.d, first.d};
    bool allSheared = true;
    Range gammaDot{INFINITY, -INFINITY};
    for (const Observation& o : data)
    {
        const Condition& c = o.condition;
        e.phi = include(e.phi, c.phi);
        e.x = include(e.x, c.x);
        e.T = include(e.T, c.T);
        e.d = include(e.d, c.d);
        if (c.gammaDot)
        {
            gammaDot = include(gammaDot, *c.gammaDot);
        }
        else
        {
            allSheared = false;
        }
    }
    if (allSheared)
    {
        e.gammaDot = gammaDot;
    }
    return e;
}

} // namespace sdf::fit

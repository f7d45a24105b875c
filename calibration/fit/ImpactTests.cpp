#include "ImpactTests.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sdf::fit::breakage
{

const std::vector<std::string>& impactTestColumns()
{
    static const std::vector<std::string> columns =
        {"size", "velocity", "energy", "impacts", "tested", "broken"};
    return columns;
}

namespace
{

std::string joined(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
    return out;
}

[[noreturn]] void refuse(const std::string& source, int line, const std::string& what)
{
    throw std::invalid_argument(source + ":" + std::to_string(line) + ": " + what);
}

// The line without its comment, split into words
std::vector<std::string> words(const std::string& text)
{
    std::istringstream in(text.substr(0, text.find('#')));
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

double number(const std::string& word, const std::string& source, int line, const std::string& column)
{
    std::size_t used = 0;
    double value = 0;
    try
    {
        value = std::stod(word, &used);
    }
    catch (const std::exception&)
    {
        used = 0;
    }
    if (used != word.size() || !std::isfinite(value))
    {
        refuse(source, line, "column '" + column + "': '" + word + "' is not a finite number");
    }
    return value;
}

// A count: a whole number in [minimum, 1e15] (beyond any tester, and exact in a double)
long count(double value, long minimum, const std::string& source, int line, const std::string& column)
{
    if (value != std::floor(value) || value < double(minimum) || value > 1e15)
    {
        std::ostringstream msg;
        msg << "column '" << column << "': " << value << " must be a whole number >= " << minimum
            << " (and at most 1e15)";
        refuse(source, line, msg.str());
    }
    return long(value);
}

bool isNumber(const std::string& word)
{
    std::size_t used = 0;
    try { std::stod(word, &used); } catch (const std::exception&) { return false; }
    return used == word.size();
}

} // namespace

std::vector<ImpactTest> readImpactTests(std::istream& stream, const std::string& source)
{
    std::vector<std::string> header;
    std::vector<ImpactTest> tests;
    std::string text;
    int line = 0;
    auto at = [&](const std::string& name)
    {
        return int(std::find(header.begin(), header.end(), name) - header.begin());
    };
    while (std::getline(stream, text))
    {
        ++line;
        const std::vector<std::string> row = words(text);
        if (row.empty()) continue;
        if (header.empty())
        {
            if (std::all_of(row.begin(), row.end(), isNumber))
            {
                refuse(source, line, "numbers before a header line naming the columns ("
                       + joined(impactTestColumns()) + ")");
            }
            for (const std::string& name : row)
            {
                const auto& valid = impactTestColumns();
                if (std::find(valid.begin(), valid.end(), name) == valid.end())
                {
                    refuse(source, line, "unknown column '" + name + "'; valid columns: " + joined(valid));
                }
                if (std::find(header.begin(), header.end(), name) != header.end())
                {
                    refuse(source, line, "column '" + name + "' given twice");
                }
                header.push_back(name);
            }
            for (const char* name : {"size", "impacts", "tested", "broken"})
            {
                if (at(name) == int(header.size()))
                {
                    refuse(source, line, std::string("no column '") + name + "' (the columns: size, "
                           "velocity or energy, impacts, tested, broken)");
                }
            }
            const bool hasVelocity = at("velocity") < int(header.size());
            const bool hasEnergy = at("energy") < int(header.size());
            if (hasVelocity == hasEnergy)
            {
                refuse(source, line, hasVelocity
                    ? "both 'velocity' and 'energy' given: one of them (W = v^2/2)"
                    : "neither 'velocity' [m/s] nor 'energy' [J/kg] given");
            }
            continue;
        }
        if (row.size() != header.size())
        {
            refuse(source, line, std::to_string(row.size()) + " values for "
                   + std::to_string(header.size()) + " columns (" + joined(header) + ")");
        }
        auto value = [&](const std::string& name)
        {
            return number(row[std::size_t(at(name))], source, line, name);
        };
        ImpactTest t;
        t.line = line;
        t.size = value("size");
        if (!(t.size > 0)) refuse(source, line, "column 'size': " + row[std::size_t(at("size"))] + " must be > 0 [m]");
        if (at("velocity") < int(header.size()))
        {
            const double v = value("velocity");
            if (v < 0) refuse(source, line, "column 'velocity': " + row[std::size_t(at("velocity"))] + " must be >= 0 [m/s]");
            t.energy = 0.5*v*v;
        }
        else
        {
            t.energy = value("energy");
            if (t.energy < 0) refuse(source, line, "column 'energy': " + row[std::size_t(at("energy"))] + " must be >= 0 [J/kg]");
        }
        const long impacts = count(value("impacts"), 1, source, line, "impacts");
        if (impacts > 1000000) refuse(source, line, "column 'impacts': " + std::to_string(impacts) + " impacts per particle: at most 1e6");
        t.impacts = int(impacts);
        t.tested = count(value("tested"), 1, source, line, "tested");
        t.broken = count(value("broken"), 0, source, line, "broken");
        if (t.broken > t.tested)
        {
            refuse(source, line, "column 'broken': " + std::to_string(t.broken) + " particles broken of "
                   + std::to_string(t.tested) + " tested");
        }
        tests.push_back(t);
    }
    if (header.empty()) refuse(source, std::max(line, 1), "no header line naming the columns (" + joined(impactTestColumns()) + ")");
    if (tests.empty()) refuse(source, line, "no tests after the header");
    return tests;
}

std::vector<ImpactTest> readImpactTests(const std::string& path)
{
    std::ifstream in(path);
    if (!in) throw std::invalid_argument("cannot open impact tests '" + path + "'");
    return readImpactTests(in, path);
}

} // namespace sdf::fit::breakage

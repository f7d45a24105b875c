#include "CellConfig.hpp"
#include "CellSettings.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace sdf::dem
{

namespace
{

std::string trim(const std::string& s)
{
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

void addPair
(
    CellConfig& config,
    const std::string& line,
    const std::string& where,
    const std::set<std::string>& valid
)
{
    const auto eq = line.find('=');
    if (eq == std::string::npos)
    {
        throw std::invalid_argument(where + ": expected key = value, got '" + line + "'");
    }
    const std::string key = trim(line.substr(0, eq));
    if (!valid.count(key))
    {
        std::string names;
        for (const auto& k : valid) names += " " + k;
        throw std::invalid_argument(where + ": unknown key '" + key + "'; valid keys:" + names);
    }
    config[key] = trim(line.substr(eq + 1));
}

//- "pairs = fine/coarse:restitution=0.7:friction=0.4 coarse/coarse:normalStiffness=3000"
std::vector<PairContactSettings> pairsFrom(const std::string& text)
{
    std::vector<PairContactSettings> pairs;
    std::istringstream in(text);
    std::string token;
    const std::string form =
        "expected first/second:key=value[:key=value ...] with keys restitution, friction,"
        " normalStiffness, rollingFriction";
    while (in >> token)
    {
        std::istringstream parts(token);
        std::string names, item;
        std::getline(parts, names, ':');
        PairContactSettings p;
        const auto slash = names.find('/');
        if (slash == std::string::npos || slash == 0 || slash + 1 == names.size())
        {
            throw std::invalid_argument("entry 'pairs': '" + token + "': " + form);
        }
        p.first = names.substr(0, slash);
        p.second = names.substr(slash + 1);
        bool any = false;
        while (std::getline(parts, item, ':'))
        {
            const auto eq = item.find('=');
            const std::string key = item.substr(0, eq);
            double value = 0;
            try
            {
                std::size_t used = 0;
                value = std::stod(item.substr(eq == std::string::npos ? item.size() : eq + 1), &used);
                if (eq == std::string::npos || used != item.size() - eq - 1) throw std::invalid_argument("");
            }
            catch (const std::exception&)
            {
                throw std::invalid_argument("entry 'pairs': '" + item + "' in '" + token + "': " + form);
            }
            if (key == "restitution") p.restitution = value;
            else if (key == "friction") p.friction = value;
            else if (key == "normalStiffness") p.normalStiffness = value;
            else if (key == "rollingFriction") p.rollingFriction = value;
            else
            {
                throw std::invalid_argument
                (
                    "entry 'pairs': unknown key '" + key + "' in '" + token + "'; valid:"
                    " restitution friction normalStiffness"
                );
            }
            any = true;
        }
        if (!any) throw std::invalid_argument("entry 'pairs': '" + token + "' sets nothing; " + form);
        pairs.push_back(p);
    }
    return pairs;
}

} // namespace

std::set<std::string> cellConfigKeys()
{
    std::set<std::string> keys =
        {"species", "volumeFractions", "mode", "model", "pairs", "progressEvery", "label"};
    for (const CellSetting& s : cellSettings()) keys.insert(s.name);
    return keys;
}

CellConfig readCellConfig
(
    const std::string& path,
    int argc,
    char** argv,
    int first,
    const std::set<std::string>& validKeys
)
{
    CellConfig config;
    std::ifstream in(path);
    if (!in)
    {
        throw std::runtime_error("cannot read configuration file '" + path + "'");
    }
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line = line.substr(0, hash);
        if (trim(line).empty()) continue;
        addPair(config, line, path + ":" + std::to_string(lineNo), validKeys);
    }
    for (int a = first; a < argc; ++a)
    {
        addPair(config, argv[a], "argument " + std::to_string(a), validKeys);
    }
    return config;
}

double configNumber(const CellConfig& c, const std::string& key, double fallback)
{
    const auto it = c.find(key);
    if (it == c.end()) return fallback;
    try
    {
        std::size_t used = 0;
        const double v = std::stod(it->second, &used);
        if (trim(it->second.substr(used)).size()) throw std::invalid_argument("");
        return v;
    }
    catch (const std::exception&)
    {
        throw std::invalid_argument("entry '" + key + "': not a number: '" + it->second + "'");
    }
}

std::string configText(const CellConfig& c, const std::string& key, const std::string& fallback)
{
    const auto it = c.find(key);
    return it == c.end() ? fallback : it->second;
}

void refuseKeys
(
    const CellConfig& config,
    const std::vector<std::string>& keys,
    const std::string& cell,
    const std::string& reason
)
{
    for (const std::string& key : keys)
    {
        if (config.count(key))
        {
            throw std::invalid_argument("entry '" + key + "' is not used by " + cell + ": " + reason);
        }
    }
}

void requireCoarseLast(const CellRunSettings& settings, bool equalAllowed)
{
    const Species& coarse = settings.species.back();
    for (std::size_t s = 0; s + 1 < settings.species.size(); ++s)
    {
        const double d = settings.species[s].diameter;
        if (equalAllowed ? d > coarse.diameter : !(d < coarse.diameter))
        {
            throw std::invalid_argument
            (
                "entry 'species': the last species is taken for the coarse one and must be"
                " the largest ('" + settings.species[s].name + "' is "
              + (equalAllowed ? "larger than '" : "not smaller than '") + coarse.name + "')"
            );
        }
    }
}

CellRunSettings cellRunSettingsFrom(const CellConfig& c)
{
    CellRunSettings s;
    if (!c.count("species")) throw std::invalid_argument("entry 'species' missing");
    std::istringstream sp(c.at("species"));
    std::string token;
    while (sp >> token)
    {
        std::istringstream parts(token);
        std::string name, d, rho;
        if (!std::getline(parts, name, ':') || !std::getline(parts, d, ':') || !std::getline(parts, rho))
        {
            throw std::invalid_argument("entry 'species': expected name:diameter:density, got '" + token + "'");
        }
        double diameter = 0, density = 0;
        try
        {
            std::size_t usedD = 0, usedRho = 0;
            diameter = std::stod(d, &usedD);
            density = std::stod(rho, &usedRho);
            if (usedD != d.size() || usedRho != rho.size()) throw std::invalid_argument("");
        }
        catch (const std::exception&)
        {
            throw std::invalid_argument
            (
                "entry 'species': '" + token + "': diameter and density must be numbers"
                " (name:diameter:density)"
            );
        }
        s.species.push_back({name, diameter, density});
    }
    if (c.count("volumeFractions"))
    {
        std::istringstream vf(c.at("volumeFractions"));
        double v;
        while (vf >> v) s.volumeFractions.push_back(v);
    }
    else
    {
        s.volumeFractions.assign(s.species.size(), 1.0/s.species.size());
    }
    // every scalar setting by its one description; the defaults are CellRunSettings'
    for (const auto& [key, value] : c)
    {
        setCellSetting(s, key, value);
    }
    SimulationSettings& sim = s.simulation;
    sim.mode = cellModeFromName(configText(c, "mode", "thermostatted"));
    sim.contact.model = contactModelFromName(configText(c, "model", "linearSpringDashpot"));
    if (c.count("pairs")) sim.contact.pairs = pairsFrom(c.at("pairs"));
    s.progressEvery = long(configNumber(c, "progressEvery", 0));
    s.label = configText(c, "label", "periodicDEM");
    return s;
}

} // namespace sdf::dem

#include "CellSettings.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sdf::dem
{

namespace
{

using S = CellSetting::Scope;
using R = CellRunSettings;

} // namespace

const std::vector<CellSetting>& cellSettings()
{
    // The store's key lists, after the species: the condition settings with a label, the
    // contact model and its constants, then the run controls with a label, in this order
    // (the keys of existing stores depend on it).
    static const std::vector<CellSetting> table
    {
        {"particles", S::condition, true, "particles", false,
            [](const R& s) { return double(s.particles); },
            [](R& s, double v) { s.particles = int(v); }},
        {"solidsFraction", S::condition, false, nullptr, false,
            [](const R& s) { return s.solidsFraction; },
            [](R& s, double v) { s.solidsFraction = v; }},
        {"temperature", S::condition, false, nullptr, false,
            [](const R& s) { return s.simulation.targetTemperature; },
            [](R& s, double v) { s.simulation.targetTemperature = v; }},
        {"shearRate", S::condition, false, nullptr, false,
            [](const R& s) { return s.simulation.shearRate; },
            [](R& s, double v) { s.simulation.shearRate = v; }},
        {"targetPressure", S::condition, false, nullptr, false,
            [](const R& s) { return s.simulation.targetPressure; },
            [](R& s, double v) { s.simulation.targetPressure = v; }},
        {"seed", S::condition, true, nullptr, false,
            [](const R& s) { return double(s.seed); },
            [](R& s, double v) { s.seed = std::uint64_t(v); }},

        {"restitution", S::contact, false, "e", false,
            [](const R& s) { return s.simulation.contact.restitution; },
            [](R& s, double v) { s.simulation.contact.restitution = v; }},
        {"friction", S::contact, false, "mu", false,
            [](const R& s) { return s.simulation.contact.friction; },
            [](R& s, double v) { s.simulation.contact.friction = v; }},
        {"normalStiffness", S::contact, false, "kn", false,
            [](const R& s) { return s.simulation.contact.normalStiffness; },
            [](R& s, double v) { s.simulation.contact.normalStiffness = v; }},
        {"tangentialStiffnessRatio", S::contact, false, "kt/kn", false,
            [](const R& s) { return s.simulation.contact.tangentialStiffnessRatio; },
            [](R& s, double v) { s.simulation.contact.tangentialStiffnessRatio = v; }},
        {"tangentialDampingRatio", S::contact, false, "gt/gn", false,
            [](const R& s) { return s.simulation.contact.tangentialDampingRatio; },
            [](R& s, double v) { s.simulation.contact.tangentialDampingRatio = v; }},
        {"youngsModulus", S::contact, false, "E", false,
            [](const R& s) { return s.simulation.contact.youngsModulus; },
            [](R& s, double v) { s.simulation.contact.youngsModulus = v; }},
        {"poissonRatio", S::contact, false, "nu", false,
            [](const R& s) { return s.simulation.contact.poissonRatio; },
            [](R& s, double v) { s.simulation.contact.poissonRatio = v; }},

        // rolling resistance: not labelled (the store's key names it only when on, so
        // the keys of stores without it stand: Store.cpp)
        {"rollingFriction", S::contact, false, nullptr, false,
            [](const R& s) { return s.simulation.contact.rollingFriction; },
            [](R& s, double v) { s.simulation.contact.rollingFriction = v; }},
        {"rollingStiffness", S::contact, false, nullptr, false,
            [](const R& s) { return s.simulation.contact.rollingStiffness; },
            [](R& s, double v) { s.simulation.contact.rollingStiffness = v; }},
        {"rollingDamping", S::contact, false, nullptr, false,
            [](const R& s) { return s.simulation.contact.rollingDamping; },
            [](R& s, double v) { s.simulation.contact.rollingDamping = v; }},

        {"timeStep", S::runControl, false, "timeStep", false,
            [](const R& s) { return s.simulation.timeStep; },
            [](R& s, double v) { s.simulation.timeStep = v; }},
        {"thermostatTime", S::runControl, false, "thermostatTime", false,
            [](const R& s) { return s.simulation.thermostatTime; },
            [](R& s, double v) { s.simulation.thermostatTime = v; }},
        {"barostatTime", S::runControl, false, nullptr, false,
            [](const R& s) { return s.simulation.barostatTime; },
            [](R& s, double v) { s.simulation.barostatTime = v; }},
        {"equilibrationTime", S::runControl, false, "equilibrationTime", false,
            [](const R& s) { return s.equilibrationTime; },
            [](R& s, double v) { s.equilibrationTime = v; }},
        {"maxEquilibrationTime", S::runControl, false, "maxEquilibrationTime", false,
            [](const R& s) { return s.maxEquilibrationTime; },
            [](R& s, double v) { s.maxEquilibrationTime = v; }},
        {"samplingTime", S::runControl, false, "samplingTime", true,
            [](const R& s) { return s.samplingTime; },
            [](R& s, double v) { s.samplingTime = v; }},
        {"sampleEvery", S::runControl, true, "sampleEvery", false,
            [](const R& s) { return double(s.sampleEvery); },
            [](R& s, double v) { s.sampleEvery = int(v); }},
        {"blocks", S::runControl, true, "blocks", false,
            [](const R& s) { return double(s.blocks); },
            [](R& s, double v) { s.blocks = int(v); }},
        {"threads", S::runControl, true, nullptr, false,
            [](const R& s) { return double(s.simulation.threads); },
            [](R& s, double v) { s.simulation.threads = int(v); }},
        {"skin", S::runControl, false, nullptr, false,
            [](const R& s) { return s.simulation.skin; },
            [](R& s, double v) { s.simulation.skin = v; }},
        {"maxOverlapFraction", S::runControl, false, nullptr, false,
            [](const R& s) { return s.simulation.maxOverlapFraction; },
            [](R& s, double v) { s.simulation.maxOverlapFraction = v; }},
    };
    return table;
}


const CellSetting* findCellSetting(const std::string& name)
{
    for (const CellSetting& s : cellSettings())
    {
        if (name == s.name) return &s;
    }
    return nullptr;
}


std::vector<std::string> cellSettingNames(CellSetting::Scope scope)
{
    std::vector<std::string> names;
    for (const CellSetting& s : cellSettings())
    {
        if (s.scope == scope) names.push_back(s.name);
    }
    return names;
}


bool setCellSetting(CellRunSettings& settings, const std::string& name, const std::string& text)
{
    const CellSetting* s = findCellSetting(name);
    if (!s) return false;
    double v = 0;
    try
    {
        std::size_t used = 0;
        v = std::stod(text, &used);
        if (text.find_first_not_of(" \t\r", used) != std::string::npos) throw std::invalid_argument("");
    }
    catch (const std::exception&)
    {
        throw std::invalid_argument("entry '" + name + "': not a number: '" + text + "'");
    }
    checkCellSettingValue(*s, v);
    s->set(settings, v);
    return true;
}


void checkCellSettingValue(const CellSetting& setting, double v)
{
    const std::string entry = "entry '" + std::string(setting.name) + "': ";
    if (!std::isfinite(v))
    {
        throw std::invalid_argument(entry + "not a finite number");
    }
    if (!setting.integer) return;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    if (v != std::floor(v))
    {
        throw std::invalid_argument(entry + "not a whole number: " + buf);
    }
    const double limit = std::string(setting.name) == "seed" ? 9007199254740992.0 : 2147483648.0;
    if (v < 0 || v >= limit)
    {
        throw std::invalid_argument
        (
            entry + buf + " outside [0, " + (limit > 3e9 ? "2^53" : "2^31") + ")"
        );
    }
}


std::string cellSettingText(const CellSetting& setting, const CellRunSettings& settings)
{
    const double v = setting.get(settings);
    char buf[64];
    if (setting.integer)
    {
        std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
    }
    else
    {
        std::snprintf(buf, sizeof buf, "%.10g", v);
    }
    return buf;
}

} // namespace sdf::dem

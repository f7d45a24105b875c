// periodicDEM-cli: runs one periodic DEM cell from a key = value file and prints a summary
// (and writes HDF5 when output = file.h5 is given).
//
//   periodicDEM-cli cell.cfg [key=value ...]      command-line pairs override the file
//
// Keys (SI units; '#' starts a comment): the scalar settings of the cell, by the names of
// transport/CellSettings.cpp (particles, solidsFraction, temperature, shearRate, seed; the
// contact constants restitution, friction, normalStiffness, tangentialStiffnessRatio,
// tangentialDampingRatio, youngsModulus, poissonRatio; the run controls timeStep (0: half
// the recommended maximum), thermostatTime, equilibrationTime, maxEquilibrationTime,
// samplingTime [s], sampleEvery [steps], blocks, threads, skin [m], maxOverlapFraction),
// and:
//   species          name:diameter:density [name:diameter:density ...]
//   volumeFractions  solids volume fraction of each species (default: equal)
//   mode             nve | thermostatted (default) | leesEdwards | stochastic
//   model            linearSpringDashpot | hertzMindlin
//   pairs            per species pair, first/second:key=value[:key=value ...] with keys
//                    restitution, friction, normalStiffness (unset: the single values)
//   progressEvery [steps], output (HDF5 file), label
//   lammpsData (write the initial state as a LAMMPS data file), throughputOnly (1: no
//   measurements, only T; for speed comparisons), threadScalingRounds (with throughputOnly:
//   the equilibrated state run alternately on 1 and on `threads` threads, this many
//   rounds; prints the speed-ups), checkpointFile, checkpointEvery [steps],
//   resume (1: continue the sampling from checkpointFile, same settings)
#include "CellRun.hpp"
#include "CellSettings.hpp"

#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

using namespace sdf::dem;

namespace
{

std::string trim(const std::string& s)
{
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
}

//- The keys that are not scalar settings of the cell (those come from CellSettings.hpp)
const std::set<std::string> otherKeys =
{
    "species", "volumeFractions", "mode", "model", "pairs", "progressEvery", "output",
    "label", "lammpsData", "throughputOnly", "threadScalingRounds", "checkpointFile",
    "checkpointEvery", "resume"
};

std::set<std::string> validKeys()
{
    std::set<std::string> keys = otherKeys;
    for (const CellSetting& s : cellSettings()) keys.insert(s.name);
    return keys;
}

void addPair(std::map<std::string, std::string>& config, const std::string& line, const std::string& where)
{
    const auto eq = line.find('=');
    if (eq == std::string::npos)
    {
        throw std::invalid_argument(where + ": expected key = value, got '" + line + "'");
    }
    const std::string key = trim(line.substr(0, eq));
    const std::set<std::string> valid = validKeys();
    if (!valid.count(key))
    {
        std::string names;
        for (const auto& k : valid) names += " " + k;
        throw std::invalid_argument(where + ": unknown key '" + key + "'; valid keys:" + names);
    }
    config[key] = trim(line.substr(eq + 1));
}

double number(const std::map<std::string, std::string>& c, const std::string& key, double fallback)
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

std::string text(const std::map<std::string, std::string>& c, const std::string& key, const std::string& fallback)
{
    const auto it = c.find(key);
    return it == c.end() ? fallback : it->second;
}

//- "pairs = fine/coarse:restitution=0.7:friction=0.4 coarse/coarse:normalStiffness=3000"
std::vector<PairContactSettings> pairsFrom(const std::string& text)
{
    std::vector<PairContactSettings> pairs;
    std::istringstream in(text);
    std::string token;
    const std::string form =
        "expected first/second:key=value[:key=value ...] with keys restitution, friction,"
        " normalStiffness";
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

CellRunSettings settingsFrom(const std::map<std::string, std::string>& c)
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
        s.species.push_back({name, std::stod(d), std::stod(rho)});
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
    sim.mode = cellModeFromName(text(c, "mode", "thermostatted"));
    sim.contact.model = contactModelFromName(text(c, "model", "linearSpringDashpot"));
    if (c.count("pairs")) sim.contact.pairs = pairsFrom(c.at("pairs"));
    s.progressEvery = long(number(c, "progressEvery", 0));
    s.label = text(c, "label", "periodicDEM");
    s.lammpsDataFile = text(c, "lammpsData", "");
    s.throughputOnly = number(c, "throughputOnly", 0) != 0;
    s.threadScalingRounds = int(number(c, "threadScalingRounds", 0));
    s.checkpointFile = text(c, "checkpointFile", "");
    s.checkpointEvery = long(number(c, "checkpointEvery", 0));
    s.resume = number(c, "resume", 0) != 0;
    return s;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: periodicDEM-cli cell.cfg [key=value ...]\n";
        return 2;
    }
    try
    {
        std::map<std::string, std::string> config;
        const std::string path = argv[1];
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
            addPair(config, line, path + ":" + std::to_string(lineNo));
        }
        for (int a = 2; a < argc; ++a) addPair(config, argv[a], "argument " + std::to_string(a));

        const CellRunSettings settings = settingsFrom(config);
        const CellRunResult result = runCell(settings);
        std::cout << summary(result);
        const std::string output = text(config, "output", "");
        if (!output.empty())
        {
            writeCellRun(result, output);
            std::cout << "written " << output << "\n";
        }
    }
    catch (const std::exception& err)
    {
        std::cerr << "periodicDEM-cli: error: " << err.what() << "\n";
        return 1;
    }
    return 0;
}

#include "store/Store.hpp"

#include "io/Hdf5File.hpp"
#include "CellSettings.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace sdf::store
{

namespace
{

//- What current adds at its end when stored is its beginning; empty otherwise
std::string addedAtTheEnd(const std::string& stored, const std::string& current)
{
    if
    (
        current.size() > stored.size()
     && current.compare(0, stored.size(), stored) == 0
    )
    {
        return current.substr(stored.size());
    }
    return std::string();
}

//- %.6g: the precision of the condition names
std::string fmt6(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.6g", v);
    return buf;
}

//- %.10g: the precision of the settings fingerprint
std::string fmt10(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.10g", v);
    return buf;
}

std::optional<double> optionalDouble(const io::Group& g, const std::string& name)
{
    if (!g.hasAttribute(name))
    {
        return std::nullopt;
    }
    return g.readDouble(name);
}

RheologyRecord readRheology(const io::Group& g)
{
    RheologyRecord h;
    h.targetPressure = g.readDouble("targetPressure");
    h.meanDiameter = g.readDouble("meanDiameter");
    h.solidsDensity = g.readDouble("solidsDensity");
    h.inertialNumber = g.readDouble("inertialNumber");
    h.inertialNumberError = g.readDouble("inertialNumberError");
    h.stressRatio = g.readDouble("stressRatio");
    h.stressRatioError = g.readDouble("stressRatioError");
    h.solidsFraction = g.readDouble("solidsFraction");
    h.solidsFractionError = g.readDouble("solidsFractionError");
    h.pressure = g.readDouble("pressure");
    h.pressureError = g.readDouble("pressureError");
    h.coordinationNumber = g.readDouble("coordinationNumber");
    h.regime = g.readString("regime");
    return h;
}


//- The attributes of the group `segregation`: one list for the writer and the reader
const std::vector<std::pair<const char*, double SegregationRecord::*>>& segregationAttributes()
{
    static const std::vector<std::pair<const char*, double SegregationRecord::*>> attributes
    {
        {"normalStress", &SegregationRecord::normalStress},
        {"wallSpeed", &SegregationRecord::wallSpeed},
        {"fineDiameter", &SegregationRecord::fineDiameter},
        {"sizeRatio", &SegregationRecord::sizeRatio},
        {"meanDiameter", &SegregationRecord::meanDiameter},
        {"solidsFraction", &SegregationRecord::solidsFraction},
        {"pressureNumber", &SegregationRecord::pressureNumber},
        {"inertialNumber", &SegregationRecord::inertialNumber},
        {"percolationLengthEarly", &SegregationRecord::early},
        {"percolationLengthEarlyError", &SegregationRecord::earlyError},
        {"earlyCoarseShare", &SegregationRecord::earlyCoarseShare},
        {"earlyShearRate", &SegregationRecord::earlyShearRate},
        {"percolationLengthBalance", &SegregationRecord::balance},
        {"percolationLengthBalanceError", &SegregationRecord::balanceError},
        {"coarseShare", &SegregationRecord::coarseShare},
        {"shearRate", &SegregationRecord::shearRate},
        {"shearRateError", &SegregationRecord::shearRateError},
        {"diffusivity", &SegregationRecord::diffusivity},
        {"diffusivityError", &SegregationRecord::diffusivityError},
        {"shearRateDiffusivity", &SegregationRecord::shearRateDiffusivity},
        {"shearRateDiffusivityError", &SegregationRecord::shearRateDiffusivityError},
        {"diffusiveShare", &SegregationRecord::diffusiveShare},
        {"topWallLoad", &SegregationRecord::topWallLoad}
    };
    return attributes;
}


SegregationRecord readSegregation(const io::Group& g)
{
    SegregationRecord r;
    for (const auto& [name, member] : segregationAttributes())
    {
        r.*member = g.readDouble(name);
    }
    return r;
}


SpeciesRecord readSpecies(const io::Group& g)
{
    SpeciesRecord s;
    if (g.hasAttribute("count"))
    {
        s.count = g.readInt64("count");
    }
    s.D = g.readDouble("D");
    s.DError = optionalDouble(g, "DError");
    s.DMsd = optionalDouble(g, "DMsd");
    s.DMsdError = optionalDouble(g, "DMsdError");
    if (g.hasGroup("diffusiveRegime"))
    {
        const io::Group r = g.openGroup("diffusiveRegime");
        s.DConverged = r.readInt64("converged") != 0;
        s.DVerdict = r.readString("verdict");
        s.DSlopeChange = r.readDouble("slopeChange");
        if (r.hasAttribute("drift")) s.DDrift = r.readDouble("drift");
        s.DFitStart = r.readDouble("fitStart");
        s.DCorrelationTime = r.readDouble("correlationTime");
        s.DWindowPastDecay = r.readInt64("windowPastDecay") != 0;
    }
    s.eta = optionalDouble(g, "eta");
    s.etaError = optionalDouble(g, "etaError");
    s.etaWithCrossTerms = optionalDouble(g, "etaWithCrossTerms");
    s.etaWithCrossTermsError = optionalDouble(g, "etaWithCrossTermsError");
    return s;
}

//- /conditions/<name>/collisions: the cell's collision statistics, per unordered
//  species pair (a <= b in species order), counts and histograms as integers so that
//  they read back exactly.
void writeCollisions(const io::Group& g, const dem::CellRunResult& r)
{
    const dem::CollisionStatistics& col = r.collisions;
    const int n = int(r.settings.species.size());
    if (col.binEdges.empty() || col.nSpecies != n)
    {
        return;   // not measured
    }
    const io::Group cg = g.createGroup("collisions");
    cg.setAttribute("elapsedTime", col.elapsedTime);
    cg.setAttribute("impactEnergy", "0.5 m* v_n^2 at the first step of a contact [J]");
    cg.writeVector("binEdges", col.binEdges);
    for (int a = 0; a < n; ++a)
    {
        for (int b = a; b < n; ++b)
        {
            const int k = dem::speciesPairIndex(a, b, n);
            const io::Group pg = cg.createGroup
            (
                r.settings.species[a].name + "/" + r.settings.species[b].name
            );
            pg.setAttribute("count", std::int64_t(col.counts[k]));
            pg.setAttribute("energySum", col.energySum[k]);
            pg.writeInt64Vector
            (
                "histogram",
                std::vector<std::int64_t>(col.histogram[k].begin(), col.histogram[k].end())
            );
        }
    }
}

CollisionRecord readCollisions(const io::Group& cg)
{
    CollisionRecord c;
    c.elapsedTime = cg.readDouble("elapsedTime");
    c.binEdges = cg.readVector("binEdges");
    for (const std::string& first : cg.childNames())
    {
        if (!cg.hasGroup(first))
        {
            continue;   // binEdges
        }
        const io::Group fg = cg.openGroup(first);
        for (const std::string& second : fg.childNames())
        {
            const io::Group pg = fg.openGroup(second);
            PairCollisionRecord p;
            p.first = first;
            p.second = second;
            p.count = pg.readInt64("count");
            p.energySum = pg.readDouble("energySum");
            p.histogram = pg.readInt64Vector("histogram");
            if (p.histogram.size() != c.binEdges.size() + 1)
            {
                throw std::runtime_error
                (
                    pg.path() + "/histogram has " + std::to_string(p.histogram.size())
                  + " slots, the " + std::to_string(c.binEdges.size())
                  + " bin edges need " + std::to_string(c.binEdges.size() + 1)
                );
            }
            c.pairs.push_back(std::move(p));
        }
    }
    return c;
}

} // namespace


const PairCollisionRecord* CollisionRecord::pair
(
    const std::string& a,
    const std::string& b
) const
{
    for (const PairCollisionRecord& p : pairs)
    {
        if ((p.first == a && p.second == b) || (p.first == b && p.second == a))
        {
            return &p;
        }
    }
    return nullptr;
}


double CollisionRecord::frequencyPerParticle
(
    const std::string& of,
    const std::string& with,
    std::int64_t countOf
) const
{
    const PairCollisionRecord* p = pair(of, with);
    if (!p)
    {
        throw std::invalid_argument
        (
            "no collisions stored for the species pair " + of + "/" + with
        );
    }
    if (countOf <= 0)
    {
        throw std::invalid_argument
        (
            "collision frequency of " + of + ": particle count "
          + std::to_string(countOf) + " must be > 0"
        );
    }
    if (elapsedTime <= 0)
    {
        return 0;
    }
    const double involved = (of == with ? 2.0 : 1.0)*double(p->count);
    return involved/(elapsedTime*double(countOf));
}


StoreError::StoreError(const std::string& file, const std::string& message)
:
    std::runtime_error("calibration store " + file + ": " + message),
    file_(file),
    message_(message)
{}


SettingsMismatch::SettingsMismatch
(
    const std::string& file,
    const std::string& condition,
    const std::string& storedKey,
    const std::string& currentKey
)
:
    StoreError
    (
        file,
        "condition " + condition + " was run with other DEM settings:\n    stored:  "
      + storedKey + "\n    current: " + currentKey
      + (
            addedAtTheEnd(storedKey, currentKey).empty()
          ? std::string()
          : "\n    (the same settings, written before the measurement changed: the current"
            " key adds \"" + addedAtTheEnd(storedKey, currentKey) + "\"; move the store"
            " away to rerun its conditions)"
        )
    ),
    storedKey_(storedKey),
    currentKey_(currentKey)
{}


std::string SettingsMismatch::addedSinceStored() const
{
    return addedAtTheEnd(storedKey_, currentKey_);
}


bool isStored
(
    const std::string& path,
    const std::map<std::string, std::string>& stored,
    const std::string& name,
    const std::string& key
)
{
    const auto it = stored.find(name);
    if (it == stored.end())
    {
        return false;
    }
    if (it->second != key)
    {
        throw SettingsMismatch(path, name, it->second, key);
    }
    return true;
}


void checkIsStore(const io::Group& root)
{
    if
    (
        !root.hasAttribute("content")
     || root.attributeType("content") != io::AttributeType::string
     || root.readString("content") != contentName
    )
    {
        throw std::runtime_error
        (
            "it is a segregationDegradationFoam HDF5 file, but not a"
            " calibration store (root attribute content = \""
          + std::string(contentName) + "\" missing)"
        );
    }
}


namespace
{

//- phi<phi>_x<x>_<drive><value>_seed<seed>
std::string pointName(double phi, double x, const char* drive, double value, std::int64_t seed)
{
    return
        "phi" + fmt6(phi) + "_x" + fmt6(x) + "_" + drive + fmt6(value)
      + "_seed" + std::to_string(seed);
}

} // namespace


std::string conditionName(double phi, double x, double T, std::int64_t seed)
{
    return pointName(phi, x, "T", T, seed);
}


std::string shearedConditionName(double phi, double x, double gammaDot, std::int64_t seed)
{
    return pointName(phi, x, "gammaDot", gammaDot, seed);
}


std::string rheologyConditionName
(
    double inertialNumber,
    double pressure,
    double x,
    std::int64_t seed
)
{
    char name[160];
    std::snprintf
    (
        name, sizeof name, "rheology_I%.6g_p%.6g_x%.6g_seed%lld", inertialNumber, pressure,
        x, static_cast<long long>(seed)
    );
    return name;
}


std::string segregationConditionName(double normalStress, double x, std::int64_t seed)
{
    char name[160];
    std::snprintf
    (
        name, sizeof name, "segregation_sigma%.6g_x%.6g_seed%lld", normalStress, x,
        static_cast<long long>(seed)
    );
    return name;
}


std::string sizedConditionName(const std::string& name, std::int64_t particles)
{
    return name + "_N" + std::to_string(particles);
}


std::string settingsKey(const dem::CellRunSettings& b, const std::string& contactModel)
{
    const dem::SimulationSettings& sim = b.simulation;
    const dem::ContactSettings& c = sim.contact;
    std::ostringstream key;
    key << "species";
    for (const auto& sp : b.species)
    {
        key << " " << sp.name << ":" << fmt10(sp.diameter) << ":" << fmt10(sp.density);
    }
    // the scalar settings from their one description (CellSettings.hpp): the condition's
    // labelled ones, the contact law's constants after its name, then the run controls
    using Scope = dem::CellSetting::Scope;
    const auto labelled = [&](Scope scope, const char* separator)
    {
        for (const dem::CellSetting& setting : dem::cellSettings())
        {
            if (setting.scope != scope || !setting.fingerprint) continue;
            key << separator << setting.fingerprint << " " << dem::cellSettingText(setting, b);
        }
    };
    labelled(Scope::condition, "; ");
    key << "; contact " << contactModel;
    labelled(Scope::contact, " ");
    labelled(Scope::runControl, "; ");
    // per-pair contact constants: named only when set, so the keys of older stores
    // stand; canonical (names of a pair in order, pairs in order), so the same physics
    // given in another order reuses its conditions
    std::vector<std::string> pairs;
    for (dem::PairContactSettings p : c.pairs)
    {
        if (p.second < p.first) std::swap(p.first, p.second);
        pairs.push_back(dem::pairContactText(p));
    }
    std::sort(pairs.begin(), pairs.end());
    for (const std::string& p : pairs)
    {
        key << "; pair " << p;
    }
    // the driving: named only when it is not the velocity-rescaling thermostat, so the
    // keys of stores written before the choice existed stay valid
    if (sim.mode != dem::CellMode::thermostatted)
    {
        key << "; mode " << dem::cellModeName(sim.mode);
    }
    // rolling resistance: named only when on (in a pair or for all)
    if (dem::hasRollingResistance(c))
    {
        key << "; rolling mu_r " << fmt10(c.rollingFriction) << " k_r "
            << fmt10(c.rollingStiffness) << " gamma_r " << fmt10(c.rollingDamping);
    }
    // pressure control: named only when on, so the keys of volume-controlled stores stand
    if (sim.targetPressure > 0)
    {
        key << "; pressure " << fmt10(sim.targetPressure) << " barostatTime "
            << fmt10(sim.barostatTime);
    }
    // a sheared cell's eta: its stress products are correlated about the run's mean
    // (before, raw: such stores' eta grew with the window and are not reused)
    if (sim.mode == dem::CellMode::leesEdwards)
    {
        key << "; stress ACF about the mean";
    }
    // Green-Kubo read within the MSD's lags (before, up to a whole block: such
    // stores' D can sit above the MSD's by a slow tail; they are refused, the
    // message naming the tag, so that their conditions are rerun)
    key << "; Green-Kubo within the MSD's lags";
    return key.str();
}


namespace
{

//- Adds the group conditions/<name> to the store at path (created with the root
//  attributes if there is none), write(group) filling it, atomically; any failure a
//  StoreError naming the file and the condition.
void appendConditionGroup
(
    const std::string& path,
    const std::string& fineSpecies,
    const std::string& coarseSpecies,
    const std::string& name,
    const std::function<void(const io::Group&)>& write
)
{
    try
    {
        const bool exists = std::filesystem::is_regular_file(path);
        io::AtomicFile out = exists ? io::AtomicFile::update(path) : io::AtomicFile::create(path);
        const io::Group root = out.root();
        if (exists)
        {
            checkIsStore(root);
        }
        else
        {
            root.setAttribute("content", contentName);
            root.setAttribute("fineSpecies", fineSpecies);
            root.setAttribute("coarseSpecies", coarseSpecies);
        }
        write(root.createGroup("conditions/" + name));
        out.commit();
    }
    catch (const StoreError&)
    {
        throw;
    }
    catch (const std::exception& err)
    {
        throw StoreError(path, "adding condition " + name + " failed: " + err.what());
    }
}

} // namespace


void appendCondition
(
    const std::string& path,
    const std::string& fineSpecies,
    const std::string& coarseSpecies,
    const std::string& key,
    const ConditionInputs& cond,
    const dem::CellRunResult& r
)
{
    appendConditionGroup(path, fineSpecies, coarseSpecies, cond.name, [&](const io::Group& g)
    {
        // inputs
        g.setAttribute("phi", cond.phi);
        g.setAttribute("x", cond.x);
        if (cond.gammaDot)
        {
            g.setAttribute("gammaDot", *cond.gammaDot);
        }
        else
        {
            g.setAttribute("targetT", cond.targetT);
        }
        if (cond.inertialNumber)
        {
            g.setAttribute("targetInertialNumber", *cond.inertialNumber);
        }
        g.setAttribute("seed", cond.seed);
        g.setAttribute("particles", std::int64_t(r.settings.particles));
        g.setAttribute("settingsKey", key);
        // results
        g.setAttribute("T", r.temperature);
        g.setAttribute("TError", r.temperatureError);
        if (cond.gammaDot)
        {
            g.setAttribute("savageJeffreyR", r.savageJeffreyR);
        }
        g.setAttribute("equilibrated", std::int64_t(r.equilibrated ? 1 : 0));
        g.setAttribute("equilibrationTime", r.equilibrationTime);
        g.setAttribute("timeStep", r.timeStep);
        g.setAttribute("boxLength", r.boxLength);
        g.setAttribute("steps", std::int64_t(r.steps));
        for (std::size_t i = 0; i < r.species.size(); ++i)
        {
            const dem::SpeciesTransport& st = r.species[i];
            const io::Group sg = g.createGroup("species/" + st.name);
            sg.setAttribute("role", i == 0 ? "fine" : "coarse");
            sg.setAttribute("d", r.settings.species[i].diameter);
            sg.setAttribute("count", std::int64_t(st.count));
            sg.setAttribute("T", st.temperature);
            sg.setAttribute("D", st.greenKubo.integral.value);
            sg.setAttribute("DError", st.greenKubo.integral.standardError);
            sg.setAttribute("DPlateauFound", std::int64_t(st.greenKubo.plateauFound ? 1 : 0));
            sg.setAttribute("DMsd", st.diffusivityMsd.value);
            sg.setAttribute("DMsdError", st.diffusivityMsd.standardError);
            dem::writeDiffusiveRegime(sg.createGroup("diffusiveRegime"), st.diffusiveRegime);
            if (i < r.kineticSieving.size())
            {
                sg.setAttribute("eta", r.kineticSieving[i].value);
                sg.setAttribute("etaError", r.kineticSieving[i].standardError);
            }
            if (i < r.kineticSievingWithCrossTerms.size())
            {
                sg.setAttribute("etaWithCrossTerms", r.kineticSievingWithCrossTerms[i].value);
                sg.setAttribute("etaWithCrossTermsError", r.kineticSievingWithCrossTerms[i].standardError);
            }
        }
        writeCollisions(g, r);
        if (cond.inertialNumber)
        {
            dem::writeRheology(g, r.rheology);
        }
        // timings: the only attributes that differ between identical runs
        const io::Group t = g.createGroup("timing");
        t.setAttribute("wallSeconds", r.wallSeconds);
        t.setAttribute("cpuSeconds", r.cpuSeconds);
        t.setAttribute("particleStepsPerSecond", r.particleStepsPerSecond);
    });
}


SegregationRecord segregationRecordOf(const dem::GravityShearRunResult& result)
{
    const dem::SegregationMeasurement& m = result.segregation;
    SegregationRecord r;
    r.normalStress = result.settings.walls.normalStress;
    r.wallSpeed = result.settings.walls.wallSpeed;
    r.fineDiameter = m.fineDiameter;
    r.sizeRatio = m.sizeRatio;
    r.meanDiameter = m.meanDiameter;
    r.solidsFraction = m.solidsFraction;
    r.pressureNumber = m.pressureNumber;
    r.inertialNumber = m.inertialNumber;
    r.early = m.early.value;
    r.earlyError = m.early.standardError;
    r.earlyCoarseShare = m.earlyCoarseShare;
    r.earlyShearRate = m.earlyShearRate;
    r.balance = m.balance.value;
    r.balanceError = m.balance.standardError;
    r.coarseShare = m.coarseShare;
    r.shearRate = m.shearRate.value;
    r.shearRateError = m.shearRate.standardError;
    r.diffusivity = m.diffusivity.value;
    r.diffusivityError = m.diffusivity.standardError;
    r.shearRateDiffusivity = m.shearRateDiffusivity.value;
    r.shearRateDiffusivityError = m.shearRateDiffusivity.standardError;
    r.diffusiveShare = m.diffusiveShare;
    r.topWallLoad = m.topWallLoad;
    return r;
}


void appendSegregationCondition
(
    const std::string& path,
    const std::string& fineSpecies,
    const std::string& coarseSpecies,
    const std::string& key,
    const ConditionInputs& cond,
    const dem::GravityShearRunResult& result
)
{
    appendConditionGroup(path, fineSpecies, coarseSpecies, cond.name, [&](const io::Group& g)
    {
        g.setAttribute("phi", cond.phi);
        g.setAttribute("x", cond.x);
        g.setAttribute("normalStress", result.settings.walls.normalStress);
        g.setAttribute("seed", cond.seed);
        g.setAttribute("particles", std::int64_t(result.settings.cell.particles));
        g.setAttribute("settingsKey", key);
        const io::Group s = g.createGroup("segregation");
        const SegregationRecord record = segregationRecordOf(result);
        for (const auto& [name, member] : segregationAttributes())
        {
            s.setAttribute(name, record.*member);
        }
        const io::Group t = g.createGroup("timing");
        t.setAttribute("wallSeconds", result.wallSeconds);
        t.setAttribute("cpuSeconds", result.cpuSeconds);
    });
}


std::map<std::string, std::string> storedSettingsKeys(const std::string& path)
{
    std::map<std::string, std::string> stored;
    if (!std::filesystem::is_regular_file(path))
    {
        return stored;
    }
    try
    {
        const io::File f = io::File::openReadOnly(path);
        const io::Group root = f.root();
        checkIsStore(root);
        if (root.hasGroup("conditions"))
        {
            const io::Group conditions = root.openGroup("conditions");
            for (const std::string& name : conditions.childNames())
            {
                stored[name] = conditions.openGroup(name).readString("settingsKey");
            }
        }
    }
    catch (const std::exception& err)
    {
        throw StoreError(path, err.what());
    }
    return stored;
}


StoreContents readStore(const std::string& path)
{
    StoreContents contents;
    try
    {
        const io::File f = io::File::openReadOnly(path);
        const io::Group root = f.root();
        checkIsStore(root);
        contents.fineSpecies = root.readString("fineSpecies");
        contents.coarseSpecies = root.readString("coarseSpecies");
        if (!root.hasGroup("conditions"))
        {
            return contents;
        }
        const io::Group conditions = root.openGroup("conditions");
        for (const std::string& name : conditions.childNames())
        {
            const io::Group g = conditions.openGroup(name);
            ConditionRecord c;
            c.name = name;
            c.phi = g.readDouble("phi");
            c.x = g.readDouble("x");
            c.particles = g.hasAttribute("particles") ? g.readInt64("particles") : 0;
            if (g.hasGroup("segregation"))
            {
                c.segregation = readSegregation(g.openGroup("segregation"));
                contents.conditions.push_back(c);
                continue;
            }
            if (g.hasAttribute("gammaDot"))
            {
                c.gammaDot = g.readDouble("gammaDot");
                c.savageJeffreyR = optionalDouble(g, "savageJeffreyR");
            }
            else
            {
                c.targetT = g.readDouble("targetT");
            }
            c.T = g.readDouble("T");
            // Written by every calibration; hand-made stores may lack it
            c.particles = g.hasAttribute("particles") ? g.readInt64("particles") : 0;
            c.fine = readSpecies(g.openGroup("species/" + contents.fineSpecies));
            const std::string coarse = "species/" + contents.coarseSpecies;
            if (g.hasGroup(coarse))
            {
                c.coarse = readSpecies(g.openGroup(coarse));
            }
            if (g.hasGroup("collisions"))
            {
                c.collisions = readCollisions(g.openGroup("collisions"));
            }
            if (g.hasGroup("rheology"))
            {
                c.rheology = readRheology(g.openGroup("rheology"));
                c.rheology->targetInertialNumber = g.readDouble("targetInertialNumber");
            }
            contents.conditions.push_back(c);
        }
    }
    catch (const std::exception& err)
    {
        throw StoreError(path, err.what());
    }
    return contents;
}


void writeTextAtomically(const std::string& path, const std::string& text)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream os(tmp);
        os << text;
        if (!os.good())
        {
            throw StoreError(path, "cannot write " + tmp);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        throw StoreError(path, "cannot rename " + tmp + " to " + path);
    }
}

} // namespace sdf::store

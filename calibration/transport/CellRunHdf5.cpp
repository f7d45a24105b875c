#include "CellRun.hpp"
#include "CellSettings.hpp"

#include "io/Hdf5File.hpp"

namespace sdf::dem
{

namespace
{

void writeGreenKubo(const io::Group& g, const correlation::GreenKuboResult& gk)
{
    g.setAttribute("value", gk.integral.value);
    g.setAttribute("standardError", gk.integral.standardError);
    g.setAttribute("blocks", std::int64_t(gk.integral.samples));
    g.setAttribute("plateauFound", std::int64_t(gk.plateauFound ? 1 : 0));
    g.setAttribute("plateauTime", gk.plateauTime);
    g.setAttribute("windowEnd", gk.windowEnd);
    g.writeVector("times", gk.times);
    g.writeVector("correlation", gk.meanCorrelation);
    g.writeVector("correlationError", gk.correlationError);
    g.writeVector("runningIntegral", gk.meanRunningIntegral);
    g.writeVector("runningIntegralError", gk.runningIntegralError);
}

} // namespace


void writeDiffusiveRegime(const io::Group& g, const correlation::DiffusiveRegimeCheck& c)
{
    g.setAttribute("converged", std::int64_t(c.converged() ? 1 : 0));
    g.setAttribute("measured", std::int64_t(c.measured ? 1 : 0));
    g.setAttribute("verdict", c.verdict());
    g.setAttribute("correlationTime", c.correlationTime);
    g.setAttribute("fitStart", c.fitStart);
    g.setAttribute("fitEnd", c.fitEnd);
    const auto estimate = [&g](const std::string& name, const correlation::Estimate& e)
    {
        g.setAttribute(name, e.value);
        g.setAttribute(name + "Error", e.standardError);
    };
    estimate("earlySlope", c.earlySlope);
    estimate("lateSlope", c.lateSlope);
    estimate("slopeChange", c.slopeChange);
    estimate("greenKuboMinusMsd", c.greenKuboMinusMsd);
    estimate("drift", c.drift);
    g.setAttribute("windowPastDecay", std::int64_t(c.windowPastDecay ? 1 : 0));
    g.setAttribute("slopeFlat", std::int64_t(c.slopeFlat ? 1 : 0));
    g.setAttribute("greenKuboAgrees", std::int64_t(c.greenKuboAgrees ? 1 : 0));
    g.setAttribute("plateauFound", std::int64_t(c.plateauFound ? 1 : 0));
    g.setAttribute("stationary", std::int64_t(c.stationary ? 1 : 0));
}


void writeRheology(const io::Group& res, const RheologyResult& h)
{
    if (!h.measured) return;
    const io::Group g = res.createGroup("rheology");
    g.setAttribute("pressureControlled", std::int64_t(h.pressureControlled ? 1 : 0));
    g.setAttribute("targetPressure", h.targetPressure);
    g.setAttribute("barostatTime", h.barostatTime);
    g.setAttribute("meanDiameter", h.meanDiameter);
    g.setAttribute("solidsDensity", h.solidsDensity);
    const std::pair<const char*, const correlation::Estimate*> estimates[] =
    {
        {"pressure", &h.pressure}, {"shearStress", &h.shearStress},
        {"stressRatio", &h.stressRatio}, {"inertialNumber", &h.inertialNumber},
        {"solidsFraction", &h.solidsFraction}, {"coordinationNumber", &h.coordinationNumber},
        {"meanOverlapFraction", &h.meanOverlapFraction}, {"bondOrder", &h.bondOrder}
    };
    for (const auto& [name, e] : estimates)
    {
        g.setAttribute(name, e->value);
        g.setAttribute(std::string(name) + "Error", e->standardError);
    }
    g.setAttribute("steady", std::int64_t(h.steady ? 1 : 0));
    g.setAttribute("steadyCheck", h.steadyCheck);
    g.setAttribute("regime", h.regime);
    g.setAttribute("regimeReason", h.regimeReason);
}

namespace
{

//- inputs: the cell's settings
void writeInputs(const io::Group& inputs, const CellRunResult& r)
{
    const CellRunSettings& s = r.settings;
    inputs.setAttribute("mode", cellModeName(s.simulation.mode));
    inputs.setAttribute("contactModel", contactModelName(s.simulation.contact.model));
    // every scalar setting under its one name (CellSettings.hpp)
    for (const CellSetting& setting : cellSettings())
    {
        if (setting.integer)
        {
            inputs.setAttribute(setting.name, std::int64_t(setting.get(s)));
        }
        else
        {
            inputs.setAttribute(setting.name, setting.get(s));
        }
    }
    {
        std::string pairs;
        for (const PairContactSettings& p : s.simulation.contact.pairs)
        {
            pairs += (pairs.empty() ? "" : "; ") + pairContactText(p);
        }
        inputs.setAttribute("pairContacts", pairs);
    }
    inputs.setAttribute("temperatureConvention", "T = <|c|^2>, sum of the three components; T1 = T/3");
    {
        std::vector<double> d, rho;
        for (const Species& sp : s.species) { d.push_back(sp.diameter); rho.push_back(sp.density); }
        inputs.writeVector("diameter", d);
        inputs.writeVector("density", rho);
        inputs.writeVector("volumeFractions", s.volumeFractions);
        std::vector<std::int64_t> counts(r.speciesCounts.begin(), r.speciesCounts.end());
        inputs.writeInt64Vector("counts", counts);
        std::string names;
        for (std::size_t k = 0; k < s.species.size(); ++k)
        {
            names += (k ? " " : "") + s.species[k].name;
        }
        inputs.setAttribute("speciesNames", names);
    }
}

//- run: steps, timings, equilibration
void writeRun(const io::Group& run, const CellRunResult& r)
{
    // 2: /inputs from the settings table (temperature, not targetTemperature; timeStep as
    // given, the step used is /run/timeStep)
    run.setAttribute("version", "sdf_dem 2");
    run.setAttribute("boxLength", r.boxLength);
    run.setAttribute("timeStep", r.timeStep);
    run.setAttribute("steps", std::int64_t(r.steps));
    run.setAttribute("wallSeconds", r.wallSeconds);
    run.setAttribute("cpuSeconds", r.cpuSeconds);
    run.setAttribute("particleStepsPerSecond", r.particleStepsPerSecond);
    run.setAttribute("equilibrated", std::int64_t(r.equilibrated ? 1 : 0));
    run.setAttribute("equilibrationTime", r.equilibrationTime);
}

//- results: the temperature and the diffusion measurements per species (velocity
//  autocorrelation, mean-square displacement)
void writeSpeciesResults(const io::Group& res, const CellRunResult& r)
{
    res.setAttribute("temperature", r.temperature);
    res.setAttribute("temperatureError", r.temperatureError);
    res.setAttribute("meanDiameter", r.meanDiameter);
    res.setAttribute("savageJeffreyR", r.savageJeffreyR);
    res.setAttribute("diffusionComponent", std::int64_t(r.diffusionComponent));
    res.setAttribute("collectiveMotionTransverse", r.collectiveMotionTransverse.value);
    res.setAttribute("collectiveMotionTransverseError", r.collectiveMotionTransverse.standardError);
    res.setAttribute("collectiveMotionLongitudinal", r.collectiveMotionLongitudinal.value);
    res.setAttribute("collectiveMotionLongitudinalError", r.collectiveMotionLongitudinal.standardError);
    const io::Group sp = res.createGroup("species");
    for (const SpeciesTransport& st : r.species)
    {
        const io::Group g = sp.createGroup(st.name);
        g.setAttribute("count", std::int64_t(st.count));
        g.setAttribute("temperature", st.temperature);
        g.setAttribute("temperatureError", st.temperatureError);
        g.setAttribute("diffusivityMsd", st.diffusivityMsd.value);
        g.setAttribute("diffusivityMsdError", st.diffusivityMsd.standardError);
        writeGreenKubo(g.createGroup("greenKubo"), st.greenKubo);
        writeDiffusiveRegime(g.createGroup("diffusiveRegime"), st.diffusiveRegime);
        if (!st.msd.empty())
        {
            g.writeVector("msdTimes", st.msdTimes);
            g.writeVector("msd", st.msd);
        }
    }
}

//- results/stress: the stress autocorrelation measurement
void writeStress(const io::Group& stress, const CellRunResult& r)
{
    std::string names;
    for (std::size_t k = 0; k < r.stressSeriesNames.size(); ++k)
    {
        names += (k ? " " : "") + r.stressSeriesNames[k];
    }
    stress.setAttribute("series", names);
    stress.setAttribute
    (
        "definition",
        "s_k = J_xy^k / sqrt(V); integrals of <s_i(0) s_j(t)> about the means (the run's,"
        " each block's in the linear terms: correlation::aboutMeans)"
    );
    stress.writeVector("meanShearStress", r.meanStress);
    if (!r.stressIntegrals.terms.empty())
    {
        stress.setAttribute("crossToProductRatio", r.stressIntegrals.crossToProductRatio);
        const std::size_t n = r.stressIntegrals.seriesCount;
        Eigen::MatrixXd value(n, n), error(n, n);
        for (std::size_t i = 0; i < n; ++i)
        {
            for (std::size_t j = 0; j < n; ++j)
            {
                value(i, j) = r.stressIntegrals.term(i, j).integral.value;
                error(i, j) = r.stressIntegrals.term(i, j).integral.standardError;
                writeGreenKubo
                (
                    stress.createGroup("term_" + std::to_string(i) + "_" + std::to_string(j)),
                    r.stressIntegrals.term(i, j)
                );
            }
        }
        stress.writeMatrix("integrals", value);
        stress.writeMatrix("integralErrors", error);
        writeGreenKubo(stress.createGroup("total"), r.stressIntegrals.total);
        auto writeEta = [&stress](const std::string& name, const std::vector<correlation::Estimate>& values)
        {
            std::vector<double> eta, etaErr;
            for (const auto& e : values) { eta.push_back(e.value); etaErr.push_back(e.standardError); }
            if (!eta.empty())
            {
                stress.writeVector(name, eta);
                stress.writeVector(name + "Error", etaErr);
            }
        };
        writeEta("kineticSieving", r.kineticSieving);
        writeEta("kineticSievingWithCrossTerms", r.kineticSievingWithCrossTerms);
    }
}

//- results/collisions: the collision measurement
void writeCollisions(const io::Group& col, const CellRunResult& r)
{
    col.setAttribute("elapsedTime", r.collisions.elapsedTime);
    col.setAttribute("impactEnergy", "0.5 m* v_n^2 at the first step of a contact [J]");
    col.writeVector("binEdges", r.collisions.binEdges);
    {
        std::vector<std::int64_t> counts(r.collisions.counts.begin(), r.collisions.counts.end());
        col.writeInt64Vector("counts", counts);
        const int n = int(r.species.size());
        Eigen::MatrixXd hist(r.collisions.histogram.size(),
                             r.collisions.histogram.empty() ? 0 : r.collisions.histogram[0].size());
        for (std::size_t a = 0; a < r.collisions.histogram.size(); ++a)
        {
            for (std::size_t b = 0; b < r.collisions.histogram[a].size(); ++b)
            {
                hist(a, b) = double(r.collisions.histogram[a][b]);
            }
        }
        col.writeMatrix("histogram", hist);
        Eigen::MatrixXd freq(n, n);
        for (int a = 0; a < n; ++a)
        {
            for (int b = 0; b < n; ++b)
            {
                freq(a, b) = r.collisions.frequencyPerParticle(a, b, r.speciesCounts);
            }
        }
        col.writeMatrix("frequencyPerParticle", freq);
        col.writeVector("energySum", r.collisions.energySum);
    }
}

} // namespace

void writeCellRun(const CellRunResult& r, const std::string& path)
{
    io::AtomicFile file = io::AtomicFile::create(path);
    const io::Group root = file.root();
    writeInputs(root.createGroup("inputs"), r);
    writeRun(root.createGroup("run"), r);
    const io::Group results = root.createGroup("results");
    writeSpeciesResults(results, r);
    writeRheology(results, r.rheology);
    writeStress(results.createGroup("stress"), r);
    writeCollisions(results.createGroup("collisions"), r);
    file.commit();
}

} // namespace sdf::dem

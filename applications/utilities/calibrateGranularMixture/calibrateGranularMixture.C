/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    calibrateGranularMixture

Group
    grpPreProcessingUtilities

Description
    Calibration workflow of a binary mixture: runs the embedded periodic DEM
    engine (calibration/dem) over an envelope of conditions (solids fraction
    phi, coarse fraction x, granular temperature T, replicas), stores every
    finished condition at once in constant/calibration.h5 (a rerun skips the
    stored ones), fits constitutive laws (calibration/fit) to the diffusivity
    of the fines (D) and the kinetic sieving coefficient of the coarse (eta),
    chooses among candidate laws by AIC and writes constant/granularCoefficients.

    Species (d, rho) come from constant/granularProperties (exactly two: the
    smaller is the fine species); the rest from system/calibrationDict:
    \verbatim
    phi             (0.2 0.3);          // total solids fractions, 0 < phi < 0.64
    x               (0.2 0.4);          // coarse fractions of the solids, 0 < x < 1
    T               (0.005 0.01);       // granular temperature [m2/s2], sum of 3 components
    replicas        (1);                // DEM seeds: one run per seed and condition
    coefficients    (D eta);            // which to calibrate: D (fines), eta (coarse)
    laws            (powerLaw kineticTheoryGroups);   // candidate laws for D
    etaLaws         (sievingCompositionPowerLaw sievingPowerLaw); // candidate laws for eta
    etaDiameterPower 1;                 // k of the eta laws (E d^k ...)
    fitMaxIterations 2000;              // per law; a law not converged is reported
    particles       200;
    mode            thermostatted;
    contact         { model linearSpringDashpot; restitution 0.9; friction 0.3;
                      normalStiffness 2e3; }
    timeStep        0;
    equilibrationTime 0.002;
    samplingTime    0.01;
    sampleEvery     10;
    blocks          8;
    threads         1;
    plot            true;               // gnuplot PNGs in postProcessing/calibration
    concurrentConditions 0;             // conditions at once; 0: cores / threads
    fromCase        { points 3; minTRatio 1e-3; }   // -fromCase only
    \endverbatim
    Several conditions run at once on worker threads (only the main thread
    calls HDF5); under mpirun with -parallel the conditions are dealt to the
    ranks round-robin, each rank stores its own in
    constant/calibration.processor<N>.h5 and the master merges those into
    calibration.h5 at the end and at the start of any run (no decomposition
    needed). -fromCase [time] takes the envelope from the case's fields
    (n.<species>, T over the cells with phi >= phiMin) and the coefficients
    from the mechanisms granularProperties switches on.
    Bad input stops with a FatalIOError naming the entry; a calibration.h5
    that is not ours (corrupt, foreign) stops with a FatalError naming the
    file and is left untouched. Documentation: docs/calibration.md.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "sigFpe.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include "clock.H"
#include "IFstream.H"
#include "ITstream.H"

#include "demDictionary.H"
#include "calibrationStore.H"
#include "io/Hdf5File.hpp"
#include "fit/FitData.hpp"
#include "fit/Laws.hpp"
#include "fit/LeastSquares.hpp"
#include "fit/ModelSelection.hpp"
#include "fit/OpenFOAMDictionary.hpp"
#include "fit/SievingNormalisation.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <iomanip>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <omp.h>

using namespace Foam;

namespace
{

//- Jamming limit of the envelope (random close packing)
const scalar phiJamming = 0.64;

const wordList validEntries
({
    "phi", "x", "T", "replicas", "coefficients", "laws", "etaLaws",
    "etaDiameterPower", "fitMaxIterations",
    "particles", "mode", "plot", "concurrentConditions", "fromCase"
});

const wordList validCoefficients({"D", "eta"});
const wordList validDLaws({"powerLaw", "kineticTheoryGroups"});
const wordList validEtaLaws({"sievingCompositionPowerLaw", "sievingPowerLaw"});


std::string fmt(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.6g", v);
    return buf;
}


//- A list entry of the envelope: present, non-empty, every value in (lo, hi)
//- Candidate laws of one coefficient: entry `key` (default: all valid ones),
//  not empty, every name known
wordList readLawList
(
    const dictionary& dict,
    const word& key,
    const wordList& valid,
    const word& coefficient
)
{
    const wordList laws(dict.getOrDefault<wordList>(key, valid));
    if (laws.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' is empty; valid laws for "
            << coefficient << ": " << valid << nl << exit(FatalIOError);
    }
    for (const word& l : laws)
    {
        if (!valid.found(l))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown law '" << l << "' in entry '" << key << "'" << nl
                << "    valid laws for " << coefficient << ": " << valid << nl
                << exit(FatalIOError);
        }
    }
    return laws;
}


scalarList readEnvelopeList
(
    const dictionary& dict,
    const word& key,
    const scalar lo,
    const scalar hi,
    const string& meaning
)
{
    if (!dict.found(key))
    {
        FatalIOErrorInFunction(dict)
            << "Missing envelope entry '" << key << "' (" << meaning.c_str()
            << ") in " << dict.name() << nl << exit(FatalIOError);
    }
    const scalarList values(dict.get<scalarList>(key));
    if (values.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Envelope entry '" << key << "' (" << meaning.c_str()
            << ") is empty: give at least one value" << nl
            << exit(FatalIOError);
    }
    std::set<scalar> seen;
    for (const scalar v : values)
    {
        if (!std::isfinite(v) || v <= lo || v >= hi)
        {
            FatalIOErrorInFunction(dict)
                << "Envelope entry '" << key << "' (" << meaning.c_str()
                << "): value " << v << " is outside (" << lo << ", "
                << (hi > 1e300 ? std::string("inf") : fmt(hi)).c_str()
                << ")" << nl << exit(FatalIOError);
        }
        if (!seen.insert(v).second)
        {
            FatalIOErrorInFunction(dict)
                << "Envelope entry '" << key << "': value " << v
                << " appears twice" << nl << exit(FatalIOError);
        }
    }
    // An envelope axis is a grid line (the tabulated models interpolate
    // along it): values in increasing order, so an inverted range is caught
    for (label i = 1; i < values.size(); ++i)
    {
        if (!(values[i] > values[i - 1]))
        {
            FatalIOErrorInFunction(dict)
                << "Envelope entry '" << key << "' (" << meaning.c_str()
                << ") is not in increasing order (inverted envelope?): "
                << values << nl
                << "    give the values from the smallest to the largest"
                << nl << exit(FatalIOError);
        }
    }
    return values;
}


//- Envelope and coefficients derived from a case (-fromCase)
struct CaseEnvelope
{
    scalarList phi, x, T;
    wordList coefficients;
};


//- Limits of the envelope a case's fields are clipped to: the DEM's valid
//  range with a margin (a periodic cell near random close packing 0.64
//  jams; a cell of one species only has no mixture to calibrate)
const scalar fromCasePhiMax = 0.6;
const scalar fromCaseXMin = 0.05;
const scalar fromCaseXMax = 0.95;


//- "(v1 v2 ...)" with %.6g: the envelope values as the condition names show them
std::string listText(const scalarList& values)
{
    std::string text("(");
    for (const scalar v : values)
    {
        text += (text.size() > 1 ? " " : "") + fmt(v);
    }
    return text + ")";
}


//- v rounded to 4 significant digits: the envelope values read as printed
//  (and as they appear in the condition names)
scalar roundSignificant(const scalar v)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%.4g", v);
    return std::strtod(buf, nullptr);
}


//- n values spanning [lo, hi], linearly or logarithmically spaced; one value
//  if the range is degenerate (after rounding to 4 significant digits)
scalarList envelopeValues
(
    const scalar lo,
    const scalar hi,
    const label n,
    const bool logSpacing
)
{
    scalarList values;
    const scalar first = roundSignificant(lo);
    if (n == 1 || roundSignificant(hi) <= first)
    {
        values.append(first);
        return values;
    }
    for (label i = 0; i < n; ++i)
    {
        const scalar f = scalar(i)/(n - 1);
        const scalar v =
            logSpacing
          ? lo*std::pow(hi/lo, f)
          : lo + (hi - lo)*f;
        const scalar r = roundSignificant(v);
        if (values.empty() || r > values.last())
        {
            values.append(r);
        }
    }
    return values;
}


//- Cell values of a volScalarField file: its internalField, uniform (one
//  value) or nonuniform (one value per cell). Read as a dictionary, so that
//  no mesh is needed (and -parallel needs no decomposition).
struct CellValues
{
    bool uniform = true;
    scalarList values;

    scalar operator[](const label celli) const
    {
        return uniform ? values[0] : values[celli];
    }
};


CellValues readCellValues(const fileName& file, const Time& runTime)
{
    IFstream is(file);
    IOobject io(file.name(), file.path().name(), runTime);
    if (!is.good() || !io.readHeader(is))
    {
        FatalErrorInFunction
            << "Cannot read the field file " << file << nl << exit(FatalError);
    }
    const dictionary fieldDict(is);
    ITstream& its = fieldDict.lookup("internalField");
    CellValues cv;
    const token kind(its);
    if (kind.isWord() && kind.wordToken() == "uniform")
    {
        cv.values.append(readScalar(its));
    }
    else if (kind.isWord() && kind.wordToken() == "nonuniform")
    {
        cv.uniform = false;
        its >> cv.values;
    }
    else
    {
        FatalIOErrorInFunction(fieldDict)
            << "internalField of " << file << " is neither uniform nor"
            << " nonuniform" << nl << exit(FatalIOError);
    }
    return cv;
}


//- The time directories of a directory (names that read as numbers)
wordList timeDirectories(const fileName& dir)
{
    std::vector<std::pair<scalar, word>> times;
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        scalar t;
        if (readScalar(d, t))
        {
            times.push_back({t, word(d)});
        }
    }
    std::sort(times.begin(), times.end());
    wordList names;
    for (const auto& t : times)
    {
        names.append(t.second);
    }
    return names;
}


//- Whether granularProperties switches a mechanism on (model not none)
bool mechanismOn(const dictionary& properties, const word& mechanism)
{
    if (!properties.isDict(mechanism))
    {
        FatalIOErrorInFunction(properties)
            << "-fromCase: " << properties.name() << " has no sub-dictionary '"
            << mechanism << "' (give it with 'model none;' to switch the"
            << " mechanism off)" << nl << exit(FatalIOError);
    }
    return properties.subDict(mechanism).get<word>("model") != "none";
}


//- The envelope of a case at a time: the ranges of phi, x and T over the
//  cells holding material (phi >= phiMin), clipped to the DEM's valid range
//  and turned into fromCase/points values per axis; the coefficients of the
//  mechanisms the case switches on. An empty coefficient list: nothing to
//  calibrate.
CaseEnvelope deriveEnvelope
(
    const Time& runTime,
    const dictionary& properties,
    const dictionary& dict,
    const word& timeArg
)
{
    CaseEnvelope env;
    const fileName caseDir(runTime.globalPath());

    // Coefficients of the mechanisms the case switches on
    const bool diffusion = mechanismOn(properties, "diffusivity");
    const bool sieving = mechanismOn(properties, "kineticSieving");
    if (diffusion) env.coefficients.append("D");
    if (sieving) env.coefficients.append("eta");
    Info<< "-fromCase: diffusivity "
        << properties.subDict("diffusivity").get<word>("model")
        << ", kineticSieving "
        << properties.subDict("kineticSieving").get<word>("model")
        << " in constant/granularProperties -> coefficients (";
    for (const word& c : env.coefficients)
    {
        Info<< (&c == &env.coefficients.first() ? "" : " ") << c;
    }
    Info<< ")" << nl;
    if (env.coefficients.empty())
    {
        return env;
    }

    // Options
    const dictionary& opts = dict.subOrEmptyDict("fromCase");
    demDictionary::checkEntries(opts, wordList({"points", "minTRatio"}));
    const label points = opts.getOrDefault<label>("points", 3);
    if (points < 1)
    {
        FatalIOErrorInFunction(opts)
            << "Entry 'fromCase/points' " << points << ": give the number of"
            << " values per envelope axis, >= 1" << nl << exit(FatalIOError);
    }
    const scalar minTRatio = opts.getOrDefault<scalar>("minTRatio", 1e-3);
    if (!(minTRatio > 0 && minTRatio <= 1))
    {
        FatalIOErrorInFunction(opts)
            << "Entry 'fromCase/minTRatio' " << minTRatio << " is outside"
            << " (0, 1]: the smallest T calibrated, as a fraction of the"
            << " largest T of the case" << nl << exit(FatalIOError);
    }

    // Species: fine = smaller diameter
    const dictionary& speciesDict = properties.subDict("species");
    wordList names(speciesDict.sortedToc());
    if (names.size() != 2)
    {
        FatalIOErrorInFunction(speciesDict)
            << "calibrateGranularMixture calibrates binary mixtures: "
            << speciesDict.name() << " declares " << names.size()
            << " species " << names << ", need 2" << nl << exit(FatalIOError);
    }
    if
    (
        speciesDict.subDict(names[1]).get<scalar>("d")
      < speciesDict.subDict(names[0]).get<scalar>("d")
    )
    {
        std::swap(names[0], names[1]);
    }
    const word& fine = names[0];
    const word& coarse = names[1];
    const scalar phiMin = properties.getOrDefault<scalar>("phiMin", 0.05);

    // Time: the latest of the case (or of its processor directories when
    // the case ran decomposed and was not reconstructed), or the one given
    const wordList times(timeDirectories(caseDir));
    const wordList procTimes(timeDirectories(caseDir/"processor0"));
    word time;
    if (timeArg == "latestTime")
    {
        scalar latest = -GREAT;
        for (const wordList* list : {&times, &procTimes})
        {
            if (!list->empty() && readScalar(list->last()) > latest)
            {
                latest = readScalar(list->last());
                time = list->last();
            }
        }
    }
    else
    {
        scalar wanted;
        if (!readScalar(timeArg, wanted))
        {
            FatalErrorInFunction
                << "-fromCase " << timeArg << ": not a time (give a time"
                << " directory name of the case, or nothing for the latest)"
                << nl << exit(FatalError);
        }
        for (const wordList* list : {&times, &procTimes})
        {
            for (const word& t : *list)
            {
                if (mag(readScalar(t) - wanted) <= 1e-12*max(mag(wanted), 1))
                {
                    time = t;
                }
            }
        }
    }
    if (time.empty())
    {
        FatalErrorInFunction
            << "-fromCase " << timeArg << ": no such time directory in "
            << caseDir << " (times: " << times << ", processor0: "
            << procTimes << ")" << nl << exit(FatalError);
    }

    // Where the fields are: the case, or every processor directory
    std::vector<fileName> sources;
    if (isDir(caseDir/time))
    {
        sources.push_back(caseDir/time);
    }
    else
    {
        for (label proci = 0; isDir(caseDir/("processor" + Foam::name(proci))); ++proci)
        {
            sources.push_back(caseDir/("processor" + Foam::name(proci))/time);
        }
    }

    const bool haveT = isFile(sources[0]/"T");
    if (!haveT && !dict.found("T"))
    {
        FatalErrorInFunction
            << "-fromCase: the granular temperature field T is missing: no"
            << " file " << sources[0]/"T" << nl
            << "    The solver writes T when constant/granularProperties has"
            << " 'writeFields (T ...);' (and a granularTemperature model):"
            << " add T to writeFields and rerun the solver to time " << time
            << ", or give the temperatures as 'T (..);' in"
            << " system/calibrationDict" << nl << exit(FatalError);
    }

    scalar phiLo = GREAT, phiHi = -GREAT;
    scalar xLo = GREAT, xHi = -GREAT;
    scalar TLo = GREAT, THi = -GREAT;
    label cells = 0, material = 0;
    for (const fileName& dir : sources)
    {
        const CellValues nFine(readCellValues(dir/("n." + fine), runTime));
        const CellValues nCoarse(readCellValues(dir/("n." + coarse), runTime));
        const CellValues T
        (
            haveT ? readCellValues(dir/"T", runTime) : CellValues()
        );
        label n = 1;
        for (const CellValues* f : {&nFine, &nCoarse, &T})
        {
            if (!f->uniform)
            {
                if (n > 1 && f->values.size() != n)
                {
                    FatalErrorInFunction
                        << "-fromCase: the fields in " << dir << " have"
                        << " different numbers of cells" << nl
                        << exit(FatalError);
                }
                n = f->values.size();
            }
        }
        cells += n;
        for (label celli = 0; celli < n; ++celli)
        {
            const scalar phi = nFine[celli] + nCoarse[celli];
            if (!(phi >= phiMin))
            {
                continue;
            }
            ++material;
            const scalar x = nCoarse[celli]/phi;
            phiLo = min(phiLo, phi);
            phiHi = max(phiHi, phi);
            xLo = min(xLo, x);
            xHi = max(xHi, x);
            if (haveT && T[celli] > 0)
            {
                TLo = min(TLo, T[celli]);
                THi = max(THi, T[celli]);
            }
        }
    }
    if (material == 0)
    {
        FatalErrorInFunction
            << "-fromCase: no cell at time " << time << " holds material"
            << " (phi = n." << fine << " + n." << coarse << " >= phiMin "
            << phiMin << ")" << nl << exit(FatalError);
    }

    Info<< "-fromCase: fields at time " << time << " ("
        << (sources.size() > 1 ? "processor directories" : "case") << "), "
        << material << " of " << cells << " cells hold material (phi >= "
        << phiMin << "), " << points << " points per axis" << nl;
    auto report = [](const char* axis, scalar lo, scalar hi, scalar cLo,
                     scalar cHi, const scalarList& values)
    {
        Info<< "-fromCase " << axis << ": case range [" << fmt(lo).c_str()
            << ", " << fmt(hi).c_str() << "], clipped [" << fmt(cLo).c_str()
            << ", " << fmt(cHi).c_str() << "] -> " << listText(values).c_str()
            << nl;
    };

    const scalar phiCLo = min(phiLo, fromCasePhiMax);
    const scalar phiCHi = min(phiHi, fromCasePhiMax);
    env.phi = envelopeValues(phiCLo, phiCHi, points, false);
    report("phi", phiLo, phiHi, phiCLo, phiCHi, env.phi);

    const scalar xCLo = min(max(xLo, fromCaseXMin), fromCaseXMax);
    const scalar xCHi = min(max(xHi, fromCaseXMin), fromCaseXMax);
    env.x = envelopeValues(xCLo, xCHi, points, false);
    report("x", xLo, xHi, xCLo, xCHi, env.x);

    if (haveT)
    {
        if (!(THi > 0))
        {
            FatalErrorInFunction
                << "-fromCase: T is zero in every cell holding material at"
                << " time " << time << ": a static case, no granular"
                << " temperature to calibrate at; give 'T (..);' in"
                << " system/calibrationDict" << nl << exit(FatalError);
        }
        // T spans many decades in a silo (nearly static zones): calibrate
        // above minTRatio times the largest T; the calibrated models'
        // outsideEnvelope decides below it
        const scalar TCLo = max(TLo, minTRatio*THi);
        env.T = envelopeValues(TCLo, THi, points, true);
        report("T", TLo, THi, TCLo, THi, env.T);
    }
    else
    {
        env.T = readEnvelopeList
        (
            dict, "T", 0, 1e301, "granular temperature [m2/s2], sum of 3 components"
        );
        Info<< "-fromCase T: no field T at time " << time << ", the T list"
            << " of system/calibrationDict is used: " << listText(env.T).c_str()
            << nl;
    }
    for (const word& key : wordList({"phi", "x", "T", "coefficients"}))
    {
        if (dict.found(key) && !(key == "T" && !haveT))
        {
            Info<< "-fromCase: entry '" << key.c_str() << "' of "
                << dict.name() << " is overridden by the case" << nl;
        }
    }
    Info<< endl;
    return env;
}


struct Setup
{
    // species: index 0 fine, 1 coarse
    std::vector<sdf::dem::Species> species;
    scalarList phi, x, T;
    labelList replicas;
    wordList coefficients;
    wordList laws;
    wordList etaLaws;
    label etaDiameterPower = 1;
    label fitMaxIterations = 2000;
    bool plot = true;
    sdf::dem::CellRunSettings base;   // everything but the condition
    std::string settingsKey;          // DEM settings a stored result belongs to
};


Setup readSetup
(
    const dictionary& properties,
    const dictionary& dict,
    const CaseEnvelope* fromCase = nullptr
)
{
    wordList valid(validEntries);
    valid.append(demDictionary::runControlEntries());
    demDictionary::checkEntries(dict, valid);
    Setup s;

    // Species: exactly two, fine = smaller diameter
    const dictionary& speciesDict = properties.subDict("species");
    const wordList names(speciesDict.sortedToc());
    if (names.size() != 2)
    {
        FatalIOErrorInFunction(speciesDict)
            << "calibrateGranularMixture calibrates binary mixtures: "
            << speciesDict.name() << " declares " << names.size()
            << " species " << names << ", need 2" << nl << exit(FatalIOError);
    }
    for (const word& name : names)
    {
        const dictionary& sd = speciesDict.subDict(name);
        s.species.push_back({name, sd.get<scalar>("d"), sd.get<scalar>("rho")});
    }
    if (s.species[1].diameter < s.species[0].diameter)
    {
        std::swap(s.species[0], s.species[1]);
    }
    if (!(s.species[1].diameter > s.species[0].diameter))
    {
        FatalIOErrorInFunction(speciesDict)
            << "The two species have the same diameter: no fine and coarse"
            << nl << exit(FatalIOError);
    }

    // Envelope
    if (fromCase)
    {
        s.phi = fromCase->phi;
        s.x = fromCase->x;
        s.T = fromCase->T;
    }
    else
    {
        s.phi = readEnvelopeList(dict, "phi", 0, phiJamming, "solids fraction, below jamming 0.64");
        s.x = readEnvelopeList(dict, "x", 0, 1, "coarse fraction of the solids");
        s.T = readEnvelopeList(dict, "T", 0, 1e301, "granular temperature [m2/s2], sum of 3 components");
    }

    s.replicas = dict.getOrDefault<labelList>("replicas", labelList({1}));
    if (s.replicas.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'replicas' (DEM seeds) is empty" << nl << exit(FatalIOError);
    }
    {
        std::set<label> seen;
        for (const label r : s.replicas)
        {
            if (r < 0 || !seen.insert(r).second)
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'replicas': seed " << r
                    << " is negative or appears twice" << nl << exit(FatalIOError);
            }
        }
    }

    s.coefficients = dict.getOrDefault<wordList>("coefficients", wordList({"D"}));
    if (s.coefficients.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coefficients' is empty; valid names: "
            << validCoefficients << nl << exit(FatalIOError);
    }
    for (const word& c : s.coefficients)
    {
        if (!validCoefficients.found(c))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown coefficient '" << c << "' in entry 'coefficients'"
                << nl << "    valid names: " << validCoefficients
                << " (D: diffusivity of the fines, eta: kinetic sieving"
                << " coefficient of the coarse)" << nl << exit(FatalIOError);
        }
    }
    if (fromCase)
    {
        s.coefficients = fromCase->coefficients;
    }
    s.laws = readLawList(dict, "laws", validDLaws, "D");
    s.etaLaws = readLawList(dict, "etaLaws", validEtaLaws, "eta");
    s.etaDiameterPower = dict.getOrDefault<label>("etaDiameterPower", 1);
    s.fitMaxIterations = dict.getOrDefault<label>("fitMaxIterations", 2000);
    if (s.fitMaxIterations < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fitMaxIterations' must be at least 1, not "
            << s.fitMaxIterations << nl << exit(FatalIOError);
    }
    s.plot = dict.getOrDefault<bool>("plot", true);

    // DEM settings
    sdf::dem::CellRunSettings& b = s.base;
    b.species = s.species;
    b.particles = dict.getOrDefault<label>("particles", 1000);
    const word mode(dict.getOrDefault<word>("mode", "thermostatted"));
    if (mode != "thermostatted")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mode' " << mode << ": calibrateGranularMixture runs"
            << " driven cells only (mode thermostatted)" << nl
            << exit(FatalIOError);
    }
    b.simulation.mode = sdf::dem::cellModeFromName(mode);
    demDictionary::readRunControls(dict, b);
    b.progressEvery = 0;
    // Fingerprint of the DEM settings (everything but the condition): a
    // stored condition is reused only if it was run with the same settings.
    s.settingsKey = calibrationStore::settingsKey
    (
        b,
        dict.subOrEmptyDict("contact")
            .getOrDefault<word>("model", "linearSpringDashpot")
    );

    return s;
}


struct ConditionSpec
{
    scalar phi, x, T;
    label seed;
    std::string name;
};


std::string conditionName(scalar phi, scalar x, scalar T, label seed)
{
    return calibrationStore::conditionName(phi, x, T, seed);
}


//- Condition groups already in the file, with their settings keys. Stops
//  with a FatalError naming the file if it is not a calibration file of ours.
std::map<std::string, std::string> storedConditions(const fileName& h5)
{
    std::map<std::string, std::string> stored;
    if (!isFile(h5))
    {
        return stored;
    }
    try
    {
        sdf::io::File f = sdf::io::File::openReadOnly(h5);
        const sdf::io::Group root = f.root();
        calibrationStore::checkIsStore(root);
        if (root.hasGroup("conditions"))
        {
            const sdf::io::Group conditions = root.openGroup("conditions");
            for (const std::string& name : conditions.childNames())
            {
                stored[name] =
                    conditions.openGroup(name).readString("settingsKey");
            }
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Cannot use " << h5 << " as the calibration store:" << nl
            << "    " << err.what() << nl
            << "    The file is left untouched: move it away (or remove it)"
            << " to start a new calibration." << nl << exit(FatalError);
    }
    return stored;
}


//- Appends one finished condition to the store, atomically (the file is
//  copied to <file>.tmp, the group added, and the copy renamed over it).
void storeCondition
(
    const fileName& h5,
    const Setup& setup,
    const ConditionSpec& cond,
    const sdf::dem::CellRunResult& r
)
{
    calibrationStore::storeCondition
    (
        h5,
        setup.species[0].name,
        setup.species[1].name,
        setup.settingsKey,
        {cond.name, cond.phi, cond.x, cond.T, cond.seed},
        r
    );
}


struct StoredResult
{
    ConditionSpec cond;
    scalar T = 0;
    scalar D = 0, DError = 0;        // fines
    scalar eta = 0, etaError = 0;    // coarse, m2/s (converted on reading)
    bool hasEta = false;
};


std::vector<StoredResult> readResults
(
    const fileName& h5,
    const Setup& setup,
    const std::vector<ConditionSpec>& conds
)
{
    std::vector<StoredResult> out;
    try
    {
        sdf::io::File f = sdf::io::File::openReadOnly(h5);
        const sdf::io::Group conditions = f.root().openGroup("conditions");
        for (const ConditionSpec& c : conds)
        {
            const sdf::io::Group g = conditions.openGroup(c.name);
            StoredResult r;
            r.cond = c;
            r.T = g.readDouble("T");
            const sdf::io::Group fine =
                g.openGroup("species/" + setup.species[0].name);
            const sdf::io::Group coarse =
                g.openGroup("species/" + setup.species[1].name);
            r.D = fine.readDouble("D");
            r.DError = fine.readDouble("DError");
            if (coarse.hasAttribute("eta"))
            {
                // stored in engine units (kg^2 m s^-3); fitted and plotted
                // in the m2/s of the solver's flux (docs/calibration-fit.md)
                const sdf::fit::SphereSpecies fineSpecies
                {
                    setup.species[0].diameter, setup.species[0].density
                };
                const sdf::fit::SphereSpecies coarseSpecies
                {
                    setup.species[1].diameter, setup.species[1].density
                };
                const double toKinematic =
                    sdf::fit::kinematicSievingCoefficient
                    (
                        1.0, c.phi, c.x, r.T, fineSpecies, coarseSpecies
                    );
                r.hasEta = true;
                r.eta = toKinematic*coarse.readDouble("eta");
                r.etaError = toKinematic*coarse.readDouble("etaError");
            }
            out.push_back(r);
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Reading the results back from " << h5 << " failed:" << nl
            << "    " << err.what() << nl << exit(FatalError);
    }
    return out;
}


sdf::fit::ConstitutiveLaw lawFromName(const word& name)
{
    if (name == "powerLaw") return sdf::fit::SeedPowerLaw{};
    return sdf::fit::KineticTheoryGroupsLaw{};
}


void reportFit(const sdf::fit::FitResult& fit)
{
    Info<< "    law " << fit.law.name().c_str() << ": "
        << fit.law.formula().c_str() << nl;
    if (!fit.converged())
    {
        Info<< "      FAILED: " << fit.message.c_str() << nl;
        return;
    }
    for (const auto& p : fit.parameters)
    {
        Info<< "      " << p.name.c_str() << " = " << fmt(p.value).c_str()
            << " +- " << fmt(p.standardError).c_str() << nl;
    }
    Info<< "      R2 = " << fmt(fit.rSquared).c_str()
        << ", reduced chi2 = " << fmt(fit.reducedChiSquare).c_str()
        << ", AIC = " << fmt(fit.aic).c_str()
        << ", BIC = " << fmt(fit.bic).c_str()
        << ", points = " << label(fit.points) << nl;
}


//- Data file and gnuplot PNG of a coefficient (D of the fines or eta of
//  the coarse) vs T per phi, one figure per x
void plotCoefficient
(
    const fileName& dir,
    const std::vector<StoredResult>& results,
    const Setup& setup,
    const sdf::fit::FitResult* fit,
    const bool isD
)
{
    const std::string prefix = isD ? "D" : "eta";
    const std::string what =
        isD
      ? "D of the fines [m^2/s]"
      : "eta of the coarse [m^2/s]";
    const scalar d = setup.species[isD ? 0 : 1].diameter;
    mkDir(dir);
    for (const scalar x : setup.x)
    {
        const std::string tag = "x" + fmt(x);
        const fileName dat(dir/(prefix + "_" + tag + ".dat"));
        {
            std::ofstream os(dat);
            os << "# " << what << " vs T at x = " << fmt(x)
               << "; blocks per phi: T value error fitted\n";
            for (const scalar phi : setup.phi)
            {
                os << "# phi " << fmt(phi) << "\n";
                for (const StoredResult& r : results)
                {
                    if (r.cond.x != x || r.cond.phi != phi) continue;
                    if (!isD && !r.hasEta) continue;
                    sdf::fit::Condition c{phi, x, r.T, d, {}};
                    os << std::setprecision(10) << r.T << " "
                       << (isD ? r.D : r.eta) << " "
                       << (isD ? r.DError : r.etaError) << " "
                       << (fit ? fit->evaluate(c) : 0.0) << "\n";
                }
                os << "\n\n";
            }
        }
        if (std::system("command -v gnuplot > /dev/null 2>&1") != 0)
        {
            continue;
        }
        const fileName gp(dir/(prefix + "_" + tag + ".gp"));
        const fileName png(dir/(prefix + "_" + tag + ".png"));
        {
            std::ofstream os(gp);
            os << "set terminal pngcairo size 800,600\n"
               << "set output '" << png.c_str() << "'\n"
               << (isD ? "set logscale xy\n" : "set logscale x\n")
               << "set key top left\n"
               << "set xlabel 'T [m^2/s^2] (sum of 3 components)'\n"
               << "set ylabel '" << what << "'\n"
               << "set title 'DEM (Green-Kubo)"
               << (fit ? " and fitted law " + fit->law.name() : std::string())
               << ", x = " << fmt(x) << "'\n"
               << "plot ";
            label i = 0;
            for (const scalar phi : setup.phi)
            {
                if (i) os << ", ";
                os << "'" << dat.c_str() << "' index " << i
                   << " using 1:2:3 with yerrorbars lc " << i + 1
                   << " pt 7 title 'DEM phi = " << fmt(phi) << "'";
                if (fit)
                {
                    os << ", '' index " << i << " using 1:4 with lines lc " << i + 1
                       << " notitle";
                }
                ++i;
            }
            os << "\n";
        }
        const std::string cmd = "gnuplot '" + std::string(gp) + "' > /dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0)
        {
            Info<< "Written " << png << nl;
        }
    }
}


void writeAtomically(const fileName& path, const std::string& text)
{
    const fileName tmp(path + ".tmp");
    {
        std::ofstream os(tmp);
        os << text;
        if (!os.good())
        {
            FatalErrorInFunction
                << "Cannot write " << tmp << nl << exit(FatalError);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
    {
        FatalErrorInFunction
            << "Cannot rename " << tmp << " to " << path << nl << exit(FatalError);
    }
}

//- DEM settings of one condition (the envelope point on top of the base)
sdf::dem::CellRunSettings cellSettings
(
    const Setup& setup,
    const ConditionSpec& c
)
{
    sdf::dem::CellRunSettings s = setup.base;
    s.volumeFractions = {1 - c.x, c.x};
    s.solidsFraction = c.phi;
    s.simulation.targetTemperature = c.T;
    s.seed = c.seed;
    s.label = c.name;
    return s;
}


//- Copies the attributes and sub-groups of one condition group (our
//  condition groups hold no datasets); doubles and integers are copied
//  exactly, so a merged condition equals the one its rank stored
void copyGroup(const sdf::io::Group& from, const sdf::io::Group& to)
{
    for (const std::string& name : from.attributeNames())
    {
        switch (from.attributeType(name))
        {
            case sdf::io::AttributeType::floating:
                to.setAttribute(name, from.readDouble(name));
                break;
            case sdf::io::AttributeType::integer:
                to.setAttribute(name, from.readInt64(name));
                break;
            case sdf::io::AttributeType::string:
                to.setAttribute(name, from.readString(name));
                break;
            default:
                throw std::runtime_error
                (
                    "attribute " + from.path() + "/" + name
                  + " is of a type a calibration store does not hold"
                );
        }
    }
    for (const std::string& child : from.childNames())
    {
        if (!from.hasGroup(child))
        {
            throw std::runtime_error
            (
                from.path() + "/" + child
              + " is a dataset: a calibration store holds none"
            );
        }
        copyGroup(from.openGroup(child), to.createGroup(child));
    }
}


//- Store of one MPI rank: constant/calibration.processor<N>.h5
fileName processorStore(const fileName& h5, const label proci)
{
    return h5.path()/("calibration.processor" + Foam::name(proci) + ".h5");
}


//- Moves the conditions of every processor store left in the directory of
//  h5 (by this run or by a parallel run that was killed) into h5, in one
//  atomic update, then removes the processor stores. A condition already
//  in h5 is not copied again (a merge killed between the rename of h5 and
//  the removal of the processor stores is completed by the next run).
//  Returns the number of conditions moved.
label mergeProcessorStores(const fileName& h5)
{
    const fileName dir(h5.path());
    std::vector<fileName> stores;
    for (const fileName& f : readDir(dir, fileName::FILE))
    {
        const std::string name(f);
        if (name.rfind("calibration.processor", 0) != 0)
        {
            continue;
        }
        if (name.size() > 3 && name.compare(name.size() - 3, 3, ".h5") == 0)
        {
            stores.push_back(dir/f);
        }
        else if
        (
            name.size() > 7
         && name.compare(name.size() - 7, 7, ".h5.tmp") == 0
        )
        {
            // A rank killed while adding a condition: the copy it was
            // writing is incomplete, its store holds every finished one.
            // No rank writes now (start or end of a run).
            Foam::rm(dir/f);
        }
    }
    std::sort(stores.begin(), stores.end());
    if (stores.empty())
    {
        return 0;
    }

    const std::map<std::string, std::string> inMain = storedConditions(h5);
    label moved = 0;
    try
    {
        std::optional<sdf::io::AtomicFile> out;
        std::set<std::string> copied;
        for (const fileName& store : stores)
        {
            // The same checks as for the main store: a foreign or corrupt
            // file stops the run with the file named, untouched
            storedConditions(store);
            sdf::io::File in = sdf::io::File::openReadOnly(store);
            const sdf::io::Group root = in.root();
            if (!root.hasGroup("conditions"))
            {
                continue;
            }
            const sdf::io::Group conditions = root.openGroup("conditions");
            for (const std::string& name : conditions.childNames())
            {
                if (inMain.count(name) || copied.count(name))
                {
                    continue;
                }
                if (!out)
                {
                    const bool exists = isFile(h5);
                    out.emplace
                    (
                        exists
                      ? sdf::io::AtomicFile::update(h5)
                      : sdf::io::AtomicFile::create(h5)
                    );
                    if (!exists)
                    {
                        for (const char* attr : {"content", "fineSpecies", "coarseSpecies"})
                        {
                            out->root().setAttribute(attr, root.readString(attr));
                        }
                    }
                }
                copyGroup
                (
                    conditions.openGroup(name),
                    out->root().createGroup("conditions/" + name)
                );
                copied.insert(name);
                ++moved;
            }
        }
        if (out)
        {
            out->commit();
        }
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Merging the processor stores " << stores << " into " << h5
            << " failed:" << nl << "    " << err.what() << nl
            << "    The processor stores are left as they are." << nl
            << exit(FatalError);
    }
    for (const fileName& store : stores)
    {
        Foam::rm(store);
        Foam::rm(store + ".tmp");
    }
    Info<< "Merged " << moved << " conditions of " << label(stores.size())
        << " processor stores into " << h5 << nl << endl;
    return moved;
}


//- A DEM condition finished by a worker thread, handed to the main thread
//  (the only one that calls HDF5 and writes to Info)
struct FinishedCondition
{
    label index = -1;                    // in the list of all conditions
    sdf::dem::CellRunResult result;
    std::string error;                   // the engine's message if it stopped
    double seconds = 0;
};


//- Runs the conditions conds[todo[i]] on `workers` threads at once. Each
//  worker takes the next condition from an atomic counter; the main thread
//  stores every finished condition in `store` at once (serial HDF5 is not
//  thread-safe: only this thread calls it) and prints progress with an ETA.
//  A condition's result does not depend on the number of workers (the
//  engine is deterministic per seed and thread count). If one condition
//  fails, no new ones are started, those running are finished and stored,
//  then the run stops with the first error. Returns the conditions run.
label runConditions
(
    const std::vector<ConditionSpec>& conds,
    const std::vector<label>& todo,
    const Setup& setup,
    const label workers,
    const fileName& store,
    OSstream& progress
)
{
    std::mutex mutex;
    std::condition_variable finishedOne;
    std::deque<FinishedCondition> finished;
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    label running = workers;

    auto work = [&]()
    {
        for (;;)
        {
            const std::size_t j = next++;
            if (stop || j >= todo.size())
            {
                break;
            }
            FinishedCondition f;
            f.index = todo[j];
            const auto t0 = std::chrono::steady_clock::now();
            try
            {
                f.result = sdf::dem::runCell(cellSettings(setup, conds[f.index]));
            }
            catch (const std::exception& err)
            {
                f.error = err.what();
            }
            f.seconds = std::chrono::duration<double>
                (std::chrono::steady_clock::now() - t0).count();
            {
                std::lock_guard<std::mutex> lock(mutex);
                finished.push_back(std::move(f));
            }
            finishedOne.notify_one();
        }
        {
            std::lock_guard<std::mutex> lock(mutex);
            --running;
        }
        finishedOne.notify_one();
    };

    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (label w = 0; w < workers; ++w)
    {
        pool.emplace_back(work);
    }

    label ran = 0;
    std::string firstError;
    std::unique_lock<std::mutex> lock(mutex);
    for (;;)
    {
        finishedOne.wait
        (
            lock, [&]{ return !finished.empty() || running == 0; }
        );
        if (finished.empty())
        {
            break;
        }
        FinishedCondition f(std::move(finished.front()));
        finished.pop_front();
        lock.unlock();

        const ConditionSpec& c = conds[f.index];
        const std::string where =
            "condition " + std::to_string(f.index + 1) + "/"
          + std::to_string(conds.size())
          + " (phi " + fmt(c.phi) + " x " + fmt(c.x) + " T " + fmt(c.T)
          + " seed " + std::to_string(c.seed) + ")";
        if (!f.error.empty())
        {
            stop = true;
            if (firstError.empty())
            {
                firstError =
                    "The DEM engine stopped " + where + ":\n    " + f.error;
            }
        }
        else
        {
            try
            {
                storeCondition(store, setup, c, f.result);
                ++ran;
                const double total = std::chrono::duration<double>
                    (std::chrono::steady_clock::now() - start).count();
                const double eta = total/ran*(label(todo.size()) - ran);
                const sdf::dem::CellRunResult& r = f.result;
                progress << where.c_str() << " done in " << fmt(f.seconds).c_str()
                    << " s, ETA " << fmt(eta).c_str()
                    << " s (T = " << fmt(r.temperature).c_str()
                    << ", D_" << setup.species[0].name.c_str() << " = "
                    << fmt(r.species[0].greenKubo.integral.value).c_str()
                    << " +- "
                    << fmt(r.species[0].greenKubo.integral.standardError).c_str()
                    << " m2/s"
                    << (r.species[0].greenKubo.plateauFound ? "" : ", no plateau")
                    << ")" << endl;
            }
            catch (const std::exception& err)
            {
                stop = true;
                if (firstError.empty())
                {
                    firstError =
                        "Storing " + where + " in " + std::string(store)
                      + " failed:\n    " + err.what();
                }
            }
        }
        lock.lock();
    }
    lock.unlock();
    for (std::thread& t : pool)
    {
        t.join();
    }
    if (!firstError.empty())
    {
        FatalErrorInFunction
            << firstError.c_str() << nl
            << "    Every condition finished before is stored in " << store
            << nl << exit(FatalError);
    }
    return ran;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Calibrate the transport coefficients of a binary mixture with the"
        " embedded DEM (system/calibrationDict): runs the envelope, stores"
        " each condition in constant/calibration.h5 (reruns skip stored"
        " ones), fits laws and writes constant/granularCoefficients"
    );
    argList::addBoolOption("noFit", "run and store the DEM conditions only");
    argList::addBoolOption
    (
        "dryRun",
        "check the input, print the envelope and the conditions to run,"
        " run and write nothing"
    );
    argList::addOption
    (
        "fromCase",
        "time",
        "derive the envelope (phi, x, T) from the case's fields at this time"
        " (nothing or latestTime: the latest) and calibrate the coefficients"
        " of the mechanisms granularProperties switches on"
    );

    // -fromCase takes an optional time: with none after it, the latest
    std::vector<char*> arguments(argv, argv + argc);
    static char latestTime[] = "latestTime";
    for (std::size_t i = 0; i < arguments.size(); ++i)
    {
        if
        (
            std::string(arguments[i]) == "-fromCase"
         && (i + 1 == arguments.size() || arguments[i + 1][0] == '-')
        )
        {
            arguments.insert(arguments.begin() + i + 1, latestTime);
        }
    }
    argc = int(arguments.size());
    arguments.push_back(nullptr);
    argv = arguments.data();
    argList::addNote
    (
        "Parallel: several conditions run at once on all cores (entry"
        " concurrentConditions); with -parallel under mpirun the conditions"
        " are spread over the ranks (no decomposition needed)"
    );
    // -parallel spreads DEM conditions over ranks: no mesh is decomposed,
    // so the case needs no processor directories
    argList::noCheckProcessorDirectories();

    #include "setRootCase.H"

    // The DEM engine and GSL's least squares handle IEEE infinities and
    // NaNs themselves (GSL's trust-region steps may overflow and recover);
    // OpenFOAM's floating-point trap would abort them
    sigFpe::unset();
    #include "createTime.H"

    IOdictionary properties
    (
        IOobject
        (
            "granularProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    IOdictionary dict
    (
        IOobject
        (
            "calibrationDict",
            runTime.system(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );

    std::optional<CaseEnvelope> fromCase;
    if (args.found("fromCase"))
    {
        fromCase = deriveEnvelope(runTime, properties, dict, args.get<word>("fromCase"));
        if (fromCase->coefficients.empty())
        {
            Info<< "Nothing to calibrate: constant/granularProperties switches"
                << " off both diffusivity and kineticSieving (model none)."
                << " Nothing is run or written." << nl << nl << "End" << nl
                << endl;
            return 0;
        }
    }
    const Setup setup =
        readSetup(properties, dict, fromCase ? &*fromCase : nullptr);

    std::vector<ConditionSpec> conds;
    for (const scalar phi : setup.phi)
    {
        for (const scalar x : setup.x)
        {
            for (const scalar T : setup.T)
            {
                for (const label seed : setup.replicas)
                {
                    conds.push_back({phi, x, T, seed, conditionName(phi, x, T, seed)});
                }
            }
        }
    }

    // Check every condition's DEM settings before running anything
    for (const ConditionSpec& c : conds)
    {
        sdf::dem::CellRunSettings s = setup.base;
        s.volumeFractions = {1 - c.x, c.x};
        s.solidsFraction = c.phi;
        s.simulation.targetTemperature = c.T;
        s.seed = c.seed;
        s.label = c.name;
        try
        {
            sdf::dem::validateCellRunSettings(s);
        }
        catch (const std::exception& err)
        {
            FatalIOErrorInFunction(dict)
                << "The DEM engine refuses condition " << c.name.c_str() << ":"
                << nl << "    " << err.what() << nl << exit(FatalIOError);
        }
    }

    // The case's own directories (under -parallel runTime.path() is a
    // processor directory that need not exist)
    const fileName h5(runTime.globalPath()/runTime.constant()/"calibration.h5");
    // Conditions a killed parallel run left in processor stores first
    if (Pstream::master())
    {
        mergeProcessorStores(h5);
    }
    if (Pstream::parRun())
    {
        label synchronised = 0;
        reduce(synchronised, sumOp<label>());
    }
    std::map<std::string, std::string> stored = storedConditions(h5);

    Info<< "Calibration of " << setup.species[0].name.c_str() << " (fine, d = "
        << setup.species[0].diameter << ") / " << setup.species[1].name.c_str()
        << " (coarse, d = " << setup.species[1].diameter << "): "
        << label(conds.size()) << " conditions (" << setup.phi.size()
        << " phi x " << setup.x.size() << " x x " << setup.T.size()
        << " T x " << setup.replicas.size() << " replicas), store " << h5
        << nl << endl;

    // A stored condition is reused only if run with the same DEM settings
    for (const ConditionSpec& c : conds)
    {
        const auto it = stored.find(c.name);
        if (it != stored.end() && it->second != setup.settingsKey)
        {
            FatalErrorInFunction
                << "Condition " << c.name.c_str() << " in " << h5
                << " was run with other DEM settings:" << nl
                << "    stored:  " << it->second.c_str() << nl
                << "    current: " << setup.settingsKey.c_str() << nl
                << "    Move the file away to recalibrate, or restore"
                << " the settings." << nl << exit(FatalError);
        }
    }

    if (args.found("dryRun"))
    {
        label toRun = 0;
        for (const ConditionSpec& c : conds)
        {
            if (!stored.count(c.name)) ++toRun;
        }
        Info<< "Envelope: phi " << listText(setup.phi).c_str() << ", x "
            << listText(setup.x).c_str() << ", T " << listText(setup.T).c_str()
            << ", coefficients (";
        for (const word& c : setup.coefficients)
        {
            Info<< (&c == &setup.coefficients.first() ? "" : " ") << c;
        }
        Info<< ")" << nl << "Dry run (-dryRun): " << toRun << " of "
            << label(conds.size()) << " conditions would run, "
            << label(conds.size()) - toRun << " are stored; nothing is run"
            << " or written" << nl << nl << "End" << nl << endl;
        return 0;
    }

    // Run the conditions still missing from the store. Without -parallel:
    // several at once on this machine's cores. With -parallel: spread over
    // the ranks round-robin; every rank stores its conditions at once in
    // its own store (calibration.processor<N>.h5), which the master merges
    // into calibration.h5 at the end (and at the start of any run, so that
    // nothing a killed parallel run finished is lost).
    std::vector<label> toRun;
    for (label i = 0; i < label(conds.size()); ++i)
    {
        const ConditionSpec& c = conds[i];
        if (stored.count(c.name))
        {
            Info<< "skipping condition " << i + 1 << "/" << label(conds.size())
                << " (phi " << fmt(c.phi).c_str() << " x " << fmt(c.x).c_str()
                << " T " << fmt(c.T).c_str() << " seed " << c.seed
                << ") (already in calibration.h5)" << endl;
        }
        else
        {
            toRun.push_back(i);
        }
    }
    std::vector<label> mine;
    for (std::size_t j = 0; j < toRun.size(); ++j)
    {
        if (label(j % Pstream::nProcs()) == Pstream::myProcNo())
        {
            mine.push_back(toRun[j]);
        }
    }

    const label threadsPerCell =
        setup.base.simulation.threads > 0
      ? label(setup.base.simulation.threads)
      : label(omp_get_max_threads());
    const label hardwareThreads =
        max(label(1), label(std::thread::hardware_concurrency()));
    label workers = dict.getOrDefault<label>("concurrentConditions", 0);
    if (workers < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'concurrentConditions' " << workers << " is negative:"
            << " give the number of DEM conditions to run at once, or 0 for"
            << " automatic (hardware threads / threads per cell; 1 per rank"
            << " with -parallel)" << nl << exit(FatalIOError);
    }
    if (workers == 0)
    {
        workers =
            Pstream::parRun()
          ? 1
          : max(label(1), hardwareThreads/threadsPerCell);
    }
    workers = max(label(1), min(workers, label(mine.size())));

    OSstream& progress = Pstream::parRun() ? Pout : Info();
    if (!mine.empty())
    {
        progress
            << label(mine.size()) << " conditions to run, " << workers
            << " at once (" << threadsPerCell << " threads per cell, "
            << hardwareThreads << " hardware threads"
            << (
                   Pstream::parRun()
                 ? ", rank " + std::to_string(Pstream::myProcNo()) + " of "
                 + std::to_string(Pstream::nProcs())
                 : std::string()
               ).c_str()
            << ")" << endl;
    }
    const fileName store =
        Pstream::parRun() ? processorStore(h5, Pstream::myProcNo()) : h5;
    const auto start = std::chrono::steady_clock::now();
    label ran = runConditions(conds, mine, setup, workers, store, progress);

    if (Pstream::parRun())
    {
        // Every rank has stored its conditions once all arrive here
        reduce(ran, sumOp<label>());
        if (Pstream::master())
        {
            mergeProcessorStores(h5);
        }
    }
    Info<< nl << "DEM: " << ran << " conditions run, "
        << label(conds.size()) - ran << " taken from " << h5 << ", "
        << fmt(std::chrono::duration<double>
           (std::chrono::steady_clock::now() - start).count()).c_str()
        << " s" << nl << endl;

    // Only the master fits and writes
    if (!Pstream::master())
    {
        return 0;
    }

    if (args.found("noFit"))
    {
        Info<< "End (no fit: -noFit)" << nl << endl;
        return 0;
    }

    // Fits
    const std::vector<StoredResult> results = readResults(h5, setup, conds);
    std::vector<sdf::fit::CalibratedCoefficient> calibrated;
    std::optional<sdf::fit::FitResult> bestD, bestEta;

    for (const word& coeff : setup.coefficients)
    {
        std::vector<sdf::fit::Observation> rows;
        bool allPositive = true;
        for (const StoredResult& r : results)
        {
            const bool isD = coeff == "D";
            if (!isD && !r.hasEta)
            {
                FatalErrorInFunction
                    << "Condition " << r.cond.name.c_str() << " in " << h5
                    << " has no kinetic sieving coefficient eta" << nl
                    << exit(FatalError);
            }
            sdf::fit::Observation o;
            o.condition.phi = r.cond.phi;
            o.condition.x = r.cond.x;
            o.condition.T = r.T;
            o.condition.d = setup.species[isD ? 0 : 1].diameter;
            o.value = isD ? r.D : r.eta;
            o.sigma = isD ? r.DError : r.etaError;
            allPositive = allPositive && o.value > 0;
            rows.push_back(o);
        }

        sdf::fit::FitOptions options;
        options.maxIterations = std::size_t(setup.fitMaxIterations);
        wordList laws;
        if (coeff == "D")
        {
            laws = setup.laws;
        }
        else
        {
            laws = setup.etaLaws;
            if (!allPositive)
            {
                options.space = sdf::fit::FitSpace::linear;
            }
        }

        Info<< "Fit of " << coeff << " ("
            << (coeff == "D"
                ? "diffusivity of " + setup.species[0].name
                : "kinetic sieving coefficient of " + setup.species[1].name).c_str()
            << ") to " << label(rows.size()) << " rows, "
            << (options.space == sdf::fit::FitSpace::linear ? "linear" : "log")
            << " space:" << nl;

        std::vector<sdf::fit::FitResult> fits;
        for (const word& lawName : laws)
        {
            const sdf::fit::ConstitutiveLaw law =
                coeff == "D"
              ? lawFromName(lawName)
              : lawName == "sievingCompositionPowerLaw"
              ? sdf::fit::ConstitutiveLaw
                (
                    sdf::fit::SievingCompositionPowerLaw
                    (
                        int(setup.etaDiameterPower)
                    )
                )
              : sdf::fit::ConstitutiveLaw
                (
                    sdf::fit::SievingPowerLaw(int(setup.etaDiameterPower))
                );
            try
            {
                fits.push_back(sdf::fit::fitLaw(law, rows, options));
            }
            catch (const std::exception& err)
            {
                FatalErrorInFunction
                    << "Fit of law '" << lawName << "' to " << coeff
                    << " refused its data:" << nl << "    " << err.what() << nl
                    << "    constant/granularCoefficients is not written."
                    << nl << exit(FatalError);
            }
            reportFit(fits.back());
        }

        try
        {
            sdf::fit::ModelSelection sel = sdf::fit::selectModel(fits);
            Info<< "  model selection by AIC for " << coeff << ":" << nl;
            for (const auto& rk : sel.ranking)
            {
                Info<< "    " << rk.law.c_str() << ": AIC = " << fmt(rk.criterion).c_str()
                    << ", delta = " << fmt(rk.delta).c_str()
                    << ", weight = " << fmt(rk.weight).c_str() << nl;
            }
            for (const auto& f : sel.failed)
            {
                Warning
                    << "Law '" << f.first.c_str() << "' for " << coeff
                    << " did not converge and takes no part: "
                    << f.second.c_str() << endl;
            }
            const sdf::fit::FitResult& best = fits[sel.best().index];
            Info<< "  chosen for " << coeff << ": " << sel.best().law.c_str()
                << nl << endl;
            if (coeff == "D") bestD = best; else bestEta = best;
            calibrated.push_back({coeff, best, sel});
        }
        catch (const std::exception& err)
        {
            FatalErrorInFunction
                << "No law for " << coeff << " could be fitted:" << nl
                << "    " << err.what() << nl
                << "    constant/granularCoefficients is not written." << nl
                << exit(FatalError);
        }
    }

    std::ostringstream text;
    try
    {
        sdf::fit::writeOpenFOAMDictionary(text, calibrated);
    }
    catch (const std::exception& err)
    {
        FatalErrorInFunction
            << "Writing the coefficients failed: " << err.what() << nl
            << "    constant/granularCoefficients is not written." << nl
            << exit(FatalError);
    }
    const fileName coeffFile(runTime.globalPath()/runTime.constant()/"granularCoefficients");
    writeAtomically(coeffFile, text.str());
    Info<< "Written " << coeffFile << nl;

    if (setup.plot)
    {
        const fileName dir(runTime.globalPath()/"postProcessing"/"calibration");
        plotCoefficient(dir, results, setup, bestD ? &*bestD : nullptr, true);
        bool haveEta = true;
        for (const StoredResult& r : results) haveEta = haveEta && r.hasEta;
        if (haveEta)
        {
            plotCoefficient
            (
                dir, results, setup, bestEta ? &*bestEta : nullptr, false
            );
        }
    }

    Info<< "End" << nl << endl;
    return 0;
}


// ************************************************************************* //

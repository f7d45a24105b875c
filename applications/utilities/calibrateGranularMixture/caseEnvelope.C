/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "caseEnvelope.H"
#include "numberText.H"
#include "calibrationSettings.H"
#include "demDictionary.H"
#include "granularMixture.H"
#include "IFstream.H"
#include "ITstream.H"
#include "OSspecific.H"

#include <algorithm>
#include <initializer_list>
#include <cstdlib>
#include <utility>
#include <vector>

using namespace Foam;
using numberText::fmt;
using numberText::listText;

namespace
{

//- Limits of the envelope a case's fields are clipped to: the DEM's valid
//  range with a margin (a periodic cell near random close packing 0.64
//  jams; a cell of one species only has no mixture to calibrate)
const scalar fromCasePhiMax = 0.6;
const scalar fromCaseXMin = 0.05;
const scalar fromCaseXMax = 0.95;


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


//- The number of cells of fields read from dir: that of the nonuniform ones (1 when
//  all are uniform); FatalError when they differ
label cellCount
(
    const fileName& dir,
    std::initializer_list<const CellValues*> fields
)
{
    label n = -1;
    for (const CellValues* f : fields)
    {
        if (!f->uniform)
        {
            if (n >= 0 && f->values.size() != n)
            {
                FatalErrorInFunction
                    << "-fromCase: the fields in " << dir << " have"
                    << " different numbers of cells" << nl
                    << exit(FatalError);
            }
            n = f->values.size();
        }
    }
    return n < 0 ? 1 : n;
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

//- The pressure scale of a case for its rheology cells: the median of the
//  bulk's pressure p (written by bulkFlow muI) over the cells that hold
//  material (phi >= phiMin) and shear (gammaDot >= minRatio times its
//  largest, when the case wrote gammaDot: the flowing zones, where mu(I)
//  decides the flow). The median, not the largest: mu(I) of stiff grains
//  does not depend on p (the cells report k_n/(p d)). A median over cells,
//  not volume (the fields are read without the mesh): on a graded mesh it
//  leans to the finer cells.
scalar rheologyPressureOfCase
(
    const std::vector<fileName>& sources,
    const word& time,
    const Time& runTime,
    const calibrationSettings& settings,
    const scalar phiMin,
    const scalar minRatio
)
{
    const word& fine = settings.fine().name;
    const word& coarse = settings.coarse().name;
    if (!isFile(sources[0]/"p"))
    {
        if (settings.rheologyPressureGiven())
        {
            Info<< "-fromCase rheology: no field p at time " << time
                << " (the bulk's pressure, written by bulkFlow muI): the"
                << " entry rheology/pressure "
                << settings.rheology().pressure << " Pa is used" << nl;
            return 0;
        }
        FatalErrorInFunction
            << "-fromCase rheology: the field p is missing: no file "
            << sources[0]/"p" << nl
            << "    The pressure of the rheology cells is derived from the"
            << " bulk's pressure p, which bulkFlow muI writes: run the case"
            << " with 'bulkFlow { model muI; }' to time " << time
            << ", or give 'pressure' [Pa] in the rheology entry of "
            << settings.dict().name() << nl << exit(FatalError);
    }
    const bool haveShear = isFile(sources[0]/"gammaDot");

    // (p, gammaDot) of the cells holding material, over every source
    std::vector<std::pair<scalar, scalar>> cells;
    for (const fileName& dir : sources)
    {
        const CellValues nFine(readCellValues(dir/("n." + fine), runTime));
        const CellValues nCoarse(readCellValues(dir/("n." + coarse), runTime));
        const CellValues p(readCellValues(dir/"p", runTime));
        const CellValues shear
        (
            haveShear ? readCellValues(dir/"gammaDot", runTime) : CellValues()
        );
        const label n = cellCount(dir, {&nFine, &nCoarse, &p, &shear});
        for (label celli = 0; celli < n; ++celli)
        {
            if (nFine[celli] + nCoarse[celli] >= phiMin)
            {
                cells.push_back({p[celli], haveShear ? shear[celli] : 1});
            }
        }
    }
    scalar shearMax = 0;
    for (const auto& c : cells)
    {
        shearMax = max(shearMax, c.second);
    }
    std::vector<scalar> pressures;
    for (const auto& c : cells)
    {
        if (shearMax > 0 && c.second >= minRatio*shearMax)
        {
            pressures.push_back(c.first);
        }
    }
    if (pressures.empty())
    {
        FatalErrorInFunction
            << "-fromCase rheology: no cell at time " << time << " "
            << (
                   cells.empty()
                 ? "holds material (n." + fine + " + n." + coarse + " >= phiMin)"
                 : std::string("shears (gammaDot zero in every cell holding material)")
               ).c_str()
            << ": give 'pressure' [Pa] in the rheology entry of "
            << settings.dict().name() << nl << exit(FatalError);
    }
    std::sort(pressures.begin(), pressures.end());
    // rounded as the envelope's values are, so that a case rerun a little
    // differently reuses the stored rheology cells (their key holds p)
    const scalar median = roundSignificant(pressures[pressures.size()/2]);
    if (!(median > 0))
    {
        FatalErrorInFunction
            << "-fromCase rheology: the median pressure " << median
            << " Pa (range [" << fmt(pressures.front()).c_str() << ", "
            << fmt(pressures.back()).c_str() << "] Pa) of the flowing cells"
            << " at time " << time << " is not > 0"
            << " (a case without weight on its bulk?): give 'pressure' [Pa]"
            << " in the rheology entry of " << settings.dict().name() << nl
            << exit(FatalError);
    }
    Info<< "-fromCase rheology: p over " << label(pressures.size())
        << " cells holding material"
        << (
               haveShear
             ? " with gammaDot >= " + fmt(minRatio) + " x its largest"
             : std::string(" (no field gammaDot: every one)")
           ).c_str()
        << ": [" << fmt(pressures.front()).c_str() << ", "
        << fmt(pressures.back()).c_str() << "] Pa, median "
        << fmt(median).c_str() << " Pa -> the rheology cells' pressure";
    if (settings.rheologyPressureGiven())
    {
        Info<< " (the entry rheology/pressure "
            << settings.rheology().pressure << " Pa is overridden)";
    }
    Info<< nl;
    return median;
}

//- The loads sigma_N of the segregation cells: segregationPoints values of
//  p* log-spaced over the cells holding material, from minPressureNumber up
scalarList segregationLoadsOfCase
(
    const std::vector<fileName>& sources,
    const word& time,
    const Time& runTime,
    const calibrationSettings& settings,
    const scalar phiMin,
    const dictionary& opts
)
{
    const label points = opts.getOrDefault<label>("segregationPoints", 4);
    const scalar minPStar = opts.getOrDefault<scalar>("minPressureNumber", 2);
    if (points < 3 || !(minPStar > 0))
    {
        FatalIOErrorInFunction(opts)
            << "Entries 'fromCase/segregationPoints' " << points << " (at least"
            << " 3: the pressure law has two parameters) and 'fromCase/minPressureNumber' "
            << minPStar << " (> 0)" << nl << exit(FatalIOError);
    }
    // p* of the segregation law as the case evaluated it, or the bulk's p
    const bool havePStar = isFile(sources[0]/"pStar");
    const bool haveP = isFile(sources[0]/"p");
    if (!havePStar && !haveP)
    {
        FatalErrorInFunction
            << "-fromCase: no field pStar (written by percolation calibrated)"
            << " or p (written by bulkFlow muI) at time " << time << " of the"
            << " case: the segregation cells' loads cannot be derived; run the"
            << " case with percolation calibrated (e.g. on a shipped"
            << " calibration) or give segregationVelocity/normalStress [Pa] in "
            << settings.dict().name() << nl << exit(FatalError);
    }
    const calibrationSettings::segregationEnvelope& e = settings.segregation();
    const sdf::dem::CellRunSettings cell =
        settings.segregationCellSettings(1, 0, "").cell;
    const scalar pStarUnit =
        sdf::dem::solidsDensity(cell)*e.gravity*sdf::dem::meanDiameter(cell);
    const word& fine = settings.fine().name;
    const word& coarse = settings.coarse().name;
    scalar lo = GREAT, hi = -GREAT;
    label material = 0;
    for (const fileName& dir : sources)
    {
        const CellValues v
        (
            readCellValues(dir/(havePStar ? "pStar" : "p"), runTime)
        );
        const CellValues nFine(readCellValues(dir/("n." + fine), runTime));
        const CellValues nCoarse(readCellValues(dir/("n." + coarse), runTime));
        const label cells = cellCount(dir, {&v, &nFine, &nCoarse});
        for (label celli = 0; celli < cells; ++celli)
        {
            if (nFine[celli] + nCoarse[celli] >= phiMin)
            {
                const scalar pStar = havePStar ? v[celli] : v[celli]/pStarUnit;
                lo = min(lo, pStar);
                hi = max(hi, pStar);
                ++material;
            }
        }
    }
    if (material == 0)
    {
        FatalErrorInFunction
            << "-fromCase: no cell holds material (n." << fine << " + n."
            << coarse << " >= phiMin " << phiMin << ") at time " << time
            << ": no pressures to calibrate the segregation at; give"
            << " segregationVelocity/normalStress" << nl << exit(FatalError);
    }
    // the cell's interior sits below its top wall: its p* is the load's and
    // a few more; at the free surface p* -> 0, where the law is clamped
    const scalar cLo = max(lo, minPStar);
    const scalar cHi = max(hi, 2*cLo);
    const scalarList pStars(envelopeValues(cLo, cHi, points, true));
    scalarList loads(pStars.size());
    forAll(pStars, i)
    {
        loads[i] = pStars[i]*pStarUnit;
    }
    Info<< "-fromCase segregation: p* of the " << material << " cells holding"
        << " material (field " << (havePStar ? "pStar" : "p/(rho_s g dMean)")
        << ") [" << fmt(lo).c_str() << ", " << fmt(hi).c_str() << "], from"
        << " minPressureNumber " << fmt(minPStar).c_str() << ": p* "
        << listText(pStars).c_str() << " -> sigma_N " << listText(loads).c_str()
        << " Pa (rho_s g dMean " << fmt(pStarUnit).c_str() << " Pa)" << nl;
    return loads;
}


} // End anonymous namespace


//- The envelope of a case at a time: the ranges of phi, x and T over the
//  cells holding material (phi >= phiMin), clipped to the DEM's valid range
//  and turned into fromCase/points values per axis; the coefficients of the
//  mechanisms the case switches on. An empty coefficient list: nothing to
//  calibrate.
Foam::caseEnvelope Foam::deriveEnvelope
(
    const Time& runTime,
    const dictionary& properties,
    const calibrationSettings& settings,
    const word& timeArg
)
{
    const dictionary& dict = settings.dict();
    caseEnvelope env;
    const fileName caseDir(runTime.globalPath());

    // Coefficients of the mechanisms the case switches on (breakage: only
    // when its selection rate is calibrated)
    const bool diffusion = mechanismOn(properties, "diffusivity");
    const bool sieving = mechanismOn(properties, "kineticSieving");
    // Breakage needs DEM only with the calibrated selection rate (the other
    // models take their rates from their own coefficients); a case without
    // a breakage block has none
    const word breakageModel =
        properties.isDict("breakage")
      ? properties.subDict("breakage").get<word>("model")
      : word::null;
    if (diffusion) env.coefficients.append("D");
    if (sieving) env.coefficients.append("eta");
    if (breakageModel == "calibrated") env.coefficients.append("breakage");
    Info<< "-fromCase: diffusivity "
        << properties.subDict("diffusivity").get<word>("model")
        << ", kineticSieving "
        << properties.subDict("kineticSieving").get<word>("model");
    if (!breakageModel.empty())
    {
        Info<< ", breakage " << breakageModel;
    }
    Info<< " in constant/granularProperties -> coefficients (";
    for (const word& c : env.coefficients)
    {
        Info<< (&c == &env.coefficients.first() ? "" : " ") << c;
    }
    Info<< ")" << nl;
    const bool rheology = settings.calibratesRheology();
    const bool segregation =
        settings.calibratesSegregation()
     && !settings.segregation().normalStressGiven;
    if (env.coefficients.empty() && !rheology && !segregation)
    {
        return env;
    }

    // Options
    const dictionary& opts = dict.subOrEmptyDict("fromCase");
    // The ratio of the other drive is an unknown key here (it would be
    // ignored); the rheology's pressure is taken where the bulk shears
    wordList optionKeys
    ({
        "points", settings.sheared() ? "minGammaDotRatio" : "minTRatio"
    });
    if (rheology && !settings.sheared())
    {
        optionKeys.append("minGammaDotRatio");
    }
    if (segregation)
    {
        optionKeys.append("segregationPoints");
        optionKeys.append("minPressureNumber");
    }
    modelCoeffs::checkKeys(opts, optionKeys);
    const label points = opts.getOrDefault<label>("points", 3);
    if (points < 1)
    {
        FatalIOErrorInFunction(opts)
            << "Entry 'fromCase/points' " << points << ": give the number of"
            << " values per envelope axis, >= 1" << nl << exit(FatalIOError);
    }
    // The drive: T of driven cells, or gammaDot of sheared ones (its field
    // written by the solver's writeFields); both span decades in a silo
    const word rate(settings.rateName());
    const word ratioKey(settings.sheared() ? "minGammaDotRatio" : "minTRatio");
    const string rateMeaning
    (
        settings.sheared()
      ? "shear rate of the bulk flow [1/s]"
      : "granular temperature [m2/s2], sum of 3 components"
    );
    const scalar minRatio = opts.getOrDefault<scalar>(ratioKey, 1e-3);
    if (!(minRatio > 0 && minRatio <= 1))
    {
        FatalIOErrorInFunction(opts)
            << "Entry 'fromCase/" << ratioKey << "' " << minRatio
            << " is outside (0, 1]: the smallest " << rate << " calibrated,"
            << " as a fraction of the largest " << rate << " of the case"
            << nl << exit(FatalIOError);
    }

    // Species: the fine is the smaller diameter
    const word& fine = settings.fine().name;
    const word& coarse = settings.coarse().name;
    const scalar phiMin = granularMixture::readPhiMin(properties);

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

    if (rheology)
    {
        // the cells whose pressure sets the rheology's: those that shear
        const scalar shearRatio =
            settings.sheared()
          ? minRatio
          : opts.getOrDefault<scalar>("minGammaDotRatio", 1e-3);
        if (!(shearRatio > 0 && shearRatio <= 1))
        {
            FatalIOErrorInFunction(opts)
                << "Entry 'fromCase/minGammaDotRatio' " << shearRatio
                << " is outside (0, 1]: the cells whose pressure sets the"
                << " rheology's, by their shear rate as a fraction of the"
                << " largest" << nl << exit(FatalIOError);
        }
        env.rheologyPressure = rheologyPressureOfCase
        (
            sources, time, runTime, settings, phiMin, shearRatio
        );
    }
    if (segregation)
    {
        env.segregationNormalStress = segregationLoadsOfCase
        (
            sources, time, runTime, settings, phiMin, opts
        );
    }
    if (env.coefficients.empty())
    {
        Info<< endl;
        return env;
    }

    const bool haveRate = isFile(sources[0]/rate);
    if (!haveRate && !dict.found(rate))
    {
        FatalErrorInFunction
            << "-fromCase: the field " << rate << " is missing ("
            << rateMeaning.c_str() << "): no file " << sources[0]/rate << nl
            << "    The solver writes " << rate << " when"
            << " constant/granularProperties has 'writeFields (" << rate
            << " ...);'"
            << (settings.sheared() ? "" : " (and a granularTemperature model)")
            << ": add " << rate << " to writeFields and rerun the solver to"
            << " time " << time << ", or give the values as '" << rate
            << " (..);' in system/calibrationDict" << nl << exit(FatalError);
    }

    scalar phiLo = GREAT, phiHi = -GREAT;
    scalar xLo = GREAT, xHi = -GREAT;
    scalar rateLo = GREAT, rateHi = -GREAT;
    label cells = 0, material = 0;
    for (const fileName& dir : sources)
    {
        const CellValues nFine(readCellValues(dir/("n." + fine), runTime));
        const CellValues nCoarse(readCellValues(dir/("n." + coarse), runTime));
        const CellValues rateValues
        (
            haveRate ? readCellValues(dir/rate, runTime) : CellValues()
        );
        const label n = cellCount(dir, {&nFine, &nCoarse, &rateValues});
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
            if (haveRate && rateValues[celli] > 0)
            {
                rateLo = min(rateLo, rateValues[celli]);
                rateHi = max(rateHi, rateValues[celli]);
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

    calibrationSettings::envelopeAxes& axes = env.axes;
    const scalar phiCLo = min(phiLo, fromCasePhiMax);
    const scalar phiCHi = min(phiHi, fromCasePhiMax);
    axes.phi = envelopeValues(phiCLo, phiCHi, points, false);
    report("phi", phiLo, phiHi, phiCLo, phiCHi, axes.phi);

    const scalar xCLo = min(max(xLo, fromCaseXMin), fromCaseXMax);
    const scalar xCHi = min(max(xHi, fromCaseXMin), fromCaseXMax);
    axes.x = envelopeValues(xCLo, xCHi, points, false);
    report("x", xLo, xHi, xCLo, xCHi, axes.x);

    scalarList& rates = settings.sheared() ? axes.gammaDot : axes.T;
    if (haveRate)
    {
        if (!(rateHi > 0))
        {
            FatalErrorInFunction
                << "-fromCase: " << rate << " is zero in every cell holding"
                << " material at time " << time << ": a static case, nothing"
                << " to calibrate at; give '" << rate << " (..);' in"
                << " system/calibrationDict" << nl << exit(FatalError);
        }
        // The drive spans many decades in a silo (nearly static zones):
        // calibrate above minRatio times its largest value; the calibrated
        // models' outsideEnvelope decides below it
        const scalar rateCLo = max(rateLo, minRatio*rateHi);
        rates = envelopeValues(rateCLo, rateHi, points, true);
        report(rate.c_str(), rateLo, rateHi, rateCLo, rateHi, rates);
    }
    else
    {
        settings.checkRateAxis(dict);
        rates = calibrationSettings::readEnvelopeList
        (
            dict, rate, 0, 1e301, rateMeaning
        );
        Info<< "-fromCase " << rate << ": no field " << rate << " at time "
            << time << ", the " << rate << " list of system/calibrationDict"
            << " is used: " << listText(rates).c_str() << nl;
    }
    for (const word& key : wordList({"phi", "x", rate, "coefficients"}))
    {
        if (dict.found(key) && !(key == rate && !haveRate))
        {
            Info<< "-fromCase: entry '" << key.c_str() << "' of "
                << dict.name() << " is overridden by the case"
                << (
                       key == "coefficients" && settings.calibratesRheology()
                     ? " (its rheology is kept: the rheology entry's cells)"
                     : ""
                   )
                << (
                       key == "coefficients" && settings.calibratesSegregation()
                     ? " (its segregationVelocity is kept: the"
                       " segregationVelocity entry's cells)"
                     : ""
                   )
                << nl;
        }
    }
    Info<< endl;
    return env;
}


// ************************************************************************* //

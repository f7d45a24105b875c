/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "calibrationSettings.H"
#include "demDictionary.H"
#include "numberText.H"
#include "store/Store.hpp"

#include <cmath>
#include <cstdio>
#include <set>

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::wordList Foam::calibrationSettings::validCoefficients
({
    "D", "eta", "breakage", "rheology", "segregationVelocity"
});

const Foam::wordList Foam::calibrationSettings::validDLaws
({
    "powerLaw", "kineticTheoryGroups"
});

const Foam::wordList Foam::calibrationSettings::validEtaLaws
({
    "sievingCompositionPowerLaw", "sievingPowerLaw"
});

const Foam::wordList
Foam::calibrationSettings::validCollisionFrequencyLaws
({
    "collisionFrequencyGroups"
});

const Foam::wordList Foam::calibrationSettings::validImpactEnergyLaws
({
    "impactEnergyGroups"
});


namespace
{

const Foam::wordList validEntries
({
    "phi", "x", "T", "gammaDot", "replicas", "coefficients", "laws", "etaLaws",
    "collisionFrequencyLaws", "impactEnergyLaws",
    "etaDiameterPower", "fitMaxIterations",
    "particles", "mode", "plot", "concurrentConditions", "fromCase",
    "equilibrationStrain", "maxEquilibrationStrain", "samplingStrain",
    "finiteSize", "sievingAttribution", "diffusivityEstimate", "rheology",
    "segregationVelocity"
});


using Foam::numberText::fmt;


//- Candidate laws of one coefficient: entry `key` (default: all valid ones),
//  not empty, every name known
Foam::wordList readLawList
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::wordList& valid,
    const Foam::word& coefficient
)
{
    using namespace Foam;
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

//- The run lengths in strain of sheared cells, checked: samplingStrain > 0,
//  equilibrationStrain >= 0, maxEquilibrationStrain >= equilibrationStrain,
//  all finite (the transport cells' and the rheology cells')
void checkStrains
(
    const Foam::dictionary& dict,
    const Foam::scalar sampling,
    const Foam::scalar equilibration,
    const Foam::scalar maxEquilibration
)
{
    using namespace Foam;
    if
    (
        !(sampling > 0) || !(equilibration >= 0)
     || !(maxEquilibration >= equilibration)
     || !std::isfinite(sampling)
     || !std::isfinite(maxEquilibration)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Strains: samplingStrain " << sampling << " must be"
            << " > 0, equilibrationStrain " << equilibration
            << " >= 0 and maxEquilibrationStrain " << maxEquilibration
            << " >= equilibrationStrain (all finite)" << nl
            << exit(FatalIOError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::FixedList<Foam::granularSpecies, 2>
Foam::calibrationSettings::fineAndCoarse
(
    const List<granularSpecies>& species,
    const dictionary& speciesContext
)
{
    if (species.size() != 2)
    {
        wordList names(species.size());
        forAll(species, i)
        {
            names[i] = species[i].name;
        }
        FatalIOErrorInFunction(speciesContext)
            << "calibrateGranularMixture calibrates binary mixtures: "
            << speciesContext.name() << " declares " << species.size()
            << " species " << names << ", need 2" << nl << exit(FatalIOError);
    }
    FixedList<granularSpecies, 2> pair({species[0], species[1]});
    if (pair[1].d < pair[0].d)
    {
        std::swap(pair[0], pair[1]);
    }
    if (!(pair[1].d > pair[0].d))
    {
        FatalIOErrorInFunction(speciesContext)
            << "The two species " << pair[0].name << " and " << pair[1].name
            << " have the same diameter 'd " << pair[0].d << "' in 'species'"
            << " of " << speciesContext.name() << ": no fine and coarse"
            << nl << exit(FatalIOError);
    }
    return pair;
}


Foam::scalarList Foam::calibrationSettings::readEnvelopeList
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


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::calibrationSettings::calibrationSettings
(
    const dictionary& calibrationDict,
    const granularSpecies& fine,
    const granularSpecies& coarse,
    const bool rheologyPressureFromCase
)
:
    dict_(calibrationDict),
    fine_(fine),
    coarse_(coarse),
    etaDiameterPower_(1),
    fitMaxIterations_(2000),
    plot_(true),
    concurrentConditions_(0),
    transportRunControls_(true),
    equilibrationStrain_(0),
    maxEquilibrationStrain_(0),
    samplingStrain_(0)
{
    const dictionary& dict = dict_;
    wordList valid(validEntries);
    valid.append(demDictionary::runControlEntries());
    modelCoeffs::checkKeys(dict, valid);

    replicas_ = dict.getOrDefault<labelList>("replicas", labelList({1}));
    if (replicas_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'replicas' (DEM seeds) is empty" << nl
            << exit(FatalIOError);
    }
    {
        std::set<label> seen;
        for (const label r : replicas_)
        {
            if (r < 0 || !seen.insert(r).second)
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'replicas': seed " << r
                    << " is negative or appears twice" << nl
                    << exit(FatalIOError);
            }
        }
    }

    coefficients_ =
        dict.getOrDefault<wordList>("coefficients", wordList({"D"}));
    if (coefficients_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'coefficients' is empty; valid names: "
            << validCoefficients << nl << exit(FatalIOError);
    }
    for (const word& c : coefficients_)
    {
        if (!validCoefficients.found(c))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown coefficient '" << c << "' in entry 'coefficients'"
                << nl << "    valid names: " << validCoefficients
                << " (D: diffusivity of the fines, eta: kinetic sieving"
                << " coefficient of the coarse, breakage: collision frequency"
                << " and mean impact energy of both species, rheology: mu(I)"
                << " and phi(I) of the bulk, the entry 'rheology';"
                << " segregationVelocity: the percolation length S of the"
                << " coarse in sheared cells under gravity, the entry"
                << " 'segregationVelocity')" << nl
                << exit(FatalIOError);
        }
    }
    if (calibratesRheology())
    {
        readRheology(dict, rheologyPressureFromCase);
    }
    else if (dict.found("rheology"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'rheology' given, but 'coefficients' " << coefficients_
            << " does not hold rheology: add it to calibrate mu(I) and"
            << " phi(I), or remove the entry" << nl << exit(FatalIOError);
    }
    if (calibratesSegregation())
    {
        readSegregation(dict, rheologyPressureFromCase);
    }
    else if (dict.found("segregationVelocity"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'segregationVelocity' given, but 'coefficients' "
            << coefficients_ << " does not hold segregationVelocity: add it to"
            << " calibrate the segregation velocity, or remove the entry" << nl
            << exit(FatalIOError);
    }
    laws_ = readLawList(dict, "laws", validDLaws, "D");
    etaLaws_ = readLawList(dict, "etaLaws", validEtaLaws, "eta");
    collisionFrequencyLaws_ = readLawList
    (
        dict, "collisionFrequencyLaws", validCollisionFrequencyLaws,
        "omega"
    );
    impactEnergyLaws_ = readLawList
    (
        dict, "impactEnergyLaws", validImpactEnergyLaws,
        "Wmean"
    );
    etaDiameterPower_ = dict.getOrDefault<label>("etaDiameterPower", 1);
    sievingAttribution_ =
        dict.getOrDefault<word>("sievingAttribution", "seed");
    if (sievingAttribution_ != "seed" && sievingAttribution_ != "crossTerms")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'sievingAttribution' " << sievingAttribution_
            << ": valid: seed (the seed's eqs 8-13, the stress"
            << " autocorrelation's cross terms dropped), crossTerms (kept,"
            << " split by the species' shares; docs/user/calibration.md)"
            << nl << exit(FatalIOError);
    }
    diffusivityEstimate_ =
        dict.getOrDefault<word>("diffusivityEstimate", "greenKubo");
    if
    (
        diffusivityEstimate_ != "greenKubo"
     && diffusivityEstimate_ != "meanSquareDisplacement"
    )
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'diffusivityEstimate' " << diffusivityEstimate_
            << ": valid: greenKubo (the VACF's plateau), meanSquareDisplacement"
            << " (the Einstein fit's slope over the MSD's later lags; both are"
            << " measured in every cell, docs/user/calibration.md)"
            << nl << exit(FatalIOError);
    }
    fitMaxIterations_ = dict.getOrDefault<label>("fitMaxIterations", 2000);
    if (fitMaxIterations_ < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'fitMaxIterations' must be at least 1, not "
            << fitMaxIterations_ << nl << exit(FatalIOError);
    }
    plot_ = dict.getOrDefault<bool>("plot", true);
    concurrentConditions_ =
        dict.getOrDefault<label>("concurrentConditions", 0);
    if (concurrentConditions_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'concurrentConditions' " << concurrentConditions_
            << " is negative: give the number of DEM conditions to run at"
            << " once, or 0 for automatic (hardware threads / threads per"
            << " cell; 1 per rank with -parallel)" << nl << exit(FatalIOError);
    }

    // DEM settings
    sdf::dem::CellRunSettings& b = base_;
    b.species =
    {
        {fine_.name, fine_.d, fine_.rho},
        {coarse_.name, coarse_.d, coarse_.rho}
    };
    b.particles = dict.getOrDefault<label>("particles", 1000);
    readFiniteSize(dict);
    if (!finiteSizeParticles_.empty())
    {
        // The largest cell is the one whose other results (eta, collisions)
        // are used; its settings are the base
        b.particles = finiteSizeParticles_.last();
    }
    const word mode(dict.getOrDefault<word>("mode", "thermostatted"));
    if (mode != "thermostatted" && mode != "stochastic" && mode != "leesEdwards")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'mode' " << mode << ": valid: thermostatted (velocity"
            << " rescaling), stochastic (random kicks per particle), both"
            << " homogeneous cells at the envelope's temperatures T;"
            << " leesEdwards (simple shear at the envelope's shear rates"
            << " gammaDot, T measured)" << nl << exit(FatalIOError);
    }
    b.simulation.mode = sdf::dem::cellModeFromName(mode);
    checkRateAxis(dict);
    readStrains(dict);
    const bool rheologyOnly =
        (calibratesRheology() || calibratesSegregation())
     && transportCoefficients().empty();
    transportRunControls_ = !(rheologyOnly && !dict.found("samplingTime"));
    if (samplingStrain_ > 0 || !transportRunControls_)
    {
        // The run controls require samplingTime; with samplingStrain (and
        // no time entries, readStrains) it is set per condition
        // (conditionSettings), and the rheology cells take theirs from
        // rheology/samplingStrain: this value is never run
        dictionary runControls(dict);
        runControls.add
        (
            "samplingTime", samplingStrain_ > 0 ? samplingStrain_ : scalar(1)
        );
        demDictionary::readRunControls(runControls, b);
    }
    else
    {
        demDictionary::readRunControls(dict, b);
    }
    b.progressEvery = 0;

    contactModel_ =
        dict.subOrEmptyDict("contact")
            .getOrDefault<word>("model", "linearSpringDashpot");
    settingsKey_ = settingsKey(b.particles);
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::calibrationSettings::readFiniteSize(const dictionary& dict)
{
    if (!dict.found("finiteSize"))
    {
        return;
    }
    const dictionary& fs = dict.subDict("finiteSize");
    modelCoeffs::checkKeys(fs, wordList({"particles"}));
    if (dict.found("particles"))
    {
        FatalIOErrorInFunction(dict)
            << "Entries 'particles' and 'finiteSize' both given: with"
            << " finiteSize every condition runs at each of"
            << " finiteSize/particles; give the cell sizes there only"
            << nl << exit(FatalIOError);
    }
    finiteSizeParticles_ = fs.get<labelList>("particles");
    if (finiteSizeParticles_.size() < 2)
    {
        FatalIOErrorInFunction(fs)
            << "Entry 'finiteSize/particles' " << finiteSizeParticles_
            << ": give at least two cell sizes (numbers of particles) to"
            << " extrapolate D to the infinite cell" << nl
            << exit(FatalIOError);
    }
    for (label i = 0; i < finiteSizeParticles_.size(); ++i)
    {
        if
        (
            finiteSizeParticles_[i] < 2
         || (i > 0 && finiteSizeParticles_[i] <= finiteSizeParticles_[i - 1])
        )
        {
            FatalIOErrorInFunction(fs)
                << "Entry 'finiteSize/particles' " << finiteSizeParticles_
                << ": give distinct cell sizes (>= 2 particles) from the"
                << " smallest to the largest" << nl << exit(FatalIOError);
        }
    }
}


void Foam::calibrationSettings::readRheology
(
    const dictionary& dict,
    const bool pressureOptional
)
{
    if (!dict.isDict("rheology"))
    {
        FatalIOErrorInFunction(dict)
            << "'coefficients' holds rheology but the sub-dictionary"
            << " 'rheology' is missing; give at least" << nl
            << "    rheology { inertialNumber (0.003 0.01 0.03 0.1 0.3);"
            << " pressure 1000; }" << nl
            << "    (the inertial numbers of the cells, each in (0, 1], and the"
            << " pressure [Pa] they are sheared at)" << nl << exit(FatalIOError);
    }
    const dictionary& rd = dict.subDict("rheology");
    modelCoeffs::checkKeys
    (
        rd,
        wordList
        ({
            "inertialNumber", "pressure", "x", "phi", "equilibrationStrain",
            "maxEquilibrationStrain", "samplingStrain"
        })
    );
    rheologyEnvelope& r = rheology_;
    if (rd.found("inertialNumber"))
    {
        // the dense regime: I -> 0 is quasi-static (jammed), I > 1 a gas
        for (const scalar I : rd.get<scalarList>("inertialNumber"))
        {
            if (!(I > 0 && I <= 1))
            {
                FatalIOErrorInFunction(rd)
                    << "Entry 'inertialNumber': value " << I << " is outside"
                    << " (0, 1], the dense regime of mu(I) (I -> 0 is"
                    << " quasi-static, a jammed cell; above 1 the cell is a"
                    << " granular gas)" << nl << exit(FatalIOError);
            }
        }
    }
    r.inertialNumber = readEnvelopeList
    (
        rd, "inertialNumber", 0, 1 + SMALL,
        "inertial numbers of the rheology cells, each in (0, 1]"
    );
    r.pressureGiven = rd.found("pressure");
    if (!r.pressureGiven && !pressureOptional)
    {
        FatalIOErrorInFunction(rd)
            << "Missing entry 'pressure' [Pa]: the normal stress sigma_yy the"
            << " rheology cells are sheared at (the pressure scale of the case,"
            << " e.g. rho_bulk g H/2 of its depth H; -fromCase derives it from"
            << " the case's field p)" << nl << exit(FatalIOError);
    }
    if (r.pressureGiven)
    {
        r.pressure = rd.get<scalar>("pressure");
        if (!(r.pressure > 0) || !std::isfinite(r.pressure))
        {
            FatalIOErrorInFunction(rd)
                << "Entry 'pressure " << r.pressure << "' must be a pressure > 0"
                << " Pa (the normal stress sigma_yy of the rheology cells)" << nl
                << exit(FatalIOError);
        }
    }
    r.x = rd.getOrDefault<scalar>("x", 0.5);
    if (!(r.x > 0 && r.x < 1))
    {
        FatalIOErrorInFunction(rd)
            << "Entry 'x " << r.x << "' (coarse fraction of the rheology"
            << " cells' solids) must lie in (0, 1)" << nl << exit(FatalIOError);
    }
    r.phi = rd.getOrDefault<scalar>("phi", 0.5);
    if (!(r.phi > 0.05 && r.phi < phiJamming))
    {
        FatalIOErrorInFunction(rd)
            << "Entry 'phi " << r.phi << "' (the packing the rheology cells"
            << " start from; the barostat then finds the steady one) must lie"
            << " in (0.05, " << phiJamming << ")" << nl << exit(FatalIOError);
    }
    r.equilibrationStrain = rd.getOrDefault<scalar>("equilibrationStrain", 10);
    r.maxEquilibrationStrain =
        rd.getOrDefault<scalar>
        (
            "maxEquilibrationStrain", 3*r.equilibrationStrain
        );
    r.samplingStrain = rd.getOrDefault<scalar>("samplingStrain", 20);
    checkStrains
    (
        rd, r.samplingStrain, r.equilibrationStrain, r.maxEquilibrationStrain
    );
}


void Foam::calibrationSettings::readSegregation
(
    const dictionary& dict,
    const bool normalStressOptional
)
{
    if (!dict.isDict("segregationVelocity"))
    {
        FatalIOErrorInFunction(dict)
            << "'coefficients' holds segregationVelocity but the sub-dictionary"
            << " 'segregationVelocity' is missing; give at least" << nl
            << "    segregationVelocity { normalStress (100 400 1600); }" << nl
            << "    (the top wall's loads sigma_N [Pa] of the sheared cells under"
            << " gravity; -fromCase derives them from the case)" << nl
            << exit(FatalIOError);
    }
    const dictionary& sd = dict.subDict("segregationVelocity");
    modelCoeffs::checkKeys
    (
        sd,
        wordList
        ({
            "normalStress", "x", "phi", "wallSpeed", "gravity",
            "profileRelaxationTime", "particles", "developmentTime",
            "samplingTime", "blocks", "heightRatio", "wallThickness", "layers",
            "driftStartStrain", "driftEndStrain", "diffusionStrain",
            "sampleEvery", "estimator"
        })
    );
    segregationEnvelope& e = segregation_;
    e.normalStressGiven = sd.found("normalStress");
    if (!e.normalStressGiven && !normalStressOptional)
    {
        FatalIOErrorInFunction(sd)
            << "Missing entry 'normalStress' [Pa]: the top wall's loads sigma_N"
            << " of the sheared cells under gravity (the pressures of the case,"
            << " p* = p/(rho_s g dMean) from a few to a few hundred; -fromCase"
            << " derives them from the case's bulk flow)" << nl
            << exit(FatalIOError);
    }
    if (e.normalStressGiven)
    {
        e.normalStress = readEnvelopeList
        (
            sd, "normalStress", 0, GREAT,
            "the top wall's loads sigma_N [Pa], each > 0"
        );
        if (e.normalStress.size() < 3)
        {
            FatalIOErrorInFunction(sd)
                << "Entry 'normalStress " << e.normalStress << "': give at least"
                << " 3 loads (the pressure law B dMean (R - 1)/(C + p*) has two"
                << " parameters; replicas do not add pressures)" << nl
                << exit(FatalIOError);
        }
    }
    const auto inOpen = [&sd](const word& key, const scalar value, const scalar lo,
        const scalar hi, const char* meaning)
    {
        const scalar v = sd.getOrDefault<scalar>(key, value);
        if (!(v > lo && v < hi) || !std::isfinite(v))
        {
            FatalIOErrorInFunction(sd)
                << "Entry '" << key << " " << v << "' (" << meaning
                << ") must lie in (" << lo << ", "
                << (hi > 1e300 ? std::string("inf") : fmt(hi)).c_str() << ")"
                << nl << exit(FatalIOError);
        }
        return v;
    };
    e.x = inOpen("x", e.x, 0, 1, "coarse fraction of the cells' solids");
    e.phi = inOpen("phi", e.phi, 0.05, phiJamming, "the packing the cells are cut from");
    e.wallSpeed = inOpen("wallSpeed", e.wallSpeed, 0, GREAT, "the top wall's speed U [m/s]");
    e.gravity = inOpen("gravity", e.gravity, 0, GREAT, "g [m/s^2], normal to the walls");
    e.profileRelaxationTime = inOpen
    (
        "profileRelaxationTime", e.profileRelaxationTime, -SMALL, GREAT,
        "tau_u of the force holding the linear profile [s]; 0: off"
    );
    e.developmentTime = inOpen
    (
        "developmentTime", e.developmentTime, 0, GREAT,
        "the development from the mixed start before the sampling [s]"
    );
    e.samplingTime = inOpen("samplingTime", e.samplingTime, 0, GREAT, "the sampling [s]");
    e.heightRatio = inOpen("heightRatio", e.heightRatio, 0, GREAT, "the packing's height over its width");
    e.wallThickness = inOpen("wallThickness", e.wallThickness, 0, GREAT, "each wall's thickness [coarse diameters]");
    e.driftStartStrain = inOpen("driftStartStrain", e.driftStartStrain, -SMALL, GREAT, "strain U t/gap");
    e.driftEndStrain = inOpen("driftEndStrain", e.driftEndStrain, -SMALL, GREAT, "strain U t/gap; 0: the development's end");
    e.diffusionStrain = inOpen("diffusionStrain", e.diffusionStrain, 0, GREAT, "strain U t/gap");
    e.particles = sd.getOrDefault<label>("particles", e.particles);
    e.blocks = sd.getOrDefault<label>("blocks", e.blocks);
    e.layers = sd.getOrDefault<label>("layers", e.layers);
    e.sampleEvery = sd.getOrDefault<label>("sampleEvery", e.sampleEvery);
    if
    (
        e.particles < 100 || e.blocks < 2 || e.layers < 2 || e.layers > 1000
     || e.sampleEvery < 1
    )
    {
        FatalIOErrorInFunction(sd)
            << "Entries 'particles " << e.particles << "' (at least 100), 'blocks "
            << e.blocks << "' (at least 2), 'layers " << e.layers
            << "' (2 to 1000), 'sampleEvery " << e.sampleEvery << "' (at least 1)"
            << nl << exit(FatalIOError);
    }
    e.estimator = sd.getOrDefault<word>("estimator", e.estimator);
    if (e.estimator != "balance" && e.estimator != "early")
    {
        FatalIOErrorInFunction(sd)
            << "Entry 'estimator " << e.estimator << "': valid: balance (the"
            << " sampled profile's flux balance, the diffusive back-flux"
            << " included), early (the drift of the mixed start)" << nl
            << exit(FatalIOError);
    }
}


void Foam::calibrationSettings::setSegregationNormalStresses
(
    const scalarList& normalStress
)
{
    for (label i = 0; i < normalStress.size(); ++i)
    {
        if
        (
            !(normalStress[i] > 0) || !std::isfinite(normalStress[i])
         || (i > 0 && !(normalStress[i] > normalStress[i - 1]))
        )
        {
            FatalErrorInFunction
                << "The segregation cells' loads from the case, " << normalStress
                << " Pa, are not increasing pressures > 0: give 'normalStress'"
                << " in the segregationVelocity entry of " << dict_.name() << nl
                << exit(FatalError);
        }
    }
    if (normalStress.empty())
    {
        FatalErrorInFunction
            << "No segregation cells' loads from the case: give 'normalStress'"
            << " in the segregationVelocity entry of " << dict_.name() << nl
            << exit(FatalError);
    }
    segregation_.normalStress = normalStress;
}


sdf::dem::GravityShearRunSettings
Foam::calibrationSettings::segregationCellSettings
(
    const scalar normalStress,
    const label seed,
    const std::string& name
) const
{
    const segregationEnvelope& e = segregation_;
    sdf::dem::GravityShearRunSettings s;
    s.cell = base_;
    s.cell.volumeFractions = {1 - e.x, e.x};
    s.cell.solidsFraction = e.phi;
    s.cell.particles = e.particles;
    s.cell.equilibrationTime = e.developmentTime;
    s.cell.maxEquilibrationTime = 0;
    s.cell.samplingTime = e.samplingTime;
    s.cell.blocks = e.blocks;
    s.cell.sampleEvery = e.sampleEvery;
    s.cell.simulation.mode = sdf::dem::CellMode::nve;
    s.cell.simulation.targetPressure = 0;
    s.cell.seed = seed;
    s.cell.label = name;
    s.walls.gravity = e.gravity;
    s.walls.wallSpeed = e.wallSpeed;
    s.walls.normalStress = normalStress;
    s.walls.profileRelaxationTime = e.profileRelaxationTime;
    s.heightRatio = e.heightRatio;
    s.wallThickness = e.wallThickness;
    s.layers = e.layers;
    s.driftStartStrain = e.driftStartStrain;
    s.driftEndStrain = e.driftEndStrain;
    s.diffusionStrain = e.diffusionStrain;
    return s;
}


std::string Foam::calibrationSettings::segregationSettingsKey() const
{
    const segregationEnvelope& e = segregation_;
    // sigma_N and x are in the condition's name; the packing's phi is in
    // neither the name nor the cell's key
    const sdf::dem::GravityShearRunSettings s =
        segregationCellSettings(1, 0, "");
    return
        sdf::store::settingsKey(s.cell, contactModel_)
      + "; gravityShear phi " + fmt(e.phi)
      + " g " + fmt(e.gravity) + " U " + fmt(e.wallSpeed)
      + " profileRelaxationTime " + fmt(e.profileRelaxationTime)
      + " heightRatio " + fmt(e.heightRatio)
      + " wallThickness " + fmt(e.wallThickness)
      + " layers " + std::to_string(e.layers)
      + " driftStartStrain " + fmt(e.driftStartStrain)
      + " driftEndStrain " + fmt(e.driftEndStrain)
      + " diffusionStrain " + fmt(e.diffusionStrain);
}


void Foam::calibrationSettings::readStrains(const dictionary& dict)
{
    const wordList strainKeys
    ({
        "equilibrationStrain", "maxEquilibrationStrain", "samplingStrain"
    });
    const wordList timeKeys
    ({
        "equilibrationTime", "maxEquilibrationTime", "samplingTime"
    });
    bool anyStrain = false;
    for (const word& k : strainKeys) anyStrain = anyStrain || dict.found(k);
    if (!anyStrain)
    {
        return;
    }
    if (!sheared())
    {
        FatalIOErrorInFunction(dict)
            << "Entries " << strainKeys << " are the run lengths of sheared"
            << " cells (mode leesEdwards); a driven cell's are "
            << timeKeys << nl << exit(FatalIOError);
    }
    // One unit for all run lengths: a time beside a strain would be
    // overridden silently
    for (const word& t : timeKeys)
    {
        if (dict.found(t))
        {
            FatalIOErrorInFunction(dict)
                << "Entry '" << t << "' given with run lengths in strain: give"
                << " the run lengths of the sheared cells all in strain ("
                << strainKeys << ") or all in time (" << timeKeys << ")"
                << nl << exit(FatalIOError);
        }
    }
    samplingStrain_ = dict.get<scalar>("samplingStrain");
    equilibrationStrain_ = dict.getOrDefault<scalar>("equilibrationStrain", 2);
    maxEquilibrationStrain_ =
        dict.getOrDefault<scalar>
        (
            "maxEquilibrationStrain", 2*equilibrationStrain_
        );
    checkStrains
    (
        dict, samplingStrain_, equilibrationStrain_, maxEquilibrationStrain_
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::calibrationSettings::envelopeAxes
Foam::calibrationSettings::envelope() const
{
    envelopeAxes axes;
    axes.phi = readEnvelopeList
    (
        dict_, "phi", 0, phiJamming, "solids fraction, below jamming 0.64"
    );
    axes.x = readEnvelopeList
    (
        dict_, "x", 0, 1, "coarse fraction of the solids"
    );
    checkRateAxis(dict_);
    if (sheared())
    {
        axes.gammaDot = readEnvelopeList
        (
            dict_, "gammaDot", 0, 1e301, "shear rate of the sheared cells [1/s]"
        );
    }
    else
    {
        axes.T = readEnvelopeList
        (
            dict_, "T", 0, 1e301,
            "granular temperature [m2/s2], sum of 3 components"
        );
    }
    return axes;
}


bool Foam::calibrationSettings::sheared() const
{
    return base_.simulation.mode == sdf::dem::CellMode::leesEdwards;
}


void Foam::calibrationSettings::checkRateAxis(const dictionary& dict) const
{
    // The one axis the cells are driven along; the other is their output
    const word axis(sheared() ? "gammaDot" : "T");
    const word other(sheared() ? "T" : "gammaDot");
    if (dict.found(other))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << other << "' does not apply with mode "
            << sdf::dem::cellModeName(base_.simulation.mode).c_str() << ": "
            << (
                   sheared()
                 ? "a sheared cell's granular temperature is measured, not"
                   " set; give the shear rates as 'gammaDot (..);'"
                 : "a driven cell is not sheared; give the temperatures as"
                   " 'T (..);', or 'mode leesEdwards;' with 'gammaDot (..);'"
               )
            << nl << exit(FatalIOError);
    }
}


sdf::dem::CellRunSettings Foam::calibrationSettings::conditionSettings
(
    const scalar phi,
    const scalar x,
    const scalar rate,
    const label seed,
    const std::string& name,
    const label particles
) const
{
    if (!transportRunControls_)
    {
        // (the runDEM policy of a tabulated model reads this dictionary too)
        FatalIOErrorInFunction(dict_)
            << "A transport cell (phi " << phi << ", x " << x << ") asked of"
            << " a calibrationDict that calibrates only the rheology and has"
            << " no 'samplingTime': give the transport cells' run controls"
            << " (samplingTime, equilibrationTime, ...)" << nl
            << exit(FatalIOError);
    }
    sdf::dem::CellRunSettings s = base_;
    if (particles > 0)
    {
        s.particles = particles;
    }
    s.volumeFractions = {1 - x, x};
    s.solidsFraction = phi;
    if (sheared())
    {
        s.simulation.shearRate = rate;
        if (samplingStrain_ > 0)
        {
            s.samplingTime = samplingStrain_/rate;
            s.equilibrationTime = equilibrationStrain_/rate;
            s.maxEquilibrationTime = maxEquilibrationStrain_/rate;
        }
    }
    else
    {
        s.simulation.targetTemperature = rate;
    }
    s.seed = seed;
    s.label = name;
    return s;
}


Foam::wordList Foam::calibrationSettings::transportCoefficients() const
{
    wordList transport;
    for (const word& c : coefficients_)
    {
        if (c != "rheology" && c != "segregationVelocity")
        {
            transport.append(c);
        }
    }
    return transport;
}


void Foam::calibrationSettings::setRheologyPressure(const scalar p)
{
    if (!(p > 0) || !std::isfinite(p))
    {
        FatalErrorInFunction
            << "The rheology cells' pressure from the case, " << p << " Pa,"
            << " is not a pressure > 0: give 'pressure' in the rheology"
            << " entry of " << dict_.name() << nl << exit(FatalError);
    }
    rheology_.pressure = p;
}


sdf::dem::CellRunSettings Foam::calibrationSettings::rheologyCellSettings
(
    const scalar inertialNumber,
    const label seed,
    const std::string& name
) const
{
    const rheologyEnvelope& r = rheology_;
    sdf::dem::CellRunSettings mixture = base_;
    mixture.volumeFractions = {1 - r.x, r.x};
    mixture.solidsFraction = r.phi;
    mixture.simulation.targetPressure = r.pressure;
    sdf::dem::CellRunSettings s = sdf::dem::atInertialNumber
    (
        mixture, inertialNumber, r.equilibrationStrain,
        r.maxEquilibrationStrain, r.samplingStrain
    );
    s.seed = seed;
    s.label = name;
    return s;
}


std::string Foam::calibrationSettings::rheologySettingsKey() const
{
    sdf::dem::CellRunSettings s = rheologyCellSettings(1, 0, "");
    // the times follow from the strains and I (in the name): the key names
    // the strains, and not the transport cells' times (a transport
    // calibration beside it must not invalidate the stored rheology)
    s.equilibrationTime = 0;
    s.maxEquilibrationTime = 0;
    s.samplingTime = 0;
    const rheologyEnvelope& r = rheology_;
    return
        sdf::store::settingsKey(s, contactModel_)
      + "; rheology start phi " + fmt(r.phi)
      + " equilibrationStrain " + fmt(r.equilibrationStrain)
      + " maxEquilibrationStrain " + fmt(r.maxEquilibrationStrain)
      + " samplingStrain " + fmt(r.samplingStrain);
}


std::string Foam::calibrationSettings::settingsKey(const label particles) const
{
    sdf::dem::CellRunSettings b = base_;
    if (particles > 0)
    {
        b.particles = particles;
    }
    std::string key = sdf::store::settingsKey(b, contactModel_);
    if (samplingStrain_ > 0)
    {
        // The times of the key are placeholders then: the strains decide
        // %.10g as the rest of the key
        auto g10 = [](const scalar v)
        {
            char buf[32];
            std::snprintf(buf, sizeof(buf), "%.10g", v);
            return std::string(buf);
        };
        key +=
            " equilibrationStrain " + g10(equilibrationStrain_)
          + " maxEquilibrationStrain " + g10(maxEquilibrationStrain_)
          + " samplingStrain " + g10(samplingStrain_);
    }
    return key;
}


void Foam::calibrationSettings::appendToStore
(
    const std::string& path,
    const sdf::store::ConditionInputs& inputs,
    const sdf::dem::CellRunResult& result
) const
{
    sdf::store::appendCondition
    (
        path, fine_.name, coarse_.name,
        inputs.inertialNumber
      ? rheologySettingsKey()
      : settingsKey(result.settings.particles),
        inputs, result
    );
}


void Foam::calibrationSettings::appendToStore
(
    const std::string& path,
    const sdf::store::ConditionInputs& inputs,
    const sdf::dem::GravityShearRunResult& result
) const
{
    sdf::store::appendSegregationCondition
    (
        path, fine_.name, coarse_.name, segregationSettingsKey(), inputs, result
    );
}


// ************************************************************************* //

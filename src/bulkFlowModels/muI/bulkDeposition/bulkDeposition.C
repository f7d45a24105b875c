/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "bulkDeposition.H"
#include "granularMixture.H"
#include "modelCoeffs.H"
#include "Map.H"
#include "surfaceFields.H"

// * * * * * * * * * * * * * * * * * Constants * * * * * * * * * * * * * * * //

namespace
{
    // A cell at least this full holds up the stream (the one above it is
    // where it lands); one less full is where it lands if it is held up
    constexpr Foam::scalar supportFraction = 0.5;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkDeposition::bulkDeposition
(
    const dictionary& dict,
    const granularMixture& mixture,
    const scalar packedFraction
)
:
    mesh_(mixture.mesh()),
    rate_(0),
    centre_(dict.get<point>("centre")),
    gHat_(normalised(mixture.gravity())),
    radius_(0),
    composition_(mixture.size(), Zero),
    start_(dict.getOrDefault<scalar>("start", 0)),
    end_(dict.getOrDefault<scalar>("end", GREAT)),
    packedFraction_(packedFraction),
    k_
    (
        IOobject("depositionRate", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    minusK_
    (
        IOobject("depositionRateSp", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    source_
    (
        IOobject("depositionSource", mesh_.time().timeName(), mesh_),
        mesh_,
        dimensionedScalar(dimless/dimTime, Zero)
    ),
    poured_(0),
    deposited_(0),
    depositedSpecies_(mixture.size(), Zero)
{
    modelCoeffs::checkKeys
    (
        dict, {"rate", "centre", "radius", "composition", "start", "end"}
    );
    rate_ = modelCoeffs::get(dict, "rate", dimVolume/dimTime).value();
    radius_ = modelCoeffs::get(dict, "radius", dimLength).value();
    if (!(rate_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "'rate " << rate_ << "' must be > 0 [m3/s of bulk]"
            << nl << exit(FatalIOError);
    }
    if (!(radius_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "'radius " << radius_ << "' must be > 0 [m]: the stream's"
            << " footprint around the spout's axis" << nl << exit(FatalIOError);
    }
    if (!(end_ > start_))
    {
        FatalIOErrorInFunction(dict)
            << "'end " << end_ << "' must be after 'start " << start_ << "'"
            << nl << exit(FatalIOError);
    }

    // The feed's composition: every species named, fractions in [0, 1]
    // summing to 1
    const dictionary& feed = dict.subDict("composition");
    modelCoeffs::checkKeys(feed, mixture.names());
    scalar sum = 0;
    forAll(mixture.names(), k)
    {
        const word& name = mixture.names()[k];
        if (!feed.found(name))
        {
            FatalIOErrorInFunction(feed)
                << "No entry for species '" << name << "'; the feed's solids"
                << " volume fraction of every species " << mixture.names()
                << " is needed" << nl << exit(FatalIOError);
        }
        composition_[k] = feed.get<scalar>(name);
        if (!(composition_[k] >= 0 && composition_[k] <= 1))
        {
            FatalIOErrorInFunction(feed)
                << "'" << name << " " << composition_[k] << "' must lie in"
                << " [0, 1]" << nl << exit(FatalIOError);
        }
        sum += composition_[k];
    }
    if (mag(sum - 1) > 1e-6)
    {
        FatalIOErrorInFunction(feed)
            << "The feed's fractions " << composition_ << " sum to " << sum
            << ", not 1" << nl << exit(FatalIOError);
    }
    // exactly 1, so the species' sum stays packedFraction alpha
    composition_ /= sum;

    findColumn();
    if (returnReduce(cells_.size(), sumOp<label>()) == 0)
    {
        FatalIOErrorInFunction(dict)
            << "No cell centre lies within 'radius " << radius_ << "' of the"
            << " spout's axis through 'centre " << centre_ << "' along g "
            << gHat_ << nl << exit(FatalIOError);
    }

    if (Pstream::master())
    {
        const fileName dir
        (
            mesh_.time().globalPath()/"postProcessing"/"deposition"
           /mesh_.time().timeName()
        );
        mkDir(dir);
        file_.reset(new OFstream(dir/"deposition.dat"));
        OFstream& os = file_();
        os.precision(15);
        os  << "# the pour deposited where it lands (muICoeffs/deposition):"
            << " rate " << rate_ << " m3/s of bulk at solids fraction "
            << packedFraction_ << ", spout through " << centre_
            << " radius " << radius_ << " m" << nl
            << "# time [s]  bulk deposited in the step [m3/s]"
            << "  bulk deposited in all [m3]";
        for (const word& name : mixture.names())
        {
            os  << "  solids " << name << " in all [m3]";
        }
        os  << nl;
    }

    Info<< "    muI: deposition of " << rate_ << " m3/s of bulk from "
        << start_ << " s to " << end_ << " s, where it lands under the spout"
        << " through " << centre_ << " (radius " << radius_ << " m, "
        << returnReduce(cells_.size(), sumOp<label>()) << " cells), feed "
        << composition_ << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bulkDeposition::findColumn()
{
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Sf = mesh_.faceAreas();
    const labelUList& own = mesh_.faceOwner();

    DynamicList<label> cells, down;
    DynamicList<scalar> footprint;
    forAll(C, celli)
    {
        const vector d(C[celli] - centre_);
        if (mag(d - (d & gHat_)*gHat_) > radius_)
        {
            continue;
        }
        // the face whose outward normal points most along g
        label best = -1;
        scalar bestCos = -GREAT, bestArea = 0;
        for (const label facei : mesh_.cells()[celli])
        {
            const vector out(own[facei] == celli ? Sf[facei] : -Sf[facei]);
            const scalar c = (out & gHat_)/max(mag(out), VSMALL);
            if (c > bestCos)
            {
                bestCos = c;
                best = facei;
                bestArea = out & gHat_;
            }
        }
        cells.append(celli);
        down.append(best);
        footprint.append(max(bestArea, scalar(0)));
    }
    cells_.transfer(cells);
    downFace_.transfer(down);
    footprint_.transfer(footprint);
    airShare_.setSize(cells_.size(), Zero);
}


Foam::scalarList Foam::bulkDeposition::alphaBelow
(
    const volScalarField& alpha
) const
{
    const labelUList& own = mesh_.faceOwner();
    const labelUList& nei = mesh_.faceNeighbour();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const surfaceScalarField& phi =
        mesh_.lookupObject<surfaceScalarField>("phi");

    // the neighbours' values on the coupled patches met (processor, cyclic)
    Map<scalarField> neighbourValues;

    scalarList below(cells_.size());
    forAll(cells_, i)
    {
        const label facei = downFace_[i];
        if (facei < mesh_.nInternalFaces())
        {
            below[i] = alpha[own[facei] == cells_[i] ? nei[facei] : own[facei]];
            continue;
        }
        const label patchi = patches.whichPatch(facei);
        const fvPatchScalarField& alphap = alpha.boundaryField()[patchi];
        if (!alphap.coupled())
        {
            // a floor: a wall, the hopper, a closed outlet; not a face the
            // flux leaves through (an open outlet)
            const scalar phib =
                phi.boundaryField()[patchi][facei - patches[patchi].start()];
            below[i] = phib > 0 ? 0 : 1;
            continue;
        }
        if (!neighbourValues.found(patchi))
        {
            neighbourValues.insert(patchi, scalarField(alphap.patchNeighbourField()));
        }
        below[i] = neighbourValues[patchi][facei - patches[patchi].start()];
    }
    return below;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::bulkDeposition::pourFraction() const
{
    // the share of the step [t - dt, t] inside [start, end)
    const scalar t = mesh_.time().value();
    const scalar dt = mesh_.time().deltaTValue();
    return max(min(t, end_) - max(t - dt, start_), scalar(0))/dt;
}


bool Foam::bulkDeposition::pouring() const
{
    return pourFraction() > 0;
}


void Foam::bulkDeposition::update(const volScalarField& alpha)
{
    k_ = dimensionedScalar(dimless/dimTime, Zero);
    minusK_ = dimensionedScalar(dimless/dimTime, Zero);
    source_ = dimensionedScalar(dimless/dimTime, Zero);
    airShare_ = Zero;
    if (!pouring())
    {
        return;
    }

    const scalarField& V = mesh_.V().field();
    const scalar dt = mesh_.time().deltaTValue();
    const scalarList below(alphaBelow(alpha));

    // The landing cells: one per stack, the first less than half full over
    // one at least half full (or a floor); they take the rate by their
    // footprints, none more than half the air it holds, and what a cell
    // cannot take goes to the others
    scalarList given(cells_.size(), Zero), capacity(cells_.size(), Zero);
    boolList open(cells_.size(), false);
    label nOpen = 0;
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        if
        (
            alpha[celli] < supportFraction
         && below[i] >= supportFraction
         && footprint_[i] > 0
        )
        {
            open[i] = true;
            ++nOpen;
            capacity[i] = 0.5*(1 - alpha[celli])*V[celli]/dt;
        }
    }
    reduce(nOpen, sumOp<label>());

    // The pour in this step, with what the steps before took more or less
    // than poured (a cell's take depends on what else flows in and out of
    // it in the step): the total follows the pour to within a step
    const scalar pour = rate_*pourFraction();
    const scalar target = max(pour + (poured_ - deposited_)/dt, scalar(0));
    scalar remaining = target;
    // each pass places everything or fills at least one more cell
    for (label pass = 0; pass <= nOpen && remaining > 1e-12*rate_; ++pass)
    {
        scalar weight = 0;
        forAll(open, i)
        {
            if (open[i]) weight += footprint_[i];
        }
        reduce(weight, sumOp<scalar>());
        if (!(weight > 0))
        {
            break;
        }
        const scalar perArea = remaining/weight;
        scalar used = 0;
        forAll(open, i)
        {
            if (!open[i]) continue;
            const scalar add = min(perArea*footprint_[i], capacity[i] - given[i]);
            given[i] += add;
            used += add;
            if (given[i] >= (1 - 1e-12)*capacity[i]) open[i] = false;
        }
        reduce(used, sumOp<scalar>());
        remaining -= used;
    }
    // What cannot be placed now is made up in the next steps; only a
    // column that cannot take this step's own pour is full
    if (target - remaining < (1 - 1e-9)*min(pour, target))
    {
        FatalErrorInFunction
            << "muICoeffs/deposition at time " << mesh_.time().timeName()
            << ": the landing cells under the spout (through " << centre_
            << ", radius " << radius_ << " m) take only " << target - remaining
            << " of the " << pour << " m3/s poured: the deposit has filled"
            << " the spout's column. End the pour earlier ('end') or lower"
            << " its 'rate'." << exit(FatalError);
    }

    // Each cell's share of the air it holds; k follows with the number of
    // alpha's sub-cycles (setSubCycles)
    // (capacity > 0, so air, wherever a share was given)
    forAll(cells_, i)
    {
        if (given[i] > 0)
        {
            const label celli = cells_[i];
            airShare_[i] = given[i]*dt/V[celli]/(1 - alpha[celli]);
        }
    }
}


void Foam::bulkDeposition::setSubCycles(const label nSub)
{
    // k such that a cell nothing else flows into takes its share s of its
    // volume in the step's nSub implicit sub-steps: (1 - a)(1 - (1 + k
    // dt/n)^-n) = s, k = n/dt ((1 - r)^(-1/n) - 1) with r = s/(1 - a), the
    // share of its air; with r <= 1/2, k dt <= n (2^(1/n) - 1) <= 1
    const scalar dt = mesh_.time().deltaTValue();
    forAll(cells_, i)
    {
        const label celli = cells_[i];
        const scalar r = airShare_[i];
        k_[celli] = r > 0 ? nSub/dt*(pow(1 - r, -1.0/nSub) - 1) : 0;
        minusK_[celli] = -k_[celli];
    }
}


void Foam::bulkDeposition::beginSolve()
{
    source_ = dimensionedScalar(dimless/dimTime, Zero);
}


void Foam::bulkDeposition::addTaken
(
    const volScalarField& alpha,
    const scalar fraction
)
{
    for (const label celli : cells_)
    {
        source_[celli] += fraction*k_[celli]*(1 - alpha[celli]);
    }
}


Foam::scalar Foam::bulkDeposition::depositedRate() const
{
    return gSum(source_.field()*mesh_.V().field());
}


void Foam::bulkDeposition::record()
{
    if (!pouring())
    {
        return;
    }
    const scalar rate = depositedRate();
    const scalar dt = mesh_.time().deltaTValue();
    deposited_ += rate*dt;
    poured_ += rate_*pourFraction()*dt;
    forAll(depositedSpecies_, k)
    {
        depositedSpecies_[k] += packedFraction_*composition_[k]*rate*dt;
    }
    if (file_.valid())
    {
        OFstream& os = file_();
        os  << mesh_.time().value() << ' ' << rate << ' ' << deposited_;
        for (const scalar v : depositedSpecies_)
        {
            os  << ' ' << v;
        }
        os  << endl;
    }
    Info<< "    muI: deposited " << rate << " m3/s of bulk, " << deposited_
        << " m3 in all (poured " << poured_ << ")" << endl;
}


// ************************************************************************* //

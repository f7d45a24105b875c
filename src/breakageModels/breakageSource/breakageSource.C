/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "breakageSource.H"
#include "fvmSup.H"
#include "fvmDdt.H"
#include "zeroGradientFvPatchFields.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::dictionary Foam::breakageSource::selectionDict
(
    const dictionary& breakageDict
)
{
    dictionary dict(breakageDict);
    dict.remove("daughterSizeDistribution");
    dict.remove("fines");
    return dict;
}


bool Foam::breakageSource::readFines(const dictionary& breakageDict)
{
    const word fines(breakageDict.getOrDefault<word>("fines", "finestClass"));
    if (fines != "dust" && fines != "finestClass")
    {
        FatalIOErrorInFunction(breakageDict)
            << "Unknown 'fines " << fines << "' in " << breakageDict.name()
            << nl << "    valid: finestClass (fragments below the finest"
            << " class join it, volume kept) dust (removed to the dust"
            << " field, volume and number accounted)" << nl
            << exit(FatalIOError);
    }
    return fines == "dust";
}


Foam::List<Foam::breakageWeights> Foam::breakageSource::fragmentWeights
(
    const granularMixture& mixture,
    const dictionary& breakageDict,
    bool& dustSink
)
{
    dustSink = readFines(breakageDict);

    if (!breakageDict.isDict("daughterSizeDistribution"))
    {
        FatalIOErrorInFunction(breakageDict)
            << "Missing dictionary 'daughterSizeDistribution' in "
            << breakageDict.name() << nl
            << "    e.g. daughterSizeDistribution { model uniformBinary; }"
            << nl << exit(FatalIOError);
    }
    const autoPtr<daughterSizeDistributionModel> daughters
    (
        daughterSizeDistributionModel::New
        (
            breakageDict.subDict("daughterSizeDistribution"),
            mixture
        )
    );

    List<breakageWeights> weights(mixture.size());
    forAll(weights, j)
    {
        const labelList grid
        (
            daughterSizeDistributionModel::classGrid(mixture, j)
        );
        weights[j] = daughters->weights(j, grid, dustSink);

        const breakageWeights& w = weights[j];
        if (mag(w.volumeBalance() - 1) > 1e-9)
        {
            FatalIOErrorInFunction(breakageDict)
                << "The fragments of species " << mixture.names()[j]
                << " keep " << w.volumeBalance() << " of the parent's"
                << " volume (must be 1): daughterSizeDistribution in "
                << breakageDict.name() << nl << exit(FatalIOError);
        }
    }
    return weights;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::breakageSource::breakageSource
(
    const granularMixture& mixture,
    const dictionary& breakageDict
)
:
    mixture_(mixture),
    selection_(breakageModel::New(selectionDict(breakageDict), mixture)),
    dustSink_(false)
{
    if (!selection_->active())
    {
        // Nothing breaks, but the entries of the source that are given are
        // read as for an active model: a malformed one is refused now, not
        // when the breakage is switched on
        if (breakageDict.found("daughterSizeDistribution"))
        {
            bool dustSink;
            fragmentWeights(mixture, breakageDict, dustSink);
        }
        else
        {
            readFines(breakageDict);
        }
        if
        (
            breakageDict.found("daughterSizeDistribution")
         || breakageDict.found("fines")
        )
        {
            Info<< "Breakage: model none; 'fines' and"
                << " 'daughterSizeDistribution' checked, not used" << nl
                << endl;
        }
        return;
    }

    weights_ = fragmentWeights(mixture, breakageDict, dustSink_);

    parents_.setSize(mixture.size());
    Info<< "Breakage: fragments on the class grid (volume fraction of the"
        << " parent, fragments per event)" << nl;
    forAll(weights_, j)
    {
        const breakageWeights& w = weights_[j];
        Info<< "    " << mixture.names()[j] << " ->";
        forAll(w.volume, i)
        {
            if (w.volume[i] > 0)
            {
                Info<< " " << mixture.names()[i] << " " << w.volume[i]
                    << " (" << w.number[i] << ")";
                if (i != j)
                {
                    parents_[i].append(j);
                }
            }
        }
        if (w.dustVolume > 0)
        {
            Info<< " dust " << w.dustVolume << " (" << w.dustNumber << ")";
        }
        Info<< nl;
    }
    Info<< endl;

    // The accumulated fields: read back on a restart and written with the
    // species (kept), or only the log's (the per-species gains)
    auto accumulated = [&mixture](const word& name, const bool kept)
    {
        const fvMesh& mesh = mixture.mesh();
        return new volScalarField
        (
            IOobject
            (
                name,
                mesh.time().timeName(),
                mesh,
                kept ? IOobject::READ_IF_PRESENT : IOobject::NO_READ,
                kept ? IOobject::AUTO_WRITE : IOobject::NO_WRITE
            ),
            mesh,
            dimensionedScalar(name, dimless, Zero),
            zeroGradientFvPatchScalarField::typeName
        );
    };
    if (dustSink_)
    {
        dust_.reset(accumulated("dust", true));
    }
    if (mixture.writeField("brokenVolume"))
    {
        brokenVolume_.reset(accumulated("brokenVolume", true));
    }
    if (active())
    {
        gain_.setSize(mixture.size());
        forAll(gain_, i)
        {
            gain_.set(i, accumulated("breakageGain." + mixture.names()[i], false));
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::breakageSource::correct
(
    const granularTemperatureModel& granularTemperature
)
{
    if (active())
    {
        selection_->correct(granularTemperature);
    }
}


Foam::tmp<Foam::volScalarField::Internal>
Foam::breakageSource::lossRate(const label j) const
{
    return (1 - weights_[j].volume[j])*selection_->S(j).internalField();
}


Foam::tmp<Foam::fvScalarMatrix> Foam::breakageSource::source
(
    const label i,
    volScalarField& ni
) const
{
    tmp<fvScalarMatrix> tB(-fvm::Sp(lossRate(i), ni));

    // The gains from the coarser species, added to the matrix source in
    // one pass per parent (as fvMatrix += field does: source -= V field),
    // without a temporary field per parent: a class has up to all the
    // coarser classes as parents
    scalarField& source = tB.ref().source();
    const scalarField& V = mixture_.mesh().V().field();
    for (const label j : parents_[i])
    {
        const scalar beta = weights_[j].volume[i];
        const scalarField& Sj = selection_->S(j).primitiveField();
        const scalarField& nj = mixture_.n()[j].primitiveField();
        forAll(source, celli)
        {
            source[celli] -= beta*Sj[celli]*nj[celli]*V[celli];
        }
    }
    return tB;
}


void Foam::breakageSource::accumulate()
{
    if (!active())
    {
        return;
    }

    // The rates with this step's solved fields, as the species saw them
    volScalarField::Internal dustRate
    (
        IOobject("dustRate", mixture_.mesh().time().timeName(), mixture_.mesh()),
        mixture_.mesh(),
        dimensionedScalar("0", inv(dimTime), Zero)
    );
    volScalarField::Internal brokenRate(dustRate);
    forAll(weights_, j)
    {
        const scalarField& Sj = selection_->S(j).primitiveField();
        const scalarField& nj = mixture_.n()[j].primitiveField();
        const scalar toDust = weights_[j].dustVolume;
        const scalar broken = 1 - weights_[j].volume[j];
        forAll(dustRate, celli)
        {
            dustRate[celli] += toDust*Sj[celli]*nj[celli];
            brokenRate[celli] += broken*Sj[celli]*nj[celli];
        }
    }

    // ddt(field) = rate with the case's time scheme, the one the species
    // use: solids + dust is then kept by Euler, backward or Crank-Nicolson
    // alike. The matrix is diagonal (no transport): field = source/diag
    auto advance = [](volScalarField& field, const volScalarField::Internal& rate)
    {
        fvScalarMatrix eqn(fvm::ddt(field));
        eqn -= rate;
        field.primitiveFieldRef() = eqn.source()/eqn.diag();
        field.correctBoundaryConditions();
    };
    if (dust_)
    {
        advance(dust_(), dustRate);
    }
    if (brokenVolume_)
    {
        advance(brokenVolume_(), brokenRate);
    }

    // Each species' net gain, -lossRate n_i + sum over its parents of
    // beta S_j n_j: the source its equation had
    forAll(gain_, i)
    {
        volScalarField::Internal gainRate
        (
            -lossRate(i)*mixture_.n()[i].internalField()
        );
        for (const label j : parents_[i])
        {
            const scalar beta = weights_[j].volume[i];
            gainRate.field() +=
                beta*selection_->S(j).primitiveField()
               *mixture_.n()[j].primitiveField();
        }
        advance(gain_[i], gainRate);
    }
}


void Foam::breakageSource::writeDerivedFields() const
{
    if (active() && mixture_.writeField("S"))
    {
        forAll(mixture_.n(), j)
        {
            selection_->S(j).write();
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "BreakingRebound.H"
#include "breakageSource.H"
#include "caseFields.H"
#include "parcelSpecies.H"
#include "wallPolyPatch.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::BreakingRebound<CloudType>::wallImpactCoeffs
(
    const dictionary& breakageDict
)
{
    const word model(breakageDict.get<word>("model"));
    if (model != "wallImpact")
    {
        FatalIOErrorInFunction(breakageDict)
            << "breakingRebound breaks parcels with the case's wall-breakage"
            << " model: 'model " << model << "' in " << breakageDict.name()
            << " must be wallImpact" << nl << exit(FatalIOError);
    }
    return modelCoeffs::coeffsDict(breakageDict, "wallImpact");
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::BreakingRebound<CloudType>::BreakingRebound
(
    const dictionary& dict,
    CloudType& cloud
)
:
    PatchInteractionModel<CloudType>(dict, cloud, typeName),
    e_(this->coeffDict().template get<scalar>("e")),
    mu_(this->coeffDict().template get<scalar>("mu")),
    startTime_(this->coeffDict().getOrDefault("startTime", scalar(0))),
    species_(caseSpecies(cloud.mesh())),
    kernel_
    (
        wallImpactCoeffs(caseGranularProperties(cloud.mesh()).subDict("breakage"))
    ),
    dustSink_(false),
    impacts_(species_.size(), Zero),
    events_(species_.size(), Zero),
    brokenVolume_(species_.size(), Zero),
    dustVolume_(0)
{
    for (const auto& bound : {std::make_pair("e", e_), std::make_pair("mu", mu_)})
    {
        if (!(bound.second >= 0 && bound.second <= 1))
        {
            FatalIOErrorInFunction(this->coeffDict())
                << "'" << bound.first << " " << bound.second << "' in "
                << this->coeffDict().name() << " must lie in [0, 1]" << nl
                << exit(FatalIOError);
        }
    }

    // The fragment fractions of the continuum: from a mixture of the case's
    // species (which needs 0/n.<species>), used once
    const granularMixture mixture(cloud.mesh());
    weights_ = breakageSource::fragmentWeights
    (
        mixture,
        mixture.subDict("breakage"),
        dustSink_
    );
}


template<class CloudType>
Foam::BreakingRebound<CloudType>::BreakingRebound
(
    const BreakingRebound<CloudType>& pim
)
:
    PatchInteractionModel<CloudType>(pim),
    e_(pim.e_),
    mu_(pim.mu_),
    startTime_(pim.startTime_),
    species_(pim.species_),
    kernel_(pim.kernel_),
    weights_(pim.weights_),
    dustSink_(pim.dustSink_),
    impacts_(pim.impacts_),
    events_(pim.events_),
    brokenVolume_(pim.brokenVolume_),
    dustVolume_(pim.dustVolume_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
bool Foam::BreakingRebound<CloudType>::correct
(
    typename CloudType::parcelType& p,
    const polyPatch& pp,
    bool& keepParticle
)
{
    if (!isA<wallPolyPatch>(pp))
    {
        return false;
    }

    keepParticle = true;
    p.active(true);

    vector nw, Up;
    this->owner().patchData(p, pp, nw, Up);
    vector& U = p.U();
    U -= Up;
    const scalar Un = U & nw;
    const vector Ut = U - Un*nw;

    // The counters from startTime on (a window with a full pipe); the
    // breakage itself at every time
    // (half a step's margin, as particlePass: the step that ends at
    // startTime plus round-off is not counted)
    const Time& time = this->owner().mesh().time();
    const bool counting =
        time.value() > startTime_ + 0.5*time.deltaTValue();

    if (Un > 0)
    {
        const label j = parcelSpecies(species_, p.d());
        if (counting)
        {
            impacts_[j] += p.nParticle();
        }

        const scalar P = kernel_.probability(species_[j].d, Un, mag(Ut));
        Random& rnd = this->owner().rndGen();
        if (P > 0 && rnd.template sample01<scalar>() < P)
        {
            const scalar parcelVolume =
                counting ? p.nParticle()*p.volume() : 0;
            if (counting)
            {
                events_[j] += p.nParticle();
            }

            // The class the fragments go to, with the volume fractions of
            // the continuum (beta_jj: fragments that stay in the class)
            const breakageWeights& w = weights_[j];
            const scalar r = rnd.template sample01<scalar>();
            scalar cumulative = 0;
            label target = -1;
            forAll(w.volume, i)
            {
                cumulative += w.volume[i];
                if (r < cumulative)
                {
                    target = i;
                    break;
                }
            }

            if (target != j)
            {
                brokenVolume_[j] += parcelVolume;
            }
            if (target < 0)
            {
                // Finer than the finest class: dust (or round-off at the
                // top of the cumulative sum with finestClass)
                if (dustSink_)
                {
                    dustVolume_ += parcelVolume;
                    keepParticle = false;
                    p.active(false);
                    U = Zero;
                    return true;
                }
                target = findMax(w.volume);
            }
            if (target != j)
            {
                const scalar di = species_[target].d;
                p.nParticle() *= pow3(p.d()/di);
                p.d() = di;
            }
        }

        U -= (1 + e_)*Un*nw;
    }
    U -= mu_*Ut;
    U += Up;

    return true;
}


template<class CloudType>
void Foam::BreakingRebound<CloudType>::info(Ostream& os)
{
    PatchInteractionModel<CloudType>::info(os);
    os  << "    breakingRebound from t = " << startTime_ << " s over "
        << max(this->owner().mesh().time().value() - startTime_, scalar(0))
        << " s: per species impacts / breakage events / broken volume [m3]"
        << nl;
    forAll(species_, j)
    {
        os  << "      " << species_[j].name << ' '
            << returnReduce(impacts_[j], sumOp<scalar>()) << ' '
            << returnReduce(events_[j], sumOp<scalar>()) << ' '
            << returnReduce(brokenVolume_[j], sumOp<scalar>()) << nl;
    }
    os  << "      dust volume [m3] "
        << returnReduce(dustVolume_, sumOp<scalar>()) << nl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "BreakingRebound.H"
#include "breakageSource.H"
#include "parcelSpecies.H"
#include "countingWindow.H"
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


template<class CloudType>
bool Foam::BreakingRebound<CloudType>::readExpected(const dictionary& coeffs)
{
    const word mode(coeffs.getOrDefault<word>("fragments", "sampled"));
    if (mode != "sampled" && mode != "expected")
    {
        FatalIOErrorInFunction(coeffs)
            << "'fragments " << mode << "' in " << coeffs.name()
            << ": valid choices are sampled (a broken parcel becomes one"
            << " class, drawn: the reference) and expected (every impact"
            << " splits the parcel into its expected shares: the continuum's"
            << " particle pass)" << nl << exit(FatalIOError);
    }
    return mode == "expected";
}


template<class CloudType>
Foam::scalar Foam::BreakingRebound<CloudType>::readRoughness
(
    const dictionary& coeffs
)
{
    const scalar degrees(coeffs.getOrDefault("roughness", scalar(0)));
    if (!(degrees >= 0 && degrees < 45))
    {
        FatalIOErrorInFunction(coeffs)
            << "'roughness " << degrees << "' in " << coeffs.name()
            << ": the standard deviation of the wall's inclination, in"
            << " degrees, lies in [0, 45) (0: a smooth wall)" << nl
            << exit(FatalIOError);
    }
    return degToRad(degrees);
}


template<class CloudType>
bool Foam::BreakingRebound<CloudType>::readCoulomb(const dictionary& coeffs)
{
    const word law(coeffs.getOrDefault<word>("tangential", "lossFraction"));
    if (law != "lossFraction" && law != "coulomb")
    {
        FatalIOErrorInFunction(coeffs)
            << "'tangential " << law << "' in " << coeffs.name()
            << ": valid choices are lossFraction (every impact loses the"
            << " fraction mu of the tangential velocity: OpenFOAM's"
            << " standardWallInteraction) and coulomb (mu the friction"
            << " coefficient: a sliding impact loses mu (1 + e) Un of its"
            << " tangential speed, one that sticks keeps 5/7 of it)" << nl
            << exit(FatalIOError);
    }
    return law == "coulomb";
}


template<class CloudType>
Foam::vector Foam::BreakingRebound<CloudType>::rebound
(
    const vector& U,
    const vector& n
) const
{
    const scalar Un = U & n;
    const vector Ut = U - Un*n;
    if (!coulomb_)
    {
        return U - (1 + e_)*Un*n - mu_*Ut;
    }

    // A sphere's impact with Coulomb friction, its spin not carried:
    // the contact slides when the tangential impulse that would make it
    // roll (bring the contact point to rest), 2/7 m Ut, exceeds mu times
    // the normal impulse, mu m (1 + e) Un; it then loses mu (1 + e) Un of
    // its tangential speed, else it rolls off with 5/7 of it
    const scalar sliding = mu_*(1 + e_)*Un;
    const scalar magUt = mag(Ut);
    const vector UtAfter =
        magUt > 3.5*sliding
      ? (1 - sliding/magUt)*Ut
      : (5.0/7.0)*Ut;
    return UtAfter - e_*Un*n;
}


template<class CloudType>
Foam::vector Foam::BreakingRebound<CloudType>::roughRebound
(
    const vector& U,
    const vector& nw
)
{
    // The impact's plane: nw and the tangential direction t (any for a
    // normal impact)
    vector t = U - (U & nw)*nw;
    if (mag(t) < SMALL*mag(U))
    {
        t = nw ^ (mag(nw.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0));
    }
    t.normalise();
    const vector b = nw ^ t;

    // The facets are drawn with their inclinations' distribution by area
    // and hit in proportion to the flux onto them, U^ & n (the shadow
    // effect: a facet turned away from the parcel is hit less, or not at
    // all); a rebound that would not leave the pipe's wall is drawn again
    // (it would hit the wall again at once)
    const vector Uhat = U/mag(U);
    Random& rnd = this->owner().rndGen();
    for (label draw = 0; draw < 1000; ++draw)
    {
        const scalar inPlane = roughness_*rnd.template GaussNormal<scalar>();
        const scalar across = roughness_*rnd.template GaussNormal<scalar>();
        if
        (
            mag(inPlane) >= constant::mathematical::piByTwo
         || mag(across) >= constant::mathematical::piByTwo
        )
        {
            // A tilt past 90 degrees is no facet (tan would fold it back)
            continue;
        }
        const vector n = normalised(nw + ::tan(inPlane)*t + ::tan(across)*b);
        if (rnd.template sample01<scalar>() < (Uhat & n))
        {
            const vector Uafter = rebound(U, n);
            if ((Uafter & nw) < 0)
            {
                return Uafter;
            }
        }
    }
    // No tilt kept in 1000 draws: a grazing impact (a grain sliding along
    // the wall) on a wall so smooth that hardly any facet faces it; the
    // smooth wall's rebound, counted (info)
    ++smoothFallbacks_;
    return rebound(U, nw);
}


template<class CloudType>
bool Foam::BreakingRebound<CloudType>::sampleFragments
(
    typename CloudType::parcelType& p,
    const label j,
    const bool counting
)
{
    const scalar parcelVolume = p.nParticle()*p.volume();
    const label celli = p.cell();
    if (counting)
    {
        events_[j] += p.nParticle();
    }

    // The class the fragments go to, with the volume fractions of the
    // continuum (beta_jj: fragments that stay in the class)
    const breakageWeights& w = weights_[j];
    const scalar r = this->owner().rndGen().template sample01<scalar>();
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

    if (target < 0 && !dustSink_)
    {
        // Round-off at the top of the cumulative sum with finestClass
        target = findMax(w.volume);
    }
    if (target != j && counting)
    {
        lostVolume_[j][celli] += parcelVolume;
    }
    if (target < 0)
    {
        // Finer than the finest class: dust
        if (counting)
        {
            dustVolume_ += parcelVolume;
        }
        return false;
    }
    if (target != j)
    {
        const scalar di = species_[target].d;
        p.nParticle() *= pow3(p.d()/di);
        p.d() = di;
        if (counting)
        {
            bornVolume_[target][celli] += parcelVolume;
        }
    }
    return true;
}


template<class CloudType>
void Foam::BreakingRebound<CloudType>::splitFragments
(
    typename CloudType::parcelType& p,
    const label j,
    const scalar P,
    const bool counting,
    DynamicList<Tuple2<label, scalar>>& fragments
)
{
    const scalar parcelVolume = p.nParticle()*p.volume();
    const label celli = p.cell();

    // The volume shares of the fragments; without dust, round-off of the
    // fractions goes to the largest share (as sampled does)
    scalarList share(weights_[j].volume);
    const scalar rest = 1 - sum(share);
    if (!dustSink_)
    {
        share[findMax(share)] += rest;
    }

    const scalar lost = P*(1 - share[j])*parcelVolume;
    if (counting)
    {
        events_[j] += P*p.nParticle();
        lostVolume_[j][celli] += lost;
        if (dustSink_)
        {
            dustVolume_ += P*max(rest, scalar(0))*parcelVolume;
        }
    }
    forAll(share, i)
    {
        if (i != j && share[i] > 0)
        {
            const scalar volume = P*share[i]*parcelVolume;
            fragments.append(Tuple2<label, scalar>(i, volume));
            if (counting)
            {
                bornVolume_[i][celli] += volume;
            }
        }
    }
    p.nParticle() *= 1 - P*(1 - share[j]);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::BreakingRebound<CloudType>::BreakingRebound
(
    const dictionary& dict,
    CloudType& cloud
)
:
    // The case's mixture (which needs 0/n.<species>), used at construction
    BreakingRebound(dict, cloud, granularMixture(cloud.mesh()))
{}


template<class CloudType>
Foam::BreakingRebound<CloudType>::BreakingRebound
(
    const dictionary& dict,
    CloudType& cloud,
    const granularMixture& mixture
)
:
    PatchInteractionModel<CloudType>(dict, cloud, typeName),
    e_(this->coeffDict().template get<scalar>("e")),
    mu_(this->coeffDict().template get<scalar>("mu")),
    coulomb_(readCoulomb(this->coeffDict())),
    roughness_(readRoughness(this->coeffDict())),
    smoothFallbacks_(0),
    startTime_(this->coeffDict().getOrDefault("startTime", scalar(0))),
    species_(granularMixture::readSpecies(mixture)),
    kernel_(wallImpactCoeffs(mixture.subDict("breakage"))),
    dustSink_(false),
    expected_(readExpected(this->coeffDict())),
    bornVolume_(species_.size(), scalarField(cloud.mesh().nCells(), Zero)),
    lostVolume_(species_.size(), scalarField(cloud.mesh().nCells(), Zero)),
    impacts_(species_.size(), Zero),
    events_(species_.size(), Zero),
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

    // The fragment fractions of the continuum
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
    coulomb_(pim.coulomb_),
    roughness_(pim.roughness_),
    smoothFallbacks_(pim.smoothFallbacks_),
    startTime_(pim.startTime_),
    species_(pim.species_),
    kernel_(pim.kernel_),
    weights_(pim.weights_),
    dustSink_(pim.dustSink_),
    expected_(pim.expected_),
    bornVolume_(pim.bornVolume_),
    lostVolume_(pim.lostVolume_),
    impacts_(pim.impacts_),
    events_(pim.events_),
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

    // The counters from startTime on (a window with a full pipe, the
    // same steps as particlePass); the breakage itself at every time
    const bool counting = countingFrom(this->owner().mesh().time(), startTime_);

    // Expected: (species, volume) of the fragment parcels to add
    DynamicList<Tuple2<label, scalar>> fragments;
    bool brokenWhole = false;
    if (Un > 0)
    {
        const label j = parcelSpecies(species_, p.d(), p.rho());
        if (counting)
        {
            impacts_[j] += p.nParticle();
        }

        const scalar P = kernel_.probability(species_[j].d, Un, mag(Ut));
        if (P > 0 && expected_)
        {
            splitFragments(p, j, P, counting, fragments);
            // P = 1 (to double precision) and nothing stays in the class:
            // the parcel is all fragments and leaves the cloud below
            brokenWhole = !(p.nParticle() > 0);
        }
        else if
        (
            P > 0
         && this->owner().rndGen().template sample01<scalar>() < P
         && !sampleFragments(p, j, counting)
        )
        {
            // Turned to dust: the parcel leaves the cloud
            keepParticle = false;
            p.active(false);
            U = Zero;
            return true;
        }

        if (roughness_ > 0)
        {
            // The rebound from the wall's local inclination
            U = roughRebound(U, nw);
        }
        else if (coulomb_)
        {
            U = rebound(U, nw);
        }
        else
        {
            U -= (1 + e_)*Un*nw;
            U -= mu_*Ut;
        }
    }
    else if (!coulomb_)
    {
        // A parcel on the wall that does not move into it: the loss
        // fraction still applies (standardWallInteraction's rebound);
        // without a normal impulse Coulomb friction has nothing to act on
        U -= mu_*Ut;
    }
    U += Up;

    // The fragment parcels: copies of the rebounding parcel (same place,
    // cell, step fraction and velocity) with their class's diameter; the
    // cloud's move loop tracks them for the rest of this step
    for (const Tuple2<label, scalar>& f : fragments)
    {
        const granularSpecies& s = species_[f.first()];
        auto* fragment = new typename CloudType::parcelType(p);
        fragment->d() = s.d;
        fragment->nParticle() = f.second()/s.particleVolume();
        fragment->origId() = fragment->getNewParticleID();
        fragment->origProc() = Pstream::myProcNo();
        this->owner().addParticle(fragment);
    }
    if (brokenWhole)
    {
        keepParticle = false;
        p.active(false);
    }

    return true;
}


template<class CloudType>
void Foam::BreakingRebound<CloudType>::info(Ostream& os)
{
    PatchInteractionModel<CloudType>::info(os);
    // 12 digits: the volumes balance to round-off (born + dust = broken)
    const label precision = os.precision(12);
    os  << "    breakingRebound (fragments "
        << (expected_ ? "expected" : "sampled") << ") from t = "
        << startTime_ << " s over "
        << max(this->owner().mesh().time().value() - startTime_, scalar(0))
        << " s: per species impacts / breakage events / broken volume [m3]"
        << " / fragment volume born [m3]" << nl;
    forAll(species_, j)
    {
        os  << "      " << species_[j].name << ' '
            << returnReduce(impacts_[j], sumOp<scalar>()) << ' '
            << returnReduce(events_[j], sumOp<scalar>()) << ' '
            << gSum(lostVolume_[j]) << ' '
            << gSum(bornVolume_[j]) << nl;
    }
    os  << "      dust volume [m3] "
        << returnReduce(dustVolume_, sumOp<scalar>()) << nl;
    // After the counters: the readers of the log take the lines of five
    // entries that follow the header
    os  << "      wall: e " << e_ << ", mu " << mu_ << ", tangential "
        << (coulomb_ ? "coulomb" : "lossFraction") << ", roughness "
        << radToDeg(roughness_) << " deg" << nl;
    if (roughness_ > 0)
    {
        os  << "      rough wall " << radToDeg(roughness_) << " deg: impacts"
            << " rebounding from the smooth wall (no facet kept in 1000"
            << " draws) " << returnReduce(smoothFallbacks_, sumOp<label>())
            << nl;
    }
    os.precision(precision);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "granularMixture.H"

#include <algorithm>
#include "zeroGradientFvPatchFields.H"
#include "uniformDimensionedFields.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(granularMixture, 0);
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::List<Foam::granularSpecies> Foam::granularMixture::readSpecies
(
    const dictionary& granularProperties
)
{
    if (!granularProperties.isDict("species"))
    {
        FatalIOErrorInFunction(granularProperties)
            << "Missing dictionary 'species' in " << granularProperties.name()
            << nl << "    e.g. species { fine { d 1e-3; rho 2500; } }" << nl
            << exit(FatalIOError);
    }

    // The species are the keys of the block, in the order written: unique
    // by construction (the dictionary parser merges a repeated key)
    const dictionary& speciesDict = granularProperties.subDict("species");
    const wordList names(speciesDict.toc());

    if (names.empty())
    {
        FatalIOErrorInFunction(speciesDict)
            << "The dictionary 'species' in " << granularProperties.name()
            << " declares no species: at least one is needed" << nl
            << exit(FatalIOError);
    }

    List<granularSpecies> species(names.size());
    forAll(names, i)
    {
        if (!speciesDict.isDict(names[i]))
        {
            FatalIOErrorInFunction(speciesDict)
                << "Species entry '" << names[i] << "' must be a dictionary"
                << " with entries d and rho" << nl << exit(FatalIOError);
        }
        const dictionary& sd = speciesDict.subDict(names[i]);
        modelCoeffs::checkKeys(sd, {"d", "rho"});

        granularSpecies& s = species[i];
        s.name = names[i];
        // A bare number in SI units, or with its dimensions
        s.d = modelCoeffs::get(sd, "d", dimLength).value();
        s.rho = modelCoeffs::get(sd, "rho", dimDensity).value();

        if (!(s.d > 0))
        {
            FatalIOErrorInFunction(sd)
                << "Non-positive diameter 'd " << s.d << "' of species '"
                << s.name << "': d must be > 0 [m]" << nl
                << exit(FatalIOError);
        }
        if (!(s.rho > 0))
        {
            FatalIOErrorInFunction(sd)
                << "Non-positive density 'rho " << s.rho << "' of species '"
                << s.name << "': rho must be > 0 [kg/m3]" << nl
                << exit(FatalIOError);
        }
    }
    return species;
}


Foam::scalar Foam::granularMixture::readPhiMin
(
    const dictionary& granularProperties
)
{
    const scalar phiMin =
        granularProperties.getOrDefault<scalar>("phiMin", 0.05);
    if (!(phiMin > 0 && phiMin < 1))
    {
        FatalIOErrorInFunction(granularProperties)
            << "phiMin " << phiMin << " must lie in (0, 1)" << nl
            << exit(FatalIOError);
    }
    return phiMin;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::granularMixture::checkInitialFields() const
{
    // Fields the solver wrote hold round-off negatives at the level of the
    // linear solvers' tolerance (-1e-22 .. -1e-11 in cells the solids have
    // left); a restart from them must be accepted
    const scalar roundOff = 1e-10;
    forAll(n_, i)
    {
        const scalarField& ni = n_[i].primitiveField();
        forAll(ni, celli)
        {
            if (!std::isfinite(ni[celli]) || ni[celli] < -roundOff)
            {
                FatalErrorInFunction
                    << "Field " << n_[i].objectPath() << ": value "
                    << ni[celli] << " at cell " << celli
                    << " (centre " << mesh_.C()[celli] << ")." << nl
                    << "    A solids volume fraction must be finite and >= 0"
                    << " (round-off down to -" << roundOff << " accepted)"
                    << nl << exit(FatalError);
            }
        }
    }

    const scalarField& phi = nTotal_.primitiveField();
    forAll(phi, celli)
    {
        if (phi[celli] > 1 + 1e-10)
        {
            FatalErrorInFunction
                << "Total solids fraction sum of n.* = " << phi[celli]
                << " > 1 at cell " << celli << " (centre "
                << mesh_.C()[celli] << "): check the initial fields" << nl
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::granularMixture::granularMixture(const fvMesh& mesh)
:
    IOdictionary
    (
        IOobject
        (
            "granularProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ_IF_MODIFIED,
            IOobject::NO_WRITE
        )
    ),
    mesh_(mesh),
    nTotal_
    (
        IOobject
        (
            "nTotal",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar("s", dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    phiMin_(readPhiMin(*this)),
    writeFields_(getOrDefault<wordList>("writeFields", wordList()))
{
    const wordList validFields
    (
        {"T", "gammaDot", "dMean", "D", "nTotal", "S", "brokenVolume"}
    );
    for (const word& f : writeFields_)
    {
        if (!validFields.found(f))
        {
            FatalIOErrorInFunction(*this)
                << "Unknown entry '" << f << "' in writeFields; valid: "
                << validFields << nl << exit(FatalIOError);
        }
    }
    if (!writeField("nTotal"))
    {
        nTotal_.writeOpt() = IOobject::NO_WRITE;
    }

    const List<granularSpecies> species(readSpecies(*this));
    names_.setSize(species.size());
    d_.setSize(species.size());
    rho_.setSize(species.size());
    forAll(species, i)
    {
        names_[i] = species[i].name;
        d_[i] = species[i].d;
        rho_[i] = species[i].rho;
    }

    n_.setSize(names_.size());
    forAll(names_, i)
    {
        IOobject io
        (
            "n." + names_[i],
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::AUTO_WRITE
        );
        // A species without its field: say which species and where it is
        // declared (OpenFOAM's own error names only the file it looked for)
        if (!io.typeHeaderOk<volScalarField>(false))
        {
            FatalIOErrorInFunction(*this)
                << "Missing field " << io.name() << " of species '"
                << names_[i] << "' (declared in 'species' of " << objectPath()
                << "): every species needs its volume fraction field "
                << io.name() << " in the start time directory "
                << mesh.time().timeName() << nl << exit(FatalIOError);
        }
        n_.set(i, new volScalarField(io, mesh));
        if (n_[i].dimensions() != dimless)
        {
            FatalErrorInFunction
                << "Field " << n_[i].objectPath() << " has dimensions "
                << n_[i].dimensions() << "; a volume fraction is dimensionless"
                << " [0 0 0 0 0 0 0]" << nl << exit(FatalError);
        }
    }

    correct();
    checkInitialFields();

    Info<< "Granular mixture: " << names_.size() << " species" << nl;
    forAll(names_, i)
    {
        Info<< "    " << names_[i] << ": d = " << d_[i] << " m, rho = "
            << rho_[i] << " kg/m3" << nl;
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::granularMixture::dMin() const
{
    return min(d_);
}


Foam::scalar Foam::granularMixture::dMax() const
{
    return max(d_);
}


Foam::label Foam::granularMixture::coarsest() const
{
    label imax = 0;
    forAll(d_, i)
    {
        if (d_[i] > d_[imax])
        {
            imax = i;
        }
    }
    return imax;
}


Foam::labelList Foam::granularMixture::sizeOrder() const
{
    labelList order(identity(size()));
    std::stable_sort
    (
        order.begin(),
        order.end(),
        [this](const label a, const label b) { return d_[a] > d_[b]; }
    );
    return order;
}


const Foam::dictionary&
Foam::granularMixture::mechanismDict(const word& mechanism) const
{
    if (!isDict(mechanism))
    {
        FatalIOErrorInFunction(*this)
            << "Missing dictionary '" << mechanism << "' in " << objectPath()
            << nl << "    e.g. " << mechanism << " { model none; }" << nl
            << exit(FatalIOError);
    }
    return subDict(mechanism);
}


bool Foam::granularMixture::writeField(const word& fieldName) const
{
    return writeFields_.found(fieldName);
}


void Foam::granularMixture::correct()
{
    nTotal_ == dimensionedScalar("s", dimless, Zero);
    forAll(n_, i)
    {
        nTotal_ += n_[i];
    }
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::c(const label i) const
{
    // c = n_i/phi where phi > SMALL, 0 in empty cells; bounded to [0, 1]
    // because round-off leaves n_i ~ -1e-17 next to phi ~ 1e-16 in cells
    // that have just emptied, where the bare ratio is meaningless
    return
        min
        (
            max
            (
                n_[i]/max(nTotal_, dimensionedScalar("s", dimless, SMALL)),
                dimensionedScalar("zero", dimless, 0)
            ),
            dimensionedScalar("one", dimless, 1)
        )*pos(nTotal_ - SMALL);
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::coarseFraction() const
{
    tmp<volScalarField> tx
    (
        volScalarField::New
        (
            "x",
            mesh_,
            dimensionedScalar("s", dimless, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );

    const scalar dRange = dMax() - dMin();
    if (dRange <= 0)
    {
        // A monodisperse mixture has no coarse species
        return tx;
    }

    volScalarField& x = tx.ref();
    forAll(n_, i)
    {
        x += ((d_[i] - dMin())/dRange)*c(i);
    }
    return tx;
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::speciesMean
(
    const word& name,
    const scalarList& values,
    const dimensionSet& dims
) const
{
    tmp<volScalarField> tmean
    (
        volScalarField::New
        (
            name,
            mesh_,
            dimensionedScalar("s", dims, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    volScalarField& mean = tmean.ref();
    forAll(n_, i)
    {
        mean += dimensionedScalar("s", dims, values[i])*c(i);
    }

    // Empty cells take the mean of the species' values so that every law
    // stays finite there
    const scalar average = Foam::average(values);
    forAll(mean, celli)
    {
        if (nTotal_[celli] <= SMALL)
        {
            mean[celli] = average;
        }
    }
    mean.correctBoundaryConditions();
    return tmean;
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::dMean() const
{
    return speciesMean("dMean", d_, dimLength);
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::solidsDensity() const
{
    return speciesMean("rhoS", rho_, dimDensity);
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::phiRegularised() const
{
    return max(nTotal_, dimensionedScalar("s", dimless, phiMin_));
}


Foam::tmp<Foam::volScalarField> Foam::granularMixture::presence() const
{
    return min(nTotal_/phiMin_, dimensionedScalar("s", dimless, 1));
}


Foam::vector Foam::granularMixture::gravity() const
{
    const uniformDimensionedVectorField g
    (
        IOobject
        (
            "g",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    if (mag(g.value()) < VSMALL)
    {
        FatalErrorInFunction
            << "constant/g is zero: percolation and the kinematic bulk flow"
            << " act along gravity" << nl << exit(FatalError);
    }
    return g.value();
}


void Foam::granularMixture::checkFinite(const word& where) const
{
    forAll(n_, i)
    {
        const scalarField& ni = n_[i].primitiveField();
        forAll(ni, celli)
        {
            if (!std::isfinite(ni[celli]))
            {
                FatalErrorInFunction
                    << "Non-finite value " << ni[celli] << " of field "
                    << n_[i].name() << " at cell " << celli << " (centre "
                    << mesh_.C()[celli] << ") " << where << ", time "
                    << mesh_.time().timeName() << nl
                    << "    Stopping before anything is written." << nl
                    << exit(FatalError);
            }
        }
    }

    // More solids than space: a bulk flow that piles the species up (a
    // particle pass whose particles gather where they come to rest, a
    // kinematic field that converges) would go on filling without bound
    const scalarField& total = nTotal_.primitiveField();
    const label celli = findMax(total);
    const scalar worst = returnReduce
    (
        total.size() ? total[celli] : scalar(0), maxOp<scalar>()
    );
    // (1 + 1e-6: cases that carry fractions of a full bed, n summing to
    // 1, reach it to round-off)
    if (worst > 1 + 1e-6)
    {
        FatalErrorInFunction
            << "Solids volume fraction " << worst << " > 1 " << where
            << ", time " << mesh_.time().timeName() << ": the bulk flow"
            << " piles the species up beyond any packing (bulkFlow"
            << " particlePass: the pass's particles gather where they come"
            << " to rest; restitution, wall friction or a gas that cannot"
            << " carry them)" << nl
            << "    Stopping before this time is written." << nl
            << exit(FatalError);
    }
}


// ************************************************************************* //

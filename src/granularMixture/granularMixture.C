/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "granularMixture.H"
#include "zeroGradientFvPatchFields.H"
#include "uniformDimensionedFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(granularMixture, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::granularMixture::readSpecies()
{
    if (!found("species") || !isDict("species"))
    {
        FatalIOErrorInFunction(*this)
            << "Missing dictionary 'species' in " << objectPath() << nl
            << "    e.g. species { fine { d 1e-3; rho 2500; } }" << nl
            << exit(FatalIOError);
    }

    const dictionary& speciesDict = subDict("species");
    names_ = speciesDict.toc();

    if (names_.empty())
    {
        FatalIOErrorInFunction(speciesDict)
            << "The dictionary 'species' in " << objectPath()
            << " declares no species: at least one is needed" << nl
            << exit(FatalIOError);
    }

    d_.setSize(names_.size());
    rho_.setSize(names_.size());

    forAll(names_, i)
    {
        if (!speciesDict.isDict(names_[i]))
        {
            FatalIOErrorInFunction(speciesDict)
                << "Species entry '" << names_[i] << "' must be a dictionary"
                << " with entries d and rho" << nl << exit(FatalIOError);
        }
        const dictionary& sd = speciesDict.subDict(names_[i]);
        d_[i] = sd.get<scalar>("d");
        rho_[i] = sd.get<scalar>("rho");

        if (!(d_[i] > 0))
        {
            FatalIOErrorInFunction(sd)
                << "Non-positive diameter 'd " << d_[i] << "' of species '"
                << names_[i] << "': d must be > 0 [m]" << nl
                << exit(FatalIOError);
        }
        if (!(rho_[i] > 0))
        {
            FatalIOErrorInFunction(sd)
                << "Non-positive density 'rho " << rho_[i] << "' of species '"
                << names_[i] << "': rho must be > 0 [kg/m3]" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::granularMixture::checkInitialFields() const
{
    forAll(n_, i)
    {
        const scalarField& ni = n_[i].primitiveField();
        forAll(ni, celli)
        {
            if (!std::isfinite(ni[celli]) || ni[celli] < 0)
            {
                FatalErrorInFunction
                    << "Field " << n_[i].objectPath() << ": value "
                    << ni[celli] << " at cell " << celli
                    << " (centre " << mesh_.C()[celli] << ")." << nl
                    << "    A solids volume fraction must be finite and >= 0"
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
    phiMin_(getOrDefault<scalar>("phiMin", 0.05)),
    writeFields_(getOrDefault<wordList>("writeFields", wordList()))
{
    if (!(phiMin_ > 0 && phiMin_ < 1))
    {
        FatalIOErrorInFunction(*this)
            << "phiMin " << phiMin_ << " must lie in (0, 1)" << nl
            << exit(FatalIOError);
    }

    const wordList validFields({"T", "gammaDot", "dMean", "D", "nTotal"});
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

    readSpecies();

    n_.setSize(names_.size());
    forAll(names_, i)
    {
        n_.set
        (
            i,
            new volScalarField
            (
                IOobject
                (
                    "n." + names_[i],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::MUST_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh
            )
        );
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


Foam::tmp<Foam::volScalarField> Foam::granularMixture::dMean() const
{
    tmp<volScalarField> tdMean
    (
        volScalarField::New
        (
            "dMean",
            mesh_,
            dimensionedScalar("s", dimLength, Zero),
            zeroGradientFvPatchScalarField::typeName
        )
    );
    volScalarField& dm = tdMean.ref();
    forAll(n_, i)
    {
        dm += dimensionedScalar("s", dimLength, d_[i])*c(i);
    }

    // Empty cells take the mean of the species diameters so that every law
    // stays finite there
    const scalar dAvg = average(d_);
    forAll(dm, celli)
    {
        if (nTotal_[celli] <= SMALL)
        {
            dm[celli] = dAvg;
        }
    }
    dm.correctBoundaryConditions();
    return tdMean;
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
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "particlePassFlow.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"

namespace Foam
{
namespace bulkFlowModels
{
    defineTypeNameAndDebug(particlePass, 0);
    addToRunTimeSelectionTable(bulkFlowModel, particlePass, dictionary);
}
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::boolList Foam::bulkFlowModels::particlePass::gasVelocityClasses
(
    const granularMixture& mixture
)
{
    const wordList& names = mixture.names();
    boolList byGas(names.size(), false);
    const wordList gasClasses
    (
        coeffs_.getOrDefault<wordList>("gasVelocity", wordList())
    );
    if (gasClasses.empty())
    {
        return byGas;
    }

    const fvMesh& mesh = mixture.mesh();
    const scalar stokesLimit =
        coeffs_.getOrDefault<scalar>("stokesLimit", 0.2);
    modelCoeffs::checkNonNegative
    (
        coeffs_, "stokesLimit", stokesLimit, "Bulk flow"
    );
    const scalar muGas =
        modelCoeffs::get(coeffs_, "gasViscosity", dimDynamicViscosity).value();
    const scalar pipeD =
        modelCoeffs::get(coeffs_, "pipeDiameter", dimLength).value();
    if (!(muGas > 0) || !(pipeD > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "bulkFlow particlePass: gasViscosity " << muGas
            << " and pipeDiameter " << pipeD << " in " << coeffs_.name()
            << " must be > 0" << exit(FatalIOError);
    }

    IOobject gasIO
    (
        "phiGas",
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!gasIO.typeHeaderOk<surfaceScalarField>(false))
    {
        FatalIOErrorInFunction(coeffs_)
            << "bulkFlow particlePass: gasVelocity " << gasClasses
            << " needs the gas face flux in " << gasIO.objectPath()
            << " (the gas stage's phi; tutorials/pipeBend/Allrun copies it)"
            << exit(FatalIOError);
    }
    gasPhi_.reset(new surfaceScalarField(gasIO, mesh));
    noFluxThroughWalls(gasPhi_.ref());
    const scalar gasSpeed =
        gMax(mag(gasPhi_->primitiveField())/mesh.magSf().primitiveField());
    if (!(gasSpeed > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "bulkFlow particlePass: gasVelocity " << gasClasses
            << " but the gas flux " << gasIO.objectPath() << " is zero"
            << " everywhere: nothing would carry them" << exit(FatalIOError);
    }

    for (const word& name : gasClasses)
    {
        const label i = names.find(name);
        if (i < 0)
        {
            FatalIOErrorInFunction(coeffs_)
                << "bulkFlow particlePass: gasVelocity names " << name
                << ", which is not a species; species: " << names
                << exit(FatalIOError);
        }
        // Stokes drag: the slip Reynolds number of a particle that follows
        // the gas is small, and Stokes's response time is the longest
        const scalar tauP = mixture.rho(i)*sqr(mixture.d(i))/(18*muGas);
        const scalar stokes = tauP*gasSpeed/pipeD;
        if (stokes > stokesLimit)
        {
            FatalIOErrorInFunction(coeffs_)
                << "bulkFlow particlePass: gasVelocity " << name
                << ": Stokes number " << stokes << " (tau_p " << tauP
                << " s, gas speed " << gasSpeed << " m/s, pipeDiameter "
                << pipeD << " m) is above stokesLimit " << stokesLimit
                << ": the class does not follow the gas. Take it out of"
                << " gasVelocity (it then moves with its phiPass."
                << name << " from the particle pass)" << exit(FatalIOError);
        }
        byGas[i] = true;
        Info<< "Bulk flow: particlePass: " << name << " moves with the gas"
            << " (Stokes number " << stokes << " <= " << stokesLimit << ")"
            << endl;
    }
    return byGas;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkFlowModels::particlePass::particlePass
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    bulkFlowModel
    (
        typeName,
        modelCoeffs::checked
        (
            dict,
            typeName,
            {"gasVelocity", "stokesLimit", "gasViscosity", "pipeDiameter"}
        ),
        mixture,
        false
    ),
    speciesPhi_(mixture.size()),
    gasPhi_(nullptr)
{
    const fvMesh& mesh = mixture.mesh();
    const boolList byGas(gasVelocityClasses(mixture));

    auto passHeader = [&mesh](const word& name)
    {
        IOobject io
        (
            name,
            mesh.time().timeName(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        if (!io.typeHeaderOk<volScalarField>(false))
        {
            FatalErrorInFunction
                << "bulkFlow particlePass: no file " << io.objectPath()
                << nl << "    Run the particle pass (cloud function object"
                << " particlePass of libsegregationDegradationLagrangian)"
                << " and copy its alphaPass.*, UPass.* and phiPass.* to the"
                << " start time (tutorials/pipeBend/Allrun)"
                << exit(FatalError);
        }
        return io;
    };

    volScalarField alphaSum
    (
        IOobject("alphaPassSum", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar(dimless, Zero)
    );
    volVectorField alphaU
    (
        IOobject("alphaUPass", mesh.time().timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );

    // The species flux, registered and written as phi.<species>
    auto setSpeciesPhi = [&](const label i, const surfaceScalarField& source)
    {
        speciesPhi_.set
        (
            i,
            new surfaceScalarField
            (
                IOobject
                (
                    "phi." + mixture.names()[i],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                source
            )
        );
    };

    forAll(mixture.names(), i)
    {
        const word& name = mixture.names()[i];
        if (byGas[i])
        {
            setSpeciesPhi(i, gasPhi_());
            continue;
        }
        const volScalarField alpha(passHeader("alphaPass." + name), mesh);
        const volVectorField Ui(passHeader("UPass." + name), mesh);
        alphaSum += alpha;
        alphaU += alpha*Ui;

        setSpeciesPhi
        (
            i, surfaceScalarField(passHeader("phiPass." + name), mesh)
        );

        noFluxThroughWalls(speciesPhi_[i]);
    }

    forAll(U_, celli)
    {
        if (alphaSum[celli] > 0)
        {
            U_[celli] = alphaU[celli]/alphaSum[celli];
        }
    }
    U_.correctBoundaryConditions();
    updateFluxFromU();

    Info<< "Bulk flow: particle pass, one face flux per species"
        << " (phi.<species>) from " << mesh.time().timeName() << nl << endl;
}


// ************************************************************************* //

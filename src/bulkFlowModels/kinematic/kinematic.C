/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "kinematic.H"
#include "scratchField.H"
#include "openPatches.H"
#include "addToRunTimeSelectionTable.H"
#include "fvm.H"
#include "fvc.H"
#include "convectionScheme.H"
#include "laplacianScheme.H"
#include "IStringStream.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "wallFvPatch.H"
#include "mathematicalConstants.H"
#include "modelCoeffs.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bulkFlowModels
{
    defineTypeNameAndDebug(kinematic, 0);
    addToRunTimeSelectionTable(bulkFlowModel, kinematic, dictionary);
}
}


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * * //

namespace
{

// Solver controls from fvSolution if given there, else robust defaults
Foam::dictionary solverControls
(
    const Foam::fvMesh& mesh,
    const Foam::word& name,
    const bool symmetric
)
{
    if (mesh.solutionDict().subOrEmptyDict("solvers").found(name))
    {
        return mesh.solverDict(name);
    }
    Foam::dictionary d;
    d.add("solver", symmetric ? "PCG" : "PBiCGStab");
    d.add("preconditioner", symmetric ? "DIC" : "DILU");
    d.add("tolerance", 1e-12);
    d.add("relTol", 0.0);
    d.add("maxIter", 5000);
    return d;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::bulkFlowModels::kinematic::readDischargeRate()
{
    const fvMesh& mesh = mixture_.mesh();

    scalar meshOutletArea = 0;
    for (const label patchi : outletPatches_)
    {
        meshOutletArea += gSum(mesh.magSf().boundaryField()[patchi]);
    }

    const word rateType(coeffs_.get<word>("dischargeRate"));

    // Entries that only the other discharge rate reads are refused, not
    // silently ignored
    const wordList unread
    (
        rateType == "beverloo"
      ? wordList({"Q", "fullOutletArea"})
      : wordList({"beverlooCoeffs"})
    );
    for (const word& key : unread)
    {
        if (coeffs_.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Entry '" << key << "' is not read with dischargeRate "
                << rateType << " (Q and fullOutletArea go with given;"
                << " with beverloo, fullOutletArea belongs in beverlooCoeffs)"
                << nl << exit(FatalIOError);
        }
    }

    if (rateType == "given")
    {
        Q_ = modelCoeffs::get(coeffs_, "Q", dimVolume/dimTime).value();
        // Optional, default the outlet patches' area: the mesh holds the
        // full geometry
        fullOutletArea_ = modelCoeffs::getOrDefault
        (
            coeffs_,
            "fullOutletArea",
            dimArea,
            meshOutletArea
        ).value();
    }
    else if (rateType == "beverloo")
    {
        const dictionary& bev = coeffs_.subDict("beverlooCoeffs");
        modelCoeffs::checkKeys
        (
            bev,
            {"C", "k", "D0", "hopperHalfAngle", "fullOutletArea"}
        );
        // Optional, defaults Beverloo's C 0.58 and k 1.5 (dimensionless)
        const scalar C = bev.getOrDefault<scalar>("C", 0.58);
        const scalar k = bev.getOrDefault<scalar>("k", 1.5);
        const scalar D0 = modelCoeffs::get(bev, "D0", dimLength).value();
        if (!(C > 0) || !(k >= 0))
        {
            FatalIOErrorInFunction(bev)
                << "Beverloo: 'C " << C << "' must be > 0 and 'k " << k
                << "' >= 0" << nl << exit(FatalIOError);
        }

        // Mean diameter of the initial mixture, weighted by solids volume
        const volScalarField dMean(mixture_.dMean());
        const scalar solids = gSum(mixture_.nTotal().primitiveField()*mesh.V());
        const scalar d =
            solids > VSMALL
          ? gSum(dMean.primitiveField()*mixture_.nTotal().primitiveField()*mesh.V())
           /solids
          : average(dMean.primitiveField());

        if (!(D0 - k*d > 0))
        {
            FatalIOErrorInFunction(bev)
                << "Beverloo: D0 - k d = " << D0 << " - " << k << "*" << d
                << " <= 0: the outlet (D0) is too small for the particles"
                << nl << exit(FatalIOError);
        }

        Q_ = C*sqrt(mag(mixture_.gravity()))*pow(D0 - k*d, 2.5);

        // Optional, no default: without it the silo has a flat bottom and
        // the hopper factor (tan theta)^-0.35 is left out
        if (bev.found("hopperHalfAngle"))
        {
            const scalar thetaDeg = bev.get<scalar>("hopperHalfAngle");
            if (!(thetaDeg > 0 && thetaDeg < 90))
            {
                FatalIOErrorInFunction(bev)
                    << "'hopperHalfAngle " << thetaDeg << "' must lie in"
                    << " (0, 90) [degrees from the vertical]" << nl
                    << exit(FatalIOError);
            }
            Q_ *= pow(tan(degToRad(thetaDeg)), -0.35);
        }
        // Optional, default the area of a circular outlet pi D0^2/4 (the
        // full geometry of an axisymmetric silo)
        fullOutletArea_ = modelCoeffs::getOrDefault
        (
            bev,
            "fullOutletArea",
            dimArea,
            constant::mathematical::pi*sqr(D0)/4
        ).value();
        Info<< "    Beverloo discharge rate Q = " << Q_
            << " m3/s (bulk volume, full outlet), mean d = " << d << nl;
    }
    else
    {
        FatalIOErrorInFunction(coeffs_)
            << "Unknown dischargeRate '" << rateType
            << "'; valid: (beverloo given)" << nl << exit(FatalIOError);
    }

    if (!(Q_ > 0) || !(fullOutletArea_ > 0) || !(meshOutletArea > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Discharge rate Q " << Q_ << ", fullOutletArea "
            << fullOutletArea_ << " and the outlet patches' area "
            << meshOutletArea << " must all be > 0" << nl
            << exit(FatalIOError);
    }

    // The share of the geometry the mesh holds (e.g. a wedge)
    Q_ *= meshOutletArea/fullOutletArea_;
}


void Foam::bulkFlowModels::kinematic::solveVelocity()
{
    const fvMesh& mesh = mixture_.mesh();

    const vector gHat(mixture_.gravity()/mag(mixture_.gravity()));

    // Downward speed v: 1 on the outlets (scaled later), no flux of v
    // through walls
    wordList vTypes
    (
        mesh.boundary().size(),
        zeroGradientFvPatchScalarField::typeName
    );
    for (const label patchi : outletPatches_)
    {
        vTypes[patchi] = fixedValueFvPatchScalarField::typeName;
    }

    tmp<volScalarField> vField
    (
        scratchField(mesh, "vKinematic", dimVelocity, vTypes)
    );
    volScalarField& v = vField.ref();
    for (const label patchi : outletPatches_)
    {
        v.boundaryFieldRef()[patchi] == scalar(1);
    }

    // The "upward" flux of the marching equation. Zero through walls: the
    // conservative form then keeps the integral of v over every horizontal
    // section constant (the discharge rate), whatever the wall's slope
    surfaceScalarField phiUp("phiUp", -(mesh.Sf() & gHat));
    forAll(mesh.boundary(), patchi)
    {
        if (isA<wallFvPatch>(mesh.boundary()[patchi]))
        {
            phiUp.boundaryFieldRef()[patchi] = Zero;
        }
    }
    const surfaceTensorField Bh
    (
        IOobject
        (
            "Bh",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedTensor("t", dimLength, B_*(I - sqr(gHat)))
    );

    tmp<fv::convectionScheme<scalar>> upwindScheme
    (
        fv::convectionScheme<scalar>::New
        (
            mesh,
            phiUp,
            IStringStream("Gauss upwind")()
        )
    );
    tmp<fv::laplacianScheme<scalar, tensor>> lapScheme
    (
        fv::laplacianScheme<scalar, tensor>::New
        (
            mesh,
            IStringStream("Gauss linear corrected")()
        )
    );

    for (int corr = 0; corr < 3; ++corr)
    {
        fvScalarMatrix vEqn
        (
            upwindScheme->fvmDiv(phiUp, v)
          - lapScheme->fvmLaplacian(Bh, v)
        );
        vEqn.solve(solverControls(mesh, "vKinematic", false));
    }

    U_ = dimensionedScalar("s", dimLength, B_)*((I - sqr(gHat)) & fvc::grad(v))
       + v*gHat;
    U_.correctBoundaryConditions();
    updateFluxFromU();

    // Project the flux onto a discretely divergence-free one
    wordList pTypes
    (
        mesh.boundary().size(),
        zeroGradientFvPatchScalarField::typeName
    );
    for (const label patchi : openPatches(mesh))
    {
        pTypes[patchi] = fixedValueFvPatchScalarField::typeName;
    }
    tmp<volScalarField> pKField
    (
        scratchField(mesh, "pKinematic", dimArea/dimTime, pTypes)
    );
    volScalarField& pK = pKField.ref();

    mesh.setFluxRequired(pK.name());
    const dictionary pControls(solverControls(mesh, "pKinematic", true));
    tmp<fv::laplacianScheme<scalar, scalar>> pLapScheme
    (
        fv::laplacianScheme<scalar, scalar>::New
        (
            mesh,
            IStringStream("Gauss linear corrected")()
        )
    );
    const surfaceScalarField unity
    (
        IOobject("unity", mesh.time().timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1)
    );
    const surfaceScalarField phiNT(phi_);
    for (int corr = 0; corr < 4; ++corr)
    {
        fvScalarMatrix pEqn
        (
            pLapScheme->fvmLaplacian(unity, pK)
         == fvc::div(phiNT)
        );
        pEqn.solve(pControls);
        phi_ = phiNT - pEqn.flux();
    }

    // Scale to the discharge rate
    scalar outflow = 0;
    for (const label patchi : outletPatches_)
    {
        outflow += gSum(phi_.boundaryField()[patchi]);
    }
    if (!(outflow > 0))
    {
        FatalErrorInFunction
            << "The kinematic flow leaves through the outlet patches at rate "
            << outflow << ": check outletPatches and constant/g" << nl
            << exit(FatalError);
    }
    phi_ *= Q_/outflow;

    // U for output and for the shear rate: the Nedderman-Tuzun velocity
    // scaled to the same discharge (smooth, where a reconstruction of the
    // projected flux is not on the cells next to the outlet)
    scalar outflowNT = 0;
    for (const label patchi : outletPatches_)
    {
        outflowNT += gSum(phiNT.boundaryField()[patchi]);
    }
    U_ *= Q_/outflowNT;
    U_.correctBoundaryConditions();

    const volScalarField divPhi(fvc::div(phi_));
    Info<< "    kinematic bulk flow: outlet flux " << Q_
        << " m3/s on the mesh, max |div(phi)|*V/Q = "
        << gMax(mag(divPhi.primitiveField())*mesh.V())/Q_ << nl << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkFlowModels::kinematic::kinematic
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
            {
                "B", "outletPatches", "dischargeRate", "Q",
                "fullOutletArea", "beverlooCoeffs"
            }
        ),
        mixture,
        false
    ),
    B_(modelCoeffs::get(coeffs_, "B", dimLength).value()),
    outletPatches_(),
    Q_(0),
    fullOutletArea_(0)
{
    const fvMesh& mesh = mixture.mesh();

    if (!(B_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Kinematic constant 'B " << B_ << "' must be > 0 [m]" << nl
            << exit(FatalIOError);
    }

    const wordRes outletNames(coeffs_.get<wordRes>("outletPatches"));
    outletPatches_ =
        mesh.boundaryMesh().patchSet(outletNames).sortedToc();
    if (outletPatches_.empty())
    {
        FatalIOErrorInFunction(coeffs_)
            << "outletPatches " << outletNames << " match no patch; patches: "
            << mesh.boundaryMesh().names() << nl << exit(FatalIOError);
    }

    readDischargeRate();
    solveVelocity();
}


// ************************************************************************* //

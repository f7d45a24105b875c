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
#include <sstream>
#include "IStringStream.H"
#include "OStringStream.H"
#include "zeroGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "mathematicalConstants.H"
#include "modelCoeffs.H"
#include "volFields.H"

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

void Foam::bulkFlowModels::kinematic::readGeometry()
{
    const fvMesh& mesh = mixture_.mesh();
    const vector gHat(normalised(mixture_.gravity()));

    // The outlets must face down: a gravity along the wrong axis (e.g. a
    // case's constant/g copied to a mesh with another vertical) leaves
    // nothing to march the kinematic equation along
    vector outletNormal(Zero);
    for (const label patchi : outletPatches_)
    {
        outletNormal += sum(mesh.Sf().boundaryField()[patchi]);
    }
    reduce(outletNormal, sumOp<vector>());
    outletNormal /= max(mag(outletNormal), VSMALL);
    if (!((outletNormal & gHat) > 0.5))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Gravity " << mixture_.gravity() << " (constant/g) does not"
            << " point out of the outlet patches " << outletPatches_
            << " (their mean outward normal is "
            << outletNormal << "): the kinematic flow runs"
            << " down along g to the outlets. Check constant/g and"
            << " 'outletPatches'" << nl << exit(FatalIOError);
    }

    // The empty space the discharge leaves comes in through an open patch
    // that is not an outlet (the silo's top)
    label nInlets = 0;
    for (const label patchi : openPatches(mesh))
    {
        if (!outletPatches_.found(patchi))
        {
            ++nInlets;
        }
    }
    if (!nInlets)
    {
        FatalIOErrorInFunction(coeffs_)
            << "The mesh's open patches (type patch) are only the outlets "
            << outletPatches_ << ": the space the discharge leaves is"
            << " filled through an open patch above the material (e.g. the"
            << " silo's top, type patch); patches: "
            << mesh.boundaryMesh().names() << nl << exit(FatalIOError);
    }

    geometry_.reset(new siloGeometry(mesh, outletPatches_, gHat));

    // A declared geometry must be the mesh's; a 3-D slab may be declared
    // planar
    if (coeffs_.found("geometry"))
    {
        const word declared(coeffs_.get<word>("geometry"));
        if (!siloGeometry::kindNames.found(declared))
        {
            FatalIOErrorInFunction(coeffs_)
                << "Unknown geometry '" << declared << "'; valid: "
                << siloGeometry::kindNames << nl << exit(FatalIOError);
        }
        const siloGeometry::kind k = siloGeometry::kindNames[declared];
        if
        (
            k == siloGeometry::kind::planar
         && geometry_->geometry() == siloGeometry::kind::threeD
        )
        {
            geometry_->declarePlanar();
        }
        else if (k != geometry_->geometry())
        {
            FatalIOErrorInFunction(coeffs_)
                << "'geometry " << declared << "' does not match the mesh,"
                << " which is "
                << siloGeometry::kindNames[geometry_->geometry()] << " ("
                << geometry_->kindReason().c_str() << "). Only a 3-D slab"
                << " may be declared planar" << nl << exit(FatalIOError);
        }
    }

    const siloGeometry& geo = geometry_();
    Info<< "    silo geometry " << siloGeometry::kindNames[geo.geometry()]
        << " (" << geo.kindReason().c_str() << "); orifice "
        << (geo.throat() ? "at the throat, height " : "at the outlet patches, height ")
        << geo.orificeHeight() << " m: "
        << (geo.geometry() == siloGeometry::kind::planar ? "slot width b = " : "D0 = ")
        << geo.orificeSize() << " m";
    if (geo.geometry() == siloGeometry::kind::planar)
    {
        Info<< ", slot length L = " << geo.slotLength() << " m";
    }
    Info<< ", area on the mesh " << geo.orificeArea() << " m2" << nl;
}


void Foam::bulkFlowModels::kinematic::readDischargeRate()
{
    const siloGeometry& geo = geometry_();
    const bool planar = (geo.geometry() == siloGeometry::kind::planar);

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

    scalar fullOutletArea = geo.fullOrificeArea();

    if (rateType == "given")
    {
        Q_ = modelCoeffs::get(coeffs_, "Q", dimVolume/dimTime).value();
        // Optional, default the full geometry's orifice
        fullOutletArea = modelCoeffs::getOrDefault
        (
            coeffs_,
            "fullOutletArea",
            dimArea,
            fullOutletArea
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
        // Optional, defaults Beverloo's C 0.58 (circular orifice) or 1.03
        // (slot, Nedderman 1992) and k 1.5 (dimensionless)
        const scalar C = bev.getOrDefault<scalar>("C", planar ? 1.03 : 0.58);
        const scalar k = bev.getOrDefault<scalar>("k", 1.5);
        if (!(C > 0) || !(k >= 0))
        {
            FatalIOErrorInFunction(bev)
                << "Beverloo: 'C " << C << "' must be > 0 and 'k " << k
                << "' >= 0" << nl << exit(FatalIOError);
        }

        // The orifice comes from the mesh; a D0 given must be it
        const scalar D0 = geo.orificeSize();
        if (bev.found("D0"))
        {
            const scalar D0given =
                modelCoeffs::get(bev, "D0", dimLength).value();
            if (!(mag(D0given - D0) <= 0.02*D0))
            {
                FatalIOErrorInFunction(bev)
                    << "'D0 " << D0given << "' does not match the mesh's"
                    << " orifice, " << (planar ? "a slot " : "")
                    << D0 << " m wide ("
                    << (geo.throat() ? "the throat at height " : "the outlet patches at height ")
                    << geo.orificeHeight() << " m, "
                    << siloGeometry::kindNames[geo.geometry()]
                    << " geometry): remove D0 or correct it (2 % tolerance)"
                    << nl << exit(FatalIOError);
            }
        }

        // Mean diameter of the initial mixture, weighted by solids volume
        const fvMesh& mesh = mixture_.mesh();
        const volScalarField dMean(mixture_.dMean());
        const scalar solids = gSum(mixture_.nTotal().primitiveField()*mesh.V());
        const scalar d =
            solids > VSMALL
          ? gSum(dMean.primitiveField()*mixture_.nTotal().primitiveField()*mesh.V())
           /solids
          : gAverage(dMean.primitiveField());

        if (!(D0 - k*d > 0))
        {
            FatalIOErrorInFunction(bev)
                << "Beverloo: D0 - k d = " << D0 << " - " << k << "*" << d
                << " <= 0: the mesh's orifice is too small for the particles"
                << " (no flow)" << nl << exit(FatalIOError);
        }

        const scalar sqrtG = sqrt(mag(mixture_.gravity()));
        if (planar)
        {
            Q_ = C*sqrtG*geo.slotLength()*pow(D0 - k*d, 1.5);
        }
        else
        {
            Q_ = C*sqrtG*pow(D0 - k*d, 2.5);
        }

        // Optional, no default: without it the silo has a flat bottom and
        // the hopper factor (tan theta)^-0.35 is left out
        if (bev.found("hopperHalfAngle"))
        {
            if (planar)
            {
                FatalIOErrorInFunction(bev)
                    << "'hopperHalfAngle': the factor (tan theta)^-0.35 is"
                    << " for conical hoppers; for a planar (wedge-shaped)"
                    << " hopper give a C of its own instead" << nl
                    << exit(FatalIOError);
            }
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
        // Optional, default the full geometry's orifice
        fullOutletArea = modelCoeffs::getOrDefault
        (
            bev,
            "fullOutletArea",
            dimArea,
            fullOutletArea
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

    if (!(Q_ > 0) || !(fullOutletArea > 0) || !(geo.orificeArea() > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Discharge rate Q " << Q_ << ", fullOutletArea "
            << fullOutletArea << " and the mesh's orifice area "
            << geo.orificeArea() << " must all be > 0" << nl
            << exit(FatalIOError);
    }

    // The share of the geometry the mesh holds (e.g. a wedge)
    Qmesh_ = Q_*geo.orificeArea()/fullOutletArea;
}


Foam::string Foam::bulkFlowModels::kinematic::readMarchingScheme
(
    const dictionary& coeffs
)
{
    if (!coeffs.found("marchingScheme"))
    {
        return "Gauss linearUpwind grad(vKinematic)";
    }
    // As fvSchemes writes it (words) or quoted as one string
    ITstream& is = coeffs.lookup("marchingScheme");
    OStringStream os;
    for (label i = 0; i < is.size(); ++i)
    {
        const token& tok = is[i];
        if (i)
        {
            os << ' ';
        }
        if (tok.isWord())
        {
            os << tok.wordToken().c_str();
        }
        else if (tok.isString())
        {
            os << tok.stringToken().c_str();
        }
        else
        {
            os << tok;
        }
    }
    return os.str();
}


void Foam::bulkFlowModels::kinematic::solveNeddermanTuzun()
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
    noFluxThroughWalls(phiUp);
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

    // The marching direction's derivative: a convection scheme along
    // phiUp. Upwind is first order in the cell height, and so is every
    // result downstream of the flow (silo2D's outlet composition converges
    // at order 1.0 in the mesh with it); linearUpwind is its second-order
    // form. Its explicit part is iterated to convergence (deferred
    // correction). Its arguments (linearUpwind's gradient name) are read
    // here: a mistake is reported against marchingScheme, not a bare stream
    tmp<fv::convectionScheme<scalar>> marchScheme;
    {
        const bool ioThrowing = FatalIOError.throwExceptions();
        const bool throwing = FatalError.throwExceptions();
        string problem;
        try
        {
            marchScheme = fv::convectionScheme<scalar>::New
            (
                mesh,
                phiUp,
                IStringStream(marchingScheme_)()
            );
        }
        catch (const Foam::error& err)
        {
            problem = err.message();
        }
        FatalIOError.throwExceptions(ioThrowing);
        FatalError.throwExceptions(throwing);
        if (!problem.empty())
        {
            FatalIOErrorInFunction(coeffs_)
                << "marchingScheme " << marchingScheme_ << ": " << problem
                << nl << exit(FatalIOError);
        }
    }
    tmp<fv::laplacianScheme<scalar, tensor>> lapScheme
    (
        fv::laplacianScheme<scalar, tensor>::New
        (
            mesh,
            IStringStream("Gauss linear corrected")()
        )
    );

    const dictionary controls(solverControls(mesh, "vKinematic", false));
    // lduMatrix::solver's own default where the entry is absent
    const scalar tolerance = controls.getOrDefault<scalar>("tolerance", 1e-6);
    // Three solves at least (non-orthogonal correction), then until the
    // explicit part has settled: a solve that starts at the tolerance (or
    // 1e-11 of the first solve's residual) or has nothing left to do. Each
    // solve from the third on must converge, or the run stops at once
    const label maxCorr = 100;
    scalar firstResidual = -1;
    for (label corr = 0; ; ++corr)
    {
        fvScalarMatrix vEqn
        (
            marchScheme->fvmDiv(phiUp, v)
          - lapScheme->fvmLaplacian(Bh, v)
        );
        const solverPerformance perf = vEqn.solve(controls);
        if (corr == 0)
        {
            firstResidual = perf.initialResidual();
        }
        if (corr >= 2 && !perf.converged())
        {
            FatalErrorInFunction
                << "The kinematic equation (vKinematic) did not converge:"
                << " final residual " << perf.finalResidual() << " after "
                << perf.nIterations() << " iterations (solver "
                << controls.get<word>("solver") << " in system/fvSolution"
                << " or the default). Check that constant/g points down"
                << " the silo to the outlet patches" << nl
                << exit(FatalError);
        }
        const bool settled =
            perf.nIterations() == 0
         || perf.initialResidual() <= max(10*tolerance, 1e-11*firstResidual);
        if (corr >= 2 && settled)
        {
            break;
        }
        if (corr == maxCorr)
        {
            FatalErrorInFunction
                << "The explicit part of marchingScheme " << marchingScheme_
                << " did not settle in " << maxCorr + 1 << " solves of the"
                << " kinematic equation (vKinematic): initial residual "
                << perf.initialResidual() << ", first "
                << firstResidual << ". Use \"Gauss upwind\" or a linear"
                << " gradient for grad(vKinematic) in gradSchemes" << nl
                << exit(FatalError);
        }
    }

    UNT_ = dimensionedScalar("s", dimLength, B_)*((I - sqr(gHat)) & fvc::grad(v))
       + v*gHat;
    UNT_.correctBoundaryConditions();
    phiNT_ = fvc::interpolate(UNT_) & mesh.Sf();
    noFluxThroughWalls(phiNT_);

    // Scaled to the discharge (smooth U, where a reconstruction of the
    // projected flux is not on the cells next to the outlet)
    scalar outflowNT = 0;
    for (const label patchi : outletPatches_)
    {
        outflowNT += gSum(phiNT_.boundaryField()[patchi]);
    }
    if (!(outflowNT > 0))
    {
        FatalErrorInFunction
            << "The kinematic flow leaves through the outlet patches at rate "
            << outflowNT << ": check outletPatches and constant/g" << nl
            << exit(FatalError);
    }
    UNT_ *= Qmesh_/outflowNT;
    UNT_.correctBoundaryConditions();
    phiNT_ *= Qmesh_/outflowNT;
}


Foam::scalar Foam::bulkFlowModels::kinematic::surfaceLevel() const
{
    const fvMesh& mesh = mixture_.mesh();
    const scalar material =
        gSum(mixture_.nTotal().primitiveField()*mesh.V())/packedFraction_;
    return geometry_->levelOfVolume(material);
}


Foam::scalar Foam::bulkFlowModels::kinematic::packedLevel() const
{
    // The bottom of the lowest cell that is not packed (2 % short)
    const scalarField& nTotal = mixture_.nTotal().primitiveField();
    scalar level = geometry_->zMax();
    forAll(nTotal, celli)
    {
        if (nTotal[celli] < 0.98*packedFraction_)
        {
            level = min(level, geometry_->cellBottom(celli));
        }
    }
    return returnReduce(level, minOp<scalar>());
}


void Foam::bulkFlowModels::kinematic::project(const surfaceScalarField& flux)
{
    const fvMesh& mesh = mixture_.mesh();

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
    for (int corr = 0; corr < 4; ++corr)
    {
        fvScalarMatrix pEqn
        (
            pLapScheme->fvmLaplacian(unity, pK)
         == fvc::div(flux)
        );
        pEqn.solve(pControls);
        phi_ = flux - pEqn.flux();
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
    phi_ *= Qmesh_/outflow;
}


void Foam::bulkFlowModels::kinematic::setFlow
(
    const scalar zs,
    const scalar zPacked
)
{
    const fvMesh& mesh = mixture_.mesh();
    const siloGeometry& geo = geometry_();
    const vector gHat(normalised(mixture_.gravity()));

    // The plug: the empty space above the surface and the material just
    // below it descend at Q/A(z_s), A the section at the surface (or, with
    // the surface at or below the orifice, the orifice)
    const scalar zCut = max(zs, geo.orificeHeight());
    scalar area = geo.sectionArea(min(zCut, geo.zMax() - 1e-9*(geo.zMax() - geo.zMin())));
    if (!(area > VSMALL))
    {
        area = geo.orificeArea();
    }
    const vector Uplug((Qmesh_/area)*gHat);

    // Depth of the layer in which the flow turns from the plug into the
    // Nedderman-Tuzun field: the section's radius or half width
    scalar layer = surfaceLayer_;
    if (!(layer > 0))
    {
        const scalar fullArea = area*geo.fullOrificeArea()/geo.orificeArea();
        layer =
            geo.geometry() == siloGeometry::kind::planar
          ? 0.5*area/geo.slotLength()
          : sqrt(fullArea/constant::mathematical::pi);
    }

    // Weight of the Nedderman-Tuzun field: 0 from the top of the packed
    // material up, 1 deeper than the layer below it. The shear of the
    // turn stays in packed material, so neither the core's draw nor the
    // shear-driven diffusion acts on the partly filled cells of the surface
    const scalar zTurn = min(zs, zPacked);
    auto weight = [zTurn, layer](const scalar z)
    {
        return min(max((zTurn - z)/layer, scalar(0)), scalar(1));
    };

    surfaceScalarField flux(phiNT_);
    const surfaceScalarField plugFlux(mesh.Sf() & Uplug);
    const surfaceVectorField& Cf = mesh.Cf();
    forAll(flux, facei)
    {
        const scalar w = weight(geo.height(Cf[facei]));
        flux[facei] = w*phiNT_[facei] + (1 - w)*plugFlux[facei];
    }
    forAll(mesh.boundary(), patchi)
    {
        scalarField& fp = flux.boundaryFieldRef()[patchi];
        const scalarField& nt = phiNT_.boundaryField()[patchi];
        const scalarField& pl = plugFlux.boundaryField()[patchi];
        const vectorField& cf = Cf.boundaryField()[patchi];
        forAll(fp, facei)
        {
            const scalar w = weight(geo.height(cf[facei]));
            fp[facei] = w*nt[facei] + (1 - w)*pl[facei];
        }
    }

    noFluxThroughWalls(flux);

    project(flux);

    // U for output and for the shear rate: the same blend of the
    // (smooth) velocities
    const volVectorField& C = mesh.C();
    forAll(U_, celli)
    {
        const scalar w = weight(geo.height(C[celli]));
        U_[celli] = w*UNT_[celli] + (1 - w)*Uplug;
    }
    // and on the boundaries (U_ is `calculated`: the walls keep the
    // Nedderman-Tuzun slip velocity, so the shear rate has no wall jump)
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& patch = mesh.boundary()[patchi];
        if (polyPatch::constraintType(patch.patch().type()))
        {
            continue;
        }
        vectorField& Up = U_.boundaryFieldRef()[patchi];
        const vectorField& UNTp = UNT_.boundaryField()[patchi];
        const vectorField& cf = patch.Cf();
        forAll(Up, facei)
        {
            const scalar w = weight(geo.height(cf[facei]));
            Up[facei] = w*UNTp[facei] + (1 - w)*Uplug;
        }
    }
    U_.correctBoundaryConditions();

    fieldLevel_ = zs;
    packedLevel_ = zPacked;

    const volScalarField divPhi(fvc::div(phi_));
    Info<< "    kinematic bulk flow: free surface at z = " << zs
        << " m, packed up to " << zPacked << " m (layer " << layer
        << " m), outlet flux " << Qmesh_
        << " m3/s on the mesh, max |div(phi)|*V/Q = "
        << gMax(mag(divPhi.primitiveField())*mesh.V())/Qmesh_ << nl << endl;
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
                "B", "outletPatches", "geometry", "dischargeRate", "Q",
                "fullOutletArea", "beverlooCoeffs", "packedFraction",
                "surfaceLayer", "marchingScheme"
            }
        ),
        mixture,
        false
    ),
    B_(modelCoeffs::get(coeffs_, "B", dimLength).value()),
    outletPatches_(),
    geometry_(),
    marchingScheme_(readMarchingScheme(coeffs_)),
    Q_(0),
    Qmesh_(0),
    packedFraction_(0),
    surfaceLayer_
    (
        modelCoeffs::getOrDefault(coeffs_, "surfaceLayer", dimLength, -1).value()
    ),
    UNT_(U_.name() + "NT", U_),
    phiNT_(phi_.name() + "NT", phi_),
    fieldLevel_(-GREAT),
    packedLevel_(-GREAT)
{
    const fvMesh& mesh = mixture.mesh();

    if (!(B_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Kinematic constant 'B " << B_ << "' must be > 0 [m]" << nl
            << exit(FatalIOError);
    }
    if (coeffs_.found("surfaceLayer") && !(surfaceLayer_ > 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'surfaceLayer " << surfaceLayer_ << "' must be > 0 [m]"
            << nl << exit(FatalIOError);
    }

    {
        // "Gauss upwind" or "Gauss linearUpwind <gradient>": checked here,
        // so that a mistake is reported against this entry. The marching
        // direction needs an upwind-biased scheme: a central one (linear,
        // the limited schemes on smooth fields) takes the matrix's
        // diagonal dominance and the Gauss-Seidel solve diverges
        std::istringstream words(marchingScheme_);
        std::string gauss, interp;
        words >> gauss >> interp;
        if (gauss != "Gauss" || (interp != "upwind" && interp != "linearUpwind"))
        {
            FatalIOErrorInFunction(coeffs_)
                << "marchingScheme " << marchingScheme_ << ": expected"
                << " \"Gauss upwind\" (first order) or \"Gauss linearUpwind"
                << " <gradient>\" (second order; the default, with"
                << " grad(vKinematic) from gradSchemes)"
                << nl << exit(FatalIOError);
        }
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

    // Optional, default the largest initial solids fraction: the silo
    // starts packed
    packedFraction_ = modelCoeffs::getOrDefault
    (
        coeffs_,
        "packedFraction",
        dimless,
        gMax(mixture.nTotal().primitiveField())
    ).value();
    if (!(packedFraction_ > 0 && packedFraction_ <= 1))
    {
        if (coeffs_.found("packedFraction"))
        {
            FatalIOErrorInFunction(coeffs_)
                << "'packedFraction " << packedFraction_ << "' must lie in"
                << " (0, 1]" << nl << exit(FatalIOError);
        }
        // An empty silo: no material, the surface at the bottom
        packedFraction_ = 1;
    }

    readGeometry();
    readDischargeRate();
    solveNeddermanTuzun();
    setFlow(surfaceLevel(), packedLevel());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bulkFlowModels::kinematic::correct()
{
    const scalar zs = surfaceLevel();
    const scalar zPacked = packedLevel();
    const scalar tolerance = 0.25*geometry_->cellHeightAt(zs);
    if
    (
        mag(zs - fieldLevel_) > tolerance
     || mag(zPacked - packedLevel_) > tolerance
    )
    {
        setFlow(zs, zPacked);
    }
}


// ************************************************************************* //

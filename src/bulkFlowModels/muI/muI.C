/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "muI.H"
#include "addToRunTimeSelectionTable.H"
#include "fvm.H"
#include "fvc.H"
#include "MULES.H"
#include "constrainHbyA.H"
#include "constrainPressure.H"
#include "prghBulkRetainingTotalPressureFvPatchScalarField.H"
#include "prghOrificeTotalPressureFvPatchScalarField.H"
#include "fixedFluxPressureFvPatchScalarField.H"
#include "adjustPhi.H"
#include "findRefCell.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "zeroGradientFvPatchFields.H"
#include "geometricOneField.H"
#include "zeroField.H"
#include "modelCoeffs.H"
#include "subCycle.H"
#include "siloGeometry.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace bulkFlowModels
{
    defineTypeNameAndDebug(muI, 0);
    addToRunTimeSelectionTable(bulkFlowModel, muI, dictionary);
}
}


// * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * * //

namespace
{

// A registered, written field of the model
Foam::IOobject writtenField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        Foam::IOobject::NO_READ,
        Foam::IOobject::AUTO_WRITE
    );
}

// A field read from the start time, written with the results
Foam::IOobject readField(const Foam::fvMesh& mesh, const Foam::word& name)
{
    return Foam::IOobject
    (
        name,
        mesh.time().timeName(),
        mesh,
        Foam::IOobject::MUST_READ,
        Foam::IOobject::AUTO_WRITE
    );
}

// Positive entry of the coefficients in the units of dims (or with its
// dimensions, as every model's), or the default
Foam::scalar positiveEntry
(
    const Foam::dictionary& dict,
    const Foam::word& key,
    const Foam::dimensionSet& dims,
    const Foam::scalar deflt
)
{
    const Foam::scalar value =
        Foam::modelCoeffs::getOrDefault(dict, key, dims, deflt).value();
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "'" << key << " " << value << "' must be > 0" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return value;
}

// The pour of muICoeffs/deposition (deposited where it lands), or nullptr
// without one; an entry that is not a dictionary is refused
Foam::bulkDeposition* newDeposition
(
    const Foam::dictionary& coeffs,
    const Foam::granularMixture& mixture,
    const Foam::scalar packedFraction
)
{
    if (!coeffs.found("deposition"))
    {
        return nullptr;
    }
    if (!coeffs.isDict("deposition"))
    {
        FatalIOErrorInFunction(coeffs)
            << "'deposition' must be a dictionary: { rate [m3/s]; centre"
            << " (x y z); radius [m]; composition { <species> <fraction>;"
            << " ... } start [s]; end [s]; }" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return new Foam::bulkDeposition
    (
        coeffs.subDict("deposition"),
        mixture,
        packedFraction
    );
}

// The bulkFlow dictionary as the model reads it: with `rheology calibrated`
// in muICoeffs, the entries of the sub-dictionary rheology of
// constant/granularCoefficients (calibrateGranularMixture, coefficient
// rheology) added to muICoeffs; with `rheology given` (default) as it is
Foam::dictionary withCalibratedRheology
(
    const Foam::dictionary& dict,
    const Foam::granularMixture& mixture
)
{
    using namespace Foam;
    const bool inSubDict = dict.isDict("muICoeffs");
    dictionary result(dict);
    dictionary& coeffs = inSubDict ? result.subDict("muICoeffs") : result;
    const word source(coeffs.getOrDefault<word>("rheology", "given"));
    if (source == "given")
    {
        return result;
    }
    if (source != "calibrated")
    {
        FatalIOErrorInFunction(coeffs)
            << "Unknown 'rheology " << source << "'; valid: (given calibrated)"
            << nl << "    given: mu_s, mu_d, I_0, packedFraction of muICoeffs;"
            << " calibrated: those of the sub-dictionary rheology of"
            << " constant/granularCoefficients (calibrateGranularMixture with"
            << " coefficients (rheology))" << nl << exit(FatalIOError);
    }
    // What the calibration measures; the rest (regularised, etaMax, ...)
    // stays the case's
    const wordList calibrated
    ({
        "mu_s", "mu_d", "I_0", "packedFraction", "d", "rhoS"
    });
    for (const word& key : calibrated)
    {
        if (coeffs.found(key))
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry '" << key << "' given with 'rheology calibrated': the"
                << " calibration (constant/granularCoefficients, sub-dictionary"
                << " rheology) sets " << calibrated << nl << "    remove '"
                << key << "' from muICoeffs, or set 'rheology given' to use the"
                << " dictionary's values" << nl << exit(FatalIOError);
        }
    }
    const fvMesh& mesh = mixture.mesh();
    IOobject io
    (
        "granularCoefficients",
        mesh.time().constant(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (!io.typeHeaderOk<IOdictionary>(true))
    {
        FatalIOErrorInFunction(coeffs)
            << "'rheology calibrated': there is no calibration in the case: "
            << io.objectPath() << " is missing" << nl
            << "    run calibrateGranularMixture with 'coefficients (rheology);'"
            << " and a rheology entry in system/calibrationDict"
            << " (docs/user/calibration.md), or set 'rheology given'" << nl
            << exit(FatalIOError);
    }
    const IOdictionary file(io);
    if (!file.isDict("rheology"))
    {
        FatalIOErrorInFunction(file)
            << "'rheology calibrated': " << file.objectPath() << " has no"
            << " sub-dictionary rheology (the rheology was not calibrated);"
            << " run calibrateGranularMixture with 'coefficients (rheology);'"
            << " or set 'rheology given'" << nl << exit(FatalIOError);
    }
    const dictionary& rd = file.subDict("rheology");
    for (const word& key : calibrated)
    {
        if (!rd.found(key))
        {
            FatalIOErrorInFunction(rd)
                << "Entry '" << key << "' missing in the calibrated rheology;"
                << " it holds " << rd.toc() << ", muI takes " << calibrated
                << nl << exit(FatalIOError);
        }
        coeffs.add(key, rd.get<scalar>(key));
    }
    const scalarList IRange
    (
        rd.getOrDefault<scalarList>("IRange", scalarList({0, 0}))
    );
    Info<< "    muI: rheology calibrated (" << file.objectPath().name()
        << ", " << rd.getOrDefault<label>("cells", 0) << " DEM cells over I "
        << IRange.first() << "-" << IRange.last() << " at "
        << rd.getOrDefault<scalar>("pressure", 0) << " Pa):";
    for (const word& key : calibrated)
    {
        Info<< " " << key << " " << coeffs.get<scalar>(key);
    }
    Info<< nl;
    return result;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::tmp<Foam::surfaceScalarField>
Foam::bulkFlowModels::muI::settlingFlux() const
{
    const fvMesh& mesh = mixture_.mesh();
    tmp<surfaceScalarField> tflux
    (
        surfaceScalarField::New
        (
            "settlingFlux",
            mesh,
            dimensionedScalar(dimVolume/dimTime, Zero)
        )
    );
    surfaceScalarField& flux = tflux.ref();
    const vector gHat(mixture_.gravity()/mag(mixture_.gravity()));

    // F = w (gHat.Sf) alpha_up (1 - alpha_down): positive (owner to
    // neighbour) where Sf points down, so the owner is the upper cell
    auto settlingFaceFlux = [this, &gHat]
    (
        const vector& Sf,
        const scalar alphaOwn,
        const scalar alphaNei
    )
    {
        const scalar gSf = gHat & Sf;
        return
            gSf > 0
          ? settlingVelocity_*gSf*alphaOwn*(1 - alphaNei)
          : settlingVelocity_*gSf*alphaNei*(1 - alphaOwn);
    };

    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const vectorField& Sf = mesh.Sf();
    forAll(own, facei)
    {
        flux[facei] =
            settlingFaceFlux
            (
                Sf[facei], alpha_[own[facei]], alpha_[nei[facei]]
            );
    }
    forAll(flux.boundaryField(), patchi)
    {
        const fvPatchScalarField& alphap = alpha_.boundaryField()[patchi];
        if (!alphap.coupled())
        {
            continue;
        }
        const scalarField alphaOwn(alphap.patchInternalField());
        const scalarField alphaNei(alphap.patchNeighbourField());
        const vectorField& Sfp = mesh.Sf().boundaryField()[patchi];
        scalarField& fluxp = flux.boundaryFieldRef()[patchi];
        forAll(fluxp, facei)
        {
            fluxp[facei] =
                settlingFaceFlux
                (
                    Sfp[facei], alphaOwn[facei], alphaNei[facei]
                );
        }
    }
    return tflux;
}


void Foam::bulkFlowModels::muI::advectAlpha()
{
    const fvMesh& mesh = mixture_.mesh();
    const dictionary& controls = mesh.solverDict(alpha_.name());
    const scalar cAlpha = controls.getOrDefault<scalar>("cAlpha", 1);
    const label nAlphaCorr = controls.getOrDefault<label>("nAlphaCorr", 1);

    // Interface compression along the interface normal (interFoam's
    // interfaceProperties::nHatf, without surface tension)
    surfaceScalarField phic(cAlpha*mag(phi_/mesh.magSf()));
    forAll(phic.boundaryField(), patchi)
    {
        if (!phic.boundaryField()[patchi].coupled())
        {
            phic.boundaryFieldRef()[patchi] == 0;
        }
    }

    // The boundary values for this step's flux: an open patch whose face
    // turned from inflow to outflow must carry the cell's alpha out, not
    // the inflow value of the last evaluation (MULES does not limit
    // boundary fluxes)
    alpha_.correctBoundaryConditions();

    for (label aCorr = 0; aCorr < nAlphaCorr; ++aCorr)
    {
        const surfaceVectorField gradAlphaf
        (
            fvc::interpolate(fvc::grad(alpha_, "grad(alpha)"))
        );
        const dimensionedScalar deltaN
        (
            "deltaN",
            1e-8/cbrt(average(mesh.V()))
        );
        const surfaceScalarField nHatf
        (
            (gradAlphaf/(mag(gradAlphaf) + deltaN)) & mesh.Sf()
        );
        const surfaceScalarField phir(phic*nHatf);
        const volScalarField alphaAir(1 - alpha_);

        alphaPhi_ =
            fvc::flux(phi_, alpha_, "div(phi,alpha)")
          + fvc::flux
            (
                -fvc::flux(-phir, alphaAir, "div(phirb,alpha)"),
                alpha_,
                "div(phirb,alpha)"
            );
        if (settlingVelocity_ > 0)
        {
            alphaPhi_ += settlingFlux();
        }

        // Upwind on the non-coupled boundaries: out with the cell's value,
        // in with the boundary's
        forAll(alphaPhi_.boundaryField(), patchi)
        {
            const fvPatchScalarField& alphap = alpha_.boundaryField()[patchi];
            if (alphap.coupled())
            {
                continue;
            }
            const scalarField& phip = phi_.boundaryField()[patchi];
            const scalarField alphaIn(alphap.patchInternalField());
            scalarField& alphaPhip = alphaPhi_.boundaryFieldRef()[patchi];
            forAll(phip, facei)
            {
                alphaPhip[facei] =
                    phip[facei]
                   *(phip[facei] >= 0 ? alphaIn[facei] : alphap[facei]);
            }
        }

        if (deposition_.valid())
        {
            // the pour's bulk appears in its landing cells: k (1 - alpha),
            // implicit in alpha, keeps alpha <= 1 whatever else flows in
            MULES::explicitSolve
            (
                geometricOneField(),
                alpha_,
                phi_,
                alphaPhi_,
                deposition_->Sp(),
                deposition_->Su(),
                oneField(),
                zeroField()
            );
        }
        else
        {
            MULES::explicitSolve
            (
                geometricOneField(),
                alpha_,
                phi_,
                alphaPhi_,
                oneField(),
                zeroField()
            );
        }
    }
}


void Foam::bulkFlowModels::muI::solveAlpha()
{
    const fvMesh& mesh = mixture_.mesh();
    const dictionary& controls = mesh.solverDict(alpha_.name());

    // Sub-cycles: at least nAlphaSubCycles, and enough to keep the explicit
    // MULES step's Courant number (with the flux of this step, which may
    // exceed the one the time step was chosen for) at or below maxAlphaCo
    const scalar maxAlphaCo =
        controls.getOrDefault<scalar>("maxAlphaCo", 0.5);
    if (!(maxAlphaCo > 0))
    {
        FatalIOErrorInFunction(controls)
            << "'maxAlphaCo " << maxAlphaCo << "' must be > 0" << nl
            << exit(FatalIOError);
    }
    // (with the settling speed's share of each face)
    const scalar alphaCo =
        0.5*gMax
        (
            fvc::surfaceSum
            (
                mag(phi_)
              + dimensionedScalar("w", dimVelocity, settlingVelocity_)*mesh.magSf()
            )().primitiveField()/mesh.V().field()
        )*mesh.time().deltaTValue();
    const label nSub = max
    (
        controls.getOrDefault<label>("nAlphaSubCycles", 1),
        label(std::ceil(alphaCo/maxAlphaCo))
    );

    if (deposition_.valid())
    {
        deposition_->setSubCycles(nSub);
        deposition_->beginSolve();
    }
    if (nSub > 1)
    {
        Time& runTime = const_cast<Time&>(mesh.time());
        const dimensionedScalar totalDeltaT = runTime.deltaT();
        surfaceScalarField alphaPhiSum
        (
            IOobject("alphaPhiSum", runTime.timeName(), mesh),
            mesh,
            dimensionedScalar(alphaPhi_.dimensions(), Zero)
        );
        for
        (
            subCycle<volScalarField> alphaSubCycle(alpha_, nSub);
            !(++alphaSubCycle).end();
        )
        {
            advectAlpha();
            alphaPhiSum += (runTime.deltaT()/totalDeltaT)*alphaPhi_;
            if (deposition_.valid())
            {
                deposition_->addTaken
                (
                    alpha_, (runTime.deltaT()/totalDeltaT).value()
                );
            }
        }
        alphaPhi_ = alphaPhiSum;
    }
    else
    {
        advectAlpha();
        if (deposition_.valid())
        {
            deposition_->addTaken(alpha_, 1);
        }
    }

    const dimensionedScalar rhoB("rhoBulk", dimDensity, rhoBulk());
    const dimensionedScalar rhoA("rhoAir", dimDensity, rhoAir_);
    rhoPhi_ = alphaPhi_*(rhoB - rhoA) + phi_*rhoA;
    rho_ = alpha_*rhoB + (1 - alpha_)*rhoA;

    Info<< "    muI: bulk volume "
        << gSum(alpha_.primitiveField()*mesh.V()) << " m3, alpha.granular"
        << " min/max " << gMin(alpha_.primitiveField()) << "/"
        << gMax(alpha_.primitiveField()) << ", " << nSub
        << " MULES sub-cycle(s), alpha Courant number " << alphaCo << endl;
}


void Foam::bulkFlowModels::muI::updateViscosity()
{
    const volScalarField gammaDot(this->gammaDot());
    const scalarField& gD = gammaDot.primitiveField();
    const scalarField& p = p_.primitiveField();
    scalarField& I = I_.primitiveFieldRef();
    scalarField& eta = eta_.primitiveFieldRef();

    forAll(eta, celli)
    {
        const scalar pEff = max(p[celli], pMin_);
        I[celli] = gD[celli]*d_/sqrt(pEff/rhoS_);
        eta[celli] =
            min(law_.mu(I[celli])*pEff/max(gD[celli], VSMALL), etaMax_);
    }
    I_.correctBoundaryConditions();
    eta_.correctBoundaryConditions();
}


Foam::tmp<Foam::volVectorField>
Foam::bulkFlowModels::muI::cellForce() const
{
    // -grad(p_rgh) - gh grad(rho), and the periodic gravity rho g_p: the
    // cell-centred counterpart of the face force
    // gravityFlux - snGrad(p_rgh) magSf
    return
        dimensionedVector("gp", dimAcceleration, gPeriodic_)*rho_
      - fvc::grad(p_rgh_)
      - gh_*fvc::grad(rho_);
}


template<class PatchField, class Action>
void Foam::bulkFlowModels::muI::forEachPatchOf(const Action& action)
{
    volScalarField::Boundary& p_rghBf = p_rgh_.boundaryFieldRef();
    forAll(p_rghBf, patchi)
    {
        auto* condition = dynamic_cast<PatchField*>(&p_rghBf[patchi]);
        if (condition)
        {
            action(*condition, patchi);
        }
    }
}


Foam::label Foam::bulkFlowModels::muI::retainBulk
(
    const surfaceScalarField& phiHbyA,
    const surfaceScalarField& rAUf
)
{
    label nClosed = 0;
    forEachPatchOf<prghBulkRetainingTotalPressureFvPatchScalarField>
    (
        [&](prghBulkRetainingTotalPressureFvPatchScalarField& top, label i)
        {
            nClosed +=
                top.retainBulk
                (
                    phiHbyA.boundaryField()[i],
                    rAUf.boundaryField()[i]
                );
        }
    );
    return nClosed;
}


Foam::label Foam::bulkFlowModels::muI::switchRetainingFaces(const bool apply)
{
    label nSwitched = 0;
    forEachPatchOf<prghBulkRetainingTotalPressureFvPatchScalarField>
    (
        [&](prghBulkRetainingTotalPressureFvPatchScalarField& top, label i)
        {
            nSwitched += top.switchFaces(phi_.boundaryField()[i], apply);
        }
    );
    return nSwitched;
}


void Foam::bulkFlowModels::muI::releaseRetainingFaces()
{
    forEachPatchOf<prghBulkRetainingTotalPressureFvPatchScalarField>
    (
        [&](prghBulkRetainingTotalPressureFvPatchScalarField& top, label i)
        {
            top.releaseTotalPressure(phi_.boundaryFieldRef()[i]);
        }
    );
}


void Foam::bulkFlowModels::muI::closeEmptyAnnulus
(
    const siloGeometry& geometry
)
{
    if (geometry.throat())
    {
        FatalIOErrorInFunction(coeffs_)
            << "'emptyAnnulus yes': the orifice is a throat "
            << geometry.orificeSize() << " m wide above the outlet patches"
            << " (at height " << geometry.orificeHeight() << " m), not on"
            << " them: the rim it would close is not on the outlet patches"
            << nl << exit(FatalIOError);
    }
    const scalar rimWidth = 0.5*k_*d_;
    scalar wallAngle = -1;
    const List<Pair<point>> rim(geometry.rimEdges(&wallAngle));
    // The band is a floor's: beside a flat floor the grains that would pass
    // within k d/2 of the rim come from the floor's stagnant corner. Beside
    // a sloping wall (a hopper's) the bulk slides along the wall into the
    // orifice and the grains' centres keep clear of the wall along its
    // whole length: there the empty annulus is the wall moved in, and a
    // band closed at the rim is a ledge that stops the wall's stream (a
    // planar hopper at 20 degrees discharged at 0.73-0.77 of its DEM peer
    // with the band, 1.05-1.08 with the slot meshed k d narrower;
    // docs/validation.md)
    const scalar steepestFloor = 45;
    if (wallAngle > steepestFloor)
    {
        FatalIOErrorInFunction(coeffs_)
            << "'emptyAnnulus yes': the orifice's rim is on a wall at "
            << wallAngle << " degrees to the outlet's plane (a hopper's or"
            << " a channel's wall); the closed band is for a floor within "
            << steepestFloor << " degrees of it. Beside a sloping wall the"
            << " empty annulus is the wall moved in: mesh the orifice k d = "
            << k_*d_ << " m narrower (the walls moved in parallel to"
            << " themselves) with 'emptyAnnulus no'" << nl
            << exit(FatalIOError);
    }
    const wordRes outletNames(coeffs_.get<wordRes>("outletPatches"));
    const fvMesh& mesh = mixture_.mesh();
    scalar area = 0;
    scalar openArea = 0;
    for
    (
        const label patchi
      : mesh.boundaryMesh().patchSet(outletNames).sortedToc()
    )
    {
        fvPatchScalarField& pp = p_rgh_.boundaryFieldRef()[patchi];
        const scalarField& magSf = mesh.magSf().boundaryField()[patchi];
        if (isA<prghOrificeTotalPressureFvPatchScalarField>(pp))
        {
            const scalarField f(geometry.openFraction(rim, patchi, rimWidth));
            refCast<prghOrificeTotalPressureFvPatchScalarField>(pp)
               .setOpenFraction(f);
            area += gSum(magSf);
            openArea += gSum(f*magSf);
        }
        else if (!isA<fixedFluxPressureFvPatchScalarField>(pp))
        {
            FatalIOErrorInFunction(coeffs_)
                << "'emptyAnnulus yes': p_rgh on outlet patch "
                << mesh.boundary()[patchi].name() << " is " << pp.type()
                << ", which cannot close the orifice's rim; valid:"
                << " prghOrificeTotalPressure (an open orifice) or"
                << " fixedFluxPressure (a closed one)" << nl
                << exit(FatalIOError);
        }
    }
    if (area > 0)
    {
        Info<< "    muI: empty annulus: a band k d/2 = " << rimWidth
            << " m wide along the orifice's rim closed; open "
            << openArea/area << " of the outlet patches' area" << endl;
    }
    else
    {
        Info<< "    muI: empty annulus: the outlet patches are closed"
            << " (fixedFluxPressure)" << endl;
    }
}


void Foam::bulkFlowModels::muI::solveFlow()
{
    const fvMesh& mesh = mixture_.mesh();

    muEff_ =
        alpha_*eta_
      + (1 - alpha_)*dimensionedScalar("muAir", dimDynamicViscosity, muAir_);
    const volScalarField& muEff = muEff_;

    fvVectorMatrix UEqn
    (
        fvm::ddt(rho_, U_)
      + fvm::div(rhoPhi_, U_, "div(rhoPhi,U)")
      - fvm::laplacian(muEff, U_)
      - fvc::div(muEff*dev2(T(fvc::grad(U_))))
    );
    UEqn.relax();

    // Gravity on the faces: the hydrostatic part through p_rgh, the
    // periodic part as a body force
    const surfaceScalarField gravityFlux
    (
        -ghf_*fvc::snGrad(rho_)*mesh.magSf()
      + fvc::interpolate(rho_)
       *(dimensionedVector("gp", dimAcceleration, gPeriodic_) & mesh.Sf())
    );

    if (pimple_.momentumPredictor())
    {
        solve
        (
            UEqn
         ==
            (
                cellGradientForces_
              ? cellForce()
              : fvc::reconstruct
                (
                    gravityFlux - fvc::snGrad(p_rgh_)*mesh.magSf()
                )
            )
        );
    }

    while (pimple_.correct())
    {
        const volScalarField rAU("rAU", 1.0/UEqn.A());
        const surfaceScalarField rAUf("rAUf", fvc::interpolate(rAU));
        volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U_, p_rgh_));
        surfaceScalarField phiHbyA
        (
            "phiHbyA",
            fvc::flux(HbyA)
          + fvc::interpolate(rho_*rAU)*fvc::ddtCorr(U_, phi_)
        );

        if (p_rgh_.needReference())
        {
            adjustPhi(phiHbyA, U_, p_rgh_);
        }

        // HbyA's own flux, before SIMPLEC's face forces join HbyA: what
        // a wall (U = 0) takes out of phiHbyA, for the orifice's closed band
        // (without emptyAnnulus every face is open and it plays no part)
        tmp<surfaceScalarField> HbyAFlux;
        if (emptyAnnulus_)
        {
            HbyAFlux = fvc::flux(HbyA);
        }

        // SIMPLEC (PIMPLE { consistent yes; }, as pimpleFoam's): where the
        // viscous coupling to the neighbours dominates the diagonal (a
        // stagnant bulk, eta up to etaMax: eta deltaT / (rho dx^2) is 30-100
        // on a silo's 2.5-5 mm cells, 3e4 on the inclined plane's), the
        // momentum predictor spreads every pressure error through the bulk
        // and PISO's correction with 1/A cannot take it back: the pressure
        // diverges within a few steps (interFoam does the same with a
        // 1e3 Pa s liquid). The correction with 1/(A - H1), about
        // deltaT/rho there, does not. pimpleFoam floors A - H1 at 0.1 A,
        // which for a viscous bulk is the 1/A correction again; the floor
        // here is the inertia rho/deltaT. The face forces of the last
        // pressure move to HbyA with the difference, so the converged flow
        // is the same
        // The floor uses the cells' density; the boundary takes the cells'
        // values (rAU's patches extrapolate, coupled ones take their
        // neighbours'), so rAtU_b >= rAU_b as in the cells. Floored on the
        // boundary with the boundary's density, an inlet of bulk into a
        // cell of air (rho_b/rho_P up to 1e3) got rAtU_b < rAU_b, and
        // fixedFluxPressure's gradient, which moves with the face force
        // (rAUf - rAtUf) into phiHbyA, grew by rAUf_b/rAtUf_b - 1 (about 7)
        // per corrector there until the fill blew up
        volScalarField rAtU("rAtU", rAU);
        if (pimple_.consistent())
        {
            const volScalarField::Internal A(1.0/rAU.internalField());
            rAtU.primitiveFieldRef() =
                1.0
               /max
                (
                    A - UEqn.H1()().internalField(),
                    rho_.internalField()/mesh.time().deltaT()
                );
            rAtU.correctBoundaryConditions();
            const surfaceScalarField faceForce
            (
                gravityFlux - fvc::snGrad(p_rgh_)*mesh.magSf()
            );
            phiHbyA += (rAUf - fvc::interpolate(rAtU))*faceForce;
            HbyA +=
                (rAU - rAtU)
               *(
                    cellGradientForces_
                  ? cellForce()
                  : fvc::reconstruct(faceForce)
                );
        }
        const surfaceScalarField rAtUf("rAtUf", fvc::interpolate(rAtU));

        const surfaceScalarField phig(gravityFlux*rAtUf);
        phiHbyA += phig;

        constrainPressure(p_rgh_, U_, phiHbyA, rAtUf);
        forEachPatchOf<prghOrificeTotalPressureFvPatchScalarField>
        (
            [&](prghOrificeTotalPressureFvPatchScalarField& orifice, label i)
            {
                orifice.closeRim
                (
                    phiHbyA.boundaryFieldRef()[i],
                    HbyAFlux.valid()
                  ? scalarField(HbyAFlux().boundaryField()[i])
                  : scalarField(phiHbyA.boundaryField()[i].size(), Zero),
                    rAtUf.boundaryField()[i]
                );
            }
        );
        const label nClosed = retainBulk(phiHbyA, rAtUf);

        // The faces of prghBulkRetainingTotalPressure patches are a one-way
        // valve for the bulk, decided before the solve from the last
        // pressure: where the solved flux leaves a cell with bulk through
        // an open face, or a closed face would draw air in, the face
        // switches and the pressure is solved again (an active set; a
        // switch is rare after the first steps)
        const label maxValveIters = 10;
        label nSwitched = 0;
        for (label valveIter = 0; ; ++valveIter)
        {
            // At the last allowed solve the faces keep the state that was
            // solved (the flux stays conservative; a few faces may carry
            // bulk out this once)
            const bool last = valveIter == maxValveIters;
            label n = 0;

            while (pimple_.correctNonOrthogonal())
            {
                fvScalarMatrix p_rghEqn
                (
                    fvm::laplacian(rAtUf, p_rgh_) == fvc::div(phiHbyA)
                );
                p_rghEqn.setReference
                (
                    pRefCell_,
                    getRefCellValue(p_rgh_, pRefCell_)
                );
                p_rghEqn.solve
                (
                    mesh.solver(p_rgh_.select(pimple_.finalInnerIter()))
                );

                if (pimple_.finalNonOrthogonalIter())
                {
                    phi_ = phiHbyA - p_rghEqn.flux();
                    // On the solved pressure, before its relaxation
                    n = switchRetainingFaces(!last);
                    p_rgh_.relax();
                    if (cellGradientForces_)
                    {
                        U_ = HbyA + rAtU*cellForce();
                    }
                    else
                    {
                        U_ = HbyA
                          + rAtU
                           *fvc::reconstruct((phig - p_rghEqn.flux())/rAtUf);
                    }
                    U_.correctBoundaryConditions();
                }
            }

            if (n == 0)
            {
                break;
            }
            if (last)
            {
                WarningInFunction
                    << "the open top's faces still switched after "
                    << maxValveIters + 1 << " pressure solves (" << n
                    << " in the last)" << endl;
                break;
            }
            nSwitched += n;
        }
        releaseRetainingFaces();
        forEachPatchOf<prghOrificeTotalPressureFvPatchScalarField>
        (
            [&](prghOrificeTotalPressureFvPatchScalarField& orifice, label i)
            {
                orifice.zeroClosedFlux(phi_.boundaryFieldRef()[i]);
            }
        );
        // U's open-patch conditions read the flux's sign: the closed faces'
        // is now exactly zero
        U_.correctBoundaryConditions();
        if (nClosed || nSwitched)
        {
            Info<< "    muI: open top: " << nClosed << " face(s) closed to"
                << " the bulk before the pressure solve, " << nSwitched
                << " switched after it" << endl;
        }

        // interFoam's continuity check: the volume error of the step
        Info<< "    muI: continuity error max |div(phi)| dt = "
            << gMax(mag(fvc::div(phi_))().primitiveField())
              *mesh.time().deltaTValue() << endl;

        p_ == p_rgh_ + rho_*gh_;
        if (p_rgh_.needReference())
        {
            p_ += dimensionedScalar
            (
                "p",
                p_.dimensions(),
                pRefValue_ - getRefCellValue(p_, pRefCell_)
            );
            p_rgh_ = p_ - rho_*gh_;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bulkFlowModels::muI::muI
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    bulkFlowModel
    (
        typeName,
        withCalibratedRheology
        (
            modelCoeffs::checked
            (
                dict,
                typeName,
                {
                    "rheology", "mu_s", "mu_d", "I_0", "regularised", "d",
                    "rhoS", "packedFraction", "etaMax", "pMin", "rhoAir",
                    "muAir", "outletPatches", "forces", "settlingVelocity",
                    "emptyAnnulus", "k", "deposition"
                }
            ),
            mixture
        ),
        mixture,
        true
    ),
    law_(coeffs_),
    d_(0),
    rhoS_(0),
    k_(positiveEntry(coeffs_, "k", dimless, 1.5)),
    emptyAnnulus_(coeffs_.getOrDefault<bool>("emptyAnnulus", false)),
    packedFraction_(coeffs_.getOrDefault<scalar>("packedFraction", 0.6)),
    etaMax_(positiveEntry(coeffs_, "etaMax", dimDynamicViscosity, 1e3)),
    pMin_(positiveEntry(coeffs_, "pMin", dimPressure, 1)),
    rhoAir_(positiveEntry(coeffs_, "rhoAir", dimDensity, 1.2)),
    muAir_(positiveEntry(coeffs_, "muAir", dimDynamicViscosity, 1.8e-5)),
    settlingVelocity_
    (
        modelCoeffs::getOrDefault
        (
            coeffs_, "settlingVelocity", dimVelocity, 0
        ).value()
    ),
    deposition_(newDeposition(coeffs_, mixture, packedFraction_)),
    pimple_(const_cast<fvMesh&>(mixture.mesh())),
    alpha_(readField(mixture.mesh(), "alpha.granular"), mixture.mesh()),
    p_rgh_(readField(mixture.mesh(), "p_rgh"), mixture.mesh()),
    p_
    (
        writtenField(mixture.mesh(), "p"),
        mixture.mesh(),
        dimensionedScalar("p", dimPressure, Zero)
    ),
    rho_
    (
        IOobject("rho", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("rho", dimDensity, Zero)
    ),
    I_
    (
        writtenField(mixture.mesh(), "I"),
        mixture.mesh(),
        dimensionedScalar("I", dimless, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    eta_
    (
        writtenField(mixture.mesh(), "eta"),
        mixture.mesh(),
        dimensionedScalar("eta", dimDynamicViscosity, Zero),
        zeroGradientFvPatchScalarField::typeName
    ),
    muEff_
    (
        IOobject("muEff", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("muEff", dimDynamicViscosity, Zero)
    ),
    alphaPhi_
    (
        IOobject("alphaPhi.granular", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("f", dimVolume/dimTime, Zero)
    ),
    rhoPhi_
    (
        IOobject("rhoPhi", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("f", dimMass/dimTime, Zero)
    ),
    hRef_
    (
        IOobject
        (
            "hRef",
            mixture.mesh().time().constant(),
            mixture.mesh(),
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        dimensionedScalar("hRef", dimLength, Zero)
    ),
    gh_
    (
        IOobject("gh", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("gh", dimAcceleration*dimLength, Zero)
    ),
    ghf_
    (
        IOobject("ghf", mixture.mesh().time().timeName(), mixture.mesh()),
        mixture.mesh(),
        dimensionedScalar("gh", dimAcceleration*dimLength, Zero)
    ),
    gPeriodic_(Zero),
    cellGradientForces_(false),
    pRefCell_(0),
    pRefValue_(0)
{
    const fvMesh& mesh = mixture.mesh();

    // Particle diameter and density: optional, defaults the initial
    // mixture's solids-weighted mean diameter and density
    scalar solids = 0, dSum = 0, rhoSum = 0;
    forAll(mixture.n(), i)
    {
        const scalar v = gSum(mixture.n()[i].primitiveField()*mesh.V());
        solids += v;
        dSum += v*mixture.d(i);
        rhoSum += v*mixture.rho(i);
    }
    d_ = positiveEntry
    (
        coeffs_,
        "d",
        dimLength,
        solids > VSMALL ? dSum/solids : mixture.d(0)
    );
    rhoS_ = positiveEntry
    (
        coeffs_,
        "rhoS",
        dimDensity,
        solids > VSMALL ? rhoSum/solids : mixture.rho(0)
    );
    if (!(packedFraction_ > 0 && packedFraction_ <= 1))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'packedFraction " << packedFraction_ << "' must lie in"
            << " (0, 1]" << nl << exit(FatalIOError);
    }

    // Optional, default 0: a negative speed would lift bulk out of air
    if (!(settlingVelocity_ >= 0))
    {
        FatalIOErrorInFunction(coeffs_)
            << "'settlingVelocity " << settlingVelocity_ << "' must be >= 0"
            << " [m/s] (0: the bulk does not settle through the air)" << nl
            << exit(FatalIOError);
    }

    // Optional, default faceFlux (interFoam's)
    const word forces(coeffs_.getOrDefault<word>("forces", "faceFlux"));
    if (forces != "faceFlux" && forces != "cellGradient")
    {
        FatalIOErrorInFunction(coeffs_)
            << "Unknown 'forces " << forces << "'; valid: (faceFlux"
            << " cellGradient)" << nl << exit(FatalIOError);
    }
    cellGradientForces_ = (forces == "cellGradient");
    Info<< "    muI: forces " << forces
        << (cellGradientForces_ ? " (cell gradients)" : " (reconstructed face forces)")
        << nl;

    // Gravity along translational cyclic directions drives as a body force.
    // The directions come from every cyclic and processorCyclic patch with
    // faces on any rank (a decomposition may leave a rank's cyclic empty)
    const vector g(mixture.gravity());
    List<DynamicList<vector>> rankDirections(Pstream::nProcs());
    DynamicList<vector>& local = rankDirections[Pstream::myProcNo()];
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        const coupledPolyPatch* cpp = nullptr;
        if (isA<cyclicPolyPatch>(pp) || isA<processorCyclicPolyPatch>(pp))
        {
            cpp = &refCast<const coupledPolyPatch>(pp);
        }
        if (!cpp || !cpp->separated() || cpp->separation().empty())
        {
            continue;
        }
        local.append(cpp->separation()[0]/max(mag(cpp->separation()[0]), VSMALL));
    }
    Pstream::gatherList(rankDirections);
    Pstream::scatterList(rankDirections);
    DynamicList<vector> periodicDirections;
    for (const DynamicList<vector>& directions : rankDirections)
    {
        for (const vector& e : directions)
        {
            bool known = false;
            for (const vector& k : periodicDirections)
            {
                known = known || mag(k & e) > 1 - 1e-6;
            }
            if (!known)
            {
                periodicDirections.append(e);
                gPeriodic_ += (g & e)*e;
            }
        }
    }
    const vector gHydrostatic(g - gPeriodic_);

    // The prgh* conditions take the full g: with a periodic part they would
    // not give p = p0 on the patch
    if (mag(gPeriodic_) > SMALL)
    {
        forAll(p_rgh_.boundaryField(), patchi)
        {
            const word& type = p_rgh_.boundaryField()[patchi].type();
            if (type.starts_with("prgh"))
            {
                FatalErrorInFunction
                    << "p_rgh on patch "
                    << mesh.boundary()[patchi].name() << " is " << type
                    << ", which takes the full gravity " << g
                    << "; the mesh is periodic along " << gPeriodic_
                    << " (gravity there drives as a body force): use"
                    << " totalPressure or fixedValue with constant/hRef at"
                    << " the patch's height" << exit(FatalError);
            }
        }
    }

    // gh as interFoam and the prgh* boundary conditions take it
    const scalar magG = mag(gHydrostatic);
    const scalar ghRef =
        magG > SMALL
      ? (gHydrostatic & (cmptMag(gHydrostatic)/magG))*hRef_.value()
      : 0;
    const dimensionedVector gh0("g", dimAcceleration, gHydrostatic);
    const dimensionedScalar ghRef0("ghRef", dimAcceleration*dimLength, ghRef);
    gh_ = (gh0 & mesh.C()) - ghRef0;
    ghf_ = (gh0 & mesh.Cf()) - ghRef0;

    alpha_.correctBoundaryConditions();
    rho_ =
        alpha_*dimensionedScalar("rhoBulk", dimDensity, rhoBulk())
      + (1 - alpha_)*dimensionedScalar("rhoAir", dimDensity, rhoAir_);
    rho_.oldTime();

    // The flux of the written time the run starts from, as interFoam's
    // createPhi: rebuilt from U, fvc::flux(U) is not divergence-free where
    // the bulk moves, and MULES's first step lifted alpha above 1 (by
    // 1.4e-4 in a discharge started from a fill's last time)
    IOobject phiHeader
    (
        "phi",
        mesh.time().timeName(),
        mesh,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (phiHeader.typeHeaderOk<surfaceScalarField>(true))
    {
        phi_ = surfaceScalarField(phiHeader, mesh);
        // The patches whose velocity is fixed carry it, not the written
        // flux: a run that switched a patch's conditions between two runs
        // (a fill's inlet closed by noSlip) would otherwise let the old
        // flux through for the first step (MULES's alpha and the species
        // take their boundary fluxes from phi before the pressure solve)
        forAll(phi_.boundaryField(), patchi)
        {
            const fvPatchVectorField& Up = U_.boundaryField()[patchi];
            if (!Up.coupled() && Up.fixesValue())
            {
                phi_.boundaryFieldRef()[patchi] =
                    Up & mesh.Sf().boundaryField()[patchi];
            }
        }
        Info<< "    muI: the flux phi read from time " << mesh.time().timeName()
            << " (fixed-velocity patches from U)" << endl;
    }
    else
    {
        phi_ = fvc::flux(U_);
    }
    rhoPhi_ = fvc::interpolate(rho_)*phi_;

    // The orifice against the particles: a bulk arches over an orifice
    // narrower than about k d (Beverloo's k = 1.5); the continuum cannot
    // arch, so it would discharge where a silo does not
    if (coeffs_.found("outletPatches"))
    {
        const wordRes outletNames(coeffs_.get<wordRes>("outletPatches"));
        const labelList outlets
        (
            mesh.boundaryMesh().patchSet(outletNames).sortedToc()
        );
        if (outlets.empty())
        {
            FatalIOErrorInFunction(coeffs_)
                << "outletPatches " << outletNames << " match no patch;"
                << " patches: " << mesh.boundaryMesh().names() << nl
                << exit(FatalIOError);
        }
        const siloGeometry geometry(mesh, outlets, normalised(g));
        const bool planar = geometry.geometry() == siloGeometry::kind::planar;
        const scalar D0 = geometry.orificeSize();
        if (!(D0 - k_*d_ > 0))
        {
            FatalIOErrorInFunction(coeffs_)
                << "outletPatches " << outletNames << ": the orifice is "
                << D0 << " m " << (planar ? "wide (a slot)" : "across")
                << ", not more than k d = " << k_ << " x " << d_ << " m"
                << " (Beverloo's k, d the particle diameter 'd'): the bulk"
                << " arches over it and does not flow; the mu(I) continuum"
                << " cannot arch, so the run is refused" << nl
                << exit(FatalIOError);
        }
        Info<< "    muI: orifice " << D0 << " m ("
            << siloGeometry::kindNames[geometry.geometry()] << ", "
            << geometry.kindReason() << "); Beverloo's law for comparison: "
            << (
                   planar
                 ? "1.03 sqrt(g) L (b - k d)^1.5 = "
                 : "0.58 sqrt(g) (D0 - k d)^2.5 (the mesh's share) = "
               )
            << (
                   planar
                 ? 1.03*sqrt(mag(g))*geometry.slotLength()*pow(D0 - k_*d_, 1.5)
                 : 0.58*sqrt(mag(g))*pow(D0 - k_*d_, 2.5)
                  *geometry.orificeArea()/geometry.fullOrificeArea()
               )
            << " m3/s of bulk; empty annulus "
            << (emptyAnnulus_ ? "closed (emptyAnnulus yes)" : "open (emptyAnnulus no)")
            << endl;
        if (emptyAnnulus_)
        {
            closeEmptyAnnulus(geometry);
        }
    }
    else if (emptyAnnulus_)
    {
        FatalIOErrorInFunction(coeffs_)
            << "'emptyAnnulus yes' needs 'outletPatches': the patches of the"
            << " orifice whose rim it closes" << nl << exit(FatalIOError);
    }

    if (!pimple_.consistent())
    {
        WarningInFunction
            << "bulkFlow muI with PISO's pressure correction (PIMPLE"
            << " consistent no in system/fvSolution): where the bulk stands"
            << " still (viscosity at etaMax) the pressure diverges; silos,"
            << " hoppers and beds at rest need 'consistent yes;'" << endl;
    }

    setRefCell(p_, p_rgh_, pimple_.dict(), pRefCell_, pRefValue_);
    mesh.setFluxRequired(p_rgh_.name());
    mesh.setFluxRequired(alpha_.name());

    p_ == p_rgh_ + rho_*gh_;
    updateViscosity();

    Info<< "    muI rheology: mu_s " << law_.muS() << ", mu_d " << law_.muD()
        << ", I_0 " << law_.I0()
        << (law_.regularised() ? ", regularised below I_N = " : ", standard")
        << (law_.regularised() ? law_.IN() : 0) << "; d " << d_
        << " m, rho_s " << rhoS_ << " kg/m3, bulk solids fraction "
        << packedFraction_ << ", eta <= " << etaMax_ << " Pa s, p >= "
        << pMin_ << " Pa; settling through air " << settlingVelocity_
        << " m/s; gravity " << gHydrostatic << " hydrostatic + "
        << gPeriodic_ << " periodic" << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bulkFlowModels::muI::checkFillOverflow()
{
    const fvMesh& mesh = mixture_.mesh();

    // Bulk entering through the boundary in this step, and where (the
    // patches bringing at least 1e-3 of it: not MULES's round-off traces)
    scalar inflow = 0;
    List<Tuple2<word, scalar>> patchInflows;
    forAll(alphaPhi_.boundaryField(), patchi)
    {
        const fvsPatchScalarField& alphaPhip = alphaPhi_.boundaryField()[patchi];
        if (alphaPhip.coupled())
        {
            continue;
        }
        const scalar patchInflow = -gSum(min(alphaPhip, scalar(0)));
        if (patchInflow > 0)
        {
            inflow += patchInflow;
            patchInflows.append
            (
                Tuple2<word, scalar>(mesh.boundary()[patchi].name(), patchInflow)
            );
        }
    }
    const scalar deposited =
        deposition_.valid() ? deposition_->depositedRate() : 0;
    if (deposited > 0)
    {
        inflow += deposited;
        patchInflows.append(Tuple2<word, scalar>("deposition", deposited));
    }
    if (!(inflow > 0))
    {
        return;
    }
    string inlets;
    for (const auto& patchInflow : patchInflows)
    {
        if (patchInflow.second() >= 1e-3*inflow)
        {
            inlets += (inlets.empty() ? "" : " ") + patchInflow.first();
        }
    }

    // The fullest cell at the open top
    scalar alphaTop = 0;
    string tops;
    forEachPatchOf<prghBulkRetainingTotalPressureFvPatchScalarField>
    (
        [&](prghBulkRetainingTotalPressureFvPatchScalarField&, label i)
        {
            tops += (tops.empty() ? "" : " ") + mesh.boundary()[i].name();
            alphaTop =
                max(alphaTop, gMax(alpha_.boundaryField()[i].patchInternalField()()));
        }
    );
    if (alphaTop > 0.5)
    {
        FatalErrorInFunction
            << "The fill overflows the bin: the bulk has reached the open"
            << " top (" << tops.c_str() << ") (alpha.granular "
            << alphaTop << " in a cell next to it) at time "
            << mesh.time().timeName() << " while " << inflow
            << " m3/s of bulk still enters through (" << inlets.c_str()
            << ")." << nl
            << "    End the fill earlier (system/controlDict endTime), lower"
            << " the inlet's rate or the fill time, or make the bin taller."
            << exit(FatalError);
    }
}


Foam::tmp<Foam::volScalarField> Foam::bulkFlowModels::muI::pressure() const
{
    return max(p_, dimensionedScalar(dimPressure, Zero));
}


void Foam::bulkFlowModels::muI::correct()
{
    if (deposition_.valid())
    {
        deposition_->update(alpha_);
    }
    while (pimple_.loop())
    {
        solveAlpha();
        checkFillOverflow();
        updateViscosity();
        solveFlow();
    }
    if (deposition_.valid())
    {
        deposition_->record();
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "speciesAdvection.H"
#include "fvm.H"
#include "gaussConvectionScheme.H"
#include "limitedSurfaceInterpolationScheme.H"
#include "fvmLaplacian.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "mixedFvPatchFields.H"
#include "gaussLaplacianScheme.H"
#include "snGradScheme.H"
#include "scratchField.H"
#include "gradScheme.H"
#include "linear.H"
#include "fvcDiv.H"
#include "IStringStream.H"
#include "OStringStream.H"

#include <algorithm>

namespace Foam
{
    defineTypeNameAndDebug(sharedWeights, 0);
    defineTypeNameAndDebug(speciesAdvection, 0);
}

const Foam::word Foam::speciesAdvection::schemeName_("div(phi,n)");

const Foam::word Foam::speciesAdvection::laplacianName_("laplacian(D,n)");

// Small against any bulk fraction that holds material worth counting: the
// term moves volume between the species (emptyWeight_ V dc a cell), and at
// 1e-9 it moved up to 1.2e-8 of a fill (surface cells at alpha ~ 1e-9,
// where it weighed as much as the bulk); at 1e-14, 1.2e-9
const Foam::scalar Foam::speciesAdvection::emptyWeight_ = 1e-14;

const Foam::scalar Foam::speciesAdvection::bulkCellAlpha_ = 0.5;

// The correction vectors of a blockMesh box are round-off (3.1e-13 on a
// 400 x 400 unit square, growing with the cells across it), not a
// correction worth a gradient per species per step: |k| is the tangent of
// the face's non-orthogonality, and below 1e-10 the correction is below
// 1e-10 of Df |Sf| |grad n| on every face
const Foam::scalar Foam::speciesAdvection::nonOrthogonalTolerance_ = 1e-10;
const Foam::scalar Foam::speciesAdvection::undershootTolerance_ = 1e-10;

// Below this share of a cell's solids a species counts as absent for the
// non-orthogonal correction (correctCorrectionFactor): 1e-12 still left
// n.coarse at -3.9e-9 in silo2D; 1e-3 would scale the column's correction
// where its fines are at 8.7e-4
const Foam::scalar Foam::speciesAdvection::presenceFraction_ = 1e-6;


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::speciesAdvection::checkDdtSchemes() const
{
    const fvMesh& mesh = mixture_.mesh();
    for (const volScalarField& n : mixture_.n())
    {
        const word ddtName("ddt(" + n.name() + ")");
        ITstream& is = mesh.ddtScheme(ddtName);
        const word scheme(is);
        if (scheme != "Euler")
        {
            FatalIOErrorInFunction(mesh.schemesDict())
                << "ddtSchemes: '" << ddtName << "' is " << scheme
                << "; with a free surface (bulk flow "
                << "with a bulk fraction, e.g. muI) the species must use "
                << "Euler, as alpha's MULES step does, so that their sum "
                << "stays packedFraction alpha" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::speciesAdvection::correctWeights
(
    const surfaceScalarField& faceFlux,
    const bool freeSurface
)
{
    weights_.clear();

    const fvMesh& mesh = mixture_.mesh();
    tmp<fv::convectionScheme<scalar>> tscheme
    (
        fv::convectionScheme<scalar>::New
        (
            mesh,
            faceFlux,
            mesh.divScheme(schemeName_)
        )
    );

    const auto* gauss =
        dynamic_cast<const fv::gaussConvectionScheme<scalar>*>(&tscheme());
    const PtrList<volScalarField>& n = mixture_.n();

    if (freeSurface && (!gauss || gauss->interpScheme().corrected()))
    {
        FatalIOErrorInFunction(mesh.schemesDict())
            << "divSchemes: '" << schemeName_ << "' is "
            << tscheme().type()
            << (gauss ? word(" " + gauss->interpScheme().type()) : word::null)
            << "; with a free surface the species need Gauss with weights"
            << " and no explicit correction: upwind, linear or a limited"
            << " scheme (vanLeer01, limitedLinear01, vanLeer, ...)" << nl
            << exit(FatalIOError);
    }
    if (!gauss || gauss->interpScheme().corrected())
    {
        // OpenFOAM's path, each species with its own explicit correction
        // (linearUpwind, LUST: their upwind part is a limited scheme whose
        // limiter is 0, so the shared limiter below would drop the
        // correction)
        return;
    }

    const auto* limited =
        dynamic_cast<const limitedSurfaceInterpolationScheme<scalar>*>
        (
            &gauss->interpScheme()
        );

    if (!limited || (n.size() < 2 && !freeSurface))
    {
        // Field-independent weights (or one species' own limited ones):
        // OpenFOAM's, kept for the operator the species share and for the
        // bulk fraction's interpolation
        weights_.reset
        (
            new surfaceScalarField
            (
                "speciesAdvectionWeights",
                gauss->interpScheme().weights(n[0])
            )
        );
        return;
    }

    tmp<surfaceScalarField> tlimiter(limited->limiter(n[0]));
    for (label k = 1; k < n.size(); ++k)
    {
        tlimiter.ref() = min(tlimiter(), limited->limiter(n[k]));
    }

    // ... and the total's, which the species' limiters do not bound where
    // the composition varies: on the snapped silo3D the total rose by up
    // to 4e-7 a step above packing without it. (With a free surface the
    // total is the bulk's, carried by alpha's MULES flux instead.)
    if (!freeSurface)
    {
        // Only where the total varies (variesAcross): where it is uniform
        // its limiter would restrict the species' faces at random
        tmp<surfaceScalarField> ttotalLimiter
        (
            limited->limiter(mixture_.nTotal())
        );
        surfaceScalarField& totalLimiter = ttotalLimiter.ref();
        totalLimiter += 2*(1 - variesAcross(mixture_.nTotal()));
        tlimiter.ref() = min(tlimiter(), totalLimiter);
    }

    // Cap at 1 (between central and upwind weights): a TVD limiter may
    // reach 2, i.e. downwind weights, which are TVD for the field they were
    // computed from but anti-diffusive, and with implicit Euler unstable,
    // for the total solids fraction that all species share. Limiters that
    // are 1 at r = 1 (vanLeer, limitedLinear, ...) stay second order.
    tlimiter.ref() = min(tlimiter(), scalar(1));

    weights_.reset
    (
        new surfaceScalarField
        (
            "speciesAdvectionWeights",
            limited->weights(n[0], mesh.surfaceInterpolation::weights(), tlimiter)
        )
    );
}


void Foam::speciesAdvection::checkInitialSum() const
{
    const volScalarField& alpha = *bulkFlow_.bulkFraction();
    const scalar packed = bulkFlow_.packedFraction();
    const scalar mismatch =
        gMax
        (
            mag
            (
                mixture_.nTotal().primitiveField()
              - packed*alpha.primitiveField()
            )
        );
    if (mismatch > 1e-4*packed)
    {
        FatalIOError
        (
            FUNCTION_NAME, __FILE__, __LINE__,
            alpha.objectPath()
        )   << "The species' sum " << mixture_.names()
            << " differs from packedFraction " << packed << " x "
            << alpha.name() << " by up to " << mismatch
            << " (more than 1e-4 packedFraction): with a free surface the"
            << " species live in the bulk; set n.<species> and "
            << alpha.name() << " together (e.g. setFields), with"
            << " sum_i n_i = packedFraction " << alpha.name() << nl
            << exit(FatalIOError);
    }
}


void Foam::speciesAdvection::correctCompositions()
{
    // Round-off may leave traces of either sign in cells the bulk has left:
    // the compositions are those of the non-negative parts, so that they
    // stay in [0, 1] and sum to 1 in every cell
    const PtrList<volScalarField>& n = mixture_.n();
    const scalarField& V = mixture_.mesh().V().field();

    scalarField sum(n[0].primitiveField().size(), Zero);
    for (const volScalarField& nk : n)
    {
        sum += max(nk.primitiveField(), scalar(0));
    }

    // Cells without solids take the mean composition of the solids in the
    // domain (a species absent everywhere stays absent); in a domain without
    // solids (a bin before its fill), that of the fixed values on the
    // boundary (the feed), else 1/N
    const scalar total = gSum(sum*V);
    scalarList mean(n.size(), 1.0/n.size());
    if (total > VSMALL)
    {
        forAll(n, k)
        {
            mean[k] = gSum(max(n[k].primitiveField(), scalar(0))*V)/total;
        }
    }
    else
    {
        // Weighted by each face's inflow; by its area where nothing flows
        // in yet
        const surfaceScalarField::Boundary& phib = bulkFlow_.phi().boundaryField();
        const surfaceScalarField::Boundary& magSfb =
            mixture_.mesh().magSf().boundaryField();
        auto fixedComposition = [&](const bool byInflow)
        {
            scalarList fixedTotal(n.size(), Zero);
            forAll(n[0].boundaryField(), patchi)
            {
                if (!composition_[0].boundaryField()[patchi].fixesValue())
                {
                    continue;
                }
                const scalarField weight
                (
                    byInflow
                  ? scalarField(max(-phib[patchi], scalar(0)))
                  : scalarField(magSfb[patchi])
                );
                forAll(n, k)
                {
                    fixedTotal[k] += gSum
                    (
                        max(n[k].boundaryField()[patchi], scalar(0))*weight
                    );
                }
            }
            return fixedTotal;
        };
        scalarList fixedTotal(fixedComposition(true));
        if (!(Foam::sum(fixedTotal) > VSMALL))
        {
            fixedTotal = fixedComposition(false);
        }
        const scalar fixedSum = Foam::sum(fixedTotal);
        if (fixedSum > VSMALL)
        {
            forAll(n, k)
            {
                mean[k] = fixedTotal[k]/fixedSum;
            }
        }
    }

    forAll(n, k)
    {
        scalarField& c = composition_[k].primitiveFieldRef();
        const scalarField nk(max(n[k].primitiveField(), scalar(0)));
        forAll(c, celli)
        {
            c[celli] = sum[celli] > VSMALL ? nk[celli]/sum[celli] : mean[k];
        }
    }

    // Fixed values on the patches where n fixes its value (an inflow)
    forAll(n[0].boundaryField(), patchi)
    {
        if (!composition_[0].boundaryField()[patchi].fixesValue())
        {
            continue;
        }
        scalarField sumb(n[0].boundaryField()[patchi].size(), Zero);
        for (const volScalarField& nk : n)
        {
            sumb += nk.boundaryField()[patchi];
        }
        forAll(n, k)
        {
            const fvPatchScalarField& nb = n[k].boundaryField()[patchi];
            fvPatchScalarField& cb = composition_[k].boundaryFieldRef()[patchi];
            forAll(cb, facei)
            {
                cb[facei] =
                    sumb[facei] > VSMALL ? nb[facei]/sumb[facei] : mean[k];
            }
        }
    }

    for (volScalarField& c : composition_)
    {
        c.correctBoundaryConditions();
    }
}


Foam::word Foam::speciesAdvection::laplacianSnGrad() const
{
    const fvMesh& mesh = mixture_.mesh();
    ITstream& is = mesh.laplacianScheme(laplacianName_);
    forAll(is, tokeni)
    {
        if (!is[tokeni].isWord())
        {
            continue;
        }
        const word& w = is[tokeni].wordToken();
        if (w == "corrected" || w == "uncorrected" || w == "orthogonal")
        {
            return w;
        }
        if (w == "limited" || w == "faceCorrected")
        {
            break;
        }
    }

    OStringStream scheme;
    forAll(is, tokeni)
    {
        scheme << (tokeni ? " " : "") << is[tokeni];
    }
    FatalIOErrorInFunction(mesh.schemesDict())
        << "laplacianSchemes: '" << laplacianName_ << "' is '"
        << scheme.str().c_str() << "'; the species share one linear "
        << "diffusion operator (so that their diffusion fluxes sum to the "
        << "total's), which a snGrad limited per species breaks. Valid "
        << "snGrad schemes: corrected, uncorrected, orthogonal" << nl
        << exit(FatalIOError);
    return word::null;
}


bool Foam::speciesAdvection::selectDiffusionGradients()
{
    // gradSchemes of every species and of their total: one unlimited
    // scheme that is linear in the field (the species' corrections then
    // sum to the total's), optionally behind a limiter
    const fvMesh& mesh = mixture_.mesh();
    static const wordHashSet limiters
    ({
        "cellLimited", "cellMDLimited", "faceLimited", "faceMDLimited"
    });
    static const std::string linearSchemes[] =
    {
        "Gauss linear", "leastSquares", "pointCellsLeastSquares"
    };

    std::string base;
    bool limited = false;
    word baseField;
    const auto parse = [&](const volScalarField& field)
    {
        const word entry("grad(" + field.name() + ')');
        ITstream& is = mesh.gradScheme(entry);
        OStringStream all;
        forAll(is, tokeni)
        {
            all << (tokeni ? " " : "") << is[tokeni];
        }
        const bool isLimited =
            is.size() > 2 && is[0].isWord()
         && limiters.found(is[0].wordToken());
        OStringStream unlimited;
        for
        (
            label tokeni = isLimited ? 1 : 0;
            tokeni < (isLimited ? is.size() - 1 : is.size());
            ++tokeni
        )
        {
            unlimited << (tokeni > (isLimited ? 1 : 0) ? " " : "")
                << is[tokeni];
        }
        const std::string fieldBase(unlimited.str());
        if
        (
            std::find
            (
                std::begin(linearSchemes), std::end(linearSchemes), fieldBase
            ) == std::end(linearSchemes)
        )
        {
            FatalIOErrorInFunction(mesh.schemesDict())
                << "gradSchemes: '" << entry << "' is '"
                << all.str().c_str() << "'; the species' diffusion takes its "
                << "non-orthogonal correction from this gradient, which must "
                << "be linear in the field (so that the species' corrections "
                << "sum to the total's): Gauss linear, leastSquares or "
                << "pointCellsLeastSquares, optionally limited (cellLimited, "
                << "cellMDLimited, faceLimited or faceMDLimited <scheme> "
                << "<coefficient>; the correction then takes one limiter "
                << "shared by the species, cellLimited <scheme> 1)" << nl
                << exit(FatalIOError);
        }
        if (baseField.empty())
        {
            base = fieldBase;
            baseField = entry;
        }
        else if (fieldBase != base)
        {
            FatalIOErrorInFunction(mesh.schemesDict())
                << "gradSchemes: '" << entry << "' uses " << fieldBase.c_str()
                << " and '" << baseField << "' " << base.c_str() << "; the species "
                << "and their total need the same gradient (limited or not) "
                << "so that their diffusion corrections sum to the total's"
                << nl << exit(FatalIOError);
        }
        limited = limited || isLimited;
    };
    for (const volScalarField& n : mixture_.n())
    {
        parse(n);
    }
    parse(mixture_.nTotal());

    if (base != diffusionGradScheme_)
    {
        linearGrad_ = fv::gradScheme<scalar>::New(mesh, IStringStream(base)());
        limitedGrad_ =
            fv::gradScheme<scalar>::New
            (
                mesh,
                IStringStream("cellLimited " + base + " 1")()
            );
        diffusionGradScheme_ = base;
    }
    return limited;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::speciesAdvection::variesAcross(const volScalarField& field) const
{
    // 1 on the internal and coupled faces whose two cells differ by more
    // than 1e-8 of the largest total, 0 elsewhere. Differences below that
    // are the linear solvers' noise: limiters computed from them (ratios
    // of noise) restrict faces at random and differ between serial and
    // parallel runs
    const fvMesh& mesh = mixture_.mesh();
    const scalar tolerance =
        1e-8*max(gMax(mixture_.nTotal().primitiveField()), SMALL);

    tmp<surfaceScalarField> tvaries
    (
        new surfaceScalarField
        (
            IOobject
            (
                "variesAcross(" + field.name() + ')',
                mesh.time().timeName(),
                mesh,
                IOobject::NO_READ,
                IOobject::NO_WRITE
            ),
            mesh,
            dimensionedScalar(dimless, Zero)
        )
    );
    surfaceScalarField& varies = tvaries.ref();

    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const scalarField& f = field.primitiveField();
    forAll(own, facei)
    {
        varies[facei] = mag(f[nei[facei]] - f[own[facei]]) > tolerance;
    }
    forAll(field.boundaryField(), patchi)
    {
        const fvPatchScalarField& fp = field.boundaryField()[patchi];
        if (!fp.coupled())
        {
            continue;
        }
        const scalarField jump
        (
            mag(fp.patchNeighbourField() - fp.patchInternalField())
        );
        scalarField& vp = varies.boundaryFieldRef()[patchi];
        forAll(vp, facei)
        {
            vp[facei] = jump[facei] > tolerance;
        }
    }
    return tvaries;
}


Foam::tmp<Foam::surfaceScalarField>
Foam::speciesAdvection::bulkFractionMinFaces() const
{
    const volScalarField& alpha = *bulkFlow_.bulkFraction();
    tmp<surfaceScalarField> talphaf
    (
        new surfaceScalarField
        (
            IOobject("alphaMinf", alpha.time().timeName(), alpha.mesh()),
            alpha.mesh(),
            dimensionedScalar(dimless, Zero)
        )
    );
    surfaceScalarField& alphaf = talphaf.ref();
    const labelUList& own = alpha.mesh().owner();
    const labelUList& nei = alpha.mesh().neighbour();
    forAll(alphaf, facei)
    {
        alphaf[facei] = min(alpha[own[facei]], alpha[nei[facei]]);
    }
    forAll(alphaf.boundaryField(), patchi)
    {
        const fvPatchScalarField& alphab = alpha.boundaryField()[patchi];
        alphaf.boundaryFieldRef()[patchi] =
            alphab.coupled()
          ? min(alphab.patchInternalField(), alphab.patchNeighbourField())
          : tmp<scalarField>(alphab);
    }
    return talphaf;
}


Foam::tmp<Foam::scalarField> Foam::speciesAdvection::bulkSolids() const
{
    return
        bulkFlow_.packedFraction()
       *bulkFlow_.bulkFraction()->primitiveField();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::speciesAdvection::speciesAdvection
(
    const granularMixture& mixture,
    const bulkFlowModel& bulkFlow
)
:
    mixture_(mixture),
    bulkFlow_(bulkFlow),
    nonOrthogonal_
    (
        gMax(mag(mixture.mesh().nonOrthCorrectionVectors())().primitiveField())
      > nonOrthogonalTolerance_
    ),
    diffusionTimeIndex_(-1),
    operatorDf_(nullptr),
    operatorEuler_(false),
    operatorTimeIndex_(-1)
{
    if (debug)
    {
        Info<< "speciesAdvection: largest non-orthogonal correction vector "
            << gMax(mag(mixture.mesh().nonOrthCorrectionVectors())().primitiveField())
            << " (corrections " << (nonOrthogonal_ ? "on" : "off") << ")"
            << endl;
    }

    if (!freeSurface())
    {
        return;
    }

    checkDdtSchemes();
    checkInitialSum();

    // The compositions take the coupled and constraint conditions of the
    // species, a fixed value where the species fix theirs (an inflow), and
    // zero gradient on the other patches (outflow with the cell's
    // composition; walls)
    const fvMesh& mesh = mixture.mesh();
    const PtrList<volScalarField>& n = mixture.n();
    composition_.setSize(n.size());
    speciesFlux_.setSize(n.size());
    forAll(n, k)
    {
        wordList types(n[k].boundaryField().types());
        forAll(types, patchi)
        {
            const fvPatchScalarField& nb = n[k].boundaryField()[patchi];
            if
            (
                !nb.coupled()
             && !polyPatch::constraintType(nb.patch().patch().type())
            )
            {
                // inletOutlet (mixed) lets the bulk out with the cell's
                // composition; the air, not the bulk, comes in
                types[patchi] =
                    nb.fixesValue() && !isA<mixedFvPatchScalarField>(nb)
                  ? fixedValueFvPatchScalarField::typeName
                  : zeroGradientFvPatchScalarField::typeName;
            }
        }
        composition_.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    "c." + mixture.names()[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE
                ),
                mesh,
                dimensionedScalar(dimless, Zero),
                types
            )
        );
        speciesFlux_.set
        (
            k,
            new surfaceScalarField
            (
                IOobject
                (
                    "nPhi." + mixture.names()[k],
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dimVolume/dimTime, Zero)
            )
        );
    }
    correctCompositions();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::speciesAdvection::correct()
{
    if (!freeSurface())
    {
        correctWeights(bulkFlow_.phi(), false);
        return;
    }

    // Weights in the direction of the bulk's own flux (the limiter is the
    // species' shared one, computed on n), then the compositions of the
    // step's start
    correctCompositions();
    correctWeights(bulkFlow_.bulkFractionFlux(), true);

    // The composition crossing a face: the shared (limited) weights where
    // both cells hold bulk (alpha >= bulkCellAlpha_ after the step), upwind
    // in the bulk's own flux elsewhere. A cell without bulk has no
    // composition of its own, and a downwind weight on it would leave a
    // cell the bulk enters with a diagonal below its inflow (a cell the
    // bulk left within the step has alpha' = 0 while its old content
    // crossed the face): with upwind there the matrix is an M-matrix.
    // Non-coupled patches keep the boundary values.
    const surfaceScalarField& alphaPhi = bulkFlow_.bulkFractionFlux();
    const surfaceScalarField alphaMin(bulkFractionMinFaces());
    surfaceScalarField& w = weights_.ref();

    forAll(w, facei)
    {
        if (alphaMin[facei] < bulkCellAlpha_)
        {
            w[facei] = pos0(alphaPhi[facei]);
        }
    }
    forAll(w.boundaryField(), patchi)
    {
        if (!w.boundaryField()[patchi].coupled())
        {
            continue;
        }
        const fvsPatchScalarField& alphaMinb = alphaMin.boundaryField()[patchi];
        const fvsPatchScalarField& alphaPhib = alphaPhi.boundaryField()[patchi];
        fvsPatchScalarField& wb = w.boundaryFieldRef()[patchi];
        forAll(wb, facei)
        {
            if (alphaMinb[facei] < bulkCellAlpha_)
            {
                wb[facei] = pos0(alphaPhib[facei]);
            }
        }
    }
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::fvmDiv
(
    const volScalarField& n
) const
{
    const surfaceScalarField& phi = bulkFlow_.phi();
    if (!weights_.valid())
    {
        return fvm::div(phi, n, schemeName_);
    }

    const fvMesh& mesh = mixture_.mesh();
    return fv::gaussConvectionScheme<scalar>
    (
        mesh,
        phi,
        tmp<surfaceInterpolationScheme<scalar>>
        (
            new sharedWeights(mesh, weights_())
        )
    ).fvmDiv(phi, n);
}


void Foam::speciesAdvection::correctDiffusion()
{
    const fvMesh& mesh = mixture_.mesh();
    diffusionTimeIndex_ = mesh.time().timeIndex();

    // The implicit part: the orthogonal snGrad for `orthogonal`, else the
    // uncorrected one (the correction is added explicitly below)
    const word snGrad(laplacianSnGrad());
    const word implicitSnGrad
    (
        snGrad == "orthogonal" ? "orthogonal" : "uncorrected"
    );
    if (!implicitLaplacian_.valid() || implicitSnGrad != implicitSnGrad_)
    {
        implicitLaplacian_.reset
        (
            new fv::gaussLaplacianScheme<scalar, scalar>
            (
                mesh,
                tmp<surfaceInterpolationScheme<scalar>>
                (
                    new linear<scalar>(mesh)
                ),
                fv::snGradScheme<scalar>::New
                (
                    mesh,
                    IStringStream(implicitSnGrad)()
                )
            )
        );
        implicitSnGrad_ = implicitSnGrad;
    }

    diffusionGrad_.clear();
    if (snGrad != "corrected")
    {
        return;
    }
    // Checked on every mesh, so that a case's schemes are refused or
    // accepted whatever its mesh
    const bool limit = selectDiffusionGradients();
    if (!nonOrthogonal_)
    {
        return;
    }

    // Unlimited gradients (gradSchemes for the species and the total):
    // the correction is OpenFOAM's corrected one. Limited gradients: the
    // limiter of each field is |cell-limited gradient|/|gradient| of the
    // same unlimited gradient (cellLimited scales it by one factor per
    // cell); the smallest over the species and their total is shared,
    // each field counting only in the cells where it varies across some
    // face (variesAcross). On skewed cells Gauss linear is not consistent
    // (its face values are not at the face centres) and leastSquares is
    // exact for linear fields: the correction is then second order
    const PtrList<volScalarField>& n = mixture_.n();
    scalarField limiter(mesh.nCells(), scalar(1));

    const auto limitBy = [&](const volScalarField& field)
    {
        const word name("diffusionGrad(" + field.name() + ')');
        tmp<volVectorField> tgLinear(linearGrad_().grad(field, name));
        if (!limit)
        {
            return tgLinear;
        }
        const volVectorField gLimited(limitedGrad_().grad(field, name));
        const scalarField variesFaces
        (
            fvc::surfaceSum(variesAcross(field))().primitiveField()
        );
        const vectorField& gLinear = tgLinear().primitiveField();
        forAll(limiter, celli)
        {
            const scalar magLinear = mag(gLinear[celli]);
            if (variesFaces[celli] > 0.5 && magLinear > VSMALL)
            {
                limiter[celli] =
                    min(limiter[celli], mag(gLimited[celli])/magLinear);
            }
        }
        return tgLinear;
    };

    diffusionGrad_.setSize(n.size());
    forAll(n, k)
    {
        diffusionGrad_.set(k, limitBy(n[k]).ptr());
    }
    correctCorrectionFactor();
    if (!limit)
    {
        return;
    }
    limitBy(mixture_.nTotal());

    for (volVectorField& grad : diffusionGrad_)
    {
        grad.primitiveFieldRef() *= limiter;
        grad.correctBoundaryConditions();
    }
}


void Foam::speciesAdvection::correctCorrectionFactor()
{
    // The correction is explicit and comes from the gradient of the cells
    // around: across a face of a cell without a species it can still carry
    // that species out of the cell. With the explicit sieving flux's
    // limited face values the species then fell below 0 (to -2.3e-6 in
    // silo2D's hopper-wall cells, 29 deg, where the sieving leaves pure
    // fines; either one alone kept the fields within 1e-17). One factor per
    // face for all species, so that their corrections still sum to the
    // total's: the smallest over the face's two cells and the species of
    // min(1, n_k/(presenceFraction_ sum_i n_i))
    const fvMesh& mesh = mixture_.mesh();
    const PtrList<volScalarField>& n = mixture_.n();
    const scalarField& total = mixture_.nTotal().primitiveField();

    tmp<volScalarField> tpresence
    (
        scratchField(mesh, "presence", dimless)
    );
    volScalarField& presence = tpresence.ref();
    scalarField& p = presence.primitiveFieldRef();
    p = 1;
    forAll(n, k)
    {
        const scalarField& nk = n[k].primitiveField();
        forAll(p, celli)
        {
            const scalar solids = presenceFraction_*total[celli];
            if (solids > VSMALL)
            {
                p[celli] =
                    min(p[celli], min(scalar(1), max(nk[celli], scalar(0))/solids));
            }
        }
    }
    presence.correctBoundaryConditions();

    if (!correctionFactor_.valid())
    {
        correctionFactor_.reset
        (
            new surfaceScalarField
            (
                IOobject
                (
                    "nonOrthogonalCorrectionFactor",
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    false
                ),
                mesh,
                dimensionedScalar("1", dimless, scalar(1))
            )
        );
    }
    surfaceScalarField& factor = correctionFactor_.ref();
    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    forAll(own, facei)
    {
        factor[facei] = min(p[own[facei]], p[nei[facei]]);
    }
    forAll(factor.boundaryField(), patchi)
    {
        const fvPatchScalarField& pp = presence.boundaryField()[patchi];
        scalarField& fp = factor.boundaryFieldRef()[patchi];
        fp = pp.patchInternalField();
        if (pp.coupled())
        {
            fp = min(fp, pp.patchNeighbourField());
        }
    }
}


Foam::tmp<Foam::scalarField> Foam::speciesAdvection::nonOrthogonalCorrection
(
    const label k,
    const surfaceScalarField& gammaMagSf
) const
{
    const fvMesh& mesh = mixture_.mesh();
    return
        mesh.V()
       *fvc::div
        (
            gammaMagSf
           *correctionFactor_()
           *linear<vector>(mesh).dotInterpolate
            (
                mesh.nonOrthCorrectionVectors(),
                diffusionGrad_[k]
            )
        )().primitiveField();
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::fvmLaplacian
(
    const label k,
    const surfaceScalarField& Df
) const
{
    const fvMesh& mesh = mixture_.mesh();
    const volScalarField& n = mixture_.n()[k];
    if (diffusionTimeIndex_ != mesh.time().timeIndex())
    {
        FatalErrorInFunction
            << "correctDiffusion() was not called in this time step before "
            << "fvmLaplacian(" << n.name() << ")" << abort(FatalError);
    }

    // The implicit part (Df is on the faces: the scheme's interpolation
    // is not used)
    tmp<fvScalarMatrix> tnEqn(implicitLaplacian_->fvmLaplacian(Df, n));

    if (k < diffusionGrad_.size())
    {
        // The non-orthogonal correction, explicit, from the species'
        // gradient (with the shared limiter)
        tnEqn.ref().source() -= nonOrthogonalCorrection(k, Df*mesh.magSf());
    }
    return tnEqn;
}


bool Foam::speciesAdvection::correctOperator
(
    const surfaceScalarField& Df,
    const bool diffusion,
    const label firstSpecies
)
{
    operatorTimeIndex_ = -1;
    sharedOperator_.clear();
    operatorGammaMagSf_.clear();
    operatorDeltaCoeffs_.clear();

    // Shared weights are kept for Gauss schemes without an explicit
    // correction (correctWeights): only then do the species' matrices
    // differ in nothing but their boundary values and sources
    if (freeSurface() || bulkFlow_.speciesFluxes() || !weights_.valid())
    {
        return false;
    }

    const fvMesh& mesh = mixture_.mesh();
    const volScalarField& n0 = mixture_.n()[firstSpecies];

    // OpenFOAM's assembly for the species solved first (its boundary
    // conditions are updated here, just before its solve, as they would be
    // by its own assembly): its lower, upper and diagonal do not depend on
    // the field
    tmp<fvScalarMatrix> top(fvmDiv(n0));
    if (diffusion)
    {
        if (diffusionTimeIndex_ != mesh.time().timeIndex())
        {
            FatalErrorInFunction
                << "correctDiffusion() was not called in this time step "
                << "before correctOperator()" << abort(FatalError);
        }
        top.ref() -= implicitLaplacian_->fvmLaplacian(Df, n0);

        // What gaussLaplacianScheme's boundary coefficients take
        operatorGammaMagSf_.reset(new surfaceScalarField(Df*mesh.magSf()));
        operatorDf_ = &Df;
        operatorDeltaCoeffs_ =
            fv::snGradScheme<scalar>::New
            (
                mesh,
                IStringStream(implicitSnGrad_)()
            )().deltaCoeffs(n0);
    }

    // Euler on a static mesh: ddt's diagonal, rDeltaT V, is every
    // species' (its source, rDeltaT V n_old, is added per species);
    // another ddt scheme is assembled per species
    operatorEuler_ = !mesh.moving();
    for (const volScalarField& n : mixture_.n())
    {
        ITstream& is = mesh.ddtScheme("ddt(" + n.name() + ')');
        operatorEuler_ =
            operatorEuler_
         && is.size() == 1 && is[0].isWord() && is[0].wordToken() == "Euler";
    }
    if (operatorEuler_)
    {
        top.ref() += fvm::ddt(n0);
    }

    sharedOperator_.reset(top.ptr());
    operatorTimeIndex_ = mesh.time().timeIndex();
    return true;
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::sharedOperator
(
    const label k
) const
{
    const fvMesh& mesh = mixture_.mesh();
    const volScalarField& n = mixture_.n()[k];
    if (operatorTimeIndex_ != mesh.time().timeIndex())
    {
        FatalErrorInFunction
            << "correctOperator() did not assemble the shared operator in "
            << "this time step before sharedOperator(" << n.name() << ")"
            << abort(FatalError);
    }

    const fvScalarMatrix& shared = sharedOperator_();
    tmp<fvScalarMatrix> tm(new fvScalarMatrix(n, shared.dimensions()));
    fvScalarMatrix& m = tm.ref();
    m.lduMatrix::operator=(shared);

    if (operatorEuler_)
    {
        // The source of EulerDdtScheme::fvmDdt, its diagonal is shared
        const scalar rDeltaT = 1.0/mesh.time().deltaTValue();
        const scalarField& nOld = n.oldTime().primitiveField();
        const scalarField& V = mesh.V().field();
        scalarField& source = m.source();
        forAll(source, celli)
        {
            source[celli] = rDeltaT*nOld[celli]*V[celli];
        }
    }

    // The species' boundary coefficients, as gaussConvectionScheme::fvmDiv
    // and gaussLaplacianScheme::fvmLaplacianUncorrected make them from its
    // patch fields
    const surfaceScalarField& phi = bulkFlow_.phi();
    const surfaceScalarField& w = weights_();
    const bool diffusion = operatorGammaMagSf_.valid();
    forAll(n.boundaryField(), patchi)
    {
        const fvPatchScalarField& pn = n.boundaryField()[patchi];
        const fvsPatchScalarField& pFlux = phi.boundaryField()[patchi];
        const fvsPatchScalarField& pw = w.boundaryField()[patchi];
        scalarField& internal = m.internalCoeffs()[patchi];
        scalarField& boundary = m.boundaryCoeffs()[patchi];

        internal = pFlux*pn.valueInternalCoeffs(pw);
        boundary = -pFlux*pn.valueBoundaryCoeffs(pw);

        if (!diffusion)
        {
            continue;
        }
        const fvsPatchScalarField& pGamma =
            operatorGammaMagSf_().boundaryField()[patchi];
        if (pn.coupled())
        {
            const fvsPatchScalarField& pDeltaCoeffs =
                operatorDeltaCoeffs_().boundaryField()[patchi];
            internal -= pGamma*pn.gradientInternalCoeffs(pDeltaCoeffs);
            boundary -= -pGamma*pn.gradientBoundaryCoeffs(pDeltaCoeffs);
        }
        else
        {
            internal -= pGamma*pn.gradientInternalCoeffs();
            boundary -= -pGamma*pn.gradientBoundaryCoeffs();
        }
    }

    if (diffusion && k < diffusionGrad_.size())
    {
        // The species' non-orthogonal correction, explicit, as in
        // fvmLaplacian
        m.source() += nonOrthogonalCorrection(k, operatorGammaMagSf_());
    }

    // Another ddt scheme, assembled for the species (once: Crank-Nicolson
    // updates its stored ddt0 at its first evaluation in a step)
    tmp<fvScalarMatrix> tddt;
    if (!operatorEuler_)
    {
        tddt = fvm::ddt(n);
        m += tddt();
    }

    if (debug)
    {
        checkSharedOperator(k, m, tddt.valid() ? tddt() : fvm::ddt(n)());
    }
    return tm;
}


void Foam::speciesAdvection::checkSharedOperator
(
    const label k,
    const fvScalarMatrix& m,
    const fvScalarMatrix& ddt
) const
{
    // The species' own assembly, as the solver makes it where the
    // operator is not shared (with the time derivative it was given: a
    // second evaluation of Crank-Nicolson's in the step would differ)
    const volScalarField& n = mixture_.n()[k];
    tmp<fvScalarMatrix> tOwn(new fvScalarMatrix(ddt));
    tOwn.ref() += fvmDiv(n);
    if (operatorGammaMagSf_.valid())
    {
        tOwn.ref() -= fvmLaplacian(k, *operatorDf_);
    }
    const fvScalarMatrix& own = tOwn();

    // The largest difference of each part relative to the largest
    // coefficient of that part (all processors)
    const auto relDiff = [](const scalarField& a, const scalarField& b)
    {
        return gMax(mag(a - b)())/max(gMax(mag(b)()), VSMALL);
    };
    scalar matrixDiff = max
    (
        relDiff(m.diag(), own.diag()),
        max(relDiff(m.upper(), own.upper()), relDiff(m.lower(), own.lower()))
    );
    scalar sourceDiff = relDiff(m.source(), own.source());
    // Each patch's coefficients relative to that patch's largest on this
    // processor (a patch with small coefficients is not hidden behind a
    // large one; no reduction per patch: processors differ in patches)
    const auto localRelDiff = [](const scalarField& a, const scalarField& b)
    {
        return
            a.empty() ? scalar(0) : max(mag(a - b))/max(max(mag(b)), VSMALL);
    };
    scalar boundaryDiff = 0;
    forAll(m.internalCoeffs(), patchi)
    {
        boundaryDiff = max
        (
            boundaryDiff,
            max
            (
                localRelDiff
                (
                    m.internalCoeffs()[patchi], own.internalCoeffs()[patchi]
                ),
                localRelDiff
                (
                    m.boundaryCoeffs()[patchi], own.boundaryCoeffs()[patchi]
                )
            )
        );
    }
    reduce(boundaryDiff, maxOp<scalar>());

    Info<< "speciesAdvection: shared operator of " << n.name()
        << " against its own assembly: relative difference "
        << max(matrixDiff, boundaryDiff) << " (matrix " << matrixDiff
        << ", boundary " << boundaryDiff << "), source " << sourceDiff
        << endl;

    if (max(max(matrixDiff, boundaryDiff), sourceDiff) > 1e-12)
    {
        FatalErrorInFunction
            << "the shared operator of " << n.name() << " differs from its "
            << "own assembly by more than 1e-12 relative: matrix "
            << matrixDiff << ", boundary " << boundaryDiff << ", source "
            << sourceDiff << abort(FatalError);
    }
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::ddtDiv
(
    const label k
) const
{
    const fvMesh& mesh = mixture_.mesh();
    const volScalarField& alpha = *bulkFlow_.bulkFraction();
    const surfaceScalarField& alphaPhi = bulkFlow_.bulkFractionFlux();
    const scalar packed = bulkFlow_.packedFraction();
    const volScalarField& c = composition_[k];
    const scalar rDeltaT = 1.0/mesh.time().deltaTValue();
    const scalarField& V = mesh.V().field();

    // packedFraction div(alphaPhi c) with the composition weights
    tmp<fvScalarMatrix> tEqn
    (
        fv::gaussConvectionScheme<scalar>
        (
            mesh,
            alphaPhi,
            tmp<surfaceInterpolationScheme<scalar>>
            (
                new sharedWeights(mesh, weights_())
            )
        ).fvmDiv(alphaPhi, c)
    );
    fvScalarMatrix& eqn = tEqn.ref();

    // packedFraction ddt(alpha c), implicit Euler with alpha's old and new
    // values, and emptyWeight_ ddt(c), which keeps the rows of empty cells
    // regular (their composition stays the domain's mean)
    eqn.diag() += (alpha.primitiveField() + emptyWeight_)*V*rDeltaT;
    eqn.source() +=
        (alpha.oldTime().primitiveField() + emptyWeight_)
       *c.primitiveField()*V*rDeltaT;

    // bulk that appeared in the step (a pour's deposition) brings its own
    // composition: with the compositions of the feed summing to 1 the
    // species' sum still follows alpha
    const volScalarField::Internal* alphaSource =
        bulkFlow_.bulkFractionSource();
    if (alphaSource)
    {
        eqn.source() +=
            bulkFlow_.bulkFractionSourceComposition(k)
           *alphaSource->field()*V;
    }

    eqn *= dimensionedScalar("packedFraction", dimless, packed);
    return tEqn;
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::laplacian
(
    const label k,
    const surfaceScalarField& Df
) const
{
    // Diffusion inside the bulk only: alpha on the face is the smaller of
    // its two cells' (none through the free surface). A limited snGrad is
    // refused as for the species
    laplacianSnGrad();
    return fvm::laplacian
    (
        bulkFlow_.packedFraction()*Df*bulkFractionMinFaces(),
        composition_[k],
        "laplacian(D,n)"
    );
}


Foam::tmp<Foam::fvScalarMatrix> Foam::speciesAdvection::inComposition
(
    const label k,
    const tmp<fvScalarMatrix>& tnEqn
) const
{
    // n = packedFraction alpha c in every cell: a diagonal matrix in n is
    // the same equation in c with its diagonal times packedFraction alpha
    const fvScalarMatrix& nEqn = tnEqn();
    if (nEqn.hasUpper() || nEqn.hasLower())
    {
        FatalErrorInFunction
            << "only a diagonal matrix (a source) in "
            << nEqn.psi().name() << " can be written for its composition"
            << abort(FatalError);
    }

    tmp<fvScalarMatrix> tcEqn
    (
        new fvScalarMatrix(composition_[k], nEqn.dimensions())
    );
    fvScalarMatrix& cEqn = tcEqn.ref();
    cEqn.diag() = nEqn.diag()*bulkSolids();
    cEqn.source() = nEqn.source();
    tnEqn.clear();
    return tcEqn;
}


void Foam::speciesAdvection::setSpecies(const label k, volScalarField& n)
{
    const volScalarField& c = composition_[k];
    n.primitiveFieldRef() = bulkSolids()*c.primitiveField();
    n.correctBoundaryConditions();

    // The species' volume flux: packedFraction alphaPhi c_f, as in its
    // equation
    speciesFlux_[k] =
        bulkFlow_.packedFraction()*bulkFlow_.bulkFractionFlux()
       *surfaceInterpolationScheme<scalar>::interpolate
        (
            c,
            tmp<surfaceScalarField>(weights_())
        );
}


Foam::label Foam::speciesAdvection::upwindAroundUndershoots()
{
    // Implicit limited weights are not bounded (a downwind share gives a
    // row a positive off-diagonal): where the composition makes new
    // extrema within the step, at the sharp front of a strong segregation
    // in a wedge, a composition fell to -6e-5 and the next step's
    // composition reset clipped it, moving 1e-3 of a fill between the
    // species. Upwind on every face of such a cell makes its row that of
    // an M-matrix (in the advection: the explicit segregation flux and
    // non-orthogonal correction stay)
    const fvMesh& mesh = mixture_.mesh();
    tmp<volScalarField> tmarked
    (
        scratchField(mesh, "undershoot", dimless)
    );
    volScalarField& marked = tmarked.ref();
    label nMarked = 0;
    forAll(marked, celli)
    {
        for (const volScalarField& c : composition_)
        {
            if (c[celli] < -undershootTolerance_)
            {
                marked[celli] = 1;
                ++nMarked;
                break;
            }
        }
    }
    reduce(nMarked, sumOp<label>());
    if (nMarked == 0)
    {
        return 0;
    }

    // Only faces whose weight changes count: where a cell's faces are all
    // upwind already (at the bulk's edge, an upwind scheme, an earlier
    // solve) the undershoot has another source (the explicit segregation
    // flux, the non-orthogonal correction) and a solve again would repeat
    // the same solve
    label nChanged = 0;
    auto setUpwind = [&nChanged](scalar& weight, const scalar flux)
    {
        const scalar upwind = pos0(flux);
        if (weight != upwind)
        {
            weight = upwind;
            ++nChanged;
        }
    };

    const labelUList& own = mesh.owner();
    const labelUList& nei = mesh.neighbour();
    const surfaceScalarField& alphaPhi = bulkFlow_.bulkFractionFlux();
    surfaceScalarField& w = weights_.ref();
    forAll(w, facei)
    {
        if (marked[own[facei]] > 0 || marked[nei[facei]] > 0)
        {
            setUpwind(w[facei], alphaPhi[facei]);
        }
    }

    // Coupled faces: marked on either side, so that both sides agree
    marked.correctBoundaryConditions();
    forAll(w.boundaryField(), patchi)
    {
        if (!w.boundaryField()[patchi].coupled())
        {
            continue;
        }
        const scalarField local
        (
            marked.boundaryField()[patchi].patchInternalField()
        );
        const scalarField remote
        (
            marked.boundaryField()[patchi].patchNeighbourField()
        );
        const fvsPatchScalarField& alphaPhib = alphaPhi.boundaryField()[patchi];
        fvsPatchScalarField& wb = w.boundaryFieldRef()[patchi];
        forAll(wb, facei)
        {
            if (local[facei] > 0 || remote[facei] > 0)
            {
                setUpwind(wb[facei], alphaPhib[facei]);
            }
        }
    }
    reduce(nChanged, sumOp<label>());

    Info<< "Species: compositions below 0 in " << nMarked << " cells";
    if (nChanged > 0)
    {
        Info<< ": upwind on " << nChanged << " more faces, solved again";
    }
    else
    {
        Info<< ", their faces upwind already: kept";
    }
    Info<< endl;
    return nChanged;
}


// ************************************************************************* //

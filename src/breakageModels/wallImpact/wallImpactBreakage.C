/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "wallImpactBreakage.H"
#include "addToRunTimeSelectionTable.H"
#include "modelCoeffs.H"
#include "IFstream.H"
#include "labelIOList.H"
#include "wallPolyPatch.H"

namespace Foam
{
namespace breakageModels
{
    defineTypeNameAndDebug(wallImpact, 0);
    addToRunTimeSelectionTable(breakageModel, wallImpact, dictionary);
}
}


namespace
{
Foam::wordList wallImpactKeys()
{
    Foam::wordList keys(Foam::impactBreakage::keys);
    keys.append("impacts");
    return keys;
}
}


Foam::labelList Foam::breakageModels::wallImpact::localFaces
(
    const label nFacesGlobal
) const
{
    const fvMesh& mesh = mixture_.mesh();
    labelList local(nFacesGlobal, -1);
    if (!Pstream::parRun())
    {
        for (label facei = 0; facei < min(nFacesGlobal, mesh.nFaces()); ++facei)
        {
            local[facei] = facei;
        }
        return local;
    }

    // decomposePar's map: local face -> 1 + undecomposed face (negative
    // when flipped)
    const labelIOList addressing
    (
        IOobject
        (
            "faceProcAddressing",
            mesh.facesInstance(),
            polyMesh::meshSubDir,
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    forAll(addressing, facei)
    {
        const label global = mag(addressing[facei]) - 1;
        if (global >= 0 && global < nFacesGlobal)
        {
            local[global] = facei;
        }
    }
    return local;
}


Foam::breakageModels::wallImpact::wallImpact
(
    const dictionary& dict,
    const granularMixture& mixture
)
:
    breakageModel
    (
        typeName,
        modelCoeffs::checked(dict, typeName, wallImpactKeys()),
        mixture
    ),
    kernel_(coeffs_),
    S_(mixture.size()),
    breakageProbability_(mixture.size())
{
    const fvMesh& mesh = mixture.mesh();
    const fileName dir
    (
        coeffs_.getOrDefault<fileName>
        (
            "impacts",
            mesh.time().globalPath()/mesh.time().constant()/"particlePass"
        ).expand()
    );

    // Read every species' list first (the largest face number sizes the
    // map of a decomposed run)
    struct record { label face; scalar rate, Un, Ut; };
    List<DynamicList<record>> records(mixture.size());
    label nFacesGlobal = mesh.nFaces();
    forAll(records, j)
    {
        const fileName file(dir/"impacts." + mixture.names()[j]);
        IFstream is(file);
        if (!is.good())
        {
            FatalIOErrorInFunction(coeffs_)
                << "breakage wallImpact: cannot read " << file
                << " (entry 'impacts' of " << coeffs_.name() << ")" << nl
                << "    The particle pass writes impacts.<species> to"
                << " postProcessing/lagrangian/<cloud>/particlePass/<time>/;"
                << " copy them there (tutorials/pipeBend/Allrun)"
                << nl << exit(FatalIOError);
        }
        string line;
        label lineNo = 0;
        while (is.getLine(line))
        {
            ++lineNo;
            if (line.empty() || line[0] == '#')
            {
                continue;
            }
            IStringStream ls(line);
            record r;
            ls >> r.face >> r.rate >> r.Un >> r.Ut;
            if
            (
                ls.bad() || r.face < 0 || !(r.rate >= 0)
             || !(r.Un >= 0) || !(r.Ut >= 0)
            )
            {
                FatalIOErrorInFunction(coeffs_)
                    << "breakage wallImpact: line " << lineNo << " of "
                    << file << " is not 'face rate Un Ut' with a face"
                    << " number and non-negative values: " << line.c_str()
                    << nl << exit(FatalIOError);
            }
            nFacesGlobal = max(nFacesGlobal, r.face + 1);
            records[j].append(r);
        }
    }

    const labelList local(localFaces(nFacesGlobal));
    const scalarField& V = mesh.V().field();

    forAll(S_, j)
    {
        const word& name = mixture.names()[j];
        const volScalarField alpha
        (
            IOobject
            (
                "alphaPass." + name,
                mesh.time().timeName(),
                mesh,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            ),
            mesh
        );

        const scalar dj = mixture.d(j);
        const scalar Vp = mixture.particleVolume(j);
        scalarField brokenRate(mesh.nCells(), Zero);
        label outside = 0;
        breakageProbability_.set
        (
            j,
            new volScalarField
            (
                IOobject
                (
                    "breakageProbability." + name,
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dimless, Zero)
            )
        );
        volScalarField::Boundary& faceP =
            breakageProbability_[j].boundaryFieldRef();
        scalarField faceRate(mesh.nBoundaryFaces(), Zero);
        for (const record& r : records[j])
        {
            const label facei = local[r.face];
            if (facei < 0)
            {
                continue;   // another processor's face
            }
            if (mesh.isInternalFace(facei))
            {
                FatalIOErrorInFunction(coeffs_)
                    << "breakage wallImpact: face " << r.face << " of "
                    << dir/"impacts." + name << " is not a boundary face"
                    << " of this mesh: was the pass run on another mesh?"
                    << nl << exit(FatalIOError);
            }
            const label celli = mesh.faceOwner()[facei];
            const scalar P = kernel_.probability(dj, r.Un, r.Ut);
            brokenRate[celli] += r.rate*Vp*P;
            const label patchi = mesh.boundaryMesh().whichPatch(facei);
            const label patchFacei =
                facei - mesh.boundaryMesh()[patchi].start();
            faceP[patchi][patchFacei] += r.rate*P;
            faceRate[facei - mesh.nInternalFaces()] += r.rate;
        }
        forAll(faceP, patchi)
        {
            const label start = mesh.boundaryMesh()[patchi].start();
            forAll(faceP[patchi], i)
            {
                const scalar rate = faceRate[start + i - mesh.nInternalFaces()];
                if (rate > 0)
                {
                    faceP[patchi][i] /= rate;
                }
            }
        }

        S_[j].setSize(mesh.nCells(), Zero);
        forAll(brokenRate, celli)
        {
            if (brokenRate[celli] > 0)
            {
                if (alpha[celli] > 0)
                {
                    S_[j][celli] = brokenRate[celli]/(alpha[celli]*V[celli]);
                }
                else
                {
                    ++outside;
                }
            }
        }
        reduce(outside, sumOp<label>());
        if (outside)
        {
            WarningInFunction
                << outside << " wall cells have impacts of species " << name
                << " but alphaPass." << name << " = 0 there: not broken"
                << endl;
        }

        Info<< "Breakage wallImpact: " << name << " broken volume rate "
            << gSum(brokenRate) << " m3/s per unit pass concentration, max S "
            << gMax(S_[j]) << " 1/s (" << returnReduce(records[j].size(), sumOp<label>())
            << " impact records)" << endl;
    }
}


void Foam::breakageModels::wallImpact::calcS
(
    const label j,
    const granularTemperatureModel&,
    volScalarField& S
) const
{
    S.primitiveFieldRef() = S_[j];
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | segregationDegradationFoam
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "siloGeometry.H"
#include "cuttingPlane.H"
#include "wedgePolyPatch.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "wallPolyPatch.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include "linePointRef.H"
#include "triPointRef.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::siloGeometry::kind> Foam::siloGeometry::kindNames
({
    { kind::axisymmetric, "axisymmetric" },
    { kind::planar, "planar" },
    { kind::threeD, "threeD" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::siloGeometry::detectKind()
{
    label nWedge = 0;
    label nEmpty = 0;
    for (const polyPatch& pp : mesh_.boundaryMesh())
    {
        if (isA<wedgePolyPatch>(pp)) { ++nWedge; }
        if (isA<emptyPolyPatch>(pp)) { ++nEmpty; }
    }
    if (nWedge)
    {
        kind_ = kind::axisymmetric;
        kindReason_ = "the mesh has wedge patches";
    }
    else if (nEmpty)
    {
        kind_ = kind::planar;
        kindReason_ = "the mesh is 2-D (empty patches)";
    }
    else
    {
        kind_ = kind::threeD;
        kindReason_ = "the mesh has neither wedge nor empty patches";
    }
}


Foam::scalar Foam::siloGeometry::cutSection
(
    const scalar z,
    pointField* points
) const
{
    const plane horizontal(-z*gHat_, -gHat_);

    // On snapped (snappyHexMesh) cells OpenFOAM's cut fails for a few warped
    // cells and warns for each of the 140 cuts of the throat scan; those
    // cells' share of the section is missing (at most 12 of the ~500 cells
    // of a section of tutorials/silo3D's mesh). Silenced for the cut only.
    const int messageLevel = messageStream::level;
    messageStream::level = 0;
    const cuttingPlane cut(horizontal, mesh_, false);
    messageStream::level = messageLevel;

    // The area projected on the horizontal (the cut lies in the plane)
    scalar area = 0;
    for (const vector& s : cut.Sf())
    {
        area += mag(s & gHat_);
    }
    if (points)
    {
        *points = cut.points();
    }
    return returnReduce(area, sumOp<scalar>());
}


Foam::scalar Foam::siloGeometry::slabDepth() const
{
    // Thinnest extent of the mesh's bounding box across gravity
    const boundBox& bb = mesh_.bounds();
    scalar depth = GREAT;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        vector e(Zero);
        e[d] = 1;
        if (mag(e & gHat_) < 0.1)
        {
            depth = min(depth, bb.span()[d]);
        }
    }
    return depth;
}


Foam::scalar Foam::siloGeometry::sectionSize
(
    const scalar area,
    const pointField& points
) const
{
    switch (kind_)
    {
        case kind::axisymmetric:
        {
            // The axis: where the wedge patches' planes meet
            List<plane> planes;
            for (const polyPatch& pp : mesh_.boundaryMesh())
            {
                if (!isA<wedgePolyPatch>(pp)) { continue; }
                vector sumSf(sum(pp.faceAreas()));
                vector sumCf(Zero);
                forAll(pp, facei)
                {
                    sumCf += mag(pp.faceAreas()[facei])*pp.faceCentres()[facei];
                }
                scalar sumMagSf(sum(mag(pp.faceAreas())));
                reduce(sumSf, sumOp<vector>());
                reduce(sumCf, sumOp<vector>());
                reduce(sumMagSf, sumOp<scalar>());
                planes.append(plane(sumCf/max(sumMagSf, VSMALL), sumSf));
            }
            if (planes.size() != 2)
            {
                FatalErrorInFunction
                    << "An axisymmetric mesh needs two wedge patches; "
                    << planes.size() << " found" << exit(FatalError);
            }
            const plane::ray axis(planes[0].planeIntersect(planes[1]));
            const vector a(normalised(axis.dir()));
            scalar rMax = 0;
            for (const point& p : points)
            {
                const vector r(p - axis.refPoint());
                rMax = max(rMax, mag(r - (r & a)*a));
            }
            return 2*returnReduce(rMax, maxOp<scalar>());
        }
        case kind::planar:
        {
            return area/slotLength_;
        }
        case kind::threeD:
        default:
        {
            return sqrt(4*area/constant::mathematical::pi);
        }
    }
}


void Foam::siloGeometry::findOrifice()
{
    // The outlet patches: their area projected on the horizontal, their
    // lowest point as the bottom of the scan
    scalar outletArea = 0;
    scalar outletTop = -GREAT;
    DynamicList<point> outletPoints;
    for (const label patchi : outletPatches_)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        for (const vector& s : pp.faceAreas())
        {
            outletArea += mag(s & gHat_);
        }
        for (const point& p : pp.localPoints())
        {
            outletTop = max(outletTop, height(p));
            outletPoints.append(p);
        }
    }
    reduce(outletArea, sumOp<scalar>());
    reduce(outletTop, maxOp<scalar>());

    orificeHeight_ = outletTop;
    orificeArea_ = outletArea;
    throat_ = false;
    pointField orificePoints(std::move(outletPoints));

    // Scan the sections above the outlet for a throat; a golden-section
    // search refines the narrowest sample
    const label nScan = 100;
    const scalar dz = (zMax_ - outletTop)/nScan;
    scalar bestArea = GREAT;
    label best = -1;
    for (label k = 1; k < nScan; ++k)
    {
        const scalar a = cutSection(outletTop + k*dz);
        if (a > VSMALL && a < bestArea)
        {
            bestArea = a;
            best = k;
        }
    }
    if (best > 0 && bestArea < 0.98*outletArea)
    {
        scalar lo = outletTop + (best - 1)*dz;
        scalar hi = outletTop + (best + 1)*dz;
        // Each iteration keeps one of its two cuts for the next
        const scalar ratio = 0.5*(sqrt(5.0) - 1);
        scalar z1 = hi - ratio*(hi - lo);
        scalar z2 = lo + ratio*(hi - lo);
        scalar a1 = cutSection(z1);
        scalar a2 = cutSection(z2);
        for (int iter = 0; iter < 40; ++iter)
        {
            if (a1 < a2)
            {
                hi = z2;
                z2 = z1;
                a2 = a1;
                z1 = hi - ratio*(hi - lo);
                a1 = cutSection(z1);
            }
            else
            {
                lo = z1;
                z1 = z2;
                a1 = a2;
                z2 = lo + ratio*(hi - lo);
                a2 = cutSection(z2);
            }
        }
        orificeHeight_ = 0.5*(lo + hi);
        orificeArea_ = cutSection(orificeHeight_, &orificePoints);
        throat_ = true;
    }

    orificeSize_ = sectionSize(orificeArea_, orificePoints);
}


Foam::List<Foam::Pair<Foam::point>> Foam::siloGeometry::rimEdges
(
    scalar* wallAngle
) const
{
    // The largest angle between a rim's wall face and the outlet face
    // beside it [rad] (-1: no rim edge with both on this rank)
    scalar largestAngle = -1;
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    const labelHashSet outlets(outletPatches_);
    DynamicList<Pair<point>> local;
    // Edges across a processor boundary with neither a wall nor another
    // outlet face here: a rim when a wall face on another rank holds them
    // and no outlet face does
    DynamicList<Pair<point>> acrossProcessors;
    // Every edge of the outlet patches' faces, for that question
    DynamicList<Pair<point>> outletEdges;
    for (const label patchi : outletPatches_)
    {
        const polyPatch& pp = patches[patchi];
        const edgeList& edges = pp.edges();
        const labelList& meshPoints = pp.meshPoints();
        for (label edgei = 0; edgei < pp.nEdges(); ++edgei)
        {
            const label a = meshPoints[edges[edgei].start()];
            const label b = meshPoints[edges[edgei].end()];
            const Pair<point> ends(mesh_.points()[a], mesh_.points()[b]);
            outletEdges.append(ends);
            // Not a boundary edge of the patch, or a collapsed one (a
            // wedge's axis)
            if
            (
                edgei < pp.nInternalEdges()
             || mag(ends.second() - ends.first()) < SMALL
            )
            {
                continue;
            }
            // The boundary faces beside the patch's own across this edge:
            // another outlet's (the orifice goes on), a wall's (the rim),
            // a processor's (the rim perhaps, on another rank); any other
            // (empty, wedge, symmetry, cyclic: the mesh's cut; an inlet) is
            // not a rim
            bool wall = false;
            bool outlet = false;
            bool processor = false;
            scalar angle = -1;
            for (const label facei : mesh_.pointFaces()[a])
            {
                if
                (
                    mesh_.isInternalFace(facei)
                 || !mesh_.faces()[facei].found(b)
                )
                {
                    continue;
                }
                const label otherPatch = patches.whichPatch(facei);
                const polyPatch& other = patches[otherPatch];
                if (outlets.found(otherPatch))
                {
                    outlet = outlet || otherPatch != patchi;
                }
                else if (isA<wallPolyPatch>(other))
                {
                    wall = true;
                    const vector nWall(normalised(mesh_.faceAreas()[facei]));
                    const vector nOutlet
                    (
                        pp.faceNormals()[pp.edgeFaces()[edgei][0]]
                    );
                    angle = max
                    (
                        angle,
                        acos(max(scalar(-1), min(scalar(1), nWall & nOutlet)))
                    );
                }
                else if
                (
                    isA<processorPolyPatch>(other)
                 && !isA<processorCyclicPolyPatch>(other)
                )
                {
                    processor = true;
                }
            }
            if (wall && !outlet)
            {
                local.append(ends);
                largestAngle = max(largestAngle, angle);
            }
            else if (processor && !outlet)
            {
                acrossProcessors.append(ends);
            }
        }
    }

    // Gathered from every rank
    const auto gathered = [](DynamicList<Pair<point>>& mine)
    {
        List<List<Pair<point>>> rankEdges(Pstream::nProcs());
        rankEdges[Pstream::myProcNo()] = std::move(mine);
        Pstream::gatherList(rankEdges);
        Pstream::scatterList(rankEdges);
        DynamicList<Pair<point>> all;
        for (const List<Pair<point>>& edges : rankEdges)
        {
            all.append(edges);
        }
        return all;
    };
    DynamicList<Pair<point>> rim(gathered(local));
    if (Pstream::parRun())
    {
        const DynamicList<Pair<point>> candidates(gathered(acrossProcessors));
        const DynamicList<Pair<point>> allOutletEdges(gathered(outletEdges));
        const scalar tol = 1e-9*mag(mesh_.bounds().span());
        const auto same = [tol](const Pair<point>& e, const Pair<point>& f)
        {
            return
                (mag(e.first() - f.first()) < tol && mag(e.second() - f.second()) < tol)
             || (mag(e.first() - f.second()) < tol && mag(e.second() - f.first()) < tol);
        };
        // Which candidates a wall face holds, on any rank
        boolList onWall(candidates.size(), false);
        if (!candidates.empty())
        {
            for (const polyPatch& pp : patches)
            {
                if (!isA<wallPolyPatch>(pp))
                {
                    continue;
                }
                const edgeList& edges = pp.edges();
                const labelList& meshPoints = pp.meshPoints();
                for (label edgei = pp.nInternalEdges(); edgei < pp.nEdges(); ++edgei)
                {
                    const Pair<point> ends
                    (
                        mesh_.points()[meshPoints[edges[edgei].start()]],
                        mesh_.points()[meshPoints[edges[edgei].end()]]
                    );
                    forAll(candidates, i)
                    {
                        onWall[i] = onWall[i] || same(candidates[i], ends);
                    }
                }
            }
        }
        Pstream::listCombineGather(onWall, orEqOp<bool>());
        Pstream::listCombineScatter(onWall);
        forAll(candidates, i)
        {
            label nFaces = 0;
            for (const Pair<point>& f : allOutletEdges)
            {
                nFaces += same(candidates[i], f);
            }
            if (nFaces == 1 && onWall[i])
            {
                rim.append(candidates[i]);
            }
        }
    }
    if (wallAngle)
    {
        *wallAngle = returnReduce(largestAngle, maxOp<scalar>());
        if (*wallAngle >= 0)
        {
            *wallAngle = radToDeg(*wallAngle);
        }
    }
    return List<Pair<point>>(std::move(rim));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::siloGeometry::siloGeometry
(
    const fvMesh& mesh,
    const labelList& outletPatches,
    const vector& g
)
:
    mesh_(mesh),
    gHat_(normalised(g)),
    outletPatches_(outletPatches),
    kind_(kind::threeD),
    kindReason_(),
    cellBottom_(mesh.nCells(), GREAT),
    cellTop_(mesh.nCells(), -GREAT),
    zMin_(GREAT),
    zMax_(-GREAT),
    orificeHeight_(0),
    orificeArea_(0),
    orificeSize_(0),
    slotLength_(0),
    throat_(false)
{
    detectKind();

    const pointField& pts = mesh.points();
    forAll(mesh.cellPoints(), celli)
    {
        for (const label pointi : mesh.cellPoints()[celli])
        {
            const scalar z = height(pts[pointi]);
            cellBottom_[celli] = min(cellBottom_[celli], z);
            cellTop_[celli] = max(cellTop_[celli], z);
        }
    }
    zMin_ = returnReduce(min(cellBottom_), minOp<scalar>());
    zMax_ = returnReduce(max(cellTop_), maxOp<scalar>());

    if (kind_ == kind::planar)
    {
        // Depth: the extent along the empty direction
        const Vector<label>& dirs = mesh.geometricD();
        const boundBox& bb = mesh.bounds();
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (dirs[d] < 0)
            {
                slotLength_ = bb.span()[d];
            }
        }
    }

    findOrifice();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::siloGeometry::declarePlanar()
{
    if (kind_ == kind::planar)
    {
        return;
    }
    kind_ = kind::planar;
    kindReason_ = "declared planar (a slab of depth the mesh's thinnest"
        " horizontal extent)";
    slotLength_ = slabDepth();
    findOrifice();
}


Foam::scalar Foam::siloGeometry::fullOrificeArea() const
{
    if (kind_ == kind::axisymmetric)
    {
        return constant::mathematical::pi*sqr(orificeSize_)/4;
    }
    return orificeArea_;
}


Foam::scalar Foam::siloGeometry::volumeBelow(const scalar z) const
{
    const scalarField& V = mesh_.V();
    scalar volume = 0;
    forAll(V, celli)
    {
        const scalar h = cellTop_[celli] - cellBottom_[celli];
        const scalar f =
            h > VSMALL
          ? min(max((z - cellBottom_[celli])/h, scalar(0)), scalar(1))
          : scalar(z > cellBottom_[celli] ? 1 : 0);
        volume += f*V[celli];
    }
    return returnReduce(volume, sumOp<scalar>());
}


Foam::scalar Foam::siloGeometry::levelOfVolume(const scalar V) const
{
    scalar lo = zMin_;
    scalar hi = zMax_;
    if (V <= 0)
    {
        return lo;
    }
    for (int iter = 0; iter < 60 && hi - lo > 1e-12*(zMax_ - zMin_); ++iter)
    {
        const scalar mid = 0.5*(lo + hi);
        if (volumeBelow(mid) < V)
        {
            lo = mid;
        }
        else
        {
            hi = mid;
        }
    }
    return 0.5*(lo + hi);
}


Foam::scalar Foam::siloGeometry::cellHeightAt(const scalar z) const
{
    scalar sumH = 0;
    label n = 0;
    forAll(cellBottom_, celli)
    {
        if (cellBottom_[celli] <= z && z <= cellTop_[celli])
        {
            sumH += cellTop_[celli] - cellBottom_[celli];
            ++n;
        }
    }
    reduce(sumH, sumOp<scalar>());
    reduce(n, sumOp<label>());
    return n ? sumH/n : (zMax_ - zMin_);
}


Foam::tmp<Foam::scalarField> Foam::siloGeometry::openFraction
(
    const List<Pair<point>>& rim,
    const label patchi,
    const scalar rimWidth
) const
{
    const polyPatch& pp = mesh_.boundaryMesh()[patchi];
    auto tfraction = tmp<scalarField>::New(pp.size(), 1);
    scalarField& fraction = tfraction.ref();

    if (rim.empty() || !(rimWidth > 0))
    {
        return tfraction;
    }
    const auto distanceToRim = [&rim](const point& p)
    {
        scalar d = GREAT;
        for (const Pair<point>& e : rim)
        {
            d = min(d, linePointRef(e.first(), e.second()).nearestDist(p).distance());
        }
        return d;
    };

    const label n = 24;
    const pointField& points = pp.points();
    forAll(pp, facei)
    {
        const face& f = pp[facei];
        const point& c = pp.faceCentres()[facei];

        // Wholly beyond the band or wholly inside it: no sampling
        scalar radius = 0;
        forAll(f, pointi)
        {
            radius = max(radius, mag(points[f[pointi]] - c));
        }
        const scalar dc = distanceToRim(c);
        if (dc - radius > rimWidth || dc + radius <= rimWidth)
        {
            fraction[facei] = dc - radius > rimWidth ? 1 : 0;
            continue;
        }

        scalar area = 0;
        scalar open = 0;
        forAll(f, pointi)
        {
            const point& p1 = points[f[pointi]];
            const point& p2 = points[f.nextLabel(pointi)];
            const scalar subArea = triPointRef(c, p1, p2).mag()/(n*n);
            const vector e1(p1 - c);
            const vector e2(p2 - c);
            // The n^2 sub-triangles of the lattice (i, j) with i + j < n:
            // n(n + 1)/2 upright and n(n - 1)/2 upside down
            for (label i = 0; i < n; ++i)
            {
                for (label j = 0; i + j < n; ++j)
                {
                    const point up(c + ((i + 1.0/3)*e1 + (j + 1.0/3)*e2)/n);
                    area += subArea;
                    open += distanceToRim(up) > rimWidth ? subArea : 0;
                    if (i + j < n - 1)
                    {
                        const point down
                        (
                            c + ((i + 2.0/3)*e1 + (j + 2.0/3)*e2)/n
                        );
                        area += subArea;
                        open += distanceToRim(down) > rimWidth ? subArea : 0;
                    }
                }
            }
        }
        fraction[facei] = area > 0 ? open/area : 1;
    }
    return tfraction;
}


// ************************************************************************* //

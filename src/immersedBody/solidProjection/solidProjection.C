/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "solidProjection.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    // Make every polygon counter-clockwise and return the areas
    Foam::scalarField orientAndMeasure
    (
        Foam::List<Foam::vector2D>& vertices,
        const Foam::labelUList& start
    )
    {
        using namespace Foam;
        scalarField area(start.size() - 1);
        forAll(area, c)
        {
            SubList<vector2D> poly(vertices, start[c + 1] - start[c], start[c]);
            vector2D centroid;
            polygonClipping::areaAndCentroid(poly, area[c], centroid);
            if (area[c] < 0)
            {
                std::reverse(poly.begin(), poly.end());
                area[c] = -area[c];
            }
        }
        return area;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::FixedList<Foam::scalar, 3> Foam::solidProjection::barycentric
(
    const vector2D& x,
    const vector2D& a,
    const vector2D& b,
    const vector2D& c
)
{
    const scalar twiceArea = polygonClipping::cross(a, b, c);
    const scalar la = polygonClipping::cross(x, b, c)/twiceArea;
    const scalar lb = polygonClipping::cross(a, x, c)/twiceArea;
    return FixedList<scalar, 3>({la, lb, 1 - la - lb});
}


Foam::solidProjection::Containment Foam::solidProjection::containment
(
    const vector2D& a,
    const vector2D& b,
    const vector2D& c,
    const vector2D* cv,
    const label nv
)
{
    using polygonClipping::cross;
    // The triangle inside the (convex, counter-clockwise) cell: each
    // vertex left of every cell edge (as clipConvex keeps it)
    bool triangleIn = true;
    for (label e = 0; e < nv && triangleIn; ++e)
    {
        const vector2D& p = cv[e];
        const vector2D& q = cv[e + 1 < nv ? e + 1 : 0];
        triangleIn =
            cross(p, q, a) >= 0 && cross(p, q, b) >= 0 && cross(p, q, c) >= 0;
    }
    if (triangleIn)
    {
        return TRIANGLE_IN_CELL;
    }
    // The cell inside a counter-clockwise triangle: each cell vertex
    // strictly left of its edges
    if (cross(a, b, c) <= 0)
    {
        return PARTIAL;
    }
    for (label k = 0; k < nv; ++k)
    {
        const vector2D& v = cv[k];
        if (!(cross(a, b, v) > 0 && cross(b, c, v) > 0 && cross(c, a, v) > 0))
        {
            return PARTIAL;
        }
    }
    return CELL_IN_TRIANGLE;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::solidProjection::solidProjection
(
    const UList<vector2D>& cellVertices,
    const labelUList& cellStart
)
:
    cellVertices_(cellVertices),
    cellStart_(cellStart),
    cellArea_(orientAndMeasure(cellVertices_, cellStart_)),
    cellCentroid_(cellArea_.size()),
    cellLo_(cellArea_.size()),
    cellHi_(cellArea_.size()),
    index_(cellVertices_, cellStart_),
    lastTriangle_(cellArea_.size(), -1),
    triangleStamp_(0),
    lastSegment_(cellArea_.size(), -1),
    segmentTag_(0)
{
    forAll(cellCentroid_, celli)
    {
        const SubList<vector2D> poly
        (
            cellVertices_, cellStart_[celli + 1] - cellStart_[celli],
            cellStart_[celli]
        );
        scalar area;
        polygonClipping::areaAndCentroid(poly, area, cellCentroid_[celli]);
        cellLo_[celli] = vector2D(GREAT, GREAT);
        cellHi_[celli] = vector2D(-GREAT, -GREAT);
        for (const vector2D& v : poly)
        {
            cellLo_[celli] = min(cellLo_[celli], v);
            cellHi_[celli] = max(cellHi_[celli], v);
        }
    }
    centroidIndex_.reset
    (
        new cellBinIndex(cellCentroid_, identity(cellCentroid_.size() + 1))
    );
}


Foam::solidProjection::solidProjection(const polyMesh& mesh)
:
    solidProjection(cellPolygons(mesh))
{}


Foam::solidProjection::solidProjection
(
    const std::pair<List<vector2D>, labelList>& polygons
)
:
    solidProjection(polygons.first, polygons.second)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

std::pair<Foam::List<Foam::vector2D>, Foam::labelList>
Foam::solidProjection::cellPolygons(const polyMesh& mesh)
{
    std::pair<List<vector2D>, labelList> result;
    List<vector2D>& vertices = result.first;
    labelList& start = result.second;

    labelList backFace(mesh.nCells(), -1);
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (!isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            if (mesh.faceAreas()[facei].z() < 0)
            {
                backFace[mesh.faceOwner()[facei]] = facei;
            }
        }
    }

    start.setSize(mesh.nCells() + 1);
    start[0] = 0;
    forAll(backFace, celli)
    {
        if (backFace[celli] < 0)
        {
            FatalErrorInFunction
                << "The immersed body needs a 2D mesh in the x-y plane (one"
                << " cell thick, 'empty' front and back patches): cell "
                << celli << " at " << mesh.cellCentres()[celli]
                << " has no face on an empty patch with normal -z"
                << exit(FatalError);
        }
        start[celli + 1] = start[celli] + mesh.faces()[backFace[celli]].size();
    }

    vertices.setSize(start.last());
    forAll(backFace, celli)
    {
        const face& f = mesh.faces()[backFace[celli]];
        forAll(f, k)
        {
            const point& p = mesh.points()[f[k]];
            vertices[start[celli] + k] = vector2D(p.x(), p.y());
        }
    }
    return result;
}


void Foam::solidProjection::project
(
    const UList<vector2D>& points,
    const UList<FixedList<label, 3>>& triangles,
    const UList<vector2D>& pointVelocities,
    scalarField& alphaSolid,
    List<vector2D>& Usolid
)
{
    project(points, triangles, pointVelocities, alphaSolid, Usolid, overlaps_);
}


void Foam::solidProjection::project
(
    const UList<vector2D>& points,
    const UList<FixedList<label, 3>>& triangles,
    const UList<vector2D>& pointVelocities,
    scalarField& alphaSolid,
    List<vector2D>& Usolid,
    solidOverlaps& overlaps,
    const UList<bool>* boundaryCell,
    const labelUList* cellState
)
{
    alphaSolid.setSize(nCells());
    Usolid.setSize(nCells());
    overlaps.clear();
    if (triangleStamp_ > labelMax - triangles.size())
    {
        lastTriangle_ = -1;
        triangleStamp_ = 0;
    }
    const label stamp = triangleStamp_;
    triangleStamp_ += triangles.size();

    // One pass over the cells: the fields cleared; the cells known
    // without a triangle, the covered ones taking their whole area now (so
    // the centroid tests below pass them by), and the centroid index's
    // bins with a cell still to decide flagged; the boundary cells listed
    // to be binned on their own (a triangle visits those only)
    const bool known = boundaryCell && cellState;
    if (known)
    {
        centroidIndex_->clearSet(unknownBins_);
    }
    boundaryCells_.clear();
    forAll(alphaSolid, celli)
    {
        Usolid[celli] = Zero;
        scalar a = 0;
        const bool boundary = boundaryCell && (*boundaryCell)[celli];
        if (known)
        {
            const label s = (*cellState)[celli];
            if (s == 1)
            {
                a = cellArea_[celli];
            }
            else if (s < 0 && !boundary)
            {
                centroidIndex_->forEachBin
                (
                    cellCentroid_[celli], cellCentroid_[celli],
                    [&](const label b)
                    {
                        centroidIndex_->flagBin(unknownBins_, b);
                    }
                );
            }
        }
        alphaSolid[celli] = a;
        if (boundary) boundaryCells_.append(celli);
    }
    if (known)
    {
        centroidIndex_->finishSet(unknownBins_);
    }
    if (boundaryCell)
    {
        index_.setSubset
        (
            boundaryCells_,
            [&](const label celli, vector2D& lo, vector2D& hi)
            {
                lo = cellLo_[celli];
                hi = cellHi_[celli];
            },
            boundarySubset_
        );
    }

    forAll(triangles, t)
    {
        const FixedList<label, 3>& tri = triangles[t];
        const vector2D& a = points[tri[0]];
        const vector2D& b = points[tri[1]];
        const vector2D& c = points[tri[2]];
        const vector2D lo(min(a, min(b, c))), hi(max(a, max(b, c)));

        // The cells the boundary crosses (all, without boundaryCell) are
        // clipped
        auto clip = [&](const label celli)
        {
            if (lastTriangle_[celli] == stamp + t) return;
            lastTriangle_[celli] = stamp + t;
            scalar area;
            vector2D centroid;
            overlapArea(a, b, c, celli, area, centroid);
            if (area <= 0) return;
            addOverlap
            (
                celli, t, area, centroid,
                barycentric(centroid, a, b, c), tri,
                pointVelocities, alphaSolid, Usolid, overlaps
            );
        };
        if (!boundaryCell)
        {
            index_.forEachCandidate(lo, hi, clip);
        }
        else if (index_.touchesSubset(lo, hi, boundarySubset_))
        {
            index_.forEachCandidateOf(boundarySubset_, lo, hi, clip);
        }

        // The others are all solid if their centroid is in a triangle
        // (then counted once, with the first such triangle), else all gas;
        // an inverted triangle (a folded view) counts for nothing, as its
        // negative clipped area does above. Each cell is in one bin of the
        // centroid index: visited once per triangle
        const scalar twiceArea = polygonClipping::cross(a, b, c);
        if
        (
            !boundaryCell || twiceArea <= 0
         || (known && !centroidIndex_->touchesSet(lo, hi, unknownBins_, true))
        )
        {
            continue;
        }
        centroidIndex_->forEachCandidate
        (
            lo, hi,
            [&](const label celli)
            {
                if
                (
                    (*boundaryCell)[celli] || alphaSolid[celli] > 0
                 || (known && (*cellState)[celli] >= 0)
                )
                {
                    return;
                }
                const vector2D& x = cellCentroid_[celli];
                // Without a division first: a centroid clearly outside
                // (the test below, with a wider margin) is most candidates
                using polygonClipping::cross;
                const scalar margin = -1e-9*twiceArea;
                if
                (
                    cross(x, b, c) < margin || cross(a, x, c) < margin
                 || cross(a, b, x) < margin
                )
                {
                    return;
                }
                const FixedList<scalar, 3> w = barycentric(x, a, b, c);
                const scalar tol = -1e-12;
                if (!(w[0] >= tol && w[1] >= tol && w[2] >= tol)) return;
                addOverlap
                (
                    celli, t, cellArea_[celli], x, w, tri,
                    pointVelocities, alphaSolid, Usolid, overlaps
                );
            }
        );
    }

    forAll(alphaSolid, celli)
    {
        if (alphaSolid[celli] > 0)
        {
            Usolid[celli] /= alphaSolid[celli];
            alphaSolid[celli] = min(alphaSolid[celli]/cellArea_[celli], 1.0);
        }
    }
}


void Foam::solidProjection::overlapArea
(
    const vector2D& a,
    const vector2D& b,
    const vector2D& c,
    const label celli,
    scalar& area,
    vector2D& centroid
)
{
    // Most overlaps are a whole cell inside a triangle or a whole triangle
    // inside a cell: no clipping for those (the clipped triangle would be
    // the triangle itself, vertex for vertex)
    const vector2D* cv = &cellVertices_[cellStart_[celli]];
    const label nv = cellStart_[celli + 1] - cellStart_[celli];
    const Containment inside = containment(a, b, c, cv, nv);
    if (inside == CELL_IN_TRIANGLE)
    {
        area = cellArea_[celli];
        centroid = cellCentroid_[celli];
        return;
    }
    // Into two fixed buffers (clipConvexFixed), falling back to the lists
    // for a cell with more vertices than they hold
    constexpr label capacity = 32;
    vector2D buf0[capacity], buf1[capacity];
    buf0[0] = a;
    buf0[1] = b;
    buf0[2] = c;
    label n = 3;
    vector2D* result = buf0;
    if (inside != TRIANGLE_IN_CELL)
    {
        n = polygonClipping::clipConvexFixed
        (
            buf0, buf1, capacity, 3, cv, nv, result
        );
    }
    if (n >= 0)
    {
        polygonClipping::areaAndCentroid
        (
            UList<vector2D>(result, n), area, centroid
        );
        return;
    }
    polygon_.clear();
    polygon_.append(a);
    polygon_.append(b);
    polygon_.append(c);
    polygonClipping::clipConvex(polygon_, cv, nv, work_);
    polygonClipping::areaAndCentroid(polygon_, area, centroid);
}


void Foam::solidProjection::addOverlap
(
    const label celli,
    const label t,
    const scalar area,
    const vector2D& centroid,
    const FixedList<scalar, 3>& w,
    const FixedList<label, 3>& tri,
    const UList<vector2D>& pointVelocities,
    scalarField& alphaSolid,
    List<vector2D>& Usolid,
    solidOverlaps& overlaps
)
{
    // The velocity is linear: its mean over the overlap is its value at
    // the overlap's centroid (barycentric weights w there)
    alphaSolid[celli] += area;
    Usolid[celli] +=
        area
       *(
            w[0]*pointVelocities[tri[0]]
          + w[1]*pointVelocities[tri[1]]
          + w[2]*pointVelocities[tri[2]]
        );
    overlaps.cell.append(celli);
    overlaps.triangle.append(t);
    overlaps.area.append(area);
    overlaps.centroid.append(centroid);
}


void Foam::solidProjection::distributeToPoints
(
    const UList<vector2D>& cellForce,
    const scalarField& alphaSolid,
    const UList<vector2D>& points,
    const UList<FixedList<label, 3>>& triangles,
    List<vector2D>& pointForces
) const
{
    // Transpose of the velocity average of project()
    const scalarField solidArea(alphaSolid*cellArea_);
    forEachPointWeight
    (
        overlaps_, solidArea, points, triangles,
        [&](const label celli, const label t, const label k, const scalar w)
        {
            pointForces[triangles[t][k]] += w*cellForce[celli];
        }
    );
}


bool Foam::solidProjection::clipSegment
(
    const label celli,
    const vector2D& a,
    const vector2D& b,
    scalar& s0,
    scalar& s1,
    const scalar onLine
) const
{
    return polygonClipping::clipSegment
    (
        a, b, &cellVertices_[cellStart_[celli]],
        cellStart_[celli + 1] - cellStart_[celli], s0, s1, onLine
    );
}


Foam::scalar Foam::solidProjection::maxCellSize() const
{
    scalar s = 0;
    forAll(cellLo_, celli)
    {
        s = max(s, cmptMax(cellHi_[celli] - cellLo_[celli]));
    }
    return s;
}


bool Foam::solidProjection::cellContains
(
    const label celli,
    const vector2D& pt
) const
{
    // Inside a counter-clockwise convex polygon: left of every edge (on an
    // edge counts as inside)
    const label start = cellStart_[celli], end = cellStart_[celli + 1];
    for (label k = start; k < end; ++k)
    {
        const vector2D& a = cellVertices_[k];
        const vector2D& b = cellVertices_[k + 1 < end ? k + 1 : start];
        const vector2D ab = b - a, ap = pt - a;
        if (ab.x()*ap.y() - ab.y()*ap.x() < 0) return false;
    }
    return true;
}


Foam::label Foam::solidProjection::findCell(const vector2D& pt) const
{
    label found = -1;
    index_.forEachCandidate
    (
        pt, pt,
        [&](const label celli)
        {
            if (found < 0 && cellContains(celli, pt)) found = celli;
        }
    );
    return found;
}


void Foam::solidProjection::findCells
(
    const vector2D& pt,
    DynamicList<label>& cells
) const
{
    index_.forEachCandidate
    (
        pt, pt,
        [&](const label celli)
        {
            // (a cell may be visited more than once by the bins)
            if (!cells.found(celli) && cellContains(celli, pt))
            {
                cells.append(celli);
            }
        }
    );
}


void Foam::solidProjection::overlapsOf
(
    const UList<vector2D>& polygon,
    DynamicList<label>& cells,
    DynamicList<scalar>& areas
) const
{
    if (polygon.empty()) return;
    vector2D lo = polygon[0], hi = polygon[0];
    for (const vector2D& p : polygon)
    {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    // Rare (crack gas handed to the mesh): its own working storage
    DynamicList<vector2D> clipped, work;
    const label first = cells.size();
    index_.forEachCandidate
    (
        lo, hi,
        [&](const label celli)
        {
            // (a cell may be visited more than once by the bins)
            if
            (
                cellLo_[celli].x() > hi.x() || cellHi_[celli].x() < lo.x()
             || cellLo_[celli].y() > hi.y() || cellHi_[celli].y() < lo.y()
             || SubList<label>(cells, cells.size() - first, first)
               .found(celli)
            )
            {
                return;
            }
            clipped = polygon;
            const label s = cellStart_[celli];
            polygonClipping::clipConvex
            (
                clipped, &cellVertices_[s], cellStart_[celli + 1] - s, work
            );
            if (clipped.size() < 3) return;
            scalar area;
            vector2D centroid;
            polygonClipping::areaAndCentroid(clipped, area, centroid);
            if (area > 0)
            {
                cells.append(celli);
                areas.append(area);
            }
        }
    );
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "solidMeshQuality.H"
#include "solidVtkWriter.H"
#include "boundBox.H"
#include "mathematicalConstants.H"

#include <algorithm>
#include <tuple>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// Items registered in the cells of a uniform grid, sorted by cell so that
// the items of a cell are contiguous
class cellGrid
{
    vector2D origin_;
    scalar h_;
    std::vector<std::tuple<int64_t, int64_t, label>> entries_;

public:

    cellGrid(const vector2D& origin, const scalar h)
    :
        origin_(origin),
        h_(h)
    {}

    int64_t ix(const scalar x) const { return int64_t(floor((x - origin_.x())/h_)); }
    int64_t iy(const scalar y) const { return int64_t(floor((y - origin_.y())/h_)); }

    void add(const int64_t i, const int64_t j, const label item)
    {
        entries_.emplace_back(i, j, item);
    }

    void sort() { std::sort(entries_.begin(), entries_.end()); }

    //- Range of entries in cell (i, j)
    std::pair<size_t, size_t> cell(const int64_t i, const int64_t j) const
    {
        const auto lo = std::lower_bound
        (
            entries_.begin(), entries_.end(), std::make_tuple(i, j, label(-1))
        );
        auto hi = lo;
        while
        (
            hi != entries_.end()
         && std::get<0>(*hi) == i && std::get<1>(*hi) == j
        )
        {
            ++hi;
        }
        return {size_t(lo - entries_.begin()), size_t(hi - entries_.begin())};
    }

    const std::vector<std::tuple<int64_t, int64_t, label>>& entries() const
    {
        return entries_;
    }
};


void triangleCorners
(
    const triangleMesh& mesh,
    const label t,
    vector2D& a,
    vector2D& b,
    vector2D& c
)
{
    const triangleVertices& tri = mesh.triangles()[t];
    a = mesh.points()[tri[0]];
    b = mesh.points()[tri[1]];
    c = mesh.points()[tri[2]];
}


scalar cross2(const vector2D& u, const vector2D& v)
{
    return u.x()*v.y() - u.y()*v.x();
}


// Interiors of two triangles overlap (no separating edge normal), with a
// tolerance eps on the projections
bool overlap(const vector2D p[3], const vector2D q[3], const scalar eps)
{
    for (int side = 0; side < 2; ++side)
    {
        const vector2D* s = side ? q : p;
        for (int k = 0; k < 3; ++k)
        {
            const vector2D d = s[(k + 1) % 3] - s[k];
            const vector2D n(-d.y(), d.x());
            const scalar len = mag(n);
            if (len < VSMALL)
            {
                continue;
            }
            scalar pMin = GREAT, pMax = -GREAT, qMin = GREAT, qMax = -GREAT;
            for (int m = 0; m < 3; ++m)
            {
                const scalar sp = (p[m] & n)/len, sq = (q[m] & n)/len;
                pMin = min(pMin, sp); pMax = max(pMax, sp);
                qMin = min(qMin, sq); qMax = max(qMax, sq);
            }
            if (pMax <= qMin + eps || qMax <= pMin + eps)
            {
                return false;
            }
        }
    }
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarList Foam::solidMeshQuality::minAngles(const triangleMesh& mesh)
{
    scalarList result(mesh.nTriangles());
    forAll(result, t)
    {
        vector2D p[3];
        triangleCorners(mesh, t, p[0], p[1], p[2]);
        scalar smallest = GREAT;
        for (int k = 0; k < 3; ++k)
        {
            const vector2D u = p[(k + 1) % 3] - p[k];
            const vector2D v = p[(k + 2) % 3] - p[k];
            smallest = min
            (
                smallest,
                std::atan2(mag(cross2(u, v)), u & v)
            );
        }
        result[t] = smallest*180.0/constant::mathematical::pi;
    }
    return result;
}


Foam::scalarList Foam::solidMeshQuality::longestEdges(const triangleMesh& mesh)
{
    scalarList result(mesh.nTriangles());
    forAll(result, t)
    {
        vector2D a, b, c;
        triangleCorners(mesh, t, a, b, c);
        result[t] = max(max(mag(b - a), mag(c - b)), mag(a - c));
    }
    return result;
}


Foam::scalarList Foam::solidMeshQuality::shortestEdges(const triangleMesh& mesh)
{
    scalarList result(mesh.nTriangles());
    forAll(result, t)
    {
        vector2D a, b, c;
        triangleCorners(mesh, t, a, b, c);
        result[t] = min(min(mag(b - a), mag(c - b)), mag(a - c));
    }
    return result;
}


Foam::scalarList Foam::solidMeshQuality::altitudes(const triangleMesh& mesh)
{
    const scalarList longest(longestEdges(mesh));
    scalarList result(mesh.nTriangles());
    forAll(result, t)
    {
        result[t] = 2*mag(mesh.area(t))/max(longest[t], VSMALL);
    }
    return result;
}


Foam::scalarList Foam::solidMeshQuality::radiusRatios(const triangleMesh& mesh)
{
    scalarList result(mesh.nTriangles());
    forAll(result, t)
    {
        vector2D a, b, c;
        triangleCorners(mesh, t, a, b, c);
        const scalar la = mag(c - b), lb = mag(a - c), lc = mag(b - a);
        const scalar area = mag(mesh.area(t));
        const scalar perimeter = la + lb + lc;
        // r_in = 2A/P, r_circ = abc/(4A): 2 r_in/r_circ = 16 A^2/(P abc)
        result[t] =
            perimeter > 0 && la*lb*lc > 0
          ? 16*area*area/(perimeter*la*lb*lc)
          : 0;
    }
    return result;
}


Foam::scalar Foam::solidMeshQuality::pWaveSpeed(const elasticProperties& p)
{
    return std::sqrt
    (
        p.E*(1 - p.nu)/(p.rho*(1 + p.nu)*(1 - 2*p.nu))
    );
}


Foam::scalar Foam::solidMeshQuality::stableTimeStep
(
    const triangleMesh& mesh,
    const UList<elasticProperties>& materials,
    label& triangle
)
{
    // Fastest wave per material: elastic, or the joint springs
    scalarList speed(materials.size());
    forAll(materials, m)
    {
        speed[m] = pWaveSpeed(materials[m]);
        if (materials[m].jointPenalty > 0)
        {
            speed[m] = max
            (
                speed[m],
                std::sqrt(materials[m].jointPenalty/materials[m].rho)
            );
        }
    }
    const scalarList h(altitudes(mesh));
    scalar dt = GREAT;
    triangle = -1;
    forAll(h, t)
    {
        const scalar dtt = h[t]/speed[mesh.triangleMaterials()[t]];
        if (dtt < dt)
        {
            dt = dtt;
            triangle = t;
        }
    }
    return dt;
}


Foam::List<Foam::labelPair> Foam::solidMeshQuality::duplicatePoints
(
    const triangleMesh& mesh,
    const scalar tol
)
{
    const List<vector2D>& pts = mesh.points();
    DynamicList<labelPair> pairs;
    if (pts.empty())
    {
        return List<labelPair>();
    }
    vector2D lo(pts[0]);
    for (const vector2D& p : pts)
    {
        lo = min(lo, p);
    }

    // Cells of size tol: a pair closer than tol is in neighbouring cells
    cellGrid grid(lo, max(tol, VSMALL));
    forAll(pts, i)
    {
        grid.add(grid.ix(pts[i].x()), grid.iy(pts[i].y()), i);
    }
    grid.sort();

    for (const auto& entry : grid.entries())
    {
        const int64_t i = std::get<0>(entry), j = std::get<1>(entry);
        const label a = std::get<2>(entry);
        for (int64_t di = -1; di <= 1; ++di)
        {
            for (int64_t dj = -1; dj <= 1; ++dj)
            {
                const auto range = grid.cell(i + di, j + dj);
                for (size_t e = range.first; e < range.second; ++e)
                {
                    const label b = std::get<2>(grid.entries()[e]);
                    if (b > a && mag(pts[a] - pts[b]) <= tol)
                    {
                        pairs.append(labelPair(a, b));
                    }
                }
            }
        }
    }
    Foam::sort(pairs);
    return List<labelPair>(std::move(pairs));
}


Foam::List<Foam::labelPair> Foam::solidMeshQuality::overlappingTriangles
(
    const triangleMesh& mesh,
    const scalar relTol
)
{
    const label nTris = mesh.nTriangles();
    DynamicList<labelPair> pairs;
    if (!nTris)
    {
        return List<labelPair>();
    }
    const scalarList longest(longestEdges(mesh));
    scalar h = 0;
    for (const scalar l : longest)
    {
        h += l/nTris;
    }
    const boundBox bb
    (
        point(min(mesh.points()).x(), min(mesh.points()).y(), 0),
        point(max(mesh.points()).x(), max(mesh.points()).y(), 0)
    );
    cellGrid grid(vector2D(bb.min().x(), bb.min().y()), max(2*h, VSMALL));

    // Cell range of each triangle's bounding box
    List<FixedList<int64_t, 4>> range(nTris);
    for (label t = 0; t < nTris; ++t)
    {
        vector2D a, b, c;
        triangleCorners(mesh, t, a, b, c);
        const vector2D lo = min(min(a, b), c), hi = max(max(a, b), c);
        range[t] = FixedList<int64_t, 4>
        ({
            grid.ix(lo.x()), grid.iy(lo.y()), grid.ix(hi.x()), grid.iy(hi.y())
        });
        for (int64_t i = range[t][0]; i <= range[t][2]; ++i)
        {
            for (int64_t j = range[t][1]; j <= range[t][3]; ++j)
            {
                grid.add(i, j, t);
            }
        }
    }
    grid.sort();

    const auto& entries = grid.entries();
    for (size_t begin = 0, end = 0; begin < entries.size(); begin = end)
    {
        const int64_t i = std::get<0>(entries[begin]);
        const int64_t j = std::get<1>(entries[begin]);
        end = begin;
        while
        (
            end < entries.size()
         && std::get<0>(entries[end]) == i && std::get<1>(entries[end]) == j
        )
        {
            ++end;
        }
        for (size_t e = begin; e < end; ++e)
        {
            const label ta = std::get<2>(entries[e]);
            vector2D p[3];
            triangleCorners(mesh, ta, p[0], p[1], p[2]);
            for (size_t f = e + 1; f < end; ++f)
            {
                const label tb = std::get<2>(entries[f]);
                // Test each pair once: in the first cell they share
                if
                (
                    max(range[ta][0], range[tb][0]) != i
                 || max(range[ta][1], range[tb][1]) != j
                )
                {
                    continue;
                }
                vector2D q[3];
                triangleCorners(mesh, tb, q[0], q[1], q[2]);
                const scalar len = max(longest[ta], longest[tb]);
                if (overlap(p, q, relTol*len))
                {
                    pairs.append(labelPair(min(ta, tb), max(ta, tb)));
                }
            }
        }
    }
    Foam::sort(pairs);
    return List<labelPair>(std::move(pairs));
}


Foam::labelList Foam::solidMeshQuality::badTriangles
(
    const triangleMesh& mesh,
    const scalar relTol
)
{
    const scalarList longest(longestEdges(mesh));
    DynamicList<label> bad;
    forAll(longest, t)
    {
        if (mesh.area(t) <= relTol*sqr(longest[t]))
        {
            bad.append(t);
        }
    }
    return labelList(std::move(bad));
}


void Foam::solidMeshQuality::report(const triangleMesh& mesh, Ostream& os)
{
    const scalarList angle(minAngles(mesh));
    const scalarList longest(longestEdges(mesh));
    const scalarList shortest(shortestEdges(mesh));
    const scalarList ratio(radiusRatios(mesh));
    const scalarList area(mesh.areas());

    const label n = max(mesh.nTriangles(), label(1));
    label nBelow20 = 0;
    scalar meanAngle = 0, meanRatio = 0, meanLongest = 0;
    forAll(angle, t)
    {
        nBelow20 += (angle[t] < 20);
        meanAngle += angle[t]/n;
        meanRatio += ratio[t]/n;
        meanLongest += longest[t]/n;
    }

    os  << "Solid mesh: " << mesh.nPoints() << " points, "
        << mesh.nTriangles() << " triangles" << nl
        << "    smallest angle [deg]: min " << gMin(angle) << ", mean "
        << meanAngle << ", below 20: " << nBelow20 << nl
        << "    radius ratio 2r/R: min " << gMin(ratio) << ", mean "
        << meanRatio << nl
        << "    edge length: min " << gMin(shortest) << ", max "
        << gMax(longest) << ", mean longest " << meanLongest << nl
        << "    area: total " << sum(area) << ", min " << gMin(area)
        << ", max " << gMax(area) << nl;

    scalarList materialArea(mesh.materials().size(), Zero);
    labelList materialCount(mesh.materials().size(), Zero);
    forAll(area, t)
    {
        materialArea[mesh.triangleMaterials()[t]] += area[t];
        ++materialCount[mesh.triangleMaterials()[t]];
    }
    forAll(mesh.materials(), m)
    {
        os  << "    material " << mesh.materials()[m] << ": "
            << materialCount[m] << " triangles, area " << materialArea[m]
            << nl;
    }
    forAll(mesh.patchNames(), patchi)
    {
        scalar length = 0;
        for (const edge& e : mesh.patchEdges()[patchi])
        {
            length += mag(mesh.points()[e[1]] - mesh.points()[e[0]]);
        }
        os  << "    patch " << mesh.patchNames()[patchi] << ": "
            << mesh.patchEdges()[patchi].size() << " edges, length "
            << length << nl;
    }
}


void Foam::solidMeshQuality::writeVtk
(
    const triangleMesh& mesh,
    solidVtkWriter& vtk
)
{
    vtk.beginStep(0, mesh.points(), mesh.triangles());
    vtk.addTriangleField("material", mesh.triangleMaterials());
    vtk.addTriangleField("area", mesh.areas());
    vtk.addTriangleField("minAngle", minAngles(mesh));
    vtk.addTriangleField("radiusRatio", radiusRatios(mesh));
    vtk.addTriangleField("longestEdge", longestEdges(mesh));
    vtk.endStep();
}


// ************************************************************************* //

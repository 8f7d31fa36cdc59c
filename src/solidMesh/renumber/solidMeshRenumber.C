/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

// METIS before any OpenFOAM header (see doc/developing.md)
#include <metis.h>

#include "solidMeshRenumber.H"
#include "EdgeMap.H"
#include "DynamicList.H"
#include "error.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// Triangle graph in compressed rows: triangles sharing an edge
void triangleGraph
(
    const triangleMesh& mesh,
    std::vector<idx_t>& xadj,
    std::vector<idx_t>& adjncy
)
{
    const List<triangleVertices>& tris = mesh.triangles();
    labelList neighbour(3*tris.size(), -1);
    EdgeMap<label> firstSide(3*tris.size());
    forAll(tris, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            const edge e(tris[t][k], tris[t][(k + 1) % 3]);
            auto iter = firstSide.find(e);
            if (iter.found())
            {
                neighbour[3*t + k] = *iter/3;
                neighbour[*iter] = t;
            }
            else
            {
                firstSide.insert(e, 3*t + k);
            }
        }
    }
    xadj.assign(1, 0);
    adjncy.clear();
    adjncy.reserve(3*tris.size());
    forAll(tris, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            if (neighbour[3*t + k] >= 0)
            {
                adjncy.push_back(neighbour[3*t + k]);
            }
        }
        xadj.push_back(adjncy.size());
    }
}

// METIS parts of the triangle graph: recursive bisection or k-way (METIS's
// fixed default seed: the same on every rank and every run)
std::vector<idx_t> metisParts
(
    const triangleMesh& mesh,
    const label nParts,
    const bool recursive,
    const labelUList& weights = labelUList::null()
)
{
    std::vector<idx_t> xadj, adjncy;
    triangleGraph(mesh, xadj, adjncy);
    idx_t n = mesh.nTriangles(), np = nParts, nCon = 1, cut = 0;
    std::vector<idx_t> part(n);
    std::vector<idx_t> vwgt(weights.begin(), weights.end());
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_NUMBERING] = 0;
    const int status =
        (recursive ? METIS_PartGraphRecursive : METIS_PartGraphKway)
        (
            &n, &nCon, xadj.data(), adjncy.data(),
            vwgt.empty() ? nullptr : vwgt.data(), nullptr, nullptr,
            &np, nullptr, nullptr, options, &cut, part.data()
        );
    if (status != METIS_OK)
    {
        FatalErrorInFunction
            << (recursive ? "METIS_PartGraphRecursive" : "METIS_PartGraphKway")
            << " failed with status " << status << " on " << n
            << " triangles" << exit(FatalError);
    }
    return part;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::labelList Foam::solidMeshRenumber::triangleOrder
(
    const triangleMesh& mesh,
    const label blockSize
)
{
    const label n = mesh.nTriangles();
    const label nParts = n/max(blockSize, label(1));
    if (nParts < 2)
    {
        return identity(n);
    }

    // Recursive bisection: parts whose indices are close are close in space
    const std::vector<idx_t> part = metisParts(mesh, nParts, true);

    // Triangles by part, in their old order within a part
    labelList count(nParts + 1, Zero);
    for (const idx_t p : part)
    {
        ++count[p + 1];
    }
    for (label p = 0; p < nParts; ++p)
    {
        count[p + 1] += count[p];
    }
    labelList order(n);
    for (label t = 0; t < n; ++t)
    {
        order[count[part[t]]++] = t;
    }
    return order;
}


Foam::labelList Foam::solidMeshRenumber::partition
(
    const triangleMesh& mesh,
    const label nParts,
    const labelUList& weights
)
{
    const label n = mesh.nTriangles();
    if (weights.size() && weights.size() != n)
    {
        FatalErrorInFunction
            << weights.size() << " weights for " << n << " triangles"
            << exit(FatalError);
    }
    for (const label w : weights)
    {
        if (w < 1)
        {
            FatalErrorInFunction
                << "triangle weights must be positive, got " << w
                << exit(FatalError);
        }
    }
    if (nParts < 2 || n < 2)
    {
        return labelList(n, Zero);
    }
    if (n < nParts)
    {
        FatalErrorInFunction
            << "cannot split " << n << " triangles into " << nParts
            << " parts" << exit(FatalError);
    }
    const std::vector<idx_t> part = metisParts(mesh, nParts, false, weights);
    labelList result(n);
    forAll(result, t)
    {
        result[t] = part[t];
    }
    return result;
}


Foam::triangleMesh Foam::solidMeshRenumber::subset
(
    const triangleMesh& mesh,
    const labelUList& triangles
)
{
    labelList newPoint(mesh.nPoints(), -1);
    label nPoints = 0;
    List<triangleVertices> tris(triangles.size());
    labelList materials(triangles.size());
    // Times each kept triangle uses an edge: 2 for an interior edge
    EdgeMap<label> edgeUse(3*triangles.size());
    forAll(triangles, t)
    {
        const label old = triangles[t];
        if (old < 0 || old >= mesh.nTriangles() || (t && old <= triangles[t-1]))
        {
            FatalErrorInFunction
                << "triangle " << old << " at " << t << ": the subset must"
                << " hold ascending triangles of the " << mesh.nTriangles()
                << " of the mesh" << exit(FatalError);
        }
        const triangleVertices& v = mesh.triangles()[old];
        for (label k = 0; k < 3; ++k)
        {
            label& p = newPoint[v[k]];
            if (p < 0)
            {
                p = nPoints++;
            }
            tris[t][k] = p;
            ++edgeUse(edge(v[k], v[(k + 1) % 3]), 0);
        }
        materials[t] = mesh.triangleMaterials()[old];
    }
    List<vector2D> points(nPoints);
    forAll(newPoint, i)
    {
        if (newPoint[i] >= 0)
        {
            points[newPoint[i]] = mesh.points()[i];
        }
    }
    auto renumbered = [&](const edge& e)
    {
        return edge(newPoint[e[0]], newPoint[e[1]]);
    };
    List<edgeList> patchEdges(mesh.patchEdges().size());
    forAll(patchEdges, patchi)
    {
        DynamicList<edge> kept;
        for (const edge& e : mesh.patchEdges()[patchi])
        {
            if (edgeUse.found(e))
            {
                kept.append(renumbered(e));
            }
        }
        patchEdges[patchi].transfer(kept);
    }
    List<triangleJointSet> jointSets(mesh.jointSets());
    for (triangleJointSet& js : jointSets)
    {
        DynamicList<edge> edges;
        DynamicList<scalar> strength, friction;
        forAll(js.edges, i)
        {
            const auto iter = edgeUse.cfind(js.edges[i]);
            if (!iter.found() || *iter != 2)
            {
                continue;
            }
            edges.append(renumbered(js.edges[i]));
            if (js.strengthFactor.size())
            {
                strength.append(js.strengthFactor[i]);
            }
            if (js.frictionAngle.size())
            {
                friction.append(js.frictionAngle[i]);
            }
        }
        // A per-edge list stays a per-edge list (empty means 'uniform')
        js.edges.transfer(edges);
        js.strengthFactor.transfer(strength);
        js.frictionAngle.transfer(friction);
    }
    triangleMesh result
    (
        points, tris, materials, mesh.materials(), mesh.patchNames(),
        patchEdges
    );
    result.setJointSets(jointSets);
    return result;
}


Foam::triangleMesh Foam::solidMeshRenumber::reorder
(
    const triangleMesh& mesh,
    const labelUList& newToOldTriangle
)
{
    if (newToOldTriangle.size() != mesh.nTriangles())
    {
        FatalErrorInFunction
            << newToOldTriangle.size() << " entries in the order of "
            << mesh.nTriangles() << " triangles" << exit(FatalError);
    }
    labelList newPoint(mesh.nPoints(), -1);
    label nPoints = 0;
    List<triangleVertices> triangles(mesh.nTriangles());
    labelList materials(mesh.nTriangles());
    forAll(newToOldTriangle, t)
    {
        const label old = newToOldTriangle[t];
        for (label k = 0; k < 3; ++k)
        {
            label& p = newPoint[mesh.triangles()[old][k]];
            if (p < 0)
            {
                p = nPoints++;
            }
            triangles[t][k] = p;
        }
        materials[t] = mesh.triangleMaterials()[old];
    }
    // Points used by no triangle go last, in their old order
    forAll(newPoint, i)
    {
        if (newPoint[i] < 0)
        {
            newPoint[i] = nPoints++;
        }
    }
    List<vector2D> points(mesh.nPoints());
    forAll(newPoint, i)
    {
        points[newPoint[i]] = mesh.points()[i];
    }
    List<edgeList> patchEdges(mesh.patchEdges());
    for (edgeList& edges : patchEdges)
    {
        for (edge& e : edges)
        {
            e = edge(newPoint[e[0]], newPoint[e[1]]);
        }
    }
    List<triangleJointSet> jointSets(mesh.jointSets());
    for (triangleJointSet& js : jointSets)
    {
        for (edge& e : js.edges)
        {
            e = edge(newPoint[e[0]], newPoint[e[1]]);
        }
    }
    triangleMesh result
    (
        points, triangles, materials, mesh.materials(), mesh.patchNames(),
        patchEdges
    );
    result.setJointSets(jointSets);
    return result;
}


Foam::triangleMesh Foam::solidMeshRenumber::renumber
(
    const triangleMesh& mesh,
    const label blockSize
)
{
    return reorder(mesh, triangleOrder(mesh, blockSize));
}


Foam::scalar Foam::solidMeshRenumber::localNeighbourFraction
(
    const triangleMesh& mesh,
    const label window
)
{
    std::vector<idx_t> xadj, adjncy;
    triangleGraph(mesh, xadj, adjncy);
    label near = 0;
    for (label t = 0; t < mesh.nTriangles(); ++t)
    {
        for (idx_t i = xadj[t]; i < xadj[t + 1]; ++i)
        {
            near += (mag(adjncy[i] - t) < window);
        }
    }
    return scalar(near)/max(label(adjncy.size()), label(1));
}


// ************************************************************************* //

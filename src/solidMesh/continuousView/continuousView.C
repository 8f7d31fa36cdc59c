/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "continuousView.H"
#include "error.H"
#include "HashSet.H"
#include "labelPair.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(continuousView, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::continuousView::collectNodes
(
    const label seed,
    const UList<bool>& broken,
    const label stamp,
    DynamicList<label>& group
)
{
    const labelList& edgeJoint = topo_.edgeJoint();

    const label start = group.size();
    group.append(seed);
    nodeMark_[seed] = stamp;

    for (label i = start; i < group.size(); ++i)
    {
        const label n = group[i];
        const label t = n/3, k = n % 3;

        // The two edges of t at node n: outgoing (k) and incoming (k+2)
        const label edges[2] = {3*t + k, 3*t + (k + 2) % 3};
        for (const label e : edges)
        {
            const label j = edgeJoint[e];
            if (j >= 0 && !broken[j])
            {
                const label m = topo_.partnerNode(j, n);
                if (nodeMark_[m] != stamp)
                {
                    nodeMark_[m] = stamp;
                    group.append(m);
                }
            }
        }
    }
}


void Foam::continuousView::splitPoint
(
    const label seed,
    const UList<bool>& broken
)
{
    const label pointi = pointOfNode_[seed];

    // All nodes of the point: connected through the joints intact before
    queue_.clear();
    collectNodes(seed, broken_, ++stamp_, queue_);
    labelList nodes(queue_);
    Foam::sort(nodes);

    // Parts after the breaks; the part of the lowest node keeps the index
    const label partStamp = ++stamp_;
    bool first = true;
    for (const label n : nodes)
    {
        if (nodeMark_[n] == partStamp)
        {
            continue;
        }
        queue2_.clear();
        collectNodes(n, broken, partStamp, queue2_);

        label newPoint = pointi;
        if (!first)
        {
            newPoint = points_.size();
            points_.append(points_[pointi]);
            nNodesOfPoint_.append(0);
        }
        first = false;

        nNodesOfPoint_[pointi] -= queue2_.size();
        nNodesOfPoint_[newPoint] += queue2_.size();
        for (const label m : queue2_)
        {
            pointOfNode_[m] = newPoint;
            triangles_[m/3][m % 3] = newPoint;
        }
    }
}


void Foam::continuousView::splitFragment(const UList<label>& seeds)
{
    // A search per seed triangle through the intact joints, in turn, one
    // triangle each; searches that meet merge. A search that runs out has
    // found a whole fragment. Once at most one search is still running, every
    // part of the old fragment is known: each part has a seed, because the
    // old fragment was connected through joints that are now broken.
    const labelList& edgeJoint = topo_.edgeJoint();
    const labelList& triA = topo_.jointTriangleA();
    const labelList& triB = topo_.jointTriangleB();

    const label nGroups = seeds.size();
    const label base = stamp_ + 1;
    stamp_ += nGroups;

    labelList parent(identity(nGroups));
    List<DynamicList<label>> queue(nGroups);
    labelList head(nGroups, Zero);
    DynamicList<label> running(nGroups), next(nGroups), finished;

    auto root = [&parent](label g)
    {
        while (parent[g] != g) { g = parent[g] = parent[parent[g]]; }
        return g;
    };

    forAll(seeds, g)
    {
        const label t = seeds[g];
        const label m = triangleMark_[t];
        if (m >= base && m < base + nGroups)
        {
            parent[g] = root(m - base);     // seed given twice
            continue;
        }
        triangleMark_[t] = base + g;
        queue[g].append(t);
        running.append(g);
    }

    while (running.size() > 1)
    {
        next.clear();
        for (const label g : running)
        {
            if (parent[g] != g)
            {
                continue;                   // merged into another search
            }
            if (head[g] == queue[g].size())
            {
                finished.append(g);
                continue;
            }
            const label t = queue[g][head[g]++];
            for (label k = 0; k < 3; ++k)
            {
                const label j = edgeJoint[3*t + k];
                if (j < 0 || broken_[j])
                {
                    continue;
                }
                const label u = (triA[j] == t ? triB[j] : triA[j]);
                const label m = triangleMark_[u];
                if (m < base || m >= base + nGroups)
                {
                    triangleMark_[u] = base + g;
                    queue[g].append(u);
                }
                else if (root(m - base) != g)
                {
                    // Met another search: take over its triangles, the
                    // larger list kept in place (the smaller one's
                    // expanded triangles are expanded again: harmless)
                    const label h = root(m - base);
                    parent[h] = g;
                    if (queue[h].size() > queue[g].size())
                    {
                        queue[g].swap(queue[h]);
                        std::swap(head[g], head[h]);
                    }
                    queue[g].append(queue[h]);
                    queue[h].clear();
                    head[h] = 0;
                }
            }
            next.append(g);
        }
        running.transfer(next);
    }

    // The last running search (or, if none, the first to finish) keeps the
    // old index; every other finished search is a new fragment
    label keeper = -1;
    for (const label g : running)
    {
        if (parent[g] == g) { keeper = g; }
    }
    for (const label g : finished)
    {
        if (keeper < 0)
        {
            keeper = g;
            continue;
        }
        const label fragment = nFragments_++;
        for (const label t : queue[g])
        {
            fragmentOfTriangle_[t] = fragment;
        }
    }
}


void Foam::continuousView::addFace(const label t, const label k)
{
    faceOfEdge_[3*t + k] = faceTriangle_.size();
    faceTriangle_.append(t);
    faceEdge_.append(k);
}


void Foam::continuousView::updateBoundaryEdges()
{
    const labelList& edgeJoint = topo_.edgeJoint();
    const label nFaces = faceTriangle_.size();
    const label nExternal = topo_.nBoundaryFaces();

    boundaryEdges_.setSize(nFaces);
    boundaryEdgeFragment_.setSize(nFaces);
    boundaryEdgeJoint_.setSize(nFaces);
    boundaryEdgePatch_.setSize(nFaces);

    for (label f = 0; f < nFaces; ++f)
    {
        const label t = faceTriangle_[f], k = faceEdge_[f];
        boundaryEdges_[f] = edge
        (
            triangles_[t][k],
            triangles_[t][(k + 1) % 3]
        );
        boundaryEdgeFragment_[f] = fragmentOfTriangle_[t];
        boundaryEdgeJoint_[f] = edgeJoint[3*t + k];
        boundaryEdgePatch_[f] =
            (f < nExternal ? topo_.boundaryPatch()[f] : label(-1));
    }
}


Foam::label Foam::continuousView::nextFace(const label f) const
{
    const labelList& edgeJoint = topo_.edgeJoint();

    // Turn round the end vertex of face f inside its fragment, crossing
    // intact joints, until an outgoing edge is a boundary face
    label t = faceTriangle_[f];
    label v = (faceEdge_[f] + 1) % 3;
    for (label step = 0; step < 3*topo_.nTriangles() + 1; ++step)
    {
        const label e = 3*t + v;
        if (faceOfEdge_[e] >= 0)
        {
            return faceOfEdge_[e];
        }
        const label j = edgeJoint[e];
        label k2;
        if (topo_.jointTriangleA()[j] == t && topo_.jointEdgeA()[j] == v)
        {
            t = topo_.jointTriangleB()[j];
            k2 = topo_.jointEdgeB()[j];
        }
        else
        {
            t = topo_.jointTriangleA()[j];
            k2 = topo_.jointEdgeA()[j];
        }
        // Edge k2 of the neighbour runs the other way: it ends at our vertex
        v = (k2 + 1) % 3;
    }

    FatalErrorInFunction
        << "No boundary face follows face " << f << " of triangle "
        << faceTriangle_[f] << ": inconsistent joint topology"
        << exit(FatalError);
    return -1;
}


void Foam::continuousView::updatePositions
(
    const UList<vector2D>& nodePositions
)
{
    // Average as (lowest node) + mean offset from it, so that nodes at one
    // place give exactly that place (round trips are exact)
    const label nPts = points_.size();
    List<vector2D>& ref = positionRef_;
    List<vector2D>& sum = positionSum_;
    ref.setSize(nPts);
    sum.setSize(nPts);
    for (label n = pointOfNode_.size() - 1; n >= 0; --n)
    {
        ref[pointOfNode_[n]] = nodePositions[n];
    }
    sum = Zero;
    forAll(pointOfNode_, n)
    {
        const label p = pointOfNode_[n];
        sum[p] += nodePositions[n] - ref[p];
    }
    for (label p = 0; p < nPts; ++p)
    {
        // Points of the source mesh used by no triangle keep their place
        if (nNodesOfPoint_[p] > 0)
        {
            points_[p] = ref[p] + sum[p]/scalar(nNodesOfPoint_[p]);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::continuousView::continuousView(const jointTopology& topo)
:
    topo_(topo),
    broken_(topo.nJoints(), false),
    nBroken_(0),
    points_(topo.initialPoints()),
    pointOfNode_(topo.nNodes(), -1),
    nNodesOfPoint_(labelList(topo.initialPoints().size(), Zero)),
    triangles_(topo.nTriangles()),
    fragmentOfTriangle_(topo.nTriangles(), -1),
    nFragments_(0),
    faceOfEdge_(topo.nNodes(), -1),
    nodeMark_(topo.nNodes(), -1),
    triangleMark_(topo.nTriangles(), -1),
    stamp_(0)
{
    const labelList& nodeVertex = topo.nodeVertex();

    // Points: connected sets of nodes; the first set at a source vertex
    // takes the vertex index, further ones (pinches) are appended
    boolList vertexTaken(points_.size(), false);
    for (label n = 0; n < topo.nNodes(); ++n)
    {
        if (pointOfNode_[n] >= 0)
        {
            continue;
        }
        queue_.clear();
        collectNodes(n, broken_, ++stamp_, queue_);

        const label v = nodeVertex[n];
        label pointi = v;
        if (vertexTaken[v])
        {
            pointi = points_.size();
            points_.append(topo.initialPoints()[v]);
            nNodesOfPoint_.append(0);
        }
        vertexTaken[v] = true;
        nNodesOfPoint_[pointi] = queue_.size();
        for (const label m : queue_)
        {
            pointOfNode_[m] = pointi;
            triangles_[m/3][m % 3] = pointi;
        }
    }

    // Fragments: connected sets of triangles, numbered by lowest triangle
    const labelList& edgeJoint = topo.edgeJoint();
    for (label t0 = 0; t0 < topo.nTriangles(); ++t0)
    {
        if (fragmentOfTriangle_[t0] >= 0)
        {
            continue;
        }
        const label fragment = nFragments_++;
        queue_.clear();
        queue_.append(t0);
        fragmentOfTriangle_[t0] = fragment;
        for (label i = 0; i < queue_.size(); ++i)
        {
            const label t = queue_[i];
            for (label k = 0; k < 3; ++k)
            {
                const label j = edgeJoint[3*t + k];
                if (j < 0)
                {
                    continue;
                }
                const label u =
                    topo.jointTriangleA()[j] == t
                  ? topo.jointTriangleB()[j] : topo.jointTriangleA()[j];
                if (fragmentOfTriangle_[u] < 0)
                {
                    fragmentOfTriangle_[u] = fragment;
                    queue_.append(u);
                }
            }
        }
    }

    // External faces, in the order (and so with the patches) of topo
    forAll(topo.boundaryTriangle(), f)
    {
        addFace(topo.boundaryTriangle()[f], topo.boundaryEdge()[f]);
    }
    updateBoundaryEdges();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::continuousView::update
(
    const UList<vector2D>& nodePositions,
    const UList<bool>& jointBroken
)
{
    if
    (
        nodePositions.size() != topo_.nNodes()
     || jointBroken.size() != topo_.nJoints()
    )
    {
        FatalErrorInFunction
            << "Expected " << topo_.nNodes() << " node positions and "
            << topo_.nJoints() << " joint states, got "
            << nodePositions.size() << " and " << jointBroken.size()
            << exit(FatalError);
    }

    // Joints that broke since the last call
    DynamicList<label> newlyBroken;
    forAll(jointBroken, j)
    {
        if (jointBroken[j] != broken_[j])
        {
            if (!jointBroken[j])
            {
                FatalErrorInFunction
                    << "Joint " << j << " was broken and is now reported"
                    << " intact: joints never heal" << exit(FatalError);
            }
            newlyBroken.append(j);
        }
    }

    if (newlyBroken.size())
    {
        // Points at both ends of each broken joint, each split once from
        // the states before and after all the breaks of this call
        labelHashSet touchedPoints(4*newlyBroken.size());
        DynamicList<label> seeds(2*newlyBroken.size());
        for (const label j : newlyBroken)
        {
            const jointNodeList& jn = topo_.jointNodes()[j];
            for (const label n : {jn[0], jn[1]})
            {
                if (touchedPoints.insert(pointOfNode_[n]))
                {
                    seeds.append(n);
                }
            }
        }
        for (const label seed : seeds)
        {
            splitPoint(seed, jointBroken);
        }

        // Crack faces, then the new state, then the fragments it separates
        for (const label j : newlyBroken)
        {
            addFace(topo_.jointTriangleA()[j], topo_.jointEdgeA()[j]);
            addFace(topo_.jointTriangleB()[j], topo_.jointEdgeB()[j]);
            broken_[j] = true;
        }
        nBroken_ += newlyBroken.size();

        // Fragments: the triangles on both sides of the broken joints,
        // searched fragment by fragment
        List<labelPair> sideSeeds(2*newlyBroken.size());
        forAll(newlyBroken, i)
        {
            const label j = newlyBroken[i];
            const label tA = topo_.jointTriangleA()[j];
            const label tB = topo_.jointTriangleB()[j];
            sideSeeds[2*i] = labelPair(fragmentOfTriangle_[tA], tA);
            sideSeeds[2*i + 1] = labelPair(fragmentOfTriangle_[tB], tB);
        }
        Foam::sort(sideSeeds);
        DynamicList<label> fragmentSeeds;
        forAll(sideSeeds, i)
        {
            fragmentSeeds.append(sideSeeds[i].second());
            if
            (
                i + 1 == sideSeeds.size()
             || sideSeeds[i + 1].first() != sideSeeds[i].first()
            )
            {
                splitFragment(fragmentSeeds);
                fragmentSeeds.clear();
            }
        }

        updateBoundaryEdges();
    }

    updatePositions(nodePositions);
}


Foam::List<Foam::labelList> Foam::continuousView::boundaryLoops
(
    const label fragment
) const
{
    const label nFaces = faceTriangle_.size();
    boolList visited(nFaces, false);
    DynamicList<labelList> loops;
    DynamicList<label> loop;

    for (label f0 = 0; f0 < nFaces; ++f0)
    {
        if (visited[f0] || boundaryEdgeFragment_[f0] != fragment)
        {
            continue;
        }
        loop.clear();
        label f = f0;
        do
        {
            if (visited[f] || loop.size() > nFaces)
            {
                FatalErrorInFunction
                    << "Boundary loop of fragment " << fragment
                    << " through face " << f0 << " does not close"
                    << exit(FatalError);
            }
            visited[f] = true;
            loop.append(f);
            f = nextFace(f);
        } while (f != f0);
        loops.append(loop);
    }
    return List<labelList>(std::move(loops));
}


Foam::List<Foam::labelList> Foam::continuousView::boundaryPolygons
(
    const label fragment
) const
{
    List<labelList> loops(boundaryLoops(fragment));
    for (labelList& loop : loops)
    {
        for (label& f : loop)
        {
            f = boundaryEdges_[f][0];
        }
    }
    return loops;
}


// ************************************************************************* //

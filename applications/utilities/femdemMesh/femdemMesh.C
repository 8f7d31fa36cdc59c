/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemMesh

Group
    grpMeshGenerationUtilities

Description
    Meshes the 2D solids described in system/femdemMeshDict with CGAL's
    constrained Delaunay mesher (smallest angle and local size bounds) and
    writes the continuous solid mesh constant/solidMesh (see triangleMesh).
    Optional pre-existing joints (entry 'jointSets', see femdemMeshJoints.H)
    are constraints of the mesh: every joint segment, clipped to the solid,
    is covered by triangle edges, listed in the mesh's jointSets with the
    set's properties.

    \verbatim
    targetSize  0.02;           // largest edge length away from refinements
    minAngle    20;             // degrees (CGAL terminates for <= 20.7)
    solids                      // later solids win where solids overlap
    {
        rock  { type rectangle; min (0 0); max (1 0.5); material granite;
                patches (bottom right top left); }  // or: patch walls;
        slab  { type polygon; points ((0 0) (1 0) (0.5 1)); material rock;
                patches (base right left); }         // one name per side
        disk  { type circle; centre (2 0); radius 0.2; material steel;
                patch rim; nSegments 64; }           // nSegments optional
    }
    holes                       // not meshed (boreholes)
    {
        borehole { type circle; centre (0.5 0.25); radius 0.02; }
                                // patch defaults to the hole's name
    }
    refinement                  // optional: smaller triangles near features
    {
        hole { type circle; centre (0.5 0.25); radius 0.02;
               size 0.004; distance 0.01; grading 0.3; }
        tip  { type point; point (0.8 0.25); size 0.005; }
        line { type polyline; points ((0 0) (1 0.5)); size 0.01; }
    }
    jointSets                   // optional: see femdemMeshJoints.H
    {
        bedding { type lines; segments (((0 0.1) (1 0.3))); tensileStrength 1e6; }
        dfn     { type file; file "constant/dfn.csv"; }
    }
    \endverbatim
    Size at a point: the smallest of targetSize and, for each refinement,
    size + grading*max(0, distance to the feature - distance) (distance
    and grading default to 0 and 0.3). Sides without a patch name belong to
    the patch 'walls'.

Usage
    femdemMesh [-case dir] [-dict file] [-renumber] [-vtk] [-maxTriangles n]

    -renumber   METIS renumbering of triangles and points (blocks of 32)
    -vtk        also write VTK/solidMesh_0.vtu (materials, quality)
    -maxTriangles  stop before meshing when the solids' area over the area
                of a triangle of edge targetSize exceeds it (default 2e7)

    A self-crossing polygon and a mesh without triangles (holes covering
    the solids) are FatalIOErrors naming the entry.

\*---------------------------------------------------------------------------*/

#include "cgalTriangulator.H"
#include "femdemMeshJoints.H"

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "caseChecks.H"
#include "clockTime.H"
#include "triangleMesh.H"
#include "jointTopology.H"
#include "solidMeshRenumber.H"
#include "solidMeshQuality.H"
#include "solidVtkWriter.H"
#include "mathematicalConstants.H"
#include "HashTable.H"
#include "EdgeMap.H"
#include "ListOps.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A closed polygon with a patch per side and a material (solids)
struct shape
{
    word name;
    List<vector2D> points;
    labelList sidePatch;
    label material;
};

//- A refinement feature: a polyline (one point: a point) or a circle
struct refinementFeature
{
    List<vector2D> points;
    bool circle;
    vector2D centre;
    scalar radius, size, distance, grading;

    scalar distanceTo(const vector2D& x) const
    {
        if (circle)
        {
            return mag(mag(x - centre) - radius);
        }
        scalar d = mag(x - points[0]);
        for (label i = 1; i < points.size(); ++i)
        {
            const vector2D a = points[i - 1], ab = points[i] - a;
            const scalar len2 = magSqr(ab);
            scalar s = len2 > 0 ? ((x - a) & ab)/len2 : 0;
            s = min(max(s, scalar(0)), scalar(1));
            d = min(d, mag(x - (a + s*ab)));
        }
        return d;
    }
};

bool inside(const List<vector2D>& poly, const vector2D& p)
{
    // Crossing number
    bool in = false;
    for (label i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
    {
        const vector2D& a = poly[i];
        const vector2D& b = poly[j];
        if
        (
            (a.y() > p.y()) != (b.y() > p.y())
         && p.x() < (b.x() - a.x())*(p.y() - a.y())/(b.y() - a.y()) + a.x()
        )
        {
            in = !in;
        }
    }
    return in;
}


label patchIndex(DynamicList<word>& patchNames, const word& name)
{
    label i = patchNames.find(name);
    if (i < 0)
    {
        i = patchNames.size();
        patchNames.append(name);
    }
    return i;
}


//- Read one solid or hole; sizeAt gives the local size for circles
shape readShape
(
    const dictionary& dict,
    const word& defaultPatch,
    DynamicList<word>& patchNames,
    const std::function<scalar(const vector2D&)>& sizeAt
)
{
    shape s;
    s.name = dict.dictName();
    s.material = -1;
    const word type = dict.get<word>("type");

    if (type == "rectangle")
    {
        const vector2D lo = dict.get<vector2D>("min");
        const vector2D hi = dict.get<vector2D>("max");
        if (!(hi.x() > lo.x() && hi.y() > lo.y()))
        {
            FatalIOErrorInFunction(dict)
                << "rectangle " << s.name << ": max " << hi
                << " must exceed min " << lo << " in x and y"
                << exit(FatalIOError);
        }
        s.points = List<vector2D>
        ({
            lo, vector2D(hi.x(), lo.y()), hi, vector2D(lo.x(), hi.y())
        });
    }
    else if (type == "polygon")
    {
        s.points = dict.get<List<vector2D>>("points");
        if (s.points.size() < 3)
        {
            FatalIOErrorInFunction(dict)
                << "polygon " << s.name << " has " << s.points.size()
                << " points; at least 3 are needed" << exit(FatalIOError);
        }
    }
    else if (type == "circle")
    {
        const vector2D c = dict.get<vector2D>("centre");
        const scalar r = dict.get<scalar>("radius");
        if (!(r > 0))
        {
            FatalIOErrorInFunction(dict)
                << "circle " << s.name << ": radius " << r
                << " must be positive" << exit(FatalIOError);
        }
        // Chords no longer than the local size anywhere on the circle
        scalar h = GREAT;
        for (label i = 0; i < 360; ++i)
        {
            const scalar a = constant::mathematical::twoPi*i/360;
            h = min(h, sizeAt(c + r*vector2D(Foam::cos(a), Foam::sin(a))));
        }
        const label n = dict.getOrDefault<label>
        (
            "nSegments",
            max(label(8), label(ceil(constant::mathematical::twoPi*r/h)))
        );
        if (n < 3)
        {
            FatalIOErrorInFunction(dict)
                << "circle " << s.name << ": nSegments " << n << " < 3"
                << exit(FatalIOError);
        }
        s.points.setSize(n);
        forAll(s.points, i)
        {
            const scalar a = constant::mathematical::twoPi*i/n;
            s.points[i] = c + r*vector2D(Foam::cos(a), Foam::sin(a));
        }
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Unknown type " << type << " of " << s.name
            << "; valid types: (rectangle polygon circle)"
            << exit(FatalIOError);
    }

    // A self-crossing outline has no well-defined inside (CGAL meshes only
    // part of it): two sides that are not neighbours must not touch
    if (type == "polygon")
    {
        const List<vector2D>& P = s.points;
        const label n = P.size();
        auto cross = [](const vector2D& a, const vector2D& b)
        {
            return a.x()*b.y() - a.y()*b.x();
        };
        for (label i = 0; i < n; ++i)
        {
            const vector2D& a = P[i];
            const vector2D& b = P[(i + 1) % n];
            for (label j = i + 1; j < n; ++j)
            {
                if (j == i + 1 || (i == 0 && j == n - 1))
                {
                    continue;   // neighbouring sides share a point
                }
                const vector2D& c = P[j];
                const vector2D& d = P[(j + 1) % n];
                const scalar d1 = cross(b - a, c - a);
                const scalar d2 = cross(b - a, d - a);
                const scalar d3 = cross(d - c, a - c);
                const scalar d4 = cross(d - c, b - c);
                bool meet = d1*d2 <= 0 && d3*d4 <= 0;
                if (d1 == 0 && d2 == 0)
                {
                    // Collinear sides meet only if their spans overlap
                    const vector2D t = b - a;
                    const scalar sc = (c - a) & t, sd = (d - a) & t;
                    meet = max(sc, sd) >= 0 && min(sc, sd) <= (t & t);
                }
                if (meet)
                {
                    FatalIOErrorInFunction(dict)
                        << "polygon " << s.name << ", entry 'points': side "
                        << i << " " << a << "-" << b << " crosses or touches"
                        << " side " << j << " " << c << "-" << d
                        << ": the outline must not cross itself"
                        << exit(FatalIOError);
                }
            }
        }
    }

    // Patches: one name for all sides, or a name per side
    s.sidePatch.setSize(s.points.size());
    if (dict.found("patches") && type != "circle")
    {
        const wordList names = dict.get<wordList>("patches");
        if (names.size() != s.points.size())
        {
            FatalIOErrorInFunction(dict)
                << s.name << ": entry 'patches' has " << names.size()
                << " names for " << s.points.size() << " sides"
                << exit(FatalIOError);
        }
        forAll(names, i)
        {
            s.sidePatch[i] = patchIndex(patchNames, names[i]);
        }
    }
    else
    {
        s.sidePatch = patchIndex
        (
            patchNames,
            dict.getOrDefault<word>("patch", defaultPatch)
        );
    }
    return s;
}


//- Joint points and pieces into the CGAL input (tag: the segment); a
//  crossing at an outline vertex takes that vertex's coordinates
void addJointInput
(
    femdemMeshJoints::clippedJoints& joints,
    const UList<List<vector2D>>& outlines,
    cgalTriangulator::domain& input
)
{
    const scalar eps = 1e-10;
    for (femdemMeshJoints::outlinePoint& op : joints.inserted)
    {
        const List<vector2D>& P = outlines[op.outline];
        if (op.s < eps || op.s > 1 - eps)
        {
            const label k = op.s < eps ? op.side : (op.side + 1) % P.size();
            joints.points[op.point] = P[k];
            op.point = -1;      // the outline has the point already
        }
    }
    for (const vector2D& p : joints.points)
    {
        input.x.push_back(p.x());
        input.y.push_back(p.y());
    }
    forAll(joints.pieceStart, i)
    {
        input.jointStart.push_back(joints.pieceStart[i]);
        input.jointEnd.push_back(joints.pieceEnd[i]);
        input.jointTag.push_back(joints.pieceSegment[i]);
    }
}


//- Outline o as constrained sides, the joints' crossings inserted in order
void addOutline
(
    const label o,
    const labelList& sidePatch,
    const femdemMeshJoints::clippedJoints& joints,
    const List<vector2D>& P,
    cgalTriangulator::domain& input
)
{
    DynamicList<label> loop, side;
    forAll(P, k)
    {
        loop.append(input.x.size());
        side.append(k);
        input.x.push_back(P[k].x());
        input.y.push_back(P[k].y());
        DynamicList<scalar> s;
        DynamicList<label> pts;
        for (const femdemMeshJoints::outlinePoint& op : joints.inserted)
        {
            if (op.outline == o && op.side == k && op.point >= 0)
            {
                s.append(op.s);
                pts.append(op.point);
            }
        }
        for (const label i : sortedOrder(s))
        {
            loop.append(pts[i]);
            side.append(k);
        }
    }
    forAll(loop, i)
    {
        input.segmentStart.push_back(loop[i]);
        input.segmentEnd.push_back(loop[(i + 1) % loop.size()]);
        input.segmentTag.push_back(sidePatch[side[i]]);
    }
}


//- The joint sets of the mesh: the edges covering each set's segments
List<triangleJointSet> meshJointSets
(
    const cgalTriangulator::mesh& m,
    const UList<femdemMeshJoints::jointSetSpec>& sets,
    const UList<femdemMeshJoints::segment>& segments
)
{
    List<triangleJointSet> result(sets.size());
    List<EdgeMap<label>> seen(sets.size());
    List<DynamicList<edge>> edges(sets.size());
    List<DynamicList<scalar>> factor(sets.size()), friction(sets.size());
    for (size_t i = 0; i < m.jointEdgeTag.size(); ++i)
    {
        const femdemMeshJoints::segment& sg = segments[m.jointEdgeTag[i]];
        const edge e(m.jointEdgeStart[i], m.jointEdgeEnd[i]);
        if (!seen[sg.set].insert(e, 0)) continue;   // overlapping segments
        edges[sg.set].append(e);
        factor[sg.set].append(sg.factor);
        friction[sg.set].append(sg.frictionAngle);
    }
    forAll(sets, s)
    {
        triangleJointSet& js = result[s];
        js.name = sets[s].name;
        js.properties = sets[s].properties;
        js.edges.transfer(edges[s]);
        if (sets[s].perEdgeFactor) js.strengthFactor.transfer(factor[s]);
        if (sets[s].perEdgeFriction) js.frictionAngle.transfer(friction[s]);
    }
    return result;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Mesh the 2D solids of system/femdemMeshDict with CGAL and write"
        " constant/solidMesh"
    );
    argList::noParallel();
    argList::addOption("dict", "file", "Alternative femdemMeshDict");
    argList::addBoolOption("renumber", "METIS renumbering for locality");
    argList::addBoolOption("vtk", "Also write VTK/solidMesh_0.vtu");
    argList::addOption
    (
        "maxTriangles", "n",
        "Stop before meshing if targetSize gives more triangles (2e7)"
    );

    argList args(argc, argv);
    const scalar maxTriangles = args.getOrDefault<scalar>("maxTriangles", 2e7);
    if (!(maxTriangles >= 1))
    {
        FatalErrorInFunction
            << "option -maxTriangles " << maxTriangles << " must be >= 1"
            << exit(FatalError);
    }
    Time runTime(args.rootPath(), args.caseName(), "system", "constant", false, false);

    const fileName dictFile =
        args.getOrDefault<fileName>("dict", runTime.system()/"femdemMeshDict");
    IOdictionary meshDict
    (
        IOobject
        (
            dictFile.isAbsolute() ? dictFile : runTime.path()/dictFile,
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    caseChecks::checkInput(meshDict);
    clockTime clock;

    const scalar targetSize = meshDict.get<scalar>("targetSize");
    const scalar minAngle = meshDict.getOrDefault<scalar>("minAngle", 20);
    if (!(targetSize > 0))
    {
        FatalIOErrorInFunction(meshDict)
            << "targetSize " << targetSize << " must be positive"
            << exit(FatalIOError);
    }
    if (!(minAngle > 0 && minAngle <= 35))
    {
        FatalIOErrorInFunction(meshDict)
            << "minAngle " << minAngle << " must be in (0, 35] degrees"
            << " (CGAL guarantees termination up to 20.7)"
            << exit(FatalIOError);
    }

    if (minAngle > 20.7)
    {
        Info<< "Note: minAngle " << minAngle << " > 20.7 degrees: CGAL does"
            << " not guarantee that the refinement terminates" << nl;
    }

    // Size function
    List<refinementFeature> features;
    if (meshDict.found("refinement"))
    {
        const dictionary& rdict = meshDict.subDict("refinement");
        for (const word& key : rdict.toc())
        {
            const dictionary& d = rdict.subDict(key);
            refinementFeature f;
            const word type = d.get<word>("type");
            f.circle = (type == "circle");
            f.radius = 0;
            if (type == "point")
            {
                f.points = List<vector2D>(1, d.get<vector2D>("point"));
            }
            else if (type == "polyline")
            {
                f.points = d.get<List<vector2D>>("points");
            }
            else if (f.circle)
            {
                f.centre = d.get<vector2D>("centre");
                f.radius = d.get<scalar>("radius");
            }
            else
            {
                FatalIOErrorInFunction(d)
                    << "Unknown refinement type " << type
                    << "; valid types: (point polyline circle)"
                    << exit(FatalIOError);
            }
            if (!f.circle && f.points.empty())
            {
                FatalIOErrorInFunction(d)
                    << "refinement " << key << " has no points"
                    << exit(FatalIOError);
            }
            f.size = d.get<scalar>("size");
            f.distance = d.getOrDefault<scalar>("distance", 0);
            f.grading = d.getOrDefault<scalar>("grading", 0.3);
            if (!(f.size > 0) || f.grading < 0 || f.distance < 0)
            {
                FatalIOErrorInFunction(d)
                    << "refinement " << key << ": size must be positive,"
                    << " distance and grading not negative"
                    << exit(FatalIOError);
            }
            features.append(f);
        }
    }
    auto sizeAt = [&](const vector2D& x)
    {
        scalar h = targetSize;
        for (const refinementFeature& f : features)
        {
            h = min(h, f.size + f.grading*max(f.distanceTo(x) - f.distance, 0));
        }
        return h;
    };

    // Shapes
    DynamicList<word> patchNames;
    DynamicList<word> materials;
    DynamicList<shape> solids, holes;
    {
        const dictionary& sdict = meshDict.subDict("solids");
        for (const word& key : sdict.toc())
        {
            const dictionary& d = sdict.subDict(key);
            shape s = readShape(d, "walls", patchNames, sizeAt);
            const word material = d.get<word>("material");
            s.material = materials.find(material);
            if (s.material < 0)
            {
                s.material = materials.size();
                materials.append(material);
            }
            solids.append(s);
        }
        if (solids.empty())
        {
            FatalIOErrorInFunction(meshDict)
                << "No solids in entry 'solids'" << exit(FatalIOError);
        }
    }
    if (meshDict.found("holes"))
    {
        const dictionary& hdict = meshDict.subDict("holes");
        for (const word& key : hdict.toc())
        {
            holes.append
            (
                readShape(hdict.subDict(key), key, patchNames, sizeAt)
            );
        }
    }

    // Stop at once when the target size would give far more triangles than
    // the solvers can run (CGAL would run for minutes or exhaust memory):
    // an equilateral triangle of edge h has the area sqrt(3)/4 h^2
    {
        scalar area = 0;
        for (const shape& sh : solids)
        {
            scalar a = 0;
            forAll(sh.points, i)
            {
                const vector2D& p = sh.points[i];
                const vector2D& q = sh.points[(i + 1) % sh.points.size()];
                a += 0.5*(p.x()*q.y() - p.y()*q.x());
            }
            area += mag(a);
        }
        const scalar estimate = area/(0.433*sqr(targetSize));
        if (estimate > maxTriangles)
        {
            FatalIOErrorInFunction(meshDict)
                << "entry 'targetSize' " << targetSize << " gives about "
                << estimate << " triangles for the solids' area " << area
                << " m2, more than -maxTriangles " << maxTriangles
                << ": raise targetSize (or -maxTriangles)"
                << exit(FatalIOError);
        }
    }

    // Joint sets, clipped to the solid (outlines: solids, then holes)
    List<List<vector2D>> outlines(solids.size() + holes.size());
    forAll(solids, i) outlines[i] = solids[i].points;
    forAll(holes, i) outlines[solids.size() + i] = holes[i].points;
    auto regionOf = [&](const vector2D& p)
    {
        for (const shape& h : holes)
        {
            if (inside(h.points, p)) return label(-1);
        }
        for (label i = solids.size() - 1; i >= 0; --i)
        {
            if (inside(solids[i].points, p)) return solids[i].material;
        }
        return label(-1);
    };
    DynamicList<femdemMeshJoints::jointSetSpec> jointSets;
    DynamicList<femdemMeshJoints::segment> jointSegments;
    femdemMeshJoints::read(meshDict, runTime.path(), jointSets, jointSegments);
    femdemMeshJoints::clippedJoints joints = femdemMeshJoints::clip
    (
        meshDict, jointSets, jointSegments, outlines,
        [&](const vector2D& p) { return regionOf(p) >= 0; }
    );

    // CGAL input: joint points first, then the outlines with the joints'
    // crossing points inserted into their sides
    cgalTriangulator::domain input;
    addJointInput(joints, outlines, input);
    forAll(outlines, o)
    {
        const shape& s =
            o < solids.size() ? solids[o] : holes[o - solids.size()];
        addOutline(o, s.sidePatch, joints, outlines[o], input);
    }
    input.region = [&](double x, double y) { return regionOf(vector2D(x, y)); };
    input.size = [&](double x, double y) { return sizeAt(vector2D(x, y)); };
    input.minAngleDegrees = minAngle;

    Info<< "Meshing " << solids.size() << " solids, " << holes.size()
        << " holes, " << input.segmentStart.size() << " boundary segments, "
        << jointSets.size() << " joint sets (" << joints.pieceStart.size()
        << " pieces of " << jointSegments.size() << " segments, "
        << joints.nClipped << " pieces outside the solid clipped),"
        << " target size " << targetSize << ", smallest angle " << minAngle
        << " degrees" << endl;

    cgalTriangulator::mesh cgalMesh;
    try
    {
        cgalMesh = cgalTriangulator::triangulate(input);
    }
    catch (const std::exception& e)
    {
        FatalIOErrorInFunction(meshDict)
            << "CGAL meshing failed: " << e.what() << exit(FatalIOError);
    }
    const scalar meshTime = clock.timeIncrement();

    if (cgalMesh.triangleRegion.empty())
    {
        FatalIOErrorInFunction(meshDict)
            << "the mesh has no triangles: entry 'holes' covers every solid"
            << " of entry 'solids'" << exit(FatalIOError);
    }

    // To the continuous solid mesh
    List<vector2D> points(cgalMesh.x.size());
    forAll(points, i)
    {
        points[i] = vector2D(cgalMesh.x[i], cgalMesh.y[i]);
    }
    List<triangleVertices> triangles(cgalMesh.triangleRegion.size());
    labelList triangleMaterials(triangles.size());
    forAll(triangles, t)
    {
        triangles[t] = triangleVertices
        ({
            cgalMesh.triangles[3*t],
            cgalMesh.triangles[3*t + 1],
            cgalMesh.triangles[3*t + 2]
        });
        triangleMaterials[t] = cgalMesh.triangleRegion[t];
    }
    List<DynamicList<edge>> patchEdges(patchNames.size());
    label nUnnamed = 0;
    for (size_t e = 0; e < cgalMesh.edgeTag.size(); ++e)
    {
        const edge ed(cgalMesh.edgeStart[e], cgalMesh.edgeEnd[e]);
        if (cgalMesh.edgeTag[e] >= 0)
        {
            patchEdges[cgalMesh.edgeTag[e]].append(ed);
        }
        else
        {
            ++nUnnamed;
        }
    }
    List<edgeList> patches(patchNames.size());
    forAll(patches, i)
    {
        patches[i].transfer(patchEdges[i]);
    }

    triangleMesh mesh
    (
        points, triangles, triangleMaterials, materials, patchNames, patches
    );
    mesh.setJointSets(meshJointSets(cgalMesh, jointSets, jointSegments));
    if (args.found("renumber"))
    {
        const scalar before = solidMeshRenumber::localNeighbourFraction(mesh);
        mesh = solidMeshRenumber::renumber(mesh);
        Info<< "METIS renumbering: neighbours closer than 64 in index "
            << 100*before << " % -> "
            << 100*solidMeshRenumber::localNeighbourFraction(mesh) << " %"
            << nl;
    }
    const jointTopology topo(mesh);
    const scalar convertTime = clock.timeIncrement();

    solidMeshQuality::report(mesh, Info);
    Info<< "    joints: " << topo.nJoints() << nl
        << "    boundary edges: " << topo.nBoundaryFaces()
        << " (not in a named patch: " << nUnnamed << ")" << nl
        << "Meshing time: " << meshTime << " s, conversion check: "
        << convertTime << " s" << nl << endl;

    mesh.write
    (
        runTime,
        IOstream::ASCII
    );
    Info<< "Wrote " << runTime.constant()/triangleMesh::meshFileName
        << " in " << clock.timeIncrement() << " s" << endl;

    if (args.found("vtk"))
    {
        solidVtkWriter vtk(runTime.path()/"VTK", "solidMesh");
        solidMeshQuality::writeVtk(mesh, vtk);
        Info<< "Wrote " << vtk.stepFile(0) << endl;
    }

    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //

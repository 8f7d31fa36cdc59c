/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "gmshReader.H"
#include "EdgeMap.H"
#include "SortableList.H"
#include "boundBox.H"
#include "error.H"

#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Number of nodes of the gmsh element types we read; 0 for the others
int nodesOfType(const int type)
{
    switch (type)
    {
        case 1: return 2;       // line
        case 2: return 3;       // triangle
        case 15: return 1;      // point
        default: return 0;
    }
}

const char* typeName(const int type)
{
    switch (type)
    {
        case 3: return "4-node quadrangle";
        case 8: return "3-node (second order) line";
        case 9: return "6-node (second order) triangle";
        case 10: return "9-node quadrangle";
        case 16: return "8-node quadrangle";
        case 4: return "tetrahedron";
        default: return "unsupported element";
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::gmshReader::fail(const std::string& msg) const
{
    FatalErrorInFunction
        << "Reading gmsh file " << name_ << ": " << msg.c_str()
        << exit(FatalError);
    std::abort();   // not reached: exit throws or ends the program
}


void Foam::gmshReader::skipSection(std::istream& is, const std::string& section)
{
    const std::string end = "$End" + section.substr(1);
    std::string token;
    while (is >> token)
    {
        if (token == end)
        {
            return;
        }
    }
    fail("section " + section + " has no " + end);
}


void Foam::gmshReader::expectEnd(std::istream& is, const std::string& section)
{
    const std::string end = "$End" + section.substr(1);
    std::string token;
    if (!(is >> token) || token != end)
    {
        fail
        (
            "section " + section + ": found '" + token + "' where " + end
          + " was expected (counts do not match the data)"
        );
    }
}


void Foam::gmshReader::readPhysicalNames(std::istream& is)
{
    label n = 0;
    if (!(is >> n))
    {
        fail("$PhysicalNames: missing count");
    }
    for (label i = 0; i < n; ++i)
    {
        label dim = 0, tag = 0;
        std::string rest;
        if (!(is >> dim >> tag) || !std::getline(is, rest))
        {
            fail("$PhysicalNames: entry " + std::to_string(i) + " unreadable");
        }
        const size_t a = rest.find('"'), b = rest.rfind('"');
        std::string name =
            (a != std::string::npos && b > a) ? rest.substr(a + 1, b - a - 1)
          : rest;
        const word w = word::validate(name);
        if (dim == 1)
        {
            curveNames_.set(tag, w);
        }
        else if (dim == 2)
        {
            surfaceNames_.set(tag, w);
        }
    }
}


void Foam::gmshReader::readEntities(std::istream& is)
{
    label nEntities[4];
    for (label& n : nEntities)
    {
        if (!(is >> n))
        {
            fail("$Entities: missing counts");
        }
    }
    for (label dim = 0; dim < 4; ++dim)
    {
        for (label e = 0; e < nEntities[dim]; ++e)
        {
            label tag = 0;
            scalar bb = 0;
            is >> tag;
            // Points: x y z; others: bounding box
            for (label i = 0; i < (dim == 0 ? 3 : 6); ++i)
            {
                is >> bb;
            }
            label nPhysical = 0;
            is >> nPhysical;
            label physical = -1;
            for (label i = 0; i < nPhysical; ++i)
            {
                label p = 0;
                is >> p;
                if (i == 0)
                {
                    physical = p;
                }
            }
            if (dim > 0)
            {
                label nBounding = 0, b = 0;
                is >> nBounding;
                for (label i = 0; i < nBounding; ++i)
                {
                    is >> b;
                }
            }
            if (!is)
            {
                fail
                (
                    "$Entities: entity " + std::to_string(tag)
                  + " of dimension " + std::to_string(dim) + " unreadable"
                );
            }
            if (dim == 1 && physical >= 0)
            {
                curvePhysical_.set(tag, physical);
            }
            else if (dim == 2 && physical >= 0)
            {
                surfacePhysical_.set(tag, physical);
            }
        }
    }
}


void Foam::gmshReader::readNodes2(std::istream& is)
{
    label n = 0;
    if (!(is >> n))
    {
        fail("$Nodes: missing count");
    }
    for (label i = 0; i < n; ++i)
    {
        label tag;
        scalar x, y, z;
        if (!(is >> tag >> x >> y >> z))
        {
            fail("$Nodes: node " + std::to_string(i) + " unreadable");
        }
        if (nodeIndex_.found(tag))
        {
            fail
            (
                "$Nodes: duplicate node id " + std::to_string(tag)
              + " (node " + std::to_string(i) + " of the section repeats the"
                " id of an earlier node)"
            );
        }
        nodeIndex_.set(tag, nodeTag_.size());
        nodeTag_.append(tag);
        nodePoint_.append(vector2D(x, y));
        nodeZ_.append(z);
    }
}


void Foam::gmshReader::readNodes4(std::istream& is)
{
    label nBlocks = 0, nNodes = 0, minTag = 0, maxTag = 0;
    if (!(is >> nBlocks >> nNodes >> minTag >> maxTag))
    {
        fail("$Nodes: missing counts");
    }
    std::vector<label> tags;
    for (label blk = 0; blk < nBlocks; ++blk)
    {
        label dim = 0, entity = 0, parametric = 0, n = 0;
        if (!(is >> dim >> entity >> parametric >> n))
        {
            fail("$Nodes: block " + std::to_string(blk) + " unreadable");
        }
        tags.resize(n);
        for (label i = 0; i < n; ++i)
        {
            is >> tags[i];
        }
        for (label i = 0; i < n; ++i)
        {
            scalar x, y, z, u;
            is >> x >> y >> z;
            for (label k = 0; parametric && k < dim; ++k)
            {
                is >> u;
            }
            if (!is)
            {
                fail("$Nodes: node " + std::to_string(tags[i]) + " unreadable");
            }
            if (nodeIndex_.found(tags[i]))
            {
                fail
                (
                    "$Nodes: duplicate node id " + std::to_string(tags[i])
                  + " (block " + std::to_string(blk) + " repeats the id of"
                    " an earlier node)"
                );
            }
            nodeIndex_.set(tags[i], nodeTag_.size());
            nodeTag_.append(tags[i]);
            nodePoint_.append(vector2D(x, y));
            nodeZ_.append(z);
        }
    }
}


void Foam::gmshReader::addElement
(
    const label tag,
    const label type,
    const label physical,
    const std::vector<label>& nodes
)
{
    if (type == 2)
    {
        triTag_.append(tag);
        triPhysical_.append(physical);
        triNodes_.append(triangleVertices({nodes[0], nodes[1], nodes[2]}));
    }
    else if (type == 1)
    {
        lineTag_.append(tag);
        linePhysical_.append(physical);
        lineNodes_.append(edge(nodes[0], nodes[1]));
    }
}


void Foam::gmshReader::readElements2(std::istream& is)
{
    label n = 0;
    if (!(is >> n))
    {
        fail("$Elements: missing count");
    }
    std::vector<label> nodes;
    for (label i = 0; i < n; ++i)
    {
        label tag = 0, type = 0, nTags = 0, physical = -1, t = 0;
        if (!(is >> tag >> type >> nTags))
        {
            fail("$Elements: element " + std::to_string(i) + " unreadable");
        }
        for (label k = 0; k < nTags; ++k)
        {
            is >> t;
            if (k == 0)
            {
                physical = t;
            }
        }
        const int nNodes = nodesOfType(type);
        if (!nNodes)
        {
            fail
            (
                "element " + std::to_string(tag) + " is a "
              + typeName(type) + " (type " + std::to_string(type)
              + "); only 3-node triangles, 2-node lines and points are read"
            );
        }
        nodes.resize(nNodes);
        for (int k = 0; k < nNodes; ++k)
        {
            is >> nodes[k];
        }
        if (!is)
        {
            fail("$Elements: element " + std::to_string(tag) + " unreadable");
        }
        addElement(tag, type, physical > 0 ? physical : -1, nodes);
    }
}


void Foam::gmshReader::readElements4(std::istream& is)
{
    label nBlocks = 0, nElements = 0, minTag = 0, maxTag = 0;
    if (!(is >> nBlocks >> nElements >> minTag >> maxTag))
    {
        fail("$Elements: missing counts");
    }
    std::vector<label> nodes;
    for (label blk = 0; blk < nBlocks; ++blk)
    {
        label dim = 0, entity = 0, type = 0, n = 0;
        if (!(is >> dim >> entity >> type >> n))
        {
            fail("$Elements: block " + std::to_string(blk) + " unreadable");
        }
        const int nNodes = nodesOfType(type);
        label physical = -1;
        if (dim == 1 && curvePhysical_.found(entity))
        {
            physical = curvePhysical_[entity];
        }
        else if (dim == 2 && surfacePhysical_.found(entity))
        {
            physical = surfacePhysical_[entity];
        }
        for (label i = 0; i < n; ++i)
        {
            label tag = 0;
            is >> tag;
            if (!nNodes)
            {
                fail
                (
                    "element " + std::to_string(tag) + " is a "
                  + typeName(type) + " (type " + std::to_string(type)
                  + "); only 3-node triangles, 2-node lines and points are"
                    " read"
                );
            }
            nodes.resize(nNodes);
            for (int k = 0; k < nNodes; ++k)
            {
                is >> nodes[k];
            }
            if (!is)
            {
                fail("$Elements: element " + std::to_string(tag) + " unreadable");
            }
            addElement(tag, type, physical, nodes);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::gmshReader::gmshReader(std::istream& is, const fileName& name)
:
    name_(name),
    version_(0),
    flipped_(0),
    droppedLines_(0)
{
    std::string token;
    while (is >> token)
    {
        if (token == "$MeshFormat")
        {
            label fileType = 0, dataSize = 0;
            if (!(is >> version_ >> fileType >> dataSize))
            {
                fail("$MeshFormat unreadable");
            }
            if (fileType != 0)
            {
                fail
                (
                    "binary .msh files are not read; write ASCII"
                    " (gmsh -format msh22 or msh41, without -bin)"
                );
            }
            // (no label(version_): a huge number traps under FOAM_SIGFPE)
            if
            (
                !((version_ >= 2 && version_ < 3)
               || (version_ > 4.05 && version_ < 4.15))
            )
            {
                fail
                (
                    "$MeshFormat: format " + std::to_string(version_)
                  + " is not read; use 2.2 or 4.1"
                );
            }
            skipSection(is, token);
        }
        else if (token == "$PhysicalNames")
        {
            readPhysicalNames(is);
            expectEnd(is, token);
        }
        else if (token == "$Entities")
        {
            readEntities(is);
            expectEnd(is, token);
        }
        else if (token == "$Nodes")
        {
            if (version_ >= 4) readNodes4(is); else readNodes2(is);
            expectEnd(is, token);
        }
        else if (token == "$Elements")
        {
            if (version_ >= 4) readElements4(is); else readElements2(is);
            expectEnd(is, token);
        }
        else if (token.size() > 1 && token[0] == '$')
        {
            skipSection(is, token);
        }
        else
        {
            fail
            (
                "unexpected '" + token + "' outside a section (a section"
                " header $MeshFormat, $PhysicalNames, $Entities, $Nodes or"
                " $Elements missing before it?)"
            );
        }
    }
    if (version_ == 0)
    {
        fail("no $MeshFormat section: not a gmsh mesh file");
    }
    if (triTag_.empty())
    {
        fail
        (
            "no 3-node triangles: mesh the surfaces in 2D (gmsh -2) and put"
            " them in physical surfaces"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::triangleMesh Foam::gmshReader::mesh()
{
    // Triangles in order of element tag
    const labelList triOrder(sortedOrder(triTag_));

    // Used nodes in order of node tag
    DynamicList<label> usedTags(3*triTag_.size());
    for (const triangleVertices& tri : triNodes_)
    {
        for (const label nodeTag : tri)
        {
            usedTags.append(nodeTag);
        }
    }
    Foam::sort(usedTags);
    label nUnique = 0;
    forAll(usedTags, i)
    {
        if (i == 0 || usedTags[i] != usedTags[nUnique - 1])
        {
            usedTags[nUnique++] = usedTags[i];
        }
    }
    usedTags.setSize(nUnique);

    Map<label> pointOfTag(2*nUnique);
    List<vector2D> points(nUnique);
    scalar zMax = 0;
    label zNode = -1;
    boundBox bb;
    forAll(usedTags, i)
    {
        const auto iter = nodeIndex_.cfind(usedTags[i]);
        if (!iter.found())
        {
            fail
            (
                "node " + std::to_string(usedTags[i])
              + " used by a triangle is not in $Nodes"
            );
        }
        pointOfTag.set(usedTags[i], i);
        points[i] = nodePoint_[*iter];
        bb.add(point(points[i].x(), points[i].y(), 0));
        if (mag(nodeZ_[*iter]) > zMax)
        {
            zMax = mag(nodeZ_[*iter]);
            zNode = usedTags[i];
        }
    }
    if (zMax > 1e-12*max(bb.mag(), VSMALL))
    {
        fail
        (
            "node " + std::to_string(zNode) + " has z = "
          + std::to_string(zMax) + ": the solid must lie in the x-y plane"
        );
    }

    // Materials: physical surfaces in order of tag. A triangle in no
    // physical surface has no material name (and its mesh usually no named
    // boundary either): an error rather than a made-up material
    forAll(triPhysical_, e)
    {
        if (triPhysical_[e] < 0)
        {
            fail
            (
                "triangle element " + std::to_string(triTag_[e])
              + " is in no physical surface: define physical groups"
                " (Physical Surface(\"rock\") = {...}; for the materials,"
                " Physical Curve(\"walls\") = {...}; for the patches)"
            );
        }
    }
    SortableList<label> physicals(triPhysical_);
    physicals.sort();
    DynamicList<label> surfaceTags;
    for (const label p : physicals)
    {
        if (surfaceTags.empty() || surfaceTags.last() != p)
        {
            surfaceTags.append(p);
        }
    }
    wordList materials(surfaceTags.size());
    Map<label> materialOfPhysical;
    forAll(surfaceTags, m)
    {
        const label p = surfaceTags[m];
        materials[m] =
            surfaceNames_.found(p) ? surfaceNames_[p]
          : word("material" + Foam::name(p));
        materialOfPhysical.set(p, m);
    }

    List<triangleVertices> triangles(triOrder.size());
    labelList triangleMaterials(triOrder.size());
    forAll(triOrder, t)
    {
        const label e = triOrder[t];
        for (label k = 0; k < 3; ++k)
        {
            triangles[t][k] = pointOfTag[triNodes_[e][k]];
        }
        const vector2D a = points[triangles[t][1]] - points[triangles[t][0]];
        const vector2D b = points[triangles[t][2]] - points[triangles[t][0]];
        if (a.x()*b.y() - a.y()*b.x() < 0)
        {
            std::swap(triangles[t][1], triangles[t][2]);
            ++flipped_;
        }
        triangleMaterials[t] = materialOfPhysical[triPhysical_[e]];
    }

    // Boundary edges of the triangles
    EdgeMap<label> edgeCount(3*triangles.size());
    for (const triangleVertices& tri : triangles)
    {
        for (label k = 0; k < 3; ++k)
        {
            ++edgeCount(edge(tri[k], tri[(k + 1) % 3]), 0);
        }
    }

    // Patches: physical curves in order of tag
    const labelList lineOrder(sortedOrder(lineTag_));
    DynamicList<label> curveTags;
    for (const label p : linePhysical_)
    {
        if (p >= 0 && !curveTags.found(p))
        {
            curveTags.append(p);
        }
    }
    Foam::sort(curveTags);
    wordList patchNames(curveTags.size());
    List<DynamicList<edge>> patchEdges(curveTags.size());
    forAll(curveTags, i)
    {
        const label p = curveTags[i];
        patchNames[i] =
            curveNames_.found(p) ? curveNames_[p] : word("patch" + Foam::name(p));
    }
    for (const label e : lineOrder)
    {
        const label p = linePhysical_[e];
        if (p < 0)
        {
            continue;
        }
        const auto a = pointOfTag.cfind(lineNodes_[e][0]);
        const auto b = pointOfTag.cfind(lineNodes_[e][1]);
        if (!a.found() || !b.found())
        {
            ++droppedLines_;        // not on any triangle
            continue;
        }
        const edge ed(*a, *b);
        const auto count = edgeCount.cfind(ed);
        if (count.found() && *count == 2)
        {
            // Inside the mesh: a joint trace if the curve is a joint set
            interiorLines_(patchNames[curveTags.find(p)]).append(ed);
        }
        if (!count.found() || *count != 1)
        {
            ++droppedLines_;        // inside the mesh
            continue;
        }
        patchEdges[curveTags.find(p)].append(ed);
    }
    List<edgeList> patches(patchEdges.size());
    forAll(patches, i)
    {
        patches[i].transfer(patchEdges[i]);
    }

    return triangleMesh
    (
        points, triangles, triangleMaterials, materials, patchNames, patches
    );
}


Foam::List<Foam::triangleJointSet> Foam::gmshReader::jointSets
(
    const dictionary& jointSetsDict
) const
{
    const wordList names = jointSetsDict.toc();
    List<triangleJointSet> sets(names.size());
    forAll(names, i)
    {
        const auto iter = interiorLines_.cfind(names[i]);
        if (!iter.found() || (*iter).empty())
        {
            FatalIOErrorInFunction(jointSetsDict)
                << "joint set '" << names[i] << "': " << name_ << " has no"
                << " physical curve of that name with lines inside the"
                << " triangles (curves with interior lines: "
                << interiorLines_.sortedToc() << ")" << exit(FatalIOError);
        }
        sets[i].name = names[i];
        sets[i].edges = *iter;
        sets[i].properties = jointSetsDict.subDict(names[i]);
    }
    return sets;
}


Foam::triangleMesh Foam::gmshReader::read(const fileName& file)
{
    std::ifstream is(file);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot open gmsh file " << file << exit(FatalError);
    }
    gmshReader reader(is, file);
    return reader.mesh();
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "triangleMesh.H"
#include "Time.H"
#include "IOdictionary.H"
#include "caseChecks.H"
#include "EdgeMap.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(triangleMesh, 0);
}

const Foam::word Foam::triangleMesh::meshFileName("solidMesh");


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

namespace
{
    // Report a mesh error against the dictionary when there is one
    void meshError(const Foam::dictionary* dictPtr, const Foam::string& msg)
    {
        using namespace Foam;
        if (dictPtr)
        {
            FatalIOErrorInFunction(*dictPtr) << msg.c_str() << nl
                << exit(FatalIOError);
        }
        else
        {
            FatalErrorInFunction << msg.c_str() << nl << exit(FatalError);
        }
    }
}


void Foam::triangleMesh::validate(const dictionary* dictPtr) const
{
    const label nPts = points_.size();

    if (triangleMaterials_.size() != triangles_.size())
    {
        meshError
        (
            dictPtr,
            "entry 'triangleMaterials' has " + Foam::name(triangleMaterials_.size())
          + " values for " + Foam::name(triangles_.size()) + " triangles"
        );
    }
    if (materials_.empty())
    {
        meshError(dictPtr, "entry 'materials' is empty");
    }
    forAll(materials_, m)
    {
        if (materials_.find(materials_[m]) != m)
        {
            meshError
            (
                dictPtr,
                "entry 'materials': material '" + materials_[m]
              + "' is listed twice (" + Foam::name(materials_.find(materials_[m]))
              + " and " + Foam::name(m) + "): each name once"
            );
        }
    }
    // Every solver divides by the number and the sizes of the triangles
    if (triangles_.empty())
    {
        meshError
        (
            dictPtr,
            "entry 'triangles' is empty: the solid mesh has no triangles"
            " (e.g. holes covering the solids)"
        );
    }

    forAll(triangles_, t)
    {
        const triangleVertices& tri = triangles_[t];
        for (const label v : tri)
        {
            if (v < 0 || v >= nPts)
            {
                meshError
                (
                    dictPtr,
                    "entry 'triangles': triangle " + Foam::name(t)
                  + " refers to point " + Foam::name(v) + " but there are "
                  + Foam::name(nPts) + " points"
                );
            }
        }
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
        {
            meshError
            (
                dictPtr,
                "entry 'triangles': triangle " + Foam::name(t)
              + " repeats a vertex (degenerate)"
            );
        }
        const scalar a = area(t);
        if (!(a > 0))
        {
            const vector2D& p0 = points_[tri[0]];
            meshError
            (
                dictPtr,
                "entry 'triangles': triangle " + Foam::name(t) + " near ("
              + Foam::name(p0.x()) + " " + Foam::name(p0.y()) + ") has area "
              + Foam::name(a)
              + (a < 0 ? " (inverted: vertices must be counter-clockwise)"
                       : " (degenerate)")
            );
        }
        const label m = triangleMaterials_[t];
        if (m < 0 || m >= materials_.size())
        {
            meshError
            (
                dictPtr,
                "entry 'triangleMaterials': triangle " + Foam::name(t)
              + " has material index " + Foam::name(m) + " but only "
              + Foam::name(materials_.size()) + " materials are listed"
            );
        }
    }

    // Neighbours traversing an edge the same way (duplicate or overlapping
    // triangles) and edges of three or more triangles. jointTopology stops
    // on these too, but only here can the error name the file and entry.
    if (dictPtr)
    {
        EdgeMap<label> firstUse(2*triangles_.size());
        forAll(triangles_, t)
        {
            const triangleVertices& tri = triangles_[t];
            for (label k = 0; k < 3; ++k)
            {
                const label a = tri[k], b = tri[(k + 1) % 3];
                auto iter = firstUse.find(edge(a, b));
                if (!iter.found())
                {
                    firstUse.insert(edge(a, b), 3*t + k);
                    continue;
                }
                const label other = *iter;
                if (other < 0)
                {
                    meshError
                    (
                        dictPtr,
                        "entry 'triangles': Non-manifold edge ("
                      + Foam::name(a) + " " + Foam::name(b) + ") shared by"
                        " three or more triangles, including triangle "
                      + Foam::name(t)
                    );
                }
                const label tOther = other/3;
                if (triangles_[tOther][other % 3] == a)
                {
                    meshError
                    (
                        dictPtr,
                        "entry 'triangles': triangles " + Foam::name(tOther)
                      + " and " + Foam::name(t) + " traverse edge ("
                      + Foam::name(a) + " " + Foam::name(b) + ") in the same"
                        " direction (duplicate or overlapping triangles)"
                    );
                }
                *iter = -1;
            }
        }
    }

    forAll(patchEdges_, patchi)
    {
        for (const edge& e : patchEdges_[patchi])
        {
            if (e[0] < 0 || e[0] >= nPts || e[1] < 0 || e[1] >= nPts)
            {
                meshError
                (
                    dictPtr,
                    "entry 'boundary/" + patchNames_[patchi] + "/edges' refers"
                    " to a point outside 0.." + Foam::name(nPts - 1)
                );
            }
        }
    }
}


void Foam::triangleMesh::validateJointSets(const dictionary* dictPtr) const
{
    if (jointSets_.empty()) return;
    EdgeMap<label> meshEdge(3*triangles_.size());
    for (const triangleVertices& tri : triangles_)
    {
        for (label k = 0; k < 3; ++k)
        {
            meshEdge.set(edge(tri[k], tri[(k + 1) % 3]), 0);
        }
    }
    for (const triangleJointSet& js : jointSets_)
    {
        const string where = "entry 'jointSets/" + js.name + "/";
        forAll(js.edges, i)
        {
            if (!meshEdge.found(js.edges[i]))
            {
                meshError
                (
                    dictPtr,
                    where + "edges': edge " + Foam::name(i) + " ("
                  + Foam::name(js.edges[i][0]) + " "
                  + Foam::name(js.edges[i][1]) + ") is not an edge of a"
                    " triangle"
                );
            }
        }
        const bool sizesOk =
            (js.strengthFactor.empty()
          || js.strengthFactor.size() == js.edges.size())
         && (js.frictionAngle.empty()
          || js.frictionAngle.size() == js.edges.size());
        if (!sizesOk)
        {
            meshError
            (
                dictPtr,
                where + "strengthFactor' and 'edgeFrictionAngle' must be"
                " empty or have one value per edge ("
              + Foam::name(js.edges.size()) + ")"
            );
        }
        for (const scalar w : js.strengthFactor)
        {
            if (!(w > 0))
            {
                meshError(dictPtr, where + "strengthFactor': values must be"
                    " positive, got " + Foam::name(w));
            }
        }
        for (const scalar phi : js.frictionAngle)
        {
            if (!(phi >= 0 && phi < 90))
            {
                meshError(dictPtr, where + "edgeFrictionAngle': values must"
                    " lie in [0, 90) degrees, got " + Foam::name(phi));
            }
        }
    }
}


void Foam::triangleMesh::readJointSets(const dictionary& dict)
{
    const dictionary* jPtr = dict.findDict("jointSets");
    if (!jPtr) return;
    const wordList names = jPtr->toc();
    jointSets_.setSize(names.size());
    forAll(names, i)
    {
        const dictionary& d = jPtr->subDict(names[i]);
        triangleJointSet& js = jointSets_[i];
        js.name = names[i];
        js.edges = d.get<edgeList>("edges");
        js.strengthFactor =
            d.getOrDefault<scalarList>("strengthFactor", scalarList());
        js.frictionAngle =
            d.getOrDefault<scalarList>("edgeFrictionAngle", scalarList());
        js.properties = d;
        js.properties.remove("edges");
        js.properties.remove("strengthFactor");
        js.properties.remove("edgeFrictionAngle");
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::triangleMesh::triangleMesh
(
    const List<vector2D>& points,
    const List<triangleVertices>& triangles,
    const labelList& triangleMaterials,
    const wordList& materials,
    const wordList& patchNames,
    const List<edgeList>& patchEdges
)
:
    points_(points),
    triangles_(triangles),
    triangleMaterials_(triangleMaterials),
    materials_(materials),
    patchNames_(patchNames),
    patchEdges_(patchEdges)
{
    validate(nullptr);
}


Foam::triangleMesh::triangleMesh(const dictionary& dict)
:
    points_(dict.get<List<vector2D>>("points")),
    triangles_(dict.get<List<triangleVertices>>("triangles")),
    triangleMaterials_(dict.get<labelList>("triangleMaterials")),
    materials_(dict.get<wordList>("materials"))
{
    const dictionary& bdict = dict.subDict("boundary");
    patchNames_ = bdict.toc();
    patchEdges_.setSize(patchNames_.size());
    forAll(patchNames_, patchi)
    {
        patchEdges_[patchi] =
            bdict.subDict(patchNames_[patchi]).get<edgeList>("edges");
    }
    validate(&dict);
    readJointSets(dict);
    validateJointSets(&dict);
}


Foam::triangleMesh Foam::triangleMesh::New(const Time& runTime)
{
    IOdictionary dict
    (
        IOobject
        (
            meshFileName,
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    caseChecks::checkInput(dict);
    return triangleMesh(dict);
}


Foam::triangleMesh Foam::triangleMesh::rectangle
(
    const vector2D& origin,
    const vector2D& size,
    const label nx,
    const label ny,
    const word& material
)
{
    List<vector2D> points((nx + 1)*(ny + 1));
    auto pointIndex = [nx](label i, label j) { return j*(nx + 1) + i; };
    for (label j = 0; j <= ny; ++j)
    {
        for (label i = 0; i <= nx; ++i)
        {
            points[pointIndex(i, j)] = vector2D
            (
                origin.x() + size.x()*i/nx,
                origin.y() + size.y()*j/ny
            );
        }
    }

    // Alternate the diagonal so that the mesh has no preferred direction
    List<triangleVertices> triangles(2*nx*ny);
    label t = 0;
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const label a = pointIndex(i, j), b = pointIndex(i + 1, j);
            const label c = pointIndex(i + 1, j + 1), d = pointIndex(i, j + 1);
            if ((i + j) % 2 == 0)
            {
                triangles[t++] = triangleVertices({a, b, c});
                triangles[t++] = triangleVertices({a, c, d});
            }
            else
            {
                triangles[t++] = triangleVertices({a, b, d});
                triangles[t++] = triangleVertices({b, c, d});
            }
        }
    }

    wordList patchNames({"left", "right", "bottom", "top"});
    List<edgeList> patchEdges(4);
    patchEdges[0].setSize(ny);
    patchEdges[1].setSize(ny);
    for (label j = 0; j < ny; ++j)
    {
        patchEdges[0][j] = edge(pointIndex(0, j + 1), pointIndex(0, j));
        patchEdges[1][j] = edge(pointIndex(nx, j), pointIndex(nx, j + 1));
    }
    patchEdges[2].setSize(nx);
    patchEdges[3].setSize(nx);
    for (label i = 0; i < nx; ++i)
    {
        patchEdges[2][i] = edge(pointIndex(i, 0), pointIndex(i + 1, 0));
        patchEdges[3][i] = edge(pointIndex(i + 1, ny), pointIndex(i, ny));
    }

    return triangleMesh
    (
        points,
        triangles,
        labelList(triangles.size(), Zero),
        wordList({material}),
        patchNames,
        patchEdges
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::triangleMesh::area(const label t) const
{
    const triangleVertices& tri = triangles_[t];
    const vector2D e1 = points_[tri[1]] - points_[tri[0]];
    const vector2D e2 = points_[tri[2]] - points_[tri[0]];
    return 0.5*(e1.x()*e2.y() - e1.y()*e2.x());
}


Foam::scalarList Foam::triangleMesh::areas() const
{
    scalarList result(triangles_.size());
    forAll(result, t)
    {
        result[t] = area(t);
    }
    return result;
}


void Foam::triangleMesh::setJointSets(const List<triangleJointSet>& sets)
{
    jointSets_ = sets;
    validateJointSets(nullptr);
}


Foam::label Foam::triangleMesh::findPatch(const word& name) const
{
    return patchNames_.find(name);
}


Foam::dictionary Foam::triangleMesh::toDict() const
{
    // Entries are stored as tokens printed with the default precision (6
    // digits): print the points with enough digits to read back exactly
    const unsigned oldPrecision = IOstream::defaultPrecision();
    IOstream::defaultPrecision(max(oldPrecision, 17u));

    dictionary dict;
    dict.add("materials", materials_);
    dict.add("points", points_);
    dict.add("triangles", triangles_);
    dict.add("triangleMaterials", triangleMaterials_);
    dictionary bdict;
    forAll(patchNames_, patchi)
    {
        dictionary pdict;
        pdict.add("edges", patchEdges_[patchi]);
        bdict.add(patchNames_[patchi], pdict);
    }
    dict.add("boundary", bdict);
    if (!jointSets_.empty())
    {
        dictionary jdict;
        for (const triangleJointSet& js : jointSets_)
        {
            dictionary sdict(js.properties);
            sdict.add("edges", js.edges);
            if (!js.strengthFactor.empty())
            {
                sdict.add("strengthFactor", js.strengthFactor);
            }
            if (!js.frictionAngle.empty())
            {
                sdict.add("edgeFrictionAngle", js.frictionAngle);
            }
            jdict.add(js.name, sdict);
        }
        dict.add("jointSets", jdict);
    }

    IOstream::defaultPrecision(oldPrecision);
    return dict;
}


void Foam::triangleMesh::write
(
    const Time& runTime,
    IOstream::streamFormat fmt
) const
{
    IOdictionary dict
    (
        IOobject
        (
            meshFileName,
            runTime.constant(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        toDict()
    );
    // Enough digits for the points to read back exactly (the default of
    // 6 would move points, and could make thin triangles inverted)
    const unsigned oldPrecision = IOstream::defaultPrecision();
    IOstream::defaultPrecision(max(oldPrecision, 17u));
    // ASCII always: OpenFOAM v1912 cannot read binary lists back from
    // dictionary entries (ITstream::readRaw is not implemented)
    if (fmt == IOstream::BINARY)
    {
        WarningInFunction
            << "constant/" << meshFileName << " is written in ascii: binary"
            << " dictionary entries cannot be read back" << endl;
    }
    dict.writeObject
    (
        IOstream::ASCII, IOstream::currentVersion, IOstream::UNCOMPRESSED, true
    );
    IOstream::defaultPrecision(oldPrecision);
}


// ************************************************************************* //

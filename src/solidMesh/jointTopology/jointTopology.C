/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "jointTopology.H"
#include "EdgeMap.H"
#include "DynamicList.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::jointTopology::jointTopology(const triangleMesh& mesh)
:
    nTriangles_(mesh.nTriangles()),
    edgeJoint_(3*mesh.nTriangles(), -1),
    nodeVertex_(3*mesh.nTriangles()),
    initialPoints_(mesh.points())
{
    const List<triangleVertices>& tris = mesh.triangles();
    forAll(tris, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            nodeVertex_[node(t, k)] = tris[t][k];
        }
    }

    // First triangle edge (3t + k) seen on each continuous edge
    EdgeMap<label> firstEdge(3*tris.size());

    DynamicList<label> triA(3*tris.size()/2), edgA(3*tris.size()/2);
    DynamicList<label> triB(3*tris.size()/2), edgB(3*tris.size()/2);

    forAll(tris, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            const label a = tris[t][k], b = tris[t][(k + 1) % 3];
            const edge e(a, b);
            auto iter = firstEdge.find(e);
            if (!iter.found())
            {
                firstEdge.insert(e, 3*t + k);
                continue;
            }
            const label other = *iter;
            if (other < 0)
            {
                FatalErrorInFunction
                    << "Non-manifold edge (" << a << ' ' << b
                    << ") shared by three or more triangles, including triangle "
                    << t << exit(FatalError);
            }
            const label tOther = other/3, kOther = other % 3;
            if (tris[tOther][kOther] == a)
            {
                FatalErrorInFunction
                    << "Triangles " << tOther << " and " << t
                    << " overlap: they traverse edge (" << a << ' ' << b
                    << ") in the same direction" << exit(FatalError);
            }
            edgeJoint_[other] = triA.size();
            edgeJoint_[3*t + k] = triA.size();
            triA.append(tOther);
            edgA.append(kOther);
            triB.append(t);
            edgB.append(k);
            *iter = -1 - other;
        }
    }

    jointTriangleA_.transfer(triA);
    jointEdgeA_.transfer(edgA);
    jointTriangleB_.transfer(triB);
    jointEdgeB_.transfer(edgB);

    jointNodes_.setSize(jointTriangleA_.size());
    forAll(jointNodes_, j)
    {
        const label tA = jointTriangleA_[j], kA = jointEdgeA_[j];
        const label tB = jointTriangleB_[j], kB = jointEdgeB_[j];
        // Edge kB of B runs the other way: its end is where p0 started
        jointNodes_[j] = jointNodeList
        ({
            node(tA, kA), node(tA, (kA + 1) % 3),
            node(tB, (kB + 1) % 3), node(tB, kB)
        });
    }

    // Boundary faces, with their patch
    DynamicList<label> bTri, bEdge, bPatch;
    forAll(edgeJoint_, i)
    {
        if (edgeJoint_[i] < 0)
        {
            bTri.append(i/3);
            bEdge.append(i % 3);
            bPatch.append(-1);
        }
    }
    boundaryTriangle_.transfer(bTri);
    boundaryEdge_.transfer(bEdge);
    boundaryPatch_.transfer(bPatch);

    labelList boundaryFaceOfEdge(3*nTriangles_, -1);
    forAll(boundaryTriangle_, f)
    {
        boundaryFaceOfEdge[3*boundaryTriangle_[f] + boundaryEdge_[f]] = f;
    }
    forAll(mesh.patchEdges(), patchi)
    {
        for (const edge& e : mesh.patchEdges()[patchi])
        {
            auto iter = firstEdge.cfind(e);
            const label f =
                (iter.found() && *iter >= 0) ? boundaryFaceOfEdge[*iter] : -1;
            if (f < 0)
            {
                FatalErrorInFunction
                    << "Edge (" << e[0] << ' ' << e[1] << ") of patch "
                    << mesh.patchNames()[patchi]
                    << " is not a boundary edge of the solid mesh"
                    << " (entry 'boundary." << mesh.patchNames()[patchi]
                    << ".edges' of constant/" << triangleMesh::meshFileName
                    << ')' << exit(FatalError);
            }
            boundaryPatch_[f] = patchi;
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vector2D> Foam::jointTopology::nodePositions
(
    const triangleMesh& mesh
)
{
    List<vector2D> positions(3*mesh.nTriangles());
    forAll(mesh.triangles(), t)
    {
        for (label k = 0; k < 3; ++k)
        {
            positions[node(t, k)] = mesh.points()[mesh.triangles()[t][k]];
        }
    }
    return positions;
}


// ************************************************************************* //

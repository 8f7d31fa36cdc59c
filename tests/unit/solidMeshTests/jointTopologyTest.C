// Joint topology of the discontinuous FEMDEM mesh built from a continuous one
#include <gtest/gtest.h>
#include "jointTopology.H"

using namespace Foam;

TEST(jointTopology, rectangleCounts)
{
    const label nx = 7, ny = 5;
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), nx, ny);
    const jointTopology topo(mesh);

    // Euler: edges = horizontal + vertical + diagonals
    const label nEdges = nx*(ny + 1) + ny*(nx + 1) + nx*ny;
    const label nBoundary = 2*(nx + ny);
    EXPECT_EQ(topo.nTriangles(), 2*nx*ny);
    EXPECT_EQ(topo.nJoints(), nEdges - nBoundary);
    EXPECT_EQ(topo.nBoundaryFaces(), nBoundary);
    RecordProperty("joints", topo.nJoints());

    // Every boundary face lies in a named patch
    for (const label p : topo.boundaryPatch())
    {
        EXPECT_GE(p, 0);
    }
}

TEST(jointTopology, jointNodesCoincideAndFaceEachOther)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 4, 3);
    const jointTopology topo(mesh);
    const List<vector2D> x = jointTopology::nodePositions(mesh);

    forAll(topo.jointNodes(), j)
    {
        const jointNodeList& n = topo.jointNodes()[j];
        EXPECT_EQ(x[n[0]], x[n[2]]) << "joint " << j;
        EXPECT_EQ(x[n[1]], x[n[3]]) << "joint " << j;

        // B lies on the side the normal (dy, -dx) points to
        const vector2D d = x[n[1]] - x[n[0]];
        const vector2D normal(d.y(), -d.x());
        const label tB = topo.jointTriangleB()[j];
        vector2D centroidB(Zero);
        for (label k = 0; k < 3; ++k)
        {
            centroidB += x[jointTopology::node(tB, k)]/3.0;
        }
        EXPECT_GT((centroidB - x[n[0]]) & normal, 0) << "joint " << j;
    }
}

TEST(jointTopology, rejectsNonManifoldEdge)
{
    // Three triangles on edge (0 1)
    List<vector2D> pts({{0, 0}, {1, 0}, {0.5, 1}, {0.5, -1}, {0.6, -2}});
    List<triangleVertices> tris
    ({
        triangleVertices({0, 1, 2}),
        triangleVertices({1, 0, 3}),
        triangleVertices({1, 0, 4})
    });
    const triangleMesh mesh(pts, tris, labelList(3, Zero), wordList({"rock"}));
    EXPECT_THROW(jointTopology topo(mesh), Foam::error);
}

// Mesh checks with spatial hashing against brute force; METIS renumbering
#include <gtest/gtest.h>
#include <random>
#include <set>
#include "solidMeshQuality.H"
#include "solidMeshRenumber.H"
#include "jointTopology.H"

using namespace Foam;

namespace
{
// Random triangles: some overlap, some points coincide
triangleMesh randomSoup(label n, unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1), s(0.01, 0.08);
    List<vector2D> pts(3*n + n/10);
    List<triangleVertices> tris(n);
    for (label t = 0; t < n; ++t)
    {
        const vector2D c(u(gen), u(gen));
        const double r = s(gen), a = 6.28*u(gen);
        for (label k = 0; k < 3; ++k)
        {
            pts[3*t + k] = c + r*vector2D(Foam::cos(a + 2.09*k), Foam::sin(a + 2.09*k));
        }
        tris[t] = triangleVertices({3*t, 3*t + 1, 3*t + 2});
    }
    // A few exact duplicates (points used by no triangle)
    for (label i = 0; i < n/10; ++i) pts[3*n + i] = pts[3*i + 1];
    return triangleMesh(pts, tris, labelList(n, Zero), wordList({"rock"}));
}

bool overlapBrute(const triangleMesh& m, label a, label b)
{
    // Separating axis, no tolerance
    vector2D p[3], q[3];
    for (label k = 0; k < 3; ++k)
    {
        p[k] = m.points()[m.triangles()[a][k]];
        q[k] = m.points()[m.triangles()[b][k]];
    }
    for (int side = 0; side < 2; ++side)
    {
        const vector2D* s = side ? q : p;
        for (int k = 0; k < 3; ++k)
        {
            const vector2D d = s[(k + 1) % 3] - s[k];
            const vector2D nrm(-d.y(), d.x());
            double p0 = 1e300, p1 = -1e300, q0 = 1e300, q1 = -1e300;
            for (int i = 0; i < 3; ++i)
            {
                p0 = min(p0, p[i] & nrm); p1 = max(p1, p[i] & nrm);
                q0 = min(q0, q[i] & nrm); q1 = max(q1, q[i] & nrm);
            }
            if (p1 <= q0 || q1 <= p0) return false;
        }
    }
    return true;
}
} // End anonymous namespace


TEST(solidMeshQuality, hashedChecksEqualBruteForce)
{
    const triangleMesh mesh = randomSoup(400, 3);
    std::set<std::pair<label, label>> over, dup;
    for (label a = 0; a < mesh.nTriangles(); ++a)
        for (label b = a + 1; b < mesh.nTriangles(); ++b)
            if (overlapBrute(mesh, a, b)) over.emplace(a, b);
    for (label a = 0; a < mesh.nPoints(); ++a)
        for (label b = a + 1; b < mesh.nPoints(); ++b)
            if (mag(mesh.points()[a] - mesh.points()[b]) <= 1e-9) dup.emplace(a, b);

    std::set<std::pair<label, label>> hashedOver, hashedDup;
    for (const labelPair& p : solidMeshQuality::overlappingTriangles(mesh, 0))
        hashedOver.emplace(p.first(), p.second());
    for (const labelPair& p : solidMeshQuality::duplicatePoints(mesh, 1e-9))
        hashedDup.emplace(p.first(), p.second());
    EXPECT_EQ(hashedOver, over);
    EXPECT_EQ(hashedDup, dup);
    EXPECT_GT(over.size(), 10u);
    EXPECT_GE(dup.size(), 40u);
    RecordProperty("overlappingPairs", int(over.size()));

    // A proper mesh has neither; its smallest angle and radius ratio are known
    const triangleMesh rect = triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 10, 10);
    EXPECT_TRUE(solidMeshQuality::overlappingTriangles(rect).empty());
    EXPECT_TRUE(solidMeshQuality::duplicatePoints(rect, 1e-6).empty());
    EXPECT_TRUE(solidMeshQuality::badTriangles(rect).empty());
    EXPECT_NEAR(gMin(solidMeshQuality::minAngles(rect)), 45, 1e-9);
    // Right isosceles triangle: 2 r_in / R = 2(sqrt2 - 1)
    EXPECT_NEAR(gMin(solidMeshQuality::radiusRatios(rect)), 2*(std::sqrt(2.0) - 1), 1e-12);

    // Time step: altitude of the right triangle (h/sqrt2) over the P wave speed
    solidMeshQuality::elasticProperties p{10e9, 0.25, 2500, 0};
    const scalar c = std::sqrt(10e9*0.75/(2500*1.25*0.5));
    EXPECT_NEAR(solidMeshQuality::pWaveSpeed(p), c, 1e-9*c);
    label t = -1;
    const scalar dt = solidMeshQuality::stableTimeStep(rect, List<solidMeshQuality::elasticProperties>(1, p), t);
    EXPECT_NEAR(dt, 0.1/std::sqrt(2.0)/c, 1e-12*dt);
}


TEST(solidMeshRenumber, metisOrderKeepsTheMeshAndImprovesLocality)
{
    // A rectangle with its triangles shuffled
    const triangleMesh rect = triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 60, 30);
    labelList shuffle(identity(rect.nTriangles()));
    std::mt19937 gen(1);
    std::shuffle(shuffle.begin(), shuffle.end(), gen);
    const triangleMesh shuffled = solidMeshRenumber::reorder(rect, shuffle);
    const triangleMesh renumbered = solidMeshRenumber::renumber(shuffled);

    // Same triangles (as point sets), materials, areas, patch lengths
    auto signature = [](const triangleMesh& m)
    {
        std::multiset<std::vector<double>> s;
        forAll(m.triangles(), t)
        {
            std::vector<double> v;
            for (const label p : m.triangles()[t]) { v.push_back(m.points()[p].x()); v.push_back(m.points()[p].y()); }
            v.push_back(m.area(t));
            s.insert(v);
        }
        return s;
    };
    EXPECT_EQ(signature(renumbered), signature(rect));
    const jointTopology topo(renumbered);
    EXPECT_EQ(topo.nJoints(), jointTopology(rect).nJoints());
    for (const label p : topo.boundaryPatch()) EXPECT_GE(p, 0);

    const scalar fShuffled = solidMeshRenumber::localNeighbourFraction(shuffled);
    const scalar fMetis = solidMeshRenumber::localNeighbourFraction(renumbered);
    const scalar fRect = solidMeshRenumber::localNeighbourFraction(rect);
    RecordProperty("localNeighboursShuffled", std::to_string(fShuffled));
    RecordProperty("localNeighboursRowByRow", std::to_string(fRect));
    RecordProperty("localNeighboursMetis", std::to_string(fMetis));
    EXPECT_LT(fShuffled, 0.05);
    EXPECT_GT(fMetis, 0.85);
}

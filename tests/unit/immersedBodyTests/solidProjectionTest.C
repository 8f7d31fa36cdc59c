// Exact projection of triangles onto fluid cells, and the transposed force
// distribution, checked against closed-form areas, moments and momenta
#include <gtest/gtest.h>
#include "solidProjection.H"
#include "triangleMesh.H"
#include "Random.H"
#include "immersedBodyTestTools.H"

using namespace Foam;

namespace
{
    using immersedBodyTestTools::sci;

    // A grid of nx*ny jittered (still convex) quadrilaterals over [0,1]^2
    std::pair<List<vector2D>, labelList> jitteredGrid(label nx, label ny)
    {
        Random rnd(1234);
        List<vector2D> nodes((nx + 1)*(ny + 1));
        for (label j = 0; j <= ny; ++j)
        {
            for (label i = 0; i <= nx; ++i)
            {
                vector2D p(scalar(i)/nx, scalar(j)/ny);
                if (i > 0 && i < nx && j > 0 && j < ny)
                {
                    p += 0.2*vector2D(rnd.sample01<scalar>() - 0.5,
                                      rnd.sample01<scalar>() - 0.5)/nx;
                }
                nodes[j*(nx + 1) + i] = p;
            }
        }
        std::pair<List<vector2D>, labelList> grid;
        grid.first.setSize(4*nx*ny);
        grid.second.setSize(nx*ny + 1);
        label k = 0;
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                grid.second[j*nx + i] = k;
                grid.first[k++] = nodes[j*(nx + 1) + i];
                grid.first[k++] = nodes[j*(nx + 1) + i + 1];
                grid.first[k++] = nodes[(j + 1)*(nx + 1) + i + 1];
                grid.first[k++] = nodes[(j + 1)*(nx + 1) + i];
            }
        }
        grid.second[nx*ny] = k;
        return grid;
    }

    // A triangulated rectangle rotated by angle about its centre, inside [0,1]^2
    List<vector2D> rotatedPoints(const triangleMesh& m, scalar angle, vector2D centre)
    {
        List<vector2D> pts(m.points());
        const scalar c = Foam::cos(angle), s = Foam::sin(angle);
        for (vector2D& p : pts)
        {
            const vector2D r = p - centre;
            p = centre + vector2D(c*r.x() - s*r.y(), s*r.x() + c*r.y());
        }
        return pts;
    }
}


TEST(solidProjection, areaAndRigidMomentumAreExact)
{
    solidProjection projection(jitteredGrid(37, 29));
    const triangleMesh solid = triangleMesh::rectangle
    (
        vector2D(0.3, 0.35), vector2D(0.4, 0.25), 13, 9
    );
    const vector2D centre(0.5, 0.475);
    const List<vector2D> pts = rotatedPoints(solid, 0.4, centre);

    // Rigid motion: translation V plus rotation omega about the origin
    const vector2D V(3, -2);
    const scalar omega = 7;
    List<vector2D> vel(pts.size());
    forAll(pts, i)
    {
        vel[i] = V + omega*vector2D(-pts[i].y(), pts[i].x());
    }

    scalarField alpha;
    List<vector2D> Us;
    projection.project(pts, solid.triangles(), vel, alpha, Us);

    scalar area = 0;
    vector2D momentum(Zero);
    forAll(alpha, c)
    {
        EXPECT_GE(alpha[c], 0);
        EXPECT_LE(alpha[c], 1);
        area += alpha[c]*projection.cellArea()[c];
        momentum += alpha[c]*projection.cellArea()[c]*Us[c];
    }
    const scalar exactArea = 0.4*0.25;
    // First moment of the solid = area * centroid (the rotation centre)
    const vector2D exactMomentum = exactArea*(V + omega*vector2D(-centre.y(), centre.x()));

    const scalar areaError = mag(area - exactArea)/exactArea;
    const scalar momentumError = mag(momentum - exactMomentum)/mag(exactMomentum);
    RecordProperty("areaError", sci(areaError));
    RecordProperty("momentumError", sci(momentumError));
    RecordProperty("overlaps", projection.nOverlaps());
    EXPECT_LT(areaError, 1e-12);
    EXPECT_LT(momentumError, 1e-12);
}


TEST(solidProjection, fullyCoveredCellsHaveAlphaOne)
{
    solidProjection projection(jitteredGrid(10, 10));
    // Two triangles covering [0,1]^2 entirely
    List<vector2D> pts({{-0.1, -0.1}, {1.1, -0.1}, {1.1, 1.1}, {-0.1, 1.1}});
    List<FixedList<label, 3>> tris
    ({
        FixedList<label, 3>({0, 1, 2}),
        FixedList<label, 3>({0, 2, 3})
    });
    List<vector2D> vel(4, vector2D(1, 2));
    scalarField alpha;
    List<vector2D> Us;
    projection.project(pts, tris, vel, alpha, Us);
    scalar worst = 0;
    forAll(alpha, c)
    {
        worst = max(worst, mag(alpha[c] - 1));
        EXPECT_LT(mag(Us[c] - vector2D(1, 2)), 1e-12);
    }
    RecordProperty("maxAlphaError", sci(worst));
    EXPECT_LT(worst, 1e-12);
}


TEST(solidProjection, forceDistributionConservesForce)
{
    solidProjection projection(jitteredGrid(23, 19));
    const triangleMesh solid = triangleMesh::rectangle
    (
        vector2D(0.2, 0.3), vector2D(0.5, 0.3), 8, 6
    );
    const List<vector2D> pts = rotatedPoints(solid, -0.7, vector2D(0.45, 0.45));
    scalarField alpha;
    List<vector2D> Us;
    projection.project(pts, solid.triangles(), List<vector2D>(pts.size(), Zero), alpha, Us);

    // A force in every cell; only the solid part of each cell is loaded
    List<vector2D> cellForce(projection.nCells());
    forAll(cellForce, c)
    {
        cellForce[c] = vector2D(Foam::sin(3.0*c), Foam::cos(5.0*c));
    }
    List<vector2D> pointForce(pts.size(), Zero);
    projection.distributeToPoints(cellForce, alpha, pts, solid.triangles(), pointForce);

    vector2D applied(Zero), received(Zero);
    forAll(alpha, c)
    {
        if (alpha[c] > 0) { applied += cellForce[c]; }
    }
    for (const vector2D& f : pointForce) { received += f; }
    const scalar forceError = mag(received - applied)/mag(applied);
    RecordProperty("forceError", sci(forceError));
    EXPECT_LT(forceError, 1e-12);
}


TEST(solidProjection, findCellAgreesWithBruteForce)
{
    // Random points against a scan of every (convex) cell; outside -> -1
    const auto grid = jitteredGrid(17, 13);
    solidProjection projection(grid);
    auto inside = [&](label c, const vector2D& p)
    {
        const label s = grid.second[c], e = grid.second[c + 1];
        for (label k = s; k < e; ++k)
        {
            const vector2D ab = grid.first[k + 1 < e ? k + 1 : s] - grid.first[k];
            const vector2D ap = p - grid.first[k];
            if (ab.x()*ap.y() - ab.y()*ap.x() < 0) return false;
        }
        return true;
    };
    Random rnd(99);
    label mismatches = 0, outside = 0;
    for (label n = 0; n < 2000; ++n)
    {
        const vector2D p(1.2*rnd.sample01<scalar>() - 0.1, 1.2*rnd.sample01<scalar>() - 0.1);
        label expected = -1;
        for (label c = 0; c < projection.nCells() && expected < 0; ++c)
        {
            if (inside(c, p)) expected = c;
        }
        outside += expected < 0;
        mismatches += projection.findCell(p) != expected;
    }
    EXPECT_EQ(projection.findCell(vector2D(GREAT, -GREAT)), -1);
    RecordProperty("pointsOutside", std::to_string(outside));
    EXPECT_GT(outside, 100);
    EXPECT_EQ(mismatches, 0);
}

// Exact projection of triangles onto fluid cells, and the transposed force
// distribution, checked against closed-form areas, moments and momenta
#include <gtest/gtest.h>
#include "solidProjection.H"
#include "polygonClipping.H"
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


TEST(solidProjection, overlapsOfACrackGapAreTheClippedAreas)
{
    // Thin sheared quadrilaterals (a crack gap p0 q0 q1 p1: length 0.02 to
    // 0.2, opening 1e-4 to 1e-2, any direction) on a jittered grid: the
    // cells and areas overlapsOf finds against clipping every cell (brute
    // force), and the areas' sum against the quadrilateral's area
    const auto grid = jitteredGrid(17, 13);
    solidProjection projection(grid);
    Random rnd(7);
    scalar worstSum = 0, worstCell = 0;
    label missed = 0, nOverlaps = 0;
    DynamicList<vector2D> clipped, work;
    for (label n = 0; n < 200; ++n)
    {
        const vector2D c(0.2 + 0.6*rnd.sample01<scalar>(), 0.2 + 0.6*rnd.sample01<scalar>());
        const scalar angle = 6.283185307179586*rnd.sample01<scalar>();
        const scalar L = 0.02 + 0.18*rnd.sample01<scalar>();
        const scalar g = Foam::pow(10, -4 + 2*rnd.sample01<scalar>());
        const vector2D t(Foam::cos(angle), Foam::sin(angle)), nrm(t.y(), -t.x());
        const vector2D shear = (rnd.sample01<scalar>() - 0.5)*g*t;
        const vector2D p0 = c - 0.5*L*t, p1 = c + 0.5*L*t;
        const List<vector2D> gap({p0, p0 + g*nrm + shear, p1 + g*nrm + shear, p1});
        DynamicList<label> cells;
        DynamicList<scalar> areas;
        projection.overlapsOf(gap, cells, areas);
        nOverlaps += cells.size();
        const scalar exact = L*g;
        worstSum = max(worstSum, mag(sum(areas)/exact - 1));
        for (label ci = 0; ci < projection.nCells(); ++ci)
        {
            clipped = gap;
            const label s = grid.second[ci];
            polygonClipping::clipConvex
            (
                clipped, &grid.first[s], grid.second[ci + 1] - s, work
            );
            scalar a = 0;
            vector2D centroid;
            if (clipped.size() >= 3)
            {
                polygonClipping::areaAndCentroid(clipped, a, centroid);
            }
            const label k = cells.find(ci);
            if (a > 1e-14*exact && k < 0) ++missed;
            if (k >= 0) worstCell = max(worstCell, mag(areas[k] - a)/exact);
        }
    }
    RecordProperty("gapCellOverlaps", std::to_string(nOverlaps));
    RecordProperty("worstAreaSumError", sci(worstSum));
    RecordProperty("worstCellAreaError", sci(worstCell));
    EXPECT_EQ(missed, 0);
    EXPECT_GT(nOverlaps, 400);
    EXPECT_LT(worstSum, 1e-11);
    EXPECT_LT(worstCell, 1e-14);
}

// Time-averaged face apertures of a moving solid: exact covered lengths,
// the geometric conservation law for translations (every cell's swept gas
// area equals minus the open face vectors dotted with the displacement),
// and the event-based time integration against fine sampling
#include <gtest/gtest.h>
#include "faceApertures.H"
#include "solidProjection.H"
#include "outlineRegions.H"
#include "triangleMesh.H"
#include "Random.H"
#include "clockValue.H"
#include <map>
#include <functional>
#include "immersedBodyTestTools.H"

using namespace Foam;

namespace
{
    using immersedBodyTestTools::sci;

    // Jittered quadrilateral grid over [0,1]^2: cell polygons (CSR) and the
    // faces (segments oriented counter-clockwise for their first cell, the
    // owner) with owner and neighbour (-1 on the boundary)
    struct grid
    {
        std::pair<List<vector2D>, labelList> cells;
        List<vector2D> start, end;
        labelList owner, neighbour;
    };

    grid jitteredGrid(label nx, label ny, scalar jitter = 0.2, scalar extent = 1)
    {
        Random rnd(4321);
        List<vector2D> nodes((nx + 1)*(ny + 1));
        for (label j = 0; j <= ny; ++j)
        {
            for (label i = 0; i <= nx; ++i)
            {
                vector2D p(extent*i/nx, extent*j/ny);
                if (i > 0 && i < nx && j > 0 && j < ny)
                {
                    p += extent*jitter*vector2D(rnd.sample01<scalar>() - 0.5,
                                         rnd.sample01<scalar>() - 0.5)/nx;
                }
                nodes[j*(nx + 1) + i] = p;
            }
        }
        grid g;
        g.cells.first.setSize(4*nx*ny);
        g.cells.second.setSize(nx*ny + 1);
        std::map<std::pair<label, label>, label> faceOf;
        DynamicList<vector2D> s, e;
        DynamicList<label> own, nei;
        label k = 0;
        for (label j = 0; j < ny; ++j)
        {
            for (label i = 0; i < nx; ++i)
            {
                const label c = j*nx + i;
                const label n[4] =
                {
                    j*(nx + 1) + i, j*(nx + 1) + i + 1,
                    (j + 1)*(nx + 1) + i + 1, (j + 1)*(nx + 1) + i
                };
                g.cells.second[c] = k;
                for (label v = 0; v < 4; ++v)
                {
                    g.cells.first[k++] = nodes[n[v]];
                    const label a = n[v], b = n[(v + 1) % 4];
                    const auto key = std::make_pair(min(a, b), max(a, b));
                    auto it = faceOf.find(key);
                    if (it == faceOf.end())
                    {
                        faceOf[key] = s.size();
                        s.append(nodes[a]);
                        e.append(nodes[b]);
                        own.append(c);
                        nei.append(-1);
                    }
                    else
                    {
                        nei[it->second] = c;
                    }
                }
            }
        }
        g.cells.second[nx*ny] = k;
        g.start.transfer(s);
        g.end.transfer(e);
        g.owner.transfer(own);
        g.neighbour.transfer(nei);
        return g;
    }

    List<vector2D> rigidMotion
    (
        const UList<vector2D>& pts, const scalar angle, const vector2D& centre,
        const vector2D& shift
    )
    {
        List<vector2D> out(pts.size());
        const scalar c = Foam::cos(angle), s = Foam::sin(angle);
        forAll(pts, i)
        {
            const vector2D r = pts[i] - centre;
            out[i] = centre + shift + vector2D(c*r.x() - s*r.y(), s*r.x() + c*r.y());
        }
        return out;
    }

    // Gas area per cell: cell area minus the projected solid area
    scalarField gasArea
    (
        solidProjection& proj, const UList<vector2D>& pts,
        const UList<FixedList<label, 3>>& tris
    )
    {
        scalarField alpha;
        List<vector2D> Us;
        proj.project(pts, tris, List<vector2D>(pts.size(), Zero), alpha, Us);
        return (1 - alpha)*proj.cellArea();
    }
}


TEST(faceApertures, coveredLengthOfASegmentInATriangle)
{
    // Triangle (0,0) (2,0) (0,2): the segment y = 0.5 from x = -1 to 3 is
    // inside for x in [0, 1.5]; either orientation of the triangle
    const vector2D a(0, 0), b(2, 0), c(0, 2);
    const scalar l1 = faceApertures::coveredLength({-1, 0.5}, {3, 0.5}, a, b, c);
    const scalar l2 = faceApertures::coveredLength({3, 0.5}, {-1, 0.5}, a, c, b);
    const scalar l3 = faceApertures::coveredLength({-1, 3}, {3, 3}, a, b, c);
    RecordProperty("covered", sci(l1));
    EXPECT_NEAR(l1, 1.5, 1e-15);
    EXPECT_NEAR(l2, 1.5, 1e-15);
    EXPECT_EQ(l3, 0);
}


TEST(faceApertures, axisAlignedBlockOnACartesianGrid)
{
    // Block [0.23, 0.61] x [0.305, 0.695] on a 10 x 10 grid: a vertical face
    // at x = 0.3 is covered over its part of [0.305, 0.695]
    const grid g = jitteredGrid(10, 10, 0);
    faceApertures ap(g.start, g.end);
    const triangleMesh block = triangleMesh::rectangle
    (
        vector2D(0.23, 0.305), vector2D(0.38, 0.39), 3, 4
    );
    ap.update(block.points(), block.points(), block.triangles());
    scalar worst = 0;
    forAll(g.start, f)
    {
        const vector2D& s = g.start[f];
        const vector2D& e = g.end[f];
        scalar exact = 0;
        if (s.x() == e.x() && s.x() > 0.23 && s.x() < 0.61)
        {
            exact = max(0.0, min(0.695, max(s.y(), e.y())) - max(0.305, min(s.y(), e.y())));
        }
        else if (s.y() == e.y() && s.y() > 0.305 && s.y() < 0.695)
        {
            exact = max(0.0, min(0.61, max(s.x(), e.x())) - max(0.23, min(s.x(), e.x())));
        }
        worst = max(worst, mag(ap.covered()[f] - exact));
    }
    RecordProperty("maxCoveredError", sci(worst));
    EXPECT_LT(worst, 1e-14);
}


TEST(faceApertures, translationSatisfiesTheGeometricConservationLaw)
{
    // A rotated triangulated block translated by d over one step: for every
    // cell, gasArea(x1) - gasArea(x0) = -sum_f sigma_f a_f L_f n_f . d with
    // the time-averaged apertures a_f (vertices cross face lines in the step)
    const grid g = jitteredGrid(37, 29);
    faceApertures ap(g.start, g.end);
    solidProjection proj(g.cells);
    const triangleMesh block = triangleMesh::rectangle
    (
        vector2D(0.3, 0.35), vector2D(0.4, 0.25), 13, 9
    );
    scalar worst = 0, maxSwept = 0;
    label nSteps = 0;
    Random rnd(7);
    for (const scalar angle : {0.0, 0.4, 0.5236, -1.1})
    {
        const List<vector2D> x0 =
            rigidMotion(block.points(), angle, vector2D(0.5, 0.475), Zero);
        for (label trial = 0; trial < 5; ++trial)
        {
            // Up to 0.8 cells, any direction
            const vector2D d =
                0.8/37*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
            List<vector2D> x1(x0);
            for (vector2D& p : x1) p += d;

            ap.update(x0, x1, block.triangles());
            const scalarField dA
            (
                gasArea(proj, x1, block.triangles())
              - gasArea(proj, x0, block.triangles())
            );
            scalarField flux(dA.size(), 0);
            forAll(g.start, f)
            {
                const vector2D t = g.end[f] - g.start[f];
                const vector2D nL(t.y(), -t.x());
                const scalar q = ap.aperture(f)*(nL & d);
                flux[g.owner[f]] -= q;
                if (g.neighbour[f] >= 0) flux[g.neighbour[f]] += q;
            }
            forAll(dA, c)
            {
                worst = max(worst, mag(dA[c] - flux[c]));
                maxSwept = max(maxSwept, mag(dA[c]));
            }
            ++nSteps;
        }
    }
    const scalar cellArea = 1.0/(37*29);
    RecordProperty("steps", nSteps);
    RecordProperty("maxSweptOverCellArea", sci(maxSwept/cellArea));
    RecordProperty("maxGclErrorOverCellArea", sci(worst/cellArea));
    EXPECT_GT(maxSwept/cellArea, 0.1);
    EXPECT_LT(worst/cellArea, 1e-12);
}


TEST(faceApertures, eventIntegrationOfADeformingTriangle)
{
    // Vertices on straight lines of different speeds (rotation and
    // stretching) against a 200000-point midpoint rule: a step of a few per
    // cent of the triangle size (as in a coupled step) and a huge one
    const List<vector2D> x0({{0.1, 0.1}, {0.9, 0.2}, {0.3, 0.8}});
    const List<vector2D> big({{0.3, -0.2}, {0.7, 0.9}, {-0.2, 0.5}});
    const List<FixedList<label, 3>> tri({FixedList<label, 3>({0, 1, 2})});
    const List<vector2D> s({{-0.5, 0.4}, {0.45, -0.5}, {0.0, 0.0}, {0.1, 0.12}});
    const List<vector2D> e({{1.5, 0.45}, {0.5, 1.5}, {0.6, 0.6}, {0.9, 0.19}});
    faceApertures ap(s, e);
    scalarField worst(2, 0);
    for (const label k : {0, 1})
    {
        List<vector2D> x1(3);
        forAll(x1, i)
        {
            x1[i] = x0[i] + (k == 0 ? 0.05 : 1.0)*(big[i] - x0[i]);
        }
        ap.update(x0, x1, tri);
        const label n = 200000;
        forAll(s, f)
        {
            scalar sum = 0;
            for (label i = 0; i < n; ++i)
            {
                const scalar tau = (i + 0.5)/n;
                sum += faceApertures::coveredLength
                (
                    s[f], e[f],
                    x0[0] + tau*(x1[0] - x0[0]), x0[1] + tau*(x1[1] - x0[1]),
                    x0[2] + tau*(x1[2] - x0[2])
                );
            }
            worst[k] = max(worst[k], mag(ap.covered()[f] - sum/n)/ap.length()[f]);
        }
    }
    RecordProperty("maxRelativeErrorSmallStep", sci(worst[0]));
    RecordProperty("maxRelativeErrorHugeStep", sci(worst[1]));
    EXPECT_LT(worst[0], 1e-9);
    EXPECT_LT(worst[1], 1e-3);
}


TEST(faceApertures, closedFormOverRandomDeformingTriangles)
{
    // The covered length integrated in closed form between events, against
    // adaptive Simpson on 64 pieces of the step (a piece halved until its
    // halves agree to 1e-12 of the face length: it refines at the events
    // it knows nothing of, where the covered length has kinks), over random
    // triangles whose vertices move independently: steps of 5 % of the
    // triangle size (a coupled step), of its size (shapes turn inside out),
    // and faces nearly parallel to an edge (the bound's line turns slowly:
    // the Gauss-Legendre branch, or the numerical fallback where it turns
    // parallel)
    Random rnd(2718);
    auto point = [&](const scalar s)
    {
        return s*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
    };
    const label nConfigs = 60, nFaces = 3;
    scalarField worst(3, 0);
    labelList pairs(3, 0);
    for (label kind = 0; kind < 3; ++kind)
    {
        for (label c = 0; c < nConfigs; ++c)
        {
            List<vector2D> x0(3), x1(3);
            forAll(x0, k)
            {
                x0[k] = vector2D(0.5, 0.5) + point(0.8);
                x1[k] = x0[k] + point(kind == 1 ? 0.8 : 0.05);
            }
            List<vector2D> s(nFaces), e(nFaces);
            forAll(s, f)
            {
                if (kind == 2)
                {
                    // Along edge f, turned by 1e-6 to 1e-2 rad, shifted
                    // a little off it
                    const vector2D a = x0[f], b = x0[(f + 1) % 3];
                    const scalar angle =
                        Foam::pow(10.0, -6 + 4*rnd.sample01<scalar>());
                    const vector2D m = 0.5*(a + b), h = 0.7*(b - a);
                    const scalar cs = Foam::cos(angle), sn = Foam::sin(angle);
                    const vector2D r(cs*h.x() - sn*h.y(), sn*h.x() + cs*h.y());
                    const vector2D off = 1e-3*point(1);
                    s[f] = m - r + off;
                    e[f] = m + r + off;
                }
                else
                {
                    s[f] = vector2D(0.5, 0.5) + point(1.2);
                    e[f] = vector2D(0.5, 0.5) + point(1.2);
                }
            }
            faceApertures ap(s, e);
            ap.update(x0, x1, List<FixedList<label, 3>>({FixedList<label, 3>({0, 1, 2})}));
            forAll(s, f)
            {
                auto covered = [&](const scalar tau)
                {
                    return faceApertures::coveredLength
                    (
                        s[f], e[f],
                        x0[0] + tau*(x1[0] - x0[0]), x0[1] + tau*(x1[1] - x0[1]),
                        x0[2] + tau*(x1[2] - x0[2])
                    );
                };
                const scalar tol = 1e-12*ap.length()[f];
                std::function<scalar(scalar, scalar, scalar, scalar, scalar, int)>
                simpson = [&]
                (
                    const scalar a, const scalar b, const scalar fa,
                    const scalar fm, const scalar fb, const int depth
                ) -> scalar
                {
                    const scalar m = 0.5*(a + b);
                    const scalar flm = covered(0.5*(a + m)), frm = covered(0.5*(m + b));
                    const scalar whole = (b - a)*(fa + 4*fm + fb)/6;
                    const scalar left = (m - a)*(fa + 4*flm + fm)/6;
                    const scalar right = (b - m)*(fm + 4*frm + fb)/6;
                    if (depth > 30 || mag(left + right - whole) <= 15*tol*(b - a))
                    {
                        return left + right + (left + right - whole)/15;
                    }
                    return simpson(a, m, fa, flm, fm, depth + 1)
                         + simpson(m, b, fm, frm, fb, depth + 1);
                };
                scalar sum = 0;
                const label pieces = 64;
                for (label i = 0; i < pieces; ++i)
                {
                    const scalar a = scalar(i)/pieces, b = scalar(i + 1)/pieces;
                    sum += simpson
                    (
                        a, b, covered(a), covered(0.5*(a + b)), covered(b), 0
                    );
                }
                if (sum > 0) ++pairs[kind];
                worst[kind] =
                    max(worst[kind], mag(ap.covered()[f] - sum)/ap.length()[f]);
            }
        }
    }
    RecordProperty("maxRelativeErrorSmallSteps", sci(worst[0]));
    RecordProperty("maxRelativeErrorLargeSteps", sci(worst[1]));
    RecordProperty("maxRelativeErrorNearlyParallel", sci(worst[2]));
    RecordProperty("coveredPairs", name(pairs[0]) + " " + name(pairs[1]) + " " + name(pairs[2]));
    for (label kind = 0; kind < 3; ++kind)
    {
        EXPECT_GT(pairs[kind], nConfigs/4);
        EXPECT_LT(worst[kind], 1e-11);
    }
}


TEST(faceApertures, costFollowsTheSolidNotTheMesh)
{
    // The same block and cell size on a 100x100 grid over [0, 1]^2 and a
    // 400x400 grid over [0, 4]^2 (16x the faces): the face-triangle pairs
    // clipped (the work) stay about the same
    const triangleMesh block = triangleMesh::rectangle
    (
        vector2D(0.3, 0.35), vector2D(0.2, 0.15), 20, 15
    );
    const List<vector2D> x0 = rigidMotion(block.points(), 0.3, vector2D(0.4, 0.42), Zero);
    const List<vector2D> x1 = rigidMotion(block.points(), 0.3, vector2D(0.4, 0.42), vector2D(1e-3, 5e-4));
    labelList pairs(2);
    scalarField seconds(2);
    label k = 0;
    for (const label n : {100, 400})
    {
        const grid g = jitteredGrid(n, n, 0.2, n/100);
        faceApertures ap(g.start, g.end);
        const clockValue t0(clockValue::now());
        ap.update(x0, x1, block.triangles());
        seconds[k] = t0.elapsed();
        pairs[k++] = ap.nPairs();
    }
    RecordProperty("triangles", block.nTriangles());
    RecordProperty("pairs100", pairs[0]);
    RecordProperty("pairs400", pairs[1]);
    RecordProperty("seconds100", sci(seconds[0]));
    RecordProperty("seconds400", sci(seconds[1]));
    EXPECT_LT(scalar(pairs[1]), 1.2*pairs[0]);
}


namespace
{
    // A rectangular block with a hole (triangles whose centroid is within
    // 'radius' of 'centre' removed) and the edges of its outline (inner
    // and outer: the edges of one triangle only)
    struct holedBlock
    {
        List<vector2D> points;
        List<FixedList<label, 3>> triangles;
        List<edge> boundary;
    };

    holedBlock makeHoledBlock
    (
        const vector2D& centre, const vector2D& size, const label nx,
        const label ny, const scalar radius
    )
    {
        const triangleMesh block = triangleMesh::rectangle
        (
            centre - 0.5*size, size, nx, ny
        );
        holedBlock b;
        b.points = block.points();
        DynamicList<FixedList<label, 3>> kept;
        for (const FixedList<label, 3>& t : block.triangles())
        {
            const vector2D c =
                (b.points[t[0]] + b.points[t[1]] + b.points[t[2]])/3;
            if (mag(c - centre) > radius) kept.append(t);
        }
        b.triangles.transfer(kept);
        std::map<std::pair<label, label>, label> count;
        for (const FixedList<label, 3>& t : b.triangles)
        {
            for (label k = 0; k < 3; ++k)
            {
                const label p = t[k], q = t[(k + 1) % 3];
                ++count[std::make_pair(min(p, q), max(p, q))];
            }
        }
        DynamicList<edge> outline;
        for (const auto& pc : count)
        {
            if (pc.second == 1)
            {
                outline.append(edge(pc.first.first, pc.first.second));
            }
        }
        b.boundary.transfer(outline);
        return b;
    }
}


TEST(faceApertures, boundaryOnlyPathsEqualClippingEverywhere)
{
    // The coupling clips only the cells and integrates only the faces the
    // solid's outline reaches; every other cell or face is decided by a
    // point-in-triangle test. Both must give what clipping everything
    // gives: a holed block (outline inside and out), moved rigidly by up to
    // 0.8 cells, on a coarse grid (triangles smaller than cells) and a fine
    // one (cells smaller than triangles)
    scalar worstAlpha = 0, worstCovered = 0;
    label nFull = 0, nCases = 0, nFold = 0, nKnown = 0, nFaces = 0;
    scalar worstKnown = 0;
    Random rnd(11);
    for (const label n : {23, 97})
    {
        const grid g = jitteredGrid(n, n);
        faceApertures apAll(g.start, g.end), apFast(g.start, g.end);
        faceApertures apKnown(g.start, g.end);
        solidProjection proj(g.cells);
        const holedBlock b = makeHoledBlock
        (
            vector2D(0.5, 0.5), vector2D(0.6, 0.45), 31, 23, 0.12
        );
        for (const scalar angle : {0.0, 0.37, -1.1, 0.2})
        {
            List<vector2D> x0 =
                rigidMotion(b.points, angle, vector2D(0.5, 0.5), Zero);
            const bool folded = angle == 0.2;
            if (folded)
            {
                // A folded view (as where fragments of closed cracks part):
                // a point next to the outline pushed 2.5 elements out over it
                x0[40] += vector2D(0.01, -0.05);
            }
            const vector2D d = 0.8/n*vector2D
            (
                rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5
            );
            List<vector2D> x1(x0);
            for (vector2D& p : x1) p += d;

            // The outline of the union: the boundary and, where the view
            // is folded, the edges of the inverted triangles
            DynamicList<edge> outline(b.boundary), fold;
            for (const FixedList<label, 3>& t : b.triangles)
            {
                if (polygonClipping::cross(x0[t[0]], x0[t[1]], x0[t[2]]) <= 0)
                {
                    for (label k = 0; k < 3; ++k)
                    {
                        fold.append(edge(t[k], t[(k + 1) % 3]));
                    }
                }
            }
            if (folded) { EXPECT_GT(fold.size(), 0); }
            nFold += fold.size()/3;
            outline.append(fold);
            apAll.update(x0, x1, b.triangles);
            apFast.update(x0, x1, b.triangles, outline);
            forAll(g.start, f)
            {
                worstCovered = max
                (
                    worstCovered,
                    mag(apAll.covered()[f] - apFast.covered()[f])
                   /apAll.length()[f]
                );
            }

            boolList cut(proj.nCells(), false);
            for (const edge& e : outline)
            {
                proj.forEachSegmentPiece
                (
                    x0[e.start()], x0[e.end()],
                    [&](const label c, const scalar, const scalar)
                    {
                        cut[c] = true;
                    }
                );
            }
            const List<vector2D> v(x0.size(), vector2D(3, -2));
            scalarField alphaAll, alphaFast;
            List<vector2D> U;
            solidOverlaps overlaps;
            proj.project(x0, b.triangles, v, alphaAll, U, overlaps);
            proj.project(x0, b.triangles, v, alphaFast, U, overlaps, &cut);

            // The coupling's path: the faces next to a cell the outline does
            // not cross take that cell's state, the rest as apFast; the
            // same values bit for bit (a known face is covered wholly or
            // not at all, as its midpoint test says)
            labelList cellState, state;
            faceApertures::cellStatesOf(cut, alphaFast, cellState);
            faceApertures::faceStatesFromCells
            (
                g.owner, g.neighbour, cellState, apKnown.activeFaces(), state
            );
            apKnown.update(x0, x1, b.triangles, outline, state);
            forAll(g.start, f)
            {
                worstKnown = max
                (
                    worstKnown,
                    mag(apFast.covered()[f] - apKnown.covered()[f])
                   /apAll.length()[f]
                );
                if (state[f] >= 0) ++nKnown;
            }
            nFaces += g.start.size();
            forAll(alphaAll, c)
            {
                worstAlpha = max(worstAlpha, mag(alphaAll[c] - alphaFast[c]));
                if (!cut[c] && alphaFast[c] == 1)
                {
                    ++nFull;
                    EXPECT_LT(mag(U[c] - vector2D(3, -2)), 1e-12);
                }
            }
            ++nCases;
        }
    }
    RecordProperty("cases", nCases);
    RecordProperty("fullCellsNotClipped", nFull);
    RecordProperty("invertedTriangles", nFold);
    RecordProperty("maxAlphaDifference", sci(worstAlpha));
    RecordProperty("maxCoveredDifferenceOverLength", sci(worstCovered));
    RecordProperty
    (
        "facesKnownFromTheirCells",
        std::to_string(nKnown) + " of " + std::to_string(nFaces)
    );
    RecordProperty("maxCoveredDifferenceKnownStatesVsOutlinePath", sci(worstKnown));
    EXPECT_GT(nFull, 1000);
    EXPECT_EQ(worstKnown, 0);
    // Most faces are known from their cells (else the path is not taken)
    EXPECT_GT(nKnown, nFaces/2);
    EXPECT_LT(worstAlpha, 1e-12);
    // The full path integrates to a relative 1e-10 of the face length
    EXPECT_LT(worstCovered, 1e-9);
}


TEST(outlineRegions, regionsGiveEveryCellItsCentroidTestsState)
{
    // The coupling's start projection decides the cells far from the
    // outline one region at a time (outlineRegions): the fractions must be
    // those of the cell-by-cell centroid tests, bit for bit. Cases: the
    // holed block turned and shifted, folded, on jittered grids with cells
    // larger and smaller than the triangles, and axis-aligned on a regular
    // grid whose lines its outer and hole-free edges lie on (a wall along
    // a face: the round-off case of the near test)
    label nCases = 0, nByRegion = 0, nCells = 0, nRegions = 0;
    scalar worst = 0, worstFull = 0;
    Random rnd(17);
    for (const scalar jitter : {0.2, 0.0})
    {
        for (const label n : {20, 23, 97})
        {
            const grid g = jitteredGrid(n, n, jitter);
            solidProjection proj(g.cells);
            outlineRegions regions(g.owner, g.neighbour, proj);
            // 0.6 x 0.4 about (0.5, 0.5): on the lines of the 20-cell grid
            const holedBlock b = makeHoledBlock
            (
                vector2D(0.5, 0.5), vector2D(0.6, 0.4), 30, 20, 0.1
            );
            for (const scalar angle : {0.0, 0.37, -1.1, 0.2})
            {
                List<vector2D> x = rigidMotion
                (
                    b.points, angle, vector2D(0.5, 0.5),
                    angle == 0 ? vector2D(Zero) : 0.3/n*vector2D
                    (
                        rnd.sample01<scalar>() - 0.5,
                        rnd.sample01<scalar>() - 0.5
                    )
                );
                if (angle == 0.2) x[40] += vector2D(0.01, -0.05);
                DynamicList<edge> outline(b.boundary);
                vector2D lo(GREAT, GREAT), hi(-GREAT, -GREAT);
                for (const vector2D& p : x)
                {
                    lo = min(lo, p);
                    hi = max(hi, p);
                }
                for (const FixedList<label, 3>& t : b.triangles)
                {
                    if (polygonClipping::cross(x[t[0]], x[t[1]], x[t[2]]) <= 0)
                    {
                        for (label k = 0; k < 3; ++k)
                        {
                            outline.append(edge(t[k], t[(k + 1) % 3]));
                        }
                    }
                }
                // As immersedBodyCoupling::markBoundaryCells
                boolList cut(proj.nCells(), false), near(proj.nCells(), false);
                for (const edge& e : outline)
                {
                    const vector2D& p = x[e.start()];
                    const vector2D& q = x[e.end()];
                    proj.forEachCellNear
                    (
                        p, q, regions.tol(),
                        [&](const label c)
                        {
                            near[c] = true;
                            scalar s0, s1;
                            if (proj.clipSegment(c, p, q, s0, s1)) cut[c] = true;
                        }
                    );
                }
                const List<vector2D> v(x.size(), vector2D(1, 2));
                scalarField alphaAll, alphaCells, alphaRegions;
                List<vector2D> U;
                solidOverlaps overlaps;
                proj.project(x, b.triangles, v, alphaAll, U, overlaps);
                proj.project(x, b.triangles, v, alphaCells, U, overlaps, &cut);
                regions.update(near, lo, hi);
                proj.project
                (
                    x, b.triangles, v, alphaRegions, U, overlaps, &cut,
                    &regions.cellState()
                );
                regions.fill(alphaRegions);
                forAll(alphaCells, c)
                {
                    worst = max(worst, mag(alphaRegions[c] - alphaCells[c]));
                    worstFull = max(worstFull, mag(alphaRegions[c] - alphaAll[c]));
                    if (regions.cellState()[c] == 0) ++nByRegion;
                }
                nCells += proj.nCells();
                nRegions += regions.nRegions();
                ++nCases;
            }
        }
    }
    RecordProperty("cases", nCases);
    RecordProperty
    (
        "cellsDecidedByTheirRegion",
        std::to_string(nByRegion) + " of " + std::to_string(nCells)
    );
    RecordProperty("regions", nRegions);
    RecordProperty("maxAlphaDifferenceRegionsVsCentroidTests", sci(worst));
    RecordProperty("maxAlphaDifferenceRegionsVsClippingAll", sci(worstFull));
    EXPECT_EQ(worst, 0);
    EXPECT_LT(worstFull, 1e-12);
    // The path is taken: most cells are decided by their region
    EXPECT_GT(nByRegion, nCells/2);
}


TEST(cellBinIndex, binSetAgreesWithTheBinWalk)
{
    // touchesSet (four lookups in the blocks' summed-area table, then, if
    // exact, the walk) against touchesFlagged (the walk over the box's
    // bins), random flags and boxes (inside, straddling and outside the
    // grid): exact, the same answer; not exact, never a false no (a false
    // yes only in a block holding a flagged bin). One set refilled at each
    // density, so that the sparse clear is tested too (a bin left flagged
    // would differ)
    const grid g = jitteredGrid(41, 29);
    const cellBinIndex index(g.cells.first, g.cells.second);
    Random rnd(5);
    boolList flag(index.nBins());
    cellBinIndex::binSet set;
    label nTrue = 0, nQueries = 0, nDiffer = 0;
    label nFalseNo = 0, nFalseYes = 0;
    for (const scalar density : {0.0, 0.01, 0.2, 1.0, 0.003, 0.0})
    {
        index.clearSet(set);
        forAll(flag, b)
        {
            flag[b] = rnd.sample01<scalar>() < density;
            if (flag[b]) index.flagBin(set, b);
        }
        index.finishSet(set);
        for (label q = 0; q < 4000; ++q)
        {
            const vector2D a
            (
                1.4*rnd.sample01<scalar>() - 0.2, 1.4*rnd.sample01<scalar>() - 0.2
            );
            const vector2D d
            (
                0.3*rnd.sample01<scalar>(), 0.3*rnd.sample01<scalar>()
            );
            const bool walk = index.touchesFlagged(a, a + d, flag);
            if (walk != index.touchesSet(a, a + d, set, true)) ++nDiffer;
            const bool blocks = index.touchesSet(a, a + d, set, false);
            if (walk && !blocks) ++nFalseNo;
            nFalseYes += blocks && !walk;
            nTrue += walk;
            ++nQueries;
        }
    }
    RecordProperty("queries", nQueries);
    RecordProperty("touching", nTrue);
    RecordProperty("differ", nDiffer);
    RecordProperty("blocksFalseNo", nFalseNo);
    RecordProperty("blocksFalseYes", nFalseYes);
    std::cout<< "binSet: " << nQueries << " queries, " << nTrue
        << " touching, exact differs " << nDiffer << ", blocks: false no "
        << nFalseNo << ", false yes " << nFalseYes << std::endl;
    EXPECT_EQ(nDiffer, 0);
    EXPECT_EQ(nFalseNo, 0);
    // The blocks tell most of the boxes that touch nothing
    EXPECT_LT(nFalseYes, (nQueries - nTrue)/4);
    EXPECT_GT(nTrue, nQueries/4);
    EXPECT_LT(nTrue, nQueries);
}


TEST(cellBinIndex, subsetVisitsInTheIndexOrder)
{
    // forEachCandidateOf against forEachCandidate filtered to the subset:
    // the same polygons in the same order, for random subsets refilled
    // into one subset (so that the sparse reset of its bins is tested)
    const grid g = jitteredGrid(37, 23);
    const cellBinIndex index(g.cells.first, g.cells.second);
    const label nCells = g.cells.second.size() - 1;
    auto box = [&](const label c, vector2D& lo, vector2D& hi)
    {
        lo = vector2D(GREAT, GREAT);
        hi = vector2D(-GREAT, -GREAT);
        for (label k = g.cells.second[c]; k < g.cells.second[c + 1]; ++k)
        {
            lo = min(lo, g.cells.first[k]);
            hi = max(hi, g.cells.first[k]);
        }
    };
    Random rnd(11);
    cellBinIndex::subset sub;
    boolList in(nCells);
    label nQueries = 0, nDiffer = 0, nVisits = 0;
    for (const scalar density : {0.3, 0.02, 1.0, 0.0, 0.1})
    {
        DynamicList<label> cells;
        forAll(in, c)
        {
            in[c] = rnd.sample01<scalar>() < density;
            if (in[c]) cells.append(c);
        }
        index.setSubset(cells, box, sub);
        for (label q = 0; q < 500; ++q)
        {
            const vector2D a
            (
                1.4*rnd.sample01<scalar>() - 0.2, 1.4*rnd.sample01<scalar>() - 0.2
            );
            const vector2D d
            (
                0.3*rnd.sample01<scalar>(), 0.3*rnd.sample01<scalar>()
            );
            DynamicList<label> all, of;
            index.forEachCandidate
            (
                a, a + d, [&](const label c) { if (in[c]) all.append(c); }
            );
            index.forEachCandidateOf
            (
                sub, a, a + d, [&](const label c) { of.append(c); }
            );
            if (all != of) ++nDiffer;
            // touchesSubset may say yes next to the subset, never no
            // where a polygon is visited
            if (!of.empty() && !index.touchesSubset(a, a + d, sub)) ++nDiffer;
            nVisits += of.size();
            ++nQueries;
        }
    }
    RecordProperty("queries", nQueries);
    RecordProperty("visits", nVisits);
    RecordProperty("differ", nDiffer);
    EXPECT_EQ(nDiffer, 0);
    EXPECT_GT(nVisits, nQueries);
}

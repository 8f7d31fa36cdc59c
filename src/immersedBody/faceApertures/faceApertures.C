/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "faceApertures.H"
#include "polygonClipping.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    inline scalar cross2(const vector2D& u, const vector2D& v)
    {
        return u.x()*v.y() - u.y()*v.x();
    }

    // Insertion sort of the few event times of a face-triangle pair
    inline void sortSmall(scalar* t, const label n)
    {
        for (label i = 1; i < n; ++i)
        {
            const scalar v = t[i];
            label j = i;
            for (; j > 0 && t[j - 1] > v; --j) t[j] = t[j - 1];
            t[j] = v;
        }
    }

    // Roots of c0 + c1 t + c2 t^2 strictly inside (0, 1), appended to t
    inline void addRoots
    (
        const scalar c0, const scalar c1, const scalar c2,
        scalar* t, label& n
    )
    {
        const scalar scale = mag(c0) + mag(c1) + mag(c2);
        if (scale <= 0)
        {
            return;
        }
        // Most face-triangle pairs have none: both ends of one sign and no
        // extremum inside (monotonic on [0, 1]), told without a division
        // or a square root
        if
        (
            c0*(c0 + c1 + c2) > 0
         && (c2 > 0 ? !(0 < -c1 && -c1 < 2*c2) : !(0 > -c1 && -c1 > 2*c2))
        )
        {
            return;
        }
        auto add = [&](const scalar r)
        {
            if (r > 0 && r < 1) t[n++] = r;
        };
        if (mag(c2) <= 1e-12*scale)
        {
            if (mag(c1) > 1e-14*scale) add(-c0/c1);
            return;
        }
        const scalar disc = c1*c1 - 4*c2*c0;
        if (disc < 0)
        {
            return;
        }
        // Numerically stable form of the two roots
        const scalar q = -0.5*(c1 + (c1 >= 0 ? 1 : -1)*std::sqrt(disc));
        add(q/c2);
        if (q != 0) add(c0/q);
    }
}


namespace
{
    // Adaptive 2-point Gauss of a smooth function on [a, b] ('whole': the
    // rule on [a, b]), halving until the halves agree to tol per unit length
    // or maxDepth halvings (2^maxDepth pieces: a smooth function converges
    // long before; one that has not is not smooth at round-off level, and
    // deeper halving only multiplies the cost: at 20 halvings a projectile
    // ringing in a barrel spent 94 % of its run here)
    constexpr int maxDepth = 10;
    template<class Rule>
    Foam::scalar adaptiveGauss
    (
        const Rule& gauss, const Foam::scalar a, const Foam::scalar b,
        const Foam::scalar whole, const Foam::scalar tol, const int depth
    )
    {
        const Foam::scalar m = 0.5*(a + b);
        const Foam::scalar left = gauss(a, m), right = gauss(m, b);
        const Foam::scalar halves = left + right;
        if (depth >= maxDepth || std::abs(halves - whole) <= tol*(b - a))
        {
            return halves + (halves - whole)/15;
        }
        return adaptiveGauss(gauss, a, m, left, tol, depth + 1)
             + adaptiveGauss(gauss, m, b, right, tol, depth + 1);
    }
}


namespace
{
    // Integral over [a, b] of N/D, N = c0 + c1 tau + c2 tau^2 and D = g0 +
    // g1 tau of one sign on [a, b]. Closed form when D changes by more than
    // a tenth over the interval: N/D = (c1 + c2 (tau + tau*))/g1
    // + N(tau*)/(g1 (tau - tau*)), tau* = -g0/g1 the root of D, whose
    // terms are at most about 1/eps^2 = 100 times the integral (eps =
    // |g1| h/min|D|). Below that they cancel more, and 5-point
    // Gauss-Legendre is used instead: exact to degree 9, its error is
    // about 1e-6 eps^8 of the integral, below 1e-14
    inline Foam::scalar rationalIntegral
    (
        const Foam::scalar c0, const Foam::scalar c1, const Foam::scalar c2,
        const Foam::scalar g0, const Foam::scalar g1,
        const Foam::scalar a, const Foam::scalar b
    )
    {
        const Foam::scalar h = b - a;
        const Foam::scalar Da = g0 + g1*a, Db = g0 + g1*b;
        if (std::abs(g1)*h < 0.1*Foam::min(std::abs(Da), std::abs(Db)))
        {
            static const Foam::scalar x[3] =
                {0, 0.5384693101056831, 0.9061798459386640};
            static const Foam::scalar w[3] =
                {0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
            const Foam::scalar m = 0.5*(a + b), r = 0.5*h;
            auto f = [&](const Foam::scalar t)
            {
                return (c0 + t*(c1 + t*c2))/(g0 + g1*t);
            };
            Foam::scalar sum = w[0]*f(m);
            for (int i = 1; i < 3; ++i)
            {
                sum += w[i]*(f(m - r*x[i]) + f(m + r*x[i]));
            }
            return r*sum;
        }
        const Foam::scalar ts = -g0/g1;
        const Foam::scalar C = c0 + ts*(c1 + ts*c2);
        return
            (h*(c1 + c2*(0.5*(a + b) + ts)) + C*std::log1p(g1*h/Da))/g1;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::faceApertures::intervalCoveredLength
(
    const vector2D& p0,
    const vector2D& p1,
    const FixedList<vector2D, 3>& x0,
    const FixedList<vector2D, 3>& dx,
    const scalar a,
    const scalar b,
    scalar& integral
)
{
    // Between events the same lines bound the covered part: found by
    // clipping at the interval's midpoint as clipSegment does, noting
    // which edge (or the face's own end) gave each bound
    const vector2D d = p1 - p0;
    const scalar m = 0.5*(a + b);
    FixedList<vector2D, 3> xm;
    for (label k = 0; k < 3; ++k)
    {
        xm[k] = x0[k] + m*dx[k];
    }
    const bool ccw = polygonClipping::cross(xm[0], xm[1], xm[2]) >= 0;
    const label order[3] = {0, ccw ? 1 : 2, ccw ? 2 : 1};
    scalar s0 = 0, s1 = 1;
    label e0 = -1, e1 = -1;
    integral = 0;
    for (label k = 0; k < 3 && s0 < s1; ++k)
    {
        const vector2D& u = xm[order[k]];
        const vector2D& w = xm[order[(k + 1) % 3]];
        const scalar f = polygonClipping::cross(u, w, p0);
        const scalar g = cross2(w - u, d);
        if (g == 0)
        {
            if (f < 0) return true;
        }
        else if (g > 0)
        {
            if (-f/g > s0) { s0 = -f/g; e0 = k; }
        }
        else if (-f/g < s1)
        {
            s1 = -f/g;
            e1 = k;
        }
    }
    if (!(s1 > s0))
    {
        return true;
    }

    // The bound of edge u -> w along the face: s = -f/g, f = (w - u) x
    // (p0 - u) quadratic in tau, g = (w - u) x d linear
    auto boundIntegral = [&](const label k, const scalar end, scalar& I)
    {
        if (k < 0)
        {
            I = end*(b - a);
            return true;
        }
        const label u = order[k], w = order[(k + 1) % 3];
        const vector2D E0 = x0[w] - x0[u], dE = dx[w] - dx[u];
        const vector2D R0 = p0 - x0[u];
        const scalar g0 = cross2(E0, d), g1 = cross2(dE, d);
        if (!((g0 + g1*a)*(g0 + g1*b) > 0))
        {
            return false;
        }
        I = -rationalIntegral
        (
            cross2(E0, R0),
            cross2(dE, R0) - cross2(E0, dx[u]),
            -cross2(dE, dx[u]),
            g0, g1, a, b
        );
        return true;
    };
    scalar I0, I1;
    if (!boundIntegral(e0, 0, I0) || !boundIntegral(e1, 1, I1))
    {
        return false;
    }
    integral = (I1 - I0)*mag(d);
    return true;
}



Foam::label Foam::faceApertures::collinearSide
(
    const vector2D& p0,
    const vector2D& p1,
    const FixedList<vector2D, 3>& x0,
    const FixedList<vector2D, 3>& x1,
    label& edge
)
{
    // An edge lies on the line of the face over the whole step if both its
    // vertices are within collinearTol face lengths of the line at both
    // ends of the step (the distances are linear in tau): a solid surface
    // that lies on a face (or a symmetry plane) up to round-off or joint
    // compliance closes it, and does not leave a sliver of gas
    const vector2D d = p1 - p0;
    const scalar tol = collinearTol*magSqr(d);
    FixedList<scalar, 3> s0, s1;
    for (label k = 0; k < 3; ++k)
    {
        s0[k] = cross2(d, x0[k] - p0);
        s1[k] = cross2(d, x1[k] - p0);
    }
    for (label k = 0; k < 3; ++k)
    {
        const label j = (k + 1) % 3, o = (k + 2) % 3;
        if
        (
            mag(s0[k]) <= tol && mag(s0[j]) <= tol
         && mag(s1[k]) <= tol && mag(s1[j]) <= tol
        )
        {
            edge = k;
            return s0[o] + s1[o] > 0 ? 1 : -1;
        }
    }
    return 0;
}


Foam::scalar Foam::faceApertures::averageEdgeOverlap
(
    const vector2D& p0,
    const vector2D& p1,
    const vector2D& a0,
    const vector2D& a1,
    const vector2D& b0,
    const vector2D& b1
)
{
    // The edge's ends projected on the face, t = (x - p0).d/|d|^2, move
    // linearly in tau; the overlap of [t_a, t_b] with [0, 1] is linear
    // between the times an end crosses 0 or 1: midpoint rule per interval
    const vector2D d = p1 - p0;
    const scalar r = 1/magSqr(d);
    const scalar ta0 = ((a0 - p0) & d)*r, ta1 = ((a1 - p0) & d)*r;
    const scalar tb0 = ((b0 - p0) & d)*r, tb1 = ((b1 - p0) & d)*r;
    scalar t[6] = {0, 1};
    label n = 2;
    for (const scalar c : {0.0, 1.0})
    {
        for (const auto& e : {std::make_pair(ta0, ta1), std::make_pair(tb0, tb1)})
        {
            if ((e.first - c)*(e.second - c) < 0)
            {
                t[n++] = (c - e.first)/(e.second - e.first);
            }
        }
    }
    sortSmall(t, n);
    scalar sum = 0;
    for (label i = 0; i + 1 < n; ++i)
    {
        const scalar m = 0.5*(t[i] + t[i + 1]);
        const scalar ta = ta0 + m*(ta1 - ta0), tb = tb0 + m*(tb1 - tb0);
        const scalar lo = max(min(ta, tb), scalar(0));
        const scalar hi = min(max(ta, tb), scalar(1));
        sum += (t[i + 1] - t[i])*max(hi - lo, scalar(0));
    }
    return sum*mag(d);
}


Foam::cellBinIndex Foam::faceApertures::makeIndex
(
    const UList<vector2D>& start,
    const UList<vector2D>& end,
    const bool midpoints
)
{
    // The faces of empty patches (length 0) are in no bin: they would all
    // sit in the bin of the origin and every triangle over it would visit
    // them
    List<vector2D> vertices((midpoints ? 1 : 2)*start.size());
    labelList polygonStart(start.size() + 1);
    label n = 0;
    forAll(start, f)
    {
        polygonStart[f] = n;
        if (start[f] == end[f]) continue;
        if (midpoints)
        {
            vertices[n++] = 0.5*(start[f] + end[f]);
        }
        else
        {
            vertices[n++] = start[f];
            vertices[n++] = end[f];
        }
    }
    polygonStart[start.size()] = n;
    vertices.setSize(n);
    return cellBinIndex(vertices, polygonStart);
}


Foam::scalar Foam::faceApertures::averageCoveredLength
(
    const vector2D& p0,
    const vector2D& p1,
    const FixedList<vector2D, 3>& x0,
    const FixedList<vector2D, 3>& x1
)
{
    // Events: a vertex crosses the line of the face (linear in tau), an end
    // of the face crosses the line of an edge (quadratic in tau)
    // (the ends, 3 vertex crossings, 6 x 2 end crossings, 2 orientation
    // changes)
    scalar t[2 + 3 + 3*2*2 + 2];
    label n = 0;
    t[n++] = 0;
    const vector2D d = p1 - p0;
    FixedList<vector2D, 3> dx;
    // (for the shortcut below: no vertex on the face's line, the face's
    // ends strictly on one side of every edge line, at the start)
    bool strict = true;
    label nLeft = 0;
    for (label k = 0; k < 3; ++k)
    {
        dx[k] = x1[k] - x0[k];
        const scalar s0 = cross2(d, x0[k] - p0);
        const scalar s1 = cross2(d, x1[k] - p0);
        strict = strict && s0 != 0;
        if ((s0 < 0) != (s1 < 0) && s0 != s1)
        {
            const scalar r = s0/(s0 - s1);
            if (r > 0 && r < 1) t[n++] = r;
        }
    }
    for (label k = 0; k < 3; ++k)
    {
        const label j = (k + 1) % 3;
        const vector2D e0 = x0[j] - x0[k];
        const vector2D de = dx[j] - dx[k];
        for (const vector2D* q : {&p0, &p1})
        {
            // (e0 + tau de) x (q - x0_k - tau dx_k)
            const vector2D r0 = *q - x0[k];
            const scalar side0 = cross2(e0, r0);
            strict = strict && side0 != 0;
            nLeft += side0 > 0;
            addRoots
            (
                cross2(e0, r0),
                cross2(de, r0) - cross2(e0, dx[k]),
                -cross2(de, dx[k]),
                t, n
            );
        }
    }
    t[n++] = 1;
    sortSmall(t, n);

    // The covered length at one instant, and adaptive 2-point Gauss with
    // Richardson extrapolation for the intervals the closed form below does
    // not take (a bound that can be steep when the face is nearly parallel
    // to an edge)
    const bool translation =
        dx[1] == dx[0] && dx[2] == dx[0];
    auto covered = [&](const scalar tau)
    {
        return coveredLength
        (
            p0, p1, x0[0] + tau*dx[0], x0[1] + tau*dx[1], x0[2] + tau*dx[2]
        );
    };
    static const scalar g = 0.5/std::sqrt(3.0);
    auto gauss = [&](const scalar a, const scalar b)
    {
        const scalar h = b - a, m = 0.5*(a + b);
        return 0.5*h*(covered(m - g*h) + covered(m + g*h));
    };
    const scalar tol = 1e-10*mag(d);

    // Without events inside the step nothing changes how the face and the
    // triangle meet: a face wholly inside (or wholly outside) at the start,
    // strictly, stays so (its ends would have to cross an edge line, or a
    // vertex the face's line): no quadrature for those
    if (n == 2 && strict)
    {
        // Wholly inside: both ends left of all three edges (or right of
        // all, a clockwise triangle)
        if (nLeft == 6 || nLeft == 0)
        {
            return mag(d);
        }
        if (covered(0) <= 0)
        {
            return 0;
        }
    }

    // A deforming triangle: the times its area changes sign are events too
    // (its orientation, and so which edges bound the covered part)
    if (!translation)
    {
        const vector2D e1 = x0[1] - x0[0], e2 = x0[2] - x0[0];
        const vector2D de1 = dx[1] - dx[0], de2 = dx[2] - dx[0];
        const label n0 = n;
        addRoots
        (
            cross2(e1, e2), cross2(de1, e2) + cross2(e1, de2),
            cross2(de1, de2), t, n
        );
        if (n > n0)
        {
            sortSmall(t, n);
        }
    }

    // Between events: a translation's covered length is linear (midpoint
    // rule); otherwise each bound is a ratio of a quadratic to a linear
    // function of tau, integrated in closed form (intervalCoveredLength),
    // or by adaptive quadrature where that does not apply
    scalar integral = 0;
    for (label i = 0; i + 1 < n; ++i)
    {
        const scalar a = t[i], b = t[i + 1];
        if (b <= a) continue;
        scalar exact;
        integral +=
            translation
          ? (b - a)*covered(0.5*(a + b))
          : intervalCoveredLength(p0, p1, x0, dx, a, b, exact)
          ? exact
          : adaptiveGauss(gauss, a, b, gauss(a, b), tol, 0);
    }
    return integral;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::faceApertures::faceApertures
(
    const UList<vector2D>& start,
    const UList<vector2D>& end
)
:
    start_(start),
    end_(end),
    length_(start.size()),
    midpoint_(start.size()),
    index_(makeIndex(start, end, false)),
    midpointIndex_(makeIndex(start, end, true)),
    covered_(start.size(), 0),
    nPairs_(0),
    onLeft_(start.size(), 0),
    onRight_(start.size(), 0),
    lastTriangle_(start.size(), -1),
    faceState_(nullptr)
{
    DynamicList<label> active(length_.size());
    forAll(length_, f)
    {
        length_[f] = mag(end_[f] - start_[f]);
        midpoint_[f] = 0.5*(start_[f] + end_[f]);
        if (length_[f] > 0) active.append(f);
    }
    activeFaces_.transfer(active);
}


namespace
{
    // Back segments of the faces of a 2D mesh (length 0 on empty patches)
    std::pair<Foam::List<Foam::vector2D>, Foam::List<Foam::vector2D>>
    meshSegments(const Foam::polyMesh& mesh)
    {
        using namespace Foam;
        std::pair<List<vector2D>, List<vector2D>> seg;
        seg.first.setSize(mesh.nFaces(), Zero);
        seg.second.setSize(mesh.nFaces(), Zero);
        const scalar zMid = 0.5*(mesh.bounds().min().z() + mesh.bounds().max().z());
        const pointField& pts = mesh.points();
        auto segment = [&](const label facei)
        {
            const face& f = mesh.faces()[facei];
            label k = 0;
            vector2D ends[2];
            forAll(f, i)
            {
                const point& p = pts[f[i]];
                if (p.z() < zMid && k < 2)
                {
                    ends[k++] = vector2D(p.x(), p.y());
                }
            }
            if (k != 2)
            {
                FatalErrorInFunction
                    << "The immersed body needs a 2D mesh in the x-y plane"
                    << " (one cell thick): face " << facei << " at "
                    << mesh.faceCentres()[facei] << " does not have two"
                    << " points on the back plane" << exit(FatalError);
            }
            // Normal (dy, -dx) along the face's area vector
            const vector& S = mesh.faceAreas()[facei];
            const vector2D d = ends[1] - ends[0];
            if (d.y()*S.x() - d.x()*S.y() < 0)
            {
                std::swap(ends[0], ends[1]);
            }
            seg.first[facei] = ends[0];
            seg.second[facei] = ends[1];
        };
        for (label facei = 0; facei < mesh.nInternalFaces(); ++facei)
        {
            segment(facei);
        }
        for (const polyPatch& pp : mesh.boundaryMesh())
        {
            if (isA<emptyPolyPatch>(pp)) continue;
            forAll(pp, i)
            {
                segment(pp.start() + i);
            }
        }
        return seg;
    }
}


Foam::faceApertures::faceApertures(const polyMesh& mesh)
:
    faceApertures(meshSegments(mesh))
{}


Foam::faceApertures::faceApertures
(
    const std::pair<List<vector2D>, List<vector2D>>& segments
)
:
    faceApertures(segments.first, segments.second)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::faceApertures::coveredLength
(
    const vector2D& p0,
    const vector2D& p1,
    const vector2D& a,
    const vector2D& b,
    const vector2D& c
)
{
    // Parametric clipping by the counter-clockwise triangle
    const bool ccw = polygonClipping::cross(a, b, c) >= 0;
    const vector2D tri[3] = {a, ccw ? b : c, ccw ? c : b};
    scalar lo, hi;
    return
        polygonClipping::clipSegment(p0, p1, tri, 3, lo, hi)
      ? (hi - lo)*mag(p1 - p0)
      : 0;
}


bool Foam::faceApertures::inside
(
    const vector2D& x,
    const FixedList<vector2D, 3>& tri
)
{
    // Either orientation; a point on an edge shared by two triangles is in
    // both (the caller counts a face once)
    using polygonClipping::cross;
    const scalar twiceArea = cross(tri[0], tri[1], tri[2]);
    const scalar tol = 1e-12*mag(twiceArea);
    if (tol <= 0) return false;
    const scalar c0 = cross(tri[0], tri[1], x);
    const scalar c1 = cross(tri[1], tri[2], x);
    const scalar c2 = cross(tri[2], tri[0], x);
    return
        (c0 >= -tol && c1 >= -tol && c2 >= -tol)
     || (c0 <= tol && c1 <= tol && c2 <= tol);
}


void Foam::faceApertures::update
(
    const UList<vector2D>& points0,
    const UList<vector2D>& points1,
    const UList<FixedList<label, 3>>& triangles
)
{
    boundaryFace_.setSize(length_.size());
    boundaryFace_ = true;
    boundaryFaceList_ = activeFaces_;
    integrate(points0, points1, triangles);
}


void Foam::faceApertures::update
(
    const UList<vector2D>& points0,
    const UList<vector2D>& points1,
    const UList<FixedList<label, 3>>& triangles,
    const UList<edge>& boundaryEdges
)
{
    boundaryFace_.setSize(length_.size());
    boundaryFace_ = false;
    boundaryFaceList_.clear();
    for (const edge& e : boundaryEdges)
    {
        const vector2D& a0 = points0[e.start()];
        const vector2D& b0 = points0[e.end()];
        const vector2D& a1 = points1[e.start()];
        const vector2D& b1 = points1[e.end()];
        index_.forEachCandidate
        (
            min(min(a0, b0), min(a1, b1)),
            max(max(a0, b0), max(a1, b1)),
            [&](const label f)
            {
                if (!boundaryFace_[f])
                {
                    boundaryFace_[f] = true;
                    boundaryFaceList_.append(f);
                }
            }
        );
    }
    // The boundary faces binned on their own (in ascending order, as the
    // index lists them): a triangle that reaches a face shares a bin with
    // it
    Foam::sort(boundaryFaceList_);
    index_.setSubset
    (
        boundaryFaceList_,
        [&](const label f, vector2D& lo, vector2D& hi)
        {
            lo = min(start_[f], end_[f]);
            hi = max(start_[f], end_[f]);
        },
        boundarySubset_
    );
    integrate(points0, points1, triangles, &boundarySubset_);
}


void Foam::faceApertures::update
(
    const UList<vector2D>& points0,
    const UList<vector2D>& points1,
    const UList<FixedList<label, 3>>& triangles,
    const UList<edge>& boundaryEdges,
    const labelUList& faceState
)
{
    if (faceState.size() != length_.size())
    {
        FatalErrorInFunction
            << "faceApertures: " << faceState.size() << " face states for "
            << length_.size() << " faces" << abort(FatalError);
    }
    faceState_ = &faceState;
    update(points0, points1, triangles, boundaryEdges);
    faceState_ = nullptr;
}


void Foam::faceApertures::cellStatesOf
(
    const UList<bool>& boundaryCell,
    const scalarField& alpha,
    labelList& cellState
)
{
    // A cell decided by its centroid has alpha exactly 0 or 1; anything
    // else (a clipped cell) tells nothing
    cellState.setSize(alpha.size());
    forAll(alpha, c)
    {
        const scalar a = alpha[c];
        cellState[c] = boundaryCell[c] ? -1 : a == 1 ? 1 : a == 0 ? 0 : -1;
    }
}


void Foam::faceApertures::faceStatesFromCells
(
    const labelUList& owner,
    const labelUList& neighbour,
    const labelUList& cellState,
    const labelUList& faces,
    labelList& faceState
)
{
    if (faceState.size() != owner.size())
    {
        faceState.setSize(owner.size());
        faceState = -1;
    }
    for (const label f : faces)
    {
        label s = cellState[owner[f]];
        if (s < 0 && f < neighbour.size() && neighbour[f] >= 0)
        {
            s = cellState[neighbour[f]];
        }
        faceState[f] = s;
    }
}


void Foam::faceApertures::clipFace
(
    const label f,
    const vector2D& lo,
    const vector2D& hi,
    const FixedList<vector2D, 3>& x0,
    const FixedList<vector2D, 3>& x1,
    const bool moving
)
{
    const vector2D& p0 = start_[f];
    const vector2D& p1 = end_[f];
    // Face and swept triangle boxes apart: nothing covered
    if
    (
        max(p0.x(), p1.x()) < lo.x() || min(p0.x(), p1.x()) > hi.x()
     || max(p0.y(), p1.y()) < lo.y() || min(p0.y(), p1.y()) > hi.y()
    )
    {
        return;
    }
    ++nPairs_;
    // A face along an edge shared by two triangles would be counted twice:
    // such parts are counted per side, once
    label edge = -1;
    const label side = collinearSide(p0, p1, x0, x1, edge);
    if (side == 0)
    {
        covered_[f] +=
            moving
          ? averageCoveredLength(p0, p1, x0, x1)
          : coveredLength(p0, p1, x0[0], x0[1], x0[2]);
        return;
    }
    const label j = (edge + 1) % 3;
    const scalar c =
        averageEdgeOverlap(p0, p1, x0[edge], x1[edge], x0[j], x1[j]);
    if (side > 0) onLeft_[f] += c;
    else onRight_[f] += c;
}


void Foam::faceApertures::integrate
(
    const UList<vector2D>& points0,
    const UList<vector2D>& points1,
    const UList<FixedList<label, 3>>& triangles,
    const cellBinIndex::subset* boundary
)
{
    const bool moving = &points0 != &points1;
    nPairs_ = 0;
    clippedFaces_.clear();

    // The faces the outline does not reach and whose state is known take
    // it (exactly what the midpoint test gives them); the midpoints of the
    // others are tested, in the bins that hold one
    const labelUList* state = faceState_;
    midpointIndex_.clearSet(unknownBins_);
    if (!state)
    {
        covered_ = 0;
        for (label b = 0; b < midpointIndex_.nBins(); ++b)
        {
            midpointIndex_.flagBin(unknownBins_, b);
        }
    }
    else
    {
        // (covered_ of a face of length 0 stays 0: nothing clips it)
        for (const label f : activeFaces_)
        {
            covered_[f] = 0;
            if (boundaryFace_[f]) continue;
            const label s = (*state)[f];
            if (s >= 0)
            {
                covered_[f] = s == 1 ? length_[f] : 0;
            }
            else
            {
                midpointIndex_.forEachBin
                (
                    midpoint_[f], midpoint_[f],
                    [&](const label b)
                    {
                        midpointIndex_.flagBin(unknownBins_, b);
                    }
                );
            }
        }
    }

    midpointIndex_.finishSet(unknownBins_);

    forAll(triangles, t)
    {
        const FixedList<label, 3>& tri = triangles[t];
        FixedList<vector2D, 3> x0, x1;
        vector2D lo(GREAT, GREAT), hi(-GREAT, -GREAT);
        for (label k = 0; k < 3; ++k)
        {
            x0[k] = points0[tri[k]];
            x1[k] = points1[tri[k]];
            lo = min(lo, min(x0[k], x1[k]));
            hi = max(hi, max(x0[k], x1[k]));
        }

        // The faces a boundary edge's swept box reaches, clipped over the
        // step: those in the bins the triangle's box touches (a boundary
        // face may be listed in other bins too: all candidates)
        auto clip = [&](const label f)
        {
            if (lastTriangle_[f] == t) return;
            if (lastTriangle_[f] < 0) clippedFaces_.append(f);
            lastTriangle_[f] = t;
            clipFace(f, lo, hi, x0, x1, moving);
        };
        if (boundary)
        {
            if (index_.touchesSubset(lo, hi, *boundary))
            {
                index_.forEachCandidateOf(*boundary, lo, hi, clip);
            }
        }
        else
        {
            index_.forEachCandidate
            (
                lo, hi,
                [&](const label f) { if (boundaryFace_[f]) clip(f); }
            );
        }

        // Every other face is covered all the step or open all the step,
        // as its midpoint is in a triangle at the start or not (each face
        // is in one bin of the midpoint index: visited once per triangle)
        const vector2D lo0(min(x0[0], min(x0[1], x0[2])));
        const vector2D hi0(max(x0[0], max(x0[1], x0[2])));
        if (!midpointIndex_.touchesSet(lo0, hi0, unknownBins_, true))
        {
            continue;
        }
        midpointIndex_.forEachCandidate
        (
            lo0, hi0,
            [&](const label f)
            {
                if
                (
                    !boundaryFace_[f] && (!state || (*state)[f] < 0)
                 && covered_[f] < length_[f]
                 && inside(midpoint_[f], x0)
                )
                {
                    covered_[f] = length_[f];
                }
            }
        );
    }

    // Overlapping triangles (contact) could count a part twice (only a
    // clipped face can exceed its length or have parts on edges)
    for (const label f : clippedFaces_)
    {
        covered_[f] =
            min(covered_[f] + max(onLeft_[f], onRight_[f]), length_[f]);
        onLeft_[f] = 0;
        onRight_[f] = 0;
        lastTriangle_[f] = -1;
    }
}


// ************************************************************************* //

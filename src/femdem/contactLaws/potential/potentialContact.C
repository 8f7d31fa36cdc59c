/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "potentialContact.H"
#include "addToRunTimeSelectionTable.H"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(potential, 0);
    addToRunTimeSelectionTable(contactLaw, potential, dictionary);
}
}


// * * * * * * * * * * * * * * * Local Types * * * * * * * * * * * * * * * //

//- The data of a target triangle t that its contactors share: computed once
//  per pair (or once for the lower triangle of all its pairs), with the
//  same operations as before it was shared (bitwise the same forces)
struct Foam::contactLaws::potential::targetGeometry
{
    label t;
    const vector2D* T[3];
    //- Bounding box (xmin, ymin, xmax, ymax)
    scalar box[4];
    //- Twice the area and its inverse
    scalar A2, iA2;
    //- Edge i opposite vertex i: T_{i+2} - T_{i+1}
    scalar ex[3], ey[3];
    //- Largest inverse mass of the three nodes
    scalar invMMax;

    //- The box only (the broad-phase test)
    inline void setBox(const vector2D* x, const label tri)
    {
        t = tri;
        T[0] = &x[3*t];
        T[1] = &x[3*t + 1];
        T[2] = &x[3*t + 2];
        const vector2D& T0 = *T[0];
        const vector2D& T1 = *T[1];
        const vector2D& T2 = *T[2];
        box[0] = min(T0.x(), min(T1.x(), T2.x()));
        box[1] = min(T0.y(), min(T1.y(), T2.y()));
        box[2] = max(T0.x(), max(T1.x(), T2.x()));
        box[3] = max(T0.y(), max(T1.y(), T2.y()));
    }

    //- The rest, after setBox
    inline void setShape(const scalar* invM)
    {
        const vector2D& T0 = *T[0];
        const vector2D& T1 = *T[1];
        const vector2D& T2 = *T[2];
        A2 = (T1.x() - T0.x())*(T2.y() - T0.y())
           - (T1.y() - T0.y())*(T2.x() - T0.x());
        // not inverted by a non-positive area (the contact is skipped)
        iA2 = A2 <= 0 ? 0 : 1/A2;
        for (label i = 0; i < 3; ++i)
        {
            const vector2D& a = *T[(i + 1) % 3];
            const vector2D& b = *T[(i + 2) % 3];
            ex[i] = b.x() - a.x();
            ey[i] = b.y() - a.y();
        }
        const label t0 = 3*t;
        invMMax = max(invM[t0], max(invM[t0 + 1], invM[t0 + 2]));
    }

    //- Whether the boxes of this and o overlap (touching counts)
    inline bool overlaps(const targetGeometry& o) const
    {
        return !
        (
            box[2] < o.box[0] || o.box[2] < box[0]
         || box[3] < o.box[1] || o.box[3] < box[1]
        );
    }
};


namespace
{

//- Single-precision bounds that contain [lo, hi]
inline void roundOutward(const double lo, const double hi, float& l, float& h)
{
    l = float(lo);
    if (double(l) > lo) l = std::nextafter(l, -HUGE_VALF);
    h = float(hi);
    if (double(h) < hi) h = std::nextafter(h, HUGE_VALF);
}

//- Size l to n: exactly at the first build; a list that grows later gets
//  1/8 spare (DynamicList would double its capacity), so that a list growing
//  by a little is not reallocated at every build
template<class T>
inline void fit(Foam::DynamicList<T>& l, const Foam::label n)
{
    if (n > l.capacity()) l.setCapacity(l.capacity() ? n + n/8 : n);
    l.setSize(n);
}


#if defined(__x86_64__) && defined(__GNUC__)
#define FEMDEM_CONTACT_LANES 1

//- A block of contactor-target calls as lanes: the inputs of the edge
//  tests of forEachCrossingEdge and, per edge k of the contactor, their
//  results
struct callLanes
{
    static constexpr Foam::label size = 32;     // a multiple of 8
    //- The contactor's nodes 0, 1, 2: x, y
    double cx[6][size];
    //- The target's box (xmin, ymin, xmax, ymax), the point of its edge i
    //  (vertex (i + 1) % 3), its edge vectors and 1/(2 A)
    double box[4][size];
    double ax[3][size], ay[3][size], ex[3][size], ey[3][size];
    double iA2[size];
    //- 1 where edge k is free and the target's area positive
    double valid[3][size];
    //- Per edge k: lambda_i = l0 + s dl, the clipped range, the edge
    //  vector and its squared length, 1 where it crosses the target
    double l0[3][3][size], dl[3][3][size], s0[3][size], s1[3][size];
    double dx[3][size], dy[3][size], len2[3][size], crosses[3][size];
    //- Per call: contactor, target and its largest inverse mass, penalty,
    //  friction, and the call's first crossing edge in the edge lanes
    Foam::label contactor[size], target[size];
    double targetInvMMax[size], penalty[size], friction[size];
    Foam::label firstEdge[size + 1];

    //- Pad calls n .. to a multiple of 8 with copies of call 0's test
    //  inputs and no valid edge; returns the padded count
    Foam::label pad(const Foam::label n)
    {
        const Foam::label nc = (n + 7)/8*8;
        for (Foam::label j = n; j < nc; ++j)
        {
            for (int m = 0; m < 6; ++m) cx[m][j] = cx[m][0];
            for (int m = 0; m < 4; ++m) box[m][j] = box[m][0];
            for (int k = 0; k < 3; ++k)
            {
                ax[k][j] = ax[k][0];
                ay[k][j] = ay[k][0];
                ex[k][j] = ex[k][0];
                ey[k][j] = ey[k][0];
                valid[k][j] = 0;
            }
            iA2[j] = iA2[0];
        }
        return nc;
    }
};


//- The contactor edges that cross their targets, as lanes (structure of
//  arrays): where the inputs of integrateEdge are (gathered), and per piece
//  of the edge (at most 4) the target's force terms, in the order
//  integrateEdge subtracts them, and whether its friction and normal force
//  were applied
struct edgeLanes
{
    static constexpr Foam::label size = 96;     // a multiple of 8
    //- Where each edge's data are: its call j, its results in the call
    //  lanes (k size + j, and 3 k size + j for l0 and dl), its nodes nA, nB
    //  and its target's first node
    int call[size], kj[size], k3j[size], nA[size], nB[size], t0[size];
    double fA[2][size], fB[2][size];
    double friction[4][size], normal[4][size];
    double tf[4][6][size], tn[4][6][size];
    //- The target's terms summed over the pieces from 0 (the sum a call
    //  with this edge alone adds), and whether any piece had a force
    double fT[6][size], any[size];

    //- The crossing edges of calls 0 .. n of C, call by call, edge by
    //  edge (where their data are: integrateEdgesV4 gathers them), padded
    //  to a multiple of 8 with the last (results unused); sets
    //  C.firstEdge, returns the padded count
    Foam::label gather(callLanes& C, const Foam::label n)
    {
        Foam::label nEdges = 0;
        for (Foam::label j = 0; j < n; ++j)
        {
            C.firstEdge[j] = nEdges;
            const Foam::label c = C.contactor[j];
            for (int k = 0; k < 3; ++k)
            {
                if (!(C.crosses[k][j] > 0)) continue;
                const Foam::label e = nEdges++;
                call[e] = j;
                kj[e] = k*callLanes::size + j;
                k3j[e] = 3*k*callLanes::size + j;
                nA[e] = 3*c + k;
                nB[e] = 3*c + (k == 2 ? 0 : k + 1);
                t0[e] = 3*C.target[j];
            }
        }
        C.firstEdge[n] = nEdges;
        const Foam::label ne = (nEdges + 7)/8*8;
        for (Foam::label e = nEdges; e < ne; ++e)
        {
            const Foam::label l = nEdges - 1;
            call[e] = call[l];
            kj[e] = kj[l];
            k3j[e] = k3j[l];
            nA[e] = nA[l];
            nB[e] = nB[l];
            t0[e] = t0[l];
        }
        return ne;
    }

    //- The target's force of call j of C (the terms of its edges' pieces
    //  in integrateEdge's order; one edge: its lane's sum); false if none
    bool targetForce(const callLanes& C, const Foam::label j, double fTj[3][2])
        const
    {
        const Foam::label e0 = C.firstEdge[j], e1 = C.firstEdge[j + 1];
        if (e1 - e0 == 1)
        {
            for (int i = 0; i < 3; ++i)
            {
                fTj[i][0] = fT[2*i][e0];
                fTj[i][1] = fT[2*i + 1][e0];
            }
            return any[e0] > 0;
        }
        bool anyForce = false;
        for (Foam::label e = e0; e < e1; ++e)
        {
            // Piece by piece: its friction share, then its normal share
            auto take = [&](const double share[6][size])
            {
                for (int i = 0; i < 3; ++i)
                {
                    fTj[i][0] -= share[2*i][e];
                    fTj[i][1] -= share[2*i + 1][e];
                }
            };
            for (int q = 0; q < 4; ++q)
            {
                if (friction[q][e] > 0) take(tf[q]);
                if (normal[q][e] > 0)
                {
                    take(tn[q]);
                    anyForce = true;
                }
            }
        }
        return anyForce;
    }
};


//- Add the forces of calls 0 .. nCalls of C integrated in L, pair by pair
//  (calls 2 i and 2 i + 1), call by call: the contactor's edge forces,
//  then the target's, as contactorTarget adds them; returns the number of
//  pairs with a force
Foam::label addLaneForces
(
    const callLanes& C,
    const edgeLanes& L,
    const Foam::label nCalls,
    Foam::UList<Foam::vector2D>& f
)
{
    using namespace Foam;
    label nActive = 0;
    for (label call = 0; call < nCalls; call += 2)
    {
        bool active = false;
        for (label j = call; j <= call + 1; ++j)
        {
            scalar fT[3][2] = {{0, 0}, {0, 0}, {0, 0}};
            const bool any = L.targetForce(C, j, fT);
            for (label e = C.firstEdge[j]; e < C.firstEdge[j + 1]; ++e)
            {
                const label nA = L.nA[e], nB = L.nB[e];
                f[nA].x() += L.fA[0][e];
                f[nA].y() += L.fA[1][e];
                f[nB].x() += L.fB[0][e];
                f[nB].y() += L.fB[1][e];
            }
            if (any)
            {
                const label t = C.target[j];
                for (label i = 0; i < 3; ++i)
                {
                    f[3*t + i].x() += fT[i][0];
                    f[3*t + i].y() += fT[i][1];
                }
            }
            active = active || any;
        }
        if (active) ++nActive;
    }
    return nActive;
}


//- integrateEdge for 8 edges at a time, AVX-512 intrinsics: the same IEEE
//  operations in the same order for every piece (no fused multiply-add;
//  _mm512_max_pd(a, b) and _mm512_min_pd(a, b) are Foam::max(a, b) and
//  Foam::min(a, b), a > b ? a : b and a < b ? a : b; quiet comparisons).
//  The break points are sorted by a network (the same values as the
//  insertion sort), the pieces past the last break point are empty (zero
//  length: skipped by I <= 0 as an empty piece of the scalar loop is), and
//  the divisions are masked to the lanes that use them (no trap)
// (GCC 12's AVX-512 headers warn of an uninitialised temporary of their
// own: its bug 105593)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"

// The operations of the lanes (x86-64-v4 code; a lambda inside the target
// function would not take its target)
#define FEMDEM_V4_INLINE \
    static inline __attribute__((target("arch=x86-64-v4"), always_inline))
typedef __m512d V;
typedef __mmask8 M;
FEMDEM_V4_INLINE V ld(const double* p) { return _mm512_loadu_pd(p); }
FEMDEM_V4_INLINE __m256i ldi(const int* p)
{
    return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}
FEMDEM_V4_INLINE V gather(const __m256i i, const double* base)
{
    return _mm512_i32gather_pd(i, base, 8);
}
FEMDEM_V4_INLINE V neg(const V x)
{
    // (the sign flipped, as unary minus; 0 - x would give +0 for +0)
    return _mm512_castsi512_pd
    (
        _mm512_xor_si512
        (
            _mm512_castpd_si512(x),
            _mm512_set1_epi64(std::int64_t(0x8000000000000000ull))
        )
    );
}
FEMDEM_V4_INLINE M lt(const V a, const V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
FEMDEM_V4_INLINE M gt(const V a, const V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
FEMDEM_V4_INLINE M le(const V a, const V b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
FEMDEM_V4_INLINE V mx(const V a, const V b) { return _mm512_max_pd(a, b); }
FEMDEM_V4_INLINE V mn(const V a, const V b) { return _mm512_min_pd(a, b); }
FEMDEM_V4_INLINE V add(const V a, const V b) { return _mm512_add_pd(a, b); }
FEMDEM_V4_INLINE V sub(const V a, const V b) { return _mm512_sub_pd(a, b); }
FEMDEM_V4_INLINE V mul(const V a, const V b) { return _mm512_mul_pd(a, b); }
//- ell/6 (2 pa La + pa Lc + pc La + 2 pc Lc), e6 = ell/6
FEMDEM_V4_INLINE V integral
(
    const V e6, const V pa, const V pc, const V La, const V Lc
)
{
    const V two = _mm512_set1_pd(2);
    return mul
    (
        e6,
        add
        (
            add(add(mul(mul(two, pa), La), mul(pa, Lc)), mul(pc, La)),
            mul(mul(two, pc), Lc)
        )
    );
}
//- The target's share c_i r (gx, gy) of a force on its node i: stored at
//  out[2 i] + j, out[2 i + 1] + j for the replay, and taken from fT in the
//  lanes of m (friction: c = li, r = 1/sum li; normal: c = IT, r = I/sum IT)
FEMDEM_V4_INLINE void shareWithTarget
(
    const V c[3], const V r, const V gx, const V gy, const M m,
    double* const out[6], const Foam::label j, V fT[6]
)
{
    for (int i = 0; i < 3; ++i)
    {
        const V w = mul(c[i], r);
        const V sx = mul(w, gx), sy = mul(w, gy);
        _mm512_storeu_pd(out[2*i] + j, sx);
        _mm512_storeu_pd(out[2*i + 1] + j, sy);
        fT[2*i] = _mm512_mask_sub_pd(fT[2*i], m, fT[2*i], sx);
        fT[2*i + 1] = _mm512_mask_sub_pd(fT[2*i + 1], m, fT[2*i + 1], sy);
    }
}
#undef FEMDEM_V4_INLINE


//- The points of an edge's pieces, P[0] = s0 < ... <= P[4] = s1: the break
//  points where the minimum of lambda_i changes branch (as integrateEdge
//  finds them), sorted by a network (the values of its insertion sort)
//  and, past the last one, s1 (empty pieces); returns the number of pieces
//  the 8 lanes need (one more than the most break points of a lane)
__attribute__((target("arch=x86-64-v4"))) inline int piecePoints
(
    const V l0[3],
    const V dl[3],
    const V s0,
    const V s1,
    V P[5]
)
{
    const V zero = _mm512_setzero_pd();
    const V inf = _mm512_set1_pd(std::numeric_limits<double>::infinity());
    V r[3];
    M found[3];
    for (int i = 0; i < 3; ++i)
    {
        const int k = (i + 1) % 3;
        const V dd = sub(dl[i], dl[k]);
        const V num = sub(l0[k], l0[i]);
        const V lo = mul(s0, dd), hi = mul(s1, dd);
        const M pos = gt(dd, zero), negd = lt(dd, zero);
        const M maybe =
            (pos & gt(num, lo) & lt(num, hi))
          | (negd & lt(num, lo) & gt(num, hi));
        const V q = _mm512_mask_div_pd(inf, maybe, num, dd);
        const M valid = maybe & gt(q, s0) & lt(q, s1);
        r[i] = _mm512_mask_blend_pd(valid, inf, q);
        found[i] = valid;
    }
    const V a = mn(r[0], r[1]), b = mx(r[0], r[1]);
    const V c = mn(b, r[2]), d = mx(b, r[2]);
    const V e = mn(a, c), f = mx(a, c);
    P[0] = s0;
    P[1] = mn(e, s1);
    P[2] = mn(f, s1);
    P[3] = mn(d, s1);
    P[4] = s1;
    return
        1 + ((found[0] | found[1] | found[2]) != 0)
      + (((found[0] & found[1]) | (found[0] & found[2]) | (found[1] & found[2])) != 0)
      + ((found[0] & found[1] & found[2]) != 0);
}


__attribute__((target("arch=x86-64-v4"))) void integrateEdgesV4
(
    edgeLanes* __restrict Lp,
    const callLanes* __restrict Cp,
    const double* __restrict v,
    const double* __restrict invM,
    const Foam::label n,
    const double frictionFactor,
    const double dt
)
{
    edgeLanes& L = *Lp;
    const callLanes& C = *Cp;
    const V zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
    const V three = _mm512_set1_pd(3);
    const V six = _mm512_set1_pd(6), half = _mm512_set1_pd(0.5);

    for (Foam::label j = 0; j < n; j += 8)
    {
        const __m256i kj = ldi(L.kj + j), k3j = ldi(L.k3j + j);
        const __m256i call = ldi(L.call + j);
        const __m256i nA = ldi(L.nA + j), nB = ldi(L.nB + j);
        const __m256i t0 = ldi(L.t0 + j);
        const V len = _mm512_sqrt_pd(gather(kj, C.len2[0]));
        const V dx = gather(kj, C.dx[0]), dy = gather(kj, C.dy[0]);
        const V s0 = gather(kj, C.s0[0]), s1 = gather(kj, C.s1[0]);
        V l0[3], dl[3];
        for (int i = 0; i < 3; ++i)
        {
            l0[i] = gather(k3j, C.l0[0][i]);
            dl[i] = gather(k3j, C.dl[0][i]);
        }

        V P[5];
        const int nPieces = piecePoints(l0, dl, s0, s1, P);

        const V iLen = _mm512_div_pd(one, len);
        const V tx = mul(dx, iLen), ty = mul(dy, iLen);
        const V nx = ty, ny = neg(tx);
        const __m256i nA2 = _mm256_slli_epi32(nA, 1);
        const __m256i nB2 = _mm256_slli_epi32(nB, 1);
        const V vAx = gather(nA2, v), vAy = gather(nA2, v + 1);
        const V vBx = gather(nB2, v), vBy = gather(nB2, v + 1);
        V vT[6];
        for (int i = 0; i < 3; ++i)
        {
            const __m256i ti =
                _mm256_slli_epi32(_mm256_add_epi32(t0, _mm256_set1_epi32(i)), 1);
            vT[2*i] = gather(ti, v);
            vT[2*i + 1] = gather(ti, v + 1);
        }
        const V p = gather(call, C.penalty), mu = gather(call, C.friction);
        // Friction regularisation eta = f/(invMMax len dt), mu > 0, with
        // invMMax = max(max(invM[nA], invM[nB]), the target's)
        const V invMMax =
            mx(mx(gather(nA, invM), gather(nB, invM)), gather(call, C.targetInvMMax));
        const V eta = _mm512_mask_div_pd
        (
            zero, gt(mu, zero), _mm512_set1_pd(frictionFactor),
            mul(mul(invMMax, len), _mm512_set1_pd(dt))
        );
        V fT[6];
        for (int i = 0; i < 6; ++i) fT[i] = zero;
        M any = 0;
        const M damped = gt(eta, zero);

        V lam[5][3], phi[5];
        for (int k = 0; k < 5; ++k)
        {
            for (int i = 0; i < 3; ++i)
            {
                lam[k][i] = mx(add(l0[i], mul(P[k], dl[i])), zero);
            }
            phi[k] = mul(three, mn(lam[k][0], mn(lam[k][1], lam[k][2])));
        }

        V fAx = zero, fAy = zero, fBx = zero, fBy = zero;
        for (int q = nPieces; q < 4; ++q)
        {
            _mm512_storeu_pd(L.friction[q] + j, zero);
            _mm512_storeu_pd(L.normal[q] + j, zero);
        }
        for (int q = 0; q < nPieces; ++q)
        {
            const V sa = P[q], sc = P[q + 1];
            const V pa = phi[q], pc = phi[q + 1];
            const M skip = le(pa, zero) & le(pc, zero);
            const V ell = mul(sub(sc, sa), len);
            const V e6 = _mm512_div_pd(ell, six);
            const V IA = integral(e6, pa, pc, sub(one, sa), sub(one, sc));
            const V IB = integral(e6, pa, pc, sa, sc);
            const V I = add(IA, IB);
            const M applied = ~skip & gt(I, zero);
            V IT[3];
            for (int i = 0; i < 3; ++i)
            {
                IT[i] = integral(e6, pa, pc, lam[q][i], lam[q + 1][i]);
            }
            const V ITsum = add(add(IT[0], IT[1]), IT[2]);

            // Friction at the piece's middle point
            const M fric = applied & damped;
            const V sm = mul(half, add(sa, sc));
            const V vcx = add(mul(sub(one, sm), vAx), mul(sm, vBx));
            const V vcy = add(mul(sub(one, sm), vAy), mul(sm, vBy));
            V li[3], vtx = zero, vty = zero;
            for (int i = 0; i < 3; ++i)
            {
                li[i] = mul(half, add(lam[q][i], lam[q + 1][i]));
                vtx = add(vtx, mul(li[i], vT[2*i]));
                vty = add(vty, mul(li[i], vT[2*i + 1]));
            }
            const V vt = add(mul(sub(vcx, vtx), tx), mul(sub(vcy, vty), ty));
            V ft = mn(mul(mul(mu, p), I), mul(mul(eta, _mm512_abs_pd(vt)), ell));
            ft = _mm512_mask_blend_pd(gt(vt, zero), ft, neg(ft));
            const V Gx = mul(ft, tx), Gy = mul(ft, ty);
            fAx = _mm512_mask_add_pd(fAx, fric, fAx, mul(sub(one, sm), Gx));
            fAy = _mm512_mask_add_pd(fAy, fric, fAy, mul(sub(one, sm), Gy));
            fBx = _mm512_mask_add_pd(fBx, fric, fBx, mul(sm, Gx));
            fBy = _mm512_mask_add_pd(fBy, fric, fBy, mul(sm, Gy));
            const V iL = _mm512_mask_div_pd
            (
                zero, fric, one, add(add(li[0], li[1]), li[2])
            );
            double* const tfOut[6] =
            {
                L.tf[q][0], L.tf[q][1], L.tf[q][2], L.tf[q][3], L.tf[q][4],
                L.tf[q][5]
            };
            shareWithTarget(li, iL, Gx, Gy, fric, tfOut, j, fT);

            // Normal force
            const V pnx = mul(neg(p), nx), pny = mul(neg(p), ny);
            fAx = _mm512_mask_add_pd(fAx, applied, fAx, mul(IA, pnx));
            fAy = _mm512_mask_add_pd(fAy, applied, fAy, mul(IA, pny));
            fBx = _mm512_mask_add_pd(fBx, applied, fBx, mul(IB, pnx));
            fBy = _mm512_mask_add_pd(fBy, applied, fBy, mul(IB, pny));
            const V rr = _mm512_mask_div_pd(zero, applied, I, ITsum);
            double* const tnOut[6] =
            {
                L.tn[q][0], L.tn[q][1], L.tn[q][2], L.tn[q][3], L.tn[q][4],
                L.tn[q][5]
            };
            shareWithTarget(IT, rr, pnx, pny, applied, tnOut, j, fT);
            any |= applied;
            _mm512_storeu_pd
            (
                L.friction[q] + j, _mm512_mask_blend_pd(fric, zero, one)
            );
            _mm512_storeu_pd
            (
                L.normal[q] + j, _mm512_mask_blend_pd(applied, zero, one)
            );
        }
        for (int i = 0; i < 6; ++i) _mm512_storeu_pd(L.fT[i] + j, fT[i]);
        _mm512_storeu_pd(L.any + j, _mm512_mask_blend_pd(any, zero, one));
        _mm512_storeu_pd(L.fA[0] + j, fAx);
        _mm512_storeu_pd(L.fA[1] + j, fAy);
        _mm512_storeu_pd(L.fB[0] + j, fBx);
        _mm512_storeu_pd(L.fB[1] + j, fBy);
    }
}




//- The edge tests of forEachCrossingEdge for 8 calls at a time, AVX-512
//  intrinsics: every test evaluated and combined (the same operations;
//  the clipping's divisions masked to the lanes that are not trivially
//  outside and divide, where dl is not 0)
__attribute__((target("arch=x86-64-v4"))) void testCallsV4
(
    callLanes* __restrict Cp,
    const Foam::label n
)
{
    callLanes& C = *Cp;
    const V zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1);
    for (Foam::label j = 0; j < n; j += 8)
    {
        const V box0 = ld(C.box[0] + j), box1 = ld(C.box[1] + j);
        const V box2 = ld(C.box[2] + j), box3 = ld(C.box[3] + j);
        const V iA2 = ld(C.iA2 + j);
        for (int k = 0; k < 3; ++k)
        {
            const int kB = k == 2 ? 0 : k + 1;
            const V Ax = ld(C.cx[2*k] + j), Ay = ld(C.cx[2*k + 1] + j);
            const V Bx = ld(C.cx[2*kB] + j), By = ld(C.cx[2*kB + 1] + j);
            const M boxOut =
                lt(mx(Ax, Bx), box0) | gt(mn(Ax, Bx), box2)
              | lt(mx(Ay, By), box1) | gt(mn(Ay, By), box3);
            const V dx = sub(Bx, Ax), dy = sub(By, Ay);
            const V len2 = add(mul(dx, dx), mul(dy, dy));
            V l0[3], dl[3];
            M outside = 0;
            for (int i = 0; i < 3; ++i)
            {
                const V exi = ld(C.ex[i] + j), eyi = ld(C.ey[i] + j);
                l0[i] = mul
                (
                    sub
                    (
                        mul(exi, sub(Ay, ld(C.ay[i] + j))),
                        mul(eyi, sub(Ax, ld(C.ax[i] + j)))
                    ),
                    iA2
                );
                dl[i] = mul(sub(mul(exi, dy), mul(eyi, dx)), iA2);
                outside |= le(l0[i], zero) & le(add(l0[i], dl[i]), zero);
            }
            V s0 = zero, s1 = one;
            for (int i = 0; i < 3; ++i)
            {
                const M below = lt(l0[i], zero);
                const M above = lt(add(l0[i], dl[i]), zero);
                const V r = _mm512_mask_div_pd
                (
                    zero, M(~outside & (below | above)), neg(l0[i]), dl[i]
                );
                s0 = _mm512_mask_blend_pd(below, s0, mx(s0, r));
                s1 = _mm512_mask_blend_pd(M(~below & above), s1, mn(s1, r));
                _mm512_storeu_pd(C.l0[k][i] + j, l0[i]);
                _mm512_storeu_pd(C.dl[k][i] + j, dl[i]);
            }
            const M crosses =
                gt(ld(C.valid[k] + j), zero) & ~boxOut & gt(len2, zero)
              & ~outside & gt(s1, s0);
            _mm512_storeu_pd(C.s0[k] + j, s0);
            _mm512_storeu_pd(C.s1[k] + j, s1);
            _mm512_storeu_pd(C.dx[k] + j, dx);
            _mm512_storeu_pd(C.dy[k] + j, dy);
            _mm512_storeu_pd(C.len2[k] + j, len2);
            _mm512_storeu_pd
            (
                C.crosses[k] + j, _mm512_mask_blend_pd(crosses, zero, one)
            );
        }
    }
}

//- Which of the n (<= 8) triangles tb = partner[0 .. n) have a box that
//  overlaps box (the broad phase's test of forEachContactPair, the same
//  comparisons of the same minima and maxima), leaving out halo partners
//  of a halo row (share: the node shares, null if not partitioned)
__attribute__((target("arch=x86-64-v4"))) unsigned overlapMaskV4
(
    const double* x,
    const double* share,
    const bool haloRow,
    const double box[4],
    const Foam::label* partner,
    const Foam::label n
)
{
    const M lanes = M((1u << n) - 1);
    const __m256i tb = _mm256_maskz_loadu_epi32(lanes, partner);
    const __m256i i6 = _mm256_mullo_epi32(tb, _mm256_set1_epi32(6));
    V c[6];
    for (int k = 0; k < 6; ++k)
    {
        c[k] = _mm512_mask_i32gather_pd
        (
            _mm512_setzero_pd(), lanes,
            _mm256_add_epi32(i6, _mm256_set1_epi32(k)), x, 8
        );
    }
    // (the operand order of setBox: min(T0, min(T1, T2)))
    const V xmin = mn(c[0], mn(c[2], c[4])), xmax = mx(c[0], mx(c[2], c[4]));
    const V ymin = mn(c[1], mn(c[3], c[5])), ymax = mx(c[1], mx(c[3], c[5]));
    const M apart =
        lt(_mm512_set1_pd(box[2]), xmin) | lt(xmax, _mm512_set1_pd(box[0]))
      | lt(_mm512_set1_pd(box[3]), ymin) | lt(ymax, _mm512_set1_pd(box[1]));
    M keep = M(lanes & ~apart);
    if (share && haloRow)
    {
        const __m256i i3 = _mm256_mullo_epi32(tb, _mm256_set1_epi32(3));
        const V sh = _mm512_mask_i32gather_pd
        (
            _mm512_setzero_pd(), lanes, i3, share, 8
        );
        keep = M(keep & ~_mm512_cmp_pd_mask(sh, _mm512_setzero_pd(), _CMP_EQ_OQ));
    }
    return keep;
}

#pragma GCC diagnostic pop
#endif

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::potential::potential(const dictionary& dict)
:
    contactLaw(dict),
    activeChanges_(-1),
    meanFreeEdges_(0),
    expired_(-1),
    nCandidates_(0),
    nActive_(0),
    frictionFactor_
    (
        dict.subOrEmptyDict("potentialCoeffs")
            .getOrDefault<scalar>("frictionRegularisation", 0.5)
    ),
    skin_
    (
        dict.subOrEmptyDict("potentialCoeffs")
            .getOrDefault<scalar>("skin", 0.2)
    ),
    nBuilds_(0)
{
    if (!(skin_ >= 0 && skin_ < 10))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'potentialCoeffs.skin' must lie in [0, 10) (a fraction"
            << " of the largest triangle box; 0: rebuild every step), got "
            << skin_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactLaws::potential::setActive(const femdemSolid& solid)
{
    const List<unsigned char>& free = solid.freeEdges();
    label n = 0;
    forAll(free, t) if (free[t]) ++n;
    active_.setCapacity(n);
    active_.setSize(n);
    n = 0;
    label nFree = 0;
    forAll(free, t)
    {
        if (!free[t]) continue;
        active_[n++] = t;
        for (label k = 0; k < 3; ++k) nFree += (free[t] >> k) & 1;
    }
    meanFreeEdges_ = n ? scalar(nFree)/n : 0;
    activeChanges_ = solid.freeEdgeChanges();

    const List<femdemMaterial>& mats = solid.materials();
    penalty_.setSize(mats.size());
    friction_.setSize(mats.size());
    forAll(mats, m)
    {
        penalty_[m] = mats[m].pc;
        friction_[m] = mats[m].friction;
    }
}


bool Foam::contactLaws::potential::joined
(
    const femdemSolid& solid,
    const label a,
    const label b
) const
{
    const labelList& edgeJoint = solid.topology().edgeJoint();
    const boolList& broken = solid.jointBroken();
    for (label k = 0; k < 3; ++k)
    {
        const label j = edgeJoint[3*a + k];
        if (j >= 0 && !broken[j])
        {
            if
            (
                solid.topology().jointTriangleA()[j] == b
             || solid.topology().jointTriangleB()[j] == b
            )
            {
                return true;
            }
        }
    }
    return false;
}


bool Foam::contactLaws::potential::listValid(const femdemSolid& solid) const
{
    if (grown_.size() != active_.size()) return false;
    const vector2D* x = solid.x().cdata();
    targetGeometry g;
    bool inside = true;
    forAll(active_, a)
    {
        g.setBox(x, active_[a]);
        const FixedList<float, 4>& G = grown_[a];
        // Written so that a NaN position counts as outside
        inside = inside
         && g.box[0] >= G[0] && g.box[1] >= G[1]
         && g.box[2] <= G[2] && g.box[3] <= G[3];
    }
    return inside;
}


Foam::label Foam::contactLaws::potential::binGrownBoxes(label& ny)
{
    const label nA = active_.size();
    scalar xmin = GREAT, ymin = GREAT, xmax = -GREAT, ymax = -GREAT;
    scalar extent = 0;
    for (const FixedList<float, 4>& b : grown_)
    {
        extent = max(extent, scalar(max(b[2] - b[0], b[3] - b[1])));
        xmin = min(xmin, scalar(b[0])); ymin = min(ymin, scalar(b[1]));
        xmax = max(xmax, scalar(b[2])); ymax = max(ymax, scalar(b[3]));
    }

    // Grid: cell >= largest box, at most ~1 cell per triangle
    scalar cs = max(extent, 1e-12*max(xmax - xmin, ymax - ymin) + VSMALL);
    label nx;
    while (true)
    {
        nx = label((xmax - xmin)/cs) + 1;
        ny = label((ymax - ymin)/cs) + 1;
        if (scalar(nx)*scalar(ny) <= nA + 64) break;
        cs *= 1.5;
    }
    const label nCells = nx*ny;
    auto cellOf = [&](const FixedList<float, 4>& b)
    {
        const label ix =
            min(label((0.5*(scalar(b[0]) + b[2]) - xmin)/cs), nx - 1);
        const label iy =
            min(label((0.5*(scalar(b[1]) + b[3]) - ymin)/cs), ny - 1);
        return ix + nx*iy;
    };

    // Counting sort: fill through the end pointers, then restore starts
    cellStart_.setSize(nCells + 1);
    for (label i = 0; i <= nCells; ++i) cellStart_[i] = 0;
    for (label a = 0; a < nA; ++a) ++cellStart_[cellOf(grown_[a]) + 1];
    for (label i = 0; i < nCells; ++i) cellStart_[i + 1] += cellStart_[i];
    sorted_.setSize(nA);
    for (label a = 0; a < nA; ++a) sorted_[cellStart_[cellOf(grown_[a])]++] = a;
    for (label i = nCells; i > 0; --i) cellStart_[i] = cellStart_[i - 1];
    cellStart_[0] = 0;
    return nx;
}


template<class Visitor>
void Foam::contactLaws::potential::forEachGrownPair
(
    const label nx,
    const label ny,
    Visitor& visit
) const
{
    auto tryPair = [&](const label a, const label b)
    {
        const FixedList<float, 4>& ba = grown_[a];
        const FixedList<float, 4>& bb = grown_[b];
        if (ba[2] < bb[0] || bb[2] < ba[0] || ba[3] < bb[1] || bb[3] < ba[1])
        {
            return;
        }
        visit(a, b);
    };
    for (label iy = 0; iy < ny; ++iy)
    {
        for (label ix = 0; ix < nx; ++ix)
        {
            const label cell = ix + nx*iy;
            const label start = cellStart_[cell], end = cellStart_[cell + 1];
            for (label i = start; i < end; ++i)
            {
                const label a = sorted_[i];
                for (label k = i + 1; k < end; ++k) tryPair(a, sorted_[k]);

                // Forward neighbours: (+1,-1) (+1,0) (+1,+1) (0,+1)
                const label nbx[4] = {ix + 1, ix + 1, ix + 1, ix};
                const label nby[4] = {iy - 1, iy, iy + 1, iy + 1};
                for (label m = 0; m < 4; ++m)
                {
                    if (nbx[m] >= nx || nby[m] < 0 || nby[m] >= ny) continue;
                    const label other = nbx[m] + nx*nby[m];
                    for
                    (
                        label k = cellStart_[other];
                        k < cellStart_[other + 1];
                        ++k
                    )
                    {
                        tryPair(a, sorted_[k]);
                    }
                }
            }
        }
    }
}


void Foam::contactLaws::potential::buildList(const femdemSolid& solid)
{
    ++nBuilds_;
    const label nA = active_.size();
    const vector2D* x = solid.x().cdata();

    // Present boxes, grown by skin/2 of the largest extent
    targetGeometry g;
    scalar extent = 0;
    for (label a = 0; a < nA; ++a)
    {
        g.setBox(x, active_[a]);
        extent = max(extent, max(g.box[2] - g.box[0], g.box[3] - g.box[1]));
    }
    const scalar h = 0.5*skin_*extent;
    fit(grown_, nA);
    for (label a = 0; a < nA; ++a)
    {
        g.setBox(x, active_[a]);
        FixedList<float, 4>& G = grown_[a];
        roundOutward(g.box[0] - h, g.box[2] + h, G[0], G[2]);
        roundOutward(g.box[1] - h, g.box[3] + h, G[1], G[3]);
    }

    label ny;
    const label nx = binGrownBoxes(ny);

    // Pairs as rows of the lower active index: the grid visited once, the
    // pairs not joined kept (lower and higher index) and counted per row,
    // then filled into the rows through the end pointers, the starts
    // restored and each row sorted
    fit(pairStart_, nA + 1);
    for (label a = 0; a <= nA; ++a) pairStart_[a] = 0;
    // (room for the last build's pairs and 1/8 more: few reallocations)
    const label room = partner_.size() + partner_.size()/8 + 16;
    pairLo_.clear();
    pairHi_.clear();
    pairLo_.setCapacity(room);
    pairHi_.setCapacity(room);
    auto keep = [&](const label a, const label b)
    {
        if (!joined(solid, active_[a], active_[b]))
        {
            const label lo = min(a, b);
            ++pairStart_[lo + 1];
            pairLo_.append(lo);
            pairHi_.append(max(a, b));
        }
    };
    forEachGrownPair(nx, ny, keep);
    for (label a = 0; a < nA; ++a) pairStart_[a + 1] += pairStart_[a];
    const label nPairs = pairStart_[nA];
    fit(partner_, nPairs);
    for (label k = 0; k < nPairs; ++k)
    {
        partner_[pairStart_[pairLo_[k]]++] = active_[pairHi_[k]];
    }
    for (label a = nA; a > 0; --a) pairStart_[a] = pairStart_[a - 1];
    pairStart_[0] = 0;
    // The grid and the pairs are needed again only at the next build
    cellStart_.clearStorage();
    sorted_.clearStorage();
    pairLo_.clearStorage();
    pairHi_.clearStorage();
    for (label a = 0; a < nA; ++a)
    {
        std::sort
        (
            partner_.begin() + pairStart_[a],
            partner_.begin() + pairStart_[a + 1]
        );
    }
}


template<class Sink>
void Foam::contactLaws::potential::forEachCrossingEdge
(
    const femdemSolid& solid,
    const label c,
    const targetGeometry& tg,
    Sink& sink
) const
{
    const unsigned char freeC = solid.freeEdges()[c];
    if (!freeC) return;

    const vector2D* x = solid.x().cdata();

    if (tg.A2 <= 0) return;
    const scalar iA2 = tg.iA2;
    const scalar tx0 = tg.box[0], ty0 = tg.box[1];
    const scalar tx1 = tg.box[2], ty1 = tg.box[3];
    const vector2D* const* T = tg.T;
    const scalar* ex = tg.ex;
    const scalar* ey = tg.ey;

    for (label k = 0; k < 3; ++k)
    {
        if (!(freeC & (1u << k))) continue;

        // (k + 1) % 3 without the integer division
        const label nA = 3*c + k, nB = 3*c + (k == 2 ? 0 : k + 1);
        const vector2D& A = x[nA];
        const vector2D& B = x[nB];

        // Edge outside the target's box: nothing to integrate
        if
        (
            max(A.x(), B.x()) < tx0 || min(A.x(), B.x()) > tx1
         || max(A.y(), B.y()) < ty0 || min(A.y(), B.y()) > ty1
        )
        {
            continue;
        }
        const scalar dx = B.x() - A.x(), dy = B.y() - A.y();
        const scalar len2 = dx*dx + dy*dy;
        if (len2 <= 0) continue;

        // lambda_i(s) = l0[i] + s dl[i]; trivial rejection (both ends
        // outside one side) before any division. An edge inside the
        // target passes the clipping below unchanged (s0 = 0, s1 = 1): it
        // is not flagged separately (the flag cost more than it saved).
        scalar l0[3], dl[3];
        bool outside = false;
        for (label i = 0; i < 3; ++i)
        {
            const vector2D& a = *T[i == 2 ? 0 : i + 1];
            l0[i] = (ex[i]*(A.y() - a.y()) - ey[i]*(A.x() - a.x()))*iA2;
            dl[i] = (ex[i]*dy - ey[i]*dx)*iA2;
            const scalar l1 = l0[i] + dl[i];
            if (l0[i] <= 0 && l1 <= 0) { outside = true; break; }
        }
        if (outside) continue;
        scalar s0 = 0, s1 = 1;
        for (label i = 0; i < 3; ++i)
        {
            const scalar l1 = l0[i] + dl[i];
            if (l0[i] < 0) s0 = max(s0, -l0[i]/dl[i]);
            else if (l1 < 0) s1 = min(s1, -l0[i]/dl[i]);
        }
        if (!(s1 > s0)) continue;
        const crossingEdge e
        {
            nA, nB, dx, dy, len2, {l0[0], l0[1], l0[2]},
            {dl[0], dl[1], dl[2]}, s0, s1
        };
        sink(e);
    }
}


bool Foam::contactLaws::potential::contactorTarget
(
    const femdemSolid& solid,
    const label c,
    const targetGeometry& tg,
    const scalar p,
    const scalar mu,
    const scalar dt,
    UList<vector2D>& f
) const
{
    bool any = false;
    scalar fT[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    auto integrate = [&](const crossingEdge& e)
    {
        integrateEdge(solid, e, tg, p, mu, dt, f, fT, any);
    };
    forEachCrossingEdge(solid, c, tg, integrate);
    if (any)
    {
        for (label i = 0; i < 3; ++i)
        {
            f[3*tg.t + i].x() += fT[i][0];
            f[3*tg.t + i].y() += fT[i][1];
        }
    }
    return any;
}


void Foam::contactLaws::potential::integrateEdge
(
    const femdemSolid& solid,
    const crossingEdge& e,
    const targetGeometry& tg,
    const scalar p,
    const scalar mu,
    const scalar dt,
    UList<vector2D>& f,
    scalar fT[3][2],
    bool& any
) const
{
    const label nA = e.nA, nB = e.nB;
    const scalar dx = e.dx, dy = e.dy, len2 = e.len2;
    const scalar* l0 = e.l0;
    const scalar* dl = e.dl;
    const scalar s0 = e.s0, s1 = e.s1;
    const vector2D* v = solid.v().cdata();
    const scalar* invM = solid.invMass().cdata();
    const label t = tg.t;
    // The length only for an edge that crosses the target
    const scalar len = std::sqrt(len2);

    // Break points where the minimum changes branch
    scalar sb[6];
    label nb = 0;
    sb[nb++] = s0;
    for (label i = 0; i < 3; ++i)
    {
        const label j = (i + 1) % 3;
        const scalar dd = dl[i] - dl[j];
        const scalar num = l0[j] - l0[i];
        // Divide only when r = num/dd may lie in (s0, s1)
        const bool maybe =
            dd > 0 ? (num > s0*dd && num < s1*dd)
          : dd < 0 ? (num < s0*dd && num > s1*dd)
          : false;
        if (maybe)
        {
            const scalar r = num/dd;
            if (r > s0 && r < s1) sb[nb++] = r;
        }
    }
    sb[nb++] = s1;
    // Insertion sort of the (at most 3) interior break points
    for (label i = 2; i < nb - 1; ++i)
    {
        const scalar key = sb[i];
        label m = i - 1;
        while (m >= 1 && sb[m] > key) { sb[m + 1] = sb[m]; --m; }
        sb[m + 1] = key;
    }

    // Outward normal and tangent of the contactor edge
    const scalar iLen = 1/len;
    const scalar tx = dx*iLen, ty = dy*iLen;
    const scalar nx = ty, ny = -tx;
    const vector2D& vA = v[nA];
    const vector2D& vB = v[nB];
    const label t0 = 3*t;

    // Friction regularisation from the lightest node involved
    scalar eta = 0;
    if (mu > 0)
    {
        const scalar invMMax =
            max(max(invM[nA], invM[nB]), tg.invMMax);
        eta = frictionFactor_/(invMMax*len*dt);
    }

    // Barycentric coordinates and potential at the break points: phi
    // and the shape functions are linear on each piece, so the
    // integrals of phi N are exact from the end values
    scalar lam[6][3], phi[6];
    for (label k = 0; k < nb; ++k)
    {
        for (label i = 0; i < 3; ++i)
        {
            lam[k][i] = max(l0[i] + sb[k]*dl[i], scalar(0));
        }
        phi[k] = 3*min(lam[k][0], min(lam[k][1], lam[k][2]));
    }

    scalar fAx = 0, fAy = 0, fBx = 0, fBy = 0;
    for (label q = 0; q + 1 < nb; ++q)
    {
        const scalar sa = sb[q], sc = sb[q + 1];
        const scalar pa = phi[q], pc = phi[q + 1];
        if (pa <= 0 && pc <= 0) continue;
        const scalar ell = (sc - sa)*len;

        // int phi L over the piece for L linear: ell/6 (2 pa La +
        // pa Lc + pc La + 2 pc Lc)
        auto integral = [&](const scalar La, const scalar Lc)
        {
            return ell/6*(2*pa*La + pa*Lc + pc*La + 2*pc*Lc);
        };
        const scalar IA = integral(1 - sa, 1 - sc);
        const scalar IB = integral(sa, sc);
        const scalar I = IA + IB;
        if (I <= 0) continue;
        scalar IT[3];
        for (label i = 0; i < 3; ++i)
        {
            IT[i] = integral(lam[q][i], lam[q + 1][i]);
        }
        const scalar ITsum = IT[0] + IT[1] + IT[2];

        // Friction of the piece at its middle point M: tangential force
        // -min(mu p int phi, eta |v_t| l) sign(v_t), applied at M (edge
        // shape functions / barycentric coordinates of M)
        if (eta > 0)
        {
            const scalar sm = 0.5*(sa + sc);
            const scalar vcx = (1 - sm)*vA.x() + sm*vB.x();
            const scalar vcy = (1 - sm)*vA.y() + sm*vB.y();
            scalar li[3], vtx = 0, vty = 0;
            for (label i = 0; i < 3; ++i)
            {
                li[i] = 0.5*(lam[q][i] + lam[q + 1][i]);
                vtx += li[i]*v[t0 + i].x();
                vty += li[i]*v[t0 + i].y();
            }
            const scalar vt = (vcx - vtx)*tx + (vcy - vty)*ty;
            scalar ft = min(mu*p*I, eta*mag(vt)*ell);
            if (vt > 0) ft = -ft;
            const scalar Gx = ft*tx, Gy = ft*ty;
            fAx += (1 - sm)*Gx; fAy += (1 - sm)*Gy;
            fBx += sm*Gx; fBy += sm*Gy;
            const scalar iL = 1/(li[0] + li[1] + li[2]);
            for (label i = 0; i < 3; ++i)
            {
                fT[i][0] -= li[i]*iL*Gx;
                fT[i][1] -= li[i]*iL*Gy;
            }
        }

        // Normal force F = -p I n_c on the contactor (int phi n), split
        // in the ratios IA/I, IB/I (contactor: F IA/I = -p IA n) and
        // IT/ITsum (target; ITsum = I but for round-off)
        const scalar pnx = -p*nx, pny = -p*ny;
        fAx += IA*pnx; fAy += IA*pny;
        fBx += IB*pnx; fBy += IB*pny;
        const scalar r = I/ITsum;
        for (label i = 0; i < 3; ++i)
        {
            const scalar wi = IT[i]*r;
            fT[i][0] -= wi*pnx;
            fT[i][1] -= wi*pny;
        }
        any = true;
    }
    f[nA].x() += fAx;
    f[nA].y() += fAy;
    f[nB].x() += fBx;
    f[nB].y() += fBy;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::contactLaws::potential::listExpired
(
    const femdemSolid& solid
) const
{
    return grown_.size() == active_.size() && !listValid(solid);
}


void Foam::contactLaws::potential::setListExpired(const bool expired)
{
    expired_ = expired;
}


void Foam::contactLaws::potential::addForces
(
    const femdemSolid& solid,
    UList<vector2D>& f,
    const scalar dt
)
{
    bool rebuild = skin_ == 0;
    if (activeChanges_ != solid.freeEdgeChanges() || penalty_.empty())
    {
        setActive(solid);
        rebuild = true;
    }
    nCandidates_ = 0;
    nActive_ = 0;
    const label nA = active_.size();
    if (nA < 2) return;
    // (a decision of setListExpired holds for this call only)
    const label decided = expired_;
    expired_ = -1;
    if (rebuild || decided == 1 || (decided < 0 && !listValid(solid)))
    {
        buildList(solid);
    }

#ifdef FEMDEM_CONTACT_LANES
    if (femdemSolid::vectorCode() == femdemSolid::AVX512 && meanFreeEdges_ >= 2)
    {
        addForcesLanes(solid, f, dt);
        return;
    }
#endif
    auto narrowPhase = [&]
    (
        const targetGeometry& ga,
        const targetGeometry& gb,
        const scalar p,
        const scalar mu
    )
    {
        const bool f1 = contactorTarget(solid, ga.t, gb, p, mu, dt, f);
        const bool f2 = contactorTarget(solid, gb.t, ga, p, mu, dt, f);
        if (f1 || f2) ++nActive_;
    };
    forEachContactPair<decltype(narrowPhase), false>(solid, narrowPhase);
}


template<class Visitor, bool Prefilter>
void Foam::contactLaws::potential::forEachContactPair
(
    const femdemSolid& solid,
    Visitor& visit
)
{
    const label nA = active_.size();
    const vector2D* x = solid.x().cdata();
    const scalar* invM = solid.invMass().cdata();
    const label* mat = solid.triangleMaterial().cdata();

    // A partitioned solid: a pair of two halo triangles pushes only halo
    // nodes, whose state their owners overwrite after the step (FEMDEM
    // nodes belong to one triangle each): skipped. A pair with an owned
    // triangle is computed as in the whole solid, bitwise
    const scalar* share =
        solid.nodeShares().empty() ? nullptr : solid.nodeShares().cdata();

    // Rows in the order of the lower triangle, partners ascending: the
    // order of the forces does not depend on the build
    // (value-initialised: GCC cannot see that setShape always runs before
    // a visit)
    targetGeometry ga{}, gb{};
    for (label a = 0; a < nA; ++a)
    {
        const label end = pairStart_[a + 1];
        label k = pairStart_[a];
        if (k == end) continue;
        const label ta = active_[a];
        const bool haloA = share && share[3*ta] == 0;
        ga.setBox(x, ta);
        bool gaShape = false;
        auto pair = [&](const label tb)
        {
            if (!gaShape)
            {
                ga.setShape(invM);
                gaShape = true;
            }
            gb.setShape(invM);
            ++nCandidates_;
            const scalar p = max(penalty_[mat[ta]], penalty_[mat[tb]]);
            const scalar mu = min(friction_[mat[ta]], friction_[mat[tb]]);
            visit(ga, gb, p, mu);
        };
#ifdef FEMDEM_CONTACT_LANES
        if (Prefilter)
        {
            // The box tests 8 partners at a time: the pairs that overlap
            // in the list's order
            for (; k < end; k += 8)
            {
                unsigned m = overlapMaskV4
                (
                    &x[0].x(), share, haloA, ga.box, partner_.cdata() + k,
                    min(label(8), end - k)
                );
                while (m)
                {
                    const label tb = partner_[k + __builtin_ctz(m)];
                    m &= m - 1;
                    gb.setBox(x, tb);
                    pair(tb);
                }
            }
            continue;
        }
#endif
        for (; k < end; ++k)
        {
            const label tb = partner_[k];
            if (haloA && share[3*tb] == 0) continue;
            gb.setBox(x, tb);
            if (!ga.overlaps(gb)) continue;
            pair(tb);
        }
    }
}


#ifdef FEMDEM_CONTACT_LANES
void Foam::contactLaws::potential::addForcesLanes
(
    const femdemSolid& solid,
    UList<vector2D>& f,
    const scalar dt
)
{
    // Blocks of calls (both calls of each pair, contactor the lower
    // triangle first): their edge tests 8 calls at a time (testCallsV4),
    // the edges that cross their targets gathered in the calls' order and
    // integrated 8 at a time (integrateEdgesV4), then their forces added
    // call by call in the pairs' order, as contactorTarget adds them
    const vector2D* x = solid.x().cdata();
    const List<unsigned char>& freeEdges = solid.freeEdges();
    callLanes C;
    edgeLanes L;
    static_assert(edgeLanes::size >= 3*callLanes::size, "edge lanes");
    label nCalls = 0;

    // Lane j: contactor c against target tg
    auto setCall = [&]
    (
        const label j,
        const label c,
        const targetGeometry& tg,
        const scalar p,
        const scalar mu
    )
    {
        C.contactor[j] = c;
        C.target[j] = tg.t;
        C.targetInvMMax[j] = tg.invMMax;
        C.penalty[j] = p;
        C.friction[j] = mu;
        for (label k = 0; k < 3; ++k)
        {
            C.cx[2*k][j] = x[3*c + k].x();
            C.cx[2*k + 1][j] = x[3*c + k].y();
            C.valid[k][j] = (freeEdges[c] & (1u << k)) && tg.A2 > 0 ? 1 : 0;
            const vector2D& a = *tg.T[k == 2 ? 0 : k + 1];
            C.ax[k][j] = a.x();
            C.ay[k][j] = a.y();
            C.ex[k][j] = tg.ex[k];
            C.ey[k][j] = tg.ey[k];
        }
        for (label m = 0; m < 4; ++m) C.box[m][j] = tg.box[m];
        C.iA2[j] = tg.iA2;
    };

    auto flush = [&]()
    {
        testCallsV4(&C, C.pad(nCalls));
        const label ne = L.gather(C, nCalls);
        if (ne)
        {
            integrateEdgesV4
            (
                &L, &C, &solid.v()[0].x(), solid.invMass().cdata(), ne,
                frictionFactor_, dt
            );
        }
        nActive_ += addLaneForces(C, L, nCalls, f);
        nCalls = 0;
    };

    auto collect = [&]
    (
        const targetGeometry& ga,
        const targetGeometry& gb,
        const scalar p,
        const scalar mu
    )
    {
        setCall(nCalls, ga.t, gb, p, mu);
        setCall(nCalls + 1, gb.t, ga, p, mu);
        nCalls += 2;
        if (nCalls == callLanes::size) flush();
    };
    forEachContactPair<decltype(collect), true>(solid, collect);
    if (nCalls) flush();
}


#endif


void Foam::contactLaws::potential::addPairCounts(UList<label>& count) const
{
    // The list of the last build (none before the first)
    if (pairStart_.size() != active_.size() + 1) return;
    for (label a = 0; a < active_.size(); ++a)
    {
        for (label i = pairStart_[a]; i < pairStart_[a + 1]; ++i)
        {
            ++count[active_[a]];
            ++count[partner_[i]];
        }
    }
}


std::size_t Foam::contactLaws::potential::memoryBytes() const
{
    return
        active_.capacity()*sizeof(label)
      + grown_.capacity()*sizeof(FixedList<float, 4>)
      + pairStart_.capacity()*sizeof(label)
      + partner_.capacity()*sizeof(label)
      + cellStart_.capacity()*sizeof(label)
      + sorted_.capacity()*sizeof(label)
      + pairLo_.capacity()*sizeof(label)
      + pairHi_.capacity()*sizeof(label);
}


// ************************************************************************* //

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

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::potential::potential(const dictionary& dict)
:
    contactLaw(dict),
    activeChanges_(-1),
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
    forAll(free, t) if (free[t]) active_[n++] = t;
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

    // Pairs as rows of the lower active index: count, then fill through
    // the end pointers, then restore the starts and sort each row
    fit(pairStart_, nA + 1);
    for (label a = 0; a <= nA; ++a) pairStart_[a] = 0;
    auto count = [&](const label a, const label b)
    {
        if (!joined(solid, active_[a], active_[b])) ++pairStart_[min(a, b) + 1];
    };
    forEachGrownPair(nx, ny, count);
    for (label a = 0; a < nA; ++a) pairStart_[a + 1] += pairStart_[a];
    const label nPairs = pairStart_[nA];
    fit(partner_, nPairs);
    auto fill = [&](const label a, const label b)
    {
        if (!joined(solid, active_[a], active_[b]))
        {
            partner_[pairStart_[min(a, b)]++] = active_[max(a, b)];
        }
    };
    forEachGrownPair(nx, ny, fill);
    for (label a = nA; a > 0; --a) pairStart_[a] = pairStart_[a - 1];
    pairStart_[0] = 0;
    // The grid is needed again only at the next build
    cellStart_.clearStorage();
    sorted_.clearStorage();
    for (label a = 0; a < nA; ++a)
    {
        std::sort
        (
            partner_.begin() + pairStart_[a],
            partner_.begin() + pairStart_[a + 1]
        );
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
    const unsigned char freeC = solid.freeEdges()[c];
    if (!freeC) return false;

    const vector2D* x = solid.x().cdata();
    const vector2D* v = solid.v().cdata();
    const scalar* invM = solid.invMass().cdata();

    const label t = tg.t;
    if (tg.A2 <= 0) return false;
    const scalar iA2 = tg.iA2;
    const scalar tx0 = tg.box[0], ty0 = tg.box[1];
    const scalar tx1 = tg.box[2], ty1 = tg.box[3];
    const vector2D* const* T = tg.T;
    const scalar* ex = tg.ex;
    const scalar* ey = tg.ey;

    bool any = false;
    scalar fT[3][2] = {{0, 0}, {0, 0}, {0, 0}};
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
    if (any)
    {
        for (label i = 0; i < 3; ++i)
        {
            f[3*t + i].x() += fT[i][0];
            f[3*t + i].y() += fT[i][1];
        }
    }
    return any;
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
    targetGeometry ga, gb;
    for (label a = 0; a < nA; ++a)
    {
        const label end = pairStart_[a + 1];
        label k = pairStart_[a];
        if (k == end) continue;
        const label ta = active_[a];
        const bool haloA = share && share[3*ta] == 0;
        ga.setBox(x, ta);
        bool gaShape = false;
        for (; k < end; ++k)
        {
            const label tb = partner_[k];
            if (haloA && share[3*tb] == 0) continue;
            gb.setBox(x, tb);
            if (!ga.overlaps(gb)) continue;
            if (!gaShape)
            {
                ga.setShape(invM);
                gaShape = true;
            }
            gb.setShape(invM);
            ++nCandidates_;
            const scalar p = max(penalty_[mat[ta]], penalty_[mat[tb]]);
            const scalar mu = min(friction_[mat[ta]], friction_[mat[tb]]);
            const bool f1 = contactorTarget(solid, ta, gb, p, mu, dt, f);
            const bool f2 = contactorTarget(solid, tb, ga, p, mu, dt, f);
            if (f1 || f2) ++nActive_;
        }
    }
}


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
      + sorted_.capacity()*sizeof(label);
}


// ************************************************************************* //

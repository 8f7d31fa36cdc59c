/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "potentialContact.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(potential, 0);
    addToRunTimeSelectionTable(contactLaw, potential, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaws::potential::potential(const dictionary& dict)
:
    contactLaw(dict),
    activeBroken_(-1),
    nCandidates_(0),
    nActive_(0),
    frictionFactor_
    (
        dict.subOrEmptyDict("potentialCoeffs")
            .getOrDefault<scalar>("frictionRegularisation", 0.5)
    )
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::contactLaws::potential::setActive(const femdemSolid& solid)
{
    active_.clear();
    const List<unsigned char>& free = solid.freeEdges();
    forAll(free, t)
    {
        if (free[t]) active_.append(t);
    }
    activeBroken_ = solid.nBrokenJoints();

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


bool Foam::contactLaws::potential::contactorTarget
(
    const femdemSolid& solid,
    const label c,
    const label t,
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

    const vector2D& T0 = x[3*t];
    const vector2D& T1 = x[3*t + 1];
    const vector2D& T2 = x[3*t + 2];
    const scalar A2 =
        (T1.x() - T0.x())*(T2.y() - T0.y()) - (T1.y() - T0.y())*(T2.x() - T0.x());
    if (A2 <= 0) return false;
    const scalar iA2 = 1/A2;
    const scalar tx0 = min(T0.x(), min(T1.x(), T2.x()));
    const scalar tx1 = max(T0.x(), max(T1.x(), T2.x()));
    const scalar ty0 = min(T0.y(), min(T1.y(), T2.y()));
    const scalar ty1 = max(T0.y(), max(T1.y(), T2.y()));

    // Barycentric coordinate of vertex i: cross(T_{i+2} - T_{i+1}, P - T_{i+1})/A2
    const vector2D* T[3] = {&T0, &T1, &T2};
    scalar ex[3], ey[3];
    for (label i = 0; i < 3; ++i)
    {
        const vector2D& a = *T[(i + 1) % 3];
        const vector2D& b = *T[(i + 2) % 3];
        ex[i] = b.x() - a.x();
        ey[i] = b.y() - a.y();
    }

    bool any = false;
    scalar fT[3][2] = {{0, 0}, {0, 0}, {0, 0}};
    for (label k = 0; k < 3; ++k)
    {
        if (!(freeC & (1u << k))) continue;

        const label nA = 3*c + k, nB = 3*c + (k + 1) % 3;
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
        const scalar len = std::sqrt(dx*dx + dy*dy);
        if (len <= 0) continue;

        // lambda_i(s) = l0[i] + s dl[i]; trivial rejection (both ends
        // outside one side) before any division
        scalar l0[3], dl[3];
        bool outside = false, inside = true;
        for (label i = 0; i < 3; ++i)
        {
            const vector2D& a = *T[(i + 1) % 3];
            l0[i] = (ex[i]*(A.y() - a.y()) - ey[i]*(A.x() - a.x()))*iA2;
            dl[i] = (ex[i]*dy - ey[i]*dx)*iA2;
            const scalar l1 = l0[i] + dl[i];
            if (l0[i] <= 0 && l1 <= 0) { outside = true; break; }
            if (l0[i] < 0 || l1 < 0) inside = false;
        }
        if (outside) continue;
        scalar s0 = 0, s1 = 1;
        if (!inside)
        {
            for (label i = 0; i < 3; ++i)
            {
                const scalar l1 = l0[i] + dl[i];
                if (l0[i] < 0) s0 = max(s0, -l0[i]/dl[i]);
                else if (l1 < 0) s1 = min(s1, -l0[i]/dl[i]);
            }
        }
        if (!(s1 > s0)) continue;

        // Break points where the minimum changes branch
        scalar sb[6];
        label nb = 0;
        sb[nb++] = s0;
        for (label i = 0; i < 3; ++i)
        {
            const label j = (i + 1) % 3;
            const scalar dd = dl[i] - dl[j];
            if (dd != 0)
            {
                const scalar r = (l0[j] - l0[i])/dd;
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
        const scalar tx = dx/len, ty = dy/len;
        const scalar nx = ty, ny = -tx;
        const vector2D& vA = v[nA];
        const vector2D& vB = v[nB];
        const label t0 = 3*t;

        // Friction regularisation from the lightest node involved
        scalar eta = 0;
        if (mu > 0)
        {
            const scalar invMMax = max
            (
                max(invM[nA], invM[nB]),
                max(invM[t0], max(invM[t0 + 1], invM[t0 + 2]))
            );
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

            // Normal: -p phi n_c on the contactor
            scalar Fx = -p*I*nx, Fy = -p*I*ny;

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

            const scalar wA = IA/I, wB = IB/I;
            fAx += wA*Fx; fAy += wA*Fy;
            fBx += wB*Fx; fBy += wB*Fy;
            for (label i = 0; i < 3; ++i)
            {
                const scalar wi = IT[i]/ITsum;
                fT[i][0] -= wi*Fx;
                fT[i][1] -= wi*Fy;
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

void Foam::contactLaws::potential::addForces
(
    const femdemSolid& solid,
    UList<vector2D>& f,
    const scalar dt
)
{
    if (activeBroken_ != solid.nBrokenJoints() || penalty_.empty())
    {
        setActive(solid);
    }
    nCandidates_ = 0;
    nActive_ = 0;
    const label nA = active_.size();
    if (nA < 2) return;

    const vector2D* x = solid.x().cdata();
    const label* mat = solid.triangleMaterial().cdata();

    // Bounding boxes
    box_.setSize(nA);
    scalar xmin = GREAT, ymin = GREAT, xmax = -GREAT, ymax = -GREAT;
    scalar extent = 0;
    for (label a = 0; a < nA; ++a)
    {
        const label t = active_[a];
        const vector2D& p0 = x[3*t];
        const vector2D& p1 = x[3*t + 1];
        const vector2D& p2 = x[3*t + 2];
        FixedList<scalar, 4>& b = box_[a];
        b[0] = min(p0.x(), min(p1.x(), p2.x()));
        b[1] = min(p0.y(), min(p1.y(), p2.y()));
        b[2] = max(p0.x(), max(p1.x(), p2.x()));
        b[3] = max(p0.y(), max(p1.y(), p2.y()));
        extent = max(extent, max(b[2] - b[0], b[3] - b[1]));
        xmin = min(xmin, b[0]); ymin = min(ymin, b[1]);
        xmax = max(xmax, b[2]); ymax = max(ymax, b[3]);
    }

    // Grid: cell >= largest box, at most ~4 cells per triangle
    scalar cs = max(extent, 1e-12*max(xmax - xmin, ymax - ymin) + VSMALL);
    label nx, ny;
    while (true)
    {
        nx = label((xmax - xmin)/cs) + 1;
        ny = label((ymax - ymin)/cs) + 1;
        if (scalar(nx)*scalar(ny) <= 4.0*nA + 64) break;
        cs *= 1.5;
    }
    const label nCells = nx*ny;

    cellStart_.setSize(nCells + 1);
    for (label i = 0; i <= nCells; ++i) cellStart_[i] = 0;
    cellOf_.setSize(nA);
    for (label a = 0; a < nA; ++a)
    {
        const FixedList<scalar, 4>& b = box_[a];
        const label ix = min(label((0.5*(b[0] + b[2]) - xmin)/cs), nx - 1);
        const label iy = min(label((0.5*(b[1] + b[3]) - ymin)/cs), ny - 1);
        cellOf_[a] = ix + nx*iy;
        ++cellStart_[cellOf_[a] + 1];
    }
    for (label i = 0; i < nCells; ++i) cellStart_[i + 1] += cellStart_[i];
    sorted_.setSize(nA);
    {
        // Fill using the end pointers, then restore the starts
        for (label a = 0; a < nA; ++a) sorted_[cellStart_[cellOf_[a]]++] = a;
        for (label i = nCells; i > 0; --i) cellStart_[i] = cellStart_[i - 1];
        cellStart_[0] = 0;
    }

    auto tryPair = [&](const label a, const label b)
    {
        const FixedList<scalar, 4>& ba = box_[a];
        const FixedList<scalar, 4>& bb = box_[b];
        if
        (
            ba[2] < bb[0] || bb[2] < ba[0] || ba[3] < bb[1] || bb[3] < ba[1]
        )
        {
            return;
        }
        const label ta = active_[a], tb = active_[b];
        if (joined(solid, ta, tb)) return;
        ++nCandidates_;
        const scalar p = max(penalty_[mat[ta]], penalty_[mat[tb]]);
        const scalar mu = min(friction_[mat[ta]], friction_[mat[tb]]);
        const bool f1 = contactorTarget(solid, ta, tb, p, mu, dt, f);
        const bool f2 = contactorTarget(solid, tb, ta, p, mu, dt, f);
        if (f1 || f2) ++nActive_;
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


std::size_t Foam::contactLaws::potential::memoryBytes() const
{
    return
        active_.capacity()*sizeof(label)
      + box_.capacity()*sizeof(FixedList<scalar, 4>)
      + cellOf_.capacity()*sizeof(label)
      + cellStart_.capacity()*sizeof(label)
      + sorted_.capacity()*sizeof(label);
}


// ************************************************************************* //

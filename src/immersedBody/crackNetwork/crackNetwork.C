/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackNetwork.H"
#include "caseChecks.H"
#include <algorithm>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    // The crack gas's flux scheme: Kurganov-Tadmor unless chosen. Gas
    // rushing into an emptied crack meets near-vacuum states, where HLLC
    // (Davis speeds) gave a crack 7e-6 kg/m3 at 4 bar (c = 3e5 m/s) and
    // 1e6 gas sub-steps per fluid step in the first coupled runs
    Foam::dictionary withFlux(const Foam::dictionary& dict)
    {
        Foam::dictionary d(dict);
        if (!d.found("flux"))
        {
            d.add("flux", Foam::word("KurganovTadmor"));
        }
        return d;
    }
}


namespace
{
    // The entries of a list, ascending, once each
    Foam::labelList uniqueSorted(Foam::DynamicList<Foam::label>&& n)
    {
        Foam::labelList sorted(std::move(n));
        Foam::sort(sorted);
        Foam::label m = 0;
        forAll(sorted, i)
        {
            if (i == 0 || sorted[i] != sorted[m - 1]) sorted[m++] = sorted[i];
        }
        sorted.setSize(m);
        return sorted;
    }
}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::crackNetwork::subStepBound>
Foam::crackNetwork::subStepBoundNames
({
    { subStepBound::solid, "solid" },
    { subStepBound::gasSpring, "gasSpring" },
    { subStepBound::volumeChange, "volumeChange" },
    { subStepBound::acceleration, "acceleration" },
    { subStepBound::voidSpring, "voidSpring" },
    { subStepBound::voidVolumeChange, "voidVolumeChange" },
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::crackNetwork::crackNetwork
(
    const jointTopology& topology,
    const blastMixture& mixture,
    const dictionary& dict
)
:
    topo_(topology),
    mixture_(mixture),
    gas_(mixture, withFlux(dict)),
    minAperture_(dict.getOrDefault<scalar>("minAperture", 1e-6)),
    maxVolumeChange_(dict.getOrDefault<scalar>("maxVolumeChange", 0.1)),
    subStepBounds_(Zero),
    ambientRho_(1.2),
    ambientP_(1e5),
    jointCV_(topology.nJoints(), -1),
    restricted_(false),
    localNodes_(false),
    createdMass_(0),
    createdEnergy_(0),
    removedMass_(0),
    removedEnergy_(0),
    nGasSubSteps_(0)
{
    setVertexFans();
    if (!(minAperture_ > 0) || !std::isfinite(minAperture_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'minAperture' must be a length > 0, got "
            << minAperture_ << exit(FatalIOError);
    }
    if (!(maxVolumeChange_ > 0) || !(maxVolumeChange_ <= 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'maxVolumeChange' must be a fraction in (0, 0.5], got "
            << maxVolumeChange_ << exit(FatalIOError);
    }
    if (dict.found("ambient"))
    {
        const dictionary& a = dict.subDict("ambient");
        ambientRho_ = a.get<scalar>("rho");
        ambientP_ = a.get<scalar>("p");
        if (!(ambientRho_ > 0) || !(ambientP_ > 0))
        {
            FatalIOErrorInFunction(a)
                << "Entries 'rho' and 'p' of 'ambient' must be > 0, got "
                << ambientRho_ << " and " << ambientP_ << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::crackNetwork::jointGeometry
(
    const jointNodeList& jn,
    const UList<vector2D>& x,
    scalar& area,
    scalar& L,
    vector2D& n,
    scalar& g0,
    scalar& g1
) const
{
    const vector2D& p0 = x[jn[0]];
    const vector2D& p1 = x[jn[1]];
    const vector2D& q0 = x[jn[2]];
    const vector2D& q1 = x[jn[3]];
    const vector2D d = p1 - p0;
    L = mag(d);
    n = vector2D(d.y(), -d.x())/max(L, VSMALL);
    g0 = (q0 - p0) & n;
    g1 = (q1 - p1) & n;
    // The trapezoid of the openings, each end's opening g + minAperture (a
    // closed crack keeps minAperture; faces pressed further into each other
    // count as closed), at least L minAperture/2. A sheared gap's
    // quadrilateral can twist to no area while its ends are open, and the
    // interfaces, as wide as the openings, would then face a volume they
    // could empty many times in a step
    const scalar a = minAperture_;
    area = max
    (
        0.5*L*(max(g0 + a, scalar(0)) + max(g1 + a, scalar(0))),
        0.5*L*a
    );
}


void Foam::crackNetwork::gapForces
(
    const jointNodeList& jn,
    const UList<vector2D>& x,
    const bool floored,
    const scalar* open,
    const scalar p,
    FixedList<vector2D, 4>& f
) const
{
    // f = p grad V of the gap area of jointGeometry. With d = p1 - p0,
    // L n = (d.y, -d.x) and w_e = q_e - p_e, an open end contributes
    // (w_e.(L n) + a L)/2: its gradient is +-L n/2 on q_e and p_e, and,
    // through d, +-(rot90(w_e) + a t)/2 on p1 and p0 (rot90(w) =
    // (-w.y, w.x) = g t - s n for w = g n + s t: the faces' offset along
    // the joint turns them). Without these, a sheared gap closed at one end
    // had its volume change by rotation while its forces did no work:
    // squeezed, its gas lost energy instead of gaining it. At the floor
    // (L a/2) and at a shut end: no force (no volume to pay work from)
    f = vector2D::zero;
    if (floored || !(p > 0)) return;
    const scalar a = minAperture_;
    const vector2D d = x[jn[1]] - x[jn[0]];
    const scalar L = mag(d);
    if (!(L > 0)) return;
    const vector2D Ln(d.y(), -d.x()), t(d/L);
    for (const label e : {0, 1})
    {
        if (!(open[e] + a > 0)) continue;
        const vector2D w = x[jn[2 + e]] - x[jn[e]];
        const vector2D turn = 0.5*p*(vector2D(-w.y(), w.x()) + a*t);
        f[2 + e] += 0.5*p*Ln;
        f[e] -= 0.5*p*Ln;
        f[1] += turn;
        f[0] -= turn;
    }
}


Foam::scalarField Foam::crackNetwork::gapAreas(const UList<vector2D>& x) const
{
    scalarField V(cvJoint_.size());
    forAll(cvJoint_, i)
    {
        scalar L, g0, g1;
        vector2D n;
        jointGeometry(topo_.jointNodes()[cvJoint_[i]], x, V[i], L, n, g0, g1);
    }
    addVoidShares(x, V);
    return V;
}


void Foam::crackNetwork::setVertexFans()
{
    const labelList& nodeVertex = topo_.nodeVertex();
    const List<vector2D>& X0 = topo_.initialPoints();
    const label nV = X0.size();
    vertexOnBoundary_.setSize(nV);
    vertexOnBoundary_ = false;
    forAll(topo_.boundaryTriangle(), b)
    {
        const label t = topo_.boundaryTriangle()[b];
        const label k = topo_.boundaryEdge()[b];
        vertexOnBoundary_[nodeVertex[jointTopology::node(t, k)]] = true;
        vertexOnBoundary_[nodeVertex[jointTopology::node(t, (k + 1)%3)]] = true;
    }
    vertexOpen_.setSize(nV);
    vertexOpen_ = false;

    // The nodes of each vertex, in the order of their triangles' centroids
    // around it (counter-clockwise): the corners of the void there, in the
    // order that gives a void opening between separating triangles a
    // positive area
    vertexNodeStart_.setSize(nV + 1);
    vertexNodeStart_ = 0;
    forAll(nodeVertex, n) ++vertexNodeStart_[nodeVertex[n] + 1];
    for (label v = 0; v < nV; ++v)
    {
        vertexNodeStart_[v + 1] += vertexNodeStart_[v];
    }
    vertexNode_.setSize(nodeVertex.size());
    labelList fillAt(SubList<label>(vertexNodeStart_, nV));
    forAll(nodeVertex, n) vertexNode_[fillAt[nodeVertex[n]]++] = n;
    DynamicList<std::pair<scalar, label>> fan;
    for (label v = 0; v < nV; ++v)
    {
        fan.clear();
        for (label k = vertexNodeStart_[v]; k < vertexNodeStart_[v + 1]; ++k)
        {
            const label n = vertexNode_[k], t = n/3;
            const vector2D c =
                (
                    X0[nodeVertex[3*t]] + X0[nodeVertex[3*t + 1]]
                  + X0[nodeVertex[3*t + 2]]
                )/3 - X0[v];
            fan.append({std::atan2(c.y(), c.x()), n});
        }
        std::sort(fan.begin(), fan.end());
        forAll(fan, i) vertexNode_[vertexNodeStart_[v] + i] = fan[i].second;
    }
}


void Foam::crackNetwork::setVoids()
{
    // A void where m >= 2 cracks of the network meet at a vertex inside the
    // solid: not on its outline (the void would open onto the outside) and
    // touched by no joint open to the fluid mesh (its gas is the mesh's)
    DynamicList<label> vertex, cvStart(1, 0), cv, cornerStart(1, 0);
    for (label a = 0; a < ends_.size(); )
    {
        label b = a;
        while (b < ends_.size() && ends_[b][0] == ends_[a][0]) ++b;
        const label v = ends_[a][0];
        if (b - a >= 2 && !vertexOnBoundary_[v] && !vertexOpen_[v])
        {
            vertex.append(v);
            for (label k = a; k < b; ++k) cv.append(ends_[k][1]);
            cvStart.append(cv.size());
            cornerStart.append
            (
                cornerStart.last()
              + vertexNodeStart_[v + 1] - vertexNodeStart_[v]
            );
        }
        a = b;
    }
    voidVertex_.transfer(vertex);
    voidCVStart_.transfer(cvStart);
    voidCV_.transfer(cv);
    voidCornerStart_.transfer(cornerStart);
    const label nc = voidCornerStart_.last();
    voidNode_.setSize(nc);
    forAll(voidVertex_, k)
    {
        const label s = vertexNodeStart_[voidVertex_[k]];
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            voidNode_[c] = vertexNode_[s + c - voidCornerStart_[k]];
        }
    }
    voidArea_.setSize(voidVertex_.size());
    voidArea_ = 0;
    voidGrad_.setSize(nc);
    voidGrad_ = Zero;
    voidForce_.setSize(nc);
    voidForce_ = Zero;
    voidDLast_.setSize(nc);
    voidDLast_ = Zero;
}


Foam::scalar Foam::crackNetwork::voidArea
(
    const label k,
    const UList<vector2D>& x,
    vector2D* grad
) const
{
    // The polygon of the corners (shoelace, about the first corner). Less
    // minAperture^2, so that the round-off area of the corners of a
    // straight crack through the vertex (two rows of coincident corners)
    // counts for nothing and pushes nothing; the gradient of that area is
    // the force per unit pressure on each corner (the volume's gradient,
    // as for the gaps: the gas pays exactly the work it does)
    const label* node = &cornerNodes()[voidCornerStart_[k]];
    const label K = voidCornerStart_[k + 1] - voidCornerStart_[k];
    const vector2D& o = x[node[0]];
    scalar twiceA = 0;
    for (label i = 0; i < K; ++i)
    {
        const vector2D a = x[node[i]] - o;
        const vector2D b = x[node[(i + 1)%K]] - o;
        twiceA += a.x()*b.y() - a.y()*b.x();
    }
    const scalar A = 0.5*twiceA - sqr(minAperture_);
    if (grad)
    {
        for (label i = 0; i < K; ++i)
        {
            const vector2D& prev = x[node[(i + K - 1)%K]];
            const vector2D& next = x[node[(i + 1)%K]];
            grad[i] =
                A > 0
              ? 0.5*vector2D(next.y() - prev.y(), prev.x() - next.x())
              : vector2D::zero;
        }
    }
    return max(A, scalar(0));
}


void Foam::crackNetwork::addVoidShares
(
    const UList<vector2D>& x,
    scalarField& V
) const
{
    forAll(voidVertex_, k)
    {
        const scalar A = voidArea(k, x);
        const label c0 = voidCVStart_[k], c1 = voidCVStart_[k + 1];
        for (label c = c0; c < c1; ++c) V[voidCV_[c]] += A/(c1 - c0);
    }
}


Foam::scalar Foam::crackNetwork::voidsArea(const UList<vector2D>& x) const
{
    scalar A = 0;
    forAll(voidVertex_, k) A += voidArea(k, x);
    return A;
}


bool Foam::crackNetwork::setOpenJoints(const boolList& open)
{
    if (open.size() != topo_.nJoints())
    {
        FatalErrorInFunction
            << "crackNetwork: " << open.size() << " open flags for "
            << topo_.nJoints() << " joints" << exit(FatalError);
    }
    const labelList& nodeVertex = topo_.nodeVertex();
    // (called every step: the flags go into a kept work list)
    boolList& vo = vertexOpenNew_;
    vo.setSize(vertexOpen_.size());
    vo = false;
    forAll(open, j)
    {
        if (!open[j]) continue;
        const jointNodeList& jn = topo_.jointNodes()[j];
        vo[nodeVertex[jn[0]]] = true;
        vo[nodeVertex[jn[1]]] = true;
    }
    if (vo == vertexOpen_) return false;
    vertexOpen_.swap(vo);
    const labelList oldVertex(voidVertex_);
    setVoids();
    return voidVertex_ != oldVertex;
}


void Foam::crackNetwork::connect()
{
    // (vertex, control volume, end) of every end, sorted by vertex
    const labelList& nodeVertex = topo_.nodeVertex();
    List<FixedList<label, 3>>& ends = ends_;
    ends.setSize(2*cvJoint_.size());
    forAll(cvJoint_, i)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        ends[2*i] = FixedList<label, 3>({nodeVertex[jn[0]], i, 0});
        ends[2*i + 1] = FixedList<label, 3>({nodeVertex[jn[1]], i, 1});
    }
    std::sort(ends.begin(), ends.end());
    links_.clear();
    for (label a = 0; a < ends.size(); )
    {
        label b = a;
        while (b < ends.size() && ends[b][0] == ends[a][0]) ++b;
        const label m = b - a;
        for (label k = a; k < b; ++k)
        {
            for (label l = k + 1; l < b; ++l)
            {
                links_.append
                (
                    FixedList<label, 5>
                    ({ends[k][1], ends[l][1], ends[k][2], ends[l][2], m})
                );
            }
        }
        a = b;
    }
    setVoids();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::crackNetwork::setJoints
(
    const labelUList& joints,
    const UList<vector2D>& x,
    DynamicList<std::pair<label, ductNetwork::content>>* released
)
{
    // New control volumes: a restriction no longer applies
    restricted_ = false;
    // The old network's content and volumes, by joint
    const labelList oldJoints(cvJoint_);
    List<ductNetwork::content> oldContent(oldJoints.size());
    forAll(oldJoints, i)
    {
        oldContent[i] = gas_.contentOf(i);
    }
    const labelList oldCV(jointCV_);

    cvJoint_ = joints;
    jointCV_ = -1;
    forAll(cvJoint_, i)
    {
        jointCV_[cvJoint_[i]] = i;
    }
    connect();
    mouths_.clear();
    gas_.setSize(cvJoint_.size(), links_.size());
    nodeForce_.setSize(cvJoint_.size());
    nodeForce_ = FixedList<vector2D, 4>(Zero);
    const scalarField V(gapAreas(x));

    // Joints that stay keep their content
    boolList has(cvJoint_.size(), false);
    forAll(cvJoint_, i)
    {
        const label o = oldCV[cvJoint_[i]];
        if (o >= 0)
        {
            gas_.setContent(i, oldContent[o]);
            has[i] = true;
        }
        else
        {
            gas_.setContent(i, {0, 0, 0, 0, Zero});
        }
    }

    // A joint that leaves gives its content (equal shares) to the joints
    // that stay at the vertices of its ends, else it is removed
    // (the ends of the new network, sorted by vertex by connect())
    const labelList& nodeVertex = topo_.nodeVertex();
    DynamicList<label> to;
    forAll(oldJoints, o)
    {
        if (jointCV_[oldJoints[o]] >= 0) continue;
        if (released)
        {
            released->append({oldJoints[o], oldContent[o]});
            continue;
        }
        const jointNodeList& jn = topo_.jointNodes()[oldJoints[o]];
        to.clear();
        for (const label e : {0, 1})
        {
            const FixedList<label, 3> key({nodeVertex[jn[e]], -1, -1});
            for
            (
                auto it = std::lower_bound(ends_.begin(), ends_.end(), key);
                it != ends_.end() && (*it)[0] == key[0];
                ++it
            )
            {
                if (has[(*it)[1]] && !to.found((*it)[1])) to.append((*it)[1]);
            }
        }
        const ductNetwork::content& c = oldContent[o];
        if (to.empty())
        {
            removedMass_ += c.m;
            removedEnergy_ += c.mE;
            continue;
        }
        const scalar s = 1.0/to.size();
        for (const label i : to)
        {
            ductNetwork::content d = gas_.contentOf(i);
            d.m += s*c.m; d.mE += s*c.mE; d.aV += s*c.aV; d.m1 += s*c.m1;
            d.mU += s*c.mU;
            gas_.setContent(i, d);
        }
    }

    // New joints: share the content of a neighbour that has gas, at its
    // density and specific energies (in proportion to the volumes), out
    // from the old network along the links (breadth first); the rest take
    // the ambient gas
    labelList nLinks(cvJoint_.size() + 1, Zero);
    for (const FixedList<label, 5>& l : links_)
    {
        ++nLinks[l[0] + 1];
        ++nLinks[l[1] + 1];
    }
    for (label i = 0; i < cvJoint_.size(); ++i) nLinks[i + 1] += nLinks[i];
    labelList adjacent(nLinks.last());
    labelList fillAt(SubList<label>(nLinks, cvJoint_.size()));
    for (const FixedList<label, 5>& l : links_)
    {
        adjacent[fillAt[l[0]]++] = l[1];
        adjacent[fillAt[l[1]]++] = l[0];
    }
    DynamicList<label> queue;
    forAll(has, i)
    {
        if (has[i]) queue.append(i);
    }
    for (label q = 0; q < queue.size(); ++q)
    {
        const label from = queue[q];
        for (label k = nLinks[from]; k < nLinks[from + 1]; ++k)
        {
            const label next = adjacent[k];
            if (has[next]) continue;
            ductNetwork::content c = gas_.contentOf(from);
            const scalar s = V[next]/(V[from] + V[next]);
            const ductNetwork::content give
                {s*c.m, s*c.mE, s*c.aV, s*c.m1, s*c.mU};
            c.m -= give.m; c.mE -= give.mE; c.aV -= give.aV;
            c.m1 -= give.m1; c.mU -= give.mU;
            gas_.setContent(from, c);
            gas_.setContent(next, give);
            has[next] = true;
            queue.append(next);
        }
    }
    const scalar rhoe =
        mixture_.rhoe(0, ambientRho_, ambientRho_, ambientP_);
    forAll(has, i)
    {
        if (has[i]) continue;
        const ductNetwork::content c
            {ambientRho_*V[i], rhoe*V[i], 0, 0, Zero};
        gas_.setContent(i, c);
        createdMass_ += c.m;
        createdEnergy_ += c.mE;
    }
    if (cvJoint_.size())
    {
        gas_.correct(V);
    }
}


void Foam::crackNetwork::setMouths(const UList<FixedList<label, 2>>& mouths)
{
    for (const FixedList<label, 2>& m : mouths)
    {
        if (m[0] < 0 || m[0] >= cvJoint_.size() || m[1] < 0 || m[1] > 1)
        {
            FatalErrorInFunction
                << "crackNetwork: mouth (" << m[0] << " " << m[1] << ") of a"
                << " network of " << cvJoint_.size() << " control volumes"
                << exit(FatalError);
        }
    }
    mouths_ = mouths;
    gas_.setSize(cvJoint_.size(), links_.size() + mouths_.size());
}


void Foam::crackNetwork::fill
(
    const scalar rho,
    const scalar p,
    const UList<vector2D>& x,
    const scalar alpha1
)
{
    const scalarField V(gapAreas(x));
    gas_.geom().V0 = V;
    forAll(cvJoint_, i)
    {
        gas_.setState(i, rho, Zero, p, alpha1);
    }
    createdMass_ = createdEnergy_ = removedMass_ = removedEnergy_ = 0;
}


void Foam::crackNetwork::beginStep
(
    const UList<vector2D>& x,
    const UList<vector2D>& d
)
{
    const label n = cvJoint_.size();
    V0_.setSize(n); Gamma_.setSize(n); open0_.setSize(2*n);
    content0_.setSize(n); eInt0_.setSize(n);
    V_.setSize(n); L_.setSize(n); p_.setSize(n); n_.setSize(n);
    nodeForce_.setSize(n); work_.setSize(n); dLast_.setSize(n);
    const ductNetwork& g = gas_;
    forAll(cvJoint_, i)
    {
        scalar L;
        vector2D nrm;
        jointGeometry
        (
            topo_.jointNodes()[cvJoint_[i]], x, V0_[i], L, nrm, open0_[2*i],
            open0_[2*i + 1]
        );
        Gamma_[i] = g.rho()[i]*sqr(g.c()[i])/g.p()[i];
        const ductNetwork::content c = g.contentOf(i);
        content0_[i] = c;
        eInt0_[i] = c.mE - 0.5*magSqr(c.mU)/c.m;
        nodeForce_[i] = FixedList<vector2D, 4>(Zero);
        work_[i] = 0;
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        for (label k = 0; k < 4; ++k) dLast_[i][k] = d[jn[k]];
    }
    addVoidShares(x, V0_);
    // The material-1 volume of each gas moves with its gap in the
    // sub-steps (Kapila term), from the content's at the start
    aVNow_.setSize(n); VLast_.setSize(n); KLast_.setSize(n);
    pathE_.setSize(n);
    forAll(cvJoint_, i)
    {
        aVNow_[i] = content0_[i].aV;
        VLast_[i] = V0_[i];
        pathE_[i] = eInt0_[i];
        p_[i] = max
        (
            gapPressure(i, V0_[i], aVNow_[i]/V0_[i], eInt0_[i], &KLast_[i]),
            scalar(0)
        );
    }
    floored_.setSize(n);
    openNow_.setSize(2*n);
    voidForce_ = Zero;
    forAll(voidVertex_, k)
    {
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            voidDLast_[c] = d[voidNode_[c]];
        }
    }
}


void Foam::crackNetwork::jointFields
(
    const UList<vector2D>& x,
    DynamicList<word>& names,
    DynamicList<scalarList>& values
) const
{
    const label nJ = jointCV_.size();
    const bool two = mixture_.twoPhase();
    names.append("crackGas");
    names.append("p");
    names.append("rho");
    if (two) names.append("alpha." + mixture_.materials()[0]);
    names.append("aperture");
    const label first = values.size();
    for (label k = first; k < names.size(); ++k)
    {
        values.append(scalarList(nJ, Zero));
    }
    forAll(cvJoint_, i)
    {
        const label j = cvJoint_[i];
        scalar V, L, g0, g1;
        vector2D n;
        jointGeometry(topo_.jointNodes()[j], x, V, L, n, g0, g1);
        label k = first;
        values[k++][j] = 1;
        values[k++][j] = gas_.p()[i];
        values[k++][j] = gas_.rho()[i];
        if (two) values[k++][j] = gas_.alpha1()[i];
        values[k++][j] = V/max(L, VSMALL);
    }
}


Foam::scalar Foam::crackNetwork::gapPressure
(
    const label i,
    const scalar V,
    const scalar alpha,
    const scalar E,
    scalar* K
) const
{
    // The gas's content at the step's start, in the gap's volume now, with
    // the internal energy E
    const ductNetwork::content& c = content0_[i];
    const scalar rhoe = E/V;
    if (!mixture_.twoPhase())
    {
        const scalar rho = c.m/V;
        return mixture_.p(1, rho, rho, rhoe);
    }
    const scalar alphaEps = 1e-12, rhoFloor = 1e-12;
    const scalar a = min(max(alpha, scalar(0)), scalar(1));
    const scalar m1 = min(max(c.m1, scalar(0)), c.m);
    const scalar rho1 = max(m1/(max(a, alphaEps)*V), rhoFloor);
    const scalar rho2 = max((c.m - m1)/(max(1 - a, alphaEps)*V), rhoFloor);
    const scalar p = mixture_.p(a, rho1, rho2, rhoe);
    if (K)
    {
        *K = gas_.kapila() ? gas_.kapilaCoefficient(a, rho1, rho2, p) : 0;
    }
    return p;
}


Foam::scalar Foam::crackNetwork::pathPressure
(
    const label i,
    const scalar alpha,
    scalar* K
)
{
    // Why not the energy the gas has paid so far (e0 less its work): the
    // work of a sub-step is measured over the central displacement
    // (femdemSolid's, half of the sub-step before and half of the one
    // after), so that energy lags the gap by half a sub-step: too high
    // while the gap opens, too low while it closes. A vibrating gap then
    // drains its gas into the solid by (Gamma - 1)/2 (dV/V)^2 p V every
    // sub-step, a first-order error that made the venting depend on the
    // sub-step. The trapezoidal rule is symmetric: a gap that closes back
    // to where it was finds its energy back, and follows the isentrope to
    // third order in dV/V. What the gas pays stays the work done (endStep)
    const scalar V = V_[i], dV = V - VLast_[i];
    const scalar EA = pathE_[i];
    const scalar pA = gapPressure(i, V, alpha, EA, K);
    if (dV == 0) return max(pA, scalar(0));
    // p = pA + b (E - EA): b from a second state (exact for an affine law)
    const scalar dE = 1e-3*(mag(EA) + mag(p_[i]*dV)) + ROOTVSMALL;
    const scalar b = (gapPressure(i, V, alpha, EA - dE) - pA)/(-dE);
    const scalar den = 1 + 0.5*b*dV;
    scalar E = EA - 0.5*(p_[i] + pA)*dV/max(den, SMALL);
    scalar p = pA + b*(E - EA);
    if (!(p > 0) || !(den > SMALL))
    {
        // Spent on the way (or a closing step beyond the law's reach):
        // the gas pushes with at most its last pressure
        E = EA - 0.5*p_[i]*dV;
        p = gapPressure(i, V, alpha, E, K);
    }
    pathE_[i] = E;
    return max(p, scalar(0));
}


void Foam::crackNetwork::updateForces
(
    const UList<vector2D>& x,
    UList<vector2D>& nodeForces
)
{
    // The gaps, then the voids' shares of their volumes (the pressures
    // need the whole volume), then the forces: the gaps' on their faces,
    // the voids' on their corners
    const scalar a = minAperture_;
    const labelList& cvs = activeCVs();
    for (const label i : cvs)
    {
        jointGeometry
        (
            cvNodes(i), x, V_[i], L_[i], n_[i], openNow_[2*i],
            openNow_[2*i + 1]
        );
        floored_[i] = V_[i] <= 0.5*L_[i]*a*(1 + SMALL);
    }
    // (restricted: the areas of the voids at the ends of its control
    // volumes, added to those only)
    for (const label k : restricted_ ? areaVoids_ : activeVoids())
    {
        voidArea_[k] = voidArea(k, x, &voidGrad_[voidCornerStart_[k]]);
        const label c0 = voidCVStart_[k], c1 = voidCVStart_[k + 1];
        for (label c = c0; c < c1; ++c)
        {
            if (restricted_ && !cvActive_[voidCV_[c]]) continue;
            V_[voidCV_[c]] += voidArea_[k]/(c1 - c0);
        }
    }
    for (const label i : cvs)
    {
        // The gas pushes where the gap has volume to lose: on the nodes of
        // an end whose opening counts (V = L (o0 + o1)/2 with o = g + a,
        // a = minAperture, does not change with the nodes of an end pressed
        // shut beyond a, nor at all at its floor L a/2). A force on faces
        // pressed into each other would do work with no volume to pay it
        // from, and drain the gas
        // The materials share the gap's change as their compressibilities
        // ask (explicit over a sub-step: it changes the gap by 5 % at
        // most, stableSubStep)
        aVNow_[i] = min
        (
            max
            (
                aVNow_[i]
              + (aVNow_[i]/VLast_[i] + KLast_[i])*(V_[i] - VLast_[i]),
                scalar(0)
            ),
            V_[i]
        );
        // Spent gas (p -> 0 on its isentrope) pushes no more; what it did
        // is paid at the step's end, where a state the work left
        // unphysical stops the run (ductNetwork::addEnergy)
        p_[i] = pathPressure(i, aVNow_[i]/V_[i], &KLast_[i]);
        VLast_[i] = V_[i];
        const jointNodeList& jn = cvNodes(i);
        FixedList<vector2D, 4> fNew(Zero);
        gapForces(jn, x, floored_[i], &openNow_[2*i], p_[i], fNew);
        FixedList<vector2D, 4>& last = nodeForce_[i];
        for (label k = 0; k < 4; ++k)
        {
            nodeForces[jn[k]] += fNew[k] - last[k];
            last[k] = fNew[k];
        }
    }
    // A void's corners: the mean pressure of the volumes sharing it times
    // its area's gradient (each share pushes with its own pressure)
    const labelList& corner = cornerNodes();
    for (const label k : activeVoids())
    {
        const label c0 = voidCVStart_[k], c1 = voidCVStart_[k + 1];
        scalar P = 0;
        for (label c = c0; c < c1; ++c) P += p_[voidCV_[c]];
        P /= c1 - c0;
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            const vector2D f = P*voidGrad_[c];
            nodeForces[corner[c]] += f - voidForce_[c];
            voidForce_[c] = f;
        }
    }
}


Foam::scalar Foam::crackNetwork::subSteps::limit
(
    femdemSolid& solid,
    subStepBound& bound
)
{
    List<vector2D>& f = solid.externalForce();
    if (first_)
    {
        // advance() has zeroed the work displacement
        net_.beginStep(solid.x(), solid.workDisplacement());
        f = otherForces_;
        first_ = false;
    }
    net_.updateForces(solid.x(), f);
    return net_.stableSubStep(solid.v(), solid.invMass(), &bound);
}


Foam::scalar Foam::crackNetwork::subSteps::beforeSubStep(femdemSolid& solid)
{
    subStepBound b = subStepBound::solid;
    const scalar h = limit(solid, b);
    net_.countSubStep(h, b, solid.stableTimeStep());
    return h;
}


void Foam::crackNetwork::subSteps::afterSubStep(const femdemSolid& solid)
{
    net_.addWork(solid.workDisplacement());
}


Foam::scalar Foam::crackNetwork::stableSubStep
(
    const UList<vector2D>& v,
    const UList<scalar>& invMass,
    subStepBound* bound
) const
{
    // Stability: a node moving by delta changes the gap's volume by
    // L delta/2, its pressure by Gamma p L delta/(2 V), its force by L/2 of
    // that: k = Gamma p L^2/(4 V); two opposite nodes close on each other,
    // so omega^2 = 2 k/m, and h <= 0.5*2/omega. Accuracy: the gap changes
    // by at most maxVolumeChange in a sub-step (the forces are those at its start: a
    // thin gap that opens many times over in one sub-step would be paid at
    // its start pressure), from the faces' speed and acceleration
    scalar h = GREAT;
    subStepBound which = subStepBound::solid;
    // h = min(h, x) (x where !(h < x), as Foam::min), noting which bound
    auto limitBy = [&](const scalar x, const subStepBound b)
    {
        if (!(h < x))
        {
            h = x;
            which = b;
        }
    };
    for (const label i : activeCVs())
    {
        // The gap and its gas as the last updateForces found them
        const scalar V = V_[i], L = L_[i], p = p_[i];
        const vector2D& n = n_[i];
        const scalar k = Gamma_[i]*p*L*L/(4*V);
        const jointNodeList& jn = cvNodes(i);
        scalar im = 0;
        for (const label node : jn) im = max(im, invMass[node]);
        if (k*im > 0)
        {
            limitBy(0.5*2/Foam::sqrt(2*k*im), subStepBound::gasSpring);
        }
        const scalar gap = V/L;
        const scalar speed = max
        (
            mag((v[jn[2]] - v[jn[0]]) & n), mag((v[jn[3]] - v[jn[1]]) & n)
        );
        const scalar accel = p*L*im;
        limitBy
        (
            maxVolumeChange_*gap/max(speed, VSMALL),
            subStepBound::volumeChange
        );
        limitBy
        (
            Foam::sqrt(0.1*gap/max(accel, VSMALL)),
            subStepBound::acceleration
        );
    }
    // A void: its corner c moved by delta changes each of the m shares by
    // G_c.delta/m, the pressure of share j by Gamma_j p_j of that over
    // V_j, the force by G_c/m of that; and no share changes by more than
    // 5 % in a sub-step
    const labelList& corner = cornerNodes();
    for (const label k : activeVoids())
    {
        if (!(voidArea_[k] > 0)) continue;
        const label c0 = voidCVStart_[k], c1 = voidCVStart_[k + 1];
        const label m = c1 - c0;
        scalar stiff = 0, Vmin = GREAT;
        for (label c = c0; c < c1; ++c)
        {
            const label j = voidCV_[c];
            stiff += Gamma_[j]*p_[j]/(m*m*V_[j]);
            Vmin = min(Vmin, V_[j]);
        }
        scalar g2im = 0, rate = 0;
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            const label node = corner[c];
            g2im = max(g2im, magSqr(voidGrad_[c])*invMass[node]);
            rate += voidGrad_[c] & v[node];
        }
        if (stiff*g2im > 0)
        {
            limitBy
            (
                0.5*2/Foam::sqrt(2*stiff*g2im), subStepBound::voidSpring
            );
        }
        limitBy
        (
            maxVolumeChange_*m*Vmin/max(mag(rate), VSMALL),
            subStepBound::voidVolumeChange
        );
    }
    if (bound) *bound = which;
    return h;
}


const Foam::labelList& Foam::crackNetwork::activeCVs() const
{
    if (restricted_) return subCVs_;
    if (allCVs_.size() != cvJoint_.size()) allCVs_ = identity(cvJoint_.size());
    return allCVs_;
}


const Foam::labelList& Foam::crackNetwork::activeVoids() const
{
    if (restricted_) return forceVoids_;
    if (allVoids_.size() != voidVertex_.size())
    {
        allVoids_ = identity(voidVertex_.size());
    }
    return allVoids_;
}


Foam::labelList Foam::crackNetwork::restrictTo
(
    const UList<label>& triangleOwner,
    const label rank
)
{
    // Triangle of a solid node: 3 nodes per triangle
    auto mine = [&](const label node) { return triangleOwner[node/3] == rank; };
    const label nCV = cvJoint_.size(), nV = voidVertex_.size();

    // Control volumes touching an owned node (their forces act on it)
    cvActive_.setSize(nCV);
    cvActive_ = false;
    forAll(cvJoint_, i)
    {
        for (const label n : topo_.jointNodes()[cvJoint_[i]])
        {
            if (mine(n)) cvActive_[i] = true;
        }
    }
    // Voids pushing an owned corner or paying into such a control volume
    // (all of whose shares then need their pressure: active too)
    boolList forceVoid(nV, false);
    forAll(voidVertex_, k)
    {
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            if (mine(voidNode_[c])) forceVoid[k] = true;
        }
        for (label c = voidCVStart_[k]; c < voidCVStart_[k + 1]; ++c)
        {
            if (cvActive_[voidCV_[c]]) forceVoid[k] = true;
        }
    }
    forAll(voidVertex_, k)
    {
        if (!forceVoid[k]) continue;
        for (label c = voidCVStart_[k]; c < voidCVStart_[k + 1]; ++c)
        {
            cvActive_[voidCV_[c]] = true;
        }
    }
    // The voids at the ends of the active control volumes: their areas
    // are part of those volumes
    boolList areaVoid(forceVoid);
    forAll(voidVertex_, k)
    {
        for (label c = voidCVStart_[k]; c < voidCVStart_[k + 1]; ++c)
        {
            if (cvActive_[voidCV_[c]]) areaVoid[k] = true;
        }
    }
    DynamicList<label> cvs, fv, av;
    forAll(cvActive_, i) if (cvActive_[i]) cvs.append(i);
    forAll(forceVoid, k) if (forceVoid[k]) fv.append(k);
    forAll(areaVoid, k) if (areaVoid[k]) av.append(k);
    subCVs_.transfer(cvs);
    forceVoids_.transfer(fv);
    areaVoids_.transfer(av);
    restricted_ = true;

    // The nodes read: of the active control volumes and the voids' corners
    DynamicList<label> n(4*subCVs_.size());
    for (const label i : subCVs_)
    {
        for (const label node : topo_.jointNodes()[cvJoint_[i]]) n.append(node);
    }
    for (const label k : areaVoids_)
    {
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            n.append(voidNode_[c]);
        }
    }
    return uniqueSorted(std::move(n));
}


Foam::label Foam::crackNetwork::cvRank
(
    const UList<label>& triangleOwner,
    const label i
) const
{
    return triangleOwner[topo_.jointNodes()[cvJoint_[i]][0]/3];
}


void Foam::crackNetwork::unrestrict()
{
    restricted_ = false;
    localNodes_ = false;
}


void Foam::crackNetwork::readLocal(const labelUList& localTriangle)
{
    if (!restricted_)
    {
        FatalErrorInFunction
            << "local numbering without restrictTo" << exit(FatalError);
    }
    // Node k of a triangle is node 3 t + k of the solid it is in
    auto localOf = [&](const label node)
    {
        const label t = localTriangle[node/3];
        if (t < 0)
        {
            FatalErrorInFunction
                << "node " << node << " of the crack network is not in the"
                << " local solid" << exit(FatalError);
        }
        return 3*t + node%3;
    };
    subNodes_.setSize(cvJoint_.size());
    for (const label i : subCVs_)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        for (label k = 0; k < 4; ++k) subNodes_[i][k] = localOf(jn[k]);
    }
    subVoidNode_.setSize(voidNode_.size());
    subVoidNode_ = -1;
    for (const label k : areaVoids_)
    {
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            subVoidNode_[c] = localOf(voidNode_[c]);
        }
    }
    localNodes_ = true;
}


void Foam::crackNetwork::distributeGas(const UList<label>& triangleOwner)
{
    // Each control volume on the rank owning its joint's first triangle
    // (the owner of its work, shareWork)
    gasRank_.setSize(cvJoint_.size());
    forAll(cvJoint_, i)
    {
        gasRank_[i] = cvRank(triangleOwner, i);
    }
}


void Foam::crackNetwork::shareWork(const UList<label>& triangleOwner)
{
    // Each control volume's work from the rank owning its joint's first
    // triangle (which ran it and every void paying into it): x + 0 = x
    const label rank = Pstream::myProcNo();
    scalarList w(work_.size());
    forAll(cvJoint_, i)
    {
        w[i] = cvRank(triangleOwner, i) == rank ? work_[i] : 0;
    }
    Pstream::listCombineGather(w, plusEqOp<scalar>());
    Pstream::listCombineScatter(w);
    work_ = w;
}


Foam::labelList Foam::crackNetwork::nodes() const
{
    DynamicList<label> n(4*cvJoint_.size() + voidNode_.size());
    for (const label j : cvJoint_)
    {
        for (const label node : topo_.jointNodes()[j]) n.append(node);
    }
    n.append(voidNode_);
    return uniqueSorted(std::move(n));
}


void Foam::crackNetwork::addWork(const UList<vector2D>& d)
{
    for (const label i : activeCVs())
    {
        const jointNodeList& jn = cvNodes(i);
        FixedList<vector2D, 4>& last = dLast_[i];
        vector2D dd[4];
        for (label k = 0; k < 4; ++k)
        {
            dd[k] = d[jn[k]] - last[k];
        }
        const FixedList<vector2D, 4>& f = nodeForce_[i];
        work_[i] +=
            (f[0] & dd[0]) + (f[1] & dd[1]) + (f[2] & dd[2]) + (f[3] & dd[3]);
        for (label k = 0; k < 4; ++k) last[k] = d[jn[k]];
    }
    // A void's forces (P G_c on its corners, P the mean of its shares'
    // pressures) did P dA, dA = sum G_c.dd_c: each share pays p_j/m dA
    const labelList& corner = cornerNodes();
    for (const label k : activeVoids())
    {
        scalar dA = 0;
        for (label c = voidCornerStart_[k]; c < voidCornerStart_[k + 1]; ++c)
        {
            const vector2D& dn = d[corner[c]];
            dA += voidGrad_[c] & (dn - voidDLast_[c]);
            voidDLast_[c] = dn;
        }
        const label c0 = voidCVStart_[k], c1 = voidCVStart_[k + 1];
        for (label c = c0; c < c1; ++c)
        {
            work_[voidCV_[c]] += p_[voidCV_[c]]/(c1 - c0)*dA;
        }
    }
}


Foam::scalar Foam::crackNetwork::endStep
(
    const UList<vector2D>& x,
    const scalar dt
)
{
    ductNetwork::geometry& g = gas_.geom();
    scalarField& open1 = open1_;
    open1.setSize(2*cvJoint_.size());
    forAll(cvJoint_, i)
    {
        scalar L;
        vector2D n;
        jointGeometry
        (
            topo_.jointNodes()[cvJoint_[i]], x, g.V1[i], L, n, open1[2*i],
            open1[2*i + 1]
        );
        g.V0[i] = V0_[i];
        // Axis along A's face: n = (dy, -dx)/L, so the axis is (-n.y, n.x)
        g.axis[i] = vector(-n.y(), n.x(), 0);
        g.wallArea[i] = 2*L;
    }
    addVoidShares(x, g.V1);
    forAll(links_, f)
    {
        const FixedList<label, 5>& l = links_[f];
        const label a = l[0], b = l[1];
        auto width = [&](const scalarField& open)
        {
            const scalar w = min(open[2*a + l[2]], open[2*b + l[3]]);
            return max(w, minAperture_)/(l[4] - 1);
        };
        // Out of a at its end: -axis at p0, +axis at p1
        const vector dir = (l[2] == 1 ? 1 : -1)*g.axis[a];
        g.owner[f] = a;
        g.neighbour[f] = b;
        g.Sf[f] = 0.5*(width(open0_) + width(open1))*dir;
    }
    forAll(mouths_, k)
    {
        const label a = mouths_[k][0], e = mouths_[k][1];
        const label f = links_.size() + k;
        const scalar w =
            0.5*(max(open0_[2*a + e], minAperture_) + max(open1[2*a + e], minAperture_));
        g.owner[f] = a;
        g.neighbour[f] = -1;
        g.Sf[f] = w*(e == 1 ? 1 : -1)*g.axis[a];
    }
    // The gas pays the work its forces did (not p dV: a thin gap that
    // opens many times over in a step would take more than the gas has),
    // all of it first, in its start volume: those forces came from this
    // content on its isentrope, so they never took more than it holds,
    // whereas paid along the step, after fluxes had carried gas out of a
    // small gap, the same work could leave it with none. Then the fluxes
    // sub-step as their stability asks (below), the volumes moving
    // linearly along the step, with no wall work of their own
    gas_.addEnergy(-work_);
    VEnd_ = g.V1;
    g.wallWork.setSize(work_.size());
    g.wallWork = 0;
    // A plenum's limit holds for the whole step: each sub-step its share
    const scalarField maxMass0(gas_.plenum().maxMass);
    const label nm = mouths_.size();
    mouthMass_.setSize(nm); mouthMass_ = 0;
    mouthMass1_.setSize(nm); mouthMass1_ = 0;
    mouthEnergy_.setSize(nm); mouthEnergy_ = 0;
    mouthMomentum_.setSize(nm); mouthMomentum_ = Zero;
    // Each sub-step as long as the gas's state at its start allows
    // (Courant number 0.4 on the smaller of the volumes now and at the
    // step's end: the volumes move linearly in between). A step count fixed
    // at the step's start let a gap squeezed to its floor with gas rushing
    // in take sub-steps its later state could not: benchBlast stopped at
    // 0.27 ms with a control volume at negative pressure
    // On a partitioned solid the ranks share the gas step (distributeGas)
    if (gasRank_.size())
    {
        gas_.distribute(gasRank_);
    }
    scalar t = 0;
    label n = 0;
    while (t < dt*(1 - 1e-12))
    {
        const scalar s0 = t/dt;
        forAll(VEnd_, i)
        {
            g.V0[i] = V0_[i] + s0*(VEnd_[i] - V0_[i]);
            g.V1[i] = VEnd_[i];
        }
        scalar h = min(dt - t, gas_.maxDeltaT(0.4));
        // With the Kapila term, no gap changes by more than 10 % in a
        // sub-step (it is explicit in the materials' share)
        if (gas_.kapila())
        {
            forAll(VEnd_, i)
            {
                const scalar rate = mag(VEnd_[i] - V0_[i])/dt;
                if (rate > 0) h = min(h, 0.1*g.V0[i]/rate);
            }
        }
        // No sliver of a last sub-step
        if (dt - t - h < 1e-3*h) h = dt - t;
        const scalar s1 = min((t + h)/dt, scalar(1));
        forAll(VEnd_, i)
        {
            g.V1[i] = V0_[i] + s1*(VEnd_[i] - V0_[i]);
        }
        gas_.plenum().maxMass = maxMass0*(h/dt);
        gas_.advance(h);
        forAll(mouths_, m)
        {
            const label f = links_.size() + m;
            mouthMass_[m] += gas_.inMass()[f];
            mouthMass1_[m] += gas_.inMass1()[f];
            mouthEnergy_[m] += gas_.inEnergy()[f];
            mouthMomentum_[m] += gas_.inMomentum()[f];
        }
        t += h;
        if (++n > 10000000)
        {
            FatalErrorInFunction
                << "crackNetwork: more than 1e7 gas sub-steps in a step of "
                << dt << " s (at " << t << " s into it, sub-step " << h
                << " s): the crack gas cannot follow its gaps"
                << exit(FatalError);
        }
    }
    gas_.plenum().maxMass = maxMass0;
    if (gas_.distributed())
    {
        // The whole network and every mouth's inflow on every rank (the
        // mouths' sums held by the rank of their control volume)
        gas_.collect();
        scalarList& q = mouthBuf_;
        q.setSize(6*nm);
        labelList& rank = mouthRank_;
        rank.setSize(nm);
        forAll(mouths_, m)
        {
            rank[m] = gasRank_[mouths_[m][0]];
            q[6*m] = mouthMass_[m];
            q[6*m + 1] = mouthMass1_[m];
            q[6*m + 2] = mouthEnergy_[m];
            for (label d = 0; d < 3; ++d) q[6*m + 3 + d] = mouthMomentum_[m][d];
        }
        ductPartition::fromOwners(q, 6, rank);
        forAll(mouths_, m)
        {
            mouthMass_[m] = q[6*m];
            mouthMass1_[m] = q[6*m + 1];
            mouthEnergy_[m] = q[6*m + 2];
            mouthMomentum_[m] = vector(q[6*m + 3], q[6*m + 4], q[6*m + 5]);
        }
    }
    gasRank_.clear();
    nGasSubSteps_ = n;
    return sum(work_);
}


void Foam::crackNetwork::writeState(Ostream& os) const
{
    const label n = cvJoint_.size();
    scalarList m(n), mE(n), aV(n), m1(n);
    List<vector> mU(n);
    forAll(cvJoint_, i)
    {
        const ductNetwork::content c = gas_.contentOf(i);
        m[i] = c.m; mE[i] = c.mE; aV[i] = c.aV; m1[i] = c.m1; mU[i] = c.mU;
    }
    // Round-trip precision: a restart continues the run bit for bit
    const int oldPrecision = os.precision(17);
    os.writeEntry("joints", cvJoint_);
    os.writeEntry("m", m);
    os.writeEntry("mE", mE);
    os.writeEntry("aV", aV);
    os.writeEntry("m1", m1);
    os.writeEntry("mU", mU);
    os.writeEntry("createdMass", createdMass_);
    os.writeEntry("createdEnergy", createdEnergy_);
    os.writeEntry("removedMass", removedMass_);
    os.writeEntry("removedEnergy", removedEnergy_);
    os.precision(oldPrecision);
}


void Foam::crackNetwork::readState
(
    const dictionary& dict,
    const UList<vector2D>& x
)
{
    const labelList joints(dict.get<labelList>("joints"));
    const label n = joints.size();
    labelList cv(topo_.nJoints(), -1);
    forAll(joints, i)
    {
        const label j = joints[i];
        if (j < 0 || j >= cv.size() || cv[j] >= 0)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'joints': joint " << j << " (control volume " << i
                << ") is " << (j < 0 || j >= cv.size() ? "not" : "twice")
                << " in a solid of " << cv.size() << " joints"
                << exit(FatalIOError);
        }
        cv[j] = i;
    }
    const scalarList m(dict.get<scalarList>("m"));
    const scalarList mE(dict.get<scalarList>("mE"));
    const scalarList aV(dict.get<scalarList>("aV"));
    const scalarList m1(dict.get<scalarList>("m1"));
    const List<vector> mU(dict.get<List<vector>>("mU"));
    const FixedList<std::pair<word, label>, 5> sizes
    ({
        {"m", m.size()}, {"mE", mE.size()}, {"aV", aV.size()},
        {"m1", m1.size()}, {"mU", mU.size()}
    });
    for (const std::pair<word, label>& s : sizes)
    {
        if (s.second != n)
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << s.first << "': " << s.second << " values for"
                << " the " << n << " control volumes of 'joints'"
                << exit(FatalIOError);
        }
    }
    // The gas of a control volume: mass > 0, and no negative material
    // volume or mass beyond round-off (a material that left a control
    // volume through its fluxes can leave -1e-41 kg behind: benchBlast
    // wrote m1 = -1.07e-41 at 0.2 ms, with m of order 1e-6; the volume is
    // checked below, against the gap's)
    const scalar roundOff = 1e-9;
    forAll(joints, i)
    {
        const word bad =
            !(m[i] > 0) ? "m"
          : !(m1[i] >= -roundOff*m[i]) ? "m1"
          : "";
        if (bad.size())
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << bad << "': control volume " << i << " (joint "
                << joints[i] << ") has " << bad << " = "
                << (bad == "m" ? m[i] : m1[i])
                << ", not a state the crack gas writes (m > 0, aV >= 0,"
                << " m1 >= 0, to round-off)" << exit(FatalIOError);
        }
    }
    const FixedList<word, 4> counters
    ({"createdMass", "createdEnergy", "removedMass", "removedEnergy"});
    scalar value[4];
    forAll(counters, k)
    {
        value[k] = dict.get<scalar>(counters[k]);
    }
    for (const label k : {0, 2})
    {
        if (!(value[k] >= 0))
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << counters[k] << "' is " << value[k]
                << "; it sums masses and must be >= 0" << exit(FatalIOError);
        }
    }

    cvJoint_ = joints;
    jointCV_ = cv;
    connect();
    mouths_.clear();
    gas_.setSize(n, links_.size());
    nodeForce_.setSize(n);
    nodeForce_ = FixedList<vector2D, 4>(Zero);
    forAll(joints, i)
    {
        gas_.setContent(i, {m[i], mE[i], aV[i], m1[i], mU[i]});
    }
    createdMass_ = value[0];
    createdEnergy_ = value[1];
    removedMass_ = value[2];
    removedEnergy_ = value[3];
    if (n)
    {
        // A content without a physical state in its gap (no pressure)
        // stops naming the control volume: its pressure as the next step
        // sees it (gapPressure of the content, no work done yet); any other
        // error of the primitives naming the file
        const scalarField V(gapAreas(x));
        V0_ = V;
        content0_.setSize(n);
        eInt0_.setSize(n);
        work_.setSize(n);
        work_ = 0;
        forAll(joints, i)
        {
            content0_[i] = gas_.contentOf(i);
            eInt0_[i] = mE[i] - 0.5*magSqr(mU[i])/m[i];
            if (!(aV[i] >= -roundOff*V[i]))
            {
                FatalIOErrorInFunction(dict)
                    << "entry 'aV': control volume " << i << " (joint "
                    << joints[i] << ") has aV = " << aV[i] << " in a gap of "
                    << V[i] << ", not a state the crack gas writes (m > 0,"
                    << " aV >= 0, m1 >= 0, to round-off)"
                    << exit(FatalIOError);
            }
            const scalar p = gapPressure(i, V[i], aV[i]/V[i], eInt0_[i]);
            if (!(p > 0) || !std::isfinite(p))
            {
                FatalIOErrorInFunction(dict)
                    << "entries 'm', 'mE', 'mU': control volume " << i
                    << " (joint " << joints[i] << ") has no physical state"
                    << " in its gap (pressure " << p << " in volume " << V[i]
                    << "): not a state the crack gas writes"
                    << exit(FatalIOError);
            }
        }
        caseChecks::readNaming(dict, [&](){ gas_.correct(V); });
    }
}


// ************************************************************************* //

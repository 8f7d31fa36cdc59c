/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackNetwork.H"
#include <algorithm>

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
    gas_(mixture, dict),
    minAperture_(dict.getOrDefault<scalar>("minAperture", 1e-6)),
    ambientRho_(1.2),
    ambientP_(1e5),
    jointCV_(topology.nJoints(), -1),
    createdMass_(0),
    createdEnergy_(0),
    removedMass_(0),
    removedEnergy_(0)
{
    if (!(minAperture_ > 0) || !std::isfinite(minAperture_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'minAperture' must be a length > 0, got "
            << minAperture_ << exit(FatalIOError);
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
    const label j,
    const UList<vector2D>& x,
    scalar& area,
    scalar& L,
    vector2D& n,
    scalar& g0,
    scalar& g1
) const
{
    const jointNodeList& jn = topo_.jointNodes()[j];
    const vector2D& p0 = x[jn[0]];
    const vector2D& p1 = x[jn[1]];
    const vector2D& q0 = x[jn[2]];
    const vector2D& q1 = x[jn[3]];
    const vector2D d = p1 - p0;
    L = mag(d);
    n = vector2D(d.y(), -d.x())/max(L, VSMALL);
    g0 = (q0 - p0) & n;
    g1 = (q1 - p1) & n;
    // Shoelace of p0 q0 q1 p1: positive while B lies on n's side of A
    auto cross = [](const vector2D& a, const vector2D& b)
    {
        return a.x()*b.y() - a.y()*b.x();
    };
    const scalar twice =
        cross(p0, q0) + cross(q0, q1) + cross(q1, p1) + cross(p1, p0);
    area = max(0.5*twice, L*minAperture_);
}


Foam::scalarField Foam::crackNetwork::gapAreas(const UList<vector2D>& x) const
{
    scalarField V(cvJoint_.size());
    forAll(cvJoint_, i)
    {
        scalar L, g0, g1;
        vector2D n;
        jointGeometry(cvJoint_[i], x, V[i], L, n, g0, g1);
    }
    return V;
}


void Foam::crackNetwork::connect()
{
    // (vertex, control volume, end) of every end, sorted by vertex
    const labelList& nodeVertex = topo_.nodeVertex();
    List<FixedList<label, 3>> ends(2*cvJoint_.size());
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::crackNetwork::setJoints
(
    const labelUList& joints,
    const UList<vector2D>& x
)
{
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
    gas_.setSize(cvJoint_.size(), links_.size());
    faceForce_.setSize(cvJoint_.size());
    faceForce_ = Zero;
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
    const labelList& nodeVertex = topo_.nodeVertex();
    List<FixedList<label, 2>> atVertex(2*cvJoint_.size());
    forAll(cvJoint_, i)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        atVertex[2*i] = FixedList<label, 2>({nodeVertex[jn[0]], i});
        atVertex[2*i + 1] = FixedList<label, 2>({nodeVertex[jn[1]], i});
    }
    std::sort(atVertex.begin(), atVertex.end());
    DynamicList<label> to;
    forAll(oldJoints, o)
    {
        if (jointCV_[oldJoints[o]] >= 0) continue;
        const jointNodeList& jn = topo_.jointNodes()[oldJoints[o]];
        to.clear();
        for (const label e : {0, 1})
        {
            const FixedList<label, 2> key({nodeVertex[jn[e]], -1});
            for
            (
                auto it = std::lower_bound(atVertex.begin(), atVertex.end(), key);
                it != atVertex.end() && (*it)[0] == key[0];
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
}


void Foam::crackNetwork::fill
(
    const scalar rho,
    const scalar p,
    const UList<vector2D>& x
)
{
    const scalarField V(gapAreas(x));
    gas_.geom().V0 = V;
    forAll(cvJoint_, i)
    {
        gas_.setState(i, rho, Zero, p, 1);
    }
    createdMass_ = createdEnergy_ = removedMass_ = removedEnergy_ = 0;
}


void Foam::crackNetwork::advance
(
    const UList<vector2D>& x0,
    const UList<vector2D>& x1,
    const scalar dt
)
{
    ductNetwork::geometry& g = gas_.geom();
    scalarField open0(2*cvJoint_.size()), open1(2*cvJoint_.size());
    List<vector2D> normal(cvJoint_.size());
    scalarField length(cvJoint_.size());
    forAll(cvJoint_, i)
    {
        const label j = cvJoint_[i];
        scalar L, g0, g1;
        vector2D n;
        jointGeometry(j, x1, g.V1[i], L, n, open1[2*i], open1[2*i + 1]);
        jointGeometry(j, x0, g.V0[i], L, n, g0, g1);
        open0[2*i] = g0;
        open0[2*i + 1] = g1;
        normal[i] = n;
        length[i] = L;
        // Axis along A's face: n = (dy, -dx)/L, so the axis is (-n.y, n.x)
        g.axis[i] = vector(-n.y(), n.x(), 0);
        g.wallArea[i] = 2*L;
    }
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
        g.Sf[f] = 0.5*(width(open0) + width(open1))*dir;
    }
    gas_.advance(dt);

    const scalarField& p = gas_.meanPressure();
    forAll(faceForce_, i)
    {
        faceForce_[i] = -0.5*p[i]*length[i]*normal[i];
    }
}


void Foam::crackNetwork::addNodeForces(UList<vector2D>& nodeForces) const
{
    forAll(cvJoint_, i)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        nodeForces[jn[0]] += faceForce_[i];
        nodeForces[jn[1]] += faceForce_[i];
        nodeForces[jn[2]] -= faceForce_[i];
        nodeForces[jn[3]] -= faceForce_[i];
    }
}


Foam::scalar Foam::crackNetwork::payWork(const UList<vector2D>& d)
{
    if (d.size() != topo_.nNodes())
    {
        FatalErrorInFunction
            << "crackNetwork: " << d.size() << " work displacements for "
            << topo_.nNodes() << " nodes (femdemSolid::trackWorkDisplacement"
            << " not called?)" << exit(FatalError);
    }
    const scalarField& paid = gas_.wallWorkOf();
    scalarField dE(cvJoint_.size());
    scalar total = 0;
    forAll(cvJoint_, i)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        const scalar w =
            faceForce_[i] & (d[jn[0]] + d[jn[1]] - d[jn[2]] - d[jn[3]]);
        dE[i] = paid[i] - w;
        total += w;
    }
    gas_.addEnergy(dE);
    return total;
}


// ************************************************************************* //

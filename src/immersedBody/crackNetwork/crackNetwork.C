/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackNetwork.H"
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
    ambientRho_(1.2),
    ambientP_(1e5),
    jointCV_(topology.nJoints(), -1),
    createdMass_(0),
    createdEnergy_(0),
    removedMass_(0),
    removedEnergy_(0),
    nGasSubSteps_(0)
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
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::crackNetwork::setJoints
(
    const labelUList& joints,
    const UList<vector2D>& x,
    DynamicList<std::pair<label, ductNetwork::content>>* released
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
    mouths_.clear();
    gas_.setSize(cvJoint_.size(), links_.size());
    faceForce_.setSize(cvJoint_.size());
    faceForce_ = FixedList<vector2D, 2>(Zero);
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
    faceForce_.setSize(n); work_.setSize(n); dLast_.setSize(n);
    const ductNetwork& g = gas_;
    forAll(cvJoint_, i)
    {
        scalar L;
        vector2D nrm;
        jointGeometry
        (
            cvJoint_[i], x, V0_[i], L, nrm, open0_[2*i], open0_[2*i + 1]
        );
        Gamma_[i] = g.rho()[i]*sqr(g.c()[i])/g.p()[i];
        const ductNetwork::content c = g.contentOf(i);
        content0_[i] = c;
        eInt0_[i] = c.mE - 0.5*magSqr(c.mU)/c.m;
        faceForce_[i] = FixedList<vector2D, 2>(Zero);
        work_[i] = 0;
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        for (label k = 0; k < 4; ++k) dLast_[i][k] = d[jn[k]];
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
        jointGeometry(j, x, V, L, n, g0, g1);
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
    const scalar V
) const
{
    // The gas's own state: its content at the step's start, in the gap's
    // volume now, less the work it has done since (it pays as it pushes)
    const ductNetwork::content& c = content0_[i];
    const scalar rhoe = (eInt0_[i] - work_[i])/V;
    if (!mixture_.twoPhase())
    {
        const scalar rho = c.m/V;
        return mixture_.p(1, rho, rho, rhoe);
    }
    const scalar alphaEps = 1e-12, rhoFloor = 1e-12;
    const scalar a = min(max(c.aV/V0_[i], scalar(0)), scalar(1));
    const scalar m1 = min(max(c.m1, scalar(0)), c.m);
    const scalar rho1 = max(m1/(max(a, alphaEps)*V), rhoFloor);
    const scalar rho2 = max((c.m - m1)/(max(1 - a, alphaEps)*V), rhoFloor);
    return mixture_.p(a, rho1, rho2, rhoe);
}


void Foam::crackNetwork::updateForces
(
    const UList<vector2D>& x,
    UList<vector2D>& nodeForces
)
{
    forAll(cvJoint_, i)
    {
        scalar g0, g1;
        jointGeometry(cvJoint_[i], x, V_[i], L_[i], n_[i], g0, g1);
        // The gas pushes where the gap has volume to lose: on the nodes of
        // an end whose opening counts (V = L (o0 + o1)/2 with o = g + a,
        // a = minAperture, does not change with the nodes of an end pressed
        // shut beyond a, nor at all at its floor L a/2). A force on faces
        // pressed into each other would do work with no volume to pay it
        // from, and drain the gas
        const scalar a = minAperture_;
        const bool floored = V_[i] <= 0.5*L_[i]*a*(1 + SMALL);
        const scalar p = gapPressure(i, V_[i]);
        // Spent gas (p -> 0 on its isentrope) pushes no more; what it did
        // is paid at the step's end, where a state the work left
        // unphysical stops the run (ductNetwork::addEnergy)
        p_[i] = max(p, scalar(0));
        const vector2D f = -0.5*p_[i]*L_[i]*n_[i];
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        FixedList<vector2D, 2>& last = faceForce_[i];
        for (const label e : {0, 1})
        {
            const bool open = !floored && (e == 0 ? g0 : g1) + a > 0;
            const vector2D fe = open ? f : vector2D::zero;
            const vector2D df = fe - last[e];
            last[e] = fe;
            nodeForces[jn[e]] += df;
            nodeForces[jn[2 + e]] -= df;
        }
    }
}


Foam::scalar Foam::crackNetwork::subSteps::beforeSubStep(femdemSolid& solid)
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
    return net_.stableSubStep(solid.v(), solid.invMass());
}


void Foam::crackNetwork::subSteps::afterSubStep(const femdemSolid& solid)
{
    net_.addWork(solid.workDisplacement());
}


Foam::scalar Foam::crackNetwork::stableSubStep
(
    const UList<vector2D>& v,
    const UList<scalar>& invMass
) const
{
    // Stability: a node moving by delta changes the gap's volume by
    // L delta/2, its pressure by Gamma p L delta/(2 V), its force by L/2 of
    // that: k = Gamma p L^2/(4 V); two opposite nodes close on each other,
    // so omega^2 = 2 k/m, and h <= 0.5*2/omega. Accuracy: the gap changes
    // by at most 5 % in a sub-step (the forces are those at its start: a
    // thin gap that opens many times over in one sub-step would be paid at
    // its start pressure), from the faces' speed and acceleration
    scalar h = GREAT;
    forAll(cvJoint_, i)
    {
        // The gap and its gas as the last updateForces found them
        const scalar V = V_[i], L = L_[i], p = p_[i];
        const vector2D& n = n_[i];
        const scalar k = Gamma_[i]*p*L*L/(4*V);
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        scalar im = 0;
        for (const label node : jn) im = max(im, invMass[node]);
        if (k*im > 0)
        {
            h = min(h, 0.5*2/Foam::sqrt(2*k*im));
        }
        const scalar gap = V/L;
        const scalar speed = max
        (
            mag((v[jn[2]] - v[jn[0]]) & n), mag((v[jn[3]] - v[jn[1]]) & n)
        );
        const scalar accel = p*L*im;
        h = min(h, 0.05*gap/max(speed, VSMALL));
        h = min(h, Foam::sqrt(0.1*gap/max(accel, VSMALL)));
    }
    return h;
}


void Foam::crackNetwork::addWork(const UList<vector2D>& d)
{
    forAll(cvJoint_, i)
    {
        const jointNodeList& jn = topo_.jointNodes()[cvJoint_[i]];
        FixedList<vector2D, 4>& last = dLast_[i];
        vector2D dd[4];
        for (label k = 0; k < 4; ++k)
        {
            dd[k] = d[jn[k]] - last[k];
        }
        const FixedList<vector2D, 2>& f = faceForce_[i];
        work_[i] += (f[0] & (dd[0] - dd[2])) + (f[1] & (dd[1] - dd[3]));
        for (label k = 0; k < 4; ++k) last[k] = d[jn[k]];
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
        jointGeometry(cvJoint_[i], x, g.V1[i], L, n, open1[2*i], open1[2*i + 1]);
        g.V0[i] = V0_[i];
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
    // sub-step as their stability asks (Courant number 0.4), the volumes
    // in equal shares along the step, with no wall work of their own
    gas_.addEnergy(-work_);
    VEnd_ = g.V1;
    const label n =
        max(label(1), label(std::ceil(dt/gas_.maxDeltaT(0.4) - 1e-9)));
    const scalar h = dt/n;
    g.wallWork.setSize(work_.size());
    g.wallWork = 0;
    // A plenum's limit holds for the whole step: a share per sub-step
    scalarField& maxMass = gas_.plenum().maxMass;
    maxMass /= n;
    const label nm = mouths_.size();
    mouthMass_.setSize(nm); mouthMass_ = 0;
    mouthMass1_.setSize(nm); mouthMass1_ = 0;
    mouthEnergy_.setSize(nm); mouthEnergy_ = 0;
    mouthMomentum_.setSize(nm); mouthMomentum_ = Zero;
    for (label k = 0; k < n; ++k)
    {
        const scalar s0 = scalar(k)/n, s1 = scalar(k + 1)/n;
        forAll(VEnd_, i)
        {
            g.V0[i] = V0_[i] + s0*(VEnd_[i] - V0_[i]);
            g.V1[i] = V0_[i] + s1*(VEnd_[i] - V0_[i]);
        }
        gas_.advance(h);
        forAll(mouths_, m)
        {
            const label f = links_.size() + m;
            mouthMass_[m] += gas_.inMass()[f];
            mouthMass1_[m] += gas_.inMass1()[f];
            mouthEnergy_[m] += gas_.inEnergy()[f];
            mouthMomentum_[m] += gas_.inMomentum()[f];
        }
    }
    maxMass *= n;
    nGasSubSteps_ = n;
    return sum(work_);
}


// ************************************************************************* //

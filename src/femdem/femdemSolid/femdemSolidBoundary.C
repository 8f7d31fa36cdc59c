/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Boundary conditions of femdemSolid on named patches: fixed, prescribed
    velocity (some components), traction, follower pressure; reactions.

\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"
#include "HashSet.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::femdemSolid::setBoundaryConditions(const dictionary& dict)
{
    const dictionary bcDict = dict.subOrEmptyDict("boundaryConditions");
    const wordList keys = bcDict.toc();
    bcs_.setSize(keys.size());
    bcReaction_.setSize(keys.size(), Zero);

    forAll(keys, b)
    {
        const word& key = keys[b];
        if (!bcDict.isDict(key))
        {
            FatalIOErrorInFunction(bcDict)
                << "entry '" << key << "' must be a dictionary"
                << exit(FatalIOError);
        }
        const dictionary& d = bcDict.subDict(key);
        boundaryCondition& bc = bcs_[b];
        bc.patchName = key;
        bc.patch = patchNames_.find(key);
        if (bc.patch < 0)
        {
            FatalIOErrorInFunction(bcDict)
                << "patch '" << key << "' is not in the solid mesh (entry"
                << " 'boundary' of constant/" << triangleMesh::meshFileName
                << "); patches: " << patchNames_ << exit(FatalIOError);
        }
        const word type = d.get<word>("type");
        bc.value = Zero;
        bc.pressure = 0;
        bc.mask = 3;
        bc.rampTime = d.getOrDefault<scalar>("rampTime", 0);
        if (!(bc.rampTime >= 0))
        {
            FatalIOErrorInFunction(d)
                << "entry 'rampTime' is " << bc.rampTime << "; it must be"
                << " >= 0 (0: no ramp)" << exit(FatalIOError);
        }
        if (type == "fixed")
        {
            bc.type = boundaryCondition::FIXED;
        }
        else if (type == "velocity")
        {
            bc.type = boundaryCondition::VELOCITY;
            bc.value = d.get<vector2D>("value");
            const wordList comps =
                d.getOrDefault<wordList>("components", wordList({"x", "y"}));
            bc.mask = 0;
            for (const word& c : comps)
            {
                if (c == "x") bc.mask |= 1;
                else if (c == "y") bc.mask |= 2;
                else
                {
                    FatalIOErrorInFunction(d)
                        << "entry 'components': unknown component '" << c
                        << "' (x or y)" << exit(FatalIOError);
                }
            }
        }
        else if (type == "traction")
        {
            bc.type = boundaryCondition::TRACTION;
            bc.value = d.get<vector2D>("value");
        }
        else if (type == "pressure")
        {
            bc.type = boundaryCondition::PRESSURE;
            bc.pressure = d.get<scalar>("value");
        }
        else if (type == "symmetryPlane")
        {
            bc.type = boundaryCondition::SYMMETRYPLANE;
        }
        else
        {
            FatalIOErrorInFunction(d)
                << "entry 'type': unknown boundary condition '" << type
                << "' (fixed, velocity, traction, pressure, symmetryPlane)"
                << exit(FatalIOError);
        }

        // Faces of the patch, and its nodes: every node at a vertex of the
        // patch, not only those of the triangles owning its faces, so that
        // a triangle touching the patch at one vertex only (a fan) obeys the
        // condition too: otherwise its copy of the vertex is held by joint
        // stiffness alone and drifts off a symmetry plane by round-off
        DynamicList<label> faces;
        labelHashSet vertices;
        forAll(topo_.boundaryPatch(), fi)
        {
            if (topo_.boundaryPatch()[fi] != bc.patch) continue;
            faces.append(fi);
            const label t = topo_.boundaryTriangle()[fi];
            const label k = topo_.boundaryEdge()[fi];
            for (const label n : {3*t + k, 3*t + (k + 1) % 3})
            {
                vertices.insert(topo_.nodeVertex()[n]);
            }
        }
        DynamicList<label> nodeList;
        forAll(topo_.nodeVertex(), n)
        {
            if (vertices.found(topo_.nodeVertex()[n])) nodeList.append(n);
        }
        bc.faces.transfer(faces);
        if
        (
            bc.type == boundaryCondition::FIXED
         || bc.type == boundaryCondition::VELOCITY
         || bc.type == boundaryCondition::SYMMETRYPLANE
        )
        {
            bc.nodes.transfer(nodeList);
        }
        if (bc.type == boundaryCondition::SYMMETRYPLANE)
        {
            setSymmetryPlane(bc, d);
        }
    }

    labelHashSet constrained;
    for (const boundaryCondition& bc : bcs_) constrained.insert(bc.nodes);
    constrainedNodes_ = constrained.sortedToc();
}


Foam::scalar Foam::femdemSolid::ramp
(
    const boundaryCondition& bc,
    const scalar t
) const
{
    return bc.rampTime > 0 ? min(t/bc.rampTime, scalar(1)) : 1;
}


void Foam::femdemSolid::addLoads(UList<vector2D>& f) const
{
    for (const boundaryCondition& bc : bcs_)
    {
        if
        (
            bc.type != boundaryCondition::TRACTION
         && bc.type != boundaryCondition::PRESSURE
        )
        {
            continue;
        }
        const scalar r = ramp(bc, time_);
        for (const label fi : bc.faces)
        {
            const label t = topo_.boundaryTriangle()[fi];
            const label k = topo_.boundaryEdge()[fi];
            const label a = 3*t + k, b = 3*t + (k + 1) % 3;
            const vector2D e = x_[b] - x_[a];
            vector2D F;
            if (bc.type == boundaryCondition::TRACTION)
            {
                F = 0.5*r*mag(e)*bc.value;
            }
            else
            {
                // Outward normal times length: (e_y, -e_x)
                F = -0.5*r*bc.pressure*vector2D(e.y(), -e.x());
            }
            f[a] += F;
            f[b] += F;
        }
    }
    if (fExt_.size())
    {
        forAll(fExt_, i) f[i] += fExt_[i];
    }
}


void Foam::femdemSolid::stateBeforeConstraint
(
    const label n,
    const scalar dt,
    vector2D& vOld,
    vector2D& F
) const
{
    // Velocity before the update (the unconstrained update inverted when
    // the old velocities are not kept) and the total force on the node
    const scalar alpha = massDamping_;
    const scalar m = 1/invMass_[n];
    vOld =
        trackEnergy_
      ? vOld_[n]
      : (v_[n] - dt*(invMass_[n]*f_[n] + gravity_))/(1 - alpha*dt);
    F = f_[n] + m*gravity_ - alpha*m*vOld;
}


void Foam::femdemSolid::applyConstraints(const scalar dt, const scalar tNew)
{
    forAll(bcs_, b)
    {
        boundaryCondition& bc = bcs_[b];
        if (bc.type == boundaryCondition::SYMMETRYPLANE)
        {
            applySymmetryPlane(b, dt);
            continue;
        }
        if
        (
            bc.type != boundaryCondition::FIXED
         && bc.type != boundaryCondition::VELOCITY
        )
        {
            continue;
        }
        const vector2D target = ramp(bc, tNew)*bc.value;
        vector2D R(Zero);
        scalar work = 0;
        for (const label n : bc.nodes)
        {
            const scalar m = 1/invMass_[n];
            vector2D vOld, F;
            stateBeforeConstraint(n, dt, vOld, F);
            // A halo node's force is incomplete: its owner counts it
            const scalar share = nodeShare_.empty() ? 1 : nodeShare_[n];
            for (direction c = 0; c < 2; ++c)
            {
                if (!(bc.mask & (1 << c))) continue;
                v_[n][c] = target[c];
                const scalar Rc = share*(m*(target[c] - vOld[c])/dt - F[c]);
                R[c] += Rc;
                work += Rc*0.5*dt*(vOld[c] + target[c]);
            }
        }
        bcReaction_[b] = R;
        wExt_ += work;
    }
}


void Foam::femdemSolid::setSymmetryPlane
(
    boundaryCondition& bc,
    const dictionary& dict
) const
{
    // Normal from the faces (the solid lies to the left of each boundary
    // edge: inward normal (-e_y, e_x)); every vertex must lie on the plane
    vector2D sumN(Zero);
    scalar length = 0;
    for (const label fi : bc.faces)
    {
        const label t = topo_.boundaryTriangle()[fi];
        const label k = topo_.boundaryEdge()[fi];
        const vector2D e = x_[3*t + (k + 1) % 3] - x_[3*t + k];
        sumN += vector2D(-e.y(), e.x());
        length += mag(e);
    }
    const scalar magN = mag(sumN);
    if (bc.faces.empty() || !(magN > 0.999*length))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'type symmetryPlane' of patch '" << bc.patchName
            << "': the patch is "
            << (bc.faces.empty() ? "empty" : "not one straight line")
            << " (a symmetry plane must be straight)" << exit(FatalIOError);
    }
    bc.normal = sumN/magN;
    bc.origin = x_[bc.nodes[0]];
    for (const label n : bc.nodes)
    {
        const scalar dist = mag((x_[n] - bc.origin) & bc.normal);
        if (dist > 1e-6*length)
        {
            FatalIOErrorInFunction(dict)
                << "entry 'type symmetryPlane' of patch '" << bc.patchName
                << "': vertex " << x_[n] << " lies " << dist
                << " m off the plane through " << bc.origin << " with normal "
                << bc.normal << " (a symmetry plane must be straight)"
                << exit(FatalIOError);
        }
    }
}


void Foam::femdemSolid::applySymmetryPlane(const label b, const scalar dt)
{
    // Roller in the plane's normal direction n: v.n = 0 after the update;
    // reaction and its work as for a velocity condition on that component
    const boundaryCondition& bc = bcs_[b];
    const vector2D& nrm = bc.normal;
    scalar Rn = 0, work = 0;
    for (const label n : bc.nodes)
    {
        const scalar m = 1/invMass_[n];
        vector2D vOld, F;
        stateBeforeConstraint(n, dt, vOld, F);
        const scalar Fn = F & nrm;
        const scalar vOldN = vOld & nrm;
        v_[n] -= (v_[n] & nrm)*nrm;
        const scalar share = nodeShare_.empty() ? 1 : nodeShare_[n];
        const scalar R = share*(-m*vOldN/dt - Fn);
        Rn += R;
        work += R*0.5*dt*vOldN;
    }
    bcReaction_[b] = Rn*nrm;
    wExt_ += work;
}


void Foam::femdemSolid::addSymmetryPlaneContact(UList<vector2D>& f) const
{
    // Every node behind a plane (the nodes on it are held there) is pushed
    // back by its contact spring: the mirror image's contact, frictionless
    const label n = x_.size();
    const vector2D* x = x_.cdata();
    const scalar* k = nodeContactSpring_.cdata();
    for (const boundaryCondition& bc : bcs_)
    {
        if (bc.type != boundaryCondition::SYMMETRYPLANE) continue;
        const vector2D nrm = bc.normal;
        const scalar d0 = bc.origin & nrm;
        for (label i = 0; i < n; ++i)
        {
            const scalar d = d0 - (x[i] & nrm);
            if (d > 0)
            {
                f[i] += (k[i]*d)*nrm;
            }
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector2D Foam::femdemSolid::reaction(const word& patchName) const
{
    forAll(bcs_, b)
    {
        if (bcs_[b].patchName == patchName) return bcReaction_[b];
    }
    FatalErrorInFunction
        << "no boundary condition on patch '" << patchName << "'"
        << exit(FatalError);
    return Zero;
}


bool Foam::femdemSolid::hasBoundaryCondition(const word& patchName) const
{
    for (const boundaryCondition& bc : bcs_)
    {
        if (bc.patchName == patchName) return true;
    }
    return false;
}


const Foam::labelList& Foam::femdemSolid::patchNodes
(
    const word& patchName
) const
{
    forAll(bcs_, b)
    {
        if (bcs_[b].patchName == patchName) return bcs_[b].nodes;
    }
    FatalErrorInFunction
        << "no boundary condition on patch '" << patchName << "'"
        << exit(FatalError);
    return bcs_[0].nodes;
}


// ************************************************************************* //

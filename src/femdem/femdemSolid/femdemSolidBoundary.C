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
        else
        {
            FatalIOErrorInFunction(d)
                << "entry 'type': unknown boundary condition '" << type
                << "' (fixed, velocity, traction, pressure)"
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
        )
        {
            bc.nodes.transfer(nodeList);
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


void Foam::femdemSolid::applyConstraints(const scalar dt, const scalar tNew)
{
    const scalar alpha = massDamping_;
    forAll(bcs_, b)
    {
        boundaryCondition& bc = bcs_[b];
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
            const vector2D vUnc = v_[n];
            // Velocity before the update (unconstrained update inverted)
            const vector2D vOld =
                trackEnergy_
              ? vOld_[n]
              : (vUnc - dt*(invMass_[n]*f_[n] + gravity_))/(1 - alpha*dt);
            const vector2D F = f_[n] + m*gravity_ - alpha*m*vOld;
            for (direction c = 0; c < 2; ++c)
            {
                if (!(bc.mask & (1 << c))) continue;
                v_[n][c] = target[c];
                const scalar Rc = m*(target[c] - vOld[c])/dt - F[c];
                R[c] += Rc;
                work += Rc*0.5*dt*(vOld[c] + target[c]);
            }
        }
        bcReaction_[b] = R;
        wExt_ += work;
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

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Diagnostics (energies, fragments, memory) and the state I/O of
    femdemSolid (strain energy and stress: femdemSolidElastic.C).

\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"
#include "cohesiveLaw.H"
#include "contactLaw.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    template<class T>
    std::size_t bytes(const UList<T>& l) { return l.size()*sizeof(T); }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::femdemSolid::kineticEnergy() const
{
    scalar energy = 0;
    if (nodeShare_.empty())
    {
        forAll(v_, i) energy += 0.5*magSqr(v_[i])/invMass_[i];
    }
    else
    {
        forAll(v_, i) energy += nodeShare_[i]*0.5*magSqr(v_[i])/invMass_[i];
    }
    return energy;
}


Foam::vector2D Foam::femdemSolid::momentum() const
{
    vector2D p(Zero);
    if (nodeShare_.empty())
    {
        forAll(v_, i) p += v_[i]/invMass_[i];
    }
    else
    {
        forAll(v_, i) p += nodeShare_[i]*v_[i]/invMass_[i];
    }
    return p;
}


Foam::femdemSolid::energyBudget Foam::femdemSolid::energies() const
{
    energyBudget e;
    e.kinetic = kineticEnergy();
    e.elastic = elasticEnergy();
    e.jointStored = jointStoredStaggered();
    // Intact, undamaged joints dissipate nothing: before the first damage
    // the joints' unbalanced work is left in the residual
    e.fracture =
        jointsDamaged_
      ? -wJoint_ - (e.jointStored - jointStored0_) - jointError_
      : 0;
    e.damping = -wDamp_;
    e.contact = -wContact_;
    e.gravity = wGravity_;
    e.external = wExt_;
    e.initial = energy0_;
    return e;
}


Foam::scalar Foam::femdemSolid::jointStoredStaggered() const
{
    // The budget integrates the joint work of a step as f_n.(v_n +
    // v_n+1) dt/2 (exact for the kinetic energy of the symplectic Euler
    // step), i.e. f_n.(x_n+1 - x_n-1)/2. For joint forces f = -K x the
    // sum of these telescopes to the change of the staggered energy
    // x_n.K x_n+1/2 = U(x_n) - f_n.(x_n+1 - x_n)/2, not of U(x_n+1): the
    // difference, of the order of the step, showed as a negative
    // 'fracture' (to -3.1e-3 J/m, some 15 % of the stored energy, in a bar
    // before its first joint broke; -1.1e-4 J/m in a bar never damaged).
    // What remains (7e-5 of the stored energy, independent of the step)
    // comes from the joint forces not being the exact gradient of the
    // stored energy; checkDamageOnset leaves it in the residual.
    if (!trackEnergy_ || lastDt_ <= 0)
    {
        return cohesive_->storedEnergy(*this);
    }

    // U(x_n): the positions of the last step's start, x_n+1 - dt v_n+1;
    // x_ is restored bit for bit from the copy
    List<vector2D>& x = const_cast<List<vector2D>&>(x_);
    xScratch_ = x;
    scalar fDx = 0;
    forAll(x, i)
    {
        const vector2D dx = lastDt_*v_[i];
        x[i] -= dx;
        fDx += nodeShare_.empty() ? fJoint_[i] & dx : nodeShare_[i]*(fJoint_[i] & dx);
    }
    const scalar U = cohesive_->storedEnergy(*this);
    x = xScratch_;
    return U - 0.5*fDx;
}


bool Foam::femdemSolid::anyJointDamaged() const
{
    forAll(damage_, j)
    {
        if (damage_[j] > 0 || broken_[j]) return true;
    }
    return false;
}


void Foam::femdemSolid::setDamageOnset()
{
    // (A partitioned solid: on every rank at the same step, the first in
    // which any rank saw damage: joints carry energy across the ranks, so
    // only the sum of the ranks' joint errors at one instant is the
    // serial one)
    jointsDamaged_ = true;
    jointError_ = -wJoint_ - (jointStoredStaggered() - jointStored0_);
}


void Foam::femdemSolid::setBudgetShare(const UList<bool>& ownedTriangle)
{
    if (ownedTriangle.size() != area0_.size())
    {
        FatalErrorInFunction
            << ownedTriangle.size() << " ownership flags for "
            << area0_.size() << " triangles" << exit(FatalError);
    }
    nodeShare_.setSize(x_.size());
    forAll(nodeShare_, i)
    {
        nodeShare_[i] = ownedTriangle[i/3] ? 1 : 0;
    }
    jointShare_.setSize(broken_.size());
    forAll(jointShare_, j)
    {
        jointShare_[j] = ownedTriangle[topo_.jointTriangleA()[j]];
    }
    ownedLawTriangles_.clear();
    ownedLawTriangles_.setSize(elasticLaw::nLaws);
    List<DynamicList<label>> owned(elasticLaw::nLaws);
    forAll(ownedTriangle, t)
    {
        if (ownedTriangle[t])
        {
            owned[materials_[triangleMaterial_[t]].law].append(t);
        }
    }
    forAll(owned, l) ownedLawTriangles_[l].transfer(owned[l]);
}


Foam::scalarList Foam::femdemSolid::energyAccounts() const
{
    return scalarList
    ({
        wTri_, wDamp_, wJoint_, wContact_, wGravity_, wExt_, energy0_,
        jointStored0_, jointError_, scalar(jointsDamaged_)
    });
}


void Foam::femdemSolid::setEnergyAccounts(const UList<scalar>& acc)
{
    if (acc.size() != 10)
    {
        FatalErrorInFunction
            << "10 energy accounts needed, got " << acc.size()
            << exit(FatalError);
    }
    wTri_ = acc[0]; wDamp_ = acc[1]; wJoint_ = acc[2]; wContact_ = acc[3];
    wGravity_ = acc[4]; wExt_ = acc[5]; energy0_ = acc[6];
    jointStored0_ = acc[7]; jointError_ = acc[8]; jointsDamaged_ = acc[9] != 0;
}


void Foam::femdemSolid::resetEnergyBudget()
{
    wTri_ = wDamp_ = wJoint_ = wContact_ = wGravity_ = wExt_ = 0;
    jointError_ = 0;
    jointsDamaged_ = false;
    forAll(damage_, j)
    {
        jointsDamaged_ = jointsDamaged_ || damage_[j] > 0 || broken_[j];
    }
    jointStored0_ = cohesive_->storedEnergy(*this);
    energy0_ = kineticEnergy() + elasticEnergy() + jointStored0_;
}


Foam::List<Foam::vector2D> Foam::femdemSolid::triangleVelocity() const
{
    List<vector2D> u(area0_.size());
    forAll(u, t)
    {
        u[t] = (v_[3*t] + v_[3*t + 1] + v_[3*t + 2])/3;
    }
    return u;
}


Foam::scalarList Foam::femdemSolid::triangleDamage() const
{
    scalarList d(area0_.size(), scalar(0));
    const labelList& edgeJoint = topo_.edgeJoint();
    forAll(d, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            const label j = edgeJoint[3*t + k];
            if (j >= 0) d[t] = max(d[t], broken_[j] ? 1 : damage_[j]);
        }
    }
    return d;
}


const Foam::continuousView& Foam::femdemSolid::view() const
{
    if (!view_.valid())
    {
        view_.reset(new continuousView(topo_));
    }
    view_->update(x_, broken_);
    return *view_;
}


Foam::femdemSolid::fragmentData Foam::femdemSolid::fragments() const
{
    const continuousView& cv = view();
    const label nF = cv.nFragments();
    fragmentData fd;
    fd.mass.setSize(nF, scalar(0));
    fd.area.setSize(nF, scalar(0));
    fd.centroid.setSize(nF, Zero);
    fd.velocity.setSize(nF, Zero);
    const labelList& frag = cv.fragmentOfTriangle();
    forAll(area0_, t)
    {
        const label fr = frag[t];
        const vector2D& a = x_[3*t];
        const vector2D& b = x_[3*t + 1];
        const vector2D& c = x_[3*t + 2];
        const scalar A =
            0.5*((b.x() - a.x())*(c.y() - a.y()) - (b.y() - a.y())*(c.x() - a.x()));
        const scalar m = materials_[triangleMaterial_[t]].rho*area0_[t];
        fd.mass[fr] += m;
        fd.area[fr] += A;
        fd.centroid[fr] += A*(a + b + c)/3;
        fd.velocity[fr] += m*(v_[3*t] + v_[3*t + 1] + v_[3*t + 2])/3;
    }
    forAll(fd.mass, fr)
    {
        fd.centroid[fr] /= fd.area[fr];
        fd.velocity[fr] /= fd.mass[fr];
    }
    return fd;
}


std::size_t Foam::femdemSolid::memoryBytes() const
{
    std::size_t b =
        bytes(topo_.jointTriangleA()) + bytes(topo_.jointEdgeA())
      + bytes(topo_.jointTriangleB()) + bytes(topo_.jointEdgeB())
      + bytes(topo_.jointNodes()) + bytes(topo_.edgeJoint())
      + bytes(topo_.boundaryTriangle()) + bytes(topo_.boundaryEdge())
      + bytes(topo_.boundaryPatch())
      + bytes(topo_.nodeVertex()) + bytes(topo_.initialPoints())
      + bytes(triangleMaterial_) + bytes(DmInv_) + bytes(area0_)
      + bytes(freeEdges_) + bytes(stepScale_) + bytes(springOmega2_)
      + bytes(lawTriangles_[0]) + bytes(lawTriangles_[1])
      + bytes(x_) + bytes(v_) + bytes(f_) + bytes(invMass_) + bytes(fExt_)
      + bytes(jointClass_) + bytes(jointLength0_) + bytes(damage_)
      + bytes(broken_) + bytes(jointStrength_)
      + bytes(fTri_) + bytes(fDamp_) + bytes(fJoint_) + bytes(fContact_)
      + bytes(fLoad_) + bytes(vOld_) + bytes(constrainedNodes_);
    for (const boundaryCondition& bc : bcs_)
    {
        b += bytes(bc.nodes) + bytes(bc.faces);
    }
    return b + contact_->memoryBytes();
}


void Foam::femdemSolid::writeState(Ostream& os) const
{
    const int oldPrecision = os.precision(17);
    os.writeEntry("time", time_);
    os.writeEntry("timeIndex", step_);
    os.writeEntry("nNodes", x_.size());
    os.writeEntry("nJoints", broken_.size());
    os.writeEntry("x", x_);
    os.writeEntry("v", v_);
    os.writeEntry("damage", damage_);
    os.writeEntry("broken", broken_);
    os.writeEntry("energyAccounts", energyAccounts());
    if (fExt_.size()) os.writeEntry("externalForce", fExt_);
    // The step follows the state of the last force evaluation (one step
    // behind x): kept so that a restart takes the same sub-steps
    os.writeEntry("stableTimeStep", deltaT_);
    // The last step: the next velocity update spans half of it
    os.writeEntry("lastTimeStep", lastDt_);
    os.precision(oldPrecision);
}


void Foam::femdemSolid::setState
(
    List<vector2D>& x,
    List<vector2D>& v,
    scalarList& damage,
    boolList& broken,
    const scalar time,
    const label timeIndex
)
{
    if
    (
        x.size() != x_.size() || v.size() != v_.size()
     || damage.size() != damage_.size() || broken.size() != broken_.size()
    )
    {
        FatalErrorInFunction
            << "state of " << x.size() << ", " << v.size() << " nodes and "
            << damage.size() << ", " << broken.size() << " joints for a"
            << " solid of " << x_.size() << " nodes and " << broken_.size()
            << " joints" << exit(FatalError);
    }
    // The continuous view follows joints that break (incremental update);
    // a state with a joint intact that is broken now needs a new view
    bool healed = false;
    forAll(broken_, j) healed = healed || (broken_[j] && !broken[j]);
    x_.transfer(x);
    v_.transfer(v);
    damage_.transfer(damage);
    broken_.transfer(broken);
    nBroken_ = 0;
    forAll(broken_, j) if (broken_[j]) ++nBroken_;
    markFreeEdges();
    if (healed)
    {
        view_.clear();
    }
    time_ = time;
    step_ = timeIndex;
}


void Foam::femdemSolid::readState(const dictionary& dict)
{
    List<vector2D> x = dict.get<List<vector2D>>("x");
    List<vector2D> v = dict.get<List<vector2D>>("v");
    scalarList damage = dict.get<scalarList>("damage");
    boolList broken = dict.get<boolList>("broken");
    if (x.size() != x_.size() || v.size() != v_.size())
    {
        FatalIOErrorInFunction(dict)
            << "entries 'x', 'v': " << x.size() << ", " << v.size()
            << " nodes for a mesh of " << x_.size() << " nodes"
            << exit(FatalIOError);
    }
    if (damage.size() != damage_.size() || broken.size() != broken_.size())
    {
        FatalIOErrorInFunction(dict)
            << "entries 'damage', 'broken': sizes " << damage.size() << ", "
            << broken.size() << " for " << broken_.size() << " joints"
            << exit(FatalIOError);
    }
    setState
    (
        x, v, damage, broken, dict.get<scalar>("time"),
        dict.get<label>("timeIndex")
    );
    const scalarList acc = dict.get<scalarList>("energyAccounts");
    if (acc.size() != 8 && acc.size() != 10)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'energyAccounts' needs 10 values (8 in states written"
            << " before the joint error account), got " << acc.size()
            << exit(FatalIOError);
    }
    wTri_ = acc[0]; wDamp_ = acc[1]; wJoint_ = acc[2]; wContact_ = acc[3];
    wGravity_ = acc[4]; wExt_ = acc[5]; energy0_ = acc[6];
    jointStored0_ = acc[7];
    // Older states: fracture counted from the start, as they were written
    jointError_ = acc.size() == 10 ? acc[8] : 0;
    jointsDamaged_ = acc.size() == 10 ? acc[9] != 0 : true;
    if (dict.found("externalForce"))
    {
        fExt_ = dict.get<List<vector2D>>("externalForce");
    }
    // A state written before the step followed the deformation has no
    // entry: the step of the state read
    if (!dict.readIfPresent("stableTimeStep", deltaT_))
    {
        updateStableTimeStep();
    }
    else if (!(deltaT_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'stableTimeStep' must be positive, got " << deltaT_
            << exit(FatalIOError);
    }
    // Older states: the next step's velocity update spans the step itself
    lastDt_ = 0;
    if (dict.readIfPresent("lastTimeStep", lastDt_) && !(lastDt_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'lastTimeStep' must be >= 0, got " << lastDt_
            << exit(FatalIOError);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"
#include "caseChecks.H"
#include "cohesiveLaw.H"
#include "contactLaw.H"
#include "jointSetStrengths.H"
#include <cstdlib>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(femdemSolid, 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::femdemSolid::setMaterials
(
    const triangleMesh& mesh,
    const dictionary& dict
)
{
    const dictionary& mdict = dict.subDict("materials");
    // Top-level default of the materials' elastic law
    const elasticLaw::lawType defaultLaw =
        elasticLaw::read(dict, elasticLaw::neoHookean);
    const wordList& names = mesh.materials();
    if (names.size() > 16)
    {
        FatalIOErrorInFunction(mdict)
            << "the solid mesh has " << names.size() << " materials; at most"
            << " 16 are supported" << exit(FatalIOError);
    }
    materials_.setSize(names.size());
    forAll(names, m)
    {
        if (!mdict.isDict(names[m]))
        {
            FatalIOErrorInFunction(mdict)
                << "material '" << names[m] << "' of the solid mesh has no"
                << " sub-dictionary in 'materials' (found: " << mdict.toc()
                << ")" << exit(FatalIOError);
        }
        materials_[m] =
            femdemMaterial(names[m], mdict.subDict(names[m]), defaultLaw);
    }
    triangleMaterial_ = mesh.triangleMaterials();
    materialTable_.set(materials_);
}


void Foam::femdemSolid::setReference(const triangleMesh& mesh)
{
    x_ = jointTopology::nodePositions(mesh);
    const label nTri = mesh.nTriangles();
    v_.setSize(x_.size(), Zero);
    f_.setSize(x_.size(), Zero);
    invMass_.setSize(x_.size());
    DmInv_.setSize(nTri);
    area0_.setSize(nTri);

    for (label t = 0; t < nTri; ++t)
    {
        const vector2D& X0 = x_[3*t];
        const vector2D& X1 = x_[3*t + 1];
        const vector2D& X2 = x_[3*t + 2];
        const scalar axx = X1.x() - X0.x(), axy = X2.x() - X0.x();
        const scalar ayx = X1.y() - X0.y(), ayy = X2.y() - X0.y();
        const scalar det = axx*ayy - axy*ayx;
        // triangleMesh rejects such triangles; a mesh built otherwise must
        // not divide by zero here
        if (!(det > 0 && std::isfinite(1/det)))
        {
            FatalErrorInFunction
                << "triangle " << t << " (" << X0 << " " << X1 << " " << X2
                << ") has area " << 0.5*det << ": degenerate or inverted"
                << exit(FatalError);
        }
        DmInv_[t] = tensor2D(ayy/det, -axy/det, -ayx/det, axx/det);
        area0_[t] = 0.5*det;
        const scalar im = 3/(materials_[triangleMaterial_[t]].rho*area0_[t]);
        for (label k = 0; k < 3; ++k) invMass_[3*t + k] = im;
    }
}


void Foam::femdemSolid::setJoints(const triangleMesh& mesh)
{
    const label nMat = materials_.size();
    jointClasses_.setSize(nMat*nMat);
    for (label a = 0; a < nMat; ++a)
    {
        for (label b = 0; b < nMat; ++b)
        {
            jointClasses_[a*nMat + b] =
                femdemMaterial::joint(materials_[a], materials_[b]);
        }
    }

    const label nJ = topo_.nJoints();
    jointClass_.setSize(nJ);
    jointLength0_.setSize(nJ);
    damage_.setSize(nJ, scalar(0));
    broken_.setSize(nJ, false);
    nBroken_ = 0;
    forAll(jointClass_, j)
    {
        jointClass_[j] =
            triangleMaterial_[topo_.jointTriangleA()[j]]*nMat
          + triangleMaterial_[topo_.jointTriangleB()[j]];
        const jointNodeList& n = topo_.jointNodes()[j];
        jointLength0_[j] = mag(x_[n[1]] - x_[n[0]]);
    }
    setJointStrengths();
    // Pre-existing joints of the mesh's joint sets: their own properties
    jointSetStrengths::apply
    (
        mesh, topo_, materials_, jointClasses_, jointClass_, jointStrength_
    );
}


void Foam::femdemSolid::setJointStrengths()
{
    // Material whose distribution a pair of materials uses: the weaker
    // (smaller f_t; on a tie the lower index, which does not depend on
    // which side of the joint is A)
    const label nMat = materials_.size();
    labelList classSource(nMat*nMat);
    bool any = false;
    for (label a = 0; a < nMat; ++a)
    {
        any = any || materials_[a].strength.active();
        for (label b = 0; b < nMat; ++b)
        {
            const scalar fa = materials_[a].ft, fb = materials_[b].ft;
            classSource[a*nMat + b] =
                (fa < fb || (fa == fb && a <= b)) ? a : b;
        }
    }
    jointStrength_.clear();
    if (!any) return;

    const List<vector2D>& X = topo_.initialPoints();
    const labelList& vertex = topo_.nodeVertex();
    jointStrength_.setSize(jointClass_.size());
    forAll(jointStrength_, j)
    {
        const jointNodeList& n = topo_.jointNodes()[j];
        const strengthDistribution& sd =
            materials_[classSource[jointClass_[j]]].strength;
        jointStrength_[j] = sd.factor(X[vertex[n[0]]], X[vertex[n[1]]]);
    }
}


void Foam::femdemSolid::markFreeEdges()
{
    const labelList& edgeJoint = topo_.edgeJoint();
    freeEdges_.setSize(area0_.size());
    forAll(freeEdges_, t)
    {
        unsigned char m = 0;
        for (label k = 0; k < 3; ++k)
        {
            const label j = edgeJoint[3*t + k];
            if (j < 0 || broken_[j]) m |= (1u << k);
        }
        freeEdges_[t] = m;
    }
    ++freeEdgeChanges_;
}


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::femdemSolid* Foam::femdemSolid::active_ = nullptr;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::femdemSolid::femdemSolid
(
    const triangleMesh& mesh,
    const dictionary& dict
)
:
    topo_(mesh),
    patchNames_(mesh.patchNames()),
    singleLaw_(-1),
    freeEdgeChanges_(0),
    nBroken_(0),
    gravity_(dict.getOrDefault<vector2D>("gravity", vector2D::zero)),
    massDamping_(dict.getOrDefault<scalar>("massDamping", 0)),
    cohesive_(cohesiveLaw::New(dict)),
    contact_(contactLaw::New(dict)),
    time_(0),
    step_(0),
    deltaT_(0),
    safety_(dict.getOrDefault<scalar>("timeStepSafety", 0.5)),
    stiffestTriangle_(-1),
    stepOmega2_(0),
    stepXi2_(0),
    stepRate2_(0),
    maxStrainIncrement_(dict.getOrDefault<scalar>("maxStrainIncrement", 0.1)),
    maxNodeSpeed_(dict.getOrDefault<scalar>("maxNodeSpeed", 1e5)),
    maxSpeedSqr_(0),
    trackEnergy_(dict.getOrDefault<bool>("trackEnergy", false)),
    wTri_(0), wDamp_(0), wJoint_(0), wContact_(0), wGravity_(0), wExt_(0),
    energy0_(0),
    jointStored0_(0),
    lastDt_(0),
    jointsDamaged_(false),
    jointError_(0),
    damageSeen_(false),
    halo_(nullptr)
{
    // Before any product of the values: 1e300 would overflow to inf
    caseChecks::checkNumbers(dict);
    if (!(safety_ > 0 && safety_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'timeStepSafety' must lie in (0, 1], got " << safety_
            << exit(FatalIOError);
    }
    if (!(maxStrainIncrement_ > 0 && maxStrainIncrement_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'maxStrainIncrement' must lie in (0, 1], got "
            << maxStrainIncrement_ << exit(FatalIOError);
    }
    if (!(maxNodeSpeed_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'maxNodeSpeed' must be positive, got " << maxNodeSpeed_
            << exit(FatalIOError);
    }
    if (massDamping_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'massDamping' must be >= 0, got " << massDamping_
            << exit(FatalIOError);
    }
    setMaterials(mesh, dict);
    setReference(mesh);
    setLawGroups();
    setJoints(mesh);
    markFreeEdges();
    setBoundaryConditions(dict);
    setStableStepConstants();
    updateStableTimeStep();
    // Optional uniform initial velocity (a restart state overrides it)
    v_ = dict.getOrDefault<vector2D>("initialVelocity", vector2D::zero);
    if (trackEnergy_)
    {
        const label n = x_.size();
        fTri_.setSize(n); fDamp_.setSize(n); fJoint_.setSize(n);
        fContact_.setSize(n); fLoad_.setSize(n); vOld_.setSize(n);
    }
    active_ = this;
}


Foam::femdemSolid::~femdemSolid()
{
    if (active_ == this) active_ = nullptr;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::cohesiveLaw& Foam::femdemSolid::cohesive() const
{
    return *cohesive_;
}


const Foam::contactLaw& Foam::femdemSolid::contact() const
{
    return *contact_;
}


Foam::List<Foam::vector2D>& Foam::femdemSolid::externalForce()
{
    if (fExt_.empty()) fExt_.setSize(x_.size(), Zero);
    return fExt_;
}


void Foam::femdemSolid::jointsBroken(const label n)
{
    if (n > 0)
    {
        nBroken_ += n;
        markFreeEdges();
    }
}


void Foam::femdemSolid::setBroken(const label j)
{
    if (!broken_[j])
    {
        broken_[j] = true;
        damage_[j] = 1;
        ++nBroken_;
        ++freeEdgeChanges_;
        // Only the two faces of j become free
        freeEdges_[topo_.jointTriangleA()[j]] |= (1u << topo_.jointEdgeA()[j]);
        freeEdges_[topo_.jointTriangleB()[j]] |= (1u << topo_.jointEdgeB()[j]);
    }
}


void Foam::femdemSolid::step(const scalar dt)
{
    const label n = x_.size();
    const scalar tNew = time_ + dt;
    // Velocities live at the half steps: the force at t_n acts from the
    // middle of the last step to the middle of this one (the central
    // difference with variable steps); equal steps give dt itself
    const scalar kick = lastDt_ > 0 ? 0.5*(lastDt_ + dt) : dt;

    if (!trackEnergy_)
    {
        f_ = Zero;
        addLoads(f_);
        setStableTimeStep(addTriangleForces(f_, f_));
        jointsBroken(cohesive_->addForces(*this, f_));
        contact_->addForces(*this, f_, kick);
        addSymmetryPlaneContact(f_);
    }
    else
    {
        fTri_ = Zero; fDamp_ = Zero; fJoint_ = Zero; fContact_ = Zero;
        fLoad_ = Zero;
        addLoads(fLoad_);
        setStableTimeStep(addTriangleForces(fTri_, fDamp_));
        jointsBroken(cohesive_->addForces(*this, fJoint_));
        contact_->addForces(*this, fContact_, kick);
        addSymmetryPlaneContact(fContact_);
        for (label i = 0; i < n; ++i)
        {
            f_[i] = fTri_[i] + fDamp_[i] + fJoint_[i] + fContact_[i]
              + fLoad_[i];
        }
        vOld_ = v_;
    }

    // Velocity update: gravity and mass-proportional damping added here;
    // in the same pass the position update of the nodes that no condition
    // constrains (the others' after the constraints)
    const vector2D g = gravity_;
    const scalar alpha = massDamping_;
    vector2D* v = v_.data();
    vector2D* x = x_.data();
    const vector2D* f = f_.cdata();
    const scalar* im = invMass_.cdata();
    const label* cn = constrainedNodes_.cdata();
    const label nc = constrainedNodes_.size();
    label c = 0;
    scalar maxSpeedSqr = 0;
    // A partitioned solid: halo nodes are not integrated (their owners'
    // state overwrites theirs after the step)
    const scalar* owned = nodeShare_.empty() ? nullptr : nodeShare_.cdata();
    for (label i = 0; i < n; ++i)
    {
        if (owned && owned[i] == 0)
        {
            if (c < nc && cn[c] == i) ++c;
            continue;
        }
        v[i] += kick*(im[i]*f[i] + g - alpha*v[i]);
        const scalar s2 = magSqr(v[i]);
        // written so that a NaN is taken as the largest
        maxSpeedSqr = s2 <= maxSpeedSqr ? maxSpeedSqr : s2;
        if (c < nc && cn[c] == i)
        {
            ++c;
            continue;
        }
        x[i] += dt*v[i];
    }
    maxSpeedSqr_ = maxSpeedSqr;

    applyConstraints(kick, tNew);

    if (trackEnergy_)
    {
        const scalar h = 0.5*kick;
        scalar wt = 0, wd = 0, wj = 0, wc = 0, wl = 0, wg = 0;
        // A partitioned solid counts its owned nodes only (the halo's
        // forces are incomplete): weights 1 or 0, bitwise the serial sum
        const scalar* share = nodeShare_.empty() ? nullptr : nodeShare_.cdata();
        for (label i = 0; i < n; ++i)
        {
            const vector2D vm =
                share ? (share[i]*h)*(vOld_[i] + v[i]) : h*(vOld_[i] + v[i]);
            wt += fTri_[i] & vm;
            wd += (fDamp_[i] - alpha/im[i]*vOld_[i]) & vm;
            wj += fJoint_[i] & vm;
            wc += fContact_[i] & vm;
            wl += fLoad_[i] & vm;
            wg += (g & vm)/im[i];
        }
        if (workDisplacement_.size())
        {
            for (label i = 0; i < n; ++i)
            {
                workDisplacement_[i] += h*(vOld_[i] + v[i]);
            }
        }
        wTri_ += wt; wDamp_ += wd; wJoint_ += wj; wContact_ += wc;
        wExt_ += wl; wGravity_ += wg;
    }

    for (const label i : constrainedNodes_)
    {
        x[i] += dt*v[i];
    }

    time_ = tNew;
    lastDt_ = dt;
    ++step_;

    // Once per run: at the end of the step that damaged the first joint
    // the joints' unbalanced work goes into jointError_
    damageSeen_ = trackEnergy_ && (jointsDamaged_ || anyJointDamaged());

    // A partitioned solid: halo nodes from their owners, the stable step,
    // the speed check and the damage onset global, so that every rank
    // sub-steps alike
    if (halo_)
    {
        halo_->afterStep(*this);
    }

    if (damageSeen_ && !jointsDamaged_)
    {
        setDamageOnset();
    }
}


Foam::FixedList<Foam::scalar, 6>
Foam::femdemSolid::haloExchange::stepData(const femdemSolid& s)
{
    FixedList<scalar, 6> d;
    d[0] = s.stepOmega2_;
    d[1] = s.stepXi2_;
    d[2] = s.stepRate2_;
    d[3] = s.maxSpeedSqr_;
    d[4] = s.damageSeen_;
    d[5] = s.contact_->listExpired(s);
    return d;
}


void Foam::femdemSolid::haloExchange::setStepData
(
    femdemSolid& s,
    const FixedList<scalar, 6>& d
)
{
    s.stepOmega2_ = d[0];
    s.stepXi2_ = d[1];
    s.stepRate2_ = d[2];
    s.maxSpeedSqr_ = d[3];
    s.damageSeen_ = d[4] > 0;
    s.contact_->setListExpired(d[5] > 0);
    s.setStableTimeStep();
}


void Foam::femdemSolid::holdWorkDisplacement()
{
    workDisplacement_.setSize(x_.size(), Zero);
}


void Foam::femdemSolid::trackWorkDisplacement()
{
    if (!trackEnergy_)
    {
        FatalErrorInFunction
            << "the work displacement needs energy tracking: entry"
            << " 'trackEnergy' of constant/femdemProperties must be true"
            << exit(FatalError);
    }
    workDisplacement_.setSize(x_.size(), Zero);
}


void Foam::femdemSolid::checkInterval(const scalar interval) const
{
    // More than 1e8 sub-steps per interval is a case error (a deltaT made
    // for another problem), and beyond 2^31 the count would not fit a label
    if (!(interval < 1e8*deltaT_))
    {
        FatalErrorInFunction
            << "the interval of " << interval << " s to advance the FEMDEM"
            << " solid needs more than 1e8 sub-steps of its stable time step "
            << deltaT_ << " s: entry 'deltaT' (or 'maxDeltaT') of"
            << " system/controlDict is far too large for this solid"
            << exit(FatalError);
    }
}


Foam::label Foam::femdemSolid::advance
(
    const scalar interval,
    subStepHook& hook
)
{
    workDisplacement_ = Zero;
    checkInterval(interval);
    scalar t = 0;
    label n = 0;
    while (t < interval*(1 - 1e-12))
    {
        const scalar hMax = hook.beforeSubStep(*this);
        const scalar h = min(min(deltaT_, hMax), interval - t);
        if (!(h > 1e-8*interval) && h < interval - t)
        {
            if (hMax < deltaT_)
            {
                FatalErrorInFunction
                    << "the sub-step the coupling allows fell to " << hMax
                    << " s at time " << time_ << " (more than 1e8 sub-steps"
                    << " for the remaining " << interval - t << " s)"
                    << exit(FatalError);
            }
            reportStepCollapse(interval - t);
        }
        step(h);
        if (!(maxSpeedSqr_ <= sqr(maxNodeSpeed_)))
        {
            reportDivergence();
        }
        hook.afterSubStep(*this);
        t += h;
        ++n;
    }
    return n;
}


Foam::label Foam::femdemSolid::advance(const scalar interval)
{
    workDisplacement_ = Zero;
    checkInterval(interval);
    label n = max(label(std::ceil(interval/deltaT_*(1 - 1e-12))), 1);
    scalar dt = interval/n;
    for (label i = 0; i < n; ++i)
    {
        step(dt);
        if (!(maxSpeedSqr_ <= sqr(maxNodeSpeed_)))
        {
            reportDivergence();
        }
        // The step just taken set deltaT_ from the state it started at:
        // when the solid has stiffened (compression) re-split the rest
        if (deltaT_ < dt && i + 1 < n)
        {
            const scalar rest = (n - i - 1)*dt;
            if (!(rest < 1e8*deltaT_)) reportStepCollapse(rest);
            const label m = label(std::ceil(rest/deltaT_*(1 - 1e-12)));
            dt = rest/m;
            n = i + 1 + m;
        }
    }
    return n;
}


void Foam::femdemSolid::reportStepCollapse(const scalar rest) const
{
    const label t = max(stiffestTriangle_, 0);
    const vector2D d1 = x_[3*t + 1] - x_[3*t], d2 = x_[3*t + 2] - x_[3*t];
    FatalErrorInFunction
        << "the FEMDEM stable time step fell to " << deltaT_ << " s at time "
        << time_ << ": more than 1e8 sub-steps for the remaining " << rest
        << " s of the interval. Stiffest triangle " << t << " at "
        << x_[3*t] << " has " << 0.5*(d1.x()*d2.y() - d1.y()*d2.x())/area0_[t]
        << " of its initial area (crushed)."
        << exit(FatalError);
    std::abort();
}


void Foam::femdemSolid::reportDivergence() const
{
    label worst = 0;
    forAll(v_, i)
    {
        if (!(magSqr(v_[i]) <= magSqr(v_[worst]))) worst = i;
    }
    FatalErrorInFunction
        << "the FEMDEM solid is diverging at time " << time_ << ": node "
        << worst << " at " << x_[worst] << " moves at " << mag(v_[worst])
        << " m/s, above maxNodeSpeed " << maxNodeSpeed_ << " m/s (a crushed"
        << " or inverted triangle; a smaller timeStepSafety or a finer"
        << " mesh may help). Stopping without writing this time; the last"
        << " written time is the last good state."
        << exit(FatalError);
    std::abort();   // exit() throws or exits; keeps [[noreturn]] true
}


// ************************************************************************* //

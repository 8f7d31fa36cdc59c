/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"
#include "cohesiveLaw.H"
#include "contactLaw.H"

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
        materials_[m] = femdemMaterial(names[m], mdict.subDict(names[m]));
    }
    triangleMaterial_ = mesh.triangleMaterials();
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
        DmInv_[t] = tensor2D(ayy/det, -axy/det, -ayx/det, axx/det);
        area0_[t] = 0.5*det;
        const scalar im = 3/(materials_[triangleMaterial_[t]].rho*area0_[t]);
        for (label k = 0; k < 3; ++k) invMass_[3*t + k] = im;
    }
}


void Foam::femdemSolid::setJoints()
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
}


void Foam::femdemSolid::computeStableTimeStep()
{
    // Highest frequency per node: element (2c/h_min)^2 plus the joint and
    // contact springs acting on the node (added in parallel)
    scalarList omega2(x_.size(), scalar(0));
    scalar maxXi = 0;
    forAll(area0_, t)
    {
        const femdemMaterial& mat = materials_[triangleMaterial_[t]];
        scalar maxEdge = 0;
        for (label k = 0; k < 3; ++k)
        {
            maxEdge = max(maxEdge, mag(x_[3*t + (k + 1) % 3] - x_[3*t + k]));
        }
        const scalar hMin = 2*area0_[t]/maxEdge;
        const scalar wt = 2*mat.waveSpeed()/hMin;
        // Contact spring of a free-face node: traction 3 p d/h_min over L/2
        const scalar kc = 1.5*mat.pc*maxEdge/hMin;
        for (label k = 0; k < 3; ++k)
        {
            const label n = 3*t + k;
            omega2[n] += wt*wt + 2*kc*invMass_[n];
        }
        maxXi = max(maxXi, mat.dampingRatio);
    }
    forAll(jointClass_, j)
    {
        const femdemJointProperties& P = jointClasses_[jointClass_[j]];
        const scalar k = 0.5*max(P.pn, P.ps);
        const jointNodeList& n = topo_.jointNodes()[j];
        for (label e = 0; e < 2; ++e)
        {
            const label p = n[e], q = n[e + 2];
            const scalar w2 = k*(invMass_[p] + invMass_[q]);
            omega2[p] += w2;
            omega2[q] += w2;
        }
    }
    scalar omegaMax = 0;
    forAll(omega2, n) omegaMax = max(omegaMax, omega2[n]);
    omegaMax = std::sqrt(omegaMax);
    const scalar dampingFactor = std::sqrt(1 + maxXi*maxXi) - maxXi;
    deltaT_ = safety_*2/omegaMax*dampingFactor;
}


void Foam::femdemSolid::addTriangleForces
(
    UList<vector2D>& fe,
    UList<vector2D>& fv
) const
{
    // Per-material constants, looked up by index in the loop
    const label nMat = materials_.size();
    scalar lam[16], mu2[16], etaC[16], s0xx[16], s0xy[16], s0yy[16];
    if (nMat > 16)
    {
        FatalErrorInFunction << "more than 16 materials" << exit(FatalError);
    }
    for (label m = 0; m < nMat; ++m)
    {
        const femdemMaterial& mat = materials_[m];
        lam[m] = mat.lambda;
        mu2[m] = 2*mat.mu;
        etaC[m] = mat.dampingRatio*2*std::sqrt(mat.rho*mat.Mp);
        s0xx[m] = mat.initialStress.xx();
        s0xy[m] = mat.initialStress.xy();
        s0yy[m] = mat.initialStress.yy();
    }

    const vector2D* x = x_.cdata();
    const vector2D* v = v_.cdata();
    const tensor2D* Di = DmInv_.cdata();
    const scalar* A0 = area0_.cdata();
    const label* matOf = triangleMaterial_.cdata();
    vector2D* pe = fe.data();
    vector2D* pv = fv.data();

    const label nTri = area0_.size();
    for (label t = 0; t < nTri; ++t)
    {
        const label n0 = 3*t;
        const label m = matOf[t];
        const vector2D& x0 = x[n0];
        const vector2D& x1 = x[n0 + 1];
        const vector2D& x2 = x[n0 + 2];
        const tensor2D& D = Di[t];
        const scalar d1x = x1.x() - x0.x(), d1y = x1.y() - x0.y();
        const scalar d2x = x2.x() - x0.x(), d2y = x2.y() - x0.y();

        // Deformation gradient F = Ds Dm^-1
        const scalar Fxx = d1x*D.xx() + d2x*D.yx();
        const scalar Fxy = d1x*D.xy() + d2x*D.yy();
        const scalar Fyx = d1y*D.xx() + d2y*D.yx();
        const scalar Fyy = d1y*D.xy() + d2y*D.yy();

        // Green-Lagrange strain and St Venant-Kirchhoff stress
        const scalar Exx = 0.5*(Fxx*Fxx + Fyx*Fyx - 1);
        const scalar Eyy = 0.5*(Fxy*Fxy + Fyy*Fyy - 1);
        const scalar Exy = 0.5*(Fxx*Fxy + Fyx*Fyy);
        const scalar ltr = lam[m]*(Exx + Eyy);
        const scalar Sxx = ltr + mu2[m]*Exx + s0xx[m];
        const scalar Syy = ltr + mu2[m]*Eyy + s0yy[m];
        const scalar Sxy = mu2[m]*Exy + s0xy[m];

        // First Piola-Kirchhoff P = F S
        const scalar Pxx = Fxx*Sxx + Fxy*Sxy;
        const scalar Pxy = Fxx*Sxy + Fxy*Syy;
        const scalar Pyx = Fyx*Sxx + Fyy*Sxy;
        const scalar Pyy = Fyx*Sxy + Fyy*Syy;

        // Nodal forces H = -A0 P Dm^-T: columns on nodes 1 and 2
        const scalar a = -A0[t];
        const scalar Hxx = a*(Pxx*D.xx() + Pxy*D.xy());
        const scalar Hxy = a*(Pxx*D.yx() + Pxy*D.yy());
        const scalar Hyx = a*(Pyx*D.xx() + Pyy*D.xy());
        const scalar Hyy = a*(Pyx*D.yx() + Pyy*D.yy());
        pe[n0 + 1].x() += Hxx;
        pe[n0 + 1].y() += Hyx;
        pe[n0 + 2].x() += Hxy;
        pe[n0 + 2].y() += Hyy;
        pe[n0].x() -= Hxx + Hxy;
        pe[n0].y() -= Hyx + Hyy;

        if (etaC[m] > 0)
        {
            // Viscous stress eta sym(L), L = dF/dt F^-1
            const vector2D& v0 = v[n0];
            const scalar w1x = v[n0 + 1].x() - v0.x(), w1y = v[n0 + 1].y() - v0.y();
            const scalar w2x = v[n0 + 2].x() - v0.x(), w2y = v[n0 + 2].y() - v0.y();
            const scalar Gxx = w1x*D.xx() + w2x*D.yx();
            const scalar Gxy = w1x*D.xy() + w2x*D.yy();
            const scalar Gyx = w1y*D.xx() + w2y*D.yx();
            const scalar Gyy = w1y*D.xy() + w2y*D.yy();
            const scalar J = Fxx*Fyy - Fxy*Fyx;
            const scalar iJ = 1/J;
            // F^-1 = [Fyy -Fxy; -Fyx Fxx]/J
            const scalar Lxx = (Gxx*Fyy - Gxy*Fyx)*iJ;
            const scalar Lxy = (-Gxx*Fxy + Gxy*Fxx)*iJ;
            const scalar Lyx = (Gyx*Fyy - Gyy*Fyx)*iJ;
            const scalar Lyy = (-Gyx*Fxy + Gyy*Fxx)*iJ;
            const scalar eta = etaC[m]*std::sqrt(2*A0[t]);
            const scalar sxx = eta*Lxx, syy = eta*Lyy;
            const scalar sxy = 0.5*eta*(Lxy + Lyx);
            // P_v = J sigma F^-T = sigma [Fyy -Fyx; -Fxy Fxx]
            const scalar Qxx = sxx*Fyy - sxy*Fxy;
            const scalar Qxy = -sxx*Fyx + sxy*Fxx;
            const scalar Qyx = sxy*Fyy - syy*Fxy;
            const scalar Qyy = -sxy*Fyx + syy*Fxx;
            const scalar Vxx = a*(Qxx*D.xx() + Qxy*D.xy());
            const scalar Vxy = a*(Qxx*D.yx() + Qxy*D.yy());
            const scalar Vyx = a*(Qyx*D.xx() + Qyy*D.xy());
            const scalar Vyy = a*(Qyx*D.yx() + Qyy*D.yy());
            pv[n0 + 1].x() += Vxx;
            pv[n0 + 1].y() += Vyx;
            pv[n0 + 2].x() += Vxy;
            pv[n0 + 2].y() += Vyy;
            pv[n0].x() -= Vxx + Vxy;
            pv[n0].y() -= Vyx + Vyy;
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::femdemSolid::femdemSolid
(
    const triangleMesh& mesh,
    const dictionary& dict
)
:
    topo_(mesh),
    patchNames_(mesh.patchNames()),
    nBroken_(0),
    gravity_(dict.getOrDefault<vector2D>("gravity", vector2D::zero)),
    massDamping_(dict.getOrDefault<scalar>("massDamping", 0)),
    cohesive_(cohesiveLaw::New(dict)),
    contact_(contactLaw::New(dict)),
    time_(0),
    step_(0),
    deltaT_(0),
    safety_(dict.getOrDefault<scalar>("timeStepSafety", 0.5)),
    maxNodeSpeed_(dict.getOrDefault<scalar>("maxNodeSpeed", 1e5)),
    maxSpeedSqr_(0),
    trackEnergy_(dict.getOrDefault<bool>("trackEnergy", false)),
    wTri_(0), wDamp_(0), wJoint_(0), wContact_(0), wGravity_(0), wExt_(0),
    energy0_(0),
    jointStored0_(0)
{
    if (!(safety_ > 0 && safety_ <= 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'timeStepSafety' must lie in (0, 1], got " << safety_
            << exit(FatalIOError);
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
    setJoints();
    markFreeEdges();
    setBoundaryConditions(dict);
    computeStableTimeStep();
    // Optional uniform initial velocity (a restart state overrides it)
    v_ = dict.getOrDefault<vector2D>("initialVelocity", vector2D::zero);
    if (trackEnergy_)
    {
        const label n = x_.size();
        fTri_.setSize(n); fDamp_.setSize(n); fJoint_.setSize(n);
        fContact_.setSize(n); fLoad_.setSize(n); vOld_.setSize(n);
    }
}


Foam::femdemSolid::~femdemSolid()
{}


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
        // Only the two faces of j become free
        freeEdges_[topo_.jointTriangleA()[j]] |= (1u << topo_.jointEdgeA()[j]);
        freeEdges_[topo_.jointTriangleB()[j]] |= (1u << topo_.jointEdgeB()[j]);
    }
}


void Foam::femdemSolid::step(const scalar dt)
{
    const label n = x_.size();
    const scalar tNew = time_ + dt;

    if (!trackEnergy_)
    {
        f_ = Zero;
        addLoads(f_);
        addTriangleForces(f_, f_);
        jointsBroken(cohesive_->addForces(*this, f_));
        contact_->addForces(*this, f_, dt);
    }
    else
    {
        fTri_ = Zero; fDamp_ = Zero; fJoint_ = Zero; fContact_ = Zero;
        fLoad_ = Zero;
        addLoads(fLoad_);
        addTriangleForces(fTri_, fDamp_);
        jointsBroken(cohesive_->addForces(*this, fJoint_));
        contact_->addForces(*this, fContact_, dt);
        for (label i = 0; i < n; ++i)
        {
            f_[i] = fTri_[i] + fDamp_[i] + fJoint_[i] + fContact_[i]
              + fLoad_[i];
        }
        vOld_ = v_;
    }

    // Velocity update: gravity and mass-proportional damping added here
    const vector2D g = gravity_;
    const scalar alpha = massDamping_;
    vector2D* v = v_.data();
    const vector2D* f = f_.cdata();
    const scalar* im = invMass_.cdata();
    scalar maxSpeedSqr = 0;
    for (label i = 0; i < n; ++i)
    {
        v[i] += dt*(im[i]*f[i] + g - alpha*v[i]);
        const scalar s2 = magSqr(v[i]);
        // written so that a NaN is taken as the largest
        maxSpeedSqr = s2 <= maxSpeedSqr ? maxSpeedSqr : s2;
    }
    maxSpeedSqr_ = maxSpeedSqr;

    applyConstraints(dt, tNew);

    if (trackEnergy_)
    {
        const scalar h = 0.5*dt;
        scalar wt = 0, wd = 0, wj = 0, wc = 0, wl = 0, wg = 0;
        for (label i = 0; i < n; ++i)
        {
            const vector2D vm = h*(vOld_[i] + v[i]);
            wt += fTri_[i] & vm;
            wd += (fDamp_[i] - alpha/im[i]*vOld_[i]) & vm;
            wj += fJoint_[i] & vm;
            wc += fContact_[i] & vm;
            wl += fLoad_[i] & vm;
            wg += (g & vm)/im[i];
        }
        wTri_ += wt; wDamp_ += wd; wJoint_ += wj; wContact_ += wc;
        wExt_ += wl; wGravity_ += wg;
    }

    vector2D* x = x_.data();
    for (label i = 0; i < n; ++i)
    {
        x[i] += dt*v[i];
    }

    time_ = tNew;
    ++step_;
}


Foam::label Foam::femdemSolid::advance(const scalar interval)
{
    const label n = max(label(std::ceil(interval/deltaT_*(1 - 1e-12))), 1);
    const scalar dt = interval/n;
    for (label i = 0; i < n; ++i)
    {
        step(dt);
        if (!(maxSpeedSqr_ <= sqr(maxNodeSpeed_)))
        {
            reportDivergence();
        }
    }
    return n;
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
}


// ************************************************************************* //

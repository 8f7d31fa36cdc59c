/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    The triangles of femdemSolid: elastic and viscous nodal forces, strain
    energy, Cauchy stress and the stable time step, each a loop templated
    on the elastic law (elasticLaws::StVenantKirchhoff, neoHookean) and run
    once per group of triangles sharing a law (one group when every
    material has the same law): no virtual call or law branch per triangle.

    The element part of the stable step (stiffness, damping and the
    deformation limit) is evaluated in the force loop from the state the
    forces are computed at (no extra pass over the triangles) and sets the
    step used from the next step on.

\*---------------------------------------------------------------------------*/

#include "femdemSolid.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

//- Deformation gradient F = Ds Dm^-1 of the triangle with nodes n0..n0+2
inline elasticLaws::kinematics kinematicsOf
(
    const vector2D* x,
    const tensor2D& D,
    const label n0
)
{
    const vector2D& x0 = x[n0];
    const scalar d1x = x[n0 + 1].x() - x0.x(), d1y = x[n0 + 1].y() - x0.y();
    const scalar d2x = x[n0 + 2].x() - x0.x(), d2y = x[n0 + 2].y() - x0.y();
    return elasticLaws::kinematics
    (
        d1x*D.xx() + d2x*D.yx(), d1x*D.xy() + d2x*D.yy(),
        d1y*D.xx() + d2y*D.yx(), d1y*D.xy() + d2y*D.yy()
    );
}


//- Add the nodal forces -a P Dm^-T (a = A0) of one triangle
inline void addNodal
(
    vector2D* f,
    const label n0,
    const tensor2D& D,
    const scalar a,
    const tensor2D& P
)
{
    const scalar Hxx = -a*(P.xx()*D.xx() + P.xy()*D.xy());
    const scalar Hxy = -a*(P.xx()*D.yx() + P.xy()*D.yy());
    const scalar Hyx = -a*(P.yx()*D.xx() + P.yy()*D.xy());
    const scalar Hyy = -a*(P.yx()*D.yx() + P.yy()*D.yy());
    f[n0 + 1].x() += Hxx;
    f[n0 + 1].y() += Hyx;
    f[n0 + 2].x() += Hxy;
    f[n0 + 2].y() += Hyy;
    f[n0].x() -= Hxx + Hxy;
    f[n0].y() -= Hyx + Hyy;
}


//- Rate of the deformation gradient G = dF/dt of the triangle at n0
inline tensor2D rateOf(const vector2D* v, const tensor2D& D, const label n0)
{
    const vector2D& v0 = v[n0];
    const scalar w1x = v[n0 + 1].x() - v0.x(), w1y = v[n0 + 1].y() - v0.y();
    const scalar w2x = v[n0 + 2].x() - v0.x(), w2y = v[n0 + 2].y() - v0.y();
    return tensor2D
    (
        w1x*D.xx() + w2x*D.yx(), w1x*D.xy() + w2x*D.yy(),
        w1y*D.xx() + w2y*D.yx(), w1y*D.xy() + w2y*D.yy()
    );
}


//- Viscous stress sigma_v = eta sym(L), L = G F^-1, as the first
//  Piola-Kirchhoff stress |J| sigma_v F^-T = eta sym(G cof^T) cof/|J|:
//  dissipative for any sign of J; |J| floored at Jmin so that a collapsed
//  triangle gives a finite force.
inline tensor2D viscousStress
(
    const elasticLaws::kinematics& k,
    const tensor2D& G,
    const scalar eta
)
{
    const scalar iJ = 1/max(mag(k.J), elasticLaw::Jmin());
    const scalar Lxx = (G.xx()*k.Fyy - G.xy()*k.Fyx)*iJ;
    const scalar Lxy = (-G.xx()*k.Fxy + G.xy()*k.Fxx)*iJ;
    const scalar Lyx = (G.yx()*k.Fyy - G.yy()*k.Fyx)*iJ;
    const scalar Lyy = (-G.yx()*k.Fxy + G.yy()*k.Fxx)*iJ;
    const scalar sxx = eta*Lxx, syy = eta*Lyy;
    const scalar sxy = 0.5*eta*(Lxy + Lyx);
    return tensor2D
    (
        sxx*k.Fyy - sxy*k.Fxy, -sxx*k.Fyx + sxy*k.Fxx,
        sxy*k.Fyy - syy*k.Fxy, -sxy*k.Fyx + syy*k.Fxx
    );
}


//- Largest element frequency, damping ratio and deformation rate over the
//  triangles. The viscous stress scales as s_max^2/|J| (viscousStress), the
//  frequency as sqrt(Q): the damping ratio of the current state is
//  xi^2 = xi_0^2 (s_max^2/|J|)^2 M/Q (xi_0 at rest). The velocity gradient
//  L = G F^-1 is bounded by |G| s_max/|J| (|F^-1| = s_max/|J| in 2D).
struct stepAccount
{
    scalar omega2 = 0;
    scalar xi2 = 0;
    scalar rate2 = 0;
    label triangle = -1;
    label bad = -1;     //- first triangle with a non-finite frequency

    inline void add
    (
        const label t,
        const scalar w2,
        const elasticLaws::kinematics& k,
        const tensor2D& G,
        const scalar Q,
        const scalar xi2M
    )
    {
        if (w2 > omega2)
        {
            omega2 = w2;
            triangle = t;
        }
        else if (!(w2 < VGREAT) && bad < 0)
        {
            bad = t;    // NaN or infinite: reported by setStableTimeStep
        }
        const scalar iJ = 1/max(mag(k.J), elasticLaw::Jmin());
        const scalar r2 = k.s2max*iJ*iJ;
        rate2 = max(rate2, magSqr(G)*r2);
        if (xi2M > 0)
        {
            xi2 = max(xi2, xi2M*r2*k.s2max/Q);
        }
    }

    //- The step data (a bad triangle is reported as a NaN frequency)
    inline void result(scalar& w2, scalar& x2, scalar& l2, label& t) const
    {
        w2 = bad < 0 ? omega2 : std::nan("");
        x2 = xi2;
        l2 = rate2;
        t = bad < 0 ? triangle : bad;
    }
};


//- The triangle loop over one law group (ids: the triangles, null for
//  all): stable-step data and, if Forces, the elastic and viscous forces
template<bool Forces>
struct triangleKernel
{
    const vector2D* x;
    const vector2D* v;
    const tensor2D* Di;
    const scalar* A0;
    const label* matOf;
    const scalar* stepScale;
    const scalar* springs;
    const femdemSolid::materialTable& mats;
    vector2D* pe;
    vector2D* pv;
    stepAccount step;

    template<class Law>
    void run(const label* ids, const label n)
    {
        for (label i = 0; i < n; ++i)
        {
            const label t = ids ? ids[i] : i;
            const label n0 = 3*t;
            const label m = matOf[t];
            const tensor2D& D = Di[t];
            const elasticLaws::kinematics k = kinematicsOf(x, D, n0);
            tensor2D P;
            scalar Q;
            Law::stress(k, mats.c[m], P, Q);
            const tensor2D G = rateOf(v, D, n0);
            step.add(t, stepScale[t]*Q + springs[t], k, G, Q, mats.xi2M[m]);
            if (!Forces) continue;
            addNodal(pe, n0, D, A0[t], P);
            if (mats.etaC[m] > 0)
            {
                const scalar eta = mats.etaC[m]*std::sqrt(2*A0[t]);
                addNodal(pv, n0, D, A0[t], viscousStress(k, G, eta));
            }
        }
    }
};


//- Strain energy, or the Cauchy stress of every triangle
struct energyKernel
{
    const UList<vector2D>& x;
    const UList<tensor2D>& Di;
    const scalarList& A0;
    const labelList& matOf;
    const UList<femdemMaterial>& mats;
    List<symmTensor2D>* sigma;      //- null: energy only
    scalar energy;
    const scalar* share;            //- node shares (null: all count)

    template<class Law>
    void run(const label* ids, const label n)
    {
        for (label i = 0; i < n; ++i)
        {
            const label t = ids ? ids[i] : i;
            const elasticConstants& c = mats[matOf[t]].elastic;
            const elasticLaws::kinematics k = kinematicsOf(x.cdata(), Di[t], 3*t);
            if (sigma)
            {
                tensor2D P;
                scalar Q;
                Law::stress(k, c, P, Q);
                (*sigma)[t] = k.cauchy(P);
            }
            else
            {
                const scalar e = A0[t]*Law::energy(k, c);
                energy += share ? share[3*t]*e : e;
            }
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::femdemSolid::materialTable::set(const UList<femdemMaterial>& mats)
{
    if (mats.size() > 16)
    {
        FatalErrorInFunction << "more than 16 materials" << exit(FatalError);
    }
    forAll(mats, m)
    {
        const femdemMaterial& mat = mats[m];
        c[m] = mat.elastic;
        etaC[m] = mat.dampingRatio*2*std::sqrt(mat.rho*mat.Mp);
        xi2M[m] = sqr(mat.dampingRatio)*mat.Mp;
    }
}


template<class Kernel>
void Foam::femdemSolid::forEachLawGroup
(
    Kernel& kernel,
    const bool ownedOnly
) const
{
    const bool owned = ownedOnly && ownedLawTriangles_.size();
    for (label l = 0; l < elasticLaw::nLaws; ++l)
    {
        const label* ids = nullptr;
        label n = area0_.size();
        if (owned)
        {
            if (ownedLawTriangles_[l].empty()) continue;
            ids = ownedLawTriangles_[l].cdata();
            n = ownedLawTriangles_[l].size();
        }
        else if (singleLaw_ != l)
        {
            if (singleLaw_ >= 0 || lawTriangles_[l].empty()) continue;
            ids = lawTriangles_[l].cdata();
            n = lawTriangles_[l].size();
        }
        if (l == elasticLaw::StVenantKirchhoff)
        {
            kernel.template run<elasticLaws::StVenantKirchhoff>(ids, n);
        }
        else
        {
            kernel.template run<elasticLaws::neoHookean>(ids, n);
        }
    }
}


void Foam::femdemSolid::setLawGroups()
{
    lawTriangles_.clear();
    lawTriangles_.setSize(elasticLaw::nLaws);
    labelList count(elasticLaw::nLaws, Zero);
    for (const label m : triangleMaterial_) ++count[materials_[m].law];
    singleLaw_ = -1;
    forAll(count, l)
    {
        if (count[l] == area0_.size()) singleLaw_ = l;
    }
    if (singleLaw_ >= 0) return;        // one group: no index lists
    forAll(count, l) lawTriangles_[l].setSize(count[l]);
    count = Zero;
    forAll(triangleMaterial_, t)
    {
        const label l = materials_[triangleMaterial_[t]].law;
        lawTriangles_[l][count[l]++] = t;
    }
}


Foam::femdemSolid::stableStep Foam::femdemSolid::addTriangleForces
(
    UList<vector2D>& fe,
    UList<vector2D>& fv
) const
{
    const materialTable& mats = materialTable_;
    triangleKernel<true> kernel
    {
        x_.cdata(), v_.cdata(), DmInv_.cdata(), area0_.cdata(),
        triangleMaterial_.cdata(), stepScale_.cdata(), springOmega2_.cdata(),
        mats, fe.data(), fv.data(), stepAccount()
    };
    // A partitioned solid's halo triangles push halo nodes only: skipped
    // (their stable-step data too: every triangle is owned by one rank,
    // and the step is the largest over the ranks)
    forEachLawGroup(kernel, true);
    stableStep s;
    kernel.step.result(s.omega2, s.xi2, s.rate2, s.triangle);
    return s;
}


void Foam::femdemSolid::setStableStepConstants()
{
    // Reference part: (2/h_min)^2/rho per triangle (times Q: the element
    // frequency squared) and the joint and contact springs acting on its
    // nodes (in parallel with the element; the largest of its 3 nodes)
    scalarList omega2(x_.size(), scalar(0));
    nodeContactSpring_.setSize(x_.size());
    stepScale_.setSize(area0_.size());
    forAll(area0_, t)
    {
        const femdemMaterial& mat = materials_[triangleMaterial_[t]];
        scalar maxEdge = 0;
        for (label k = 0; k < 3; ++k)
        {
            maxEdge = max(maxEdge, mag(x_[3*t + (k + 1) % 3] - x_[3*t + k]));
        }
        const scalar hMin = 2*area0_[t]/maxEdge;
        stepScale_[t] = 4/(mat.rho*hMin*hMin);
        // Contact spring of a free-face node: traction 3 p d/h_min over L/2
        const scalar kc = 1.5*mat.pc*maxEdge/hMin;
        for (label k = 0; k < 3; ++k)
        {
            omega2[3*t + k] += 2*kc*invMass_[3*t + k];
            nodeContactSpring_[3*t + k] = kc;
        }
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
    springOmega2_.setSize(area0_.size());
    forAll(springOmega2_, t)
    {
        springOmega2_[t] =
            max(omega2[3*t], max(omega2[3*t + 1], omega2[3*t + 2]));
    }
}


void Foam::femdemSolid::setStableTimeStep(const stableStep& s)
{
    // Central differences with damping ratio xi: omega dt <= 2 (sqrt(1 +
    // xi^2) - xi). A non-finite or zero frequency (a non-finite position,
    // a collapsed triangle without springs) would give a zero, infinite or
    // NaN step: stop, naming the triangle.
    if
    (
        !(s.omega2 > 0 && std::isfinite(s.omega2) && std::isfinite(s.xi2)
       && std::isfinite(s.rate2))
    )
    {
        const label t = max(s.triangle, 0);
        const elasticLaws::kinematics k = kinematicsOf(x_.cdata(), DmInv_[t], 3*t);
        FatalErrorInFunction
            << "no finite stable time step at time " << time_
            << ": triangle " << t << " (material "
            << materials_[triangleMaterial_[t]].name << ", nodes at "
            << x_[3*t] << " " << x_[3*t + 1] << " " << x_[3*t + 2]
            << ") has J = " << k.J << ", omega^2 = " << s.omega2
            << ", damping ratio^2 = " << s.xi2 << " (a degenerate or"
            << " non-finite triangle)" << exit(FatalError);
    }
    stiffestTriangle_ = s.triangle;
    stepOmega2_ = s.omega2;
    stepXi2_ = s.xi2;
    stepRate2_ = s.rate2;
    setStableTimeStep();
}


void Foam::femdemSolid::setStableTimeStep()
{
    const scalar xi = std::sqrt(stepXi2_);
    deltaT_ = safety_*2/std::sqrt(stepOmega2_)*(std::sqrt(1 + stepXi2_) - xi);
    // Deformation limit |L| dt <= maxStrainIncrement: fast-closing or
    // spinning triangles are resolved in time
    if (stepRate2_*sqr(deltaT_) > sqr(maxStrainIncrement_))
    {
        deltaT_ = maxStrainIncrement_/std::sqrt(stepRate2_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::femdemSolid::updateStableTimeStep()
{
    const materialTable& mats = materialTable_;
    triangleKernel<false> kernel
    {
        x_.cdata(), v_.cdata(), DmInv_.cdata(), area0_.cdata(),
        triangleMaterial_.cdata(), stepScale_.cdata(), springOmega2_.cdata(),
        mats, nullptr, nullptr, stepAccount()
    };
    forEachLawGroup(kernel);
    stableStep s;
    kernel.step.result(s.omega2, s.xi2, s.rate2, s.triangle);
    setStableTimeStep(s);
}


Foam::scalar Foam::femdemSolid::elasticEnergy() const
{
    energyKernel kernel
        {
            x_, DmInv_, area0_, triangleMaterial_, materials_, nullptr, 0,
            nodeShare_.empty() ? nullptr : nodeShare_.cdata()
        };
    forEachLawGroup(kernel);
    return kernel.energy;
}


Foam::List<Foam::symmTensor2D> Foam::femdemSolid::stress() const
{
    List<symmTensor2D> sigma(area0_.size());
    energyKernel kernel
        {x_, DmInv_, area0_, triangleMaterial_, materials_, &sigma, 0, nullptr};
    forEachLawGroup(kernel);
    return sigma;
}


// ************************************************************************* //

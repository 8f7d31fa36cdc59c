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

    The force loop has two forms, bitwise the same forces and step data:
    the scalar loop (triangleKernel::runScalar) and, where the CPU has
    AVX-512 (femdemSolid::vectorCode), blocks of 64 triangles as lanes
    (runLanes, laneArithmeticV4), whose arithmetic GCC vectorises.

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


//- Add the nodal terms H = -a P Dm^-T of one triangle to its nodes
inline void addTerms
(
    vector2D* f,
    const label n0,
    const scalar Hxx,
    const scalar Hxy,
    const scalar Hyx,
    const scalar Hyy
)
{
    f[n0 + 1].x() += Hxx;
    f[n0 + 1].y() += Hyx;
    f[n0 + 2].x() += Hxy;
    f[n0 + 2].y() += Hyy;
    f[n0].x() -= Hxx + Hxy;
    f[n0].y() -= Hyx + Hyy;
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
    addTerms
    (
        f, n0,
        -a*(P.xx()*D.xx() + P.xy()*D.xy()), -a*(P.xx()*D.yx() + P.xy()*D.yy()),
        -a*(P.yx()*D.xx() + P.yy()*D.xy()), -a*(P.yx()*D.yx() + P.yy()*D.yy())
    );
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

    //- One triangle's data from its ingredients: w2, the rate term |G|^2
    //  r2 and the damping term xi2M r2 s2max/Q (used if xi2M > 0)
    inline void addData
    (
        const label t,
        const scalar w2,
        const scalar rateTerm,
        const scalar xiTerm,
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
        rate2 = max(rate2, rateTerm);
        if (xi2M > 0)
        {
            xi2 = max(xi2, xiTerm);
        }
    }

    //- One triangle's data from its state
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
        const scalar iJ = 1/max(mag(k.J), elasticLaw::Jmin());
        const scalar r2 = k.s2max*iJ*iJ;
        addData
        (
            t, w2, magSqr(G)*r2, xi2M > 0 ? xi2M*r2*k.s2max/Q : 0, xi2M
        );
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


//- One block of triangles as lanes (structure of arrays): the triangle
//  loop gathers a block's nodes and constants into it, does its
//  arithmetic lane by lane in loops that vectorise across triangles, and
//  adds the nodal forces and stable-step data triangle by triangle
struct triangleLanes
{
    static constexpr label size = 64;
    label t[size];
    //- The nodes 0, 1, 2 of each triangle (x, y): copied (GCC does not
    //  vectorise the solid's groups of 6 scalars per triangle)
    scalar x[6][size];
    scalar v[6][size];
    //- A block given by triangle ids: its other inputs copied in the
    //  solid's layout (a contiguous block's are read in place)
    scalar D[4*size];       //- Dm^-1: xx, xy, yx, yy
    scalar A0[size];
    scalar stepScale[size]; //- reference part of the element frequency
    scalar springs[size];   //- joint and contact springs at its nodes
    //- Material constants per lane (filled once for a solid of one
    //  material)
    scalar c[8][size];      //- elastic constants: lambda, mu, s0xx, s0xy,
                            //  s0yy, s0max, gMin, dgMin
    scalar etaC[size];      //- damping: eta = etaC sqrt(2 A0)
    scalar xi2M[size];
    scalar lnJ[size];
    scalar He[4][size];     //- elastic nodal terms Hxx, Hxy, Hyx, Hyy
    scalar Hv[4][size];     //- viscous nodal terms
    scalar w2[size];        //- element frequency squared (with springs)
    scalar rate[size];      //- |G|^2 s_max^2/|J|^2
    scalar xi[size];        //- xi^2 of the current state (damped materials)
};


//- Where the lanes' inputs are: the nodes' x and v in the lanes, the
//  rest in the solid's layout: Dm^-1 (4 values per triangle), A0,
//  stepScale, springs (1 each)
static_assert
(
    sizeof(vector2D) == 2*sizeof(scalar) && sizeof(tensor2D) == 4*sizeof(scalar),
    "laneInputs reads vector2D and tensor2D lists as arrays of scalars"
);

struct laneInputs
{
    const scalar* D;
    const scalar* A0;
    const scalar* stepScale;
    const scalar* springs;
};


//- The kinematics of lane j (the operations of kinematicsOf)
inline elasticLaws::kinematics kinematicsOfLane
(
    const scalar x[6][triangleLanes::size],
    const scalar* Ds,
    const label j
)
{
    const scalar* D = Ds + 4*j;
    const scalar d1x = x[2][j] - x[0][j], d1y = x[3][j] - x[1][j];
    const scalar d2x = x[4][j] - x[0][j], d2y = x[5][j] - x[1][j];
    const scalar Dxx = D[0], Dxy = D[1];
    const scalar Dyx = D[2], Dyy = D[3];
    return elasticLaws::kinematics
    (
        d1x*Dxx + d2x*Dyx, d1x*Dxy + d2x*Dyy,
        d1y*Dxx + d2y*Dyx, d1y*Dxy + d2y*Dyy
    );
}


//- The nodal terms of addNodal (H = -a P Dm^-T) into lane j of H
inline void nodalTermsOfLane
(
    scalar H[4][triangleLanes::size],
    const label j,
    const scalar Dxx, const scalar Dxy, const scalar Dyx, const scalar Dyy,
    const scalar a,
    const tensor2D& P
)
{
    H[0][j] = -a*(P.xx()*Dxx + P.xy()*Dxy);
    H[1][j] = -a*(P.xx()*Dyx + P.xy()*Dyy);
    H[2][j] = -a*(P.yx()*Dxx + P.yy()*Dxy);
    H[3][j] = -a*(P.yx()*Dyx + P.yy()*Dyy);
}


#if defined(__x86_64__) && defined(__GNUC__)
#define FEMDEM_V4 1

//- The arithmetic of one block, lane by lane: log J (glibc's scalar log,
//  its own pass), then kinematics, stress, rate, viscous stress, nodal
//  terms and stable-step data. No branch in the second loop: values are
//  selected, and what a branch of the scalar loop would not compute is
//  computed from harmless operands (the floating-point traps stay quiet),
//  so every lane does exactly the scalar loop's operations. Compiled for
//  x86-64-v4 (AVX-512: 8 lanes per instruction), run where the CPU has it
//  (femdemSolid::vectorCode); no floating-point contraction
//  (-ffp-contract=off, Make/options), so it gives the scalar loop's bits.
//  (For the baseline target and x86-64-v3, AVX2, GCC 12 vectorises the
//  loop only in part: the divisions it moves into branches need AVX-512's
//  masks. That code measured no faster than the scalar loop, which
//  therefore runs on CPUs without AVX-512.)
template<class Law, bool Forces>
__attribute__((target("arch=x86-64-v4"))) void laneArithmeticV4
(
    triangleLanes* __restrict Lp,
    const scalar* __restrict Ds,
    const scalar* __restrict A0,
    const scalar* __restrict stepScale,
    const scalar* __restrict springs,
    const label n
)
{
    triangleLanes& L = *Lp;
    if (Law::usesLogJ)
    {
        for (label j = 0; j < n; ++j)
        {
            L.lnJ[j] = kinematicsOfLane(L.x, Ds, j).J;
        }
        for (label j = 0; j < n; ++j)
        {
            L.lnJ[j] = elasticLaws::neoHookean::logJ(L.lnJ[j]);
        }
    }
    for (label j = 0; j < n; ++j)
    {
        // (the material's constants gathered into the lanes: GCC does not
        // vectorise loads of a struct's members through an index)
        const elasticConstants c
        {
            L.c[0][j], L.c[1][j], L.c[2][j], L.c[3][j], L.c[4][j], L.c[5][j],
            L.c[6][j], L.c[7][j], 0
        };
        const elasticLaws::kinematics k = kinematicsOfLane(L.x, Ds, j);
        tensor2D P;
        scalar Q;
        Law::stress(k, c, L.lnJ[j], P, Q);

        // rateOf
        const scalar* D = Ds + 4*j;
        const scalar Dxx = D[0], Dxy = D[1];
        const scalar Dyx = D[2], Dyy = D[3];
        const scalar w1x = L.v[2][j] - L.v[0][j], w1y = L.v[3][j] - L.v[1][j];
        const scalar w2x = L.v[4][j] - L.v[0][j], w2y = L.v[5][j] - L.v[1][j];
        const tensor2D G
        (
            w1x*Dxx + w2x*Dyx, w1x*Dxy + w2x*Dyy,
            w1y*Dxx + w2y*Dyx, w1y*Dxy + w2y*Dyy
        );

        // stepAccount::add's ingredients (used where xi2M > 0; Q > 0 for
        // a triangle that is not degenerate: the floor only keeps a lane
        // that is not used, or a degenerate one, from a division by zero)
        L.w2[j] = stepScale[j]*Q + springs[j];
        const scalar iJ = 1/max(mag(k.J), elasticLaw::Jmin());
        const scalar r2 = k.s2max*iJ*iJ;
        L.rate[j] = magSqr(G)*r2;
        const scalar xi2M = L.xi2M[j];
        L.xi[j] = xi2M*r2*k.s2max/max(Q, VSMALL);

        if (!Forces) continue;
        const scalar a = A0[j];
        nodalTermsOfLane(L.He, j, Dxx, Dxy, Dyx, Dyy, a, P);
        // Undamped materials: the rate is replaced by 0 (not multiplied:
        // a non-finite rate would raise a trap the scalar loop does not)
        const scalar etaC = L.etaC[j];
        const bool damped = etaC > 0;
        const tensor2D Gv
        (
            damped ? G.xx() : 0, damped ? G.xy() : 0,
            damped ? G.yx() : 0, damped ? G.yy() : 0
        );
        const scalar eta = etaC*std::sqrt(2*a);
        nodalTermsOfLane
        (
            L.Hv, j, Dxx, Dxy, Dyx, Dyy, a, viscousStress(k, Gv, eta)
        );
    }
}
#endif




//- The triangle loop over one law group (ids: the triangles, null for
//  all): stable-step data and, if Forces, the elastic and viscous forces,
//  in blocks of triangleLanes::size
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
    triangleLanes L;

    //- Material of the constants in all lanes (-1: per lane; initialised
    //  so)
    label laneMaterial;

    //- The material constants of triangles t .. (n of them) into the
    //  lanes: once for a run of one material
    void setMaterials(const label* t, const label n)
    {
        const label m0 = matOf[t[0]];
        bool uniform = true;
        for (label j = 1; j < n; ++j) uniform = uniform && matOf[t[j]] == m0;
        if (uniform && m0 == laneMaterial) return;
        auto fill = [&](const label j, const label m)
        {
            const elasticConstants& c = mats.c[m];
            L.c[0][j] = c.lambda;
            L.c[1][j] = c.mu;
            L.c[2][j] = c.s0xx;
            L.c[3][j] = c.s0xy;
            L.c[4][j] = c.s0yy;
            L.c[5][j] = c.s0max;
            L.c[6][j] = c.gMin;
            L.c[7][j] = c.dgMin;
            L.etaC[j] = mats.etaC[m];
            L.xi2M[j] = mats.xi2M[m];
        };
        if (uniform)
        {
            for (label j = 0; j < triangleLanes::size; ++j) fill(j, m0);
            laneMaterial = m0;
        }
        else
        {
            for (label j = 0; j < n; ++j) fill(j, matOf[t[j]]);
            laneMaterial = -1;
        }
    }

    //- The inputs of triangles ids[i0 .. i0 + n) (i0 .. when null): read
    //  in place for a contiguous block, copied into the lanes otherwise
    laneInputs inputs(const label* ids, const label i0, const label n)
    {
        for (label j = 0; j < n; ++j) L.t[j] = ids ? ids[i0 + j] : i0 + j;
        setMaterials(L.t, n);
        for (label j = 0; j < n; ++j)
        {
            const label n0 = 3*L.t[j];
            for (label k = 0; k < 3; ++k)
            {
                L.x[2*k][j] = x[n0 + k].x();
                L.x[2*k + 1][j] = x[n0 + k].y();
                L.v[2*k][j] = v[n0 + k].x();
                L.v[2*k + 1][j] = v[n0 + k].y();
            }
        }
        if (!ids)
        {
            return laneInputs
            {
                &Di[i0].xx(), A0 + i0, stepScale + i0, springs + i0
            };
        }
        for (label j = 0; j < n; ++j)
        {
            const label t = L.t[j];
            const tensor2D& D = Di[t];
            L.D[4*j] = D.xx();
            L.D[4*j + 1] = D.xy();
            L.D[4*j + 2] = D.yx();
            L.D[4*j + 3] = D.yy();
            L.A0[j] = A0[t];
            L.stepScale[j] = stepScale[t];
            L.springs[j] = springs[t];
        }
        return laneInputs{L.D, L.A0, L.stepScale, L.springs};
    }

    //- Add lane j's nodal terms H to the triangle's nodes (addNodal)
    static inline void scatter
    (
        vector2D* f,
        const label n0,
        const scalar H[4][triangleLanes::size],
        const label j
    )
    {
        addTerms(f, n0, H[0][j], H[1][j], H[2][j], H[3][j]);
    }

    //- The scalar loop, triangle by triangle (the reference: the lanes
    //  give its bits)
    template<class Law>
    void runScalar(const label* ids, const label n)
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

    //- The loop in blocks of lanes (AVX-512 code), or the scalar loop
    template<class Law>
    void run(const label* ids, const label n)
    {
#ifdef FEMDEM_V4
        if (femdemSolid::vectorCode() == femdemSolid::AVX512)
        {
            runLanes<Law>(ids, n);
            return;
        }
#endif
        runScalar<Law>(ids, n);
    }

#ifdef FEMDEM_V4
    //- The loop in blocks of triangleLanes::size
    template<class Law>
    void runLanes(const label* ids, const label n)
    {
        for (label i0 = 0; i0 < n; i0 += triangleLanes::size)
        {
            const label nb = min(triangleLanes::size, n - i0);
            const laneInputs in = inputs(ids, i0, nb);
            laneArithmeticV4<Law, Forces>
            (
                &L, in.D, in.A0, in.stepScale, in.springs, nb
            );
            for (label j = 0; j < nb; ++j)
            {
                const label t = L.t[j];
                step.addData(t, L.w2[j], L.rate[j], L.xi[j], L.xi2M[j]);
                if (!Forces) continue;
                scatter(pe, 3*t, L.He, j);
                if (L.etaC[j] > 0) scatter(pv, 3*t, L.Hv, j);
            }
        }
    }
#endif
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


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * //

namespace
{
    //- -1: not decided yet (the switch and the CPU decide on first use)
    int chosenCode = -1;
}


Foam::femdemSolid::vectorCodeType Foam::femdemSolid::cpuVectorCode()
{
#ifdef FEMDEM_V4
    if (__builtin_cpu_supports("x86-64-v4")) return AVX512;
#endif
    return BASELINE;
}


Foam::femdemSolid::vectorCodeType Foam::femdemSolid::vectorCode()
{
    if (chosenCode < 0)
    {
        const label level =
            debug::optimisationSwitch("femdemVectorKernels", 1);
        chosenCode = min(max(level, label(0)), label(cpuVectorCode()));
    }
    return vectorCodeType(chosenCode);
}


void Foam::femdemSolid::setVectorCode(const vectorCodeType code)
{
    chosenCode = min(code, cpuVectorCode());
}


const char* Foam::femdemSolid::vectorCodeName()
{
    return
        vectorCode() == AVX512
      ? "AVX-512 lanes (bitwise the scalar loops; OptimisationSwitch"
        " femdemVectorKernels 0 for those)"
      : cpuVectorCode() == AVX512
      ? "scalar loops (femdemVectorKernels 0)"
      : "scalar loops (the CPU has no AVX-512)";
}


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
        mats, fe.data(), fv.data(), stepAccount(), triangleLanes(), -1
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
        mats, nullptr, nullptr, stepAccount(), triangleLanes(), -1
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

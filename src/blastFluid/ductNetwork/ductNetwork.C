/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "ductNetwork.H"
#include "PstreamReduceOps.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ductNetwork::ductNetwork
(
    const blastMixture& mixture,
    const dictionary& dict
)
:
    mixture_(mixture),
    flux_(fluxScheme::New(dict)),
    rk_(dict),
    frictionFactor_(dict.getOrDefault<scalar>("frictionFactor", 0)),
    kapila_
    (
        mixture.twoPhase() && dict.getOrDefault<bool>("kapilaTerm", true)
    ),
    dt_(0),
    one_(1), one1_(1), one2_(1), oneRho_(1), oneP_(1), oneE_(1), oneC2_(1),
    wallWork_(0)
{
    if (!(frictionFactor_ >= 0) || !std::isfinite(frictionFactor_))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'frictionFactor' (Fanning) must be a number >= 0, got "
            << frictionFactor_ << exit(FatalIOError);
    }
    setSize(0, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::ductNetwork::setSize(const label nVolumes, const label nInterfaces)
{
    const label n = nVolumes, nf = nInterfaces;
    geometry& g = geometry_;
    g.V0.setSize(n, 0); g.V1.setSize(n, 0);
    g.axis.setSize(n, Zero); g.wallArea.setSize(n, 0);
    g.owner.setSize(nf, -1); g.neighbour.setSize(nf, -1);
    g.Sf.setSize(nf, Zero);
    g.wallWork.clear();
    plenum_.rho.setSize(nf, 0); plenum_.p.setSize(nf, 0);
    plenum_.alpha1.setSize(nf, 1);
    plenum_.rho1.setSize(nf, 0); plenum_.rho2.setSize(nf, 0);
    plenum_.maxMass.setSize(nf, 0);

    for (scalarField* q : {&m_, &mE_, &aV_, &m1_})
    {
        q->setSize(n, 0);
    }
    mU_.setSize(n, Zero);
    for
    (
        scalarField* q :
        {
            &m0_, &mE0_, &aV0_, &m10_, &Rm_, &RmE_, &RaV_, &Rm1_, &V_, &dVdt_,
            &dilatation_,
            &rho_, &p_, &c_, &alpha_, &rho1_, &rho2_, &rhoe_, &c2_, &waveSum_,
            &wallWorkOf_, &pMean_
        }
    )
    {
        q->setSize(n);
    }
    mU0_.setSize(n); RmU_.setSize(n); U_.setSize(n, Zero); W_.setSize(n);
    magSf_.setSize(nf);
    for (scalarField* q : {&inMass_, &inEnergy_, &inMass1_, &inAlpha_})
    {
        q->setSize(nf, 0);
    }
    inMomentum_.setSize(nf, Zero);
    faces_.setSize(nf, mixture_.twoPhase());
    F_.setSize(nf, mixture_.twoPhase());
    SfA_.setSize(nf);
    magSfA_.setSize(nf);
    part_.setWhole(n, nf);
}


void Foam::ductNetwork::primitivesAfterStep()
{
    label bad = -1;
    if (!primitives(bad))
    {
        FatalErrorInFunction
            << "ductNetwork: control volume " << bad << " has no physical"
            << " state after the step (mass " << m_[bad] << ", pressure "
            << p_[bad] << ")" << exit(FatalError);
    }
}


void Foam::ductNetwork::distribute(const labelUList& volumeRank)
{
    const geometry& g = geometry_;
    if (volumeRank.size() != size())
    {
        FatalErrorInFunction
            << "ductNetwork: " << volumeRank.size() << " ranks given for "
            << size() << " control volumes" << exit(FatalError);
    }
    part_.set(volumeRank, g.owner, g.neighbour);
    volumeRank_ = volumeRank;
}


void Foam::ductNetwork::collect()
{
    if (part_.whole()) return;
    // Per volume its content, stage volume, work and mean pressure from
    // its owner
    const label n = size(), nComp = 10;
    scalarList& buf = collectBuf_;
    buf.setSize(nComp*n);
    for (const label i : part_.own())
    {
        scalar* b = &buf[nComp*i];
        b[0] = m_[i]; b[1] = mE_[i]; b[2] = aV_[i]; b[3] = m1_[i];
        b[4] = mU_[i].x(); b[5] = mU_[i].y(); b[6] = mU_[i].z();
        b[7] = wallWorkOf_[i]; b[8] = pMean_[i]; b[9] = V_[i];
    }
    ductPartition::fromOwners(buf, nComp, volumeRank_);
    for (label i = 0; i < n; ++i)
    {
        const scalar* b = &buf[nComp*i];
        m_[i] = b[0]; mE_[i] = b[1]; aV_[i] = b[2]; m1_[i] = b[3];
        mU_[i] = vector(b[4], b[5], b[6]);
        wallWorkOf_[i] = b[7]; pMean_[i] = b[8]; V_[i] = b[9];
    }
    // (the sum in another order than one rank's: round-off)
    wallWork_ = returnReduce(wallWork_, sumOp<scalar>());
    part_.setWhole(n, geometry_.owner.size());
    primitivesAfterStep();
}


void Foam::ductNetwork::setState
(
    const label i,
    const scalar rho,
    const vector& U,
    const scalar p,
    const scalar alpha1
)
{
    const scalar V = geometry_.V0[i];
    const scalar a = mixture_.twoPhase() ? alpha1 : 1;
    const scalar rhoe = mixture_.rhoe(a, rho, rho, p);
    m_[i] = rho*V;
    mU_[i] = rho*V*U;
    mE_[i] = (rhoe + 0.5*rho*magSqr(U))*V;
    aV_[i] = a*V;
    m1_[i] = a*rho*V;
    // Its primitives alone (a loop filling every volume stays O(n))
    V_[i] = V;
    rho_[i] = rho;
    U_[i] = U;
    p_[i] = p;
    rhoe_[i] = rhoe;
    alpha_[i] = a;
    rho1_[i] = rho2_[i] = rho;
    c2_[i] = mixtureC2(a, rho, rho, p);
    c_[i] = sqrt(max(c2_[i], scalar(0)));
}


bool Foam::ductNetwork::primitives(label& bad)
{
    const scalar rhoFloor = 1e-12, alphaEps = 1e-12;
    const labelList& active = part_.active();
    bad = -1;
    for (const label i : active)
    {
        const scalar V = V_[i];
        if (!(V > 0) || !(m_[i] > 0) || !std::isfinite(mE_[i]))
        {
            if (bad < 0) bad = i;
            rho_[i] = rho1_[i] = rho2_[i] = 1;
            rhoe_[i] = 1;
            U_[i] = Zero;
            alpha_[i] = 1;
            continue;
        }
        rho_[i] = m_[i]/V;
        U_[i] = mU_[i]/m_[i];
        rhoe_[i] = (mE_[i] - 0.5*(mU_[i] & U_[i]))/V;
        const scalar a = min(max(aV_[i]/V, scalar(0)), scalar(1));
        const scalar m1 = min(max(m1_[i], scalar(0)), m_[i]);
        alpha_[i] = a;
        rho1_[i] = max(m1/(max(a, alphaEps)*V), rhoFloor);
        rho2_[i] = max((m_[i] - m1)/(max(1 - a, alphaEps)*V), rhoFloor);
    }
    // One material: its density in every slot
    auto pc2 = [&]
    (
        const label n, const scalarField& a, const scalarField& r1,
        const scalarField& r2, const scalarField& r, const scalarField& e,
        scalarField& p, scalarField& c2
    )
    {
        if (mixture_.twoPhase()) mixture_.pc2(n, a, r1, r2, r, e, p, c2);
        else mixture_.pc2(n, r, r, r, r, e, p, c2);
    };
    if (part_.whole())
    {
        pc2(size(), alpha_, rho1_, rho2_, rho_, rhoe_, p_, c2_);
    }
    else
    {
        // The equation of state over the active volumes, packed
        const label n = active.size();
        for (scalarField* w : {&wA_, &wR1_, &wR2_, &wR_, &wE_, &wP_, &wC2_})
        {
            w->setSize(n);
        }
        forAll(active, k)
        {
            const label i = active[k];
            wA_[k] = alpha_[i]; wR1_[k] = rho1_[i]; wR2_[k] = rho2_[i];
            wR_[k] = rho_[i]; wE_[k] = rhoe_[i];
        }
        pc2(n, wA_, wR1_, wR2_, wR_, wE_, wP_, wC2_);
        forAll(active, k)
        {
            p_[active[k]] = wP_[k];
            c2_[active[k]] = wC2_[k];
        }
    }
    for (const label i : active)
    {
        if (!(p_[i] > 0) || !(c2_[i] > 0) || !std::isfinite(p_[i]))
        {
            if (bad < 0) bad = i;
            c_[i] = 0;
        }
        else
        {
            c_[i] = sqrt(c2_[i]);
        }
    }
    return bad < 0;
}


Foam::scalar Foam::ductNetwork::mixtureC2
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar p
) const
{
    if (!mixture_.twoPhase())
    {
        return mixture_.eos(0).c2(rho1, p);
    }
    one_[0] = alpha1; one1_[0] = rho1; one2_[0] = rho2;
    oneRho_[0] = alpha1*rho1 + (1 - alpha1)*rho2;
    oneP_[0] = p;
    mixture_.rhoeC2(1, one_, one1_, one2_, oneRho_, oneP_, oneE_, oneC2_);
    return oneC2_[0];
}


Foam::ductNetwork::boundaryState Foam::ductNetwork::inflowState
(
    const label f,
    const scalar pDuct
) const
{
    // The plenum's state, taken as the stagnation state, and its material-1
    // mass fraction, frozen along the expansion
    const bool two = mixture_.twoPhase();
    const scalar p0 = plenum_.p[f];
    const scalar a0 = two ? plenum_.alpha1[f] : 1;
    const scalar r10 = two ? plenum_.rho1[f] : plenum_.rho[f];
    const scalar r20 = two ? plenum_.rho2[f] : plenum_.rho[f];
    const scalar rho0 = a0*r10 + (1 - a0)*r20;
    const scalar Y1 = two ? a0*r10/rho0 : 1;

    boundaryState b{rho0, 0, p0, a0, r10, r20, Y1};
    if (!(pDuct < p0))
    {
        return b;
    }
    // Each material along its own isentrope in y = ln p, drho_k/dy =
    // p/c_k^2; the kinetic energy gained is the enthalpy lost, d(u^2/2)/dy
    // = -p/rho (1/rho = Y1/rho1 + Y2/rho2); stop where the flow turns
    // sonic (the mass flux rho u is largest there: choked)
    const equationOfState& eos1 = mixture_.eos(0);
    const equationOfState& eos2 = mixture_.eos(two ? 1 : 0);
    const scalar y0 = log(p0), y1 = log(pDuct);
    const label nSteps = max(label(8), label(16*(y0 - y1)));
    const scalar h = (y1 - y0)/nSteps;
    auto rhoMix = [&](const scalar r1, const scalar r2)
    {
        return two ? 1/(Y1/r1 + (1 - Y1)/r2) : r1;
    };
    auto rate = [&]
    (
        const scalar y, const scalar r1, const scalar r2,
        scalar& d1, scalar& d2, scalar& dk
    )
    {
        const scalar pp = exp(y);
        d1 = pp/eos1.c2(r1, pp);
        d2 = two ? pp/eos2.c2(r2, pp) : d1;
        dk = -pp/rhoMix(r1, r2);
    };
    scalar y = y0, r1 = r10, r2 = r20, k = 0;
    for (label s = 0; s < nSteps; ++s)
    {
        scalar a1, a2, ak, b1, b2, bk, c1, c2, ck, e1, e2, ek;
        rate(y, r1, r2, a1, a2, ak);
        rate(y + 0.5*h, r1 + 0.5*h*a1, r2 + 0.5*h*a2, b1, b2, bk);
        rate(y + 0.5*h, r1 + 0.5*h*b1, r2 + 0.5*h*b2, c1, c2, ck);
        rate(y + h, r1 + h*c1, r2 + h*c2, e1, e2, ek);
        const scalar r1End = r1 + h*(a1 + 2*b1 + 2*c1 + e1)/6;
        const scalar r2End = r2 + h*(a2 + 2*b2 + 2*c2 + e2)/6;
        const scalar kEnd = k + h*(ak + 2*bk + 2*ck + ek)/6;
        const scalar rEnd = rhoMix(r1End, r2End);
        const scalar aEnd = two ? Y1*rEnd/r1End : 1;
        if (2*kEnd >= mixtureC2(aEnd, r1End, r2End, exp(y + h)))
        {
            break;
        }
        y += h;
        r1 = r1End;
        r2 = r2End;
        k = kEnd;
    }
    b.rho = rhoMix(r1, r2);
    b.u = sqrt(max(2*k, scalar(0)));
    b.p = exp(y);
    b.alpha1 = two ? Y1*b.rho/r1 : 1;
    b.rho1 = r1;
    b.rho2 = r2;
    return b;
}


void Foam::ductNetwork::mouthFlux(const label f, const label k)
{
    const label P = geometry_.owner[f];
    const scalar A = magSf_[f];
    const vector n = geometry_.Sf[f]/A;
    scalar rhoB, pB, rhoEB, alphaB, Y1B;
    vector UB;
    if (plenum_.p[f] >= p_[P])
    {
        // Into the duct, from the plenum's state at rest
        const boundaryState b = inflowState(f, p_[P]);
        rhoB = b.rho;
        pB = b.p;
        UB = -b.u*n;
        alphaB = b.alpha1;
        Y1B = b.Y1;
        rhoEB =
            mixture_.rhoe(b.alpha1, b.rho1, b.rho2, b.p) + 0.5*b.rho*sqr(b.u);
    }
    else
    {
        // Out of the duct: its density and velocity (not back in), at the
        // plenum's pressure unless it leaves at sonic speed or above
        rhoB = rho_[P];
        const scalar un = max(U_[P] & n, scalar(0));
        UB = U_[P] + (un - (U_[P] & n))*n;
        pB = un >= c_[P] ? p_[P] : plenum_.p[f];
        rhoEB = rhoe_[P] + 0.5*rho_[P]*magSqr(UB);
        alphaB = alpha_[P];
        Y1B = alpha_[P]*rho1_[P]/rho_[P];
    }
    scalar uS = (UB & n)*A;
    // A plenum gives at most maxMass in a step (a small cut cell)
    scalar scale = 1;
    const scalar cap = plenum_.maxMass[f];
    if (cap > 0 && -rhoB*uS*dt_ > cap)
    {
        scale = cap/(-rhoB*uS*dt_);
    }
    uS *= scale;
    F_.rho[k] = rhoB*uS;
    F_.rhoU[k] = rhoB*uS*UB + scale*pB*A*n;
    F_.rhoE[k] = (rhoEB + pB)*uS;
    F_.uS[k] = uS;
    if (mixture_.twoPhase())
    {
        F_.rhoY1[k] = F_.rho[k]*Y1B;
        F_.alpha[k] = uS*alphaB;
    }
}


void Foam::ductNetwork::fluxes()
{
    const geometry& g = geometry_;
    const bool twoPhase = mixture_.twoPhase();
    blastFaceStates& s = faces_;
    auto side = [&]
    (
        const label i, scalarField& rho, vectorField& U, scalarField& p,
        scalarField& c, scalarField& E, scalarField* alpha, scalarField* Y1,
        const label f
    )
    {
        rho[f] = rho_[i];
        U[f] = U_[i];
        p[f] = p_[i];
        c[f] = c_[i];
        E[f] = rhoe_[i] + 0.5*rho_[i]*magSqr(U_[i]);
        if (alpha)
        {
            (*alpha)[f] = alpha_[i];
            (*Y1)[f] = alpha_[i]*rho1_[i]/rho_[i];
        }
    };
    // The interfaces this rank computes, packed (k-th: interface faces[k])
    const labelList& faces = part_.faces();
    const bool whole = part_.whole();
    forAll(faces, k)
    {
        const label f = faces[k];
        const label P = g.owner[f], N = g.neighbour[f];
        side
        (
            P, s.rhoL, s.UL, s.pL, s.cL, s.EL,
            twoPhase ? &s.alphaL : nullptr, &s.Y1L, k
        );
        // A mouth's second side is a copy: its flux is replaced below
        side
        (
            N >= 0 ? N : P, s.rhoR, s.UR, s.pR, s.cR, s.ER,
            twoPhase ? &s.alphaR : nullptr, &s.Y1R, k
        );
    }
    flux_->fluxes
    (
        0, faces.size(), whole ? g.Sf : SfA_, whole ? magSf_ : magSfA_, s,
        twoPhase, F_
    );
    forAll(faces, k)
    {
        if (g.neighbour[faces[k]] < 0)
        {
            mouthFlux(faces[k], k);
        }
    }
}


void Foam::ductNetwork::stage(const scalar a, const scalar b, const scalar dt)
{
    label bad = -1;
    if (!primitives(bad))
    {
        FatalErrorInFunction
            << "ductNetwork: control volume " << bad << " of " << size()
            << " has no physical state (volume " << V_[bad] << ", mass "
            << m_[bad] << ", pressure " << p_[bad] << ")"
            << exit(FatalError);
    }
    fluxes();

    const geometry& g = geometry_;
    const bool twoPhase = mixture_.twoPhase();
    Rm_ = 0; RmU_ = Zero; RmE_ = 0; RaV_ = 0; Rm1_ = 0;
    dilatation_ = dVdt_;
    // (a ghost's residual gets only part of its fluxes: never used)
    const labelList& faces = part_.faces();
    forAll(faces, k)
    {
        const label f = faces[k];
        const label P = g.owner[f], N = g.neighbour[f];
        inMass_[f] -= b*dt*F_.rho[k];
        inMomentum_[f] -= b*dt*F_.rhoU[k];
        inEnergy_[f] -= b*dt*F_.rhoE[k];
        if (twoPhase)
        {
            inMass1_[f] -= b*dt*F_.rhoY1[k];
            inAlpha_[f] -= b*dt*F_.alpha[k];
        }
        Rm_[P] -= F_.rho[k];
        RmU_[P] -= F_.rhoU[k];
        RmE_[P] -= F_.rhoE[k];
        if (N >= 0)
        {
            Rm_[N] += F_.rho[k];
            RmU_[N] += F_.rhoU[k];
            RmE_[N] += F_.rhoE[k];
        }
        if (twoPhase)
        {
            Rm1_[P] -= F_.rhoY1[k];
            RaV_[P] -= F_.alpha[k] - alpha_[P]*F_.uS[k];
            dilatation_[P] += F_.uS[k];
            if (N >= 0)
            {
                Rm1_[N] += F_.rhoY1[k];
                RaV_[N] += F_.alpha[k] - alpha_[N]*F_.uS[k];
                dilatation_[N] -= F_.uS[k];
            }
        }
    }

    for (const label i : part_.own())
    {
        // Walls: their pressure on the gas (W outward), the gas's work on
        // their motion
        RmU_[i] -= p_[i]*W_[i];
        const scalar wall =
            g.wallWork.size() ? g.wallWork[i] : dt*p_[i]*dVdt_[i];
        RmE_[i] -= wall/dt;
        wallWork_ += b*wall;
        wallWorkOf_[i] += b*wall;
        pMean_[i] += b*p_[i];
        const scalar k =
            frictionFactor_*mag(U_[i])*g.wallArea[i]/(2*V_[i]);

        m_[i] = a*m0_[i] + (1 - a)*(m_[i] + dt*Rm_[i]);
        mU_[i] = a*mU0_[i] + (1 - a)*(mU_[i] + dt*RmU_[i]);
        mE_[i] = a*mE0_[i] + (1 - a)*(mE_[i] + dt*RmE_[i]);
        if (twoPhase)
        {
            RaV_[i] += alpha_[i]*dVdt_[i];
            if (kapila_)
            {
                RaV_[i] +=
                    kapilaCoefficient(alpha_[i], rho1_[i], rho2_[i], p_[i])
                   *dilatation_[i];
            }
            aV_[i] = a*aV0_[i] + (1 - a)*(aV_[i] + dt*RaV_[i]);
            m1_[i] = a*m10_[i] + (1 - a)*(m1_[i] + dt*Rm1_[i]);
        }
        V_[i] = a*g.V0[i] + (1 - a)*(V_[i] + dt*dVdt_[i]);

        // Friction (implicit: it slows the flow, never reverses it) and
        // the duct's walls, which let it flow along the axis only
        mU_[i] /= 1 + (1 - a)*dt*k;
        const scalar ax2 = magSqr(g.axis[i]);
        if (ax2 > 0)
        {
            mU_[i] = ((mU_[i] & g.axis[i])/ax2)*g.axis[i];
        }
    }

    // Distributed: the ghosts' volumes (the same bits as their owners')
    // and contents from their owners
    if (!part_.whole())
    {
        for (const label i : part_.ghosts())
        {
            V_[i] = a*g.V0[i] + (1 - a)*(V_[i] + dt*dVdt_[i]);
        }
        part_.exchange({&m_, &mE_, &aV_, &m1_}, {&mU_});
    }
}


void Foam::ductNetwork::advance(const scalar dt)
{
    const geometry& g = geometry_;
    const label n = size();
    if
    (
        g.V0.size() != n || g.V1.size() != n || g.owner.size() != magSf_.size()
     || (g.wallWork.size() && g.wallWork.size() != n)
    )
    {
        FatalErrorInFunction
            << "ductNetwork: geometry sizes do not match setSize"
            << exit(FatalError);
    }
    W_ = Zero;
    forAll(g.owner, f)
    {
        magSf_[f] = mag(g.Sf[f]);
        W_[g.owner[f]] -= g.Sf[f];
        if (g.neighbour[f] >= 0)
        {
            W_[g.neighbour[f]] += g.Sf[f];
        }
    }
    // Distributed: the computed interfaces' areas packed for the flux
    // scheme (fluxes), once for the step's stages
    if (!part_.whole())
    {
        const labelList& faces = part_.faces();
        forAll(faces, k)
        {
            SfA_[k] = g.Sf[faces[k]];
            magSfA_[k] = magSf_[faces[k]];
        }
    }
    dt_ = dt;
    forAll(dVdt_, i)
    {
        dVdt_[i] = (g.V1[i] - g.V0[i])/dt;
    }
    V_ = g.V0;
    m0_ = m_; mU0_ = mU_; mE0_ = mE_; aV0_ = aV_; m10_ = m1_;
    wallWork_ = 0;
    inMass_ = 0; inMomentum_ = Zero; inEnergy_ = 0; inMass1_ = 0; inAlpha_ = 0;
    wallWorkOf_ = 0;
    pMean_ = 0;

    // SSP Runge-Kutta (Shu & Osher, blastTimeIntegrator): the old state's
    // weight per stage, and the weight of each stage's residual in the
    // step's result
    for (label s = 0; s < rk_.nStages(); ++s)
    {
        stage(rk_.a(s), rk_.resultWeight(s), dt);
    }
    primitivesAfterStep();
}


Foam::scalar Foam::ductNetwork::maxDeltaT(const scalar Co) const
{
    const geometry& g = geometry_;
    // (distributed: the interfaces with an own end, all an own volume
    // has; a ghost's sum is partial and not used)
    waveSum_ = 0;
    for (const label f : part_.faces())
    {
        const scalar A = mag(g.Sf[f]);
        if (A <= 0) continue;
        const vector n = g.Sf[f]/A;
        const label P = g.owner[f], N = g.neighbour[f];
        waveSum_[P] += (mag(U_[P] & n) + c_[P])*A;
        if (N >= 0)
        {
            waveSum_[N] += (mag(U_[N] & n) + c_[N])*A;
        }
    }
    scalar dt = GREAT;
    for (const label i : part_.own())
    {
        if (waveSum_[i] > 0)
        {
            dt = min(dt, Co*min(g.V0[i], g.V1[i])/waveSum_[i]);
        }
    }
    // Distributed: the smallest over the ranks, the serial one
    return part_.whole() ? dt : returnReduce(dt, minOp<scalar>());
}


Foam::scalar Foam::ductNetwork::kapilaCoefficient
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar p
) const
{
    const scalar a1 = min(max(alpha1, scalar(0)), scalar(1)), a2 = 1 - a1;
    // rho c^2 of each material at the common pressure
    const scalar z1 = rho1*mixture_.eos(0).c2(rho1, p);
    const scalar z2 = rho2*mixture_.eos(1).c2(rho2, p);
    const scalar d = a1*z2 + a2*z1;
    if (!(z1 > 0) || !(z2 > 0) || !(d > 0))
    {
        return 0;
    }
    return a1*a2*(z2 - z1)/d;
}


void Foam::ductNetwork::addEnergy(const scalarField& dE)
{
    mE_ += dE;
    label bad = -1;
    if (!primitives(bad))
    {
        FatalErrorInFunction
            << "ductNetwork: control volume " << bad << " has no physical"
            << " state after adding " << dE[bad] << " J to it"
            << exit(FatalError);
    }
}


Foam::ductNetwork::content Foam::ductNetwork::contentOf(const label i) const
{
    return {m_[i], mE_[i], aV_[i], m1_[i], mU_[i]};
}


void Foam::ductNetwork::setContent(const label i, const content& c)
{
    m_[i] = c.m;
    mE_[i] = c.mE;
    aV_[i] = c.aV;
    m1_[i] = c.m1;
    mU_[i] = c.mU;
}


void Foam::ductNetwork::correct(const scalarField& V)
{
    geometry_.V0 = V;
    V_ = V;
    label bad = -1;
    if (!primitives(bad))
    {
        FatalErrorInFunction
            << "ductNetwork: control volume " << bad << " of " << size()
            << " has no physical state (volume " << V_[bad] << ", mass "
            << m_[bad] << ")" << exit(FatalError);
    }
}


Foam::scalar Foam::ductNetwork::mouthSum(const scalarField& in) const
{
    scalar s = 0;
    forAll(in, f)
    {
        if (geometry_.neighbour[f] < 0) s += in[f];
    }
    return s;
}


Foam::scalar Foam::ductNetwork::mass() const
{
    return sum(m_);
}


Foam::scalar Foam::ductNetwork::energy() const
{
    return sum(mE_);
}


// ************************************************************************* //

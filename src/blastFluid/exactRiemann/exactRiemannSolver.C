/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "exactRiemannSolver.H"
#include "error.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::exactRiemannSolver::hugoniotDensity
(
    const equationOfState& eos,
    const state& K,
    const scalar p
) const
{
    const scalar eK = eos.e(K.rho, K.p);
    auto g = [&](const scalar rho)
    {
        return
            eos.e(rho, p) - eK - 0.5*(p + K.p)*(1/K.rho - 1/rho);
    };

    scalar lo = K.rho, hi = 2*K.rho;
    scalar glo = g(lo), ghi = g(hi);
    for (label i = 0; ghi > 0 && i < 200; ++i)
    {
        lo = hi; glo = ghi;
        hi *= 2;
        ghi = g(hi);
    }
    if (ghi > 0 || glo < 0)
    {
        FatalErrorInFunction
            << "Cannot bracket the Hugoniot density for p = " << p
            << " from rho = " << K.rho << ", p = " << K.p
            << exit(FatalError);
    }

    // Illinois method, with bisection safeguard
    int lastSide = 0;
    for (label it = 0; it < 300 && (hi - lo) > 1e-15*hi; ++it)
    {
        scalar x = (lo*ghi - hi*glo)/(ghi - glo);
        if (!(x > lo && x < hi)) x = 0.5*(lo + hi);
        const scalar gx = g(x);
        if (gx > 0)
        {
            lo = x; glo = gx;
            if (lastSide == -1) ghi *= 0.5;
            lastSide = -1;
        }
        else
        {
            hi = x; ghi = gx;
            if (lastSide == 1) glo *= 0.5;
            lastSide = 1;
        }
        if (gx == 0) { lo = hi = x; }
    }
    return 0.5*(lo + hi);
}


Foam::scalar Foam::exactRiemannSolver::isentrope
(
    const equationOfState& eos,
    const state& K,
    const scalar p,
    scalar& rhoEnd,
    DynamicList<scalar>* tabP,
    DynamicList<scalar>* tabRho,
    DynamicList<scalar>* tabU,
    const scalar sign
) const
{
    // In s = ln p:  drho/ds = p/c^2,  dI/ds = p/(rho c)
    auto drho = [&](const scalar s, const scalar rho)
    {
        const scalar pp = exp(s);
        return pp/eos.c2(rho, pp);
    };
    auto dI = [&](const scalar s, const scalar rho)
    {
        const scalar pp = exp(s);
        return pp/(rho*sqrt(eos.c2(rho, pp)));
    };

    const scalar s0 = log(K.p), s1 = log(p);
    const scalar h = (s1 - s0)/nSteps_;
    scalar rho = K.rho, I = 0;
    if (tabP)
    {
        tabP->clear(); tabRho->clear(); tabU->clear();
        tabP->append(K.p); tabRho->append(rho); tabU->append(K.u);
    }
    for (label i = 0; i < nSteps_; ++i)
    {
        const scalar s = s0 + i*h;
        const scalar k1 = drho(s, rho), q1 = dI(s, rho);
        const scalar k2 = drho(s + 0.5*h, rho + 0.5*h*k1);
        const scalar q2 = dI(s + 0.5*h, rho + 0.5*h*k1);
        const scalar k3 = drho(s + 0.5*h, rho + 0.5*h*k2);
        const scalar q3 = dI(s + 0.5*h, rho + 0.5*h*k2);
        const scalar k4 = drho(s + h, rho + h*k3);
        const scalar q4 = dI(s + h, rho + h*k3);
        rho += h/6*(k1 + 2*k2 + 2*k3 + k4);
        I += h/6*(q1 + 2*q2 + 2*q3 + q4);
        if (tabP)
        {
            tabP->append(exp(s + h));
            tabRho->append(rho);
            // u = u_L - I (left, sign 1), u_R + I (right, sign -1)
            tabU->append(K.u - sign*I);
        }
    }
    rhoEnd = rho;
    // Integral of dp/(rho c) from p to p_K (>= 0)
    return -I;
}


Foam::scalar Foam::exactRiemannSolver::waveCurve
(
    const equationOfState& eos,
    const state& K,
    const scalar p,
    scalar& rhoStar
) const
{
    if (p > K.p)
    {
        rhoStar = hugoniotDensity(eos, K, p);
        return sqrt((p - K.p)*(1/K.rho - 1/rhoStar));
    }
    else
    {
        return -isentrope
        (
            eos, K, p, rhoStar, nullptr, nullptr, nullptr, 0
        );
    }
}


Foam::exactRiemannSolver::state Foam::exactRiemannSolver::sampleFan
(
    const equationOfState& eos,
    const DynamicList<scalar>& tabP,
    const DynamicList<scalar>& tabRho,
    const DynamicList<scalar>& tabU,
    const scalar xi,
    const scalar sign,
    const label side
) const
{
    // Characteristic speed u + sign c along the table is monotonic
    auto lambda = [&](const label i)
    {
        return tabU[i] + sign*sqrt(eos.c2(tabRho[i], tabP[i]));
    };
    label lo = 0, hi = tabP.size() - 1;
    const scalar llo = lambda(lo);
    // Bisection on the monotonic sequence
    while (hi - lo > 1)
    {
        const label mid = (lo + hi)/2;
        const scalar lm = lambda(mid);
        if ((lm - xi)*(llo - xi) > 0) lo = mid; else hi = mid;
    }
    const scalar l0 = lambda(lo), l1 = lambda(hi);
    const scalar w = (l1 != l0) ? (xi - l0)/(l1 - l0) : 0;
    state s;
    s.rho = tabRho[lo] + w*(tabRho[hi] - tabRho[lo]);
    s.u = tabU[lo] + w*(tabU[hi] - tabU[lo]);
    s.p = tabP[lo] + w*(tabP[hi] - tabP[lo]);
    s.side = side;
    return s;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::exactRiemannSolver::exactRiemannSolver
(
    const equationOfState& eosL,
    const state& L,
    const equationOfState& eosR,
    const state& R,
    const label nSteps
)
:
    eosL_(eosL),
    eosR_(eosR),
    L_(L),
    R_(R),
    nSteps_(nSteps),
    pStar_(0), uStar_(0), rhoStarL_(0), rhoStarR_(0)
{
    L_.side = 0;
    R_.side = 1;
    if (!(L.rho > 0 && R.rho > 0 && L.p > 0 && R.p > 0))
    {
        FatalErrorInFunction
            << "Riemann states need positive density and pressure"
            << exit(FatalError);
    }

    auto F = [&](const scalar lnp)
    {
        scalar rL, rR;
        const scalar p = exp(lnp);
        return
            waveCurve(eosL_, L_, p, rL) + waveCurve(eosR_, R_, p, rR)
          + R_.u - L_.u;
    };

    scalar lo = log(1e-8*min(L.p, R.p));
    scalar hi = log(max(L.p, R.p));
    scalar Flo = F(lo), Fhi = F(hi);
    if (Flo > 0)
    {
        FatalErrorInFunction
            << "The Riemann problem generates vacuum" << exit(FatalError);
    }
    for (label i = 0; Fhi < 0 && i < 200; ++i)
    {
        lo = hi; Flo = Fhi;
        hi += log(4.0);
        Fhi = F(hi);
    }

    int lastSide = 0;
    for (label it = 0; it < 300 && (hi - lo) > 1e-14; ++it)
    {
        scalar x = (lo*Fhi - hi*Flo)/(Fhi - Flo);
        if (!(x > lo && x < hi)) x = 0.5*(lo + hi);
        const scalar Fx = F(x);
        if (Fx < 0)
        {
            lo = x; Flo = Fx;
            if (lastSide == -1) Fhi *= 0.5;
            lastSide = -1;
        }
        else
        {
            hi = x; Fhi = Fx;
            if (lastSide == 1) Flo *= 0.5;
            lastSide = 1;
        }
        if (Fx == 0) { lo = hi = x; }
    }
    pStar_ = exp(0.5*(lo + hi));

    const scalar fL = waveCurve(eosL_, L_, pStar_, rhoStarL_);
    const scalar fR = waveCurve(eosR_, R_, pStar_, rhoStarR_);
    uStar_ = 0.5*(L_.u + R_.u) + 0.5*(fR - fL);

    if (pStar_ <= L_.p)
    {
        isentrope(eosL_, L_, pStar_, rhoStarL_, &tabPL_, &tabRhoL_, &tabUL_, 1);
    }
    if (pStar_ <= R_.p)
    {
        isentrope(eosR_, R_, pStar_, rhoStarR_, &tabPR_, &tabRhoR_, &tabUR_, -1);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::exactRiemannSolver::leftFrontSpeed() const
{
    if (pStar_ > L_.p)
    {
        const scalar m =
            sqrt((pStar_ - L_.p)/(1/L_.rho - 1/rhoStarL_));
        return L_.u - m/L_.rho;
    }
    return L_.u - sqrt(eosL_.c2(L_.rho, L_.p));
}


Foam::scalar Foam::exactRiemannSolver::rightFrontSpeed() const
{
    if (pStar_ > R_.p)
    {
        const scalar m =
            sqrt((pStar_ - R_.p)/(1/R_.rho - 1/rhoStarR_));
        return R_.u + m/R_.rho;
    }
    return R_.u + sqrt(eosR_.c2(R_.rho, R_.p));
}


Foam::exactRiemannSolver::state Foam::exactRiemannSolver::sample
(
    const scalar xi
) const
{
    state s;
    if (xi < uStar_)
    {
        s = {rhoStarL_, uStar_, pStar_, 0};
        if (xi < leftFrontSpeed())
        {
            return L_;
        }
        if (pStar_ <= L_.p)
        {
            const scalar tail = uStar_ - sqrt(eosL_.c2(rhoStarL_, pStar_));
            if (xi < tail)
            {
                return sampleFan
                (
                    eosL_, tabPL_, tabRhoL_, tabUL_, xi, -1, 0
                );
            }
        }
        return s;
    }
    else
    {
        s = {rhoStarR_, uStar_, pStar_, 1};
        if (xi > rightFrontSpeed())
        {
            return R_;
        }
        if (pStar_ <= R_.p)
        {
            const scalar tail = uStar_ + sqrt(eosR_.c2(rhoStarR_, pStar_));
            if (xi > tail)
            {
                return sampleFan
                (
                    eosR_, tabPR_, tabRhoR_, tabUR_, xi, 1, 1
                );
            }
        }
        return s;
    }
}


// ************************************************************************* //

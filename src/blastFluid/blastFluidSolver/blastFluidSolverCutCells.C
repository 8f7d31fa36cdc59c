/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Embedded moving boundary (cut cells) in blastFluidSolver: an exactly
    conservative moving-boundary finite-volume step.

    Geometry of a step (given by the caller, e.g. the solid coupling): the
    fluid fraction phi0 of every cell at the start (the present one) and
    phi1 at the end, and the time-averaged open fraction a_f of every face.
    The wall of a cell is what closes its open faces:
        W_i = -sum_f a_f S_f           (outward from the gas, closure)
    and the volume the walls sweep is dV_i = (phi1_i - phi0_i) V_i. With
    time-averaged apertures a translation of the walls gives
    dV_i = W_i . u dt exactly (geometric conservation law).

    The gas content C_i = phi_i V_i U_i (U = rho, rho u, rho E, and with
    two materials alpha rho_1, alpha) advances by SSP Runge-Kutta stages
        C^(s+1) = a_s C^n + (1 - a_s)(C^(s) + dt R(U^(s)))
        R_i = -sum_f a_f F_f(U^(s)) + wall terms,
    wall terms (moving wall, no mass through it):
        momentum  -p_i W_i,  energy  -p_i dV_i/dt,  alpha  alpha_i dV_i/dt
    and U^(s+1) = C^(s+1)/(phi1 V). A uniform state moving with a
    translating wall stays exactly uniform. The wall impulse p W dt and
    work p dV of every cell are accumulated with the stage weights: they
    are exactly what the walls received (wallImpulse, wallWork).

    Small cells (phi1 < 1/2) would limit the time step; after every stage
    their content is merged with their open face neighbours by weighted
    state redistribution (Berger & Giuliani): neighbourhood N_i = i and the
    neighbours j across faces with a_f > 0 and phi1_j > 0; every cell j
    belongs to N_j = 1 + (number of small neighbours whose neighbourhood
    holds it) neighbourhoods and gives each 1/N_j of its volume and content;
    a neighbourhood's state is its content over its volume; a cell's final
    state is the mean of the states of the neighbourhoods it belongs to.
    Conservative to round-off, exact for uniform states, and a convex
    combination (positive density and internal energy if the neighbourhood
    content is). A cell that vanishes in the step (phi1 = 0) is a small
    cell without volume: its content goes to its neighbourhood. The same
    merging handles cells that open or close between steps
    (setFluidFraction). Every quantity across a processor face is computed
    from values exchanged through the coupled patches: a decomposed run
    gives the serial answer.

\*---------------------------------------------------------------------------*/

#include "blastFluidSolver.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastFluidSolver::contentFromState
(
    const scalarField& phi,
    scalarField& cRho, vectorField& cRhoU, scalarField& cRhoE,
    scalarField& cAlpha, scalarField& cAlphaRho1
) const
{
    cRho = rho_.primitiveField()*phi;
    cRhoU = rhoU_.primitiveField()*phi;
    cRhoE = rhoE_.primitiveField()*phi;
    if (twoPhase_)
    {
        cAlpha = alpha1Ptr_->primitiveField()*phi;
        cAlphaRho1 = alphaRho1Ptr_->primitiveField()*phi;
    }
}


void Foam::blastFluidSolver::stateFromContent
(
    const scalarField& phi,
    const scalarField& cRho, const vectorField& cRhoU,
    const scalarField& cRhoE, const scalarField& cAlpha,
    const scalarField& cAlphaRho1
)
{
    scalarField& rho = rho_.primitiveFieldRef();
    vectorField& rhoU = rhoU_.primitiveFieldRef();
    scalarField& rhoE = rhoE_.primitiveFieldRef();
    forAll(phi, i)
    {
        if (phi[i] <= 0) continue;
        const scalar r = 1/phi[i];
        rho[i] = r*cRho[i];
        rhoU[i] = r*cRhoU[i];
        rhoE[i] = r*cRhoE[i];
    }
    if (twoPhase_)
    {
        scalarField& alpha = alpha1Ptr_->primitiveFieldRef();
        scalarField& ar1 = alphaRho1Ptr_->primitiveFieldRef();
        forAll(phi, i)
        {
            if (phi[i] <= 0) continue;
            alpha[i] = min(max(cAlpha[i]/phi[i], scalar(0)), scalar(1));
            ar1[i] = cAlphaRho1[i]/phi[i];
        }
    }
    primitivesCurrent_ = false;
}


void Foam::blastFluidSolver::redistribute
(
    const volScalarField& phiField,
    scalarField& cRho, vectorField& cRhoU, scalarField& cRhoE,
    scalarField& cAlpha, scalarField& cAlphaRho1,
    const boolList* force,
    const bool forcedOnly
)
{
    if (!srd_.valid())
    {
        srd_.reset(new cutCellFields(mesh_));
    }
    cutCellFields& w = srd_();
    const scalarField& phi = phiField.primitiveField();
    const scalarField& V = mesh_.V();
    const label nCells = mesh_.nCells();

    // Small cells: less than half open or closing with gas in them, and
    // the cells in 'force' (new ones); with forcedOnly those only
    scalarField& small = w.small.primitiveFieldRef();
    forAll(small, i)
    {
        const bool forced = force && (*force)[i];
        const bool candidate = forced || (!forcedOnly && phi[i] < 0.5);
        small[i] =
            candidate && (phi[i] > 0 || cRho[i] != 0 || cRhoE[i] != 0)
          ? 1 : 0;
    }
    w.small.correctBoundaryConditions();
    scalarField smallNbr, phiNbr;
    coupledNeighbourValues(w.small, smallNbr);
    coupledNeighbourValues(phiField, phiNbr);

    // A face links small cell a to neighbour b if it is open and b has room
    auto links = [&](const label f, const scalar smallA, const scalar phiB)
    {
        return smallA > 0 && aperture_[f] > 0 && phiB > 0;
    };

    // Neighbourhoods each cell belongs to (its own included)
    scalarField& count = w.count.primitiveFieldRef();
    count = 1;
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        if (links(f, small[P], phi[N])) count[N] += 1;
        if (links(f, small[N], phi[P])) count[P] += 1;
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        const label b = cf - nInternal_, P = own_[cf];
        if (phiNbr.size() && links(cf, smallNbr[b], phi[P])) count[P] += 1;
    }
    if (!returnReduce(max(small) > 0, orOp<bool>()))
    {
        return;
    }

    // Every cell's share of volume and content per neighbourhood
    scalarField& vol = w.volume.primitiveFieldRef();
    scalarField& m = w.mass.primitiveFieldRef();
    vectorField& mu = w.momentum.primitiveFieldRef();
    scalarField& en = w.energy.primitiveFieldRef();
    scalarField& m1 = w.mass1.primitiveFieldRef();
    scalarField& v1 = w.volume1.primitiveFieldRef();
    for (label i = 0; i < nCells; ++i)
    {
        const scalar s = V[i]/count[i];
        vol[i] = phi[i]*s;
        m[i] = cRho[i]*s;
        mu[i] = cRhoU[i]*s;
        en[i] = cRhoE[i]*s;
        if (twoPhase_)
        {
            m1[i] = cAlphaRho1[i]*s;
            v1[i] = cAlpha[i]*s;
        }
    }
    for
    (
        volScalarField* fld : {&w.count, &w.volume, &w.mass, &w.energy}
    )
    {
        fld->correctBoundaryConditions();
    }
    w.momentum.correctBoundaryConditions();
    if (twoPhase_)
    {
        w.mass1.correctBoundaryConditions();
        w.volume1.correctBoundaryConditions();
    }

    // Neighbourhood sums of the small cells (volume, content); then the
    // neighbourhood states replace the shares
    scalarField volN(vol), mN(m), enN(en), m1N(m1), v1N(v1);
    vectorField muN(mu);
    {
        scalarField volB, mB, enB, m1B, v1B;
        vectorField muB;
        coupledNeighbourValues(w.volume, volB);
        coupledNeighbourValues(w.mass, mB);
        coupledNeighbourValues(w.momentum, muB);
        coupledNeighbourValues(w.energy, enB);
        if (twoPhase_)
        {
            coupledNeighbourValues(w.mass1, m1B);
            coupledNeighbourValues(w.volume1, v1B);
        }
        auto gather = [&](const label a, const label b)
        {
            volN[a] += vol[b]; mN[a] += m[b]; muN[a] += mu[b]; enN[a] += en[b];
            if (twoPhase_) { m1N[a] += m1[b]; v1N[a] += v1[b]; }
        };
        for (label f = 0; f < nInternal_; ++f)
        {
            const label P = own_[f], N = nei_[f];
            if (links(f, small[P], phi[N])) gather(P, N);
            if (links(f, small[N], phi[P])) gather(N, P);
        }
        for (label cf = nInternal_; cf < nFaces_; ++cf)
        {
            const label b = cf - nInternal_, P = own_[cf];
            if (phiNbr.size() && links(cf, small[P], phiNbr[b]))
            {
                volN[P] += volB[b]; mN[P] += mB[b]; muN[P] += muB[b];
                enN[P] += enB[b];
                if (twoPhase_) { m1N[P] += m1B[b]; v1N[P] += v1B[b]; }
            }
        }
    }

    // Neighbourhood states (per unit gas volume); a closing cell with no
    // open neighbour keeps its content (reported as lost)
    for (label i = 0; i < nCells; ++i)
    {
        if (volN[i] > 0)
        {
            const scalar r = 1/volN[i];
            m[i] = r*mN[i]; mu[i] = r*muN[i]; en[i] = r*enN[i];
            if (twoPhase_) { m1[i] = r*m1N[i]; v1[i] = r*v1N[i]; }
        }
        else if (small[i] > 0)
        {
            lostMass_ += cRho[i]*V[i];
            lostEnergy_ += cRhoE[i]*V[i];
            m[i] = 0; mu[i] = Zero; en[i] = 0; m1[i] = 0; v1[i] = 0;
        }
    }
    w.mass.correctBoundaryConditions();
    w.momentum.correctBoundaryConditions();
    w.energy.correctBoundaryConditions();
    if (twoPhase_)
    {
        w.mass1.correctBoundaryConditions();
        w.volume1.correctBoundaryConditions();
    }

    // A cell's state: the mean of the states of its neighbourhoods
    scalarField mB, enB, m1B, v1B;
    vectorField muB;
    coupledNeighbourValues(w.mass, mB);
    coupledNeighbourValues(w.momentum, muB);
    coupledNeighbourValues(w.energy, enB);
    if (twoPhase_)
    {
        coupledNeighbourValues(w.mass1, m1B);
        coupledNeighbourValues(w.volume1, v1B);
    }
    mN = m; muN = mu; enN = en; m1N = m1; v1N = v1;
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        if (links(f, small[P], phi[N]))
        {
            mN[N] += m[P]; muN[N] += mu[P]; enN[N] += en[P];
            if (twoPhase_) { m1N[N] += m1[P]; v1N[N] += v1[P]; }
        }
        if (links(f, small[N], phi[P]))
        {
            mN[P] += m[N]; muN[P] += mu[N]; enN[P] += en[N];
            if (twoPhase_) { m1N[P] += m1[N]; v1N[P] += v1[N]; }
        }
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        const label b = cf - nInternal_, P = own_[cf];
        if (phiNbr.size() && links(cf, smallNbr[b], phi[P]))
        {
            mN[P] += mB[b]; muN[P] += muB[b]; enN[P] += enB[b];
            if (twoPhase_) { m1N[P] += m1B[b]; v1N[P] += v1B[b]; }
        }
    }
    for (label i = 0; i < nCells; ++i)
    {
        const scalar s = phi[i]/count[i];
        cRho[i] = s*mN[i];
        cRhoU[i] = s*muN[i];
        cRhoE[i] = s*enN[i];
        if (twoPhase_)
        {
            cAlphaRho1[i] = s*m1N[i];
            cAlpha[i] = s*v1N[i];
        }
    }
}


void Foam::blastFluidSolver::fillEmptyCells()
{
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    rho_.correctBoundaryConditions();
    rhoU_.correctBoundaryConditions();
    rhoE_.correctBoundaryConditions();
    fluidFractionPtr_->correctBoundaryConditions();
    scalarField rhoB, rhoEB, phiB, alphaB, ar1B;
    vectorField rhoUB;
    coupledNeighbourValues(rho_, rhoB);
    coupledNeighbourValues(rhoU_, rhoUB);
    coupledNeighbourValues(rhoE_, rhoEB);
    coupledNeighbourValues(fluidFractionPtr_(), phiB);
    if (twoPhase_)
    {
        alpha1Ptr_->correctBoundaryConditions();
        alphaRho1Ptr_->correctBoundaryConditions();
        coupledNeighbourValues(alpha1Ptr_(), alphaB);
        coupledNeighbourValues(alphaRho1Ptr_(), ar1B);
    }

    // Mean of the open neighbours with gas, weighted by their fluid
    // fractions (the same weights across processor faces)
    const label nCells = mesh_.nCells();
    scalarField w(nCells, 0), r(nCells, 0), e(nCells, 0), a(nCells, 0);
    scalarField ar(nCells, 0);
    vectorField m(nCells, Zero);
    auto add = [&](const label i, const scalar wt, const scalar rr,
                   const vector& mm, const scalar ee, const scalar aa,
                   const scalar arr)
    {
        w[i] += wt; r[i] += wt*rr; m[i] += wt*mm; e[i] += wt*ee;
        a[i] += wt*aa; ar[i] += wt*arr;
    };
    const scalarField& alpha =
        twoPhase_ ? alpha1Ptr_->primitiveField() : rho_.primitiveField();
    const scalarField& ar1 =
        twoPhase_ ? alphaRho1Ptr_->primitiveField() : rho_.primitiveField();
    for (label f = 0; f < nInternal_; ++f)
    {
        if (aperture_[f] <= 0) continue;
        const label P = own_[f], N = nei_[f];
        if (phi[P] <= 0 && phi[N] > 0)
        {
            add(P, phi[N], rho_[N], rhoU_[N], rhoE_[N], alpha[N], ar1[N]);
        }
        if (phi[N] <= 0 && phi[P] > 0)
        {
            add(N, phi[P], rho_[P], rhoU_[P], rhoE_[P], alpha[P], ar1[P]);
        }
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        const label b = cf - nInternal_, P = own_[cf];
        if (aperture_[cf] > 0 && phi[P] <= 0 && phiB.size() && phiB[b] > 0)
        {
            add
            (
                P, phiB[b], rhoB[b], rhoUB[b], rhoEB[b],
                twoPhase_ ? alphaB[b] : 0, twoPhase_ ? ar1B[b] : 0
            );
        }
    }
    for (label i = 0; i < nCells; ++i)
    {
        if (phi[i] > 0 || w[i] <= 0) continue;
        const scalar s = 1/w[i];
        rho_[i] = s*r[i];
        rhoU_[i] = s*m[i];
        rhoE_[i] = s*e[i];
        if (twoPhase_)
        {
            alpha1Ptr_->primitiveFieldRef()[i] = s*a[i];
            alphaRho1Ptr_->primitiveFieldRef()[i] = s*ar[i];
        }
    }
    primitivesCurrent_ = false;
}


void Foam::blastFluidSolver::addWallTerms(const scalar a, const scalar dt)
{
    const scalar b = 1 - a;
    forAll(aperture_, f)
    {
        const scalar ap = aperture_[f];
        F_.rho[f] *= ap;
        F_.rhoU[f] *= ap;
        F_.rhoE[f] *= ap;
    }
    if (twoPhase_)
    {
        forAll(aperture_, f)
        {
            const scalar ap = aperture_[f];
            F_.rhoY1[f] *= ap;
            F_.alpha[f] *= ap;
            F_.uS[f] *= ap;
        }
    }
    assembleResidual();

    // Moving walls: no mass through them, the pressure pushes the gas and
    // does the work p dV; the impulse and work enter the Runge-Kutta
    // combination like the state, I <- (1 - a)(I + dt S)
    const scalarField& p = p_.primitiveField();
    const scalarField& V = mesh_.V();
    solidImpulse_ *= b;
    wallWork_ *= b;
    wallPressureImpulse_ *= b;
    forAll(V, i)
    {
        if (magSqr(wallVector_[i]) == 0 && sweptVolume_[i] == 0) continue;
        const vector force = p[i]*wallVector_[i];
        const scalar work = p[i]*sweptVolume_[i];
        dRhoU_[i] -= force/V[i];
        dRhoE_[i] -= work/(dt*V[i]);
        solidImpulse_[i] += b*dt*force;
        wallWork_[i] += b*work;
        wallPressureImpulse_[i] += b*dt*p[i];
    }
    if (twoPhase_)
    {
        const scalarField& alpha = alpha1Ptr_->primitiveField();
        forAll(V, i)
        {
            dAlpha_[i] += alpha[i]*sweptVolume_[i]/(dt*V[i]);
        }
    }
}


bool Foam::blastFluidSolver::cutCellStage
(
    const label s,
    const scalar a,
    const scalar dt
)
{
    if (!stageFluxes())
    {
        return false;
    }
    addWallTerms(a, dt);

    // Content of the stage's state: at the start of the step it refers to
    // phi0, later stages to phi1
    const scalarField& phiNow =
        s == 0 ? fluidFractionPtr_->primitiveField() : phiEndPtr_->primitiveField();
    const label n = mesh_.nCells();
    scalarField cRho(n), cRhoE(n), cAlpha, cAlphaRho1;
    vectorField cRhoU(n);
    contentFromState(phiNow, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);

    const scalar b = 1 - a;
    for (label i = 0; i < n; ++i)
    {
        cRho[i] = a*cRho0_[i] + b*(cRho[i] + dt*dRho_[i]);
        cRhoU[i] = a*cRhoU0_[i] + b*(cRhoU[i] + dt*dRhoU_[i]);
        cRhoE[i] = a*cRhoE0_[i] + b*(cRhoE[i] + dt*dRhoE_[i]);
    }
    if (twoPhase_)
    {
        for (label i = 0; i < n; ++i)
        {
            cAlpha[i] = a*cAlpha0_[i] + b*(cAlpha[i] + dt*dAlpha_[i]);
            cAlphaRho1[i] =
                a*cAlphaRho10_[i] + b*(cAlphaRho1[i] + dt*dAlphaRho1_[i]);
        }
    }

    redistribute
    (
        phiEndPtr_(), cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1, &newCell_
    );
    stateFromContent
    (
        phiEndPtr_->primitiveField(), cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1
    );
    return true;
}


void Foam::blastFluidSolver::advanceCutCells(const scalar dt)
{
    static const scalar a1[] = {0};
    static const scalar a2[] = {0, 0.5};
    static const scalar a3[] = {0, 0.75, 1.0/3.0};
    const scalar* a = (RKorder_ == 1 ? a1 : RKorder_ == 2 ? a2 : a3);

    fillEmptyCells();
    if (!primitivesCurrent_)
    {
        primitivesFromConservative(true);
    }
    const scalarField& phi0 = fluidFractionPtr_->primitiveField();
    contentFromState(phi0, cRho0_, cRhoU0_, cRhoE0_, cAlpha0_, cAlphaRho10_);
    rho0_ = rho_.primitiveField();
    rhoU0_ = rhoU_.primitiveField();
    rhoE0_ = rhoE_.primitiveField();
    if (twoPhase_)
    {
        alpha0_ = alpha1Ptr_->primitiveField();
        alphaRho10_ = alphaRho1Ptr_->primitiveField();
    }
    const scalar lostMass0 = lostMass_, lostEnergy0 = lostEnergy_;

    lowOrder_.primitiveFieldRef() = 0;
    anyLowOrder_ = false;
    const label maxAttempts = 4;
    for (label attempt = 0; attempt < maxAttempts; ++attempt)
    {
        solidImpulse_ = Zero;
        wallWork_ = 0;
        wallPressureImpulse_ = 0;
        bool ok = true;
        for (label s = 0; s < RKorder_ && ok; ++s)
        {
            ok = cutCellStage(s, a[s], dt);
        }
        if (ok && primitivesFromConservative(false))
        {
            if (attempt > 0)
            {
                Info<< "blastFluidSolver: step to " << mesh_.time().timeName()
                    << " needed first-order reconstruction in "
                    << returnReduce
                       (
                           label(sum(lowOrder_.primitiveField())),
                           sumOp<label>()
                       )
                    << " cells" << endl;
            }
            // The state now refers to the fluid fraction at the step's end
            fluidFractionPtr_->primitiveFieldRef() =
                phiEndPtr_->primitiveField();
            fluidFractionPtr_->correctBoundaryConditions();
            return;
        }
        if (attempt == maxAttempts - 1)
        {
            break;
        }

        // Redo the step from its start at first order around bad cells
        lostMass_ = lostMass0;
        lostEnergy_ = lostEnergy0;
        prepareRetry(attempt, maxAttempts);
    }
    primitivesFromConservative(true);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blastFluidSolver::enableCutCells(const scalarField& phi)
{
    cutCells_ = true;
    if (!readFluidFraction())
    {
        fluidFractionPtr_->primitiveFieldRef() = phi;
    }
    fluidFractionPtr_->correctBoundaryConditions();
    phiEndPtr_.reset
    (
        new volScalarField
        (
            IOobject("fluidFractionEnd", mesh_.time().timeName(), mesh_),
            fluidFractionPtr_()
        )
    );
    aperture_.setSize(nFaces_, 1);
    coupledFace_.setSize(nFaces_ - nInternal_, false);
    forAll(patchKind_, patchi)
    {
        if (patchKind_[patchi] != COUPLED) continue;
        for (label j = 0; j < mesh_.boundary()[patchi].size(); ++j)
        {
            coupledFace_[patchStart_[patchi] - nInternal_ + j] = true;
        }
    }
    wallVector_.setSize(mesh_.nCells(), Zero);
    sweptVolume_.setSize(mesh_.nCells(), 0);
    wallWork_.setSize(mesh_.nCells(), 0);
    wallPressureImpulse_.setSize(mesh_.nCells(), 0);
    solidImpulse_.setSize(mesh_.nCells(), Zero);
    lostMass_ = 0;
    lostEnergy_ = 0;
    primitivesCurrent_ = false;
}


void Foam::blastFluidSolver::setFluidFraction(const scalarField& phiNew)
{
    volScalarField& phiField = fluidFractionPtr_();
    scalarField& phi = phiField.primitiveFieldRef();
    const label n = mesh_.nCells();
    scalarField cRho(n), cRhoE(n), cAlpha, cAlphaRho1;
    vectorField cRhoU(n);
    contentFromState(phi, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);

    // Cells that open or close exchange their content with their open
    // neighbours; the others keep theirs in the new volume
    boolList changed(n, false);
    bool any = false;
    forAll(phi, i)
    {
        changed[i] = (phi[i] > 0) != (phiNew[i] > 0);
        any = any || changed[i];
    }
    phi = phiNew;
    phiField.correctBoundaryConditions();
    if (returnReduce(any, orOp<bool>()))
    {
        // The faces of the last step decide which neighbours are open
        redistribute
        (
            phiField, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1, &changed, true
        );
        // A cell that opened where no gas can reach it yet stays closed:
        // nothing is created; it opens in a step (a new cell)
        forAll(phi, i)
        {
            if (changed[i] && phi[i] > 0 && !(cRho[i] > 0)) phi[i] = 0;
        }
        phiField.correctBoundaryConditions();
    }
    stateFromContent(phi, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);
}


void Foam::blastFluidSolver::setEmbeddedBoundary
(
    const scalarField& phiEnd,
    const surfaceScalarField& aperture
)
{
    const scalarField& phi0 = fluidFractionPtr_->primitiveField();
    volScalarField& phi1Field = phiEndPtr_();
    phi1Field.primitiveFieldRef() = phiEnd;
    phi1Field.correctBoundaryConditions();
    const scalarField& phi1 = phi1Field.primitiveField();
    scalarField phi0Nbr, phi1Nbr;
    coupledNeighbourValues(fluidFractionPtr_(), phi0Nbr);
    coupledNeighbourValues(phi1Field, phi1Nbr);

    // Compact faces; a face next to a cell without gas at both ends of the
    // step is closed (no gas can pass into the solid)
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        const bool shut =
            (phi0[P] <= 0 && phi1[P] <= 0) || (phi0[N] <= 0 && phi1[N] <= 0);
        aperture_[f] = shut ? 0 : aperture[f];
    }
    forAll(patchKind_, patchi)
    {
        if (patchKind_[patchi] == SKIP) continue;
        const scalarField& ap = aperture.boundaryField()[patchi];
        const label start = patchStart_[patchi];
        forAll(ap, j)
        {
            const label cf = start + j, P = own_[cf], b = cf - nInternal_;
            bool shut = phi0[P] <= 0 && phi1[P] <= 0;
            if (patchKind_[patchi] == COUPLED)
            {
                shut = shut || (phi0Nbr[b] <= 0 && phi1Nbr[b] <= 0);
            }
            aperture_[cf] = shut ? 0 : ap[j];
        }
    }

    // A cell that opens in the step where no gas can reach it (no open
    // face to a cell holding gas: a void inside the solid, a joint opening
    // by elastic strain) stays closed: nothing is created; it opens once
    // gas is next to it
    boolList& reached = reached_;
    reached.setSize(phi0.size());
    reached = false;
    for (label f = 0; f < nInternal_; ++f)
    {
        if (aperture_[f] <= 0) continue;
        const label P = own_[f], N = nei_[f];
        if (phi0[N] > 0) reached[P] = true;
        if (phi0[P] > 0) reached[N] = true;
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        const label b = cf - nInternal_;
        if (aperture_[cf] > 0 && coupledFace_[b] && phi0Nbr[b] > 0)
        {
            reached[own_[cf]] = true;
        }
    }
    scalarField& phi1Ref = phi1Field.primitiveFieldRef();
    bool closed = false;
    forAll(phi1Ref, i)
    {
        if (phi0[i] <= 0 && phi1Ref[i] > 0 && !reached[i])
        {
            phi1Ref[i] = 0;
            closed = true;
        }
    }
    if (returnReduce(closed, orOp<bool>()))
    {
        phi1Field.correctBoundaryConditions();
        coupledNeighbourValues(phi1Field, phi1Nbr);
        for (label f = 0; f < nInternal_; ++f)
        {
            const label P = own_[f], N = nei_[f];
            if
            (
                (phi0[P] <= 0 && phi1[P] <= 0)
             || (phi0[N] <= 0 && phi1[N] <= 0)
            )
            {
                aperture_[f] = 0;
            }
        }
        for (label cf = nInternal_; cf < nFaces_; ++cf)
        {
            const label P = own_[cf], b = cf - nInternal_;
            if
            (
                (phi0[P] <= 0 && phi1[P] <= 0)
             || (coupledFace_[b] && phi0Nbr[b] <= 0 && phi1Nbr[b] <= 0)
            )
            {
                aperture_[cf] = 0;
            }
        }
    }

    // Closure: the wall of a cell closes its open faces
    wallVector_ = Zero;
    for (label f = 0; f < nInternal_; ++f)
    {
        wallVector_[own_[f]] -= aperture_[f]*Sf_[f];
        wallVector_[nei_[f]] += aperture_[f]*Sf_[f];
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        wallVector_[own_[cf]] -= aperture_[cf]*Sf_[cf];
    }
    const scalarField& V = mesh_.V();
    newCell_.setSize(V.size());
    forAll(V, i)
    {
        newCell_[i] = phi0[i] <= 0 && phi1[i] > 0;
        // The front and back planes of a 2D mesh close each other
        if (mesh_.nSolutionD() == 2) wallVector_[i].z() = 0;
        sweptVolume_[i] = (phi1[i] - phi0[i])*V[i];
        if (phi0[i] <= 0 && phi1[i] <= 0) wallVector_[i] = Zero;
    }
}


void Foam::blastFluidSolver::addEnergy(const scalarField& dE)
{
    // Into the content, then merged like the step's content: a small cell
    // cannot take the work of its whole wall alone (the solid's motion
    // within the step, e.g. elastic vibration, makes it differ from p dV)
    volScalarField& phiField = fluidFractionPtr_();
    const scalarField& phi = phiField.primitiveField();
    const scalarField& V = mesh_.V();
    const label n = mesh_.nCells();
    scalarField cRho(n), cRhoE(n), cAlpha, cAlphaRho1;
    vectorField cRhoU(n);
    contentFromState(phi, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);
    forAll(phi, i)
    {
        // A cell without gas at the end: its neighbourhood takes it
        cRhoE[i] += dE[i]/V[i];
    }
    redistribute(phiField, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);
    stateFromContent(phi, cRho, cRhoU, cRhoE, cAlpha, cAlphaRho1);
}


// ************************************************************************* //

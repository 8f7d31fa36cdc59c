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
        C^(s+1) = a_s C^n + b_s (C^(s) + dt R(U^(s)))
        R_i = -sum_f a_f F_f(U^(s)) + wall terms,
    wall terms (moving wall, no mass through it):
        momentum  -p_i W_i,  energy  -p_i dV_i/dt,  alpha  alpha_i dV_i/dt
    and U^(s+1) = C^(s+1)/(phi1 V). A uniform state moving with a
    translating wall stays exactly uniform. The wall impulse p W dt and
    work p dV of every cell are accumulated with the stage weights: they
    are exactly what the walls received (wallImpulse, wallWork).

    Small cells (phi1 < 1/2) would limit the time step; after every stage
    their content is merged with their open face neighbours by weighted
    state redistribution (Berger & Giuliani; smallCellRedistribution, where
    the neighbourhoods, the deficient and closed passes and the orphans are
    described). The same merging handles cells that open or close between
    steps (setFluidFraction), the wall work's correction (addEnergy) and
    gas handed to small cells (addContent). Every quantity across a
    processor face is computed from values exchanged through the coupled
    patches: a decomposed run gives the serial answer.

    Crushed pockets (ventCrushedPockets, when the step's geometry is set):
    a cell open to none of its faces over the step, less than half gas,
    whose gas volume the solid reduces, is a crack narrower than the cell.
    Its content goes to the nearest cells at least half gas, ring after
    ring of face neighbours (up to six) until they hold 20 times the
    pocket's mass, in proportion to their masses (each receiver's density
    grows by at most 5 %: the pocket's gas loses its volume, and the work
    its compression into the receivers would take is not there), and
    it is closed for the step (fraction 0 at both ends, no wall terms), so
    that no gas is squeezed without a wall that pushes back. A pocket whose
    rings reach a cell next to a processor face is kept (the rings are not
    searched across ranks). A face counts as open as the fluxes will have
    it: an aperture and gas on its other side at the start or the end of
    the step.

    Negative internal energy (mixNegativeEnergy, after an accepted step
    that needed first order): a cell left without positive internal
    energy, which the state check accepts at first order because a
    compressed JWL cell's cold terms keep p > 0, is mixed with its gas
    neighbours (up to three rings, until the group's internal energy is
    positive; each takes the group's average state). Kept, such cells
    travelled with the fragments as a region of e down to -3e5 J/kg and
    stopped the full-resolution cylinder.

\*---------------------------------------------------------------------------*/

#include "blastFluidSolver.H"
#include "processorPolyPatch.H"
#include "caseChecks.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastFluidSolver::scaleFluxes(const scalarField& phif)
{
    for (label f = 0; f < addr_.nFaces(); ++f)
    {
        F_.rho[f] *= phif[f];
        F_.rhoU[f] *= phif[f];
        F_.rhoE[f] *= phif[f];
    }
    if (state_.multiPhase())
    {
        for (label f = 0; f < addr_.nFaces(); ++f)
        {
            F_.rhoY1[f] *= phif[f];
            F_.alpha[f] *= phif[f];
            F_.uS[f] *= phif[f];
        }
    }
    if (state_.threePhase())
    {
        for (label f = 0; f < addr_.nFaces(); ++f)
        {
            F_.rhoY2[f] *= phif[f];
            F_.alpha2[f] *= phif[f];
        }
    }
}


bool Foam::blastFluidSolver::readFluidFraction()
{
    IOobject io
    (
        "fluidFraction",
        mesh_.time().timeName(),
        mesh_,
        IOobject::READ_IF_PRESENT,
        IOobject::AUTO_WRITE
    );
    if (!io.typeHeaderOk<volScalarField>(true))
    {
        fluidFractionPtr_.reset
        (
            new volScalarField
            (
                io,
                mesh_,
                dimensionedScalar("one", dimless, 1),
                calculatedFvPatchScalarField::typeName
            )
        );
        return false;
    }
    caseChecks::checkFieldFile(io);
    fluidFractionPtr_.reset(new volScalarField(io, mesh_));
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    forAll(phi, i)
    {
        if (!(phi[i] >= 0 && phi[i] <= 1))
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                fluidFractionPtr_->objectPath(), 0, 0
            )
                << "entry 'internalField': fluid fraction " << phi[i]
                << " in cell " << i << " is outside [0, 1]"
                << exit(FatalIOError);
        }
    }
    return true;
}


void Foam::blastFluidSolver::contentFromState
(
    const scalarField& phi,
    conservedFields& c
) const
{
    scalarField& cRho = c.rho;
    vectorField& cRhoU = c.rhoU;
    scalarField& cRhoE = c.rhoE;
    scalarField& cAlpha = c.alpha;
    scalarField& cAlphaRho1 = c.alphaRho1;
    // Element by element into lists sized once (no temporaries per stage)
    const label n = phi.size();
    cRho.setSize(n);
    cRhoU.setSize(n);
    cRhoE.setSize(n);
    const scalarField& rho = state_.rho().primitiveField();
    const vectorField& rhoU = state_.rhoU().primitiveField();
    const scalarField& rhoE = state_.rhoE().primitiveField();
    for (label i = 0; i < n; ++i)
    {
        cRho[i] = rho[i]*phi[i];
        cRhoU[i] = rhoU[i]*phi[i];
        cRhoE[i] = rhoE[i]*phi[i];
    }
    if (state_.multiPhase())
    {
        cAlpha.setSize(n);
        cAlphaRho1.setSize(n);
        const scalarField& alpha = state_.alpha1Ptr()->primitiveField();
        const scalarField& ar1 = state_.alphaRho1Ptr()->primitiveField();
        for (label i = 0; i < n; ++i)
        {
            cAlpha[i] = alpha[i]*phi[i];
            cAlphaRho1[i] = ar1[i]*phi[i];
        }
    }
    if (state_.threePhase())
    {
        c.alpha2.setSize(n);
        c.alphaRho2.setSize(n);
        const scalarField& alpha2 = state_.alpha2Ptr()->primitiveField();
        const scalarField& ar2 = state_.alphaRho2Ptr()->primitiveField();
        for (label i = 0; i < n; ++i)
        {
            c.alpha2[i] = alpha2[i]*phi[i];
            c.alphaRho2[i] = ar2[i]*phi[i];
        }
    }
}


void Foam::blastFluidSolver::stateFromContent
(
    const scalarField& phi,
    const conservedFields& c,
    DynamicList<label>* changed,
    const labelUList* cells
)
{
    const scalarField& cRho = c.rho;
    const vectorField& cRhoU = c.rhoU;
    const scalarField& cRhoE = c.rhoE;
    const scalarField& cAlpha = c.alpha;
    const scalarField& cAlphaRho1 = c.alphaRho1;
    blastFluidState& st = state_;
    scalarField* alpha2 =
        st.threePhase() ? &st.alpha2Ptr()->primitiveFieldRef() : nullptr;
    scalarField* ar2 =
        st.threePhase() ? &st.alphaRho2Ptr()->primitiveFieldRef() : nullptr;
    scalarField& rho = st.rho().primitiveFieldRef();
    vectorField& rhoU = st.rhoU().primitiveFieldRef();
    scalarField& rhoE = st.rhoE().primitiveFieldRef();
    scalarField* alpha =
        st.multiPhase() ? &st.alpha1Ptr()->primitiveFieldRef() : nullptr;
    scalarField* ar1 =
        st.multiPhase() ? &st.alphaRho1Ptr()->primitiveFieldRef() : nullptr;
    if (changed) changed->clear();
    const auto setCell = [&](const label i)
    {
        if (phi[i] <= 0) return;
        const scalar r = 1/phi[i];
        const scalar newRho = r*cRho[i];
        const vector newRhoU = r*cRhoU[i];
        const scalar newRhoE = r*cRhoE[i];
        bool differs =
            newRho != rho[i] || newRhoU != rhoU[i] || newRhoE != rhoE[i];
        rho[i] = newRho;
        rhoU[i] = newRhoU;
        rhoE[i] = newRhoE;
        if (alpha)
        {
            const scalar a =
                min(max(cAlpha[i]/phi[i], scalar(0)), scalar(1));
            const scalar m1 = cAlphaRho1[i]/phi[i];
            differs = differs || a != (*alpha)[i] || m1 != (*ar1)[i];
            (*alpha)[i] = a;
            (*ar1)[i] = m1;
        }
        if (alpha2)
        {
            const scalar a2 =
                min(max(c.alpha2[i]/phi[i], scalar(0)), scalar(1));
            const scalar m2 = c.alphaRho2[i]/phi[i];
            differs = differs || a2 != (*alpha2)[i] || m2 != (*ar2)[i];
            (*alpha2)[i] = a2;
            (*ar2)[i] = m2;
        }
        // (a NaN differs from itself: it is listed, and stops the run)
        if (changed && differs) changed->append(i);
    };
    if (cells)
    {
        for (const label i : *cells) setCell(i);
    }
    else
    {
        forAll(phi, i) setCell(i);
    }
    state_.invalidate();
}


Foam::smallCellRedistribution& Foam::blastFluidSolver::srd()
{
    if (!srd_.valid())
    {
        srd_.reset
        (
            new smallCellRedistribution
            (
                mesh_, addr_,
                state_.threePhase() ? 9 : state_.multiPhase() ? 7 : 5
            )
        );
    }
    return srd_();
}


void Foam::blastFluidSolver::fillEmptyCells()
{
    const scalarField& aperture = geometry_->aperture();
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    state_.rho().correctBoundaryConditions();
    state_.rhoU().correctBoundaryConditions();
    state_.rhoE().correctBoundaryConditions();
    fluidFractionPtr_->correctBoundaryConditions();
    emptyFillWork& k = emptyFill_;
    addr_.coupledNeighbourValues(state_.rho(), k.rhoB);
    addr_.coupledNeighbourValues(state_.rhoU(), k.rhoUB);
    addr_.coupledNeighbourValues(state_.rhoE(), k.rhoEB);
    addr_.coupledNeighbourValues(fluidFractionPtr_(), k.phiB);
    if (state_.multiPhase())
    {
        state_.alpha1Ptr()->correctBoundaryConditions();
        state_.alphaRho1Ptr()->correctBoundaryConditions();
        addr_.coupledNeighbourValues(state_.alpha1Ptr()(), k.alphaB);
        addr_.coupledNeighbourValues(state_.alphaRho1Ptr()(), k.ar1B);
    }

    // Mean of the open neighbours with gas, weighted by their fluid
    // fractions (the same weights across processor faces)
    const label nCells = mesh_.nCells();
    k.reset(nCells);
    scalarField& w = k.w;
    scalarField& r = k.r;
    scalarField& e = k.e;
    scalarField& a = k.a;
    scalarField& ar = k.ar;
    vectorField& m = k.m;
    auto add = [&](const label i, const scalar wt, const scalar rr,
                   const vector& mm, const scalar ee, const scalar aa,
                   const scalar arr)
    {
        w[i] += wt; r[i] += wt*rr; m[i] += wt*mm; e[i] += wt*ee;
        a[i] += wt*aa; ar[i] += wt*arr;
    };
    const bool mp = state_.multiPhase();
    const scalarField& rho = state_.rho().primitiveField();
    const vectorField& rhoU = state_.rhoU().primitiveField();
    const scalarField& rhoE = state_.rhoE().primitiveField();
    const scalarField& alpha =
        mp ? state_.alpha1Ptr()->primitiveField() : rho;
    const scalarField& ar1 =
        mp ? state_.alphaRho1Ptr()->primitiveField() : rho;
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        if (aperture[f] <= 0) continue;
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (phi[P] <= 0 && phi[N] > 0)
        {
            add(P, phi[N], rho[N], rhoU[N], rhoE[N], alpha[N], ar1[N]);
        }
        if (phi[N] <= 0 && phi[P] > 0)
        {
            add(N, phi[P], rho[P], rhoU[P], rhoE[P], alpha[P], ar1[P]);
        }
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal(), P = addr_.own()[cf];
        if
        (
            aperture[cf] > 0 && phi[P] <= 0 && k.phiB.size() && k.phiB[b] > 0
        )
        {
            add
            (
                P, k.phiB[b], k.rhoB[b], k.rhoUB[b], k.rhoEB[b],
                mp ? k.alphaB[b] : 0, mp ? k.ar1B[b] : 0
            );
        }
    }
    scalarField& alphaRef =
        state_.multiPhase() ? state_.alpha1Ptr()->primitiveFieldRef() : w;
    scalarField& ar1Ref =
        state_.multiPhase() ? state_.alphaRho1Ptr()->primitiveFieldRef() : w;
    for (label i = 0; i < nCells; ++i)
    {
        if (phi[i] > 0 || w[i] <= 0) continue;
        const scalar s = 1/w[i];
        state_.rho()[i] = s*r[i];
        state_.rhoU()[i] = s*m[i];
        state_.rhoE()[i] = s*e[i];
        if (state_.multiPhase())
        {
            alphaRef[i] = s*a[i];
            ar1Ref[i] = s*ar[i];
        }
    }
    if (state_.threePhase())
    {
        fillEmptyCellsField(state_.alpha2Ptr()());
        fillEmptyCellsField(state_.alphaRho2Ptr()());
    }
    state_.invalidate();
}


void Foam::blastFluidSolver::fillEmptyCellsField(volScalarField& fld)
{
    const scalarField& aperture = geometry_->aperture();
    // fillEmptyCells for one more field: the mean of the open neighbours
    // with gas weighted by their fluid fractions
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    fld.correctBoundaryConditions();
    emptyFillWork& k = emptyFill_;
    scalarField& nbr = k.rhoB;
    scalarField& phiB = k.phiB;
    addr_.coupledNeighbourValues(fld, nbr);
    addr_.coupledNeighbourValues(fluidFractionPtr_(), phiB);
    scalarField& v = fld.primitiveFieldRef();
    const label nCells = mesh_.nCells();
    k.reset(nCells);
    scalarField& w = k.w;
    scalarField& sum = k.r;
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        if (aperture[f] <= 0) continue;
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (phi[P] <= 0 && phi[N] > 0)
        {
            w[P] += phi[N]; sum[P] += phi[N]*v[N];
        }
        if (phi[N] <= 0 && phi[P] > 0)
        {
            w[N] += phi[P]; sum[N] += phi[P]*v[P];
        }
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal(), P = addr_.own()[cf];
        if (aperture[cf] > 0 && phi[P] <= 0 && phiB.size() && phiB[b] > 0)
        {
            w[P] += phiB[b]; sum[P] += phiB[b]*nbr[b];
        }
    }
    for (label i = 0; i < nCells; ++i)
    {
        if (phi[i] > 0 || w[i] <= 0) continue;
        v[i] = sum[i]/w[i];
    }
}


void Foam::blastFluidSolver::addWallTerms(const label s, const scalar dt)
{
    const scalar a = rk_->a(s), b = rk_->b(s);
    scaleFluxes(geometry_->aperture());
    assembleResidual();
    addOutflow(s, dt);

    // Moving walls: no mass through them, the pressure pushes the gas and
    // does the work p dV; the impulse and work enter the Runge-Kutta
    // combination like the state, I <- b_s (I + dt S) (rk_'s weights).
    // A wall that recedes faster than the gas can follow (a cell opening
    // in the step, a crack widening) cannot take more work than the gas
    // there has: the wall pressure is limited so that the stage leaves the
    // cell at least half of the internal energy it would have without the
    // wall (theta p, theta in [0, 1]); the impulse and the work the wall
    // receives are theta times as large, so the reaction stays exact
    const scalarField& p = state_.p().primitiveField();
    const scalarField& V = mesh_.V();
    const vectorField& wallVector = geometry_->wallVector();
    const scalarField& sweptVolume = geometry_->sweptVolume();
    wallImpulse_ *= b;
    wallWork_ *= b;
    wallPressureImpulse_ *= b;
    forAll(V, i)
    {
        if (magSqr(wallVector[i]) == 0 && sweptVolume[i] == 0) continue;
        scalar theta = 1;
        const scalar work = p[i]*sweptVolume[i];
        if (work > 0)
        {
            // Stage content without the wall's work, per cell volume (the
            // momentum with the wall's force: the face pressures alone
            // are not in balance)
            const scalar m = a*cutStart_.rho[i] + b*(cut_.rho[i] + dt*residual_.rho[i]);
            const vector mU =
                a*cutStart_.rhoU[i]
              + b*(cut_.rhoU[i] + dt*(residual_.rhoU[i] - p[i]*wallVector[i]/V[i]));
            const scalar E = a*cutStart_.rhoE[i] + b*(cut_.rhoE[i] + dt*residual_.rhoE[i]);
            const scalar ein = m > 0 ? E - 0.5*magSqr(mU)/m : 0;
            const scalar cost = b*work/V[i];
            theta = min(scalar(1), max(0.5*ein, scalar(0))/cost);
        }
        const scalar pw = theta*p[i];
        const vector force = pw*wallVector[i];
        residual_.rhoU[i] -= force/V[i];
        residual_.rhoE[i] -= theta*work/(dt*V[i]);
        wallImpulse_[i] += b*dt*force;
        wallWork_[i] += b*theta*work;
        wallPressureImpulse_[i] += b*dt*pw;
    }
    if (state_.multiPhase())
    {
        const scalarField& alpha = state_.alpha1Ptr()->primitiveField();
        forAll(V, i)
        {
            residual_.alpha[i] += alpha[i]*sweptVolume[i]/(dt*V[i]);
        }
    }
    if (state_.threePhase())
    {
        const scalarField& alpha2 = state_.alpha2Ptr()->primitiveField();
        forAll(V, i)
        {
            residual_.alpha2[i] += alpha2[i]*sweptVolume[i]/(dt*V[i]);
        }
    }
}


void Foam::blastFluidSolver::mergeBadCells
(
    const volScalarField& phiField,
    conservedFields& c
)
{
    const scalarField& cRho = c.rho;
    const vectorField& cRhoU = c.rhoU;
    const scalarField& cRhoE = c.rhoE;
    // A gas content without positive mass or internal energy (a small
    // cell whose neighbourhood could not absorb its wall force) is merged
    // with its neighbours once more: mixing conserves mass, momentum and
    // energy and can only lower the kinetic energy, so the internal energy
    // of the merged gas is at least the sum of theirs
    const scalarField& phi = phiField.primitiveField();
    boolList& bad = changed_;
    bad.setSize(phi.size());
    for (label attempt = 0; attempt < 2; ++attempt)
    {
        bool any = false;
        forAll(phi, i)
        {
            bad[i] =
                phi[i] > 0
             && !hasInternalEnergy(cRho[i], cRhoU[i], cRhoE[i]);
            any = any || bad[i];
        }
        if (!returnReduce(any, orOp<bool>()))
        {
            return;
        }
        srd().redistribute(phiField, c, srdLinks(false), &bad, true);
    }
}


bool Foam::blastFluidSolver::cutCellStage
(
    const label s,
    const scalar dt,
    const bool lastResort
)
{
    if (lastResort && s > 0 && !state_.current())
    {
        repairState(phiEndPtr_->primitiveField(), true);
    }
    if (!stageFluxes())
    {
        return false;
    }

    // Content of the stage's state: at the start of the step it refers to
    // phi0, later stages to phi1 (the wall terms look at it)
    const scalarField& phiNow =
        s == 0 ? fluidFractionPtr_->primitiveField() : phiEndPtr_->primitiveField();
    scalarField& cRho = cut_.rho;
    vectorField& cRhoU = cut_.rhoU;
    scalarField& cRhoE = cut_.rhoE;
    scalarField& cAlpha = cut_.alpha;
    scalarField& cAlphaRho1 = cut_.alphaRho1;
    contentFromState(phiNow, cut_);
    addWallTerms(s, dt);

    const blastTimeIntegrator& rk = rk_();
    rk.combine(s, dt, cutStart_.rho, cRho, residual_.rho);
    rk.combine(s, dt, cutStart_.rhoU, cRhoU, residual_.rhoU);
    rk.combine(s, dt, cutStart_.rhoE, cRhoE, residual_.rhoE);
    if (state_.multiPhase())
    {
        rk.combine(s, dt, cutStart_.alpha, cAlpha, residual_.alpha);
        rk.combine(s, dt, cutStart_.alphaRho1, cAlphaRho1, residual_.alphaRho1);
    }
    if (state_.threePhase())
    {
        rk.combine(s, dt, cutStart_.alpha2, cut_.alpha2, residual_.alpha2);
        rk.combine
        (
            s, dt, cutStart_.alphaRho2, cut_.alphaRho2, residual_.alphaRho2
        );
    }

    srd().redistribute(phiEndPtr_(), cut_, srdLinks(), &geometry_->newCell());
    mergeBadCells(phiEndPtr_(), cut_);
    stateFromContent(phiEndPtr_->primitiveField(), cut_);
    return true;
}


bool Foam::blastFluidSolver::advanceCutCells
(
    const scalar dt,
    const bool mayFail
)
{
    fillEmptyCells();
    if (!returnReduce(state_.current(), andOp<bool>()))
    {
        repairState(fluidFractionPtr_->primitiveField());
    }
    const scalarField& phi0 = fluidFractionPtr_->primitiveField();
    contentFromState(phi0, cutStart_);
    state_.saveConservative(start_);
    const scalar lostMass0 = lostMass(), lostEnergy0 = lostEnergy();

    lowOrder_.primitiveFieldRef() = 0;
    anyLowOrder_ = false;
    const label maxAttempts = 4;
    for (label attempt = 0; attempt < maxAttempts; ++attempt)
    {
        wallImpulse_ = Zero;
        wallWork_ = 0;
        wallPressureImpulse_ = 0;
        // The last attempt of a part that may not fail (first order
        // everywhere, the step already in its smallest parts): cut cells
        // still without a physical state at a stage's start or the end are
        // mixed with the gas around them (repairState), a conservative
        // last resort before the stop (a whole cell so stops the run)
        const bool lastResort = !mayFail && attempt == maxAttempts - 1;
        bool ok = true;
        for (label s = 0; s < rk_->nStages() && ok; ++s)
        {
            ok = cutCellStage(s, dt, lastResort);
        }
        if (ok && lastResort && !state_.current())
        {
            repairState(phiEndPtr_->primitiveField(), true);
        }
        // A first-order step can leave cells without positive internal
        // energy; they are mixed with the gas around them, and the mixed
        // state is checked like any other (a failure is retried)
        const bool good = ok && primitivesFromConservative(false);
        const label nMix = good && anyLowOrder_ ? mixNegativeEnergy() : 0;
        const bool mixed =
            good && anyLowOrder_ && returnReduce(nMix > 0, orOp<bool>());
        if (good && (!mixed || primitivesFromConservative(false)))
        {
            nMixed_ += nMix;
            outMass_ += stepOutMass_;
            outEnergy_ += stepOutEnergy_;
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
            return true;
        }
        // Redo the step from its start at first order around bad cells
        if (srd_.valid()) srd_->setLost(lostMass0, lostEnergy0);
        if (attempt == maxAttempts - 1)
        {
            break;
        }
        prepareRetry(attempt, maxAttempts);
    }
    if (mayFail)
    {
        // Back to the step's start (the fluid fraction is still the
        // start's): the caller takes the step in parts
        state_.restoreConservative(start_);
        state_.invalidate();
        primitivesFromConservative(true);
        ++nRetries_;
        return false;
    }
    primitivesFromConservative(true);
    return false;
}


void Foam::blastFluidSolver::findNearProcessor()
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    nearProcessor_.setSize(mesh_.nCells());
    nearProcessor_ = false;
    forAll(patches, patchi)
    {
        if (!isA<processorPolyPatch>(patches[patchi])) continue;
        for (const label c : patches[patchi].faceCells())
        {
            nearProcessor_[c] = true;
        }
    }
}


void Foam::blastFluidSolver::repairState
(
    const scalarField& phi,
    const bool cutOnly
)
{
    // Between two steps the state changes outside a step's check: the
    // solid step's work correction (addEnergy), the cells that opened or
    // closed (setFluidFraction), the vented pockets. A cell left without a
    // physical state (a cell closed on all faces that opened and took a
    // closing neighbour's gas: 2906 kg/m3 with e = 45 J/kg in 2 % of a
    // cell of the full-resolution cylinder, no sound speed) is mixed with
    // the gas around it, one ring, then two, and so on up to twelve (a
    // pocket sealed inside the cylinder's wall had no other gas within
    // seven), until every state is physical; only then does the check stop
    // the run, naming the cell. The same for a last part taken first order
    // everywhere that still leaves such cells (that pocket: e = 9 J/kg at
    // 610 kg/m3 and 960 m/s, below its cold curve). There (cutOnly) only
    // cut cells are mixed: a whole cell without a physical state after a
    // first-order step is a diverging run, which stops. Mixing is
    // conservative; a state without such cells is converted exactly as
    // before
    for (label rings = 1; rings <= 12; ++rings)
    {
        if (primitivesFromConservative(false))
        {
            return;
        }
        // The marks of a retry are not wanted here (lowOrder_ is reset at
        // the step's start): the cells without a sound speed are mixed
        const scalarField& c = state_.c();
        boolList& seed = changed_;
        seed.setSize(phi.size());
        bool any = false, whole = false;
        forAll(phi, i)
        {
            seed[i] = phi[i] > 0 && !(c[i] > 0);
            any = any || seed[i];
            whole = whole || (seed[i] && !(phi[i] < 1));
        }
        if
        (
            !returnReduce(any, orOp<bool>())
         || (cutOnly && returnReduce(whole, orOp<bool>()))
        )
        {
            break;
        }
        nRepaired_ += mixSeeds(phi, rings, rings);
    }
    primitivesFromConservative(true);
}


Foam::label Foam::blastFluidSolver::mixSeeds
(
    const scalarField& phi,
    const label maxRings,
    const label minRings
)
{
    if (nearProcessor_.size() != phi.size())
    {
        findNearProcessor();
    }
    contentFromState(phi, cut_);
    const label n = srd().mixUntilPositive
    (
        phi, cut_, changed_, nearProcessor_, maxRings, minRings
    );
    if (n > 0)
    {
        // Only the mixed cells' states change (the others keep theirs
        // bitwise)
        stateFromContent(phi, cut_, nullptr, &srd().mixedCells());
    }
    return n;
}


Foam::label Foam::blastFluidSolver::mixNegativeEnergy()
{
    const scalarField& phi = phiEndPtr_->primitiveField();
    const scalarField& rho = state_.rho().primitiveField();
    const vectorField& rhoU = state_.rhoU().primitiveField();
    const scalarField& rhoE = state_.rhoE().primitiveField();
    const scalarField& lo = lowOrder_.primitiveField();
    boolList& seed = changed_;
    seed.setSize(phi.size());
    bool any = false;
    forAll(phi, i)
    {
        seed[i] =
            lo[i] > 0 && phi[i] > 0
         && !hasInternalEnergy(rho[i], rhoU[i], rhoE[i]);
        any = any || seed[i];
    }
    if (!returnReduce(any, orOp<bool>()))
    {
        return 0;
    }
    return mixSeeds(phi, 3);
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
    geometry_.reset(new cutCellGeometry(mesh_, addr_));
    wallWork_.setSize(mesh_.nCells(), 0);
    wallPressureImpulse_.setSize(mesh_.nCells(), 0);
    wallImpulse_.setSize(mesh_.nCells(), Zero);
    if (srd_.valid()) srd_->setLost(0, 0);
    state_.invalidate();
}


void Foam::blastFluidSolver::setFluidFraction
(
    const scalarField& phiNew,
    const surfaceScalarField& aperture
)
{
    volScalarField& phiField = fluidFractionPtr_();
    scalarField& phi = phiField.primitiveFieldRef();
    const scalarField& cRho = cut_.rho;
    contentFromState(phi, cut_);

    // Cells that open or close exchange their content with their open
    // neighbours, and so do small cells whose gas volume changed (the
    // solid did not move exactly as predicted at the last step's start: a
    // cell predicted at 1e-6 of its volume that is now at 1e-11 would
    // compress its gas 1e5 times); the others keep theirs in the new volume
    boolList& changed = changed_;
    changed.setSize(phi.size());
    bool any = false;
    forAll(phi, i)
    {
        changed[i] =
            ((phi[i] > 0) != (phiNew[i] > 0))
         || (phiNew[i] != phi[i] && min(phi[i], phiNew[i]) < 0.5);
        any = any || changed[i];
    }
    phi = phiNew;
    phiField.correctBoundaryConditions();
    if (returnReduce(any, orOp<bool>()))
    {
        // The faces of the coming step decide which neighbours are open
        geometry_->loadApertures(aperture);
        srd().redistribute(phiField, cut_, srdLinks(), &changed, true);
        // A cell that opened where no gas can reach it yet stays closed:
        // nothing is created; it opens in a step (a new cell)
        forAll(phi, i)
        {
            if (changed[i] && phi[i] > 0 && !(cRho[i] > 0)) phi[i] = 0;
        }
        phiField.correctBoundaryConditions();
    }
    stateFromContent(phi, cut_);
}


void Foam::blastFluidSolver::ventCrushedPockets
(
    scalarField& phiEnd,
    const surfaceScalarField& aperture
)
{
    scalarField& phi = fluidFractionPtr_->primitiveFieldRef();
    const cellList& cells = mesh_.cells();
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    // A face is open as cutCellGeometry::closeShutFaces will have it: an
    // aperture, and gas on its other side at the start or the end of the
    // step (a projection can open a face to a cell the solid covers; the
    // fluxes then take it as closed, and so must the test for pockets, or
    // a pocket next to such a cell is crushed unvented: the cylinder with
    // writeInterval 9.19e-6 squeezed one to 0.049 of a cell at 8.9e10 Pa)
    const labelList& own = mesh_.faceOwner();
    const labelList& nei = mesh_.faceNeighbour();
    auto open = [&](const label i, const label f)
    {
        if (mesh_.isInternalFace(f))
        {
            const label o = own[f] == i ? nei[f] : own[f];
            return aperture[f] > 0 && (phi[o] > 0 || phiEnd[o] > 0);
        }
        const label patchi = patches.whichPatch(f);
        const fvsPatchScalarField& ap = aperture.boundaryField()[patchi];
        // (a face of an empty patch has no value: it is no face in 2D)
        return ap.size() > 0 && ap[f - patches[patchi].start()] > 0;
    };
    pockets_.clear();
    forAll(phi, i)
    {
        if (!(phi[i] > 0 && phi[i] < 0.5 && phiEnd[i] < phi[i])) continue;
        bool closed = true;
        for (const label f : cells[i])
        {
            if (open(i, f))
            {
                closed = false;
                break;
            }
        }
        if (closed) pockets_.append(i);
    }
    if (!returnReduce(pockets_.size() > 0, orOp<bool>()))
    {
        return;
    }

    if (nearProcessor_.size() != phi.size())
    {
        findNearProcessor();
    }
    const scalarField& V = mesh_.V();
    blastFluidState& st = state_;
    scalarField& rho = st.rho().primitiveFieldRef();
    vectorField& rhoU = st.rhoU().primitiveFieldRef();
    scalarField& rhoE = st.rhoE().primitiveFieldRef();
    // The material contents (volume fractions 0 and 2 are capped at 1)
    scalarField* extra[4] = {nullptr, nullptr, nullptr, nullptr};
    if (st.multiPhase())
    {
        extra[0] = &st.alpha1Ptr()->primitiveFieldRef();
        extra[1] = &st.alphaRho1Ptr()->primitiveFieldRef();
    }
    if (st.threePhase())
    {
        extra[2] = &st.alpha2Ptr()->primitiveFieldRef();
        extra[3] = &st.alphaRho2Ptr()->primitiveFieldRef();
    }
    // The receiving gas: cells at least half gas (a small cell could not
    // hold a pocket: its density would be the pocket's content over a
    // sliver), ring after ring until they hold minReceiverMass times the
    // pocket's mass or maxRings are searched. The pocket's gas loses its
    // volume: added to the receivers' volumes it compresses their gas
    // without the work that takes, and at a stiff equation of state's
    // densities that drops it below its cold curve (the products next to
    // the fragments of the full-resolution cylinder: a receiver from 862
    // to 1343 kg/m3 with e = 0.69 MJ/kg against a cold energy of
    // 1.0 MJ/kg); spread by mass over 20 times the pocket's mass, every
    // receiver's density grows by at most 5 %
    const label maxRings = 6;
    const scalar minReceiverMass = 20;
    bool any = false;
    for (const label i : pockets_)
    {
        const scalar pocketMass = rho[i]*phi[i]*V[i];
        scalar receiverMass = 0;
        bool nearProc = nearProcessor_[i];
        ventTargets_.clear();
        srd().forEachRing
        (
            i, maxRings,
            [&](const label j)
            {
                nearProc = nearProc || nearProcessor_[j];
                if (phi[j] >= 0.5 && rho[j] > 0)
                {
                    ventTargets_.append(j);
                    receiverMass += rho[j]*phi[j]*V[j];
                }
            },
            [&]()
            {
                return receiverMass >= minReceiverMass*pocketMass || nearProc;
            }
        );
        if (nearProc || !(receiverMass > 0)) continue;
        // Each receiver's conserved state grows by the pocket's content in
        // proportion to the receiver's mass m_j: per unit of its gas volume
        // C m_j/(M phi_j V_j) = (phi_i V_i/M) rho_j U_i, with C = phi_i V_i U_i
        // the pocket's content and M the receivers' mass (the same
        // relative growth of density everywhere)
        const scalar s = phi[i]*V[i]/receiverMass;
        for (const label j : ventTargets_)
        {
            const scalar sj = s*rho[j];
            rho[j] += sj*rho[i];
            rhoU[j] += sj*rhoU[i];
            rhoE[j] += sj*rhoE[i];
            for (scalarField* x : extra)
            {
                if (x) (*x)[j] += sj*(*x)[i];
            }
            if (extra[0]) (*extra[0])[j] = min((*extra[0])[j], scalar(1));
            if (extra[2]) (*extra[2])[j] = min((*extra[2])[j], scalar(1));
        }
        ++nVented_;
        ventedMass_ += rho[i]*phi[i]*V[i];
        phi[i] = 0;
        phiEnd[i] = 0;
        any = true;
    }
    // Every rank alike (the boundary exchange is collective, and so are the
    // conversions the invalidated state leads to): a pocket vented on one
    // rank only had the other skip this exchange, and the next reduction
    // received the patch values (MPI_ERR_TRUNCATE, the full-resolution
    // cylinder on 2 ranks at 4.6 us)
    if (returnReduce(any, orOp<bool>()))
    {
        st.invalidate();
        fluidFractionPtr_->correctBoundaryConditions();
    }
}


void Foam::blastFluidSolver::setEmbeddedBoundary
(
    const scalarField& phiEnd,
    const surfaceScalarField& aperture
)
{
    volScalarField& phi1Field = phiEndPtr_();
    phi1Field.primitiveFieldRef() = phiEnd;
    ventCrushedPockets(phi1Field.primitiveFieldRef(), aperture);
    phi1Field.correctBoundaryConditions();
    geometry_->set(fluidFractionPtr_(), phi1Field, aperture);
}


void Foam::blastFluidSolver::addEnergy(const scalarField& dE)
{
    // Into the total energy of the cells whose walls did work (dE/(phi V)
    // per unit gas volume). A cell takes at most half of its internal
    // energy either way: the difference can exceed the content of a cell
    // that opened in the step (a crack that opened faster than predicted).
    // The rest is spread over all burnt gas in proportion to its internal
    // energy (spreadEnergy, a small relative change everywhere instead of
    // a negative energy in one cell).
    // A small cell shares what it took with its neighbourhood at the next
    // redistribution (the step's start if its fluid fraction changed,
    // else the first Runge-Kutta stage); until then the cap keeps its
    // state physical. (Until 2026-12-07 every small cell was redistributed
    // here, a second averaging of the step's content and about 30 % of the
    // coupling's cost on the fragmenting cylinder.)
    const scalarField& phi = fluidFractionPtr_().primitiveField();
    const scalarField& V = mesh_.V();
    const scalarField& rho = state_.rho().primitiveField();
    const vectorField& rhoU = state_.rhoU().primitiveField();
    scalarField& rhoE = state_.rhoE().primitiveFieldRef();
    // Internal energy per unit cell volume (the content's)
    auto internal = [&](const label i)
    {
        return
            phi[i] > 0 && rho[i] > 0
          ? phi[i]*max(rhoE[i] - 0.5*magSqr(rhoU[i])/rho[i], scalar(0))
          : scalar(0);
    };
    // Only what a cap held back is spread. (Whether the primitives are
    // current decides between collective calls below: every rank takes
    // the same branch)
    const bool current = returnReduce(state_.current(), andOp<bool>());
    changedCells_.clear();
    scalar rest = 0;
    forAll(dE, i)
    {
        if (dE[i] == 0) continue;
        const scalar cap = 0.5*internal(i);
        const scalar d0 = dE[i]/V[i];
        const scalar d = min(max(d0, -cap), cap);
        if (d != 0)
        {
            rhoE[i] += d/phi[i];
            changedCells_.append(i);
        }
        if (d != d0)
        {
            rest += dE[i] - d*V[i];
        }
    }
    // Unburnt explosive (programmed burn) does not share: its internal
    // energy is mostly chemical (q = E0/rho0), and a share of it would
    // change the pressure of a charge that has not fired (5e-4 before t0)
    const scalarField* F =
        burn_.valid() ? &burn_->burnFraction().primitiveField() : nullptr;
    auto weight = [&](const label i)
    {
        return F ? internal(i)*(*F)[i] : internal(i);
    };
    // What the caps held back (mostly the work of cells that closed in the
    // step, 1e-11 to 1e-7 J/m on the fragmenting cylinder, in most steps)
    // goes to the cells that took their share, the walls' cells, in
    // proportion to their internal energy: only their primitives change.
    // If they cannot hold it (more than half of their internal energy) it
    // goes to all burnt gas, whose primitives are then all recomputed
    reduce(rest, sumOp<scalar>());
    bool wholeMesh = false;
    if (rest != 0)
    {
        scalar total = 0;
        for (const label i : changedCells_)
        {
            total += weight(i)*V[i];
        }
        reduce(total, sumOp<scalar>());
        wholeMesh = !(mag(rest) <= 0.5*total);
        if (wholeMesh)
        {
            total = 0;
            forAll(phi, i)
            {
                total += weight(i)*V[i];
            }
            reduce(total, sumOp<scalar>());
        }
        if (total > 0)
        {
            const scalar r = rest/total;
            auto share = [&](const label i)
            {
                const scalar w = weight(i);
                if (w > 0) rhoE[i] += r*w/phi[i];
            };
            if (wholeMesh)
            {
                forAll(phi, i) share(i);
            }
            else
            {
                for (const label i : changedCells_) share(i);
            }
            spreadEnergy_ += rest;
        }
    }
    state_.invalidate();

    // The written state is the corrected one, checked now: the primitives
    // of the cells that changed, when the others' are current, as the step
    // leaves them. A cell the correction left without a physical state (a
    // cell just above its cold curve that gave energy: e = 0 at 591 kg/m3
    // in the full-resolution cylinder) is mixed with its neighbours
    // (repairState); only a state that stays bad stops the run, before it
    // is written
    if
    (
        !current || wholeMesh
     || !state_.primitivesOfCells(changedCells_, burnCells(), false)
    )
    {
        repairState(fluidFractionPtr_->primitiveField());
    }
}


void Foam::blastFluidSolver::addContent
(
    const labelUList& cells,
    const UList<scalar>& dm,
    const UList<vector>& dmU,
    const UList<scalar>& dE,
    const UList<scalar>& dm1
)
{
    // Into the content (per unit cell volume), then the small cells that
    // received gas share it with their neighbourhoods as the step's
    // content does: a crack's gas handed over by the point rule to a
    // sliver (benchBlast: 3.6e-6 kg of 400 kg/m3 gas into 2.7e-9 m3 of a
    // cell 1 % open) was compressed to 1360 kg/m3 and 13 GPa alone
    if (state_.threePhase())
    {
        // The exchange carries material 1 and the rest (the crack gas of
        // two materials; jwlIbFoam refuses crackGas with three)
        FatalErrorInFunction
            << "addContent takes two materials, the case has three "
            << state_.mixture().materials() << exit(FatalError);
    }
    if (!fluidFractionPtr_.valid())
    {
        addContentFull(cells, dm, dmU, dE, dm1);
        return;
    }
    volScalarField& phiField = fluidFractionPtr_();
    const scalarField& phi = phiField.primitiveField();
    const scalarField& V = mesh_.V();
    conservedFields& q = cut_;
    contentFromState(phi, q);
    contentTo_.setSize(phi.size());
    contentTo_ = false;
    forAll(cells, k)
    {
        const label c = cells[k];
        checkHoldsGas(c, phi[c]*V[c]);
        if (state_.multiPhase())
        {
            // The added masses at the cell's phase densities, the cell's
            // gas volume kept: alpha = (alpha Vg + dm1/rho1)/(Vg + dm1/rho1
            // + dm2/rho2)
            const scalar Vg = phi[c]*V[c];
            const scalar r1 = state_.rho1Ptr()->primitiveField()[c];
            const scalar r2 = state_.rho2Ptr()->primitiveField()[c];
            const scalar v1 = dm1[k]/r1, v2 = (dm[k] - dm1[k])/r2;
            const scalar vol = q.alpha[c]*V[c] + v1;
            const scalar alpha = min
            (
                max(vol/max(Vg + v1 + v2, VSMALL), scalar(0)), scalar(1)
            );
            q.alpha[c] = alpha*phi[c];
            q.alphaRho1[c] += dm1[k]/V[c];
        }
        q.rho[c] += dm[k]/V[c];
        q.rhoU[c] += dmU[k]/V[c];
        q.rhoE[c] += dE[k]/V[c];
        checkGasLeft(c, q.rho[c], q.rhoU[c], q.rhoE[c], dm[k], dE[k]);
        if (dm[k] > 0 && phi[c] < 0.5)
        {
            contentTo_[c] = true;
        }
    }
    if (returnReduce(contentTo_.found(true), orOp<bool>()))
    {
        srd().redistribute(phiField, q, srdLinks(), &contentTo_, true);
    }
    stateFromContent(phi, q);
    primitivesFromConservative(true);
}


void Foam::blastFluidSolver::addContentFull
(
    const labelUList& cells,
    const UList<scalar>& dm,
    const UList<vector>& dmU,
    const UList<scalar>& dE,
    const UList<scalar>& dm1
)
{
    // No solid on the mesh: every cell is whole
    const scalarField& V = mesh_.V();
    scalarField& rho = state_.rho().primitiveFieldRef();
    vectorField& rhoU = state_.rhoU().primitiveFieldRef();
    scalarField& rhoE = state_.rhoE().primitiveFieldRef();
    forAll(cells, k)
    {
        const label c = cells[k];
        const scalar Vg = V[c];
        if (state_.multiPhase())
        {
            scalar& alpha = state_.alpha1Ptr()->primitiveFieldRef()[c];
            const scalar r1 = state_.rho1Ptr()->primitiveField()[c];
            const scalar r2 = state_.rho2Ptr()->primitiveField()[c];
            const scalar v1 = dm1[k]/r1, v2 = (dm[k] - dm1[k])/r2;
            alpha = min
            (
                max((alpha*Vg + v1)/max(Vg + v1 + v2, VSMALL), scalar(0)),
                scalar(1)
            );
            state_.alphaRho1Ptr()->primitiveFieldRef()[c] += dm1[k]/Vg;
        }
        rho[c] += dm[k]/Vg;
        rhoU[c] += dmU[k]/Vg;
        rhoE[c] += dE[k]/Vg;
        checkGasLeft(c, rho[c], rhoU[c], rhoE[c], dm[k], dE[k]);
    }
    state_.invalidate();
    primitivesFromConservative(true);
}


void Foam::blastFluidSolver::checkHoldsGas(const label c, const scalar Vg)
const
{
    if (!(Vg > 0))
    {
        FatalErrorInFunction
            << "blastFluidSolver: gas added to cell " << c << " at "
            << mesh_.C()[c] << ", which holds no gas"
            << exit(FatalError);
    }
}


void Foam::blastFluidSolver::checkGasLeft
(
    const label c,
    const scalar rho,
    const vector& rhoU,
    const scalar rhoE,
    const scalar dm,
    const scalar dE
) const
{
    if (!(rho > 0) || !(rhoE - 0.5*magSqr(rhoU)/rho > 0))
    {
        FatalErrorInFunction
            << "blastFluidSolver: cell " << c << " at " << mesh_.C()[c]
            << " has no gas left after giving " << -dm << " kg and "
            << -dE << " J to gas outside the mesh" << exit(FatalError);
    }
}


Foam::tmp<Foam::scalarField> Foam::blastFluidSolver::fluidFraction() const
{
    if (fluidFractionPtr_.valid())
    {
        return fluidFractionPtr_->primitiveField();
    }
    return tmp<scalarField>::New(mesh_.nCells(), 1);
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastFluidSolver.H"
#include "blastLimiter.H"
#include "surfaceFields.H"
#include "OStringStream.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(blastFluidSolver, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- Stop on an entry of dict that is not in valid (a misspelt optional
    //  entry would otherwise be ignored silently and its default used)
    void checkKnownEntries
    (
        const Foam::dictionary& dict,
        const Foam::wordList& valid
    )
    {
        for (const Foam::entry& e : dict)
        {
            const Foam::word& key = e.keyword();
            if (key != "FoamFile" && !valid.found(key))
            {
                FatalIOErrorInFunction(dict)
                    << "Unknown entry '" << key << "'. Valid entries: "
                    << flatOutput(valid)
                    << Foam::exit(Foam::FatalIOError);
            }
        }
    }


    //- A patch the gas treats as reflective (wall, symmetry, slip) gets
    //  zero normal velocity and the mirror-state pressure whatever its
    //  conditions say; its conditions must be ones that treatment honours
    //  (as OpenFOAM insists on symmetry conditions on symmetry patches),
    //  else the user's fixedValue p, normal wall velocity or inletOutlet
    //  would be ignored without a word. Honoured: U slip, noSlip,
    //  symmetry(Plane) or fixedValue without a normal component (a wall at
    //  rest or sliding in its plane: the inviscid gas cannot tell it from
    //  slip); the scalars zeroGradient, slip or symmetry(Plane)
    void reflectiveConditionError
    (
        const Foam::regIOobject& field,
        const Foam::fvPatch& pp,
        const Foam::word& bcType,
        const Foam::string& why
    )
    {
        using namespace Foam;
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, field.objectPath(), -1)
            << "file " << field.objectPath() << ": entry 'boundaryField."
            << pp.name() << "' is " << bcType << " but the gas solver treats"
            << " patch '" << pp.name() << "' (type " << pp.type() << ") as a"
            << " reflective wall (no flow through it, mirror-state pressure):"
            << " " << why.c_str() << ". On walls use " << field.name() << ' '
            << (field.name() == "U" ? "slip (or noSlip)" : "zeroGradient")
            << "; for an inflow or outlet give the patch the type patch"
            << " (fixedValue, zeroGradient)" << exit(FatalIOError);
    }

    void checkReflectiveConditions
    (
        const Foam::fvPatch& pp,
        const Foam::volVectorField& U,
        const Foam::UList<const Foam::volScalarField*>& scalars
    )
    {
        using namespace Foam;
        const label patchi = pp.index();
        const fvPatchVectorField& Ub = U.boundaryField()[patchi];
        const word& Utype = Ub.type();
        if (Utype == "fixedValue")
        {
            const vectorField nf(pp.nf());
            forAll(Ub, j)
            {
                if (mag(Ub[j] & nf[j]) > 1e-9*mag(Ub[j]))
                {
                    reflectiveConditionError
                    (
                        U, pp, Utype, "the wall velocity " + name(Ub[j])
                      + " of face " + name(j) + " has a normal component"
                        " (the walls do not move: it would be ignored)"
                    );
                }
            }
        }
        else if
        (
            Utype != "slip" && Utype != "noSlip" && Utype != "symmetry"
         && Utype != "symmetryPlane"
        )
        {
            reflectiveConditionError(U, pp, Utype, "it would be ignored");
        }
        for (const volScalarField* f : scalars)
        {
            const word& type = f->boundaryField()[patchi].type();
            if
            (
                type != "zeroGradient" && type != "slip"
             && type != "symmetry" && type != "symmetryPlane"
            )
            {
                reflectiveConditionError(*f, pp, type, "it would be ignored");
            }
        }
    }

}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastFluidSolver::readControls()
{
    caseChecks::checkInput(fluidDict_);
    // Run-time selected (entry 'limiter'); an unknown name: FatalIOError
    // naming the file, the entry and the valid names
    reconstruction_.reset
    (
        new blastReconstruction
        (
            mesh_, addr_, fluidDict_,
            state_.threePhase() ? 3 : state_.multiPhase() ? 2 : 1
        )
    );

    // Entry 'RKorder' (1, 2, 3); another value: FatalIOError naming the
    // file and the entry
    rk_.reset(new blastTimeIntegrator(fluidDict_));

    checkKnownEntries
    (
        fluidDict_, wordList({"flux", "limiter", "RKorder", "QScheme"})
    );
    const dictionary& Qdict = fluidDict_.subOrEmptyDict("QScheme");
    checkKnownEntries(Qdict, wordList({"active", "CQ", "CL"}));
    QActive_ = Qdict.getOrDefault<bool>("active", false);
    CQ_ = Qdict.getOrDefault<scalar>("CQ", 1.5);
    CL_ = Qdict.getOrDefault<scalar>("CL", 0.06);
    if (CQ_ < 0 || CL_ < 0)
    {
        FatalIOErrorInFunction(fluidDict_)
            << "QScheme coefficients CQ and CL must be >= 0"
            << exit(FatalIOError);
    }
}


void Foam::blastFluidSolver::updateBurn(const scalar t)
{
    burn_->update(t);
    const scalarField& F = burn_->burnFraction().primitiveField();
    burnL_.setSize(addr_.nFaces());
    burnR_.setSize(addr_.nFaces());
    for (label f = 0; f < addr_.nFaces(); ++f)
    {
        burnL_[f] = F[addr_.own()[f]];
        burnR_[f] = f < addr_.nInternal() ? F[addr_.nei()[f]] : burnL_[f];
    }
    addr_.coupledNeighbourValues(burn_->burnFraction(), burnNbr_);
    forAll(addr_.coupledFace(), j)
    {
        if (addr_.coupledFace()[j])
        {
            burnR_[addr_.nInternal() + j] = burnNbr_[j];
        }
    }
    state_.invalidate();
}


void Foam::blastFluidSolver::checkReflectivePatches() const
{
    // A mirror state needs conditions that mirror: the scalar fields read
    // from the case on each reflective patch
    typedef List<const volScalarField*> fieldList;
    fieldList fields
    (
        state_.multiPhase()
      ? fieldList
        ({
            &state_.p(), state_.alpha1Ptr().get(), state_.rho1Ptr().get(),
            state_.rho2Ptr().get()
        })
      : fieldList({&state_.p(), &state_.rho()})
    );
    if (state_.threePhase())
    {
        fields.append(state_.alpha2Ptr().get());
        fields.append(state_.rho3Ptr().get());
    }
    const fvBoundaryMesh& bm = mesh_.boundary();
    forAll(bm, patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::REFLECTIVE)
        {
            checkReflectiveConditions(bm[patchi], state_.U(), fields);
        }
    }
}


void Foam::blastFluidSolver::growLowOrder()
{
    lowOrder_.correctBoundaryConditions();
    const scalarField lo0(lowOrder_.primitiveField());
    scalarField& lo = lowOrder_.primitiveFieldRef();
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (lo0[P] > 0 || lo0[N] > 0)
        {
            lo[P] = 1;
            lo[N] = 1;
        }
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] != blastFaceAddressing::COUPLED) continue;
        const tmp<scalarField> tnbr =
            lowOrder_.boundaryField()[patchi].patchNeighbourField();
        const scalarField& nbr = tnbr();
        const label start = addr_.patchStart()[patchi];
        forAll(nbr, j)
        {
            if (nbr[j] > 0) lo[addr_.own()[start + j]] = 1;
        }
    }
    lowOrder_.correctBoundaryConditions();
}


void Foam::blastFluidSolver::faceStates()
{
    reconstruction_->faceStates
    (
        {
            state_.rho(), state_.U(), state_.p(),
            state_.alpha1Ptr().get(), state_.rho1Ptr().get(),
            state_.rho2Ptr().get(),
            state_.alpha2Ptr().get(), state_.rho3Ptr().get()
        },
        lowOrder_, anyLowOrder_, faces_
    );
}


void Foam::blastFluidSolver::faceThermo()
{
    const blastReconstruction::phaseFaceDensities& ph =
        reconstruction_->phaseDensities();
    blastFaceStates& s = faces_;
    const label n = addr_.nFaces();

    if (state_.threePhase())
    {
        faceThermo3(ph);
    }
    else if (state_.multiPhase())
    {
        for (label f = 0; f < n; ++f)
        {
            const scalar aL = s.alphaL[f], aR = s.alphaR[f];
            const scalar m1L = aL*ph.rho1L[f], m1R = aR*ph.rho1R[f];
            s.rhoL[f] = m1L + (1 - aL)*ph.rho2L[f];
            s.rhoR[f] = m1R + (1 - aR)*ph.rho2R[f];
            s.Y1L[f] = m1L/s.rhoL[f];
            s.Y1R[f] = m1R/s.rhoR[f];
        }
        state_.mixture().rhoeC2
        (
            n, s.alphaL, ph.rho1L, ph.rho2L, s.rhoL, s.pL, workE_, workC2_,
            burn_.valid() ? &burnL_ : nullptr
        );
        for (label f = 0; f < n; ++f)
        {
            s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
            s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
        }
        state_.mixture().rhoeC2
        (
            n, s.alphaR, ph.rho1R, ph.rho2R, s.rhoR, s.pR, workE_, workC2_,
            burn_.valid() ? &burnR_ : nullptr
        );
        for (label f = 0; f < n; ++f)
        {
            s.ER[f] = workE_[f] + 0.5*s.rhoR[f]*magSqr(s.UR[f]);
            s.cR[f] = sqrt(max(workC2_[f], scalar(0)));
        }
    }
    else
    {
        state_.mixture().rhoeC2
        (
            n, s.rhoL, s.rhoL, s.rhoL, s.rhoL, s.pL, workE_, workC2_
        );
        for (label f = 0; f < n; ++f)
        {
            s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
            s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
        }
        state_.mixture().rhoeC2
        (
            n, s.rhoR, s.rhoR, s.rhoR, s.rhoR, s.pR, workE_, workC2_
        );
        for (label f = 0; f < n; ++f)
        {
            s.ER[f] = workE_[f] + 0.5*s.rhoR[f]*magSqr(s.UR[f]);
            s.cR[f] = sqrt(max(workC2_[f], scalar(0)));
        }
    }
}


void Foam::blastFluidSolver::computeFluxes()
{
    flux_->fluxes(0, addr_.nInternal(), addr_.Sf(), addr_.magSf(), faces_, nTracked(), F_);

    forAll(addr_.kinds(), patchi)
    {
        const label start = addr_.patchStart()[patchi];
        const label size = mesh_.boundary()[patchi].size();
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP)
        {
            continue;
        }
        else if (addr_.kinds()[patchi] == blastFaceAddressing::WEDGE)
        {
            // Wedge planes: no mass or energy crosses them; the pressure on
            // the two (non-parallel) planes is the axisymmetric source. The
            // tilt of the planes gives u.n != 0 for radial flow, which is
            // not an impinging flow: no Riemann problem here.
            for (label cf = start; cf < start + size; ++cf)
            {
                F_.rho[cf] = 0;
                F_.rhoU[cf] = faces_.pL[cf]*addr_.Sf()[cf];
                F_.rhoE[cf] = 0;
                F_.uS[cf] = 0;
                zeroMaterialFluxes(cf);
            }
        }
        else if (addr_.kinds()[patchi] != blastFaceAddressing::REFLECTIVE)
        {
            flux_->fluxes
            (
                start, start + size, addr_.Sf(), addr_.magSf(), faces_, nTracked(), F_
            );
        }
        else
        {
            // Mirror-state Riemann problem: contact speed zero, so the mass
            // and energy fluxes are exactly zero (conservation to round-off)
            for (label cf = start; cf < start + size; ++cf)
            {
                const vector n = addr_.Sf()[cf]/addr_.magSf()[cf];
                const scalar un = faces_.UL[cf] & n;
                const scalar pStar = max
                (
                    faces_.pL[cf]
                  + faces_.rhoL[cf]*un*(mag(un) + un + faces_.cL[cf]),
                    scalar(0)
                );
                F_.rho[cf] = 0;
                F_.rhoU[cf] = pStar*addr_.Sf()[cf];
                F_.rhoE[cf] = 0;
                F_.uS[cf] = 0;
                zeroMaterialFluxes(cf);
            }
        }
    }
}


void Foam::blastFluidSolver::addQScheme()
{
    const vectorField& U = state_.U().primitiveField();
    divU_ = 0;
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        const scalar phi = (addr_.w()[f]*U[P] + (1 - addr_.w()[f])*U[N]) & addr_.Sf()[f];
        divU_[P] += phi;
        divU_[N] -= phi;
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP || addr_.kinds()[patchi] == blastFaceAddressing::REFLECTIVE)
        {
            continue;
        }
        const fvPatchVectorField& Ub = state_.U().boundaryField()[patchi];
        const label start = addr_.patchStart()[patchi];
        if (addr_.kinds()[patchi] == blastFaceAddressing::COUPLED)
        {
            const tmp<vectorField> tnbr = Ub.patchNeighbourField();
            const vectorField& nbr = tnbr();
            forAll(Ub, j)
            {
                const label cf = start + j;
                const label P = addr_.own()[cf];
                divU_[P] += (addr_.w()[cf]*U[P] + (1 - addr_.w()[cf])*nbr[j]) & addr_.Sf()[cf];
            }
        }
        else
        {
            forAll(Ub, j)
            {
                divU_[addr_.own()[start + j]] += Ub[j] & addr_.Sf()[start + j];
            }
        }
    }

    const scalarField& V = mesh_.V();
    const scalarField& rho = state_.rho().primitiveField();
    scalarField& q = q_.primitiveFieldRef();
    forAll(q, i)
    {
        const scalar d = divU_[i]/V[i];
        const scalar l = addr_.cellLength()[i];
        q[i] = d < 0 ? rho[i]*l*(CQ_*CQ_*l*d*d - CL_*state_.c()[i]*d) : 0;
    }
    q_.correctBoundaryConditions();

    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        const scalar qf = addr_.w()[f]*q[P] + (1 - addr_.w()[f])*q[N];
        const vector Uf = addr_.w()[f]*U[P] + (1 - addr_.w()[f])*U[N];
        F_.rhoU[f] += qf*addr_.Sf()[f];
        F_.rhoE[f] += qf*(Uf & addr_.Sf()[f]);
    }
    forAll(addr_.kinds(), patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::SKIP) continue;
        const fvPatchScalarField& qb = q_.boundaryField()[patchi];
        const fvPatchVectorField& Ub = state_.U().boundaryField()[patchi];
        const label start = addr_.patchStart()[patchi];
        const bool reflective =
        (
            addr_.kinds()[patchi] == blastFaceAddressing::REFLECTIVE || addr_.kinds()[patchi] == blastFaceAddressing::WEDGE
        );
        if (addr_.kinds()[patchi] == blastFaceAddressing::COUPLED)
        {
            const tmp<scalarField> tqn = qb.patchNeighbourField();
            const tmp<vectorField> tUn = Ub.patchNeighbourField();
            const scalarField& qn = tqn();
            const vectorField& Un = tUn();
            forAll(qb, j)
            {
                const label cf = start + j;
                const label P = addr_.own()[cf];
                const scalar w = addr_.w()[cf];
                const scalar qf = w*q[P] + (1 - w)*qn[j];
                F_.rhoU[cf] += qf*addr_.Sf()[cf];
                F_.rhoE[cf] += qf*((w*U[P] + (1 - w)*Un[j]) & addr_.Sf()[cf]);
            }
            continue;
        }
        forAll(qb, j)
        {
            const label cf = start + j;
            F_.rhoU[cf] += qb[j]*addr_.Sf()[cf];
            if (!reflective)
            {
                F_.rhoE[cf] += qb[j]*(Ub[j] & addr_.Sf()[cf]);
            }
        }
    }
}


void Foam::blastFluidSolver::assembleResidual()
{
    residual_.rho = 0;
    residual_.rhoU = Zero;
    residual_.rhoE = 0;
    if (state_.multiPhase())
    {
        residual_.alpha = 0;
        residual_.alphaRho1 = 0;
    }
    if (state_.threePhase())
    {
        residual_.alpha2 = 0;
        residual_.alphaRho2 = 0;
    }
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        residual_.rho[P] -= F_.rho[f];
        residual_.rho[N] += F_.rho[f];
        residual_.rhoU[P] -= F_.rhoU[f];
        residual_.rhoU[N] += F_.rhoU[f];
        residual_.rhoE[P] -= F_.rhoE[f];
        residual_.rhoE[N] += F_.rhoE[f];
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label P = addr_.own()[cf];
        residual_.rho[P] -= F_.rho[cf];
        residual_.rhoU[P] -= F_.rhoU[cf];
        residual_.rhoE[P] -= F_.rhoE[cf];
    }

    if (state_.multiPhase())
    {
        addMaterialResidual
        (
            F_.rhoY1, F_.alpha, state_.alpha1Ptr()->primitiveField(),
            residual_.alphaRho1, residual_.alpha
        );
    }
    if (state_.threePhase())
    {
        addMaterialResidual
        (
            F_.rhoY2, F_.alpha2, state_.alpha2Ptr()->primitiveField(),
            residual_.alphaRho2, residual_.alpha2
        );
    }

    const scalarField& V = mesh_.V();
    forAll(V, i)
    {
        const scalar rV = 1/V[i];
        residual_.rho[i] *= rV;
        residual_.rhoU[i] *= rV;
        residual_.rhoE[i] *= rV;
    }
    if (state_.multiPhase())
    {
        forAll(V, i)
        {
            residual_.alpha[i] /= V[i];
            residual_.alphaRho1[i] /= V[i];
        }
    }
    if (state_.threePhase())
    {
        forAll(V, i)
        {
            residual_.alpha2[i] /= V[i];
            residual_.alphaRho2[i] /= V[i];
        }
    }
}


void Foam::blastFluidSolver::addOutflow(const label s, const scalar dt)
{
    // Like the state: O <- a_s O0 + b_s (O + dt F), O0 = 0 at the step's
    // start, so that the step's outflow is the combination of the stages'
    // fluxes the state received (a retried step starts it again)
    scalar fm = 0, fE = 0;
    const boolList& coupled = addr_.coupledFace();
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        if (coupled[cf - addr_.nInternal()]) continue;
        fm += F_.rho[cf];
        fE += F_.rhoE[cf];
    }
    rk_->accumulate(s, stepOutMass_, dt*fm);
    rk_->accumulate(s, stepOutEnergy_, dt*fE);
}


Foam::scalar Foam::blastFluidSolver::outflowMass() const
{
    return returnReduce(outMass_, sumOp<scalar>());
}


Foam::scalar Foam::blastFluidSolver::outflowEnergy() const
{
    return returnReduce(outEnergy_, sumOp<scalar>());
}


bool Foam::blastFluidSolver::stageFluxes()
{
    if (!state_.current() && !primitivesFromConservative(false))
    {
        return false;
    }
    faceStates();
    faceThermo();
    computeFluxes();
    if (QActive_)
    {
        addQScheme();
    }
    return true;
}


bool Foam::blastFluidSolver::stage(const label s, const scalar dt)
{
    if (!stageFluxes())
    {
        return false;
    }
    assembleResidual();
    addOutflow(s, dt);

    const blastTimeIntegrator& rk = rk_();
    rk.combine
    (
        s, dt, start_.rho, state_.rho().primitiveFieldRef(), residual_.rho
    );
    rk.combine
    (
        s, dt, start_.rhoU, state_.rhoU().primitiveFieldRef(), residual_.rhoU
    );
    rk.combine
    (
        s, dt, start_.rhoE, state_.rhoE().primitiveFieldRef(), residual_.rhoE
    );
    if (state_.multiPhase())
    {
        combineTracked
        (
            s, dt, start_.alpha, state_.alpha1Ptr()(), residual_.alpha,
            start_.alphaRho1, state_.alphaRho1Ptr()(), residual_.alphaRho1
        );
    }
    if (state_.threePhase())
    {
        combineTracked
        (
            s, dt, start_.alpha2, state_.alpha2Ptr()(), residual_.alpha2,
            start_.alphaRho2, state_.alphaRho2Ptr()(), residual_.alphaRho2
        );
    }
    state_.invalidate();
    return true;
}


void Foam::blastFluidSolver::faceThermo3
(
    const blastReconstruction::phaseFaceDensities& ph
)
{
    blastFaceStates& s = faces_;
    const label n = addr_.nFaces();
    // The limiter bounds alpha1 and alpha2 on a face each by its
    // neighbours, not their sum: scale a sum above 1 back to 1, so that
    // the updated cells stay in alpha1 + alpha2 <= 1 (a convex combination
    // of cell and face values) and never need a clip that would change the
    // volume fractions without the energy (uniform p lost at a contact)
    for (label f = 0; f < n; ++f)
    {
        const scalar sL = s.alphaL[f] + s.alpha2L[f];
        if (sL > 1)
        {
            s.alphaL[f] /= sL;
            s.alpha2L[f] /= sL;
        }
        const scalar sR = s.alphaR[f] + s.alpha2R[f];
        if (sR > 1)
        {
            s.alphaR[f] /= sR;
            s.alpha2R[f] /= sR;
        }
    }
    for (label f = 0; f < n; ++f)
    {
        const scalar aL = s.alphaL[f], aR = s.alphaR[f];
        const scalar bL = s.alpha2L[f], bR = s.alpha2R[f];
        const scalar m1L = aL*ph.rho1L[f], m1R = aR*ph.rho1R[f];
        const scalar m2L = bL*ph.rho2L[f], m2R = bR*ph.rho2R[f];
        s.rhoL[f] = m1L + m2L + (1 - aL - bL)*ph.rho3L[f];
        s.rhoR[f] = m1R + m2R + (1 - aR - bR)*ph.rho3R[f];
        s.Y1L[f] = m1L/s.rhoL[f];
        s.Y1R[f] = m1R/s.rhoR[f];
        s.Y2L[f] = m2L/s.rhoL[f];
        s.Y2R[f] = m2R/s.rhoR[f];
    }
    state_.mixture().rhoeC2
    (
        n, s.alphaL, s.alpha2L, ph.rho1L, ph.rho2L, ph.rho3L, s.rhoL, s.pL,
        workE_, workC2_, burn_.valid() ? &burnL_ : nullptr
    );
    for (label f = 0; f < n; ++f)
    {
        s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
        s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
    }
    state_.mixture().rhoeC2
    (
        n, s.alphaR, s.alpha2R, ph.rho1R, ph.rho2R, ph.rho3R, s.rhoR, s.pR,
        workE_, workC2_, burn_.valid() ? &burnR_ : nullptr
    );
    for (label f = 0; f < n; ++f)
    {
        s.ER[f] = workE_[f] + 0.5*s.rhoR[f]*magSqr(s.UR[f]);
        s.cR[f] = sqrt(max(workC2_[f], scalar(0)));
    }
}


void Foam::blastFluidSolver::combineTracked
(
    const label s,
    const scalar dt,
    const scalarField& alpha0,
    volScalarField& alphaField,
    const scalarField& Ralpha,
    const scalarField& m0,
    volScalarField& mField,
    const scalarField& Rm
) const
{
    const blastTimeIntegrator& rk = rk_();
    scalarField& alpha = alphaField.primitiveFieldRef();
    rk.combine(s, dt, alpha0, alpha, Ralpha);
    forAll(alpha, i)
    {
        alpha[i] = min(max(alpha[i], scalar(0)), scalar(1));
    }
    rk.combine(s, dt, m0, mField.primitiveFieldRef(), Rm);
}


void Foam::blastFluidSolver::addMaterialResidual
(
    const scalarField& Fm,
    const scalarField& Fa,
    const scalarField& alpha,
    scalarField& Rm,
    scalarField& Ra
) const
{
    for (label f = 0; f < addr_.nInternal(); ++f)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        Rm[P] -= Fm[f];
        Rm[N] += Fm[f];
        // d alpha/dt = -div(alpha u) + alpha div(u)
        Ra[P] -= Fa[f] - alpha[P]*F_.uS[f];
        Ra[N] += Fa[f] - alpha[N]*F_.uS[f];
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label P = addr_.own()[cf];
        Rm[P] -= Fm[cf];
        Ra[P] -= Fa[cf] - alpha[P]*F_.uS[cf];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastFluidSolver::blastFluidSolver(const fvMesh& mesh)
:
    mesh_(mesh),
    state_(mesh),
    fluidDict_
    (
        IOobject
        (
            "blastFluidProperties",
            mesh.time().system(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE
        ),
        dictionary()
    ),
    flux_(fluxScheme::New(fluidDict_)),
    QActive_(false),
    CQ_(1.5),
    CL_(0.06),
    q_
    (
        IOobject
        (
            "Qpressure",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPressure, Zero),
        "zeroGradient"
    ),
    divU_(mesh.nCells(), 0),
    lowOrder_
    (
        IOobject
        (
            "lowOrder",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        ),
        mesh,
        dimensionedScalar(dimless, Zero),
        "zeroGradient"
    ),
    nRetries_(0),
    anyLowOrder_(false),
    addr_(mesh, state_.U()),
    cutCells_(false),
    stepOutMass_(0),
    stepOutEnergy_(0),
    outMass_(0),
    outEnergy_(0),
    spreadEnergy_(0),
    nVented_(0),
    ventedMass_(0),
    nMixed_(0),
    nRepaired_(0)
{
    readControls();

    const label nCells = mesh.nCells();

    checkReflectivePatches();

    faces_.setSize(addr_.nFaces(), nTracked());
    F_.setSize(addr_.nFaces(), nTracked());
    workE_.setSize(addr_.nFaces(), 0);
    workC2_.setSize(addr_.nFaces(), 0);
    if (state_.multiPhase())
    {
        start_.alpha.setSize(nCells); start_.alphaRho1.setSize(nCells);
        residual_.alpha.setSize(nCells); residual_.alphaRho1.setSize(nCells);
    }
    if (state_.threePhase())
    {
        start_.alpha2.setSize(nCells); start_.alphaRho2.setSize(nCells);
        residual_.alpha2.setSize(nCells); residual_.alphaRho2.setSize(nCells);
    }
    start_.rho.setSize(nCells); start_.rhoU.setSize(nCells); start_.rhoE.setSize(nCells);
    residual_.rho.setSize(nCells); residual_.rhoU.setSize(nCells); residual_.rhoE.setSize(nCells);

    if (programmedBurn::present(mesh))
    {
        if (!state_.multiPhase() || !state_.mixture().canBurn())
        {
            FatalIOErrorInFunction(state_.thermoDict())
                << "time " << mesh.time().timeName() << " has a lightingTime"
                << " field (programmed burn, setCharge) but entry 'materials'"
                << " " << state_.mixture().materials()
                << " has no explosive with an"
                << " unreacted state: two materials, the first a JWL with an"
                << " explosive preset or an 'unreacted' dictionary"
                << exit(FatalIOError);
        }
        burn_.reset(new programmedBurn(mesh));
        updateBurn(mesh.time().value());
    }

    state_.initialise(lowOrder_.primitiveFieldRef(), burnCells());

    if
    (
        IOstream::defaultPrecision() < 17
     && mesh.time().writeFormat() == IOstream::ASCII
    )
    {
        WarningInFunction
            << "writePrecision " << IOstream::defaultPrecision()
            << " < 17 with ascii output: a restart will not be bitwise"
            << " exact (use writePrecision 17 or writeFormat binary)" << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::blastFluidSolver::maxDeltaT(const scalar maxCo) const
{
    const vectorField& U = state_.U().primitiveField();
    const scalarField& c = state_.c();
    // Cut cells: a cell without gas keeps the state it closed with (that
    // of a sliver compressed to nothing, up to 1e17 Pa) and exchanges
    // nothing; it must not set the step (it did: 3e-10 s instead of 3e-8 s
    // in the fragmenting copper tube)
    const scalarField* phi =
        cutCells_ ? &fluidFractionPtr_->primitiveField() : nullptr;
    const scalar lambda = gasCellsMax
    (
        phi, 0,
        [&](const label i) { return (mag(U[i]) + c[i])*addr_.CoGeom()[i]; }
    );
    return maxCo/max(lambda, VSMALL);
}


void Foam::blastFluidSolver::prepareRetry
(
    const label attempt,
    const label maxAttempts
)
{
    // Non-physical state: restart the step from its initial state with
    // first-order reconstruction around the bad cells (grown twice, then
    // everywhere)
    ++nRetries_;
    anyLowOrder_ = true;
    state_.restoreConservative(start_);
    if (attempt + 2 < maxAttempts)
    {
        growLowOrder();
        growLowOrder();
    }
    else
    {
        lowOrder_.primitiveFieldRef() = 1;
        lowOrder_.correctBoundaryConditions();
    }
    state_.invalidate();
    primitivesFromConservative(true);
}


bool Foam::blastFluidSolver::advance(const scalar dt, const bool mayFail)
{
    if (burn_.valid())
    {
        // The equation of state of the whole step: burn fractions at its
        // end (the present time), as the state written at that time and
        // read by a restart: restarts stay bitwise
        updateBurn(mesh_.time().value());
    }
    if (cutCells_)
    {
        return advanceCutCells(dt, mayFail);
    }
    state_.saveConservative(start_);

    lowOrder_.primitiveFieldRef() = 0;
    anyLowOrder_ = false;
    const label maxAttempts = 4;
    for (label attempt = 0; attempt < maxAttempts; ++attempt)
    {
        bool ok = true;
        for (label s = 0; s < rk_->nStages() && ok; ++s)
        {
            ok = stage(s, dt);
        }
        if (ok && primitivesFromConservative(false))
        {
            outMass_ += stepOutMass_;
            outEnergy_ += stepOutEnergy_;
            if (attempt > 0)
            {
                Info<< "blastFluidSolver: step to " << mesh_.time().timeName()
                    << " needed first-order reconstruction in "
                    << returnReduce(label(sum(lowOrder_.primitiveField())), sumOp<label>())
                    << " cells" << endl;
            }
            return true;
        }

        if (attempt == maxAttempts - 1)
        {
            break;
        }

        prepareRetry(attempt, maxAttempts);
    }

    // First order everywhere failed as well: stop naming time and cell
    primitivesFromConservative(true);
    return false;
}


Foam::scalar Foam::blastFluidSolver::gasTotal(const scalarField& q) const
{
    // sum q V phi, in the order of gSum(q*V*phi) (the budget's figures
    // unchanged) without the temporaries (called every step)
    const scalarField& V = mesh_.V();
    scalar s = 0;
    if (fluidFractionPtr_.valid())
    {
        const scalarField& phi = fluidFractionPtr_->primitiveField();
        forAll(q, i) s += q[i]*V[i]*phi[i];
    }
    else
    {
        forAll(q, i) s += q[i]*V[i];
    }
    return returnReduce(s, sumOp<scalar>());
}


Foam::scalar Foam::blastFluidSolver::totalMass() const
{
    return gasTotal(state_.rho().primitiveField());
}


Foam::scalar Foam::blastFluidSolver::totalEnergy() const
{
    return gasTotal(state_.rhoE().primitiveField());
}


Foam::vector Foam::blastFluidSolver::totalMomentum() const
{
    // In the order of gSum(rhoU*(V*phi))
    const vectorField& rhoU = state_.rhoU().primitiveField();
    const scalarField& V = mesh_.V();
    vector s = Zero;
    if (fluidFractionPtr_.valid())
    {
        const scalarField& phi = fluidFractionPtr_->primitiveField();
        forAll(rhoU, i) s += rhoU[i]*(V[i]*phi[i]);
    }
    else
    {
        forAll(rhoU, i) s += rhoU[i]*V[i];
    }
    return returnReduce(s, sumOp<vector>());
}


Foam::scalar Foam::blastFluidSolver::maxPressure() const
{
    // Cells without gas (cut cells) keep a frozen state: not gas
    const scalarField& p = state_.p().primitiveField();
    return gasCellsMax
    (
        fluidFractionPtr_.valid()
      ? &fluidFractionPtr_->primitiveField() : nullptr,
        -GREAT, [&](const label i) { return p[i]; }
    );
}


Foam::scalar Foam::blastFluidSolver::minPressure() const
{
    const tmp<scalarField> phi = fluidFraction();
    const scalarField& p = state_.p().primitiveField();
    return -gasCellsMax(&phi(), -GREAT, [&](const label i) { return -p[i]; });
}


Foam::scalar Foam::blastFluidSolver::minDensity() const
{
    const tmp<scalarField> phi = fluidFraction();
    const scalarField& rho = state_.rho().primitiveField();
    return -gasCellsMax(&phi(), -GREAT, [&](const label i) { return -rho[i]; });
}


void Foam::blastFluidSolver::report(Ostream& os) const
{
    os  << "blastFluidSolver: " << state_.mixture().size() << " material(s) "
        << state_.mixture().materials() << nl
        << "    flux " << fluidDict_.getOrDefault<word>("flux", "HLLC")
        << ", limiter " << reconstruction_->limiter().type()
        << ", SSP RK" << rk_->order()
        << ", Q-scheme " << (QActive_ ? "on" : "off");
    if (QActive_)
    {
        os  << " (CQ " << CQ_ << ", CL " << CL_ << ")";
    }
    os  << nl;
    forAll(state_.mixture().materials(), i)
    {
        os  << "    ";
        state_.mixture().eos(i).write(os);
    }
    if (burn_.valid())
    {
        const scalarField& tau = burn_->burnTime().primitiveField();
        const scalarField& tb = burn_->lightingTime().primitiveField();
        label nBurn = 0;
        scalar t0 = GREAT, t1 = -GREAT;
        forAll(tau, i)
        {
            if (tau[i] > 0)
            {
                ++nBurn; t0 = min(t0, tb[i]); t1 = max(t1, tb[i]);
            }
        }
        os  << "    programmed burn: " << returnReduce(nBurn, sumOp<label>())
            << " cells lit from " << returnReduce(t0, minOp<scalar>())
            << " s to " << returnReduce(t1, maxOp<scalar>()) << " s" << nl;
    }
    forAll(addr_.kinds(), patchi)
    {
        static const char* kinds[] =
            {"coupled", "reflective", "ghost", "-", "wedge"};
        if (addr_.kinds()[patchi] != blastFaceAddressing::SKIP)
        {
            os  << "    patch " << mesh_.boundary()[patchi].name() << ": "
                << kinds[addr_.kinds()[patchi]] << nl;
        }
    }
    os  << endl;
}


// ************************************************************************* //

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


    //- Stop unless every value of the field read from its file (cells and,
    //  unless !patches, patch faces: a written restart state has patch
    //  values the solver does not use) lies in [lower, upper] (lowerOpen:
    //  (lower, upper]),
    //  naming the file, the entry and the cell or face. Called before the
    //  equation of state sees the values.
    void checkFieldRange
    (
        const Foam::volScalarField& f,
        const Foam::scalar lower,
        const bool lowerOpen,
        const Foam::scalar upper,
        const char* what,
        const bool patches = true
    )
    {
        using namespace Foam;
        auto ok = [&](const scalar v)
        {
            return (lowerOpen ? v > lower : v >= lower) && v <= upper;
        };
        const std::string range
        (
            upper < GREAT
          ? (lowerOpen ? "in (" : "in [") + name(lower) + ", "
            + name(upper) + "]"
          : (lowerOpen ? "> " : ">= ") + name(lower)
        );

        label bad = -1;
        const scalarField& vf = f.primitiveField();
        forAll(vf, i)
        {
            if (!ok(vf[i])) { bad = i; break; }
        }
        if (bad >= 0)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__, f.objectPath(), -1, -1
            )
                << "entry 'internalField': " << f.name() << " = "
                << vf[bad] << " in cell " << bad << " (centre "
                << f.mesh().C()[bad] << "); " << what << " must be "
                << range.c_str() << exit(FatalIOError);
        }
        forAll(f.boundaryField(), patchi)
        {
            if (!patches) break;
            const fvPatchScalarField& pf = f.boundaryField()[patchi];
            forAll(pf, j)
            {
                if (!ok(pf[j]))
                {
                    FatalIOError
                    (
                        FUNCTION_NAME, __FILE__, __LINE__, f.objectPath(),
                        -1, -1
                    )
                        << "entry 'boundaryField." << pf.patch().name()
                        << "': " << f.name() << " = " << pf[j]
                        << " on face " << j << " of patch "
                        << pf.patch().name() << "; " << what << " must be "
                        << range.c_str() << exit(FatalIOError);
                }
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
            mesh_, addr_, fluidDict_, threePhase_ ? 3 : multiPhase_ ? 2 : 1
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
    primitivesCurrent_ = false;
}


void Foam::blastFluidSolver::checkReflectivePatches() const
{
    // A mirror state needs conditions that mirror: the scalar fields read
    // from the case on each reflective patch
    typedef List<const volScalarField*> fieldList;
    fieldList fields
    (
        multiPhase_
      ? fieldList({&p_, alpha1Ptr_.get(), rho1Ptr_.get(), rho2Ptr_.get()})
      : fieldList({&p_, &rho_})
    );
    if (threePhase_)
    {
        fields.append(alpha2Ptr_.get());
        fields.append(rho3Ptr_.get());
    }
    const fvBoundaryMesh& bm = mesh_.boundary();
    forAll(bm, patchi)
    {
        if (addr_.kinds()[patchi] == blastFaceAddressing::REFLECTIVE)
        {
            checkReflectiveConditions(bm[patchi], U_, fields);
        }
    }
}


void Foam::blastFluidSolver::conservativeFromPrimitive()
{
    const label n = mesh_.nCells();
    scalarField& rho = rho_.primitiveFieldRef();
    const vectorField& U = U_.primitiveField();
    const scalarField& p = p_.primitiveField();

    // The initial fields as read, before any EOS evaluation (a negative
    // density or pressure could trap in the EOS)
    checkFieldRange(p_, 0, true, GREAT, "the pressure");

    if (threePhase_)
    {
        conservativeFromPrimitive3();
    }
    else if (multiPhase_)
    {
        scalarField& alpha = alpha1Ptr_->primitiveFieldRef();
        const scalarField& r1 = rho1Ptr_->primitiveField();
        const scalarField& r2 = rho2Ptr_->primitiveField();
        checkFieldRange(alpha1Ptr_(), 0, false, 1, "a volume fraction");
        checkFieldRange(rho1Ptr_(), 0, true, GREAT, "a phase density");
        checkFieldRange(rho2Ptr_(), 0, true, GREAT, "a phase density");
        scalarField& ar1 = alphaRho1Ptr_->primitiveFieldRef();
        for (label i = 0; i < n; ++i)
        {
            rho[i] = alpha[i]*r1[i] + (1 - alpha[i])*r2[i];
            ar1[i] = alpha[i]*r1[i];
        }
        mixture_.rhoeC2(n, alpha, r1, r2, rho, p, rhoe_, c_, burnCells());
    }
    else
    {
        checkFieldRange(rho_, 0, true, GREAT, "the density");
        mixture_.rhoeC2(n, rho, rho, rho, rho, p, rhoe_, c_);
    }

    vectorField& rhoU = rhoU_.primitiveFieldRef();
    scalarField& rhoE = rhoE_.primitiveFieldRef();
    for (label i = 0; i < n; ++i)
    {
        rhoU[i] = rho[i]*U[i];
        rhoE[i] = rhoe_[i] + 0.5*rho[i]*magSqr(U[i]);
    }
}


void Foam::blastFluidSolver::checkRestartState()
{
    // The cells only: patch values of a written state are not used (alpha
    // and alphaRho are clamped to their range as in any step)
    checkFieldRange(rho_, 0, true, GREAT, "the density", false);
    // A written state was an accepted one: its cells at the cavitation
    // cut-off are the flow's (as in the run through, so restarts stay
    // bitwise)
    cavitated_ = true;
    if (primitivesFromConservative(false))
    {
        return;
    }
    const scalarField& p = p_.primitiveField();
    label bad = 0;
    forAll(p, i)
    {
        if (!std::isfinite(p[i]) || !(p[i] > 0) || !(c_[i] > 0))
        {
            bad = i;
            break;
        }
    }
    FatalIOError
    (
        FUNCTION_NAME, __FILE__, __LINE__, rhoE_.objectPath(), -1, -1
    )
        << "entry 'internalField' of " << rho_.objectPath() << ", "
        << rhoU_.objectPath() << " and " << rhoE_.objectPath()
        << ": the state read for the restart is non-physical in cell "
        << bad << " (centre " << mesh_.C()[bad] << "): rho = "
        << rho_[bad] << ", rhoU = " << rhoU_[bad] << ", rhoE = "
        << rhoE_[bad] << " give p = " << p[bad] << exit(FatalIOError);
}


namespace
{
    // The per-cell steps of primitivesFromConservative and
    // primitivesOfCells (one definition for both)

    // Floors so that a vanishing phase or density stays finite
    const Foam::scalar rhoFloor = 1e-12;
    const Foam::scalar alphaEps = 1e-12;

    // U and rhoe of a cell from its conservative state, screened before
    // any operation that could trap (FOAM_SIGFPE): a bad state gets a
    // harmless placeholder and false
    inline bool velocityAndEnergy
    (
        const Foam::scalar rho, const Foam::vector& m, const Foam::scalar rhoE,
        Foam::vector& U, Foam::scalar& rhoe
    )
    {
        if
        (
            rho > 0 && std::isfinite(rho) && std::isfinite(rhoE)
         && std::isfinite(m.x()) && std::isfinite(m.y())
         && std::isfinite(m.z())
        )
        {
            U = m/rho;
            rhoe = rhoE - 0.5*(m & U);
            return true;
        }
        U = Foam::Zero;
        rhoe = 1;
        return false;
    }

    // Phase densities of a two-material cell (alpha clipped to [0, 1])
    inline void phaseDensities
    (
        const Foam::scalar rho, const Foam::scalar ar1,
        Foam::scalar& alpha, Foam::scalar& r1, Foam::scalar& r2
    )
    {
        using Foam::min;
        using Foam::max;
        const Foam::scalar a = min(max(alpha, Foam::scalar(0)), Foam::scalar(1));
        alpha = a;
        const Foam::scalar rhoi = max(rho, rhoFloor);
        const Foam::scalar m1 = min(max(ar1, Foam::scalar(0)), rhoi);
        r1 = max(m1/max(a, alphaEps), rhoFloor);
        r2 = max((rhoi - m1)/max(1 - a, alphaEps), rhoFloor);
    }

    // Phase densities of a three-material cell: alpha1, alpha2 clipped to
    // [0, 1] and scaled to a sum of at most 1; the partial densities
    // clipped to [0, rho]
    inline void phaseDensities3
    (
        const Foam::scalar rho, const Foam::scalar ar1,
        const Foam::scalar ar2,
        Foam::scalar& alpha1, Foam::scalar& alpha2,
        Foam::scalar& r1, Foam::scalar& r2, Foam::scalar& r3
    )
    {
        using Foam::min;
        using Foam::max;
        const Foam::scalar zero = 0, one = 1;
        Foam::scalar a1 = min(max(alpha1, zero), one);
        Foam::scalar a2 = min(max(alpha2, zero), one);
        if (a1 + a2 > 1)
        {
            const Foam::scalar s = a1 + a2;
            a1 /= s;
            a2 /= s;
        }
        alpha1 = a1;
        alpha2 = a2;
        const Foam::scalar rhoi = max(rho, rhoFloor);
        const Foam::scalar m1 = min(max(ar1, zero), rhoi);
        const Foam::scalar m2 = min(max(ar2, zero), rhoi - m1);
        r1 = max(m1/max(a1, alphaEps), rhoFloor);
        r2 = max(m2/max(a2, alphaEps), rhoFloor);
        r3 = max((rhoi - m1 - m2)/max(1 - a1 - a2, alphaEps), rhoFloor);
    }

    // The sound speed from c^2 where the state is physical (else 0 and
    // false)
    inline bool soundSpeed
    (
        const Foam::scalar rho, const Foam::scalar p, const Foam::scalar c2,
        const Foam::scalar rhoE, const Foam::vector& rhoU, Foam::scalar& c
    )
    {
        if
        (
            !(rho > 0) || !(p > 0) || !(c2 > 0)
         || !std::isfinite(p) || !std::isfinite(c2)
         || !std::isfinite(rhoE) || !std::isfinite(Foam::magSqr(rhoU))
        )
        {
            c = 0;
            return false;
        }
        c = Foam::sqrt(c2);
        return true;
    }
}


Foam::blastFluidSolver::phaseFields3::phaseFields3(blastFluidSolver& s)
:
    alpha1(s.alpha1Ptr_->primitiveFieldRef()),
    alpha2(s.alpha2Ptr_->primitiveFieldRef()),
    ar1(s.alphaRho1Ptr_->primitiveField()),
    ar2(s.alphaRho2Ptr_->primitiveField()),
    r1(s.rho1Ptr_->primitiveFieldRef()),
    r2(s.rho2Ptr_->primitiveFieldRef()),
    r3(s.rho3Ptr_->primitiveFieldRef())
{}


void Foam::blastFluidSolver::phaseFields3::phaseDensities
(
    const label i,
    const scalar rho
) const
{
    phaseDensities3
    (
        rho, ar1[i], ar2[i], alpha1[i], alpha2[i], r1[i], r2[i], r3[i]
    );
}


bool Foam::blastFluidSolver::primitivesFromConservative(const bool fatal)
{
    const label n = mesh_.nCells();
    const scalarField& rho = rho_.primitiveField();
    const vectorField& rhoU = rhoU_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    vectorField& U = U_.primitiveFieldRef();
    scalarField& p = p_.primitiveFieldRef();
    scalarField& e = e_.primitiveFieldRef();

    // Screen the conservative state before any operation that could trap
    // (FOAM_SIGFPE): a bad cell gets a harmless placeholder and is reported
    label bad = -1;
    for (label i = 0; i < n; ++i)
    {
        if (!velocityAndEnergy(rho[i], rhoU[i], rhoE[i], U[i], rhoe_[i]))
        {
            if (bad < 0) bad = i;
        }
    }

    if (threePhase_)
    {
        const phaseFields3 f(*this);
        for (label i = 0; i < n; ++i)
        {
            f.phaseDensities(i, rho[i]);
        }
        mixture_.pc2
        (
            n, f.alpha1, f.alpha2, f.r1, f.r2, f.r3, rho, rhoe_, p, c_,
            burnCells(), pEOS()
        );
    }
    else if (multiPhase_)
    {
        scalarField& alpha = alpha1Ptr_->primitiveFieldRef();
        const scalarField& ar1 = alphaRho1Ptr_->primitiveField();
        scalarField& r1 = rho1Ptr_->primitiveFieldRef();
        scalarField& r2 = rho2Ptr_->primitiveFieldRef();
        for (label i = 0; i < n; ++i)
        {
            phaseDensities(rho[i], ar1[i], alpha[i], r1[i], r2[i]);
        }
        mixture_.pc2
        (
            n, alpha, r1, r2, rho, rhoe_, p, c_, burnCells(), pEOS()
        );
    }
    else
    {
        forAll(rhoSafe_, i)
        {
            rhoSafe_[i] = max(rho[i], rhoFloor);
        }
        mixture_.pc2
        (
            n, rhoSafe_, rhoSafe_, rhoSafe_, rhoSafe_, rhoe_, p, c_,
            nullptr, pEOS()
        );
    }

    // Check and take the square root of c^2
    for (label i = 0; i < n; ++i)
    {
        if (!soundSpeed(rho[i], p[i], c_[i], rhoE[i], rhoU[i], c_[i]))
        {
            if (bad < 0) bad = i;
        }
        e[i] = rhoe_[i]/max(rho[i], VSMALL);
    }

    // Cavitation: tension the old check would have retried (p_EOS <= 0)
    // is retried unless the flow put it there (the cell was cut off in
    // the last accepted state) or the cell is first order already; so a
    // run whose retries remove every tension stays bit for bit the same
    const scalarField& lo0 = lowOrder_.primitiveField();
    const auto unexpectedTension = [&](const label i)
    {
        return
            !fatal && pEOS_.size() && !(pEOS_[i] > 0) && !cavitated_[i]
         && !(lo0[i] > 0);
    };
    label firstTension = -1;
    if (!fatal && pEOS_.size())
    {
        for (label i = 0; i < n && firstTension < 0; ++i)
        {
            if (unexpectedTension(i)) firstTension = i;
        }
    }

    if (!fatal)
    {
        if (returnReduce(bad >= 0 || firstTension >= 0, orOp<bool>()))
        {
            // Mark every bad cell for a first-order retry
            scalarField& lo = lowOrder_.primitiveFieldRef();
            const label first =
                bad < 0 ? firstTension
              : firstTension < 0 ? bad
              : min(bad, firstTension);
            for (label i = max(first, label(0)); i < n; ++i)
            {
                if
                (
                    !(rho[i] > 0) || !(p[i] > 0) || !(c_[i] > 0)
                 || !std::isfinite(p[i]) || unexpectedTension(i)
                )
                {
                    lo[i] = 1;
                }
            }
            primitivesCurrent_ = false;
            return false;
        }
    }
    if (returnReduce(bad >= 0, orOp<bool>()))
    {
        stopOnBadCell(bad);
    }
    const scalar pCav = mixture_.cavitationPressure();
    forAll(cavitated_, i)
    {
        cavitated_[i] = pEOS_[i] < pCav;
    }

    correctPrimitiveBoundaries();

    primitivesCurrent_ = true;
    return true;
}


void Foam::blastFluidSolver::primitivesOfCells(const labelUList& cells)
{
    // primitivesFromConservative(true) for these cells only, the same
    // per-cell steps (the equation of state on the gathered cells), so
    // that every primitive is what the whole-mesh call would give: the
    // caller knows the other cells' primitives are current
    const label m = cells.size();
    const scalarField& rho = rho_.primitiveField();
    const vectorField& rhoU = rhoU_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    vectorField& U = U_.primitiveFieldRef();
    scalarField& p = p_.primitiveFieldRef();
    scalarField& e = e_.primitiveFieldRef();

    // Gathered lists grow only (no allocation once they fit)
    gatheredStates& g = gathered_;
    g.fit(m);

    label bad = -1;
    forAll(cells, k)
    {
        const label i = cells[k];
        if (!velocityAndEnergy(rho[i], rhoU[i], rhoE[i], U[i], rhoe_[i]))
        {
            if (bad < 0) bad = i;
        }
        g.rhoe[k] = rhoe_[i];
    }

    const scalarField* burn = burnCells();
    if (threePhase_)
    {
        const phaseFields3 f(*this);
        forAll(cells, k)
        {
            const label i = cells[k];
            f.phaseDensities(i, rho[i]);
            g.alpha[k] = f.alpha1[i];
            g.alpha2[k] = f.alpha2[i];
            g.r1[k] = f.r1[i];
            g.r2[k] = f.r2[i];
            g.r3[k] = f.r3[i];
            g.rho[k] = rho[i];
            if (burn) g.burn[k] = (*burn)[i];
        }
        mixture_.pc2
        (
            m, g.alpha, g.alpha2, g.r1, g.r2, g.r3, g.rho, g.rhoe, g.p, g.c2,
            burn ? &g.burn : nullptr
        );
    }
    else if (multiPhase_)
    {
        scalarField& alpha = alpha1Ptr_->primitiveFieldRef();
        const scalarField& ar1 = alphaRho1Ptr_->primitiveField();
        scalarField& r1 = rho1Ptr_->primitiveFieldRef();
        scalarField& r2 = rho2Ptr_->primitiveFieldRef();
        forAll(cells, k)
        {
            const label i = cells[k];
            phaseDensities(rho[i], ar1[i], alpha[i], r1[i], r2[i]);
            g.alpha[k] = alpha[i];
            g.r1[k] = r1[i];
            g.r2[k] = r2[i];
            g.rho[k] = rho[i];
            if (burn) g.burn[k] = (*burn)[i];
        }
        mixture_.pc2
        (
            m, g.alpha, g.r1, g.r2, g.rho, g.rhoe, g.p, g.c2,
            burn ? &g.burn : nullptr
        );
    }
    else
    {
        forAll(cells, k)
        {
            const label i = cells[k];
            rhoSafe_[i] = max(rho[i], rhoFloor);
            g.rho[k] = rhoSafe_[i];
        }
        mixture_.pc2(m, g.rho, g.rho, g.rho, g.rho, g.rhoe, g.p, g.c2);
    }

    forAll(cells, k)
    {
        const label i = cells[k];
        p[i] = g.p[k];
        if (!soundSpeed(rho[i], p[i], g.c2[k], rhoE[i], rhoU[i], c_[i]))
        {
            if (bad < 0) bad = i;
        }
        e[i] = rhoe_[i]/max(rho[i], VSMALL);
    }
    if (returnReduce(bad >= 0, orOp<bool>()))
    {
        stopOnBadCell(bad);
    }
    correctPrimitiveBoundaries();
    primitivesCurrent_ = true;
}


void Foam::blastFluidSolver::correctPrimitiveBoundaries()
{
    p_.correctBoundaryConditions();
    U_.correctBoundaryConditions();
    if (multiPhase_)
    {
        alpha1Ptr_->correctBoundaryConditions();
        rho1Ptr_->correctBoundaryConditions();
        rho2Ptr_->correctBoundaryConditions();
        if (threePhase_)
        {
            alpha2Ptr_->correctBoundaryConditions();
            rho3Ptr_->correctBoundaryConditions();
        }
    }
    else
    {
        rho_.correctBoundaryConditions();
    }
}


void Foam::blastFluidSolver::stopOnBadCell(const label bad) const
{
    // Name the first bad cell (of the lowest processor that has one) in
    // the message every rank prints (collective: every rank calls it)
    const scalarField& rho = rho_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    const vectorField& U = U_.primitiveField();
    const scalarField& p = p_.primitiveField();

    List<string> where(Pstream::nProcs());
    if (bad >= 0)
    {
        OStringStream os;
        os.precision(8);
        os  << "cell " << bad;
        if (Pstream::parRun())
        {
            os  << " of processor " << Pstream::myProcNo();
        }
        os  << " (centre " << mesh_.C()[bad] << "): rho = " << rho[bad]
            << ", p = " << p[bad] << ", U = " << U[bad]
            << ", rhoE = " << rhoE[bad];
        where[Pstream::myProcNo()] = os.str();
    }
    Pstream::gatherList(where);
    Pstream::scatterList(where);
    string first;
    forAll(where, proci)
    {
        if (!where[proci].empty())
        {
            first = where[proci];
            break;
        }
    }
    FatalErrorInFunction
        << "Negative or non-finite density/pressure: non-physical"
        << " state at time " << mesh_.time().timeName() << " in "
        << first.c_str() << nl
        << "    Stopping without writing this time; the last written"
        << " time is the last good state." << exit(FatalError);
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
            rho_, U_, p_,
            alpha1Ptr_.get(), rho1Ptr_.get(), rho2Ptr_.get(),
            alpha2Ptr_.get(), rho3Ptr_.get()
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

    if (threePhase_)
    {
        faceThermo3(ph);
    }
    else if (multiPhase_)
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
        mixture_.rhoeC2
        (
            n, s.alphaL, ph.rho1L, ph.rho2L, s.rhoL, s.pL, workE_, workC2_,
            burn_.valid() ? &burnL_ : nullptr
        );
        for (label f = 0; f < n; ++f)
        {
            s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
            s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
        }
        mixture_.rhoeC2
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
        mixture_.rhoeC2(n, s.rhoL, s.rhoL, s.rhoL, s.rhoL, s.pL, workE_, workC2_);
        for (label f = 0; f < n; ++f)
        {
            s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
            s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
        }
        mixture_.rhoeC2(n, s.rhoR, s.rhoR, s.rhoR, s.rhoR, s.pR, workE_, workC2_);
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
    const vectorField& U = U_.primitiveField();
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
        const fvPatchVectorField& Ub = U_.boundaryField()[patchi];
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
    const scalarField& rho = rho_.primitiveField();
    scalarField& q = q_.primitiveFieldRef();
    forAll(q, i)
    {
        const scalar d = divU_[i]/V[i];
        const scalar l = addr_.cellLength()[i];
        q[i] = d < 0 ? rho[i]*l*(CQ_*CQ_*l*d*d - CL_*c_[i]*d) : 0;
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
        const fvPatchVectorField& Ub = U_.boundaryField()[patchi];
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
    if (multiPhase_)
    {
        residual_.alpha = 0;
        residual_.alphaRho1 = 0;
    }
    if (threePhase_)
    {
        residual_.alpha2 = 0;
        residual_.alphaRho2 = 0;
    }
    const scalarField* alphaPtr =
        multiPhase_ ? &alpha1Ptr_->primitiveField() : nullptr;

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

    if (multiPhase_)
    {
        const scalarField& alpha = *alphaPtr;
        for (label f = 0; f < addr_.nInternal(); ++f)
        {
            const label P = addr_.own()[f], N = addr_.nei()[f];
            residual_.alphaRho1[P] -= F_.rhoY1[f];
            residual_.alphaRho1[N] += F_.rhoY1[f];
            // d alpha/dt = -div(alpha u) + alpha div(u)
            residual_.alpha[P] -= F_.alpha[f] - alpha[P]*F_.uS[f];
            residual_.alpha[N] += F_.alpha[f] - alpha[N]*F_.uS[f];
        }
        for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
        {
            const label P = addr_.own()[cf];
            residual_.alphaRho1[P] -= F_.rhoY1[cf];
            residual_.alpha[P] -= F_.alpha[cf] - alpha[P]*F_.uS[cf];
        }
    }
    if (threePhase_)
    {
        addMaterialResidual
        (
            F_.rhoY2, F_.alpha2, alpha2Ptr_->primitiveField(),
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
    if (multiPhase_)
    {
        forAll(V, i)
        {
            residual_.alpha[i] /= V[i];
            residual_.alphaRho1[i] /= V[i];
        }
    }
    if (threePhase_)
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
    if (!primitivesCurrent_ && !primitivesFromConservative(false))
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
    rk.combine(s, dt, start_.rho, rho_.primitiveFieldRef(), residual_.rho);
    rk.combine(s, dt, start_.rhoU, rhoU_.primitiveFieldRef(), residual_.rhoU);
    rk.combine(s, dt, start_.rhoE, rhoE_.primitiveFieldRef(), residual_.rhoE);
    if (multiPhase_)
    {
        combineTracked
        (
            s, dt, start_.alpha, alpha1Ptr_(), residual_.alpha,
            start_.alphaRho1, alphaRho1Ptr_(), residual_.alphaRho1
        );
    }
    if (threePhase_)
    {
        combineTracked
        (
            s, dt, start_.alpha2, alpha2Ptr_(), residual_.alpha2,
            start_.alphaRho2, alphaRho2Ptr_(), residual_.alphaRho2
        );
    }
    primitivesCurrent_ = false;
    return true;
}


Foam::volScalarField* Foam::blastFluidSolver::readPrimitive
(
    const word& name
) const
{
    return new volScalarField
    (
        caseChecks::fieldIO(name, mesh_, IOobject::MUST_READ),
        mesh_
    );
}


Foam::volScalarField* Foam::blastFluidSolver::readPartialDensity
(
    const word& material,
    const bool restart
) const
{
    volScalarField* f = new volScalarField
    (
        caseChecks::fieldIO
        (
            "alphaRho." + material, mesh_, IOobject::READ_IF_PRESENT
        ),
        mesh_,
        dimensionedScalar(dimDensity, Zero),
        "calculated"
    );
    if (restart && !f->headerOk())
    {
        FatalErrorInFunction
            << "Restart from time " << mesh_.time().timeName()
            << ": rhoE present but alphaRho." << material << " missing (no"
            << " file " << f->objectPath() << " with a valid"
            << " FoamFile header)" << exit(FatalError);
    }
    return f;
}


void Foam::blastFluidSolver::conservativeFromPrimitive3()
{
    const label n = mesh_.nCells();
    scalarField& rho = rho_.primitiveFieldRef();
    const scalarField& p = p_.primitiveField();
    scalarField& alpha1 = alpha1Ptr_->primitiveFieldRef();
    scalarField& alpha2 = alpha2Ptr_->primitiveFieldRef();
    const scalarField& r1 = rho1Ptr_->primitiveField();
    const scalarField& r2 = rho2Ptr_->primitiveField();
    const scalarField& r3 = rho3Ptr_->primitiveField();
    checkFieldRange(alpha1Ptr_(), 0, false, 1, "a volume fraction");
    checkFieldRange(alpha2Ptr_(), 0, false, 1, "a volume fraction");
    checkFieldRange(rho1Ptr_(), 0, true, GREAT, "a phase density");
    checkFieldRange(rho2Ptr_(), 0, true, GREAT, "a phase density");
    checkFieldRange(rho3Ptr_(), 0, true, GREAT, "a phase density");
    for (label i = 0; i < n; ++i)
    {
        if (alpha1[i] + alpha2[i] > 1 + 1e-12)
        {
            FatalIOError
            (
                FUNCTION_NAME, __FILE__, __LINE__,
                alpha2Ptr_->objectPath(), -1, -1
            )
                << "entry 'internalField' of " << alpha1Ptr_->objectPath()
                << " and " << alpha2Ptr_->objectPath() << ": alpha."
                << mixture_.materials()[0] << " + alpha."
                << mixture_.materials()[1] << " = "
                << alpha1[i] + alpha2[i] << " > 1 in cell " << i
                << " (centre " << mesh_.C()[i] << ")" << exit(FatalIOError);
        }
    }
    scalarField& ar1 = alphaRho1Ptr_->primitiveFieldRef();
    scalarField& ar2 = alphaRho2Ptr_->primitiveFieldRef();
    for (label i = 0; i < n; ++i)
    {
        ar1[i] = alpha1[i]*r1[i];
        ar2[i] = alpha2[i]*r2[i];
        rho[i] = ar1[i] + ar2[i] + max(1 - alpha1[i] - alpha2[i], 0.0)*r3[i];
    }
    mixture_.rhoeC2
    (
        n, alpha1, alpha2, r1, r2, r3, rho, p, rhoe_, c_, burnCells()
    );
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
    mixture_.rhoeC2
    (
        n, s.alphaL, s.alpha2L, ph.rho1L, ph.rho2L, ph.rho3L, s.rhoL, s.pL,
        workE_, workC2_, burn_.valid() ? &burnL_ : nullptr
    );
    for (label f = 0; f < n; ++f)
    {
        s.EL[f] = workE_[f] + 0.5*s.rhoL[f]*magSqr(s.UL[f]);
        s.cL[f] = sqrt(max(workC2_[f], scalar(0)));
    }
    mixture_.rhoeC2
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
    thermoDict_
    (
        IOobject
        (
            "thermophysicalProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
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
    mixture_(thermoDict_),
    multiPhase_(mixture_.multiPhase()),
    threePhase_(mixture_.threePhase()),
    flux_(fluxScheme::New(fluidDict_)),
    QActive_(false),
    CQ_(1.5),
    CL_(0.06),
    p_(caseChecks::fieldIO("p", mesh, IOobject::MUST_READ), mesh),
    U_(caseChecks::fieldIO("U", mesh, IOobject::MUST_READ), mesh),
    e_
    (
        caseChecks::fieldIO("e", mesh, IOobject::NO_READ),
        mesh,
        dimensionedScalar(dimEnergy/dimMass, Zero),
        "calculated"
    ),
    rho_
    (
        caseChecks::fieldIO("rho", mesh, IOobject::READ_IF_PRESENT),
        mesh,
        dimensionedScalar(dimDensity, Zero),
        "calculated"
    ),
    rhoU_
    (
        caseChecks::fieldIO("rhoU", mesh, IOobject::READ_IF_PRESENT),
        mesh,
        dimensionedVector(dimDensity*dimVelocity, Zero),
        "calculated"
    ),
    rhoE_
    (
        caseChecks::fieldIO("rhoE", mesh, IOobject::READ_IF_PRESENT),
        mesh,
        dimensionedScalar(dimEnergy/dimVolume, Zero),
        "calculated"
    ),
    c_(mesh.nCells(), 0),
    rhoe_(mesh.nCells(), 0),
    rhoSafe_(mesh.nCells(), 1),
    pEOS_(mixture_.cavitation() ? mesh.nCells() : 0, 0),
    cavitated_(mixture_.cavitation() ? mesh.nCells() : 0, false),
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
    addr_(mesh, U_),
    cutCells_(false),
    stepOutMass_(0),
    stepOutEnergy_(0),
    outMass_(0),
    outEnergy_(0),
    spreadEnergy_(0),
    primitivesCurrent_(false)
{
    readControls();

    const label nCells = mesh.nCells();
    const bool restart =
        IOobject("rhoE", mesh.time().timeName(), mesh, IOobject::MUST_READ)
       .typeHeaderOk<volScalarField>(true);

    if (multiPhase_)
    {
        const word& m1 = mixture_.materials()[0];
        const word& m2 = mixture_.materials()[1];
        // Materials listed in the other order than the fields (e.g.
        // setCharge's products first): name the entry, not the missing file
        if
        (
            !caseChecks::fieldIO("alpha." + m1, mesh, IOobject::MUST_READ)
                .typeHeaderOk<volScalarField>(true)
         && caseChecks::fieldIO("alpha." + m2, mesh, IOobject::MUST_READ)
                .typeHeaderOk<volScalarField>(true)
        )
        {
            FatalErrorInFunction
                << "constant/thermophysicalProperties: entry 'materials' ("
                << m1 << ' ' << m2 << "): the volume fraction of the first"
                << " material, " << mesh.time().timeName() << "/alpha." << m1
                << ", is missing but alpha." << m2 << " exists: list the"
                << " materials in the order of the fields (" << m2 << ' '
                << m1 << ")" << exit(FatalError);
        }
        alpha1Ptr_.reset(readPrimitive("alpha." + m1));
        rho1Ptr_.reset(readPrimitive("rho." + m1));
        rho2Ptr_.reset(readPrimitive("rho." + m2));
        alphaRho1Ptr_.reset(readPartialDensity(m1, restart));
        if (threePhase_)
        {
            alpha2Ptr_.reset(readPrimitive("alpha." + m2));
            rho3Ptr_.reset(readPrimitive("rho." + mixture_.materials()[2]));
            alphaRho2Ptr_.reset(readPartialDensity(m2, restart));
        }
    }
    else if (!rho_.headerOk())
    {
        FatalErrorInFunction
            << "Single-material case (one material in entry 'materials' of "
            << thermoDict_.objectPath() << "): field 'rho' missing in time "
            << mesh.time().timeName() << " (no file "
            << rho_.objectPath() << " with a valid FoamFile header)"
            << exit(FatalError);
    }

    if (restart && !rhoU_.headerOk())
    {
        FatalErrorInFunction
            << "Restart from time " << mesh.time().timeName()
            << ": rhoE present but rhoU missing (no file "
            << rhoU_.objectPath() << " with a valid FoamFile header)"
            << exit(FatalError);
    }

    checkReflectivePatches();

    faces_.setSize(addr_.nFaces(), nTracked());
    F_.setSize(addr_.nFaces(), nTracked());
    workE_.setSize(addr_.nFaces(), 0);
    workC2_.setSize(addr_.nFaces(), 0);
    if (multiPhase_)
    {
        start_.alpha.setSize(nCells); start_.alphaRho1.setSize(nCells);
        residual_.alpha.setSize(nCells); residual_.alphaRho1.setSize(nCells);
    }
    if (threePhase_)
    {
        start_.alpha2.setSize(nCells); start_.alphaRho2.setSize(nCells);
        residual_.alpha2.setSize(nCells); residual_.alphaRho2.setSize(nCells);
    }
    start_.rho.setSize(nCells); start_.rhoU.setSize(nCells); start_.rhoE.setSize(nCells);
    residual_.rho.setSize(nCells); residual_.rhoU.setSize(nCells); residual_.rhoE.setSize(nCells);

    if (programmedBurn::present(mesh))
    {
        if (!multiPhase_ || !mixture_.canBurn())
        {
            FatalIOErrorInFunction(thermoDict_)
                << "time " << mesh.time().timeName() << " has a lightingTime"
                << " field (programmed burn, setCharge) but entry 'materials'"
                << " " << mixture_.materials() << " has no explosive with an"
                << " unreacted state: two materials, the first a JWL with an"
                << " explosive preset or an 'unreacted' dictionary"
                << exit(FatalIOError);
        }
        burn_.reset(new programmedBurn(mesh));
        updateBurn(mesh.time().value());
    }

    caseChecks::checkDimensions(p_, dimPressure);
    caseChecks::checkDimensions(U_, dimVelocity);
    caseChecks::checkDimensions(rho_, dimDensity);
    caseChecks::checkDimensions(rhoU_, dimDensity*dimVelocity);
    caseChecks::checkDimensions(rhoE_, dimEnergy/dimVolume);
    if (multiPhase_)
    {
        caseChecks::checkDimensions(alpha1Ptr_(), dimless);
        caseChecks::checkDimensions(rho1Ptr_(), dimDensity);
        caseChecks::checkDimensions(rho2Ptr_(), dimDensity);
        caseChecks::checkDimensions(alphaRho1Ptr_(), dimDensity);
    }
    if (threePhase_)
    {
        caseChecks::checkDimensions(alpha2Ptr_(), dimless);
        caseChecks::checkDimensions(rho3Ptr_(), dimDensity);
        caseChecks::checkDimensions(alphaRho2Ptr_(), dimDensity);
    }

    if (restart)
    {
        Info<< "blastFluidSolver: restart from the conservative state of time "
            << mesh.time().timeName() << endl;
        checkRestartState();
    }
    else
    {
        if (multiPhase_)
        {
            alpha1Ptr_->correctBoundaryConditions();
        }
        if (threePhase_)
        {
            alpha2Ptr_->correctBoundaryConditions();
        }
        conservativeFromPrimitive();
    }
    primitivesFromConservative();

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
    const vectorField& U = U_.primitiveField();
    // Cut cells: a cell without gas keeps the state it closed with (that
    // of a sliver compressed to nothing, up to 1e17 Pa) and exchanges
    // nothing; it must not set the step (it did: 3e-10 s instead of 3e-8 s
    // in the fragmenting copper tube)
    const scalarField* phi =
        cutCells_ ? &fluidFractionPtr_->primitiveField() : nullptr;
    const scalar lambda = gasCellsMax
    (
        phi, 0, [&](const label i) { return (mag(U[i]) + c_[i])*addr_.CoGeom()[i]; }
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
    rho_.primitiveFieldRef() = start_.rho;
    rhoU_.primitiveFieldRef() = start_.rhoU;
    rhoE_.primitiveFieldRef() = start_.rhoE;
    if (multiPhase_)
    {
        alpha1Ptr_->primitiveFieldRef() = start_.alpha;
        alphaRho1Ptr_->primitiveFieldRef() = start_.alphaRho1;
    }
    if (threePhase_)
    {
        alpha2Ptr_->primitiveFieldRef() = start_.alpha2;
        alphaRho2Ptr_->primitiveFieldRef() = start_.alphaRho2;
    }
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
    primitivesCurrent_ = false;
    primitivesFromConservative(true);
}


void Foam::blastFluidSolver::advance(const scalar dt)
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
        advanceCutCells(dt);
        return;
    }
    start_.rho = rho_.primitiveField();
    start_.rhoU = rhoU_.primitiveField();
    start_.rhoE = rhoE_.primitiveField();
    if (multiPhase_)
    {
        start_.alpha = alpha1Ptr_->primitiveField();
        start_.alphaRho1 = alphaRho1Ptr_->primitiveField();
    }
    if (threePhase_)
    {
        start_.alpha2 = alpha2Ptr_->primitiveField();
        start_.alphaRho2 = alphaRho2Ptr_->primitiveField();
    }

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
            return;
        }

        if (attempt == maxAttempts - 1)
        {
            break;
        }

        prepareRetry(attempt, maxAttempts);
    }

    // First order everywhere failed as well: stop naming time and cell
    primitivesFromConservative(true);
}


Foam::scalar Foam::blastFluidSolver::totalMass() const
{
    return gSum(rho_.primitiveField()*mesh_.V()*fluidFraction());
}


Foam::scalar Foam::blastFluidSolver::totalEnergy() const
{
    return gSum(rhoE_.primitiveField()*mesh_.V()*fluidFraction());
}


Foam::vector Foam::blastFluidSolver::totalMomentum() const
{
    return gSum(rhoU_.primitiveField()*(mesh_.V()*fluidFraction()));
}


Foam::scalar Foam::blastFluidSolver::maxPressure() const
{
    // Cells without gas (cut cells) keep a frozen state: not gas
    const scalarField& p = p_.primitiveField();
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
    const scalarField& p = p_.primitiveField();
    return -gasCellsMax(&phi(), -GREAT, [&](const label i) { return -p[i]; });
}


Foam::scalar Foam::blastFluidSolver::minDensity() const
{
    const tmp<scalarField> phi = fluidFraction();
    const scalarField& rho = rho_.primitiveField();
    return -gasCellsMax(&phi(), -GREAT, [&](const label i) { return -rho[i]; });
}


void Foam::blastFluidSolver::report(Ostream& os) const
{
    os  << "blastFluidSolver: " << mixture_.size() << " material(s) "
        << mixture_.materials() << nl
        << "    flux " << fluidDict_.getOrDefault<word>("flux", "HLLC")
        << ", limiter " << reconstruction_->limiter().type()
        << ", SSP RK" << rk_->order()
        << ", Q-scheme " << (QActive_ ? "on" : "off");
    if (QActive_)
    {
        os  << " (CQ " << CQ_ << ", CL " << CL_ << ")";
    }
    os  << nl;
    forAll(mixture_.materials(), i)
    {
        os  << "    ";
        mixture_.eos(i).write(os);
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

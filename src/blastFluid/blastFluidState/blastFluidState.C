/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastFluidState.H"
#include "OStringStream.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastFluidState::conservativeFromPrimitive
(
    const scalarField* burn
)
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
        conservativeFromPrimitive3(burn);
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
        mixture_.rhoeC2(n, alpha, r1, r2, rho, p, rhoe_, c_, burn);
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


void Foam::blastFluidState::checkRestartState
(
    scalarField& lowOrder,
    const scalarField* burn
)
{
    // The cells only: patch values of a written state are not used (alpha
    // and alphaRho are clamped to their range as in any step)
    checkFieldRange(rho_, 0, true, GREAT, "the density", false);
    // A written state was an accepted one: its cells at the cavitation
    // cut-off are the flow's (as in the run through, so restarts stay
    // bitwise)
    cavitated_ = true;
    // and so are its cells without positive internal energy
    noEnergy_ = true;
    if (primitivesFromConservative(false, lowOrder, burn))
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


Foam::blastFluidState::phaseFields3::phaseFields3(blastFluidState& s)
:
    alpha1(s.alpha1Ptr_->primitiveFieldRef()),
    alpha2(s.alpha2Ptr_->primitiveFieldRef()),
    ar1(s.alphaRho1Ptr_->primitiveField()),
    ar2(s.alphaRho2Ptr_->primitiveField()),
    r1(s.rho1Ptr_->primitiveFieldRef()),
    r2(s.rho2Ptr_->primitiveFieldRef()),
    r3(s.rho3Ptr_->primitiveFieldRef())
{}


void Foam::blastFluidState::phaseFields3::phaseDensities
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


void Foam::blastFluidState::cellsEOS(const scalarField* burn)
{
    const label n = mesh_.nCells();
    const scalarField& rho = rho_.primitiveField();
    scalarField& p = p_.primitiveFieldRef();

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
            burn, pEOS()
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
            n, alpha, r1, r2, rho, rhoe_, p, c_, burn, pEOS()
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
}


bool Foam::blastFluidState::markRetry
(
    const label bad,
    scalarField& lowOrder
) const
{
    const label n = mesh_.nCells();
    const scalarField& rho = rho_.primitiveField();
    const scalarField& p = p_.primitiveField();

    // Cavitation: tension the old check would have retried (p_EOS <= 0)
    // is retried unless the flow put it there (the cell was cut off in
    // the last accepted state) or the cell is first order already; so a
    // run whose retries remove every tension stays bit for bit the same
    const scalarField& lo0 = lowOrder;
    const auto unexpectedTension = [&](const label i)
    {
        return
            pEOS_.size() && !(pEOS_[i] > 0) && !cavitated_[i]
         && !(lo0[i] > 0);
    };
    // Negative internal energy: every material of the library has e > 0
    // in any physical state (ideal gas; JWL and Murnaghan above their cold
    // curves, whose energies are >= 0; stiffened gas above -gamma pInf), but
    // a compressed JWL or Murnaghan cell, or a mixed cell, keeps p > 0 and
    // c^2 > 0 through the cold terms below e = 0. Accepted, such a cell
    // grew (the products' jet between the cylinder's fragments, kinetic
    // energy 1.5 MJ/kg: e = -92 J/kg at 17.3 us, 40 cells down to -2.7e4
    // J/kg a microsecond later, then a stop); it is retried at first order
    // like a tension, unless the cell had no positive internal energy in
    // the last accepted state already (a case's input, or what a
    // first-order step left) or is first order already
    const auto unexpectedEnergy = [&](const label i)
    {
        return
            !(rhoe_[i] > 0) && !(lo0[i] > 0) && !noEnergy_[i]
         && !(cavitated_.size() && cavitated_[i]);
    };
    label firstUnexpected = -1;
    for (label i = 0; i < n && firstUnexpected < 0; ++i)
    {
        if (unexpectedTension(i) || unexpectedEnergy(i)) firstUnexpected = i;
    }

    if (!returnReduce(bad >= 0 || firstUnexpected >= 0, orOp<bool>()))
    {
        return false;
    }
    // Mark every bad cell for a first-order retry
    scalarField& lo = lowOrder;
    const label first =
        bad < 0 ? firstUnexpected
      : firstUnexpected < 0 ? bad
      : min(bad, firstUnexpected);
    for (label i = max(first, label(0)); i < n; ++i)
    {
        if
        (
            !(rho[i] > 0) || !(p[i] > 0) || !(c_[i] > 0)
         || !std::isfinite(p[i]) || unexpectedTension(i)
         || unexpectedEnergy(i)
        )
        {
            lo[i] = 1;
        }
    }
    return true;
}


bool Foam::blastFluidState::primitivesFromConservative
(
    const bool fatal,
    scalarField& lowOrder,
    const scalarField* burn
)
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

    cellsEOS(burn);

    // Check and take the square root of c^2
    for (label i = 0; i < n; ++i)
    {
        if (!soundSpeed(rho[i], p[i], c_[i], rhoE[i], rhoU[i], c_[i]))
        {
            if (bad < 0) bad = i;
        }
        e[i] = rhoe_[i]/max(rho[i], VSMALL);
    }

    if (!fatal && markRetry(bad, lowOrder))
    {
        current_ = false;
        return false;
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
    forAll(noEnergy_, i)
    {
        noEnergy_[i] = !(rhoe_[i] > 0);
    }

    correctBoundaries();

    current_ = true;
    return true;
}


void Foam::blastFluidState::listEOS
(
    const labelUList& cells,
    const scalarField* burn
)
{
    const label m = cells.size();
    const scalarField& rho = rho_.primitiveField();
    gatheredStates& g = gathered_;

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
}


bool Foam::blastFluidState::primitivesOfCells
(
    const labelUList& cells,
    const scalarField* burn,
    const bool fatal
)
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

    listEOS(cells, burn);

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
        if (!fatal)
        {
            current_ = false;
            return false;
        }
        stopOnBadCell(bad);
    }
    correctBoundaries();
    current_ = true;
    return true;
}


void Foam::blastFluidState::correctBoundaries()
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


void Foam::blastFluidState::stopOnBadCell(const label bad) const
{
    // Name the first bad cell (of the lowest processor that has one) in
    // the message every rank prints (collective: every rank calls it)
    const scalarField& rho = rho_.primitiveField();
    const scalarField& rhoE = rhoE_.primitiveField();
    const vectorField& U = U_.primitiveField();
    const scalarField& p = p_.primitiveField();

    // What is wrong with it, in the message's first words: the density,
    // the pressure, or neither (then c^2 <= 0: a state outside the
    // equation of state's range, e.g. JWL products below their cold
    // curve, whose p stays positive)
    List<string> where(Pstream::nProcs());
    if (bad >= 0)
    {
        const scalar r = rho[bad], pb = p[bad];
        OStringStream os;
        os.precision(8);
        os  <<
            (
                !(r > 0) || !std::isfinite(r)
              ? "Negative or non-finite density"
              : !(pb > 0) || !std::isfinite(pb)
              ? "Negative or non-finite pressure"
              : "No sound speed (c^2 <= 0 at positive density and pressure:"
                " outside the equation of state's range, e.g. below its"
                " cold curve)"
            )
            << ": non-physical state at time " << mesh_.time().timeName()
            << " in cell " << bad;
        if (Pstream::parRun())
        {
            os  << " of processor " << Pstream::myProcNo();
        }
        os  << " (centre " << mesh_.C()[bad] << "): rho = " << r
            << ", p = " << pb << ", U = " << U[bad]
            << ", rhoE = " << rhoE[bad];
        if (r > 0 && std::isfinite(r))
        {
            os  << ", e = " << e_[bad];
        }
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
        << first.c_str() << nl
        << "    Stopping without writing this time; the last written"
        << " time is the last good state." << exit(FatalError);
}


Foam::volScalarField* Foam::blastFluidState::readPrimitive
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


Foam::volScalarField* Foam::blastFluidState::readPartialDensity
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


void Foam::blastFluidState::conservativeFromPrimitive3
(
    const scalarField* burn
)
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
        n, alpha1, alpha2, r1, r2, r3, rho, p, rhoe_, c_, burn
    );
}


void Foam::blastFluidState::readFields()
{
    const fvMesh& mesh = mesh_;
    const bool restart = restart_;

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
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastFluidState::blastFluidState(const fvMesh& mesh)
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
    mixture_(thermoDict_),
    multiPhase_(mixture_.multiPhase()),
    threePhase_(mixture_.threePhase()),
    restart_
    (
        IOobject("rhoE", mesh.time().timeName(), mesh, IOobject::MUST_READ)
       .typeHeaderOk<volScalarField>(true)
    ),
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
    noEnergy_(mesh.nCells(), false),
    current_(false)
{
    readFields();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blastFluidState::initialise
(
    scalarField& lowOrder,
    const scalarField* burn
)
{
    if (restart_)
    {
        Info<< "blastFluidSolver: restart from the conservative state of time "
            << mesh_.time().timeName() << endl;
        checkRestartState(lowOrder, burn);
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
        conservativeFromPrimitive(burn);
    }
    primitivesFromConservative(true, lowOrder, burn);
}


void Foam::blastFluidState::saveConservative(conservedFields& c) const
{
    c.rho = rho_.primitiveField();
    c.rhoU = rhoU_.primitiveField();
    c.rhoE = rhoE_.primitiveField();
    if (multiPhase_)
    {
        c.alpha = alpha1Ptr_->primitiveField();
        c.alphaRho1 = alphaRho1Ptr_->primitiveField();
    }
    if (threePhase_)
    {
        c.alpha2 = alpha2Ptr_->primitiveField();
        c.alphaRho2 = alphaRho2Ptr_->primitiveField();
    }
}


void Foam::blastFluidState::restoreConservative(const conservedFields& c)
{
    rho_.primitiveFieldRef() = c.rho;
    rhoU_.primitiveFieldRef() = c.rhoU;
    rhoE_.primitiveFieldRef() = c.rhoE;
    if (multiPhase_)
    {
        alpha1Ptr_->primitiveFieldRef() = c.alpha;
        alphaRho1Ptr_->primitiveFieldRef() = c.alphaRho1;
    }
    if (threePhase_)
    {
        alpha2Ptr_->primitiveFieldRef() = c.alpha2;
        alphaRho2Ptr_->primitiveFieldRef() = c.alphaRho2;
    }
    current_ = false;
}


// ************************************************************************* //

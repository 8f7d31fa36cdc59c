/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    The immersed solid in blastFluidSolver: fluid fraction, face apertures,
    solid surface pressure, absorption and the redistribution of the gas when
    the solid moves (see the class description and doc/theory-coupling.md).

\*---------------------------------------------------------------------------*/

#include "blastFluidSolver.H"
#include "caseChecks.H"
#include "calculatedFvPatchFields.H"

// * * * * * * * * * * * * * * * Gas content  * * * * * * * * * * * * * * * //

//- Gas volume, mass, momentum, energy (and, with two materials, the mass
//  and the volume of material 1) held by each cell
class Foam::blastFluidSolver::gasContent
{
    blastFluidSolver& solver_;

public:

    scalarField volume, mass, energy, mass1, volume1;
    vectorField momentum;

    //- From the intrinsic states and the gas volume fractions they refer to
    gasContent(blastFluidSolver& solver, const scalarField& phi)
    :
        solver_(solver),
        volume(phi*solver.mesh_.V()),
        mass(solver.rho_.primitiveField()*volume),
        energy(solver.rhoE_.primitiveField()*volume),
        momentum(solver.rhoU_.primitiveField()*volume)
    {
        if (solver.twoPhase_)
        {
            mass1 = solver.alphaRho1Ptr_->primitiveField()*volume;
            volume1 = solver.alpha1Ptr_->primitiveField()*volume;
        }
    }

    //- Add v times the gas state (per unit gas volume) given by the
    //  intrinsic values rho, rhoU, rhoE (rho1: partial density, alpha1)
    void add
    (
        const label i, const scalar v, const scalar rho, const vector& rhoU,
        const scalar rhoE, const scalar rho1, const scalar alpha1
    )
    {
        volume[i] += v;
        mass[i] += v*rho;
        momentum[i] += v*rhoU;
        energy[i] += v*rhoE;
        if (solver_.twoPhase_)
        {
            mass1[i] += v*rho1;
            volume1[i] += v*alpha1;
        }
    }

    //- Keep the fraction s of cell i's content
    void scale(const label i, const scalar s)
    {
        volume[i] *= s; mass[i] *= s; momentum[i] *= s; energy[i] *= s;
        if (solver_.twoPhase_)
        {
            mass1[i] *= s; volume1[i] *= s;
        }
    }

    //- Intrinsic states of the cells with gas (fluid fraction phi); solid
    //  cells keep their frozen state
    void toState(const scalarField& phi) const
    {
        const scalarField& V = solver_.mesh_.V();
        scalarField& rho = solver_.rho_.primitiveFieldRef();
        vectorField& rhoU = solver_.rhoU_.primitiveFieldRef();
        scalarField& rhoE = solver_.rhoE_.primitiveFieldRef();
        forAll(phi, i)
        {
            if (phi[i] <= 0) continue;
            const scalar rV = 1/(phi[i]*V[i]);
            rho[i] = mass[i]*rV;
            rhoU[i] = momentum[i]*rV;
            rhoE[i] = energy[i]*rV;
        }
        if (solver_.twoPhase_)
        {
            scalarField& ar1 = solver_.alphaRho1Ptr_->primitiveFieldRef();
            scalarField& alpha = solver_.alpha1Ptr_->primitiveFieldRef();
            forAll(phi, i)
            {
                if (phi[i] <= 0) continue;
                ar1[i] = mass1[i]*(1/(phi[i]*V[i]));
                alpha[i] = volume[i] > 0 ? volume1[i]/volume[i] : 0;
            }
        }
    }
};


template<class Type>
void Foam::blastFluidSolver::coupledNeighbourValues
(
    const GeometricField<Type, fvPatchField, volMesh>& field,
    Field<Type>& values
) const
{
    values.setSize(nFaces_ - nInternal_);
    values = Zero;
    forAll(patchKind_, patchi)
    {
        if (patchKind_[patchi] != COUPLED) continue;
        const tmp<Field<Type>> tnbr =
            field.boundaryField()[patchi].patchNeighbourField();
        const Field<Type>& nbr = tnbr();
        forAll(nbr, j)
        {
            values[patchStart_[patchi] - nInternal_ + j] = nbr[j];
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastFluidSolver::setFaceFluidFraction()
{
    volScalarField& phiVol = fluidFractionPtr_();
    phiVol.correctBoundaryConditions();
    const scalarField& phi = phiVol.primitiveField();

    faceFluidFraction_.setSize(nFaces_);
    for (label f = 0; f < nInternal_; ++f)
    {
        faceFluidFraction_[f] = min(phi[own_[f]], phi[nei_[f]]);
    }
    forAll(patchKind_, patchi)
    {
        if (patchKind_[patchi] == SKIP) continue;
        const label start = patchStart_[patchi];
        const label size = mesh_.boundary()[patchi].size();
        if (patchKind_[patchi] == COUPLED)
        {
            const tmp<scalarField> tnbr =
                phiVol.boundaryField()[patchi].patchNeighbourField();
            const scalarField& nbr = tnbr();
            for (label j = 0; j < size; ++j)
            {
                faceFluidFraction_[start + j] =
                    min(phi[own_[start + j]], nbr[j]);
            }
        }
        else
        {
            for (label j = 0; j < size; ++j)
            {
                faceFluidFraction_[start + j] = phi[own_[start + j]];
            }
        }
    }

    // Wall faces: the closed part of a face, seen from its more open side
    DynamicList<label> gasCell(nFaces_/10 + 1), solidCell(nFaces_/10 + 1);
    DynamicList<label> wallFace(nFaces_/10 + 1);
    DynamicList<vector> area(nFaces_/10 + 1);
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        if (phi[P] > phi[N])
        {
            gasCell.append(P); solidCell.append(N); wallFace.append(f);
            area.append((phi[P] - phi[N])*Sf_[f]);
        }
        else if (phi[N] > phi[P])
        {
            gasCell.append(N); solidCell.append(P); wallFace.append(f);
            area.append((phi[P] - phi[N])*Sf_[f]);
        }
    }
    forAll(patchKind_, patchi)
    {
        if (patchKind_[patchi] != COUPLED) continue;
        const tmp<scalarField> tnbr =
            phiVol.boundaryField()[patchi].patchNeighbourField();
        const scalarField& nbr = tnbr();
        const label start = patchStart_[patchi];
        forAll(nbr, j)
        {
            const label cf = start + j, P = own_[cf];
            if (phi[P] > nbr[j])
            {
                gasCell.append(P); solidCell.append(-1); wallFace.append(cf);
                area.append((phi[P] - nbr[j])*Sf_[cf]);
            }
            else if (nbr[j] > phi[P])
            {
                // Same area vector as computed on the gas side's processor
                gasCell.append(-1); solidCell.append(P); wallFace.append(cf);
                area.append((phi[P] - nbr[j])*Sf_[cf]);
            }
        }
    }
    wallGasCell_.transfer(gasCell);
    wallSolidCell_.transfer(solidCell);
    wallFace_.transfer(wallFace);
    wallArea_.transfer(area);
}


void Foam::blastFluidSolver::scaleFluxes(const scalarField& phif)
{
    for (label f = 0; f < nFaces_; ++f)
    {
        F_.rho[f] *= phif[f];
        F_.rhoU[f] *= phif[f];
        F_.rhoE[f] *= phif[f];
    }
    if (twoPhase_)
    {
        for (label f = 0; f < nFaces_; ++f)
        {
            F_.rhoY1[f] *= phif[f];
            F_.alpha[f] *= phif[f];
            F_.uS[f] *= phif[f];
        }
    }
}


void Foam::blastFluidSolver::addSolidForcing(const scalar a, const scalar dt)
{
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    const scalarField& p = p_.primitiveField();
    const scalarField& V = mesh_.V();
    const scalar b = 1 - a;

    // Pressure of the gas side on faces shared with other processors
    scalarField pNbr;
    coupledNeighbourValues(p_, pNbr);

    // The stage's impulse enters the Runge-Kutta combination like the
    // state does, I <- (1 - a)(I + dt S): I is exactly the step's exchange
    solidImpulse_ *= b;

    forAll(wallFace_, w)
    {
        const label g = wallGasCell_[w], s = wallSolidCell_[w];
        const scalar pGas = g >= 0 ? p[g] : pNbr[wallFace_[w] - nInternal_];
        const vector force = -pGas*wallArea_[w];
        if (g >= 0)
        {
            dRhoU_[g] += force/V[g];
        }
        if (s >= 0)
        {
            solidImpulse_[s] -= b*dt*force;
        }
    }

    // Residual per unit volume of gas; solid cells do not change
    forAll(phi, i)
    {
        const scalar rPhi = phi[i] > 0 ? 1/phi[i] : 0;
        dRho_[i] *= rPhi;
        dRhoU_[i] *= rPhi;
        dRhoE_[i] *= rPhi;
    }
    if (twoPhase_)
    {
        forAll(phi, i)
        {
            const scalar rPhi = phi[i] > 0 ? 1/phi[i] : 0;
            dAlpha_[i] *= rPhi;
            dAlphaRho1_[i] *= rPhi;
        }
    }
}


void Foam::blastFluidSolver::absorbSolidVelocity(const scalar dt)
{
    const scalarField& alphaS = alphaSolidPtr_->primitiveField();
    const scalarField& phi = fluidFractionPtr_->primitiveField();
    const vectorField& Us = UsolidPtr_->primitiveField();
    const scalarField& rho = rho_.primitiveField();
    vectorField& rhoU = rhoU_.primitiveFieldRef();
    scalarField& rhoE = rhoE_.primitiveFieldRef();
    const scalarField& V = mesh_.V();

    forAll(phi, i)
    {
        if (phi[i] <= 0 || alphaS[i] <= 0)
        {
            continue;
        }
        // rho (u1 - u0)/dt = sigma (u_s - u1), sigma dt/rho = beta alpha_s
        const scalar k = absorptionBeta_*alphaS[i];
        const vector u0 = rhoU[i]/rho[i];
        const vector u1 = (u0 + k*Us[i])/(1 + k);
        const vector dRhoU = rho[i]*(u1 - u0);
        rhoU[i] += dRhoU;
        // The solid does work dRhoU . u_s on the gas; the rest of the
        // relative kinetic energy is dissipated into heat in the gas
        const scalar dRhoE = dRhoU & Us[i];
        rhoE[i] += dRhoE;
        solidImpulse_[i] -= phi[i]*V[i]*dRhoU;
    }
    primitivesCurrent_ = false;
    primitivesFromConservative(true);
}


void Foam::blastFluidSolver::fluidFractionFromSolid(scalarField& phi) const
{
    const scalarField& alphaS = alphaSolidPtr_->primitiveField();
    forAll(phi, i)
    {
        const scalar f = 1 - alphaS[i];
        phi[i] = f >= minFluidFraction_ ? f : 0;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blastFluidSolver::setSolid
(
    const volScalarField& alphaSolid,
    const volVectorField& Usolid,
    const scalar minFluidFraction,
    const scalar absorptionBeta
)
{
    alphaSolidPtr_ = &alphaSolid;
    UsolidPtr_ = &Usolid;
    minFluidFraction_ = minFluidFraction;
    absorptionBeta_ = absorptionBeta;

    // The fluid fraction is part of the state (a pocket of gas squeezed
    // by the solid keeps minFluidFraction): written at write times and read
    // back on restart; from alpha_s on a fresh start
    if (!readFluidFraction())
    {
        fluidFractionFromSolid(fluidFractionPtr_->primitiveFieldRef());
    }
    setFaceFluidFraction();
    solidImpulse_.setSize(mesh_.nCells(), Zero);
    primitivesCurrent_ = false;
}


void Foam::blastFluidSolver::updateFluidFraction()
{
    // When the solid moves, a cell that loses gas volume pushes the gas of
    // that volume into its neighbours, which receive the work p dV; a cell
    // that gains gas volume draws it from neighbours that hold gas, which
    // pay the work p dV. The transfers go preferably across the faces
    // whose closed part (seen from the neighbour) changes, at the
    // neighbour's pressure: that is where and with which pressure the gas
    // pushes the solid (addSolidForcing), so the work the gas does equals
    // the work the solid receives. Every transfer is a face quantity
    // computed from the states before the move, identical on both sides of
    // a processor face: mass, momentum and energy are conserved and a
    // decomposed run gives the serial answer.
    volScalarField& phiField = fluidFractionPtr_();
    scalarField& phi = phiField.primitiveFieldRef();
    const scalarField& V = mesh_.V();
    const scalarField& p = p_.primitiveField();
    const label nCells = mesh_.nCells();

    const volScalarField phiOldField("fluidFractionOld", phiField);
    const scalarField& phiOld = phiOldField.primitiveField();
    const scalarField vOld(phiOld*V);

    fluidFractionFromSolid(phi);
    phiField.correctBoundaryConditions();
    scalarField phiNbr, phiOldNbr;
    coupledNeighbourValues(phiField, phiNbr);
    coupledNeighbourValues(phiOldField, phiOldNbr);

    const boolList& coupledFace = coupledFace_;

    // Weights of the transfers across a face between cell a (changing) and
    // its neighbour b. Preferred: the change of the face's closed part seen
    // from b, because that closed part is where the solid force on the gas
    // of b acts (blastFluidSolver::addSolidForcing); moving gas there does
    // the work p_b dV that matches the work of that force on the solid.
    // Otherwise (a crack opening inside the solid, say): the open area.
    struct faceWeights
    {
        scalar drawClosed, drawOpen, pushClosed, pushOpen;
    };
    auto weights = [](const scalar phiOldA, const scalar phiA,
                      const scalar phiOldB, const scalar phiB, const scalar S)
    {
        const scalar closedOld = max(phiOldB - phiOldA, scalar(0));
        const scalar closedNew = max(phiB - phiA, scalar(0));
        const bool bDonates = phiOldB > 0 && phiB > 0;
        faceWeights w;
        w.drawClosed = bDonates ? max(closedOld - closedNew, scalar(0))*S : 0;
        w.drawOpen = bDonates ? min(phiA, phiB)*S : 0;
        w.pushClosed = phiB > 0 ? max(closedNew - closedOld, scalar(0))*S : 0;
        w.pushOpen = min(max(phiOldA, phiA), phiB)*S;
        return w;
    };
    // Face f seen from its owner (a = owner) and from its neighbour
    List<faceWeights> wOwn(nFaces_), wNei(nFaces_);
    scalarField sumDrawClosed(nCells, 0), sumDrawOpen(nCells, 0);
    scalarField sumPushClosed(nCells, 0), sumPushOpen(nCells, 0);
    auto addSums = [&](const label a, const faceWeights& w)
    {
        sumDrawClosed[a] += w.drawClosed;
        sumDrawOpen[a] += w.drawOpen;
        sumPushClosed[a] += w.pushClosed;
        sumPushOpen[a] += w.pushOpen;
    };
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        wOwn[f] = weights(phiOld[P], phi[P], phiOld[N], phi[N], magSf_[f]);
        wNei[f] = weights(phiOld[N], phi[N], phiOld[P], phi[P], magSf_[f]);
        addSums(P, wOwn[f]);
        addSums(N, wNei[f]);
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        const label b = cf - nInternal_, P = own_[cf];
        if (!coupledFace[b]) continue;
        wOwn[cf] =
            weights(phiOld[P], phi[P], phiOldNbr[b], phiNbr[b], magSf_[cf]);
        wNei[cf] =
            weights(phiOldNbr[b], phiNbr[b], phiOld[P], phi[P], magSf_[cf]);
        addSums(P, wOwn[cf]);
    }

    // Per cell: the volume pushed out or drawn in per unit weight, with the
    // closed-part weights if the cell has any, the open ones otherwise.
    // Pushed-out gas receives the work p dV at the receiver's pressure; a
    // donor pays the work p dV at its pressure (at most half of its
    // internal energy).
    auto newField = [&](const word& name)
    {
        return volScalarField(name, phiField*0);
    };
    volScalarField outClosedField(newField("outClosed"));
    volScalarField outOpenField(newField("outOpen"));
    volScalarField inClosedField(newField("inClosed"));
    volScalarField inOpenField(newField("inOpen"));
    scalarField& outClosed = outClosedField.primitiveFieldRef();
    scalarField& outOpen = outOpenField.primitiveFieldRef();
    scalarField& inClosed = inClosedField.primitiveFieldRef();
    scalarField& inOpen = inOpenField.primitiveFieldRef();
    scalarField drawWork(nCells, 0);
    forAll(phi, i)
    {
        const scalar dV = phi[i]*V[i] - vOld[i];
        if (dV < 0 && sumPushClosed[i] > 0)
        {
            outClosed[i] = -dV/sumPushClosed[i];
        }
        else if (dV < 0 && sumPushOpen[i] > 0)
        {
            outOpen[i] = -dV/sumPushOpen[i];
        }
        else if (dV < 0 && phi[i] < minFluidFraction_)
        {
            // Nowhere to go (a closed pocket): stays minimally open
            phi[i] = minFluidFraction_;
        }
        else if (dV > 0 && sumDrawClosed[i] > 0)
        {
            inClosed[i] = dV/sumDrawClosed[i];
        }
        else if (dV > 0 && sumDrawOpen[i] > 0)
        {
            inOpen[i] = dV/sumDrawOpen[i];
        }
        const scalar rhoe = rhoE_[i] - 0.5*magSqr(rhoU_[i])/rho_[i];
        drawWork[i] = min(p[i], 0.5*rhoe);
    }
    // Volumes moved across face f from the cell on one side (a, weights w
    // seen from a) to the other, or drawn by a from the other
    auto pushVolume = [](const scalar oC, const scalar oO, const faceWeights& w)
    {
        return oC*w.pushClosed + oO*w.pushOpen;
    };
    auto drawVolume = [](const scalar iC, const scalar iO, const faceWeights& w)
    {
        return iC*w.drawClosed + iO*w.drawOpen;
    };
    for (volScalarField* fld :
        {&outClosedField, &outOpenField, &inClosedField, &inOpenField})
    {
        fld->correctBoundaryConditions();
    }
    rho_.correctBoundaryConditions();
    rhoU_.correctBoundaryConditions();
    rhoE_.correctBoundaryConditions();
    if (twoPhase_)
    {
        alphaRho1Ptr_->correctBoundaryConditions();
        alpha1Ptr_->correctBoundaryConditions();
    }

    scalarField outCNbr, outONbr, inCNbr, inONbr;
    scalarField rhoNbr, rhoENbr, rho1Nbr, alpha1Nbr;
    vectorField rhoUNbr;
    coupledNeighbourValues(outClosedField, outCNbr);
    coupledNeighbourValues(outOpenField, outONbr);
    coupledNeighbourValues(inClosedField, inCNbr);
    coupledNeighbourValues(inOpenField, inONbr);
    coupledNeighbourValues(rho_, rhoNbr);
    coupledNeighbourValues(rhoU_, rhoUNbr);
    coupledNeighbourValues(rhoE_, rhoENbr);
    if (twoPhase_)
    {
        coupledNeighbourValues(alphaRho1Ptr_(), rho1Nbr);
        coupledNeighbourValues(alpha1Ptr_(), alpha1Nbr);
    }
    const scalarField& rho1 =
        twoPhase_ ? alphaRho1Ptr_->primitiveField() : rho_.primitiveField();
    const scalarField& alpha1 =
        twoPhase_ ? alpha1Ptr_->primitiveField() : rho_.primitiveField();
    if (!twoPhase_)
    {
        rho1Nbr = rhoNbr;
        alpha1Nbr = rhoNbr;
    }

    // A donor gives at most half of the gas it keeps after pushing (then
    // its internal energy stays positive, drawWork <= rhoe/2): a small
    // pocket next to a cell that opens widely would otherwise give more
    // gas than it holds (negative mass); the receiver expands instead
    volScalarField drawScale(newField("drawScale"));
    {
        scalarField& s = drawScale.primitiveFieldRef();
        scalarField asked(nCells, 0), pushed(nCells, 0);
        for (label f = 0; f < nInternal_; ++f)
        {
            const label P = own_[f], N = nei_[f];
            asked[N] += drawVolume(inClosed[P], inOpen[P], wOwn[f]);
            asked[P] += drawVolume(inClosed[N], inOpen[N], wNei[f]);
            pushed[P] += pushVolume(outClosed[P], outOpen[P], wOwn[f]);
            pushed[N] += pushVolume(outClosed[N], outOpen[N], wNei[f]);
        }
        for (label cf = nInternal_; cf < nFaces_; ++cf)
        {
            const label b = cf - nInternal_, P = own_[cf];
            if (!coupledFace[b]) continue;
            asked[P] += drawVolume(inCNbr[b], inONbr[b], wNei[cf]);
            pushed[P] += pushVolume(outClosed[P], outOpen[P], wOwn[cf]);
        }
        forAll(s, i)
        {
            const scalar kept = 0.5*max(vOld[i] - pushed[i], scalar(0));
            s[i] = asked[i] > kept ? kept/asked[i] : 1;
        }
        drawScale.correctBoundaryConditions();
    }
    const scalarField& drawS = drawScale.primitiveField();
    scalarField drawSNbr;
    coupledNeighbourValues(drawScale, drawSNbr);

    gasContent c(*this, vOld/V);
    const scalarField rhoOld(rho_.primitiveField());
    const vectorField rhoUOld(rhoU_.primitiveField());

    // Cell a gives gas volume v of its state, losing the energy rhoE_a + w
    auto give = [&](const label a, const scalar v, const scalar w)
    {
        c.add(a, -v, rhoOld[a], rhoUOld[a], rhoE_[a] + w, rho1[a], alpha1[a]);
    };
    // Cell a pushes volume v into b; cell b draws volume v from a
    scalarField pushedOut(nCells, 0), drawnIn(nCells, 0);
    auto push = [&](const label a, const label b, const scalar v)
    {
        if (v <= 0) return;
        c.add(b, v, rhoOld[a], rhoUOld[a], rhoE_[a] + p[b], rho1[a], alpha1[a]);
        give(a, v, 0);
        pushedOut[a] += v;
    };
    auto draw = [&](const label a, const label b, const scalar v)
    {
        if (v <= 0) return;
        c.add(b, v, rhoOld[a], rhoUOld[a], rhoE_[a], rho1[a], alpha1[a]);
        give(a, v, drawWork[a]);
        drawnIn[b] += v;
    };
    for (label f = 0; f < nInternal_; ++f)
    {
        const label P = own_[f], N = nei_[f];
        push(P, N, pushVolume(outClosed[P], outOpen[P], wOwn[f]));
        push(N, P, pushVolume(outClosed[N], outOpen[N], wNei[f]));
        draw(N, P, drawS[N]*drawVolume(inClosed[P], inOpen[P], wOwn[f]));
        draw(P, N, drawS[P]*drawVolume(inClosed[N], inOpen[N], wNei[f]));
    }
    for (label cf = nInternal_; cf < nFaces_; ++cf)
    {
        // The other side of a processor face adds the same amounts
        const label b = cf - nInternal_, P = own_[cf];
        if (!coupledFace[b]) continue;
        const scalar vPushOut = pushVolume(outClosed[P], outOpen[P], wOwn[cf]);
        const scalar vPushIn = pushVolume(outCNbr[b], outONbr[b], wNei[cf]);
        const scalar vDrawOut =
            drawS[P]*drawVolume(inCNbr[b], inONbr[b], wNei[cf]);
        const scalar vDrawIn =
            drawSNbr[b]*drawVolume(inClosed[P], inOpen[P], wOwn[cf]);
        if (vPushOut > 0)
        {
            give(P, vPushOut, 0);
            pushedOut[P] += vPushOut;
        }
        if (vDrawOut > 0)
        {
            give(P, vDrawOut, drawWork[P]);
        }
        if (vPushIn > 0)
        {
            c.add
            (
                P, vPushIn, rhoNbr[b], rhoUNbr[b], rhoENbr[b] + p[P],
                rho1Nbr[b], alpha1Nbr[b]
            );
        }
        if (vDrawIn > 0)
        {
            drawnIn[P] += vDrawIn;
            c.add
            (
                P, vDrawIn, rhoNbr[b], rhoUNbr[b], rhoENbr[b], rho1Nbr[b],
                alpha1Nbr[b]
            );
        }
    }

    // The volume change no transfer covered: the cell's own gas expands
    // (no donor, or limited donors) or is compressed in place (a closed
    // pocket); it does or receives the work p dV like transferred gas
    forAll(phi, i)
    {
        if (vOld[i] <= 0) continue;
        const scalar dV = phi[i]*V[i] - vOld[i];
        const scalar self =
            dV > 0 ? dV - drawnIn[i] : dV + pushedOut[i];
        const scalar rhoe = rhoE_[i] - 0.5*magSqr(rhoU_[i])/rho_[i];
        c.energy[i] -= min(p[i]*self, 0.5*rhoe*vOld[i]);
    }

    // A cell opened where no neighbour holds gas (a void inside the solid,
    // a crack not yet reached by the gas) stays closed until gas can reach
    // it: nothing is created
    forAll(phi, i)
    {
        if (vOld[i] == 0 && phi[i] > 0 && c.volume[i] <= 0)
        {
            phi[i] = 0;
        }
    }

    c.toState(phi);

    phiField.correctBoundaryConditions();
    setFaceFluidFraction();
    primitivesCurrent_ = false;
    primitivesFromConservative(true);
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


Foam::tmp<Foam::scalarField> Foam::blastFluidSolver::fluidFraction() const
{
    if (fluidFractionPtr_.valid())
    {
        return fluidFractionPtr_->primitiveField();
    }
    return tmp<scalarField>::New(mesh_.nCells(), 1);
}


// ************************************************************************* //

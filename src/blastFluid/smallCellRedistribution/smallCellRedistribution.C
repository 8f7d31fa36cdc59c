/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Weighted state redistribution of the cut cells' gas content (see
    smallCellRedistribution.H).

\*---------------------------------------------------------------------------*/

#include "smallCellRedistribution.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::smallCellRedistribution::smallCellRedistribution
(
    const fvMesh& mesh,
    const blastFaceAddressing& addr,
    const label nComp
)
:
    mesh_(mesh),
    addr_(addr),
    nComp_(nComp),
    w_(mesh),
    links_(nullptr),
    closedLinks_(false),
    lostMass_(0),
    lostEnergy_(0)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::smallCellRedistribution::markDeficientNeighbourhoods
(
    const scalarField& phi
)
{
    cutCellFields& w = w_;
    const scalarField& small = w.small.primitiveField();
    const scalarField& V = mesh_.V();
    scalarField& deficient = w.deficient.primitiveFieldRef();
    // The flags of the last call cleared (the lists hold every cell
    // flagged), then the small cells of the last pass tested
    w.clearDeficient();
    w.clearExtra();
    for (const label i : w.smallCells)
    {
        if (w.sumVolume[i] < 0.5*V[i])
        {
            deficient[i] = 1;
            w.deficientCells.append(i);
            w.setExtra(i);
        }
    }
    const bool any = w.deficientCells.size() > 0;
    if (!returnReduce(any, orOp<bool>()))
    {
        return false;
    }
    cutCellFields::evaluateCoupled(w.deficient);
    scalarField& deficientNbr = w.deficientNbr;
    addr_.coupledNeighbourValues(w.deficient, deficientNbr);
    // (a deficient cell is small: its faces are active)
    for (const label f : w.activeFaces)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (deficient[P] > 0 && link(f, small[P], phi[N])) w.setExtra(N);
        if (deficient[N] > 0 && link(f, small[N], phi[P])) w.setExtra(P);
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal(), P = addr_.own()[cf];
        if (deficientNbr[b] > 0 && link(cf, w.smallNbr[b], phi[P]))
        {
            w.setExtra(P);
        }
    }
    return true;
}


void Foam::smallCellRedistribution::redistributePass
(
    const volScalarField& phiField,
    conservedFields& c,
    const boolList* force,
    const bool forcedOnly
)
{
    cutCellFields& w = w_;
    const scalarField& phi = phiField.primitiveField();
    scalarField& cRho = c.rho;
    vectorField& cRhoU = c.rhoU;
    scalarField& cRhoE = c.rhoE;
    scalarField& cAlpha = c.alpha;
    scalarField& cAlphaRho1 = c.alphaRho1;

    // Small cells: less than half open or closing with gas in them, and
    // the cells in 'force' (new ones); with forcedOnly those only
    scalarField& small = w.small.primitiveFieldRef();
    // (a cell without volume that holds content is always small: its
    // content must go somewhere). The one loop over every cell of a pass:
    // the rest works on the list of small cells and their neighbours
    w.smallCells.clear();
    forAll(small, i)
    {
        const bool forced = force && (*force)[i];
        const bool candidate = forced || (!forcedOnly && phi[i] < 0.5);
        const bool content = cRho[i] != 0 || cRhoE[i] != 0;
        const bool s = (candidate && phi[i] > 0) || (phi[i] <= 0 && content);
        small[i] = s ? 1 : 0;
        if (s) w.smallCells.append(i);
    }
    cutCellFields::evaluateCoupled(w.small);
    addr_.coupledNeighbourValues(w.small, w.smallNbr);
    addr_.coupledNeighbourValues(phiField, w.phiNbr);
    w.setActive(mesh_);

    countNeighbourhoods(phi);
    if (!returnReduce(w.smallCells.size() > 0, orOp<bool>()))
    {
        return;
    }

    // The content components: mass, momentum, energy (material 1, and
    // material 2 of three)
    const label nComp = nComp_;
    auto component = [&](const label k, const label i) -> scalar&
    {
        switch (k)
        {
            case 0: return cRho[i];
            case 1: return cRhoU[i].x();
            case 2: return cRhoU[i].y();
            case 3: return cRhoU[i].z();
            case 4: return cRhoE[i];
            case 5: return cAlphaRho1[i];
            case 6: return cAlpha[i];
            case 7: return c.alphaRho2[i];
            default: return c.alpha2[i];
        }
    };

    // Every cell's share of volume and content per neighbourhood
    const scalarField& V = mesh_.V();
    const scalarField& count = w.count.primitiveField();
    scalarField& vol = w.volume.primitiveFieldRef();
    UPtrList<scalarField> share(w.shareValues(nComp));
    for (const label i : w.activeCells)
    {
        const scalar s = V[i]/count[i];
        vol[i] = phi[i]*s;
        for (label k = 0; k < nComp; ++k)
        {
            share[k][i] = component(k, i)*s;
        }
    }
    cutCellFields::evaluateCoupled(w.count);
    cutCellFields::evaluateCoupled(w.volume);
    w.evaluateShares(nComp);
    neighbourhoodStates(phi, nComp);

    // A cell's state: the mean of the states of its neighbourhoods
    w.evaluateShares(nComp);
    gatherNeighbourhoods(phi, nComp, true);
    for (const label i : w.activeCells)
    {
        const scalar s = phi[i]/count[i];
        for (label k = 0; k < nComp; ++k)
        {
            component(k, i) = s*w.sum[k][i];
        }
    }
    depositOrphans(phi, nComp, component);
}


template<class Component>
void Foam::smallCellRedistribution::depositOrphans
(
    const scalarField& phi,
    const label nComp,
    const Component& component
)
{
    // A cell that closes among closed cells (a pocket crushed between
    // fragments, a sliver whose neighbours closed in the same step) has no
    // neighbourhood: its content goes to the gas nearest to it, the cells
    // with gas in the first ring of face neighbours that has any (up to
    // maxRings), in proportion to their gas volumes. Mass, momentum and
    // energy are conserved; only beyond maxRings (or behind a processor
    // face) is the content lost, and reported
    const label maxRings = 4;
    cutCellFields& w = w_;
    const scalarField& V = mesh_.V();
    forAll(w.orphans, o)
    {
        const label seed = w.orphans[o];
        const FixedList<scalar, cutCellFields::maxComponents>& c =
            w.orphanContent[o];
        scalar gasVolume = 0;
        forEachRing
        (
            seed, maxRings,
            [&](const label j) { if (phi[j] > 0) gasVolume += phi[j]*V[j]; },
            [&]() { return gasVolume > 0; }
        );
        if (gasVolume <= 0)
        {
            lostMass_ += c[0];
            lostEnergy_ += c[4];
            continue;
        }
        for (const label j : lastRing())
        {
            if (phi[j] <= 0) continue;
            // Content per cell volume: C w_j/V_j, w_j = phi_j V_j/sum
            const scalar s = phi[j]/gasVolume;
            for (label k = 0; k < nComp; ++k)
            {
                component(k, j) += s*c[k];
            }
        }
    }
    w.orphans.clear();
    w.orphanContent.clear();
}


void Foam::smallCellRedistribution::countNeighbourhoods(const scalarField& phi)
{
    cutCellFields& w = w_;
    const scalarField& small = w.small.primitiveField();
    scalarField& count = w.count.primitiveFieldRef();
    for (const label i : w.activeCells)
    {
        count[i] = 1;
    }
    for (const label f : w.activeFaces)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (link(f, small[P], phi[N])) count[N] += 1;
        if (link(f, small[N], phi[P])) count[P] += 1;
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal(), P = addr_.own()[cf];
        if (link(cf, w.smallNbr[b], phi[P])) count[P] += 1;
    }
}


void Foam::smallCellRedistribution::gatherNeighbourhoods
(
    const scalarField& phi,
    const label nComp,
    const bool intoMembers
)
{
    // Sums over the neighbourhood of each small cell (its own share and
    // those of the neighbours it links to: intoMembers false) or over the
    // neighbourhoods each cell belongs to (intoMembers true)
    cutCellFields& w = w_;
    const scalarField& small = w.small.primitiveField();
    for (label k = 0; k < nComp; ++k)
    {
        const scalarField& sh = w.share[k].primitiveField();
        scalarField& sk = w.sum[k];
        for (const label i : w.activeCells)
        {
            sk[i] = sh[i];
        }
        addr_.coupledNeighbourValues(w.share[k], w.shareNbr[k]);
    }
    if (!intoMembers)
    {
        const scalarField& vol = w.volume.primitiveField();
        for (const label i : w.activeCells)
        {
            w.sumVolume[i] = vol[i];
        }
        addr_.coupledNeighbourValues(w.volume, w.volumeNbr);
    }

    auto add = [&](const label a, const label b)
    {
        if (!intoMembers) w.sumVolume[a] += w.volume[b];
        for (label k = 0; k < nComp; ++k)
        {
            w.sum[k][a] += w.share[k][b];
        }
    };
    for (const label f : w.activeFaces)
    {
        const label P = addr_.own()[f], N = addr_.nei()[f];
        if (intoMembers)
        {
            if (link(f, small[P], phi[N])) add(N, P);
            if (link(f, small[N], phi[P])) add(P, N);
        }
        else
        {
            if (link(f, small[P], phi[N])) add(P, N);
            if (link(f, small[N], phi[P])) add(N, P);
        }
    }
    for (label cf = addr_.nInternal(); cf < addr_.nFaces(); ++cf)
    {
        const label b = cf - addr_.nInternal(), P = addr_.own()[cf];
        const bool linked =
            intoMembers
          ? link(cf, w.smallNbr[b], phi[P])
          : link(cf, small[P], w.phiNbr[b]);
        if (linked)
        {
            if (!intoMembers) w.sumVolume[P] += w.volumeNbr[b];
            for (label k = 0; k < nComp; ++k)
            {
                w.sum[k][P] += w.shareNbr[k][b];
            }
        }
    }
}


void Foam::smallCellRedistribution::neighbourhoodStates
(
    const scalarField& phi,
    const label nComp
)
{
    // Neighbourhood states (per unit gas volume) replace the shares; a
    // closing cell without a neighbourhood goes to depositOrphans
    gatherNeighbourhoods(phi, nComp, false);
    cutCellFields& w = w_;
    const scalarField& small = w.small.primitiveField();
    const scalarField& count = w.count.primitiveField();
    UPtrList<scalarField> share(w.shareValues(nComp));
    for (const label i : w.activeCells)
    {
        if (w.sumVolume[i] > 0)
        {
            const scalar r = 1/w.sumVolume[i];
            for (label k = 0; k < nComp; ++k)
            {
                share[k][i] = r*w.sum[k][i];
            }
        }
        else if (small[i] > 0)
        {
            // The shares are content V/count: kept for depositOrphans
            FixedList<scalar, cutCellFields::maxComponents> c(Zero);
            for (label k = 0; k < nComp; ++k)
            {
                c[k] = share[k][i]*count[i];
            }
            w.orphans.append(i);
            w.orphanContent.append(c);
            for (label k = 0; k < nComp; ++k)
            {
                share[k][i] = 0;
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::smallCellRedistribution::redistribute
(
    const volScalarField& phiField,
    conservedFields& c,
    const faceLinks& links,
    const boolList* force,
    const bool forcedOnly
)
{
    links_ = &links;
    redistributePass
    (
        phiField, c, force, forcedOnly
    );
    const label maxExtraPasses = 3;
    for (label pass = 0; pass <= maxExtraPasses; ++pass)
    {
        if (!markDeficientNeighbourhoods(phiField.primitiveField()))
        {
            break;
        }
        if (pass == maxExtraPasses)
        {
            // Pockets still short of gas: a gap between fragments inside a
            // cell, open to none of its faces, next to gas across them (the
            // sub-cell crack joins them). Kept alone, such a pocket is
            // crushed within one step (1.2e15 Pa at 1.4e-4 of a cell in the
            // fragmenting tube) and its wall force flings the fragments;
            // merged, it takes its neighbours' state (mass, momentum and
            // energy conserved)
            cutCellFields& w = w_;
            w.clearExtra();
            for (const label i : w.deficientCells)
            {
                w.setExtra(i);
            }
            closedLinks_ = true;
        }
        redistributePass
        (
            phiField, c, &w_.extra, true
        );
        closedLinks_ = false;
    }
    links_ = nullptr;
}

Foam::label Foam::smallCellRedistribution::mixUntilPositive
(
    const scalarField& phi,
    conservedFields& c,
    const boolList& seed,
    const boolList& skip,
    const label maxRings,
    const label minRings
)
{
    const scalarField& V = mesh_.V();
    const label nc = phi.size();
    const auto noEnergy = [&](const label i)
    {
        return !hasInternalEnergy(c.rho[i], c.rhoU[i], c.rhoE[i]);
    };
    // The material contents mixed like the rest (empty when not tracked)
    scalarField* extra[4] = {&c.alpha, &c.alphaRho1, &c.alpha2, &c.alphaRho2};
    mixed_.clear();
    for (label i = 0; i < nc; ++i)
    {
        if (!seed[i] || !(phi[i] > 0) || (minRings == 0 && !noEnergy(i)))
        {
            continue;
        }
        scalar Vg = phi[i]*V[i];
        scalar m = c.rho[i]*V[i], E = c.rhoE[i]*V[i];
        vector mU = c.rhoU[i]*V[i];
        bool blocked = skip[i];
        group_.clear();
        group_.append(i);
        const auto positive = [&]() { return hasInternalEnergy(m, mU, E); };
        // done() is asked before each ring: the first minRings are taken
        label asked = 0;
        forEachRing
        (
            i, maxRings,
            [&](const label j)
            {
                blocked = blocked || skip[j];
                if (!(phi[j] > 0)) return;
                group_.append(j);
                Vg += phi[j]*V[j];
                m += c.rho[j]*V[j];
                mU += c.rhoU[j]*V[j];
                E += c.rhoE[j]*V[j];
            },
            [&]() { return blocked || (asked++ >= minRings && positive()); }
        );
        if (blocked || !positive() || group_.size() == 1) continue;
        scalar x[4] = {0, 0, 0, 0};
        for (label k = 0; k < 4; ++k)
        {
            if (extra[k]->size() != nc) continue;
            for (const label j : group_) x[k] += (*extra[k])[j]*V[j];
        }
        for (const label j : group_)
        {
            const scalar w = phi[j]/Vg;
            c.rho[j] = w*m;
            c.rhoU[j] = w*mU;
            c.rhoE[j] = w*E;
            for (label k = 0; k < 4; ++k)
            {
                if (extra[k]->size() == nc) (*extra[k])[j] = w*x[k];
            }
            mixed_.append(j);
        }
    }
    return mixed_.size();
}


// ************************************************************************* //

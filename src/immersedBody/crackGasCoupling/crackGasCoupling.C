/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackGasCoupling.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::crackGasCoupling::crackGasCoupling
(
    const fvMesh& mesh,
    const solidProjection& projection,
    const jointTopology& topology,
    const blastMixture& mixture,
    const dictionary& dict,
    const scalar depth
)
:
    mesh_(mesh),
    projection_(projection),
    net_(topology, mixture, dict),
    depth_(depth),
    lostMass_(0),
    lostEnergy_(0)
{
    // A misspelt entry would silently take its default
    const wordList valid
    ({"flux", "RKorder", "frictionFactor", "minAperture", "ambient"});
    for (const word& key : dict.toc())
    {
        if (!valid.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "unknown entry '" << key << "' in crackGas; valid: "
                << valid << exit(FatalIOError);
        }
    }
    if (Pstream::parRun())
    {
        FatalIOErrorInFunction(dict)
            << "crackGas runs serial only for now (on 2 ranks the run"
            << " finishes but its crack gas differs from serial by several"
            << " per cent: a mouth at a processor boundary gets another"
            << " plenum cell); remove the sub-dictionary 'crackGas' for a"
            << " parallel run"
            << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::crackGasCoupling::firstOwners(labelList& choice)
{
    // Each rank's choice (a rank that has none gives a large number); the
    // smallest wins on every rank, so that the replicated network stays the
    // same everywhere (the same rule serial: the first of the candidates)
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(choice, minEqOp<label>());
        Pstream::listCombineScatter(choice);
    }
}


void Foam::crackGasCoupling::setNetworkJoints
(
    const UList<vector2D>& x,
    const boolList& broken,
    const gasView& view,
    const blastFluidSolver& fluid
)
{
    // The joints: broken, not open to the gas
    const boolList& open = view.openJoints();
    joints_.clear();
    forAll(broken, j)
    {
        if (broken[j] && !open[j]) joints_.append(j);
    }
    if (joints_ == net_.joints()) return;

    released_.clear();
    net_.setJoints(joints_, x, &released_);
    // Handed over: into the fluid cell with gas at the joint's midpoint,
    // else at one of its nodes (the crack opened to the gas runs through
    // them); in parallel the first of these points that a rank holds, and
    // the lowest such rank
    const jointTopology& topo = view.view().topology();
    const scalarField* phi = fluid.fluidFractionField();
    const label nP = Pstream::nProcs(), me = Pstream::myProcNo();
    labelList choice(released_.size(), 5*nP);
    labelList cell(released_.size(), -1);
    forAll(released_, r)
    {
        const jointNodeList& jn = topo.jointNodes()[released_[r].first];
        const vector2D at[5] =
        {
            0.25*(x[jn[0]] + x[jn[1]] + x[jn[2]] + x[jn[3]]),
            x[jn[0]], x[jn[1]], x[jn[2]], x[jn[3]]
        };
        for (label k = 0; k < 5; ++k)
        {
            const label ci = projection_.findCell(at[k]);
            if (ci >= 0 && (!phi || (*phi)[ci] > 0))
            {
                cell[r] = ci;
                choice[r] = k*nP + me;
                break;
            }
        }
    }
    labelList mine(choice);
    firstOwners(choice);
    forAll(released_, r)
    {
        const ductNetwork::content& c = released_[r].second;
        if (choice[r] == 5*nP)
        {
            lostMass_ += c.m;
            lostEnergy_ += c.mE;
        }
        else if (choice[r] == mine[r])
        {
            givenCell_.append(cell[r]);
            given_.append(c);
        }
    }
}


void Foam::crackGasCoupling::setMouths
(
    const gasView& view,
    const blastFluidSolver& fluid
)
{
    // Mouths: crack ends at points of the view's outline, in a cell with
    // gas (in parallel: of the lowest rank that holds one)
    const continuousView& cv = view.view();
    onOutline_.setSize(cv.points().size());
    onOutline_ = false;
    for (const edge& e : cv.boundaryEdges())
    {
        onOutline_[e.start()] = true;
        onOutline_[e.end()] = true;
    }
    const labelList& pointOfNode = cv.pointOfNode();
    const scalarField* phi = fluid.fluidFractionField();
    const label nP = Pstream::nProcs(), me = Pstream::myProcNo();
    DynamicList<FixedList<label, 2>>& ends = candidates_;
    DynamicList<label>& cell = candidateCell_;
    ends.clear();
    cell.clear();
    forAll(net_.joints(), i)
    {
        const jointNodeList& jn = cv.topology().jointNodes()[net_.joints()[i]];
        for (const label e : {0, 1})
        {
            const label pt = pointOfNode[jn[e]];
            if (!onOutline_[pt]) continue;
            label c = plenumCell(fluid, projection_.findCell(cv.points()[pt]));
            if (c >= 0 && phi && !((*phi)[c] > 0)) c = -1;
            ends.append(FixedList<label, 2>({i, e}));
            cell.append(c);
        }
    }
    labelList choice(ends.size());
    forAll(ends, k)
    {
        choice[k] = cell[k] >= 0 ? me : nP;
    }
    firstOwners(choice);
    mouths_.clear();
    mouthCell_.clear();
    forAll(ends, k)
    {
        if (choice[k] == nP) continue;
        mouths_.append(ends[k]);
        mouthCell_.append(choice[k] == me ? cell[k] : -1);
    }
    net_.setMouths(mouths_);
}


void Foam::crackGasCoupling::setPlenums(const blastFluidSolver& fluid)
{
    // The cells' states, each cell's mouths sharing its cap; in parallel
    // the rank of the cell gives them, the others zeros, and the sum goes
    // to every rank
    const scalarField* phi = fluid.fluidFractionField();
    const bool two = fluid.mixture().twoPhase();
    const label nm = mouths_.size(), nq = 6;
    scalarList& q = plenumValues_;
    q.setSize(nq*nm);
    q = 0;
    forAll(mouths_, k)
    {
        const label c = mouthCell_[k];
        if (c < 0) continue;
        q[nq*k] = fluid.rho()[c];
        q[nq*k + 1] = fluid.p()[c];
        if (two)
        {
            q[nq*k + 2] = fluid.alpha1()[c];
            q[nq*k + 3] = fluid.rho1()[c];
            q[nq*k + 4] = fluid.rho2()[c];
        }
        mouthsOfCell_.insert(c, 0);
        ++mouthsOfCell_[c];
    }
    forAll(mouths_, k)
    {
        const label c = mouthCell_[k];
        if (c < 0) continue;
        q[nq*k + 5] = plenumCap(fluid, phi, c)/mouthsOfCell_[c];
    }
    mouthsOfCell_.clear();
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(q, plusEqOp<scalar>());
        Pstream::listCombineScatter(q);
    }
    ductNetwork::plenumStates& pl = net_.plenum();
    forAll(mouths_, k)
    {
        const label f = net_.mouthInterface(k);
        pl.rho[f] = q[nq*k];
        pl.p[f] = q[nq*k + 1];
        if (two)
        {
            pl.alpha1[f] = q[nq*k + 2];
            pl.rho1[f] = q[nq*k + 3];
            pl.rho2[f] = q[nq*k + 4];
        }
        pl.maxMass[f] = q[nq*k + 5];
    }
}


void Foam::crackGasCoupling::beginStep
(
    const UList<vector2D>& x,
    const boolList& broken,
    const gasView& view,
    const blastFluidSolver& fluid
)
{
    setNetworkJoints(x, broken, view, fluid);
    setMouths(view, fluid);
    setPlenums(fluid);
}


Foam::label Foam::crackGasCoupling::plenumCell
(
    const blastFluidSolver& fluid,
    const label c
) const
{
    // A small cut cell is a poor plenum: a sliver's state follows its
    // neighbours' (the small-cell treatment), and the little gas it holds
    // would cap the mouth. Its neighbour through an open face with the
    // most gas stands for it
    const scalarField* phi = fluid.fluidFractionField();
    if (c < 0 || !phi || (*phi)[c] >= 0.5) return c;
    const scalarField& ap = fluid.faceApertures();
    const scalarField& V = mesh_.V();
    label best = c;
    scalar most = (*phi)[c]*V[c];
    for (const label f : mesh_.cells()[c])
    {
        if (f >= mesh_.nInternalFaces() || !(ap[f] > 0)) continue;
        const label nb =
            mesh_.faceOwner()[f] == c
          ? mesh_.faceNeighbour()[f] : mesh_.faceOwner()[f];
        if ((*phi)[nb]*V[nb] > most)
        {
            best = nb;
            most = (*phi)[nb]*V[nb];
        }
    }
    return best;
}


Foam::scalar Foam::crackGasCoupling::plenumCap
(
    const blastFluidSolver& fluid,
    const scalarField* phi,
    const label c
) const
{
    // A fraction f of the cell's mass M leaves with the stagnation enthalpy
    // h0 = e + p/rho of the cell's state, and its momentum stays (no
    // momentum crosses a mouth), so its kinetic energy K grows by
    // K f/(1 - f) <= 4K f/3: its internal energy U keeps at least half
    // if f (M h0 + 4K/3) <= U/2; and f <= 1/4 whatever the energy
    const scalar Vg = (phi ? (*phi)[c] : 1)*mesh_.V()[c];
    const scalar rho = fluid.rho()[c];
    const scalar M = rho*Vg;
    const scalar K = 0.5*rho*magSqr(fluid.U()[c])*Vg;
    const scalar U = fluid.rhoE()[c]*Vg - K;
    if (!(M > 0) || !(U > 0)) return 0;
    const scalar h0 = U/M + fluid.p()[c]/rho;
    const scalar f = min(scalar(0.25), 0.5*U/(M*h0 + 4*K/3));
    return f*M/depth_;
}


Foam::label Foam::crackGasCoupling::advanceSolid
(
    femdemSolid& solid,
    const List<vector2D>& otherForces,
    const scalar dt
)
{
    crackNetwork::subSteps hook(net_, otherForces);
    const label n = solid.advance(dt, hook);
    net_.endStep(solid.x(), dt);
    return n;
}


void Foam::crackGasCoupling::exchange(blastFluidSolver& fluid)
{
    // What entered the mouths leaves their cells; handed-over gas enters
    // (per unit depth in the network, times the depth in the mesh)
    DynamicList<label>& cells = cells_;
    DynamicList<scalar>& dm = dm_;
    DynamicList<scalar>& dE = dE_;
    DynamicList<scalar>& dm1 = dm1_;
    DynamicList<vector>& dmU = dmU_;
    cells.clear(); dm.clear(); dE.clear(); dm1.clear(); dmU.clear();
    forAll(mouths_, k)
    {
        // In parallel, the mouths of this rank's cells
        if (mouthCell_[k] < 0) continue;
        cells.append(mouthCell_[k]);
        dm.append(-depth_*net_.mouthMass()[k]);
        // No momentum: what crosses a mouth is mostly its pressure impulse,
        // which the cell's wall term already gives its gas (the mouth is
        // part of the solid's outline in the cell); handed to a small cell
        // it made kinetic energy out of nothing
        dmU.append(vector::zero);
        dE.append(-depth_*net_.mouthEnergy()[k]);
        dm1.append(-depth_*net_.mouthMass1()[k]);
    }
    forAll(givenCell_, k)
    {
        const ductNetwork::content& c = given_[k];
        cells.append(givenCell_[k]);
        dm.append(depth_*c.m);
        dmU.append(vector::zero);
        dE.append(depth_*c.mE);
        dm1.append(depth_*c.m1);
    }
    givenCell_.clear();
    given_.clear();
    // addContent recomputes the primitives (reductions, processor
    // patches): every rank calls it when any rank has cells, also one
    // without (a collective called on some ranks only hung the run)
    if (returnReduce(cells.size(), sumOp<label>()))
    {
        fluid.addContent(cells, dm, dmU, dE, dm1);
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "crackGasCoupling.H"
#include "syncTools.H"
#include "processorPolyPatch.H"
#include "caseChecks.H"
#include "IFstream.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(crackGasCoupling, 0);
}


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
    lostEnergy_(0),
    maxRun_(0),
    maxRunOf_(0),
    maxShared_(0),
    partitionWeight_(dict.getOrDefault<scalar>("partitionWeight", 20))
{
    // A misspelt entry would silently take its default
    const wordList valid
    ({"flux", "RKorder", "frictionFactor", "kapilaTerm", "minAperture",
      "maxVolumeChange", "ambient", "partitionWeight"});
    for (const word& key : dict.toc())
    {
        if (!valid.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "unknown entry '" << key << "' in crackGas; valid: "
                << valid << exit(FatalIOError);
        }
    }
    if (!(partitionWeight_ >= 0 && partitionWeight_ <= 1e4))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'partitionWeight' in crackGas must be in [0, 1e4], got "
            << partitionWeight_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::crackGasCoupling::cellKey
(
    const scalarField* phi,
    const label c
) const
{
    const point& C = mesh_.C()[c];
    return vector((phi ? (*phi)[c] : 1)*mesh_.V()[c], C.x(), C.y());
}


void Foam::crackGasCoupling::bestOverRanks(List<vector>& keys)
{
    if (Pstream::parRun())
    {
        Pstream::listCombineGather(keys, betterOp());
        Pstream::listCombineScatter(keys);
    }
}


Foam::vector Foam::crackGasCoupling::containingKey
(
    const vector2D& pt,
    const scalarField* phi
)
{
    found_.clear();
    projection_.findCells(pt, found_);
    vector best = noCell();
    for (const label c : found_)
    {
        if (phi && !((*phi)[c] > 0)) continue;
        const vector k = cellKey(phi, c);
        if (better(k, best)) best = k;
    }
    return best;
}


Foam::label Foam::crackGasCoupling::cellOfKey(const vector& key) const
{
    // The centroid of a convex cell lies inside it and no other cell
    return key.x() < 0 ? -1 : projection_.findCell(vector2D(key.y(), key.z()));
}


void Foam::crackGasCoupling::swapNeighbours(const scalarField* phi)
{
    if (!Pstream::parRun()) return;
    scalarField gas(mesh_.V().field());
    if (phi) gas *= *phi;
    syncTools::swapBoundaryCellList(mesh_, gas, gasNbr_);
    syncTools::swapBoundaryCellPositions
    (
        mesh_, mesh_.C().primitiveField(), centreNbr_
    );
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
    // No void where a crack open to the gas meets the others (its gas is
    // the mesh's); the voids change with the open joints even when the
    // network's joints do not
    net_.setOpenJoints(open);
    if (joints_ == net_.joints()) return;

    released_.clear();
    net_.setJoints(joints_, x, &released_);
    handOver(x, view.view().topology(), fluid);
}


void Foam::crackGasCoupling::handOver
(
    const UList<vector2D>& x,
    const jointTopology& topo,
    const blastFluidSolver& fluid
)
{
    // The gas of a joint the view opened goes to the fluid cells its gap
    // (p0 q0 q1 p1, counter-clockwise) overlaps, in proportion to the
    // overlaps (exact clipping: the view opened that gap to the cells'
    // gas), the cells without gas left out; the shares' sums over the
    // ranks, so that every decomposition hands over the serial shares.
    // Only where the cells' gas holds the gap: an overlap larger than a
    // cell's gas area (the fluid fractions are the last step's, from
    // before the view opened the joint) would put the gap's gas into a
    // sliver (benchBlast: 15000 kg/m3 and negative pressure in a cut cell
    // at the hole), and the gap's gas goes to one cell by the point rule
    const scalarField* phi = fluid.fluidFractionField();
    const scalarField& cellArea = projection_.cellArea();
    DynamicList<label> cells;
    DynamicList<scalar> areas;
    scalarList total(released_.size(), Zero);
    labelList misfit(released_.size(), Zero);
    labelList cellStart(released_.size() + 1, Zero);
    DynamicList<vector2D> gap(4);
    forAll(released_, r)
    {
        const jointNodeList& jn = topo.jointNodes()[released_[r].first];
        gap.clear();
        for (const label k : {0, 2, 3, 1}) gap.append(x[jn[k]]);
        const label c0 = cells.size();
        projection_.overlapsOf(gap, cells, areas);
        label n = c0;
        for (label k = c0; k < cells.size(); ++k)
        {
            const scalar gasArea =
                (phi ? (*phi)[cells[k]] : 1)*cellArea[cells[k]];
            if (!(gasArea > 0)) continue;
            if (areas[k] > gasArea*(1 + 1e-9)) misfit[r] = 1;
            cells[n] = cells[k];
            areas[n++] = areas[k];
            total[r] += areas[n - 1];
        }
        cells.setSize(n);
        areas.setSize(n);
        cellStart[r + 1] = n;
    }
    Pstream::listCombineGather(total, plusEqOp<scalar>());
    Pstream::listCombineScatter(total);
    Pstream::listCombineGather(misfit, maxEqOp<label>());
    Pstream::listCombineScatter(misfit);
    DynamicList<label> byPoint;
    forAll(released_, r)
    {
        if (!(total[r] > 0) || misfit[r])
        {
            byPoint.append(r);
            continue;
        }
        const ductNetwork::content& c = released_[r].second;
        for (label k = cellStart[r]; k < cellStart[r + 1]; ++k)
        {
            const scalar w = areas[k]/total[r];
            givenCell_.append(cells[k]);
            given_.append({w*c.m, w*c.mE, w*c.aV, w*c.m1, w*c.mU});
        }
    }
    handOverAtPoints(x, topo, phi, byPoint);
}


void Foam::crackGasCoupling::handOverAtPoints
(
    const UList<vector2D>& x,
    const jointTopology& topo,
    const scalarField* phi,
    const labelUList& released
)
{
    // A gap that overlaps no cell with gas (twisted to no area, or over
    // cells the solid covers): into the fluid cell with gas at its
    // midpoint, else at one of its nodes (the crack opened to the gas runs
    // through them); of the cells holding the first such point, the best
    // (most gas, then lowest centre): the same cell on any decomposition.
    // Every rank calls this (bestOverRanks reduces)
    const label nPts = 5;
    cellKeys_.setSize(nPts*released.size());
    forAll(released, i)
    {
        const jointNodeList& jn =
            topo.jointNodes()[released_[released[i]].first];
        const vector2D at[nPts] =
        {
            0.25*(x[jn[0]] + x[jn[1]] + x[jn[2]] + x[jn[3]]),
            x[jn[0]], x[jn[1]], x[jn[2]], x[jn[3]]
        };
        for (label k = 0; k < nPts; ++k)
        {
            cellKeys_[nPts*i + k] = containingKey(at[k], phi);
        }
    }
    bestOverRanks(cellKeys_);
    forAll(released, i)
    {
        const ductNetwork::content& c = released_[released[i]].second;
        label k = 0;
        while (k < nPts && cellKeys_[nPts*i + k].x() < 0) ++k;
        if (k == nPts)
        {
            lostMass_ += c.m;
            lostEnergy_ += c.mE;
            continue;
        }
        const label ci = cellOfKey(cellKeys_[nPts*i + k]);
        if (ci >= 0)
        {
            givenCell_.append(ci);
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
    DynamicList<FixedList<label, 2>>& ends = candidates_;
    ends.clear();
    candidatePoint_.clear();
    forAll(net_.joints(), i)
    {
        const jointNodeList& jn = cv.topology().jointNodes()[net_.joints()[i]];
        for (const label e : {0, 1})
        {
            const label pt = pointOfNode[jn[e]];
            if (!onOutline_[pt]) continue;
            ends.append(FixedList<label, 2>({i, e}));
            candidatePoint_.append(cv.points()[pt]);
        }
    }
    // The best cell holding each end (over all ranks), then the plenum
    // that cell's rank chooses for it (its neighbours across processor
    // faces included), then the rank that holds the plenum takes the mouth
    cellKeys_.setSize(ends.size());
    forAll(ends, k)
    {
        cellKeys_[k] = containingKey(candidatePoint_[k], phi);
    }
    bestOverRanks(cellKeys_);
    swapNeighbours(phi);
    plenumKeys_.setSize(ends.size());
    forAll(ends, k)
    {
        const label c = cellOfKey(cellKeys_[k]);
        plenumKeys_[k] = c >= 0 ? plenumKey(fluid, c) : noCell();
    }
    bestOverRanks(plenumKeys_);
    mouths_.clear();
    mouthCell_.clear();
    forAll(ends, k)
    {
        if (plenumKeys_[k].x() < 0) continue;
        mouths_.append(ends[k]);
        mouthCell_.append(cellOfKey(plenumKeys_[k]));
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


Foam::vector Foam::crackGasCoupling::plenumKey
(
    const blastFluidSolver& fluid,
    const label c
) const
{
    // A small cut cell is a poor plenum: a sliver's state follows its
    // neighbours' (the small-cell treatment), and the little gas it holds
    // would cap the mouth. Its neighbour through an open face with the
    // most gas stands for it (ties: the lowest centre, as any rank sees it)
    const scalarField* phi = fluid.fluidFractionField();
    const vector own = cellKey(phi, c);
    if (!phi || (*phi)[c] >= 0.5) return own;
    const label nInternal = mesh_.nInternalFaces();
    vector best = own;
    for (const label f : mesh_.cells()[c])
    {
        if (!(fluid.meshFaceAperture(f) > 0)) continue;
        vector k;
        if (f < nInternal)
        {
            const label nb =
                mesh_.faceOwner()[f] == c
              ? mesh_.faceNeighbour()[f] : mesh_.faceOwner()[f];
            k = cellKey(phi, nb);
        }
        else if
        (
            isA<processorPolyPatch>
            (
                mesh_.boundaryMesh()[mesh_.boundaryMesh().whichPatch(f)]
            )
        )
        {
            const label b = f - nInternal;
            k = vector(gasNbr_[b], centreNbr_[b].x(), centreNbr_[b].y());
        }
        else
        {
            continue;
        }
        if (k.x() > own.x() && better(k, best)) best = k;
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


namespace
{
using namespace Foam;

//- The smaller of two (sub-step limit, bound) pairs: the limit of
//  Foam::min (b where !(a < b)), so that the limit is the one minOp gives;
//  of equal limits the first bound in crackNetwork::subStepBound's order
struct smallestLimitOp
{
    vector2D operator()(const vector2D& a, const vector2D& b) const
    {
        if (a.x() == b.x()) return a.y() <= b.y() ? a : b;
        return a.x() < b.x() ? a : b;
    }
};

//- The network's sub-steps on a partitioned solid: each rank runs the
//  control volumes and voids with a node it owns (crackNetwork::restrictTo).
//  Usually every node they read is in the rank's local solid (owned, or
//  halo: the halo exchange after every step brings their positions,
//  velocities and work displacements from their owners), and the network
//  reads and pushes the local solid's lists directly
//  (crackNetwork::readLocal). Otherwise (some rank reads a node outside its
//  halo, or debug switch 1 of crackGasCoupling) it runs on the copy of the
//  whole solid: the nodes read are copied in from the local solid, those a
//  rank does not own gathered from their owners (two gathers per
//  sub-step), and its forces copied back. The sub-step is the smallest
//  over the ranks
class partitionedSubSteps
:
    public femdemSolid::subStepHook
{
    crackNetwork& net_;
    crackNetwork::subSteps inner_;
    const UList<vector2D>& otherForces_;
    const femdemPartition& partition_;
    femdemSolid& copy_;
    //- Every read node in the local solid on every rank: the network
    //  reads the local solid
    bool direct_;
    //- Otherwise, the read nodes this rank takes from its local solid:
    //  global and local numbers
    labelList ownGlobal_, ownLocal_;
    //- Read nodes some rank does not own (the same list on every rank):
    //  global and local numbers
    labelList shared_, sharedLocal_;
    //- Local nodes whose force the network may set: global and local
    labelList forceGlobal_, forceLocal_;
    List<vector2D> buf_, buf2_;
    bool first_;

    //- The copy's read nodes from the local solid and their owners
    void copyIn(const femdemSolid& local)
    {
        List<vector2D>& x = copy_.xRef();
        List<vector2D>& v = copy_.vRef();
        forAll(ownGlobal_, i)
        {
            x[ownGlobal_[i]] = local.x()[ownLocal_[i]];
            v[ownGlobal_[i]] = local.v()[ownLocal_[i]];
        }
        // (shared_ is the same list on every rank: all or none gather)
        if (shared_.size())
        {
            partition_.gatherSubset(sharedLocal_, local.x(), local.v(), buf2_);
            const label n = shared_.size();
            forAll(shared_, i)
            {
                x[shared_[i]] = buf2_[i];
                v[shared_[i]] = buf2_[n + i];
            }
        }
    }

    //- The local solid's forces: all at the first sub-step (the other
    //  forces, held over the interval), then the network's nodes
    void copyForcesOut(femdemSolid& local)
    {
        const List<vector2D>& F = copy_.externalForce();
        List<vector2D>& f = local.externalForce();
        if (first_)
        {
            const labelList& g = partition_.globalTriangles();
            forAll(g, t)
            {
                for (label k = 0; k < 3; ++k) f[3*t + k] = F[3*g[t] + k];
            }
        }
        else
        {
            forAll(forceGlobal_, i) f[forceLocal_[i]] = F[forceGlobal_[i]];
        }
    }

    //- The network's limit on the local solid (direct_)
    scalar localLimit(femdemSolid& local, crackNetwork::subStepBound& b)
    {
        List<vector2D>& f = local.externalForce();
        if (first_)
        {
            // The step's start on the whole copy (the local solid's state,
            // the work displacement zero in both), then the local solid's
            // forces start from the other forces
            net_.beginStep(copy_.x(), copy_.workDisplacement());
            net_.readLocal(partition_.localTriangles());
            const labelList& g = partition_.globalTriangles();
            forAll(g, t)
            {
                for (label k = 0; k < 3; ++k)
                {
                    f[3*t + k] = otherForces_[3*g[t] + k];
                }
            }
        }
        net_.updateForces(local.x(), f);
        return net_.stableSubStep(local.v(), local.invMass(), &b);
    }

public:

    partitionedSubSteps
    (
        crackNetwork& net,
        const UList<vector2D>& otherForces,
        const femdemPartition& partition,
        femdemSolid& copy
    )
    :
        net_(net),
        inner_(net, otherForces),
        otherForces_(otherForces),
        partition_(partition),
        copy_(copy),
        direct_(false),
        first_(true)
    {
        const labelList& owner = partition.triangleOwner();
        const label me = Pstream::myProcNo();
        const labelList read(net.restrictTo(owner, me));
        const labelList local(partition.localNodes(read));
        // Every read node in the reader's halo (the usual case: the
        // network's nodes are vertex neighbours of an owned triangle)
        bool allLocal = !(crackGasCoupling::debug & 1);
        for (const label l : local) allLocal = allLocal && l >= 0;
        reduce(allLocal, andOp<bool>());
        if (allLocal)
        {
            direct_ = true;
            return;
        }
        DynamicList<label> og, ol, fg, fl, notMine;
        forAll(read, i)
        {
            if (local[i] >= 0)
            {
                fg.append(read[i]);
                fl.append(local[i]);
            }
            if (owner[read[i]/3] == me)
            {
                og.append(read[i]);
                ol.append(local[i]);
            }
            else
            {
                notMine.append(read[i]);
            }
        }
        ownGlobal_.transfer(og);
        ownLocal_.transfer(ol);
        forceGlobal_.transfer(fg);
        forceLocal_.transfer(fl);
        // The union over the ranks of what each does not own
        List<labelList> all(Pstream::nProcs());
        all[me].transfer(notMine);
        Pstream::gatherList(all);
        Pstream::scatterList(all);
        DynamicList<label> u;
        for (const labelList& l : all) u.append(l);
        Foam::sort(u);
        label m = 0;
        forAll(u, i)
        {
            if (i == 0 || u[i] != u[m - 1]) u[m++] = u[i];
        }
        u.setSize(m);
        shared_.transfer(u);
        sharedLocal_ = partition.localNodes(shared_);
        buf_.setSize(shared_.size());
        buf2_.setSize(2*shared_.size());
    }

    //- Nodes exchanged every sub-step
    label nShared() const { return shared_.size(); }

    virtual scalar beforeSubStep(femdemSolid& local)
    {
        // The forces (the other forces plus the network's); the limit and
        // what bounds it, the smallest over the ranks (the same count on
        // every rank). The limit first: it sets b
        crackNetwork::subStepBound b = crackNetwork::subStepBound::solid;
        scalar hLocal;
        if (direct_)
        {
            hLocal = localLimit(local, b);
        }
        else
        {
            copyIn(local);
            hLocal = inner_.limit(copy_, b);
            copyForcesOut(local);
        }
        first_ = false;
        vector2D hb(hLocal, scalar(label(b)));
        reduce(hb, smallestLimitOp());
        const scalar h = hb.x();
        net_.countSubStep
        (
            h, crackNetwork::subStepBound(label(hb.y())),
            local.stableTimeStep()
        );
        return h;
    }

    virtual void afterSubStep(const femdemSolid& local)
    {
        const List<vector2D>& dl = local.workDisplacement();
        if (direct_)
        {
            net_.addWork(dl);
            return;
        }
        List<vector2D>& d = copy_.workDisplacementRef();
        forAll(ownGlobal_, i) d[ownGlobal_[i]] = dl[ownLocal_[i]];
        if (shared_.size())
        {
            partition_.gatherSubset(sharedLocal_, dl, buf_);
            forAll(shared_, i) d[shared_[i]] = buf_[i];
        }
        inner_.afterSubStep(copy_);
    }
};

} // End anonymous namespace


Foam::label Foam::crackGasCoupling::advanceSolid
(
    femdemPartition& partition,
    femdemSolid& copy,
    const List<vector2D>& otherForces,
    const scalar dt
)
{
    // The network's work in the balancing's weights (it runs inside the
    // sub-steps, where the solid's own weights do not see it), then the
    // halo rebuilt: the hook takes the local node numbers
    setPartitionWeights(partition);
    partition.update();
    // The copy's work displacement starts from zero, as the local solid's
    copy.workDisplacementRef() = Zero;
    label n = 0;
    {
        partitionedSubSteps hook(net_, otherForces, partition, copy);
        if (net_.nRun() > maxRun_)
        {
            maxRun_ = net_.nRun();
            maxRunOf_ = net_.joints().size();
        }
        maxShared_ = max(maxShared_, hook.nShared());
        n = partition.advance(dt, hook);
    }
    partition.syncCopy(copy);
    net_.shareWork(partition.triangleOwner());
    net_.unrestrict();
    net_.distributeGas(partition.triangleOwner());
    net_.endStep(copy.x(), dt);
    return n;
}


void Foam::crackGasCoupling::setPartitionWeights(femdemPartition& partition)
{
    if (!(partitionWeight_ > 0)) return;
    // Half a control volume's work to each triangle of its joint: its
    // sub-steps run on the ranks owning a node of it, its gas step on the
    // owner of the first triangle
    const jointTopology& topo = partition.globalTopology();
    const label half = label(std::round(0.5*partitionWeight_));
    weights_.setSize(partition.triangleOwner().size());
    weights_ = 0;
    for (const label j : net_.joints())
    {
        weights_[topo.jointTriangleA()[j]] += half;
        weights_[topo.jointTriangleB()[j]] += half;
    }
    partition.setExtraWeights(weights_);
}


void Foam::crackGasCoupling::reportSubSteps() const
{
    // (the counts are the same on every rank)
    const FixedList<label, crackNetwork::nSubStepBounds>& n =
        net_.subStepBounds();
    label total = 0;
    for (const label c : n) total += c;
    Info<< "Crack gas: solid sub-steps " << total << ", bound by";
    forAll(n, i)
    {
        Info<< (i ? ", " : " ")
            << crackNetwork::subStepBoundNames[crackNetwork::subStepBound(i)]
            << " " << n[i] << " ("
            << (total > 0 ? 100.0*n[i]/total : 0) << " %)";
    }
    Info<< nl;
}


void Foam::crackGasCoupling::reportPartition() const
{
    // The rank that ran the largest share
    scalar share = maxRunOf_ > 0 ? scalar(maxRun_)/maxRunOf_ : 0;
    share = returnReduce(share, maxOp<scalar>());
    Info<< "Crack gas on the partitioned solid: one rank ran at most "
        << 100*share << " % of the network's control volumes in its"
        << " sub-steps; nodes exchanged per sub-step at most " << maxShared_
        << nl;
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


void Foam::crackGasCoupling::writeState(const fileName& file) const
{
    mkDir(file.path());
    OFstream os(file);
    // OpenFOAM's header (a time directory's uniform/ file)
    IOobject(file.name(), mesh_.time().timeName(), "uniform", mesh_)
        .writeHeader(os, "dictionary");
    net_.writeState(os);
    const int oldPrecision = os.precision(17);
    os.writeEntry("lostMass", lostMass_);
    os.writeEntry("lostEnergy", lostEnergy_);
    os.precision(oldPrecision);
}


bool Foam::crackGasCoupling::readState
(
    const fileName& file,
    const UList<vector2D>& x,
    const boolList& broken
)
{
    if (!isFile(file))
    {
        return false;
    }
    IFstream is(file);
    const dictionary dict(is);
    // Duplicates, numbers, list sizes
    caseChecks::checkInput(dict);
    net_.readState(dict, x);
    for (const label j : net_.joints())
    {
        if (!broken[j])
        {
            FatalIOErrorInFunction(dict)
                << "entry 'joints': joint " << j << " holds crack gas but is"
                << " not broken in the solid's state: the crack gas and the"
                << " solid are of different times or runs"
                << exit(FatalIOError);
        }
    }
    lostMass_ = dict.get<scalar>("lostMass");
    lostEnergy_ = dict.get<scalar>("lostEnergy");
    if (!(lostMass_ >= 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'lostMass' is " << lostMass_ << "; it sums masses and"
            << " must be >= 0" << exit(FatalIOError);
    }
    return true;
}


// ************************************************************************* //

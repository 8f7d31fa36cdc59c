/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemPartition.H"
#include "solidMeshRenumber.H"
#include "contactLaw.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
#include "PstreamReduceOps.H"
#include "DynamicList.H"
#include "ListOps.H"
#include "clockValue.H"
#include <algorithm>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(femdemPartition, 0);
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

// Message tag of the per-step exchange
constexpr int haloTag = 4711;

struct box
{
    vector2D lo, hi;
};

// Box of triangle t of the nodes x (3 per triangle)
box triangleBox(const UList<vector2D>& x, const label t)
{
    box b{x[3*t], x[3*t]};
    for (label k = 1; k < 3; ++k)
    {
        b.lo = min(b.lo, x[3*t + k]);
        b.hi = max(b.hi, x[3*t + k]);
    }
    return b;
}

scalar longestEdge(const triangleMesh& mesh)
{
    scalar l = 0;
    for (const triangleVertices& v : mesh.triangles())
    {
        for (label k = 0; k < 3; ++k)
        {
            l = max(l, mag(mesh.points()[v[(k + 1) % 3]] - mesh.points()[v[k]]));
        }
    }
    return l;
}

//- x = max(x, y), a NaN in either wins
struct maxOrNaNEqOp
{
    void operator()(scalar& x, const scalar& y) const
    {
        x = (x != x || y <= x) ? x : y;
    }
};

template<class Type>
std::size_t bytes(const UList<Type>& list)
{
    return std::size_t(list.size())*sizeof(Type);
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::labelList Foam::femdemPartition::haloTriangles
(
    const UList<vector2D>& x
) const
{
    const triangleMesh& mesh = globalMesh_;
    const labelList& owner = owner_;
    const label me = Pstream::myProcNo();
    const List<triangleVertices>& tris = mesh.triangles();
    const label nTri = tris.size();
    List<bool> inHalo(nTri, false);

    // Vertex neighbours: the joints of the owned triangles and the fan of a
    // patch vertex (femdemSolid constrains every node at a patch vertex)
    forAll(tris, t)
    {
        if (owner[t] != me) continue;
        for (label k = 0; k < 3; ++k)
        {
            for (const label n : pointTriangles_[tris[t][k]])
            {
                inHalo[n] = true;
            }
        }
    }

    // Contact range: boxes within haloWidth (in x and in y) of an owned
    // triangle's box. Owned triangles binned by centroid in cells of
    // haloWidth + the largest box extent: a partner's centroid lies in the
    // 3 x 3 cells around the candidate's
    List<box> boxes(nTri);
    box all{vector2D(GREAT, GREAT), vector2D(-GREAT, -GREAT)};
    scalar extent = 0;
    forAll(tris, t)
    {
        boxes[t] = triangleBox(x, t);
        all.lo = min(all.lo, boxes[t].lo);
        all.hi = max(all.hi, boxes[t].hi);
        extent = max(extent, cmptMax(boxes[t].hi - boxes[t].lo));
    }
    scalar cs = haloWidth_ + extent;
    const vector2D span = all.hi - all.lo;
    // At most about 4 cells per triangle (a halo far smaller than the mesh)
    while ((span.x()/cs + 1)*(span.y()/cs + 1) > 4*nTri + 16) cs *= 2;
    const label nx = label(span.x()/cs) + 1, ny = label(span.y()/cs) + 1;
    auto cellOf = [&](const label t, label& ix, label& iy)
    {
        const vector2D c = 0.5*(boxes[t].lo + boxes[t].hi) - all.lo;
        ix = min(label(c.x()/cs), nx - 1);
        iy = min(label(c.y()/cs), ny - 1);
    };
    labelList cellStart(nx*ny + 1, Zero);
    forAll(tris, t)
    {
        if (owner[t] != me) continue;
        label ix, iy;
        cellOf(t, ix, iy);
        ++cellStart[iy*nx + ix + 1];
    }
    for (label c = 0; c < nx*ny; ++c) cellStart[c + 1] += cellStart[c];
    labelList cellTris(cellStart[nx*ny]);
    {
        labelList fill(SubList<label>(cellStart, nx*ny));
        forAll(tris, t)
        {
            if (owner[t] != me) continue;
            label ix, iy;
            cellOf(t, ix, iy);
            cellTris[fill[iy*nx + ix]++] = t;
        }
    }
    // The gap to the nearest owned box (the larger of its x and y gaps),
    // looked for until one within haloWidth/2 is found
    auto ownedGap = [&](const label t)
    {
        label ix, iy;
        cellOf(t, ix, iy);
        const box& a = boxes[t];
        scalar d = GREAT;
        for (label jy = max(iy - 1, 0); jy <= min(iy + 1, ny - 1); ++jy)
        {
            for (label jx = max(ix - 1, 0); jx <= min(ix + 1, nx - 1); ++jx)
            {
                const label c = jy*nx + jx;
                for (label i = cellStart[c]; i < cellStart[c + 1]; ++i)
                {
                    const box& b = boxes[cellTris[i]];
                    d = min(d, cmptMax(max(a.lo - b.hi, b.lo - a.hi)));
                    if (d <= 0.5*haloWidth_) return d;
                }
            }
        }
        return d;
    };
    // A triangle within haloWidth/2 can touch an owned one before the next
    // rebuild; if it has a free face it is then a contact partner, so its
    // free faces must be the whole solid's: its edge neighbours are in the
    // halo too, with the joints between them (a triangle at the halo's
    // outer edge has free faces the whole solid does not have). With the
    // default haloWidth (2 x the longest edge) they are already within it
    List<bool> near(nTri, false);
    forAll(tris, t)
    {
        if (owner[t] == me) continue;
        const scalar d = ownedGap(t);
        inHalo[t] = inHalo[t] || d <= haloWidth_;
        near[t] = d <= 0.5*haloWidth_;
    }
    const labelList& edgeJoint = globalTopo_.edgeJoint();
    forAll(tris, t)
    {
        if (!near[t]) continue;
        for (label k = 0; k < 3; ++k)
        {
            const label j = edgeJoint[3*t + k];
            if (j < 0) continue;
            const label tA = globalTopo_.jointTriangleA()[j];
            const label n = tA == t ? globalTopo_.jointTriangleB()[j] : tA;
            if (owner[n] != me) inHalo[n] = true;
        }
    }

    DynamicList<label> halo;
    forAll(tris, t)
    {
        if (inHalo[t] && owner[t] != me) halo.append(t);
    }
    labelList result;
    result.transfer(halo);
    return result;
}


void Foam::femdemPartition::setExchange()
{
    const labelList& owner = owner_;
    const label me = Pstream::myProcNo();
    const label nProcs = Pstream::nProcs();
    const labelList& globalToLocal = localTriangle_;

    // What each rank needs from each owner (global indices, ascending)
    List<DynamicList<label>> need(nProcs);
    List<DynamicList<label>> recv(nProcs);
    forAll(globalTriangle_, t)
    {
        if (owned_[t]) continue;
        const label g = globalTriangle_[t];
        need[owner[g]].append(g);
        recv[owner[g]].append(t);
    }

    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (proc == me) continue;
        UOPstream os(proc, pBufs);
        os << labelList(need[proc]);
    }
    pBufs.finishedSends();

    DynamicList<label> procs;
    DynamicList<labelList> sends, recvs;
    for (label proc = 0; proc < nProcs; ++proc)
    {
        if (proc == me) continue;
        UIPstream is(proc, pBufs);
        labelList wanted(is);
        for (label& g : wanted)
        {
            const label t = globalToLocal[g];
            if (t < 0 || !owned_[t])
            {
                FatalErrorInFunction
                    << "rank " << proc << " asks rank " << me
                    << " for triangle " << g << ", which it does not own"
                    << exit(FatalError);
            }
            g = t;
        }
        if (wanted.size() || recv[proc].size())
        {
            procs.append(proc);
            sends.append(wanted);
            recvs.append(labelList(recv[proc]));
        }
    }
    procs_.transfer(procs);
    sendTriangles_.transfer(sends);
    recvTriangles_.transfer(recvs);
    sendBuf_.setSize(procs_.size());
    recvBuf_.setSize(procs_.size());
    forAll(procs_, i)
    {
        sendBuf_[i].setSize(6*sendTriangles_[i].size());
        recvBuf_[i].setSize(6*recvTriangles_[i].size());
    }
}


Foam::dictionary Foam::femdemPartition::localDict
(
    const dictionary& dict
) const
{
    dictionary local(dict);
    if (!dict.isDict("boundaryConditions"))
    {
        return local;
    }
    dictionary& bcs = local.subDict("boundaryConditions");
    for (const word& key : dict.subDict("boundaryConditions").toc())
    {
        const label patchi = mesh_.findPatch(key);
        // An unknown patch stays: the local solid reports it
        if (patchi >= 0 && mesh_.patchEdges()[patchi].empty())
        {
            bcs.remove(key);
        }
    }
    return local;
}


Foam::scalar Foam::femdemPartition::maxDisplacement() const
{
    const List<vector2D>& x = solid_->x();
    scalar d2 = 0;
    forAll(owned_, t)
    {
        if (!owned_[t]) continue;
        for (label k = 0; k < 3; ++k)
        {
            d2 = max(d2, magSqr(x[3*t + k] - x0_[3*t + k]));
        }
    }
    return returnReduce(std::sqrt(d2), maxOp<scalar>());
}


void Foam::femdemPartition::build(const UList<vector2D>& x)
{
    // Owned and halo triangles in ascending global order
    const label me = Pstream::myProcNo();
    const labelList halo = haloTriangles(x);
    globalTriangle_.setSize
    (
        halo.size() + std::count(owner_.begin(), owner_.end(), me)
    );
    owned_.setSize(globalTriangle_.size());
    label t = 0, h = 0;
    forAll(owner_, g)
    {
        const bool mine = owner_[g] == me;
        const bool inHalo = h < halo.size() && halo[h] == g;
        if (!mine && !inHalo) continue;
        if (inHalo) ++h;
        globalTriangle_[t] = g;
        owned_[t] = mine;
        ++t;
    }
    nOwned_ = std::count(owned_.begin(), owned_.end(), true);
    localTriangle_.setSize(nGlobal_);
    localTriangle_ = -1;
    forAll(globalTriangle_, t)
    {
        localTriangle_[globalTriangle_[t]] = t;
    }

    mesh_ = solidMeshRenumber::subset(globalMesh_, globalTriangle_);
    // A local part never becomes the active solid (function objects read
    // the whole one: a copy of it, when the solver holds one) unless the
    // part it replaces was
    const femdemSolid* active = femdemSolid::active();
    const bool keepActive = active && active != solid_.get();
    solid_.reset(new femdemSolid(mesh_, localDict(dict_)));
    if (keepActive)
    {
        femdemSolid::setActive(active);
    }
    // Every node and joint counted in the budget of exactly one rank
    solid_->setBudgetShare(owned_);
    if (trackWork_)
    {
        solid_->trackWorkDisplacement();
    }
    setExchange();
    x0_ = solid_->x();
    moveBound_ = 0;
    tLast_ = solid_->time();
    solid_->setHaloExchange(this);
}


void Foam::femdemPartition::readBalance(const dictionary& dict)
{
    const dictionary& pd = dict.subOrEmptyDict("partition");
    balance_ = pd.getOrDefault<bool>("balance", true);
    maxImbalance_ = pd.getOrDefault<scalar>("maxImbalance", 0.1);
    pairWeight_ = pd.getOrDefault<scalar>("contactPairWeight", 1);
    balanceInterval_ = pd.getOrDefault<label>("balanceInterval", 100);
    auto bad = [&](const word& key, const scalar value, const char* need)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'partition." << key << "' must be " << need
            << ", got " << value << exit(FatalIOError);
    };
    if (!(maxImbalance_ > 0)) bad("maxImbalance", maxImbalance_, "positive");
    if (!(pairWeight_ >= 0 && pairWeight_ <= 1000))
    {
        bad("contactPairWeight", pairWeight_, "in [0, 1000]");
    }
    if (balanceInterval_ < 1) bad("balanceInterval", scalar(balanceInterval_), ">= 1");
}


Foam::labelList Foam::femdemPartition::ownedWeights() const
{
    labelList count(globalTriangle_.size(), Zero);
    solid_->contact().addPairCounts(count);
    const bool extra = extraWeight_.size() == nGlobal_;
    forAll(count, t)
    {
        count[t] =
            owned_[t]
          ? 10 + label(std::round(5*pairWeight_*count[t]))
          + (extra ? extraWeight_[globalTriangle_[t]] : 0)
          : 0;
    }
    return count;
}


void Foam::femdemPartition::setExtraWeights(const labelUList& w)
{
    if (w.size() && w.size() != nGlobal_)
    {
        FatalErrorInFunction
            << w.size() << " extra work weights for a solid of " << nGlobal_
            << " triangles" << exit(FatalError);
    }
    extraWeight_ = w;
}


Foam::scalar Foam::femdemPartition::imbalance() const
{
    const labelList w = ownedWeights();
    scalar mine = 0;
    for (const label x : w) mine += x;
    const scalar most = returnReduce(mine, maxOp<scalar>());
    const scalar mean = returnReduce(mine, sumOp<scalar>())/Pstream::nProcs();
    return mean > 0 ? most/mean : 1;
}


void Foam::femdemPartition::checkBalance()
{
    if (!balance_ || !Pstream::parRun() || Pstream::nProcs() < 2) return;
    // The same sub-step count on every rank: every rank checks alike
    const label block = solid_->timeIndex()/balanceInterval_;
    if (block == balanceBlock_) return;
    balanceBlock_ = block;
    const scalar imb = imbalance();
    if (imb > 1 + maxImbalance_ && imb > 1.02*balancedImbalance_)
    {
        Info<< "Solid partition: work imbalance " << imb - 1
            << " (largest rank over the mean - 1, entry partition.maxImbalance "
            << maxImbalance_ << ") at time " << solid_->time()
            << ": repartitioned at the next halo rebuild" << endl;
        repartition_ = true;
        rebuild_ = true;
    }
}


void Foam::femdemPartition::repartition()
{
    // The weights in global order on the master
    const labelList local = ownedWeights();
    labelList w(nGlobal_, Zero);
    forAll(local, t)
    {
        if (owned_[t]) w[globalTriangle_[t]] = local[t];
    }
    Pstream::listCombineGather(w, plusEqOp<label>());

    const label nProcs = Pstream::nProcs();
    labelList owner;
    scalar balanced = 1;
    label moved = 0;
    if (Pstream::master())
    {
        const labelList part = solidMeshRenumber::partition
        (
            globalMesh_, nProcs, w
        );
        // Parts to ranks by the largest overlap of work first, so that as
        // little as possible migrates (METIS numbers its parts freely)
        List<scalar> overlap(nProcs*nProcs, Zero);
        forAll(part, t) overlap[part[t]*nProcs + owner_[t]] += w[t];
        labelList rankOf(nProcs, -1);
        boolList rankTaken(nProcs, false);
        for (label k = 0; k < nProcs; ++k)
        {
            label best = -1;
            forAll(overlap, i)
            {
                if
                (
                    rankOf[i/nProcs] < 0 && !rankTaken[i % nProcs]
                 && (best < 0 || overlap[i] > overlap[best])
                )
                {
                    best = i;
                }
            }
            rankOf[best/nProcs] = best % nProcs;
            rankTaken[best % nProcs] = true;
        }
        owner.setSize(nGlobal_);
        scalarList sums(nProcs, Zero);
        forAll(part, t)
        {
            owner[t] = rankOf[part[t]];
            sums[owner[t]] += w[t];
            moved += owner[t] != owner_[t];
        }
        balanced = max(sums)/(sum(sums)/nProcs);
    }
    Pstream::scatter(owner);
    Pstream::scatter(balanced);
    Pstream::scatter(moved);
    owner_.transfer(owner);
    balancedImbalance_ = balanced;
    ++nRepartitions_;
    nMigrated_ += moved;
    repartition_ = false;
    Info<< "Solid partition: repartitioned by METIS at time "
        << solid_->time() << ": " << moved << " triangles migrate, work"
        << " imbalance now " << balanced - 1 << endl;
}


void Foam::femdemPartition::rebuild()
{
    const clockValue t0(clockValue::now());
    // The state, global, from the owners; the accounts stay with the rank
    // (only their sums over the ranks mean anything)
    const List<vector2D> X = gatherNodes(solid_->x());
    const List<vector2D> V = gatherNodes(solid_->v());
    const scalarList damage = gatherJoints(solid_->jointDamage());
    const boolList broken = gatherBroken();
    const scalarList acc = solid_->energyAccounts();
    // New owners, from the work of the present owners' solids
    if (repartition_)
    {
        repartition();
    }
    setGlobalState
    (
        X, V, damage, broken, solid_->time(), solid_->timeIndex(),
        solid_->timeSteps()
    );
    solid_->setEnergyAccounts(acc);
    ++nRebuilds_;
    rebuildTime_ += t0.elapsed();
    if (debug)
    {
        Pout<< "femdemPartition: halo rebuilt at time " << solid_->time()
            << ": " << nOwned_ << " owned, " << nHalo() << " halo triangles"
            << endl;
    }
}


void Foam::femdemPartition::setGlobalState
(
    const UList<vector2D>& X,
    const UList<vector2D>& V,
    const UList<scalar>& damage,
    const UList<bool>& broken,
    const scalar time,
    const label timeIndex,
    const FixedList<scalar, 2>& timeSteps
)
{
    // New halo and local solid at the present positions, with the state
    build(X);
    const label n = globalTriangle_.size();
    List<vector2D> x(3*n), v(3*n);
    forAll(globalTriangle_, t)
    {
        for (label k = 0; k < 3; ++k)
        {
            x[3*t + k] = X[3*globalTriangle_[t] + k];
            v[3*t + k] = V[3*globalTriangle_[t] + k];
        }
    }
    const jointTopology& topo = solid_->topology();
    scalarList d(topo.nJoints());
    boolList b(topo.nJoints());
    forAll(d, j)
    {
        const label g = globalTopo_.edgeJoint()
        [
            3*globalTriangle_[topo.jointTriangleA()[j]] + topo.jointEdgeA()[j]
        ];
        d[j] = damage[g];
        b[j] = broken[g];
    }
    solid_->setState(x, v, d, b, time, timeIndex);
    solid_->restoreTimeSteps(timeSteps);
    x0_ = solid_->x();
    tLast_ = time;
    rebuild_ = false;
}


Foam::scalar Foam::femdemPartition::makeStepGlobal(femdemSolid& solid)
{
    // Each a largest over triangles or nodes: the global value is the
    // largest over the ranks, all in one gather and scatter (one message
    // each way per tree level, not one reduction per value). A NaN (a
    // diverging solid) wins, so that every rank stops
    const FixedList<scalar, 6> mine = stepData(solid);
    List<scalar> d(mine.begin(), mine.end());
    Pstream::listCombineGather(d, maxOrNaNEqOp());
    Pstream::listCombineScatter(d);
    FixedList<scalar, 6> all;
    forAll(all, i) all[i] = d[i];
    setStepData(solid, all);
    return all[3];
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::femdemPartition::femdemPartition
(
    const triangleMesh& mesh,
    const dictionary& dict,
    const labelList& owner
)
:
    haloWidth_
    (
        dict.subOrEmptyDict("partition").getOrDefault<scalar>
        (
            "haloWidth", 2*longestEdge(mesh)
        )
    ),
    nOwned_(0),
    nGlobal_(mesh.nTriangles()),
    globalMesh_(mesh),
    globalTopo_(mesh),
    owner_(owner),
    pointTriangles_(),
    dict_(dict),
    moveBound_(0),
    tLast_(0),
    nChecks_(0),
    nRebuilds_(0),
    rebuild_(false),
    exchangeTime_(0),
    rebuildTime_(0),
    trackWork_(false),
    balance_(true),
    maxImbalance_(0.1),
    pairWeight_(1),
    balanceInterval_(100),
    balanceBlock_(0),
    balancedImbalance_(1),
    repartition_(false),
    nRepartitions_(0),
    nMigrated_(0)
{
    readBalance(dict);
    if (!(haloWidth_ > 0))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'partition.haloWidth' must be positive, got "
            << haloWidth_ << exit(FatalIOError);
    }
    if (owner.size() != nGlobal_)
    {
        FatalErrorInFunction
            << owner.size() << " owners for " << nGlobal_ << " triangles"
            << exit(FatalError);
    }
    for (const label o : owner)
    {
        if (o < 0 || o >= Pstream::nProcs())
        {
            FatalErrorInFunction
                << "owner rank " << o << " outside 0.." << Pstream::nProcs() - 1
                << exit(FatalError);
        }
    }

    // The triangles at each point (the halo's vertex neighbours)
    invertManyToMany(mesh.nPoints(), mesh.triangles(), pointTriangles_);

    // The nodes at the mesh's points
    List<vector2D> x(3*nGlobal_);
    forAll(mesh.triangles(), t)
    {
        for (label k = 0; k < 3; ++k)
        {
            x[3*t + k] = mesh.points()[mesh.triangles()[t][k]];
        }
    }
    build(x);
    solid_->resetEnergyBudget();

    // The stable step of the start, global from the start
    makeStepGlobal(*solid_);
}


Foam::femdemPartition::femdemPartition
(
    const triangleMesh& mesh,
    const dictionary& dict
)
:
    femdemPartition
    (
        mesh,
        dict,
        solidMeshRenumber::partition(mesh, Pstream::nProcs())
    )
{}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::femdemPartition::~femdemPartition()
{
    if (solid_.valid())
    {
        solid_->setHaloExchange(nullptr);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::femdemPartition::bytesPerStep() const
{
    label b = 0;
    for (const List<vector2D>& buf : sendBuf_)
    {
        b += buf.byteSize();
    }
    return b;
}


Foam::label Foam::femdemPartition::advance(const scalar interval)
{
    // The rebuild a past advance() asked for, before this one: between
    // two advances the local solid keeps its last step (the staggered
    // joint energy of the budget needs it)
    update();
    return solid_->advance(interval);
}


Foam::label Foam::femdemPartition::advance
(
    const scalar interval,
    const UList<vector2D>& globalForce
)
{
    update();
    if (globalForce.size() != 3*nGlobal_)
    {
        FatalErrorInFunction
            << globalForce.size() << " nodal forces for a solid of "
            << 3*nGlobal_ << " nodes" << exit(FatalError);
    }
    List<vector2D>& f = solid_->externalForce();
    forAll(globalTriangle_, t)
    {
        const label g = globalTriangle_[t];
        for (label k = 0; k < 3; ++k)
        {
            f[3*t + k] = globalForce[3*g + k];
        }
    }
    return solid_->advance(interval);
}


void Foam::femdemPartition::update()
{
    checkBalance();
    if (rebuild_)
    {
        rebuild();
    }
}


Foam::label Foam::femdemPartition::advance
(
    const scalar interval,
    femdemSolid::subStepHook& hook
)
{
    update();
    return solid_->advance(interval, hook);
}


Foam::labelList Foam::femdemPartition::localNodes
(
    const labelList& globalNodes
) const
{
    labelList local(globalNodes.size(), -1);
    forAll(globalNodes, i)
    {
        const label t = localTriangle_[globalNodes[i]/3];
        if (t >= 0)
        {
            local[i] = 3*t + globalNodes[i]%3;
        }
    }
    return local;
}


void Foam::femdemPartition::gatherSubset
(
    const labelList& localNode,
    const UList<vector2D>& local,
    List<vector2D>& buf
) const
{
    // One contributor per entry (its owner): x + 0 = x, bitwise
    forAll(localNode, i)
    {
        const label n = localNode[i];
        buf[i] = n >= 0 && owned_[n/3] ? local[n] : vector2D::zero;
    }
    Pstream::listCombineGather(buf, plusEqOp<vector2D>());
    Pstream::listCombineScatter(buf);
}


void Foam::femdemPartition::gatherSubset
(
    const labelList& localNode,
    const UList<vector2D>& a,
    const UList<vector2D>& b,
    List<vector2D>& buf
) const
{
    const label n = localNode.size();
    forAll(localNode, i)
    {
        const label j = localNode[i];
        const bool mine = j >= 0 && owned_[j/3];
        buf[i] = mine ? a[j] : vector2D::zero;
        buf[n + i] = mine ? b[j] : vector2D::zero;
    }
    Pstream::listCombineGather(buf, plusEqOp<vector2D>());
    Pstream::listCombineScatter(buf);
}


void Foam::femdemPartition::trackWorkDisplacement()
{
    trackWork_ = true;
    solid_->trackWorkDisplacement();
}


void Foam::femdemPartition::writeMemory(Ostream& os) const
{
    const scalar local = returnReduce(scalar(localBytes()), maxOp<scalar>());
    os  << "local solid " << local/1e6
        << " MB (largest rank), copies of the whole mesh and joint topology "
        << scalar(globalBytes())/1e6 << " MB";
}


std::size_t Foam::femdemPartition::globalBytes() const
{
    std::size_t b =
        bytes(globalMesh_.points()) + bytes(globalMesh_.triangles())
      + bytes(globalMesh_.triangleMaterials())
      + bytes(globalTopo_.jointTriangleA()) + bytes(globalTopo_.jointEdgeA())
      + bytes(globalTopo_.jointTriangleB()) + bytes(globalTopo_.jointEdgeB())
      + bytes(globalTopo_.jointNodes()) + bytes(globalTopo_.edgeJoint())
      + bytes(globalTopo_.boundaryTriangle()) + bytes(globalTopo_.boundaryEdge())
      + bytes(globalTopo_.boundaryPatch()) + bytes(globalTopo_.nodeVertex())
      + bytes(globalTopo_.initialPoints()) + bytes(owner_)
      + bytes(globalTriangle_) + bytes(localTriangle_) + bytes(owned_)
      + bytes(x0_);
    for (const labelList& tris : pointTriangles_)
    {
        b += sizeof(tris) + bytes(tris);
    }
    forAll(procs_, i)
    {
        b += bytes(sendBuf_[i]) + bytes(recvBuf_[i])
          + bytes(sendTriangles_[i]) + bytes(recvTriangles_[i]);
    }
    return b;
}


Foam::List<Foam::vector2D> Foam::femdemPartition::gatherNodes
(
    const UList<vector2D>& local,
    const bool toAll
) const
{
    // Every entry has exactly one contributor: x + 0 = x, bitwise
    List<vector2D> x(3*nGlobal_, Zero);
    forAll(globalTriangle_, t)
    {
        if (!owned_[t]) continue;
        for (label k = 0; k < 3; ++k)
        {
            x[3*globalTriangle_[t] + k] = local[3*t + k];
        }
    }
    Pstream::listCombineGather(x, plusEqOp<vector2D>());
    if (toAll)
    {
        Pstream::listCombineScatter(x);
    }
    return x;
}


Foam::scalarList Foam::femdemPartition::gatherJoints
(
    const UList<scalar>& local,
    const bool toAll
) const
{
    // From the owner of the joint's first triangle (which holds the joint:
    // its other triangle shares a vertex with it); one contributor each
    scalarList values(globalTopo_.nJoints(), Zero);
    const jointTopology& topo = solid_->topology();
    forAll(local, j)
    {
        const label tA = topo.jointTriangleA()[j];
        const label g =
            globalTopo_.edgeJoint()[3*globalTriangle_[tA] + topo.jointEdgeA()[j]];
        if (owned_[tA])
        {
            values[g] = local[j];
        }
    }
    Pstream::listCombineGather(values, plusEqOp<scalar>());
    if (toAll)
    {
        Pstream::listCombineScatter(values);
    }
    return values;
}


Foam::boolList Foam::femdemPartition::gatherBroken(const bool toAll) const
{
    const boolList& local = solid_->jointBroken();
    scalarList value(local.size());
    forAll(local, j)
    {
        value[j] = local[j];
    }
    value = gatherJoints(value, toAll);
    boolList broken(value.size());
    forAll(broken, j)
    {
        broken[j] = value[j] != 0;
    }
    return broken;
}


void Foam::femdemPartition::afterStep(femdemSolid& solid)
{
    List<vector2D>& x = solid.xRef();
    List<vector2D>& v = solid.vRef();
    // With the work displacement tracked, the halo's too: computed here
    // from the local (incomplete) forces, the owners' is the one the crack
    // gas and the coupling pay with
    List<vector2D>& d = solid.workDisplacementRef();
    const bool withD = d.size() > 0;
    const label perNode = withD ? 3 : 2;

    const clockValue t0(clockValue::now());

    // Halo nodes from their owners: receives posted first, sends, wait
    const label start = UPstream::nRequests();
    forAll(procs_, i)
    {
        recvBuf_[i].setSize(3*perNode*recvTriangles_[i].size());
        if (recvBuf_[i].size())
        {
            UIPstream::read
            (
                UPstream::commsTypes::nonBlocking, procs_[i],
                reinterpret_cast<char*>(recvBuf_[i].data()),
                recvBuf_[i].byteSize(), haloTag
            );
        }
    }
    forAll(procs_, i)
    {
        sendBuf_[i].setSize(3*perNode*sendTriangles_[i].size());
        if (sendBuf_[i].empty()) continue;
        vector2D* buf = sendBuf_[i].data();
        for (const label t : sendTriangles_[i])
        {
            for (label k = 0; k < 3; ++k)
            {
                *buf++ = x[3*t + k];
                *buf++ = v[3*t + k];
                if (withD) *buf++ = d[3*t + k];
            }
        }
        UOPstream::write
        (
            UPstream::commsTypes::nonBlocking, procs_[i],
            reinterpret_cast<const char*>(sendBuf_[i].cdata()),
            sendBuf_[i].byteSize(), haloTag
        );
    }
    UPstream::waitRequests(start);
    forAll(procs_, i)
    {
        const vector2D* buf = recvBuf_[i].cdata();
        for (const label t : recvTriangles_[i])
        {
            for (label k = 0; k < 3; ++k)
            {
                x[3*t + k] = *buf++;
                v[3*t + k] = *buf++;
                if (withD) d[3*t + k] = *buf++;
            }
        }
    }

    // The same step and the same divergence check on every rank
    const scalar s2 = makeStepGlobal(solid);
    exchangeTime_ += t0.elapsed();

    // The halo holds while nothing moved by haloWidth/2; it is rebuilt
    // from haloWidth/4 on: a cheap bound first (the largest speed times
    // the step), the exact check after it
    const scalar h = solid.time() - tLast_;
    tLast_ = solid.time();
    moveBound_ += h*std::sqrt(s2);
    if (moveBound_ > (rebuild_ ? 0.5 : 0.25)*haloWidth_)
    {
        ++nChecks_;
        const scalar d = maxDisplacement();
        if (d > 0.5*haloWidth_)
        {
            FatalErrorInFunction
                << "a node of the partitioned FEMDEM solid moved " << d
                << " m within one interval of advance() (at time "
                << solid.time() << "), more than half the halo width "
                << haloWidth_ << " m, before the halo could be rebuilt:"
                << " a wider halo (entry 'partition.haloWidth' of"
                << " constant/femdemProperties) or shorter intervals"
                << exit(FatalError);
        }
        rebuild_ = rebuild_ || d > 0.25*haloWidth_;
        moveBound_ = d;
    }
}


// ************************************************************************* //

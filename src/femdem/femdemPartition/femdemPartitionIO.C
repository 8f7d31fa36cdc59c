/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Description
    Global diagnostics of the partitioned solid (energy budget, reactions,
    broken joints), the gathered copy on the master for output, and the
    state I/O: one global femdemState, the format of a serial run, so that
    serial and parallel runs restart from each other's states.

\*---------------------------------------------------------------------------*/

#include "femdemPartition.H"
#include "femdemOutput.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "OSspecific.H"
#include "OFstream.H"
#include "IFstream.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::femdemSolid& Foam::femdemPartition::globalCopy()
{
    if (!global_.valid())
    {
        // Output and state I/O only: no budget of its own (the accounts
        // it writes are the ranks' sums)
        dictionary dict(dict_);
        dict.set("trackEnergy", false);
        global_.reset(new femdemSolid(globalMesh_, dict));
    }
    return *global_;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::femdemSolid::energyBudget Foam::femdemPartition::energies() const
{
    // Each rank's budget counts its owned nodes and joints (budget share):
    // the sums are the whole solid's
    const femdemSolid::energyBudget e = solid_->energies();
    scalarField s
    ({
        e.kinetic, e.elastic, e.jointStored, e.fracture, e.damping,
        e.contact, e.gravity, e.external, e.initial
    });
    reduce(s, sumOp<scalarField>());
    femdemSolid::energyBudget g;
    g.kinetic = s[0]; g.elastic = s[1]; g.jointStored = s[2];
    g.fracture = s[3]; g.damping = s[4]; g.contact = s[5];
    g.gravity = s[6]; g.external = s[7]; g.initial = s[8];
    return g;
}


Foam::vector2D Foam::femdemPartition::reaction(const word& patchName) const
{
    // Ranks without faces on the patch have no condition on it
    vector2D R(Zero);
    if (solid_->hasBoundaryCondition(patchName))
    {
        R = solid_->reaction(patchName);
    }
    reduce(R, sumOp<vector2D>());
    return R;
}


Foam::label Foam::femdemPartition::nBrokenJoints() const
{
    label n = 0;
    forAll(solid_->jointBroken(), j)
    {
        if (solid_->jointBroken()[j] && solid_->countsJoint(j)) ++n;
    }
    return returnReduce(n, sumOp<label>());
}


const Foam::femdemSolid& Foam::femdemPartition::gather()
{
    // Master only: nodes and joints from their owners into the copy
    List<vector2D> x = gatherNodes(solid_->x(), false);
    List<vector2D> v = gatherNodes(solid_->v(), false);
    scalarList damage = gatherJoints(solid_->jointDamage(), false);
    boolList broken = gatherBroken(false);

    const scalarList acc = summedAccounts();

    if (Pstream::master())
    {
        femdemSolid& global = globalCopy();
        global.setState
        (
            x, v, damage, broken, solid_->time(), solid_->timeIndex()
        );
        global.setEnergyAccounts(acc);
        global.restoreTimeSteps(solid_->timeSteps());
        return global;
    }
    return *solid_;
}


const Foam::femdemSolid& Foam::femdemPartition::globalSolid() const
{
    if (!Pstream::master() || !global_.valid())
    {
        FatalErrorInFunction
            << "the gathered solid is on the master after gather()"
            << exit(FatalError);
    }
    return *global_;
}


void Foam::femdemPartition::writeState(const fileName& file)
{
    const femdemSolid& g = gather();
    if (Pstream::master())
    {
        femdemOutput::writeState(g, file);
    }
    appendRankAccounts(file, Pstream::master());
}


bool Foam::femdemPartition::readState(const fileName& file)
{
    // The master reads and checks (femdemOutput::readState: FatalIOErrors
    // naming the file and entry) into the gathered copy, the ranks take
    // the state from it
    bool found = false;
    List<vector2D> x, v;
    scalarList damage, acc;
    boolList broken;
    scalar time = 0;
    FixedList<scalar, 2> steps(Zero);
    label timeIndex = 0;
    if (Pstream::master())
    {
        found = femdemOutput::readState(globalCopy(), file);
        if (found)
        {
            x = global_->x();
            v = global_->v();
            damage = global_->jointDamage();
            broken = global_->jointBroken();
            acc = global_->energyAccounts();
            time = global_->time();
            timeIndex = global_->timeIndex();
            steps = global_->timeSteps();
        }
    }
    List<scalarList> rankAcc;
    if (Pstream::master() && found)
    {
        rankAcc = readRankAccounts(file);
    }
    Pstream::scatter(found);
    if (!found)
    {
        return false;
    }
    Pstream::scatter(rankAcc);
    Pstream::scatter(x);
    Pstream::scatter(v);
    Pstream::scatter(damage);
    Pstream::scatter(broken);
    Pstream::scatter(acc);
    Pstream::scatter(time);
    Pstream::scatter(timeIndex);
    Pstream::scatter(steps);
    // A state of a run without balancing entries starts its check blocks
    // here
    balanceBlock_ = timeIndex/balanceInterval_;
    readOwners(file);
    setGlobalState(x, v, damage, broken, time, timeIndex, steps);

    takeAccounts(acc, rankAcc);
    return true;
}


void Foam::femdemPartition::takeAccounts
(
    const UList<scalar>& acc,
    const List<scalarList>& rankAcc
)
{
    if (rankAcc.size() == Pstream::nProcs())
    {
        solid_->setEnergyAccounts(rankAcc[Pstream::myProcNo()]);
    }
    else
    {
        shareAccounts(acc);
    }
}


Foam::List<Foam::scalarList> Foam::femdemPartition::readRankAccounts
(
    const fileName& file
)
{
    IFstream is(file);
    const dictionary dict(is);
    List<scalarList> rankAcc;
    if (dict.readIfPresent("rankEnergyAccounts", rankAcc))
    {
        for (const scalarList& a : rankAcc)
        {
            if (a.size() != 10)
            {
                FatalIOErrorInFunction(dict)
                    << "entry 'rankEnergyAccounts': 10 values per rank"
                    << " needed, got " << a.size() << exit(FatalIOError);
            }
        }
    }
    return rankAcc;
}


void Foam::femdemPartition::appendRankAccounts
(
    const fileName& file,
    const bool append
) const
{
    List<scalarList> rankAcc(Pstream::nProcs());
    rankAcc[Pstream::myProcNo()] = solid_->energyAccounts();
    Pstream::gatherList(rankAcc);
    Pstream::scatterList(rankAcc);
    if (append)
    {
        // Each rank's budget share: a restart on as many ranks continues
        // every rank's sums, so the totals stay bitwise those of one run
        OFstream os
        (
            file, IOstream::ASCII, IOstream::currentVersion,
            IOstream::UNCOMPRESSED, true
        );
        os.precision(17);
        os.writeEntry("rankEnergyAccounts", rankAcc);
        // The owners and the balancing's schedule: a restart on as many
        // ranks continues with them (the accounts are theirs)
        os.writeEntry("triangleOwner", owner_);
        os.writeEntry
        (
            "balanceState",
            scalarList
            ({
                scalar(balanceBlock_), balancedImbalance_,
                scalar(nRepartitions_), scalar(nMigrated_)
            })
        );
    }
}


void Foam::femdemPartition::readOwners(const fileName& file)
{
    // Master: the entries of a state written on as many ranks
    labelList owner;
    scalarList bal;
    if (Pstream::master())
    {
        IFstream is(file);
        const dictionary dict(is);
        List<scalarList> rankAcc;
        if
        (
            dict.readIfPresent("rankEnergyAccounts", rankAcc)
         && rankAcc.size() == Pstream::nProcs()
         && dict.readIfPresent("triangleOwner", owner)
        )
        {
            if (owner.size() != nGlobal_)
            {
                FatalIOErrorInFunction(dict)
                    << "entry 'triangleOwner' holds " << owner.size()
                    << " owners for a solid of " << nGlobal_ << " triangles"
                    << exit(FatalIOError);
            }
            for (const label o : owner)
            {
                if (o < 0 || o >= Pstream::nProcs())
                {
                    FatalIOErrorInFunction(dict)
                        << "entry 'triangleOwner': rank " << o
                        << " outside 0.." << Pstream::nProcs() - 1
                        << exit(FatalIOError);
                }
            }
            bal = dict.getOrDefault<scalarList>("balanceState", scalarList());
            if (bal.size() && bal.size() != 4)
            {
                FatalIOErrorInFunction(dict)
                    << "entry 'balanceState' needs 4 values, got "
                    << bal.size() << exit(FatalIOError);
            }
        }
        else
        {
            owner.clear();
        }
    }
    Pstream::scatter(owner);
    Pstream::scatter(bal);
    if (owner.size())
    {
        owner_.transfer(owner);
    }
    if (bal.size() == 4)
    {
        balanceBlock_ = label(bal[0]);
        balancedImbalance_ = bal[1];
        nRepartitions_ = label(bal[2]);
        nMigrated_ = label(bal[3]);
    }
    repartition_ = false;
}


void Foam::femdemPartition::shareAccounts(const UList<scalar>& acc)
{
    // The accounts are sums over the ranks (the damage onset is global,
    // femdemSolid::setDamageOnset)
    scalarList local(10, Zero);
    if (Pstream::master())
    {
        local = acc;
    }
    local[9] = acc[9];
    solid_->setEnergyAccounts(local);
}


Foam::scalarList Foam::femdemPartition::summedAccounts() const
{
    scalarField acc(solid_->energyAccounts());
    const bool damaged = acc[9] != 0;
    reduce(acc, sumOp<scalarField>());
    acc[9] = returnReduce(damaged, orOp<bool>());
    return std::move(acc);
}


void Foam::femdemPartition::syncCopy(femdemSolid& whole) const
{
    List<vector2D> x = gatherNodes(solid_->x());
    List<vector2D> v = gatherNodes(solid_->v());
    scalarList damage = gatherJoints(solid_->jointDamage());
    boolList broken = gatherBroken();
    whole.setState(x, v, damage, broken, solid_->time(), solid_->timeIndex());
    // The step data (the same on every rank after each step) and the step
    setStepData(whole, stepData(*solid_));
    whole.restoreTimeSteps(solid_->timeSteps());
}


void Foam::femdemPartition::setStateFrom
(
    const femdemSolid& whole,
    const fileName& stateFile
)
{
    if (whole.nNodes() != 3*nGlobal_)
    {
        FatalErrorInFunction
            << "a solid of " << whole.nNodes() << " nodes for a partition of "
            << 3*nGlobal_ << exit(FatalError);
    }
    balanceBlock_ = whole.timeIndex()/balanceInterval_;
    readOwners(stateFile);
    setGlobalState
    (
        whole.x(), whole.v(), whole.jointDamage(), whole.jointBroken(), whole.time(),
        whole.timeIndex(), whole.timeSteps()
    );
    takeAccounts(whole.energyAccounts(), readRankAccounts(stateFile));
}


// ************************************************************************* //

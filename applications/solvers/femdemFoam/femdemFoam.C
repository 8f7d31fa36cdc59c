/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemFoam

Group
    grpSolidSolvers

Description
    Solid-only FEMDEM solver (2D plane strain): triangles, cohesive joints,
    contact (libfemdem's femdemSolid). Reads constant/solidMesh,
    constant/femdemProperties and system/controlDict. Each controlDict step
    deltaT is sub-cycled with the solid's stable step.

    Output:
    - <time>/femdemState at write times: the full state at full precision
      (a run restarted from it is bit-exact), with <time>/uniform/time
      (the exact time and the write schedule: restartableTime, so a restart
      writes and logs at the times of an uninterrupted run);
    - VTK/femdem.vtu.series (+ .pvd): the continuous view of the solid with
      stress, velocity, damage, material, fragment; VTK/cracks_<i>.vtp: the
      broken joints as lines;
    - postProcessing/femdem/<startTime>/: energy.dat (energy budget),
      fragments.dat, reactions.dat (reaction forces of the listed patches),
      crackEvents.dat (each broken joint once, with the log time),
      cracks_<time>.dat at write times and cracks.dat at the end (broken
      joints: x0 y0 x1 y1 of their initial positions).

    femdemProperties, besides femdemSolid's entries:
    \verbatim
    output
    {
        logInterval   1e-5;        // energy/fragment/reaction log [s]
                                   // (default: every controlDict step)
        vtk           true;        // VTK series at write times
        reactions     (top bottom);// patches with fixed/velocity conditions
        progressInterval 5;        // wall-clock seconds between progress
                                   // lines (default 5, 0: every step)
    }
    \endverbatim
    trackEnergy defaults to true in femdemFoam. With writeControl
    adjustableRunTime the controlDict deltaT is clipped so that the steps
    end on the write times.

    SIGINT (Ctrl-C) or SIGTERM: the state of the current step is written
    (a time directory with femdemState, restartable) and the run ends
    normally, exit status 0 (stopOnSignal). A second signal kills at once.

    Parallel: 'mpirun -np N femdemFoam -parallel' on the undecomposed case
    (no decomposePar: the solid has no fluid mesh). The solid is
    partitioned over the ranks (femdemPartition: METIS on the triangle
    graph, redundant halo, optional sub-dictionary 'partition' of
    femdemProperties); node positions equal the serial run's bit for bit.
    The energy budget, reactions and broken joints are sums over the ranks
    (each counts its owned nodes and joints); fragments, cracks and VTK come
    from the state gathered on the master at log and write times. The
    state is one global <time>/femdemState in the case directory, the file
    of a serial run: serial and parallel runs (any rank count) restart from
    each other's states. processor<N>/<time>/uniform/time keep the exact
    time and write schedule of each rank (restartableTime); the master
    copies it beside the global state. A parallel run restarts from the
    latest processor time (startFrom latestTime) or from a state of a
    serial run (startFrom startTime; startTime <time>).

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "femdemSolid.H"
#include "femdemPartition.H"
#include "contactLaw.H"
#include "solidVtkWriter.H"
#include "femdemOutput.H"
#include "stopOnSignal.H"
#include "restartableTime.H"
#include "runProgress.H"
#include "caseChecks.H"
#include <cmath>

using namespace Foam;
using namespace Foam::femdemOutput;



// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Solid-only FEMDEM solver (2D plane strain): triangles, cohesive"
        " joints, contact"
    );
    // Parallel runs need no processor directories: the solid is
    // partitioned at the start (femdemPartition), the state is global
    argList::noCheckProcessorDirectories();

    caseChecks::checkCasePath(argc, argv);
    #include "setRootCase.H"

    // Before Time reads system/controlDict: mpirun without -parallel, deltaT/writeInterval/endTime that Time would trap
    // on (writeInterval 0) or accept and then do nothing
    caseChecks::checkLaunch(args);
    caseChecks::checkControlDict(args, true);

    #include "createRestartableTime.H"
    caseChecks::checkStartTime(runTime);

    IOdictionary properties
    (
        IOobject
        (
            "femdemProperties",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    );
    if (properties.empty())
    {
        FatalIOErrorInFunction(properties)
            << "constant/femdemProperties is empty: it needs at least the"
            << " entry 'materials'" << exit(FatalIOError);
    }
    caseChecks::checkNoDuplicateEntries(properties);
    dictionary solidDict(properties);
    if (!solidDict.found("trackEnergy"))
    {
        solidDict.add("trackEnergy", true);
    }

    const triangleMesh mesh = triangleMesh::New(runTime);

    // solidProbes reads femdemSolid::active(): in parallel one rank's part
    if (Pstream::parRun())
    {
        const dictionary& fns =
            runTime.controlDict().subOrEmptyDict("functions");
        for (const entry& e : fns)
        {
            if
            (
                e.isDict()
             && e.dict().getOrDefault<word>("type", word::null)
             == "solidProbes"
            )
            {
                FatalIOErrorInFunction(runTime.controlDict())
                    << "entry 'functions/" << e.keyword() << "': type"
                    << " solidProbes does not run in parallel femdemFoam yet"
                    << " (it would read one rank's part of the partitioned"
                    << " solid). Run serially, or remove the entry"
                    << exit(FatalIOError);
            }
        }
    }

    // Serial: the whole solid. Parallel: this rank's part (owned + halo
    // triangles) of the partitioned solid
    autoPtr<femdemSolid> serialSolid;
    autoPtr<femdemPartition> partition;
    if (Pstream::parRun())
    {
        partition.reset(new femdemPartition(mesh, solidDict));
        Info<< "Partitioned solid over " << Pstream::nProcs() << " ranks:"
            << " halo width " << partition->haloWidth() << " m, owned"
            << " triangles per rank " << returnReduce(partition->nOwned(), minOp<label>())
            << " to " << returnReduce(partition->nOwned(), maxOp<label>())
            << ", halo triangles " << returnReduce(partition->nHalo(), sumOp<label>())
            << " in all" << nl
            << "Solid memory per rank: ";
        partition->writeMemory(Info);
        Info<< endl;
    }
    else
    {
        serialSolid.reset(new femdemSolid(mesh, solidDict));
        Info<< "Solid memory: " << scalar(serialSolid->memoryBytes())/1e6
            << " MB" << endl;
    }
    // This rank's solid now (a partitioned solid's local solid is rebuilt
    // when the halo is: never keep a reference to it)
    auto localSolid = [&]() -> femdemSolid&
    {
        return partition.valid() ? partition->solid() : serialSolid();
    };

    // The whole solid's state: the solid itself, or the master's gathered
    // copy of a partitioned one (collective: every rank calls it)
    auto wholeSolid = [&]() -> const femdemSolid&
    {
        return partition.valid() ? partition->gather() : serialSolid();
    };
    if (partition.valid())
    {
        const femdemSolid& whole = wholeSolid();
        if (Pstream::master()) reportJointStrengths(whole, false);
    }
    else
    {
        reportJointStrengths(serialSolid());
    }

    const dictionary outDict = properties.subOrEmptyDict("output");
    const scalar logInterval =
        outDict.getOrDefault<scalar>("logInterval", runTime.deltaTValue());
    if (!(logInterval > 0))
    {
        FatalIOErrorInFunction(properties)
            << "entry 'output/logInterval' must be positive, got "
            << logInterval << exit(FatalIOError);
    }
    const scalar progressInterval =
        outDict.getOrDefault<scalar>("progressInterval", 5);
    if (progressInterval < 0)
    {
        FatalIOErrorInFunction(properties)
            << "entry 'output/progressInterval' must not be negative, got "
            << progressInterval << exit(FatalIOError);
    }
    const bool doVtk = outDict.getOrDefault<bool>("vtk", true);
    const wordList reactionPatches =
        outDict.getOrDefault<wordList>("reactions", wordList());
    for (const word& p : reactionPatches)
    {
        if (std::count(reactionPatches.begin(), reactionPatches.end(), p) > 1)
        {
            FatalIOErrorInFunction(properties)
                << "entry 'output/reactions' lists patch '" << p << "' twice"
                << exit(FatalIOError);
        }
        bool found = false;
        for (const femdemSolid::boundaryCondition& bc : localSolid().boundaryConditions())
        {
            if
            (
                bc.patchName == p
             && (
                    bc.type == femdemSolid::boundaryCondition::FIXED
                 || bc.type == femdemSolid::boundaryCondition::VELOCITY
                )
            )
            {
                found = true;
            }
        }
        if (!returnReduce(found, orOp<bool>()))
        {
            FatalIOErrorInFunction(properties)
                << "entry 'output/reactions': patch '" << p << "' has no"
                << " fixed or velocity boundary condition"
                << exit(FatalIOError);
        }
    }

    // Restart from the state of the start time. femdemFoam reads nothing
    // else from time directories, so a start time directory other than 0
    // was written by an earlier run: it must hold the solid's state (else
    // the solid would silently restart from the mesh at rest). The state
    // is global (the case directory's time directories, also in parallel)
    const fileName caseDir = runTime.globalPath();
    const fileName stateFile = caseDir/runTime.timeName()/"femdemState";
    const bool restart =
        isDir(runTime.timePath()) && runTime.timeName() != "0";
    if (restart && !isFile(stateFile))
    {
        FatalErrorInFunction
            << "restart from time " << runTime.timeName() << ": the solid"
            << " state " << stateFile << " is missing (the time directory"
            << " exists, so an earlier run wrote it). Restore the file, remove"
            << " the time directory, or set startFrom/startTime to a time"
            << " with a femdemState" << exit(FatalError);
    }
    const bool restarted =
        partition.valid()
      ? partition->readState(stateFile)
      : readState(serialSolid(), stateFile);
    const label nBroken0 =
        partition.valid()
      ? partition->nBrokenJoints()
      : serialSolid().nBrokenJoints();
    if (restarted)
    {
        Info<< "Restarted from " << stateFile << " (solid time "
            << localSolid().time() << ", " << nBroken0 << " broken joints)" << nl
            << endl;
    }
    else if (!partition.valid())
    {
        // (a partitioned solid's budget starts at its construction)
        serialSolid().resetEnergyBudget();
    }

    // The whole solid's joints (a partitioned solid's local part has fewer)
    const label nJoints =
        partition.valid()
      ? partition->globalTopology().nJoints()
      : serialSolid().nJoints();
    Info<< "FEMDEM solid: " << mesh.nTriangles() << " triangles, "
        << nJoints << " joints, "
        << localSolid().materials().size() << " material(s)" << nl
        << "Element, joint and contact loops: "
        << femdemSolid::vectorCodeName() << nl
        << "Stable time step: " << localSolid().stableTimeStep() << " s ("
        << std::ceil(runTime.deltaTValue()/localSolid().stableTimeStep())
        << " sub-steps per deltaT)" << nl << endl;

    // Logs (master)
    const fileName postDir =
        caseDir/"postProcessing"/"femdem"/runTime.timeName();
    autoPtr<OFstream> energyLog, fragmentLog, reactionLog, crackLog;
    boolList crackLogged;
    if (Pstream::master())
    {
        mkDir(postDir);
        energyLog.reset(new OFstream(postDir/"energy.dat"));
        fragmentLog.reset(new OFstream(postDir/"fragments.dat"));
        reactionLog.reset(new OFstream(postDir/"reactions.dat"));
        crackLog.reset(new OFstream(postDir/"crackEvents.dat"));
        crackLog().precision(10);
        crackLog()
            << "# joints as they break (time of the log after the breakage):"
            << " time x0 y0 x1 y1 (initial positions)" << nl;
        crackLogged.setSize(nJoints, false);
        energyLog().precision(10);
        reactionLog().precision(10);
        fragmentLog().precision(10);
        energyLog()
            << "# time kinetic elastic jointStored fracture damping contact"
            << " gravity external initial residual" << nl;
        fragmentLog()
            << "# time nFragments nBrokenJoints largestMassFraction"
            << " maxFragmentSpeed meanFragmentMass" << nl;
        reactionLog() << "# time";
        for (const word& p : reactionPatches)
        {
            reactionLog() << " " << p << "_Fx " << p << "_Fy";
        }
        reactionLog() << nl;
    }

    autoPtr<solidVtkWriter> vtkWriter;
    const fileName vtkDir = caseDir/"VTK";
    if (doVtk)
    {
        const femdemSolid& whole = wholeSolid();
        if (Pstream::master())
        {
            vtkWriter.reset(new solidVtkWriter(vtkDir, "femdem"));
            writeVtk(*vtkWriter, whole, vtkDir, runTime.value());
        }
    }

    auto logState = [&]()
    {
        const scalar t = runTime.value();
        const femdemSolid::energyBudget e =
            partition.valid() ? partition->energies() : serialSolid().energies();
        if (!std::isfinite(e.kinetic) || !std::isfinite(e.elastic))
        {
            FatalErrorInFunction
                << "the solid diverged at time " << t << " (kinetic energy "
                << e.kinetic << "): lower timeStepSafety in "
                << properties.objectPath() << exit(FatalError);
        }
        List<vector2D> R(reactionPatches.size());
        forAll(reactionPatches, i)
        {
            R[i] =
                partition.valid()
              ? partition->reaction(reactionPatches[i])
              : serialSolid().reaction(reactionPatches[i]);
        }
        const femdemSolid& whole = wholeSolid();
        if (!Pstream::master())
        {
            return;
        }

        energyLog()
            << t << ' ' << e.kinetic << ' ' << e.elastic << ' '
            << e.jointStored << ' ' << e.fracture << ' ' << e.damping << ' '
            << e.contact << ' ' << e.gravity << ' ' << e.external << ' '
            << e.initial << ' ' << e.residual() << nl;

        const femdemSolid::fragmentData fr = whole.fragments();
        scalar mTotal = 0, mMax = 0, vMax = 0;
        forAll(fr.mass, i)
        {
            mTotal += fr.mass[i];
            mMax = max(mMax, fr.mass[i]);
            vMax = max(vMax, mag(fr.velocity[i]));
        }
        fragmentLog()
            << t << ' ' << fr.mass.size() << ' ' << whole.nBrokenJoints()
            << ' ' << mMax/mTotal << ' ' << vMax << ' '
            << mTotal/fr.mass.size() << nl;

        reactionLog() << t;
        for (const vector2D& Ri : R)
        {
            reactionLog() << ' ' << Ri.x() << ' ' << Ri.y();
        }
        reactionLog() << nl;

        // Joints broken since the last log
        const List<jointNodeList>& jn = whole.topology().jointNodes();
        const List<vector2D>& X0 = whole.topology().initialPoints();
        const labelList& vertex = whole.topology().nodeVertex();
        forAll(crackLogged, j)
        {
            if (whole.jointBroken()[j] && !crackLogged[j])
            {
                crackLogged[j] = true;
                const vector2D& a = X0[vertex[jn[j][0]]];
                const vector2D& b = X0[vertex[jn[j][1]]];
                crackLog()
                    << t << ' ' << a.x() << ' ' << a.y() << ' ' << b.x()
                    << ' ' << b.y() << nl;
            }
        }

        // Every row flushed: a run that stops (a diverged solid: FatalError
        // exits without unwinding) kept only whole buffers, cut mid-row
        energyLog().flush();
        fragmentLog().flush();
        reactionLog().flush();
        crackLog().flush();

        const scalar input = e.initial + e.external + e.gravity;
        Info<< "    energy: kinetic " << e.kinetic << " elastic " << e.elastic
            << " fracture " << e.fracture << " damping " << e.damping
            << " contact " << e.contact << " input " << input
            << " residual " << e.residual() << nl
            << "    fragments " << fr.mass.size() << ", broken joints "
            << whole.nBrokenJoints() << endl;
    };

    // Log times counted from the start of the write schedule (the first
    // run's start time; restartableTime), so a restart logs at the times
    // of an uninterrupted run
    const scalar eps = 1e-9*runTime.deltaTValue();
    scalar nextLog = runTime.writeStart()
      + logInterval
       *(std::floor((runTime.value() - runTime.writeStart() + eps)/logInterval) + 1);

    stopOnSignal stop;
    runProgress progress(runTime, progressInterval);

    Info<< "Starting time loop" << nl << endl;
    while (runTime.run())
    {
        // controlDict deltaT; with writeControl adjustableRunTime clipped
        // so that the steps end on the write times
        runTime.setDeltaT(runTime.controlDict().get<scalar>("deltaT"));
        ++runTime;
        const label nSub =
            partition.valid()
          ? partition->advance(runTime.deltaTValue())
          : serialSolid().advance(runTime.deltaTValue());

        Info<< "Time = " << runTime.timeName() << "  sub-steps " << nSub
            << "  broken joints "
            << (
                   partition.valid()
                 ? partition->nBrokenJoints()
                 : serialSolid().nBrokenJoints()
               )
            << endl;

        if (runTime.value() >= nextLog - eps)
        {
            logState();
            while (nextLog <= runTime.value() + eps) nextLog += logInterval;
        }
        progress.report();

        // On SIGINT/SIGTERM: makes this a write time and the last step
        stop.check(runTime);

        if (runTime.writeTime())
        {
            const fileName stateOut = caseDir/runTime.timeName()/"femdemState";
            const femdemSolid& whole = wholeSolid();
            if (Pstream::master())
            {
                mkDir(stateOut.path());
                writeState(whole, stateOut);
                writeCracks(whole, postDir/("cracks_" + runTime.timeName() + ".dat"));
                if (doVtk)
                {
                    writeVtk(*vtkWriter, whole, vtkDir, runTime.value());
                }
            }
            if (partition.valid())
            {
                // Each rank's budget share: a restart on as many ranks
                // continues the sums bitwise
                partition->appendRankAccounts(stateOut, Pstream::master());
            }
            Info<< "    wrote " << stateOut << endl;
        }

        // uniform/time at write times (exact time and write schedule for
        // restarts); in parallel into processor<N>/<time>, and the master
        // copies it beside the global state (a serial restart reads it)
        runTime.write();
        if (Pstream::parRun() && runTime.writeTime() && Pstream::master())
        {
            const fileName timeDict = runTime.timePath()/"uniform"/"time";
            mkDir(caseDir/runTime.timeName()/"uniform");
            cp(timeDict, caseDir/runTime.timeName()/"uniform"/"time");
        }
    }

    {
        const femdemSolid& whole = wholeSolid();
        if (Pstream::master())
        {
            writeCracks(whole, postDir/"cracks.dat");
        }
    }
    if (partition.valid())
    {
        // (the copy exists on the master only)
        const scalar copyMB =
            Pstream::master()
          ? scalar(partition->globalSolid().memoryBytes())/1e6
          : 0;
        const scalar tx = partition->exchangeTime();
        Info<< nl << "Halo rebuilds " << partition->nRebuilds() << " ("
            << returnReduce(scalar(partition->rebuildTime()), maxOp<scalar>())
            << " s)"
            << ", exact displacement checks "
            << partition->nDisplacementChecks() << nl
            << "Load-balancing repartitions " << partition->nRepartitions()
            << " (" << partition->nMigrated() << " triangles migrated)" << nl
            << "Per-step exchange (waiting for the other ranks and the"
            << " messages) " << returnReduce(tx, minOp<scalar>()) << " to "
            << returnReduce(tx, maxOp<scalar>()) << " s per rank" << nl
            << "The master's gathered copy of the whole solid (output): "
            << copyMB << " MB" << endl;
    }
    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

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

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "femdemSolid.H"
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
    argList::noParallel();

    caseChecks::checkCasePath(argc, argv);
    #include "setRootCase.H"

    // Before Time reads system/controlDict: mpirun without -parallel, deltaT/writeInterval/endTime that Time would trap
    // on (writeInterval 0) or accept and then do nothing
    caseChecks::checkLaunch(args);
    caseChecks::checkControlDict(args);

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
    femdemSolid solid(mesh, solidDict);
    reportJointStrengths(solid);

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
        for (const femdemSolid::boundaryCondition& bc : solid.boundaryConditions())
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
        if (!found)
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
    // the solid would silently restart from the mesh at rest)
    const fileName stateFile = runTime.timePath()/"femdemState";
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
    if (readState(solid, stateFile))
    {
        Info<< "Restarted from " << stateFile << " (solid time "
            << solid.time() << ", " << solid.nBrokenJoints()
            << " broken joints)" << nl << endl;
    }
    else
    {
        solid.resetEnergyBudget();
    }

    Info<< "FEMDEM solid: " << solid.nTriangles() << " triangles, "
        << solid.nJoints() << " joints, " << solid.materials().size()
        << " material(s)" << nl
        << "Stable time step: " << solid.stableTimeStep() << " s ("
        << std::ceil(runTime.deltaTValue()/solid.stableTimeStep())
        << " sub-steps per deltaT)" << nl << endl;

    // Logs
    const fileName postDir =
        runTime.path()/"postProcessing"/"femdem"/runTime.timeName();
    mkDir(postDir);
    OFstream energyLog(postDir/"energy.dat");
    OFstream fragmentLog(postDir/"fragments.dat");
    OFstream reactionLog(postDir/"reactions.dat");
    OFstream crackLog(postDir/"crackEvents.dat");
    crackLog.precision(10);
    crackLog
        << "# joints as they break (time of the log after the breakage):"
        << " time x0 y0 x1 y1 (initial positions)" << nl;
    boolList crackLogged(solid.nJoints(), false);
    energyLog.precision(10);
    reactionLog.precision(10);
    fragmentLog.precision(10);
    energyLog
        << "# time kinetic elastic jointStored fracture damping contact"
        << " gravity external initial residual" << nl;
    fragmentLog
        << "# time nFragments nBrokenJoints largestMassFraction"
        << " maxFragmentSpeed meanFragmentMass" << nl;
    reactionLog << "# time";
    for (const word& p : reactionPatches)
    {
        reactionLog << " " << p << "_Fx " << p << "_Fy";
    }
    reactionLog << nl;

    autoPtr<solidVtkWriter> vtkWriter;
    const fileName vtkDir = runTime.path()/"VTK";
    if (doVtk)
    {
        vtkWriter.reset(new solidVtkWriter(vtkDir, "femdem"));
        writeVtk(*vtkWriter, solid, vtkDir, runTime.value());
    }

    auto logState = [&]()
    {
        const scalar t = runTime.value();
        const femdemSolid::energyBudget e = solid.energies();
        if (!std::isfinite(e.kinetic) || !std::isfinite(e.elastic))
        {
            FatalErrorInFunction
                << "the solid diverged at time " << t << " (kinetic energy "
                << e.kinetic << "): lower timeStepSafety in "
                << properties.objectPath() << exit(FatalError);
        }
        energyLog
            << t << ' ' << e.kinetic << ' ' << e.elastic << ' '
            << e.jointStored << ' ' << e.fracture << ' ' << e.damping << ' '
            << e.contact << ' ' << e.gravity << ' ' << e.external << ' '
            << e.initial << ' ' << e.residual() << nl;

        const femdemSolid::fragmentData fr = solid.fragments();
        scalar mTotal = 0, mMax = 0, vMax = 0;
        forAll(fr.mass, i)
        {
            mTotal += fr.mass[i];
            mMax = max(mMax, fr.mass[i]);
            vMax = max(vMax, mag(fr.velocity[i]));
        }
        fragmentLog
            << t << ' ' << fr.mass.size() << ' ' << solid.nBrokenJoints()
            << ' ' << mMax/mTotal << ' ' << vMax << ' '
            << mTotal/fr.mass.size() << nl;

        reactionLog << t;
        for (const word& p : reactionPatches)
        {
            const vector2D R = solid.reaction(p);
            reactionLog << ' ' << R.x() << ' ' << R.y();
        }
        reactionLog << nl;

        // Joints broken since the last log
        const List<jointNodeList>& jn = solid.topology().jointNodes();
        const List<vector2D>& X0 = solid.topology().initialPoints();
        const labelList& vertex = solid.topology().nodeVertex();
        forAll(crackLogged, j)
        {
            if (solid.jointBroken()[j] && !crackLogged[j])
            {
                crackLogged[j] = true;
                const vector2D& a = X0[vertex[jn[j][0]]];
                const vector2D& b = X0[vertex[jn[j][1]]];
                crackLog
                    << t << ' ' << a.x() << ' ' << a.y() << ' ' << b.x()
                    << ' ' << b.y() << nl;
            }
        }

        // Every row flushed: a run that stops (a diverged solid: FatalError
        // exits without unwinding) kept only whole buffers, cut mid-row
        energyLog.flush();
        fragmentLog.flush();
        reactionLog.flush();
        crackLog.flush();

        const scalar input = e.initial + e.external + e.gravity;
        Info<< "    energy: kinetic " << e.kinetic << " elastic " << e.elastic
            << " fracture " << e.fracture << " damping " << e.damping
            << " contact " << e.contact << " input " << input
            << " residual " << e.residual() << nl
            << "    fragments " << fr.mass.size() << ", broken joints "
            << solid.nBrokenJoints() << endl;
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
        const label nSub = solid.advance(runTime.deltaTValue());

        Info<< "Time = " << runTime.timeName() << "  sub-steps " << nSub
            << "  broken joints " << solid.nBrokenJoints() << endl;

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
            mkDir(runTime.timePath());
            writeState(solid, runTime.timePath()/"femdemState");
            writeCracks(solid, postDir/("cracks_" + runTime.timeName() + ".dat"));
            if (doVtk)
            {
                writeVtk(*vtkWriter, solid, vtkDir, runTime.value());
            }
            Info<< "    wrote " << runTime.timePath()/"femdemState" << endl;
        }

        // uniform/time at write times (exact time and write schedule for
        // restarts)
        runTime.write();
    }

    writeCracks(solid, postDir/"cracks.dat");
    Info<< nl << "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //

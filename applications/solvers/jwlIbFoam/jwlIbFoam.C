/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    jwlIbFoam

Group
    grpCompressibleSolvers

Description
    Rock blasting: explicit shock-capturing solver for detonation products
    (JWL) and air (or any one or two Mie-Grueneisen materials in pressure
    equilibrium) coupled to an immersed, fracturing FEMDEM solid.

    Per time step (exact moving-boundary finite volumes, cut cells; see
    doc/theory-coupling.md):
      1. Courant-controlled dt (controlDict: adjustTimeStep, maxCo,
         maxDeltaT);
      2. the step's geometry from the solid now and moved on by dt v: fluid
         fractions at both ends, time-averaged face apertures
         (immersedBodyCoupling::startStep), given to the gas;
      3. SSP Runge-Kutta stages of the finite-volume residual (HLLC or
         central-upwind fluxes through the open part of each face,
         moving-wall terms, optional Q-scheme) with small-cell
         redistribution;
      4. the wall impulses on the solid's exposed edges (exactly the
         reaction), FEMDEM sub-cycled over dt with its own stable step,
         then the gas pays exactly the work of those forces
         (cutCellSolidStep.H): gas + solid energy is conserved.
    A coupled step whose gas has no physical state even at first order
    everywhere (a cell the solid crushes within the step) is restored and
    taken in halves, quarters, ... (each part with its own geometry and
    solid step), up to controlDict maxStepHalvings (default 5) halvings;
    beyond, the run stops naming time and cell, the last written time kept.
    A case without constant/femdemProperties runs as a pure gas solver.

    Inputs: constant/thermophysicalProperties (blastMixture),
    system/blastFluidProperties (numerics, optional), 0/p, 0/U and 0/rho
    (one material) or 0/alpha.<m1>, 0/rho.<m1>, 0/rho.<m2> (two
    materials); with a solid: constant/femdemProperties (as femdemFoam),
    constant/solidMesh, constant/immersedBodyProperties (optional).

    Restarts (startFrom latestTime) continue the exact time and the write
    schedule of the first run (restartableTime): a run stopped by a signal
    and restarted equals the uninterrupted one, also with writeControl
    adjustableRunTime. The solid and the crack gas continue from their
    states in <time>/uniform/ (a solid with broken joints and crackGas
    needs both).

    Output: the gas fields and alpha.solid, U.solid at write times;
    <time>/uniform/femdemState (the solid, bit-exact; copied by
    reconstructPar) and, with crackGas, <time>/uniform/crackGas (the crack
    gas, bit-exact: a restart continues it); VTK/femdem.vtu.series with the
    solid and its cracks;
    postProcessing/jwlIbFoam/<startTime>/budget.dat: per step the mass,
    momentum and energy of gas and solid per unit depth, sub-steps, broken
    joints and fragments. A log line per step; every few seconds of wall
    time a progress line with the estimated time left.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "blastFluidSolver.H"
#include "femdemSolid.H"
#include "femdemPartition.H"
#include "femdemOutput.H"
#include "triangleMesh.H"
#include "immersedBodyCoupling.H"
#include "crackGasCoupling.H"
#include "solidVtkWriter.H"
#include "stopOnSignal.H"
#include "restartableTime.H"
#include "caseChecks.H"
#include "runProgress.H"
#include "OFstream.H"
#include "IOmanip.H"
#include "clockValue.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace Foam
{

//- Stop if part of the solid lies outside the fluid mesh
void checkSolidInsideFluid
(
    const fvMesh& mesh,
    const immersedBodyCoupling& coupling,
    const femdemSolid& solid
)
{
    // The area of the solid as it is now (deformed, after a restart without
    // alpha.solid), not the initial area0: the projection clips the present
    // triangles, so only the part outside the fluid mesh makes them differ
    const List<vector2D>& x = solid.x();
    scalar solidArea = 0;
    for (label t = 0; t < solid.nTriangles(); ++t)
    {
        const vector2D a = x[3*t + 1] - x[3*t];
        const vector2D b = x[3*t + 2] - x[3*t];
        solidArea += 0.5*(a.x()*b.y() - a.y()*b.x());
    }
    const scalar projected =
        gSum(coupling.alphaSolid().primitiveField()*mesh.V())
       /coupling.depth();
    // Tolerance 1e-5: besides round-off, the discontinuous FEMDEM triangles
    // of a deformed (restarted) solid overlap slightly at compressed joints,
    // and the projection counts such overlaps once (2.8e-8 of the area in
    // the coupled box restarted after two steps); a solid that leaves the
    // fluid mesh loses far more
    if (mag(projected - solidArea) > 1e-5*solidArea)
    {
        FatalErrorInFunction
            << "constant/solidMesh: "
            << 100*(solidArea - projected)/solidArea << " % of the solid"
            << " area lies outside the fluid mesh (solid area " << solidArea
            << ", projected onto the fluid cells " << projected
            << "; fluid mesh bounds " << mesh.bounds() << ")"
            << exit(FatalError);
    }
}

} // End namespace Foam


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Rock blasting: JWL detonation products and air coupled to an"
        " immersed, fracturing FEMDEM solid"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    caseChecks::checkCasePath(argc, argv);
    #include "setRootCaseLists.H"

    // Before Time reads system/controlDict: mpirun without -parallel, and
    // deltaT/writeInterval/endTime that Time would trap on (writeInterval
    // 0) or accept and then do nothing
    caseChecks::checkLaunch(args);
    caseChecks::checkControlDict(args);
    #include "createRestartableTime.H"
    caseChecks::checkStartTime(runTime);
    #include "createMesh.H"
    #include "createFields.H"
    #include "createSolid.H"
    #include "createTimeControls.H"
    #include "checkTimeControls.H"
    #include "createDiagnostics.H"

    // SIGINT/SIGTERM: write the current step and stop; a progress line
    // every controlDict/progressInterval seconds of wall time
    stopOnSignal stop;
    runProgress progress
    (
        runTime,
        runTime.controlDict().getOrDefault<scalar>("progressInterval", 5)
    );

    // Wall-clock time of the parts of a step (printed at the end): the
    // coupling is startStep + setFluidFraction (and setEmbeddedBoundary)
    // + wallForces (and wallWork, addEnergy, the crack gas exchange); the
    // solid its sub-cycles (with a partitioned solid the gather of its work
    // displacement too, which waits for the slowest rank)
    double tGas = 0, tProject = 0, tFraction = 0, tForces = 0, tSolid = 0;
    // Halvings of a coupled step before a gas state that is still
    // non-physical stops the run (controlDict maxStepHalvings, default 5:
    // parts of 1/32 of the step; 0: stop at the first such step)
    const label maxStepHalvings =
        runTime.controlDict().getOrDefault<label>("maxStepHalvings", 5);
    if (maxStepHalvings < 0 || maxStepHalvings > 30)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "maxStepHalvings " << maxStepHalvings << ": must be 0 to 30"
            << " (a coupled step taken in at most 2^maxStepHalvings parts)"
            << exit(FatalIOError);
    }
    label nStepsInParts = 0;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "setDeltaT.H"

        ++runTime;
        const scalar dt = runTime.deltaTValue();

        label nSubSteps = 0;
        if (hasSolid)
        {
            #include "coupledStepInParts.H"
        }
        else
        {
            const clockValue t0(clockValue::now());
            fluid.advance(dt);
            tGas += t0.elapsed();
        }

        #include "writeDiagnostics.H"

        progress.report();
        stop.check(runTime);

        if (hasSolid && runTime.writeTime())
        {
            #include "writeSolid.H"
        }

        runTime.write();
    }

    const double tCoupling = tProject + tFraction + tForces;
    Info<< "Timing: gas " << tGas << " s, coupling " << tCoupling << " s ("
        << (tGas > 0 ? 100*tCoupling/tGas : 0) << " % of gas; startStep "
        << tProject << " s, setFluidFraction " << tFraction
        << " s, wallForces " << tForces << " s), solid " << tSolid << " s"
        << nl;
    if (hasSolid)
    {
        Info<< "Coupled steps taken in parts (the gas could not take them"
            << " whole): " << nStepsInParts << "; crushed pockets vented: "
            << returnReduce(fluid.nVented(), sumOp<label>()) << " ("
            << returnReduce(fluid.ventedMass(), sumOp<scalar>())
            << " kg of gas); cells mixed for a negative internal energy: "
            << returnReduce(fluid.nMixed(), sumOp<label>())
            << "; cells mixed for no physical state between steps: "
            << returnReduce(fluid.nRepaired(), sumOp<label>()) << nl;
    }
    if (crackGasPtr.valid()) crackGasPtr->reportSubSteps();
    if (partitionPtr.valid())
    {
        // Time a rank waits for the others in the solid's sub-steps: the
        // load imbalance of the partition and the messages
        const scalar tx = partitionPtr->exchangeTime();
        Info<< "Partitioned solid: per-step exchange "
            << returnReduce(tx, minOp<scalar>()) << " to "
            << returnReduce(tx, maxOp<scalar>()) << " s per rank, halo"
            << " rebuilds " << partitionPtr->nRebuilds() << " ("
            << returnReduce(scalar(partitionPtr->rebuildTime()), maxOp<scalar>())
            << " s), load-balancing repartitions "
            << partitionPtr->nRepartitions() << " ("
            << partitionPtr->nMigrated() << " triangles migrated)" << nl;
        // What falls with the rank count (the local solid) and what does
        // not yet (the global copies, and the coupling's copy of the whole
        // solid on every rank)
        Info<< "Solid memory per rank: ";
        partitionPtr->writeMemory(Info);
        Info<< ", the coupling's copy of the whole solid "
            << scalar(solidPtr->memoryBytes())/1e6 << " MB" << nl;
        if (crackGasPtr.valid()) crackGasPtr->reportPartition();
    }
    else if (hasSolid)
    {
        Info<< "Solid memory: " << scalar(solidPtr->memoryBytes())/1e6
            << " MB" << nl;
    }
    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << "End\n" << endl;

    return 0;
}


// ************************************************************************* //

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
    Explicit shock-capturing solver for detonation products (JWL) and air
    (or any one or two Mie-Grueneisen materials) in pressure equilibrium,
    for rock blasting. This is the gas-only path: a case without a solid
    runs as a pure gas solver; the immersed FEMDEM solid is added by a later
    development through the alphaSolid/Usolid hooks of blastFluidSolver.

    Per time step: Courant-controlled dt (controlDict: adjustTimeStep, maxCo,
    maxDeltaT), SSP Runge-Kutta stages of the finite-volume residual
    (HLLC or central-upwind fluxes, limited reconstruction, optional
    Q-scheme), a log line with time, dt, max p, total mass and energy.

    Inputs: constant/thermophysicalProperties (blastMixture),
    system/blastFluidProperties (numerics, optional), 0/p, 0/U and 0/rho
    (one material) or 0/alpha.<m1>, 0/rho.<m1>, 0/rho.<m2> (two materials).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "blastFluidSolver.H"
#include "IOmanip.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Explicit shock-capturing solver for JWL detonation products and air"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createFields.H"
    #include "createTimeControls.H"

    const scalar mass0 = fluid.totalMass();
    const scalar energy0 = fluid.totalEnergy();
    Info<< "Initial total mass " << setprecision(17) << mass0
        << " total energy " << energy0 << setprecision(6) << nl << endl;

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "setDeltaT.H"

        ++runTime;

        fluid.advance(runTime.deltaTValue());

        Info<< "Time = " << runTime.timeName()
            << "  dt = " << runTime.deltaTValue()
            << "  maxP = " << fluid.maxPressure()
            << "  mass = " << setprecision(17) << fluid.totalMass()
            << "  energy = " << fluid.totalEnergy() << setprecision(6)
            << "  minRho = " << gMin(fluid.rho().primitiveField())
            << "  minP = " << gMin(fluid.p().primitiveField())
            << endl;

        runTime.write();
    }

    Info<< "ExecutionTime = " << runTime.elapsedCpuTime() << " s"
        << "  ClockTime = " << runTime.elapsedClockTime() << " s"
        << nl << "End\n" << endl;

    return 0;
}


// ************************************************************************* //

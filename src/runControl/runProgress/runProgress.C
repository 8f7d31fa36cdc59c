/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include "Time.H"
#include <cstdio>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::runProgress::runProgress(const Time& runTime, const scalar interval)
:
    runTime_(runTime),
    interval_(interval),
    time0_(runTime.value()),
    wall0_(clock::now()),
    lastReport_(wall0_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::runProgress::report()
{
    const clock::time_point now = clock::now();
    const double sinceLast =
        std::chrono::duration<double>(now - lastReport_).count();
    if (sinceLast < interval_)
    {
        return;
    }
    lastReport_ = now;

    const double elapsed = std::chrono::duration<double>(now - wall0_).count();
    const scalar t = runTime_.value();
    const scalar t0 = runTime_.startTime().value();
    const scalar tEnd = runTime_.endTime().value();

    const scalar fraction = (tEnd > t0) ? (t - t0)/(tEnd - t0) : 1;

    // Simulated time per wall-clock second since construction
    char eta[64] = "unknown";
    if (t > time0_ && elapsed > 0)
    {
        const double left = (tEnd - t)*elapsed/(t - time0_);
        std::snprintf(eta, sizeof(eta), "%.0f s", left > 0 ? left : 0.0);
    }

    char line[256];
    std::snprintf
    (
        line, sizeof(line),
        "Progress: %.1f %% of endTime (t = %g, step %ld), elapsed %.0f s,"
        " estimated time left %s",
        100*fraction, t, long(runTime_.timeIndex()), elapsed, eta
    );
    Info<< line << endl;
}


// ************************************************************************* //

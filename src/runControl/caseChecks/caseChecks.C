/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "caseChecks.H"
#include "Time.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Enum.H"

#include <cmath>
#include <cstdlib>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
using namespace Foam;

//- Number of ranks an MPI launcher started (Open MPI, MPICH/PMI, PMIx,
//  Slurm), 1 when none is set
label launcherSize()
{
    for
    (
        const char* var
      : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"}
    )
    {
        const char* value = ::getenv(var);
        if (value && *value)
        {
            return label(std::atol(value));
        }
    }
    return 1;
}

bool hasSpace(const std::string& s)
{
    return s.find_first_of(" \t") != std::string::npos;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::caseChecks::checkCasePath(int argc, char* argv[])
{
    // fileName (hence argList) strips spaces, with only a debug message:
    // look at the raw working directory and -case argument before argList
    char buf[4096];
    std::string dir = ::getcwd(buf, sizeof(buf)) ? buf : "";
    for (int i = 1; i + 1 < argc; ++i)
    {
        if (std::string(argv[i]) == "-case")
        {
            const std::string c(argv[i + 1]);
            dir = (!c.empty() && c[0] == '/') ? c : dir + '/' + c;
        }
    }
    if (hasSpace(dir))
    {
        FatalErrorInFunction
            << "the case path '" << dir.c_str() << "' contains a space:"
            << " OpenFOAM removes spaces from file names and would read"
            << " another directory. Rename or move the case to a path"
            << " without spaces" << exit(FatalError);
    }
}


void Foam::caseChecks::checkLaunch(const argList& args)
{
    const label nRanks = launcherSize();
    if (nRanks > 1 && !Pstream::parRun())
    {
        FatalErrorInFunction
            << "started by an MPI launcher with " << nRanks << " ranks but"
            << " without -parallel: every rank would run the whole case and"
            << " write the same files. Use 'mpirun -np " << nRanks << ' '
            << args.executable() << " -parallel' (after decomposePar), or"
            << " run without mpirun" << exit(FatalError);
    }
}


void Foam::caseChecks::checkControlDict(const dictionary& dict)
{
    scalar deltaT = 0;
    if
    (
        !dict.readIfPresent("deltaT", deltaT)
     || !std::isfinite(deltaT) || !(deltaT > 0)
    )
    {
        FatalIOErrorInFunction(dict)
            << "entry 'deltaT' is "
            << (dict.found("deltaT") ? Foam::name(deltaT) : word("missing"))
            << "; it must be > 0 (the first time step, and the step of runs"
            << " without adjustTimeStep)" << exit(FatalIOError);
    }

    const word writeControl =
        dict.getOrDefault<word>("writeControl", "timeStep");
    scalar writeInterval = 0;
    if (dict.readIfPresent("writeInterval", writeInterval))
    {
        // (std::isfinite first: comparing a NaN traps under FOAM_SIGFPE)
        if (!std::isfinite(writeInterval))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'writeInterval' is " << writeInterval << "; it must"
                << " be a finite number > 0" << exit(FatalIOError);
        }
        if (writeControl == "timeStep" && !(writeInterval >= 1))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'writeInterval' is " << writeInterval << "; with"
                << " writeControl timeStep it must be a number of steps >= 1"
                << exit(FatalIOError);
        }
        if (!(writeInterval > 0))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'writeInterval' is " << writeInterval << "; it must"
                << " be > 0 (writeControl " << writeControl << ')'
                << exit(FatalIOError);
        }
    }

    const word stopAt = dict.getOrDefault<word>("stopAt", "endTime");
    scalar startTime = 0, endTime = 0;
    if
    (
        stopAt == "endTime"
     && dict.readIfPresent("startTime", startTime)
     && dict.readIfPresent("endTime", endTime)
     && endTime < startTime
    )
    {
        FatalIOErrorInFunction(dict)
            << "entry 'endTime' " << endTime << " is before entry 'startTime' "
            << startTime << ": the run would end at once and do nothing"
            << exit(FatalIOError);
    }
}


void Foam::caseChecks::checkControlDict(const argList& args)
{
    const fileName file = args.globalPath()/"system"/"controlDict";
    if (!isFile(file))
    {
        return;    // Time reports the missing file
    }
    IFstream is(file);
    const dictionary dict(is);
    checkControlDict(dict);
}


void Foam::caseChecks::checkStartTime(const Time& runTime)
{
    const dictionary& dict = runTime.controlDict();
    if
    (
        dict.getOrDefault<word>("stopAt", "endTime") == "endTime"
     && runTime.endTime().value() < runTime.value()
    )
    {
        FatalIOErrorInFunction(dict)
            << "entry 'endTime' " << runTime.endTime().value()
            << " is before the start time " << runTime.timeName()
            << " (startFrom "
            << dict.getOrDefault<word>("startFrom", "startTime")
            << "): the run would end at once and do nothing"
            << exit(FatalIOError);
    }
}


void Foam::caseChecks::checkNoDuplicateEntries(const dictionary& dict)
{
    const fileName file = dict.name();
    if (!isFile(file))
    {
        return;
    }
    // dictionary(Istream&) resets the input mode: read into an empty one
    const entry::inputMode oldMode = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    {
        IFstream is(file);
        dictionary reread(file);
        reread.read(is);
    }
    entry::globalInputMode = oldMode;
}


// ************************************************************************* //

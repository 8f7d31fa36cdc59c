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
#include "IOobject.H"
#include "objectRegistry.H"
#include "dimensionSet.H"
#include "vector.H"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
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


//- OpenFOAM's tokenizer aborts (a signal) on a negative size of a compound
//  list ('nonuniform List<scalar> -1 (...)'): look at the text first
void negativeCompoundSize(const fileName& file)
{
    std::ifstream raw(file);
    const std::string text
    (
        (std::istreambuf_iterator<char>(raw)), std::istreambuf_iterator<char>()
    );
    for
    (
        auto pos = text.find("List<");
        pos != std::string::npos;
        pos = text.find("List<", pos + 5)
    )
    {
        const auto gt = text.find('>', pos);
        const auto k =
            gt == std::string::npos
          ? gt : text.find_first_not_of(" \t\r\n", gt + 1);
        if (k != std::string::npos && text[k] == '-')
        {
            const label line =
                1 + std::count(text.begin(), text.begin() + k, '\n');
            FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, file, line)
                << "the size of the list "
                << text.substr(pos, gt - pos + 1).c_str() << " at line "
                << line << " is negative" << exit(FatalIOError);
        }
    }
}


//- Every value of a compound list token (nonuniform field values) finite
//  and of magnitude <= maxMag; false if not
bool compoundInRange(const token& t, const scalar maxMag)
{
    auto ok = [maxMag](const scalar x)
    {
        return std::isfinite(x) && std::abs(x) <= maxMag;
    };
    const token::compound& c = t.compoundToken();
    typedef token::Compound<List<scalar>> scalars;
    typedef token::Compound<List<vector>> vectors;
    if (const auto* s = dynamic_cast<const scalars*>(&c))
    {
        for (const scalar x : static_cast<const List<scalar>&>(*s))
        {
            if (!ok(x)) return false;
        }
    }
    else if (const auto* v = dynamic_cast<const vectors*>(&c))
    {
        for (const vector& x : static_cast<const List<vector>&>(*v))
        {
            if (!ok(x.x()) || !ok(x.y()) || !ok(x.z())) return false;
        }
    }
    return true;
}


//- The checks of checkFieldFile on the file of io (if present); its
//  'dimensions' into *dims when asked for. False without file or entry
bool fieldFileDimensions(const IOobject& io, dimensionSet* dims = nullptr)
{
    const fileName file = io.objectPath();
    if (!isFile(file))
    {
        return false;    // the reader reports a missing MUST_READ field
    }
    negativeCompoundSize(file);
    IFstream is(file);
    const dictionary dict(is);
    const bool found = dict.found("dimensions");
    if (found)
    {
        // OpenFOAM's unit lookup fails without naming the file
        dimensionSet read(dimless);
        caseChecks::readNaming
        (
            dict,
            [&]()
            {
                ITstream& ds = dict.lookup("dimensions");
                ds >> read;
            }
        );
        if (dims)
        {
            dims->reset(read);    // (operator= checks the dimensions)
        }
    }
    caseChecks::checkNumbers(dict, GREAT);
    return found;
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
        if (writeControl == "timeStep" && !(writeInterval <= labelMax))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'writeInterval' is " << writeInterval << "; with"
                << " writeControl timeStep it must be a number of steps <= "
                << labelMax << exit(FatalIOError);
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
    if (stopAt == "endTime" && endTime > startTime && deltaT > endTime - startTime)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'deltaT' " << deltaT << " is longer than the run"
            << " (endTime - startTime = " << endTime - startTime << ')'
            << exit(FatalIOError);
    }
}


void Foam::caseChecks::checkControlDict
(
    const argList& args,
    const bool globalTimes
)
{
    const fileName file = args.globalPath()/"system"/"controlDict";
    if (!isFile(file))
    {
        return;    // Time reports the missing file
    }
    IFstream is(file);
    const dictionary dict(is);
    checkControlDict(dict);

    // startFrom startTime other than 0: the time directory must exist
    // (else OpenFOAM names a missing field file of a time nobody wrote)
    scalar startTime = 0;
    if
    (
        dict.getOrDefault<word>("startFrom", "startTime") == "startTime"
     && dict.readIfPresent("startTime", startTime) && startTime != 0
    )
    {
        instantList times = Time::findTimes(args.path(), "constant");
        if (globalTimes && Pstream::parRun())
        {
            times.append(Time::findTimes(args.globalPath(), "constant"));
        }
        bool found = false;
        for (const instant& t : times)
        {
            found = found
             || mag(t.value() - startTime) <= 1e-12*max(mag(startTime), 1);
        }
        if (!found && std::isfinite(startTime))
        {
            FatalIOErrorInFunction(dict)
                << "entry 'startTime' " << startTime << " (startFrom"
                << " startTime): the case has no time directory for it"
                << exit(FatalIOError);
        }
    }
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


void Foam::caseChecks::checkNumbers(const dictionary& dict, const scalar maxMag)
{
    for (const entry& e : dict)
    {
        if (e.isDict())
        {
            checkNumbers(e.dict(), maxMag);
            continue;
        }
        const ITstream& is = e.stream();
        forAll(is, i)
        {
            const token& t = is[i];
            if (t.isCompound() && !compoundInRange(t, maxMag))
            {
                FatalIOErrorInFunction(dict)
                    << "entry '" << e.keyword() << "': a value of the list is"
                    << " not finite or of magnitude > " << maxMag
                    << exit(FatalIOError);
            }
            if (!t.isNumber())
            {
                continue;
            }
            // (std::isfinite first: comparing a NaN traps under FOAM_SIGFPE)
            const scalar x = t.number();
            const bool size =
                t.isLabel() && i + 1 < is.size() && is[i + 1].isPunctuation()
             && (is[i + 1].pToken() == token::BEGIN_LIST
              || is[i + 1].pToken() == token::BEGIN_BLOCK);
            if (!std::isfinite(x) || mag(x) > maxMag || (size && x < 0))
            {
                FatalIOErrorInFunction(dict)
                    << "entry '" << e.keyword() << "': "
                    << (size ? "list size " : "number ") << x
                    << (size ? " is negative" : " is out of range")
                    << " (numbers must be finite, of magnitude <= " << maxMag
                    << "; list sizes >= 0)" << exit(FatalIOError);
            }
        }
    }
}


void Foam::caseChecks::checkInput(const dictionary& dict)
{
    checkNoDuplicateEntries(dict);
    checkNumbers(dict);
}


const Foam::IOobject& Foam::caseChecks::checkFieldFile(const IOobject& io)
{
    fieldFileDimensions(io);
    return io;
}


const Foam::IOobject& Foam::caseChecks::checkFieldFile
(
    const IOobject& io,
    const dimensionSet& expected
)
{
    dimensionSet dims(expected);
    if (fieldFileDimensions(io, &dims))
    {
        checkDimensions(io, dims, expected);
    }
    return io;
}


Foam::IOobject Foam::caseChecks::fieldIO
(
    const word& name,
    const objectRegistry& db,
    const IOobject::readOption r
)
{
    IOobject io(name, db.time().timeName(), db, r, IOobject::AUTO_WRITE);
    // Numbers, list sizes and dimensions before OpenFOAM reads the file
    if (r != IOobject::NO_READ)
    {
        checkFieldFile(io);
    }
    return io;
}


void Foam::caseChecks::checkDimensions
(
    const IOobject& io,
    const dimensionSet& dims,
    const dimensionSet& expected
)
{
    if (dims != expected)
    {
        FatalIOError(FUNCTION_NAME, __FILE__, __LINE__, io.objectPath(), -1)
            << "file " << io.objectPath() << ": entry 'dimensions' is "
            << dims << " but " << io.name() << " must have the dimensions "
            << expected << " (SI units)" << exit(FatalIOError);
    }
}


// ************************************************************************* //

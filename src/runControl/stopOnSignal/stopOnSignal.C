/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

\*---------------------------------------------------------------------------*/

#include "stopOnSignal.H"
#include "Time.H"
#include "PstreamReduceOps.H"
#include "error.H"
#include "Pstream.H"
#include <fcntl.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Number of the last signal received (0: none). Only written by the handler.
volatile std::sig_atomic_t receivedSignal_ = 0;

// Parallel run: on a signal, make the output non-blocking (see below)
volatile std::sig_atomic_t parallel_ = 0;

extern "C" void stopOnSignalHandler(int sigNum)
{
    receivedSignal_ = sigNum;

    // mpirun, when it is signalled itself, stops reading the ranks' output
    // and forwards SIGTERM a second later (SIGKILL one more second later):
    // the master, blocked writing its log into the full pipe, would never
    // reach the write. The signal interrupts that write (no SA_RESTART);
    // from now on log lines that do not fit are dropped instead of waiting
    // (fcntl is async-signal-safe). Not in serial runs: the output may be
    // the terminal, shared with the shell
    if (parallel_)
    {
        for (const int fd : {1, 2})
        {
            const int flags = fcntl(fd, F_GETFL);
            if (flags != -1)
            {
                fcntl(fd, F_SETFL, flags | O_NONBLOCK);
            }
        }
    }
}


void installHandler(const int sigNum, struct sigaction* oldAction)
{
    struct sigaction action;
    action.sa_handler = stopOnSignalHandler;
    // A second signal of the same kind gets the default action (kill)
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    if (sigaction(sigNum, &action, oldAction) < 0)
    {
        FatalErrorInFunction
            << "cannot install the handler for "
            << Foam::stopOnSignal::signalName(sigNum)
            << Foam::exit(Foam::FatalError);
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::stopOnSignal::stopOnSignal()
:
    stopped_(false)
{
    receivedSignal_ = 0;
    parallel_ = Pstream::parRun();
    installHandler(SIGINT, &oldInt_);
    installHandler(SIGTERM, &oldTerm_);
    installHandler(SIGUSR1, &oldUsr1_);
    installHandler(SIGUSR2, &oldUsr2_);

    // A closed output (the reader of the log gone) must not end the run
    // unwritten: mpirun, when it is signalled itself, stops reading the
    // ranks' output at once and sends them SIGTERM only a second later; by
    // default the master's next log line would raise SIGPIPE and kill it.
    // Writes to the closed output fail instead, the run goes on
    struct sigaction ignore;
    ignore.sa_handler = SIG_IGN;
    ignore.sa_flags = 0;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &oldPipe_);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::stopOnSignal::~stopOnSignal()
{
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
    sigaction(SIGUSR1, &oldUsr1_, nullptr);
    sigaction(SIGUSR2, &oldUsr2_, nullptr);
    sigaction(SIGPIPE, &oldPipe_, nullptr);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::stopOnSignal::requested() const
{
    return receivedSignal_ != 0;
}


int Foam::stopOnSignal::signalNumber() const
{
    return receivedSignal_;
}


Foam::word Foam::stopOnSignal::signalName(const int sigNum)
{
    switch (sigNum)
    {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        case SIGUSR1: return "SIGUSR1";
        case SIGUSR2: return "SIGUSR2";
        default: return "signal_" + Foam::name(sigNum);
    }
}


bool Foam::stopOnSignal::check(Time& runTime)
{
    if (stopped_)
    {
        return true;
    }

    // Read the flag once; reduce so that every rank stops at this step
    const label sigNum =
        returnReduce(label(receivedSignal_), maxOp<label>());

    if (sigNum == 0)
    {
        return false;
    }

    stopped_ = true;
    Info<< nl << "Signal " << signalName(sigNum) << " received at time "
        << runTime.timeName()
        << ": writing the current state and stopping" << nl << endl;

    // Writes the registered objects, sets writeTime() for the rest of this
    // step and endTime = now, so run() is false at the next call
    runTime.writeAndEnd();

    return true;
}


// ************************************************************************* //

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

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

// Number of the last signal received (0: none). Only written by the handler.
volatile std::sig_atomic_t receivedSignal_ = 0;

extern "C" void stopOnSignalHandler(int sigNum)
{
    receivedSignal_ = sigNum;
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
    installHandler(SIGINT, &oldInt_);
    installHandler(SIGTERM, &oldTerm_);
    installHandler(SIGUSR1, &oldUsr1_);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * //

Foam::stopOnSignal::~stopOnSignal()
{
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
    sigaction(SIGUSR1, &oldUsr1_, nullptr);
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

// librunControl: stopOnSignal with the solver loop pattern of jwlIbFoam
// (registered objects written by runTime.write()) and runProgress's line.
#include <gtest/gtest.h>
#include "stopOnSignal.H"
#include "runProgress.H"
#include "Time.H"
#include "IOdictionary.H"
#include "OSspecific.H"
#include <csignal>
#include <sstream>

using namespace Foam;

namespace
{

// A Time in <cwd>/<caseName>: t = 0, 1, ..., 100, write every 1000 steps
// (so no regular write time in the run)
autoPtr<Time> makeTime(const word& caseName)
{
    if (isDir(cwd()/caseName)) rmDir(cwd()/caseName);
    dictionary controlDict;
    controlDict.add("startTime", 0);
    controlDict.add("endTime", 100);
    controlDict.add("deltaT", 1);
    controlDict.add("writeControl", "timeStep");
    controlDict.add("writeInterval", 1000);
    return autoPtr<Time>
    (
        new Time(controlDict, cwd(), caseName, "system", "constant",
                 false, false)
    );
}


// The loop of jwlIbFoam/femdemFoam; the signal is raised during step
// raiseAt. Returns the steps at which writeTime() was true for the solver's
// own write block.
labelList runLoop(Time& runTime, const int sigNum, const label raiseAt)
{
    IOdictionary probe
    (
        IOobject("probe", runTime.timeName(), runTime,
                 IOobject::NO_READ, IOobject::AUTO_WRITE)
    );
    probe.add("value", 1);

    stopOnSignal stop;
    EXPECT_FALSE(stop.requested());
    DynamicList<label> writeSteps;
    while (runTime.run())
    {
        ++runTime;
        if (runTime.timeIndex() == raiseAt)
        {
            std::raise(sigNum);
            EXPECT_TRUE(stop.requested());
        }
        const bool stopping = stop.check(runTime);
        EXPECT_EQ(stopping, raiseAt > 0 && runTime.timeIndex() >= raiseAt);
        if (runTime.writeTime())
        {
            writeSteps.append(runTime.timeIndex());
        }
        runTime.write();
    }
    return labelList(writeSteps);
}

} // End anonymous namespace


TEST(stopOnSignal, SIGTERMWritesTheCurrentStepAndEndsTheLoop)
{
    autoPtr<Time> runTime = makeTime("stopOnSignalTERM");
    const labelList writeSteps = runLoop(*runTime, SIGTERM, 7);
    EXPECT_EQ(writeSteps, labelList({7}));
    EXPECT_EQ(runTime->timeIndex(), 7);
    EXPECT_FALSE(runTime->run());
    EXPECT_TRUE(isFile(runTime->path()/"7"/"probe"));
    EXPECT_TRUE(isFile(runTime->path()/"7"/"uniform"/"time"));
    RecordProperty("stopStep", int(runTime->timeIndex()));
}


TEST(stopOnSignal, SIGINTWritesTheCurrentStepAndEndsTheLoop)
{
    autoPtr<Time> runTime = makeTime("stopOnSignalINT");
    const labelList writeSteps = runLoop(*runTime, SIGINT, 3);
    EXPECT_EQ(writeSteps, labelList({3}));
    EXPECT_FALSE(runTime->run());
    EXPECT_TRUE(isFile(runTime->path()/"3"/"probe"));
}


// mpirun forwards SIGUSR1 without aborting the job: the clean stop of a
// parallel run with mpirun's exit status 0
TEST(stopOnSignal, SIGUSR1WritesTheCurrentStepAndEndsTheLoop)
{
    autoPtr<Time> runTime = makeTime("stopOnSignalUSR1");
    const labelList writeSteps = runLoop(*runTime, SIGUSR1, 5);
    EXPECT_EQ(writeSteps, labelList({5}));
    EXPECT_FALSE(runTime->run());
    EXPECT_TRUE(isFile(runTime->path()/"5"/"probe"));
    EXPECT_EQ(stopOnSignal::signalName(SIGUSR1), word("SIGUSR1"));
}


TEST(stopOnSignal, NoSignalRunsToEndTime)
{
    autoPtr<Time> runTime = makeTime("stopOnSignalNone");
    const labelList writeSteps = runLoop(*runTime, SIGTERM, -1);
    EXPECT_TRUE(writeSteps.empty());
    EXPECT_EQ(runTime->timeIndex(), 100);
    EXPECT_EQ(stopOnSignal::signalName(SIGTERM), word("SIGTERM"));
    EXPECT_EQ(stopOnSignal::signalName(SIGINT), word("SIGINT"));
}


TEST(runProgress, LineGivesFractionStepAndEstimate)
{
    autoPtr<Time> runTime = makeTime("runProgress");
    runProgress progress(*runTime, 0);  // 0: a line at every call
    for (label i = 0; i < 25; ++i)
    {
        ++(*runTime);
    }
    std::ostringstream captured;
    std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
    progress.report();
    std::cout.rdbuf(old);
    const std::string line = captured.str();
    EXPECT_EQ
    (
        line.rfind("Progress: 25.0 % of endTime (t = 25, step 25), elapsed ", 0),
        0u
    ) << line;
    EXPECT_NE(line.find("estimated time left "), std::string::npos) << line;

    // An interval not yet reached prints nothing
    runProgress quiet(*runTime, 3600);
    captured.str("");
    old = std::cout.rdbuf(captured.rdbuf());
    quiet.report();
    std::cout.rdbuf(old);
    EXPECT_TRUE(captured.str().empty());
}

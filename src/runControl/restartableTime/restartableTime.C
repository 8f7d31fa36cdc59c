/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

\*---------------------------------------------------------------------------*/

#include "restartableTime.H"
#include "IOdictionary.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Sets a scalar for the lifetime of the object, then restores it
class scopedValue
{
    Foam::scalar& ref_;
    const Foam::scalar saved_;

public:

    scopedValue(Foam::scalar& ref, const Foam::scalar value)
    :
        ref_(ref),
        saved_(ref)
    {
        ref_ = value;
    }

    ~scopedValue()
    {
        ref_ = saved_;
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::restartableTime::restoreState()
{
    writeStart_ = startTime_;

    const IOdictionary timeDict
    (
        IOobject
        (
            "time",
            timeName(),
            "uniform",
            *this,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        )
    );

    // The exact time, if it is the one the directory name stands for
    scalar exact = 0;
    if
    (
        timeDict.readIfPresent("value", exact)
     && timeName(exact) == timeName()
    )
    {
        startTime_ = userTimeToTime(exact);
        setTime(startTime_, timeIndex());
    }

    // The write schedule, if writeControl and writeInterval are the same
    word control;
    scalar interval = 0, start = 0;
    label index = 0;
    if
    (
        (
            writeControl_ == wcRunTime
         || writeControl_ == wcAdjustableRunTime
        )
     && timeDict.readIfPresent("writeScheduleControl", control)
     && control == writeControlNames[writeControl_]
     && timeDict.readIfPresent("writeScheduleInterval", interval)
     && interval == writeInterval_
     && timeDict.readIfPresent("writeScheduleStart", start)
     && timeDict.readIfPresent("writeScheduleIndex", index)
    )
    {
        writeStart_ = userTimeToTime(start);
        writeTimeIndex_ = index;
        Info<< "Write schedule continued: writeControl " << control
            << ", writeInterval " << interval << " from time " << start
            << " (" << index << " write times before " << timeName() << ")"
            << nl << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::restartableTime::restartableTime
(
    const word& ctrlDictName,
    const argList& args
)
:
    Time(ctrlDictName, args),
    writeStart_(startTime_)
{
    restoreState();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::restartableTime::writeTimeDict() const
{
    // Time::writeTimeDict's entries and the write schedule; the times with
    // the full precision of "value" so that they are read back exactly
    const word tmName(timeName());
    IOdictionary timeDict
    (
        IOobject
        (
            "time",
            tmName,
            "uniform",
            *this,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    timeDict.add("value", timeName(timeToUserTime(value()), maxPrecision_));
    timeDict.add("name", string(tmName));
    timeDict.add("index", timeIndex_);
    timeDict.add("deltaT", timeToUserTime(deltaT_));
    timeDict.add("deltaT0", timeToUserTime(deltaT0_));
    timeDict.add("writeScheduleControl", writeControlNames[writeControl_]);
    timeDict.add
    (
        "writeScheduleInterval", timeName(writeInterval_, maxPrecision_)
    );
    timeDict.add
    (
        "writeScheduleStart", timeName(timeToUserTime(writeStart_), maxPrecision_)
    );
    timeDict.add("writeScheduleIndex", writeTimeIndex_);

    return timeDict.regIOobject::writeObject
    (
        IOstream::ASCII,
        IOstream::currentVersion,
        IOstream::UNCOMPRESSED,
        true
    );
}


void Foam::restartableTime::setDeltaT(const scalar deltaT, const bool adjust)
{
    const scopedValue start(startTime_, writeStart_);
    Time::setDeltaT(deltaT, adjust);
}


// * * * * * * * * * * * * * * * Member Operators  * * * * * * * * * * * * * //

Foam::Time& Foam::restartableTime::operator++()
{
    const scopedValue start(startTime_, writeStart_);
    return Time::operator++();
}


// ************************************************************************* //

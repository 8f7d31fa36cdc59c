/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "solidProbes.H"
#include "Time.H"
#include "OSspecific.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(solidProbes, 0);
    addToRunTimeSelectionTable(functionObject, solidProbes, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::femdemSolid& Foam::functionObjects::solidProbes::solid() const
{
    const femdemSolid* s = femdemSolid::active();
    if (!s)
    {
        FatalIOErrorInFunction(dict_)
            << "function object " << name() << " (type solidProbes): the"
            << " solver " << time_.caseName() << " runs has no FEMDEM solid"
            << " (constant/femdemProperties)" << exit(FatalIOError);
    }
    return *s;
}


void Foam::functionObjects::solidProbes::setUp()
{
    probes_.reset(new femdemProbes(solid(), dict_));
    if (!Pstream::master()) return;

    // postProcessing/<name>/<startTime>/velocity.dat; never overwrite a
    // file of an earlier run from the same start time
    const fileName dir =
        time_.globalPath()/"postProcessing"/name()/time_.timeName();
    mkDir(dir);
    fileName path = dir/"velocity.dat";
    for (label k = 1; isFile(path); ++k)
    {
        path = dir/("velocity_" + Foam::name(k) + ".dat");
    }
    file_.reset(new OFstream(path));
    OFstream& os = file_();
    os.precision(10);
    os  << "# Solid probes: velocity [m/s] at material points (initial"
        << " positions)" << nl;
    forAll(probes_->points(), i)
    {
        const vector2D& p = probes_->points()[i];
        os  << "# Probe " << i << " (" << p.x() << ' ' << p.y()
            << ") triangle " << probes_->triangles()[i] << nl;
    }
    os  << "# Time";
    forAll(probes_->points(), i)
    {
        os  << " probe" << i << "_Ux probe" << i << "_Uy";
    }
    os  << endl;
}


void Foam::functionObjects::solidProbes::writeRow()
{
    if (!probes_) setUp();
    if (!file_) return;
    const List<vector2D> v = probes_->velocity(solid());
    OFstream& os = file_();
    os  << time_.value();
    for (const vector2D& u : v)
    {
        os  << ' ' << u.x() << ' ' << u.y();
    }
    os  << endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::solidProbes::solidProbes
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    timeFunctionObject(name, runTime),
    dict_(dict)
{
    read(dict);
    // The state at the start time, when the solver has its solid already
    if (femdemSolid::active())
    {
        writeRow();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::solidProbes::read(const dictionary& dict)
{
    timeFunctionObject::read(dict);
    dict_ = dict;
    if (!dict_.found("points"))
    {
        FatalIOErrorInFunction(dict_)
            << "function object " << name() << " (type solidProbes): entry"
            << " 'points' ((x y) ...) is missing" << exit(FatalIOError);
    }
    probes_.clear();
    file_.clear();
    return true;
}


bool Foam::functionObjects::solidProbes::execute()
{
    writeRow();
    return true;
}


bool Foam::functionObjects::solidProbes::write()
{
    return true;
}


// ************************************************************************* //

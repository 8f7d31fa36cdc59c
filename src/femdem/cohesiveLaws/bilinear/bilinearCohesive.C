/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bilinearCohesive.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace cohesiveLaws
{
    defineTypeNameAndDebug(bilinear, 0);
    addToRunTimeSelectionTable(cohesiveLaw, bilinear, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cohesiveLaws::bilinear::bilinear(const dictionary& dict)
:
    curveCohesiveLaw<bilinearCurve>(dict)
{}


// ************************************************************************* //

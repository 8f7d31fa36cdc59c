/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "noContact.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace contactLaws
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(contactLaw, none, dictionary);
}
}

// ************************************************************************* //

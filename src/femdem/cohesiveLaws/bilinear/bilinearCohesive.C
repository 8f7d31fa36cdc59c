/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "bilinearCohesive.H"
#include "cohesiveLawTemplates.H"
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
    cohesiveLaw(dict)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::cohesiveLaws::bilinear::addForces
(
    femdemSolid& solid,
    UList<vector2D>& f
) const
{
    return processJoints(curve_, solid, f);
}


Foam::scalar Foam::cohesiveLaws::bilinear::storedEnergy
(
    const femdemSolid& solid
) const
{
    return storedEnergyOf(curve_, solid);
}


void Foam::cohesiveLaws::bilinear::traction
(
    const femdemJointProperties& P,
    const scalar h,
    const scalar o,
    const scalar s,
    scalar& damage,
    scalar& sigma,
    scalar& tau
) const
{
    tractionOf(curve_, P, h, o, s, damage, sigma, tau);
}


// ************************************************************************* //

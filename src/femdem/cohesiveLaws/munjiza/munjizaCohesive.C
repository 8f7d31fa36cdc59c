/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "munjizaCohesive.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace cohesiveLaws
{
    defineTypeNameAndDebug(munjiza, 0);
    addToRunTimeSelectionTable(cohesiveLaw, munjiza, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cohesiveLaws::munjiza::munjiza(const dictionary& dict)
:
    curveCohesiveLaw<munjizaCurve>(dict)
{
    const dictionary coeffs = dict.subOrEmptyDict("munjizaCoeffs");
    curve_.a = coeffs.getOrDefault<scalar>("a", 0.63);
    curve_.b = coeffs.getOrDefault<scalar>("b", 1.8);
    curve_.c = coeffs.getOrDefault<scalar>("c", 6.0);
    const scalar a = curve_.a, b = curve_.b, c = curve_.c;
    if (!(a > 0 && b > 0 && c > 0 && a + b > 1))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'munjizaCoeffs': need a, b, c > 0 and a + b > 1"
            << exit(FatalIOError);
    }
    curve_.A = (a + b - 1)/(a + b);
    curve_.B = (a + c*b)/((a + b)*(1 - a - b));

    // Area under z by Simpson's rule (smooth: 4000 intervals is exact to
    // round-off for the 1 % energy statements)
    const label n = 4000;
    scalar sum = curve_.z(0) + curve_.z(1);
    for (label i = 1; i < n; ++i)
    {
        sum += (i % 2 ? 4 : 2)*curve_.z(scalar(i)/n);
    }
    curve_.aSoft = sum/(3*n);
}


// ************************************************************************* //

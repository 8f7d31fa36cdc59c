/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastLimiters.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace blastLimiters
{
    defineTypeNameAndDebug(none, 0);
    addToRunTimeSelectionTable(blastLimiter, none, dictionary);

    defineTypeNameAndDebug(minmod, 0);
    addToRunTimeSelectionTable(blastLimiter, minmod, dictionary);

    defineTypeNameAndDebug(vanLeer, 0);
    addToRunTimeSelectionTable(blastLimiter, vanLeer, dictionary);

    defineTypeNameAndDebug(vanAlbada, 0);
    addToRunTimeSelectionTable(blastLimiter, vanAlbada, dictionary);

    defineTypeNameAndDebug(MC, 0);
    addToRunTimeSelectionTable(blastLimiter, MC, dictionary);

    defineTypeNameAndDebug(superbee, 0);
    addToRunTimeSelectionTable(blastLimiter, superbee, dictionary);
}
}


// ************************************************************************* //

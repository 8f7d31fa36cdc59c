/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastLimiter.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(blastLimiter, 0);
    defineRunTimeSelectionTable(blastLimiter, dictionary);
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::blastLimiter> Foam::blastLimiter::New
(
    const dictionary& dict
)
{
    const word limiterType(dict.getOrDefault<word>("limiter", "vanLeer"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(limiterType);

    if (!cstrIter.found())
    {
        // Names the file (dict.name()), the entry and the valid names
        FatalIOErrorInLookup
        (
            dict,
            "limiter",
            limiterType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<blastLimiter>(cstrIter()(dict));
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "equationOfState.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(equationOfState, 0);
    defineRunTimeSelectionTable(equationOfState, dictionary);
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::equationOfState::readPositive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be strictly positive, got "
            << value << exit(FatalIOError);
    }
    return value;
}


Foam::scalar Foam::equationOfState::readPositiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be strictly positive, got "
            << value << exit(FatalIOError);
    }
    return value;
}


void Foam::equationOfState::checkEntries
(
    const dictionary& dict,
    const wordList& valid
) const
{
    for (const entry& e : dict)
    {
        const word key(e.keyword());
        if (key != "equationOfState" && !valid.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << key << "' for material " << name_
                << " (equationOfState "
                << dict.getOrDefault<word>("equationOfState", "?")
                << "). Valid entries: " << valid << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationOfState::equationOfState
(
    const word& name,
    const dictionary& dict
)
:
    name_(name)
{}


// ************************************************************************* //

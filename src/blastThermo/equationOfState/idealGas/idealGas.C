/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "idealGas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(idealGas, 0);
    addToRunTimeSelectionTable(equationOfState, idealGas, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationsOfState::idealGas::idealGas
(
    const word& name,
    const dictionary& dict
)
:
    mieGruneisenEOS<idealGas>(name, dict),
    gamma_(dict.getOrDefault<scalar>("gamma", 1.4)),
    Cv_(readPositiveOrDefault(dict, "Cv", 718))
{
    checkEntries(dict, wordList({"gamma", "Cv"}));

    if (!(gamma_ > 1))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'gamma' of material " << name
            << " must be > 1, got " << gamma_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::equationsOfState::idealGas::write(Ostream& os) const
{
    os  << name_ << ": idealGas gamma " << gamma_ << " Cv " << Cv_ << nl;
}


// ************************************************************************* //

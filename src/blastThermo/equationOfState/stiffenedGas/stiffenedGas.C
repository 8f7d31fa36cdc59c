/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "stiffenedGas.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(stiffenedGas, 0);
    addToRunTimeSelectionTable(equationOfState, stiffenedGas, dictionary);
}
}

Foam::equationsOfState::stiffenedGas::stiffenedGas
(
    const word& name,
    const dictionary& dict
)
:
    mieGruneisenEOS<stiffenedGas>(name, dict),
    gamma_(dict.get<scalar>("gamma")),
    pInf_(dict.get<scalar>("pInf"))
{
    checkEntries(dict, wordList({"gamma", "pInf"}));

    if (!(gamma_ > 1) || pInf_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Material " << name << ": need gamma > 1 and pInf >= 0, got "
            << "gamma " << gamma_ << " pInf " << pInf_ << exit(FatalIOError);
    }
}


void Foam::equationsOfState::stiffenedGas::write(Ostream& os) const
{
    os  << name_ << ": stiffenedGas gamma " << gamma_ << " pInf " << pInf_
        << nl;
}


// ************************************************************************* //

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

constexpr Foam::scalar
Foam::equationsOfState::stiffenedGas::liquidCavitationPressure;

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
    checkEntries(dict, wordList({"gamma", "pInf", "cavitationPressure"}));

    if (!(gamma_ > 1) || pInf_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Material " << name << ": need gamma > 1 and pInf >= 0, got "
            << "gamma " << gamma_ << " pInf " << pInf_ << exit(FatalIOError);
    }

    // A liquid (pInf > 0) cavitates by default: without the cut-off water
    // drawn into an opening crack is stretched into tension and the solver
    // stops at the first negative pressure. A gas (pInf = 0) cannot be
    // stretched below p = 0 by its equation of state: no cut-off
    pCav_ = readCavitationPressure
    (
        dict,
        pInf_ > 0 ? liquidCavitationPressure : noCavitation
    );
}


void Foam::equationsOfState::stiffenedGas::write(Ostream& os) const
{
    os  << name_ << ": stiffenedGas gamma " << gamma_ << " pInf " << pInf_;
    if (cavitates())
    {
        os  << " cavitationPressure " << pCav_;
    }
    else
    {
        os  << " cavitationPressure none";
    }
    os  << nl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "Murnaghan.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(Murnaghan, 0);
    addToRunTimeSelectionTable(equationOfState, Murnaghan, dictionary);
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationsOfState::Murnaghan::Murnaghan
(
    const word& name,
    const dictionary& dict
)
:
    mieGruneisenEOS<Murnaghan>(name, dict),
    rho0_(readPositive(dict, "rho0")),
    K0_(readPositive(dict, "K0")),
    n_(readPositive(dict, "n")),
    Gamma_(readPositive(dict, "Gamma")),
    q_(dict.getOrDefault<scalar>("q", 0)),
    p0_(dict.getOrDefault<scalar>("p0", 101325))
{
    checkEntries(dict, wordList({"rho0", "K0", "n", "Gamma", "q", "p0"}));
    check(dict);
}


Foam::equationsOfState::Murnaghan::Murnaghan
(
    const word& name,
    const dictionary& dict,
    const scalar rho0,
    const scalar K0,
    const scalar n,
    const scalar Gamma,
    const scalar q,
    const scalar p0
)
:
    mieGruneisenEOS<Murnaghan>(name, dict),
    rho0_(rho0), K0_(K0), n_(n), Gamma_(Gamma), q_(q), p0_(p0)
{
    check(dict);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::equationsOfState::Murnaghan::check(const dictionary& dict) const
{
    if
    (
        !(rho0_ > 0) || !(K0_ > 0) || !(n_ > 0) || !(Gamma_ > 0)
     || !(q_ >= 0) || !(p0_ >= 0)
    )
    {
        FatalIOErrorInFunction(dict)
            << "Material " << name_ << " (Murnaghan): need rho0, K0, n,"
            << " Gamma > 0 and q, p0 >= 0, got rho0 " << rho0_ << " K0 "
            << K0_ << " n " << n_ << " Gamma " << Gamma_ << " q " << q_
            << " p0 " << p0_ << exit(FatalIOError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::equationsOfState::Murnaghan::write(Ostream& os) const
{
    os  << name_ << ": Murnaghan rho0 " << rho0_ << " K0 " << K0_ << " n "
        << n_ << " Gamma " << Gamma_ << " q " << q_ << " p0 " << p0_
        << " (c0 " << c0() << " m/s)" << nl;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastMixture.H"
#include "SubList.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastMixture::blastMixture(const dictionary& dict)
:
    materials_(dict.get<wordList>("materials")),
    eos_(materials_.size()),
    alphaMin_(dict.getOrDefault<scalar>("alphaMin", 1e-6))
{
    if (materials_.size() < 1 || materials_.size() > 2)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'materials' must list one or two materials, got "
            << materials_ << exit(FatalIOError);
    }
    if (alphaMin_ < 0 || alphaMin_ > 0.1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'alphaMin' must be in [0, 0.1], got " << alphaMin_
            << exit(FatalIOError);
    }
    // A material defined twice would be merged, the later entries winning
    caseChecks::checkInput(dict);
    if (materials_.size() == 2 && materials_[0] == materials_[1])
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'materials' lists " << materials_[0] << " twice: two"
            << " different materials (products first) or one"
            << exit(FatalIOError);
    }
    forAll(materials_, i)
    {
        const word& name = materials_[i];
        if (!dict.isDict(name))
        {
            FatalIOErrorInFunction(dict)
                << "Missing sub-dictionary '" << name
                << "' for the material listed in 'materials'"
                << exit(FatalIOError);
        }
        eos_.set(i, equationOfState::New(name, dict.subDict(name)));
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastMixture::reserve(const label n) const
{
    if (g1_.size() < n)
    {
        g1_.setSize(n); f1_.setSize(n); d1_.setSize(n);
        if (twoPhase())
        {
            g2_.setSize(n); f2_.setSize(n); d2_.setSize(n);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::blastMixture::pc2
(
    const label n,
    const UList<scalar>& alpha1,
    const UList<scalar>& rho1,
    const UList<scalar>& rho2,
    const UList<scalar>& rho,
    const UList<scalar>& rhoe,
    UList<scalar>& p,
    UList<scalar>& c2
) const
{
    reserve(n);
    SubList<scalar> g1(g1_, n), f1(f1_, n), d1(d1_, n);
    const SubList<scalar> r1(rho1, n);
    eos_[0].Gamma(r1, g1);
    eos_[0].pRefAndDerivative(r1, f1, d1);

    if (!twoPhase())
    {
        for (label i = 0; i < n; ++i)
        {
            const scalar pi = g1[i]*rhoe[i] + f1[i];
            p[i] = pi;
            c2[i] = ((1 + g1[i])*pi - f1[i])/rho1[i] + d1[i];
        }
        return;
    }

    SubList<scalar> g2(g2_, n), f2(f2_, n), d2(d2_, n);
    const SubList<scalar> r2(rho2, n);
    eos_[1].Gamma(r2, g2);
    eos_[1].pRefAndDerivative(r2, f2, d2);

    for (label i = 0; i < n; ++i)
    {
        const scalar a1 = alpha1[i];
        const scalar a2 = 1 - a1;
        const scalar xi1 = a1/g1[i];
        const scalar xi2 = a2/g2[i];
        const scalar xi = xi1 + xi2;
        const scalar pi = (rhoe[i] + xi1*f1[i] + xi2*f2[i])/xi;
        p[i] = pi;
        const scalar c21 = ((1 + g1[i])*pi - f1[i])/rho1[i] + d1[i];
        const scalar c22 = ((1 + g2[i])*pi - f2[i])/rho2[i] + d2[i];
        c2[i] = (xi1*rho1[i]*c21 + xi2*rho2[i]*c22)/(xi*rho[i]);
    }
}


void Foam::blastMixture::rhoeC2
(
    const label n,
    const UList<scalar>& alpha1,
    const UList<scalar>& rho1,
    const UList<scalar>& rho2,
    const UList<scalar>& rho,
    const UList<scalar>& p,
    UList<scalar>& rhoe,
    UList<scalar>& c2
) const
{
    reserve(n);
    SubList<scalar> g1(g1_, n), f1(f1_, n), d1(d1_, n);
    const SubList<scalar> r1(rho1, n);
    eos_[0].Gamma(r1, g1);
    eos_[0].pRefAndDerivative(r1, f1, d1);

    if (!twoPhase())
    {
        for (label i = 0; i < n; ++i)
        {
            rhoe[i] = (p[i] - f1[i])/g1[i];
            c2[i] = ((1 + g1[i])*p[i] - f1[i])/rho1[i] + d1[i];
        }
        return;
    }

    SubList<scalar> g2(g2_, n), f2(f2_, n), d2(d2_, n);
    const SubList<scalar> r2(rho2, n);
    eos_[1].Gamma(r2, g2);
    eos_[1].pRefAndDerivative(r2, f2, d2);

    for (label i = 0; i < n; ++i)
    {
        const scalar a1 = alpha1[i];
        const scalar a2 = 1 - a1;
        const scalar xi1 = a1/g1[i];
        const scalar xi2 = a2/g2[i];
        const scalar pi = p[i];
        rhoe[i] = xi1*(pi - f1[i]) + xi2*(pi - f2[i]);
        const scalar c21 = ((1 + g1[i])*pi - f1[i])/rho1[i] + d1[i];
        const scalar c22 = ((1 + g2[i])*pi - f2[i])/rho2[i] + d2[i];
        c2[i] = (xi1*rho1[i]*c21 + xi2*rho2[i]*c22)/((xi1 + xi2)*rho[i]);
    }
}


Foam::scalar Foam::blastMixture::rhoe
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar p
) const
{
    const equationOfState& e1 = eos_[0];
    if (!twoPhase())
    {
        return (p - e1.pRef(rho1))/e1.Gamma(rho1);
    }
    const equationOfState& e2 = eos_[1];
    return
        alpha1*(p - e1.pRef(rho1))/e1.Gamma(rho1)
      + (1 - alpha1)*(p - e2.pRef(rho2))/e2.Gamma(rho2);
}


Foam::scalar Foam::blastMixture::p
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar rhoe
) const
{
    const equationOfState& e1 = eos_[0];
    if (!twoPhase())
    {
        return e1.Gamma(rho1)*rhoe + e1.pRef(rho1);
    }
    const equationOfState& e2 = eos_[1];
    const scalar xi1 = alpha1/e1.Gamma(rho1);
    const scalar xi2 = (1 - alpha1)/e2.Gamma(rho2);
    return (rhoe + xi1*e1.pRef(rho1) + xi2*e2.pRef(rho2))/(xi1 + xi2);
}


// ************************************************************************* //

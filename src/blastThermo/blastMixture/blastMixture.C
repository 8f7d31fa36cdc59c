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
#include "JWL.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastMixture::blastMixture(const dictionary& dict)
:
    materials_(dict.get<wordList>("materials")),
    eos_(materials_.size()),
    alphaMin_(dict.getOrDefault<scalar>("alphaMin", 1e-6)),
    unreacted_(nullptr),
    pCav_(equationOfState::noCavitation)
{
    if (materials_.size() < 1 || materials_.size() > 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'materials' must list one, two or three materials"
            << " (e.g. (products water air)), got " << materials_
            << exit(FatalIOError);
    }
    if (alphaMin_ < 0 || alphaMin_ > 0.1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'alphaMin' must be in [0, 0.1], got " << alphaMin_
            << exit(FatalIOError);
    }
    // A material defined twice would be merged, the later entries winning
    caseChecks::checkInput(dict);
    forAll(materials_, i)
    {
        if (materials_.find(materials_[i]) != i)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'materials' lists " << materials_[i] << " twice:"
                << " different materials (products first) or one"
                << exit(FatalIOError);
        }
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
        pCav_ = max(pCav_, eos_[i].cavitationPressure());
    }
    const auto* jwl = dynamic_cast<const equationsOfState::JWL*>(&eos_[0]);
    if (jwl && jwl->hasUnreacted())
    {
        unreacted_ = &jwl->unreacted();
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::blastMixture::reserve(const label n) const
{
    if (g1_.size() < n)
    {
        g1_.setSize(n); f1_.setSize(n); d1_.setSize(n);
        if (multiPhase())
        {
            g2_.setSize(n); f2_.setSize(n); d2_.setSize(n);
        }
        if (threePhase())
        {
            g3_.setSize(n); f3_.setSize(n); d3_.setSize(n);
        }
        if (unreacted_)
        {
            gu_.setSize(n); fu_.setSize(n); du_.setSize(n);
        }
    }
}


void Foam::blastMixture::material1
(
    const label n,
    const UList<scalar>& rho1,
    const UList<scalar>* burn
) const
{
    reserve(n);
    SubList<scalar> g1(g1_, n), f1(f1_, n), d1(d1_, n);
    const SubList<scalar> r1(rho1, n);
    eos_[0].Gamma(r1, g1);
    eos_[0].pRefAndDerivative(r1, f1, d1);
    if (!burn)
    {
        return;
    }
    if (!unreacted_)
    {
        FatalErrorInFunction
            << "Material " << materials_[0] << " has no unreacted state but"
            << " a burn fraction was given" << exit(FatalError);
    }
    // Burnt everywhere (after the burn, or outside the charges): the
    // products' equation of state as it is
    const UList<scalar>& F = *burn;
    label first = 0;
    while (first < n && F[first] >= 1)
    {
        ++first;
    }
    if (first == n)
    {
        return;
    }
    SubList<scalar> gu(gu_, n), fu(fu_, n), du(du_, n);
    unreacted_->Gamma(r1, gu);
    unreacted_->pRefAndDerivative(r1, fu, du);
    for (label i = first; i < n; ++i)
    {
        const scalar Fi = F[i];
        if (Fi < 1)
        {
            const scalar Fu = 1 - Fi;
            g1_[i] = Fi*g1_[i] + Fu*gu_[i];
            f1_[i] = Fi*f1_[i] + Fu*fu_[i];
            d1_[i] = Fi*d1_[i] + Fu*du_[i];
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
    UList<scalar>& c2,
    const UList<scalar>* burn,
    UList<scalar>* pEOS
) const
{
    material1(n, rho1, burn);
    const SubList<scalar> g1(g1_, n), f1(f1_, n), d1(d1_, n);

    if (!twoPhase())
    {
        for (label i = 0; i < n; ++i)
        {
            const auto c2At = [&](const scalar pp)
            {
                return ((1 + g1[i])*pp - f1[i])/rho1[i] + d1[i];
            };
            scalar pi = g1[i]*rhoe[i] + f1[i];
            scalar c2i = c2At(pi);
            if (pEOS) (*pEOS)[i] = pi;
            cutOff(pi, c2i, c2At);
            p[i] = pi;
            c2[i] = c2i;
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
        const auto c2At = [&](const scalar pp)
        {
            const scalar c21 = ((1 + g1[i])*pp - f1[i])/rho1[i] + d1[i];
            const scalar c22 = ((1 + g2[i])*pp - f2[i])/rho2[i] + d2[i];
            return (xi1*rho1[i]*c21 + xi2*rho2[i]*c22)/(xi*rho[i]);
        };
        scalar pi = (rhoe[i] + xi1*f1[i] + xi2*f2[i])/xi;
        scalar c2i = c2At(pi);
        if (pEOS) (*pEOS)[i] = pi;
        cutOff(pi, c2i, c2At);
        p[i] = pi;
        c2[i] = c2i;
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
    UList<scalar>& c2,
    const UList<scalar>* burn
) const
{
    material1(n, rho1, burn);
    const SubList<scalar> g1(g1_, n), f1(f1_, n), d1(d1_, n);

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


void Foam::blastMixture::pc2
(
    const label n,
    const UList<scalar>& alpha1,
    const UList<scalar>& alpha2,
    const UList<scalar>& rho1,
    const UList<scalar>& rho2,
    const UList<scalar>& rho3,
    const UList<scalar>& rho,
    const UList<scalar>& rhoe,
    UList<scalar>& p,
    UList<scalar>& c2,
    const UList<scalar>* burn,
    UList<scalar>* pEOS
) const
{
    materials23(n, rho2, rho3, burn, rho1);
    for (label i = 0; i < n; ++i)
    {
        scalar xi1, xi2, xi3;
        volumeWeights(i, alpha1[i], alpha2[i], xi1, xi2, xi3);
        const scalar xi = xi1 + xi2 + xi3;
        const auto c2At = [&](const scalar pp)
        {
            return
                mixtureC2(i, pp, xi1, xi2, xi3, rho1, rho2, rho3)
               /(xi*rho[i]);
        };
        scalar pi = (rhoe[i] + xi1*f1_[i] + xi2*f2_[i] + xi3*f3_[i])/xi;
        scalar c2i = c2At(pi);
        if (pEOS) (*pEOS)[i] = pi;
        cutOff(pi, c2i, c2At);
        p[i] = pi;
        c2[i] = c2i;
    }
}


void Foam::blastMixture::rhoeC2
(
    const label n,
    const UList<scalar>& alpha1,
    const UList<scalar>& alpha2,
    const UList<scalar>& rho1,
    const UList<scalar>& rho2,
    const UList<scalar>& rho3,
    const UList<scalar>& rho,
    const UList<scalar>& p,
    UList<scalar>& rhoe,
    UList<scalar>& c2,
    const UList<scalar>* burn
) const
{
    materials23(n, rho2, rho3, burn, rho1);
    for (label i = 0; i < n; ++i)
    {
        scalar xi1, xi2, xi3;
        volumeWeights(i, alpha1[i], alpha2[i], xi1, xi2, xi3);
        const scalar pi = p[i];
        rhoe[i] = xi1*(pi - f1_[i]) + xi2*(pi - f2_[i]) + xi3*(pi - f3_[i]);
        c2[i] =
            mixtureC2(i, pi, xi1, xi2, xi3, rho1, rho2, rho3)
           /((xi1 + xi2 + xi3)*rho[i]);
    }
}


void Foam::blastMixture::materials23
(
    const label n,
    const UList<scalar>& rho2,
    const UList<scalar>& rho3,
    const UList<scalar>* burn,
    const UList<scalar>& rho1
) const
{
    if (!threePhase())
    {
        FatalErrorInFunction
            << "Three-material call with materials " << materials_
            << exit(FatalError);
    }
    material1(n, rho1, burn);
    SubList<scalar> g2(g2_, n), f2(f2_, n), d2(d2_, n);
    SubList<scalar> g3(g3_, n), f3(f3_, n), d3(d3_, n);
    const SubList<scalar> r2(rho2, n), r3(rho3, n);
    eos_[1].Gamma(r2, g2);
    eos_[1].pRefAndDerivative(r2, f2, d2);
    eos_[2].Gamma(r3, g3);
    eos_[2].pRefAndDerivative(r3, f3, d3);
}


Foam::scalar Foam::blastMixture::rhoeOf
(
    const UList<scalar>& alpha,
    const UList<scalar>& rhoK,
    const scalar p,
    const scalar F
) const
{
    scalar g1, f1;
    material1(rhoK[0], F, g1, f1);
    scalar r = alpha[0]*(p - f1)/g1;
    for (label k = 1; k < size(); ++k)
    {
        r += alpha[k]*(p - eos_[k].pRef(rhoK[k]))/eos_[k].Gamma(rhoK[k]);
    }
    return r;
}


Foam::scalar Foam::blastMixture::pOf
(
    const UList<scalar>& alpha,
    const UList<scalar>& rhoK,
    const scalar rhoe,
    const scalar F
) const
{
    scalar g1, f1;
    material1(rhoK[0], F, g1, f1);
    scalar xi = alpha[0]/g1;
    scalar num = rhoe + xi*f1;
    for (label k = 1; k < size(); ++k)
    {
        const scalar xik = alpha[k]/eos_[k].Gamma(rhoK[k]);
        xi += xik;
        num += xik*eos_[k].pRef(rhoK[k]);
    }
    return num/xi;
}


Foam::scalar Foam::blastMixture::rhoe
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar p,
    const scalar F
) const
{
    scalar g1, f1;
    material1(rho1, F, g1, f1);
    if (!twoPhase())
    {
        return (p - f1)/g1;
    }
    const equationOfState& e2 = eos_[1];
    return
        alpha1*(p - f1)/g1
      + (1 - alpha1)*(p - e2.pRef(rho2))/e2.Gamma(rho2);
}


Foam::scalar Foam::blastMixture::p
(
    const scalar alpha1,
    const scalar rho1,
    const scalar rho2,
    const scalar rhoe,
    const scalar F
) const
{
    scalar g1, f1;
    material1(rho1, F, g1, f1);
    if (!twoPhase())
    {
        return g1*rhoe + f1;
    }
    const equationOfState& e2 = eos_[1];
    const scalar xi1 = alpha1/g1;
    const scalar xi2 = (1 - alpha1)/e2.Gamma(rho2);
    return (rhoe + xi1*f1 + xi2*e2.pRef(rho2))/(xi1 + xi2);
}


const Foam::equationOfState& Foam::blastMixture::unreacted() const
{
    if (!unreacted_)
    {
        FatalErrorInFunction
            << "Material " << materials_[0] << " has no unreacted explosive"
            << " (it must be a JWL with an explosive preset or an"
            << " 'unreacted' dictionary)" << exit(FatalError);
    }
    return *unreacted_;
}


void Foam::blastMixture::material1
(
    const scalar rho1,
    const scalar F,
    scalar& g1,
    scalar& f1
) const
{
    const equationOfState& e1 = eos_[0];
    g1 = e1.Gamma(rho1);
    f1 = e1.pRef(rho1);
    if (F < 1)
    {
        const equationOfState& u = unreacted();
        g1 = F*g1 + (1 - F)*u.Gamma(rho1);
        f1 = F*f1 + (1 - F)*u.pRef(rho1);
    }
}


// ************************************************************************* //

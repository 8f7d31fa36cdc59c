/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "elasticLaw.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::elasticLaw::lawType> Foam::elasticLaw::names
({
    { lawType::StVenantKirchhoff, "StVenantKirchhoff" },
    { lawType::neoHookean, "neoHookean" },
});


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::elasticLaw::lawType Foam::elasticLaw::read
(
    const dictionary& dict,
    const lawType deflt
)
{
    // Literal, local look-up: a material must not pick up the top-level
    // entry through the parent (that is passed as deflt)
    const entry* ePtr = dict.findEntry("elasticLaw", keyType::LITERAL);
    if (!ePtr)
    {
        return deflt;
    }
    const word name = dict.get<word>("elasticLaw", keyType::LITERAL);
    if (!names.found(name))
    {
        string valid;
        for (const word& w : names.names())
        {
            valid += (valid.empty() ? "" : " ") + w;
        }
        FatalIOErrorInFunction(dict)
            << "entry 'elasticLaw': unknown elastic law '" << name
            << "'; valid elasticLaw names: (" << valid.c_str() << ")"
            << exit(FatalIOError);
    }
    return names.get(name);
}


Foam::elasticConstants Foam::elasticLaw::constants
(
    const scalar lambda,
    const scalar mu,
    const symmTensor2D& S0
)
{
    elasticConstants c;
    c.lambda = lambda;
    c.mu = mu;
    c.s0xx = S0.xx();
    c.s0xy = S0.xy();
    c.s0yy = S0.yy();
    const scalar s0 =
        0.5*(S0.xx() + S0.yy())
      + Foam::sqrt(0.25*sqr(S0.xx() - S0.yy()) + sqr(S0.xy()));
    c.s0max = max(s0, scalar(0));

    // Neo-Hookean volumetric h(J) = -mu ln J + lambda/2 (ln J)^2 and its
    // first two derivatives at Jmin, for the quadratic continuation
    const scalar Jm = Jmin();
    const scalar lnJ = Foam::log(Jm);
    c.hMin = (0.5*lambda*lnJ - mu)*lnJ;
    c.gMin = (lambda*lnJ - mu)/Jm;
    c.dgMin = (lambda*(1 - lnJ) + mu)/(Jm*Jm);
    return c;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemMaterial.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    scalar readPositive(const dictionary& dict, const word& key)
    {
        const scalar value = dict.get<scalar>(key);
        if (!(value > 0))
        {
            FatalIOErrorInFunction(dict)
                << "entry '" << key << "' must be positive, got " << value
                << exit(FatalIOError);
        }
        return value;
    }

    scalar readPositiveOrDefault
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
                << "entry '" << key << "' must be positive, got " << value
                << exit(FatalIOError);
        }
        return value;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::femdemMaterial::femdemMaterial
(
    const word& name,
    const dictionary& dict,
    const elasticLaw::lawType defaultLaw
)
:
    name(name),
    law(elasticLaw::read(dict, defaultLaw)),
    strength(dict)
{
    E = readPositive(dict, "E");
    nu = dict.get<scalar>("nu");
    if (!(nu > -1 && nu < 0.5))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'nu' must lie in (-1, 0.5), got " << nu
            << exit(FatalIOError);
    }
    rho = readPositive(dict, "rho");
    ft = readPositive(dict, "tensileStrength");
    c = readPositive(dict, "cohesion");
    phi = dict.get<scalar>("frictionAngle");
    if (!(phi >= 0 && phi < 90))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'frictionAngle' must lie in [0, 90) degrees, got " << phi
            << exit(FatalIOError);
    }
    GI = readPositive(dict, "GI");
    GII = readPositive(dict, "GII");
    pn = readPositiveOrDefault(dict, "jointPenalty", 200*E);
    ps = readPositiveOrDefault(dict, "jointShearPenalty", pn);
    pc = readPositiveOrDefault(dict, "contactPenalty", 10*E);
    friction = dict.getOrDefault<scalar>
    (
        "friction",
        Foam::tan(phi*constant::mathematical::pi/180)
    );
    if (friction < 0)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'friction' must be >= 0, got " << friction
            << exit(FatalIOError);
    }
    dampingRatio = dict.getOrDefault<scalar>("dampingRatio", 0);
    if (dampingRatio < 0)
    {
        FatalIOErrorInFunction(dict)
            << "entry 'dampingRatio' must be >= 0, got " << dampingRatio
            << exit(FatalIOError);
    }
    initialStress =
        dict.getOrDefault<symmTensor2D>("initialStress", symmTensor2D::zero);
    update();
}


Foam::femdemMaterial::femdemMaterial
(
    const word& name,
    scalar E, scalar nu, scalar rho,
    scalar ft, scalar c, scalar phiDeg,
    scalar GI, scalar GII,
    elasticLaw::lawType law
)
:
    name(name), E(E), nu(nu), rho(rho),
    ft(ft), c(c), phi(phiDeg), GI(GI), GII(GII),
    pn(200*E), ps(200*E), pc(10*E),
    friction(Foam::tan(phiDeg*constant::mathematical::pi/180)),
    dampingRatio(0),
    initialStress(symmTensor2D::zero),
    law(law)
{
    update();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::femdemMaterial::update()
{
    lambda = E*nu/((1 + nu)*(1 - 2*nu));
    mu = E/(2*(1 + nu));
    Mp = lambda + 2*mu;
    elastic = elasticLaw::constants(lambda, mu, initialStress);
}


Foam::femdemJointProperties Foam::femdemMaterial::joint
(
    const femdemMaterial& a,
    const femdemMaterial& b
)
{
    const scalar deg = constant::mathematical::pi/180;
    femdemJointProperties p;
    p.ft = min(a.ft, b.ft);
    p.c = min(a.c, b.c);
    p.tanPhi = Foam::tan(min(a.phi, b.phi)*deg);
    p.GI = min(a.GI, b.GI);
    p.GII = min(a.GII, b.GII);
    p.pn = max(a.pn, b.pn);
    p.ps = max(a.ps, b.ps);
    // In-situ stress of the joint: the average of its two sides
    p.sxx0 = 0.5*(a.initialStress.xx() + b.initialStress.xx());
    p.sxy0 = 0.5*(a.initialStress.xy() + b.initialStress.xy());
    p.syy0 = 0.5*(a.initialStress.yy() + b.initialStress.yy());
    return p;
}


// ************************************************************************* //

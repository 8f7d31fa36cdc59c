/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "strengthDistribution.H"
#include <cmath>
#include <cstring>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::Enum<Foam::strengthDistribution::distributionType>
Foam::strengthDistribution::names
({
    { distributionType::none, "none" },
    { distributionType::Weibull, "Weibull" },
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    uint64_t bits(const double d)
    {
        // +0 and -0 are the same coordinate
        const double v = (d == 0) ? 0.0 : d;
        uint64_t b;
        std::memcpy(&b, &v, sizeof b);
        return b;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::strengthDistribution::strengthDistribution()
:
    type_(none),
    modulus_(0),
    seed_(0),
    invMeanScale_(1)
{}


Foam::strengthDistribution::strengthDistribution
(
    const scalar modulus,
    const uint64_t seed
)
:
    type_(Weibull),
    modulus_(modulus),
    seed_(seed),
    invMeanScale_(1/std::tgamma(1 + 1/modulus))
{}


Foam::strengthDistribution::strengthDistribution(const dictionary& matDict)
:
    strengthDistribution()
{
    const dictionary* dPtr = matDict.findDict("strengthDistribution");
    if (!dPtr) return;
    const dictionary& d = *dPtr;

    const word typeName = d.get<word>("type");
    if (!names.found(typeName))
    {
        FatalIOErrorInFunction(d)
            << "entry 'type' of strengthDistribution: unknown type '"
            << typeName << "'; valid types: " << names.names()
            << exit(FatalIOError);
    }
    type_ = names.get(typeName);
    if (type_ == none) return;

    modulus_ = d.get<scalar>("modulus");
    if (!(modulus_ > 0 && std::isfinite(modulus_)))
    {
        FatalIOErrorInFunction(d)
            << "entry 'modulus' of strengthDistribution must be positive,"
            << " got " << modulus_ << exit(FatalIOError);
    }
    // Read as a scalar so that seeds beyond the label range are accepted
    const scalar s = d.getOrDefault<scalar>("seed", 0);
    if (!(s >= 0 && s < 9007199254740992.0 && s == std::floor(s)))
    {
        FatalIOErrorInFunction(d)
            << "entry 'seed' of strengthDistribution must be an integer in"
            << " [0, 2^53), got " << s << exit(FatalIOError);
    }
    seed_ = uint64_t(s);
    invMeanScale_ = 1/std::tgamma(1 + 1/modulus_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::strengthDistribution::uniform
(
    const uint64_t seed,
    const vector2D& a,
    const vector2D& b
)
{
    // End points in lexicographic order: the key does not depend on the
    // direction the edge is walked in
    const bool swap = (b.x() < a.x()) || (b.x() == a.x() && b.y() < a.y());
    const vector2D& p = swap ? b : a;
    const vector2D& q = swap ? a : b;
    uint64_t h = mix(seed);
    h = mix(h ^ bits(p.x()));
    h = mix(h ^ bits(p.y()));
    h = mix(h ^ bits(q.x()));
    h = mix(h ^ bits(q.y()));
    // 53 bits, centred: u in (0, 1), never 0 or 1
    return (double(h >> 11) + 0.5)*(1.0/9007199254740992.0);
}


Foam::scalar Foam::strengthDistribution::factor(const scalar u) const
{
    if (type_ == none) return 1;
    // -log1p(-u): accurate for the small u of the weak tail
    return std::pow(-std::log1p(-u), 1/modulus_)*invMeanScale_;
}


// ************************************************************************* //

// Unit tests of the two-material mixture (libblastThermo)
#include <gtest/gtest.h>
#include "blastMixture.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary dictOf(const char* text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    const char* twoText =
        "materials (products air);"
        "products { equationOfState JWL; explosive TNT; }"
        "air { equationOfState idealGas; gamma 1.4; }";
}


TEST(Mixture, PressureEquilibriumRoundTrip)
{
    blastMixture mix(dictOf(twoText));
    ASSERT_TRUE(mix.twoPhase());
    scalarField alpha({1e-6, 0.3, 0.5, 0.999999});
    scalarField r1({1630, 1000, 80, 1630});
    scalarField r2({1.2, 5, 7, 1630});
    scalarField p({1e5, 2e7, 2.5e7, 8e9});
    scalarField rho(alpha*r1 + (1 - alpha)*r2);
    scalarField rhoe(4), c2(4), p2(4), c22(4);
    mix.rhoeC2(4, alpha, r1, r2, rho, p, rhoe, c2);
    mix.pc2(4, alpha, r1, r2, rho, rhoe, p2, c22);
    forAll(p, i)
    {
        EXPECT_NEAR(p2[i], p[i], 1e-9*p[i]);
        EXPECT_NEAR(c22[i], c2[i], 1e-9*c2[i]);
        EXPECT_GT(c2[i], 0);
        EXPECT_NEAR(mix.p(alpha[i], r1[i], r2[i], rhoe[i]), p[i], 1e-9*p[i]);
    }
}


TEST(Mixture, PureLimitsAreTheMaterials)
{
    blastMixture mix(dictOf(twoText));
    // alpha = 1: products alone; alpha = 0: air alone
    scalarField a1(1, 1.0), a0(1, 0.0), r(1, 1630.0), ra(1, 1.2), p(1, 8e9), pa(1, 1e5);
    scalarField rhoe(1), c2(1);
    mix.rhoeC2(1, a1, r, r, r, p, rhoe, c2);
    EXPECT_NEAR(c2[0], mix.eos(0).c2(1630, 8e9), 1e-9*c2[0]);
    mix.rhoeC2(1, a0, ra, ra, ra, pa, rhoe, c2);
    EXPECT_NEAR(c2[0], 1.4*1e5/1.2, 1e-9*c2[0]);
    EXPECT_NEAR(rhoe[0], 1e5/0.4, 1e-6);
}


TEST(Mixture, BadDictionaries)
{
    EXPECT_THROW(blastMixture(dictOf("materials (a b c);")), Foam::error);
    EXPECT_THROW(blastMixture(dictOf("materials (products);")), Foam::error);
    EXPECT_THROW(blastMixture(dictOf("air { equationOfState idealGas; }")), Foam::error);
}

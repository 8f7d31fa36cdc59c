// Unit tests of the numerical fluxes (libblastFluid; limiters: limiterTest.C)
#include <gtest/gtest.h>
#include "fluxScheme.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    void setState
    (
        blastFaceStates& s, const bool left, const scalar rho,
        const vector& U, const scalar p, const scalar alpha = 1
    )
    {
        const scalar c = Foam::sqrt(1.4*p/rho);
        const scalar E = p/0.4 + 0.5*rho*magSqr(U);
        if (left)
        {
            s.rhoL[0] = rho; s.UL[0] = U; s.pL[0] = p; s.cL[0] = c;
            s.EL[0] = E; s.alphaL[0] = alpha; s.Y1L[0] = alpha;
        }
        else
        {
            s.rhoR[0] = rho; s.UR[0] = U; s.pR[0] = p; s.cR[0] = c;
            s.ER[0] = E; s.alphaR[0] = alpha; s.Y1R[0] = alpha;
        }
    }
}


class FluxSchemes : public ::testing::TestWithParam<const char*> {};

TEST_P(FluxSchemes, ConsistencyWithPhysicalFlux)
{
    IStringStream is(std::string("flux ") + GetParam() + ";");
    autoPtr<fluxScheme> flux = fluxScheme::New(dictionary(is));
    blastFaceStates s;
    blastFaceFluxes F;
    s.setSize(1, true);
    F.setSize(1, true);
    const vectorField Sf(1, vector(0.6, 0.8, 0)*2);
    const scalarField magSf(1, 2.0);
    const vector U(30, -10, 5);
    setState(s, true, 1.3, U, 2e5, 0.7);
    setState(s, false, 1.3, U, 2e5, 0.7);
    flux->fluxes(0, 1, Sf, magSf, s, true, F);
    const scalar un = U & vector(0.6, 0.8, 0);
    EXPECT_NEAR(F.rho[0], 2*1.3*un, 1e-10);
    const vector FU = 2*(1.3*un*U + 2e5*vector(0.6, 0.8, 0));
    EXPECT_NEAR(mag(F.rhoU[0] - FU), 0, 1e-8*mag(FU));
    EXPECT_NEAR(F.rhoE[0], 2*(s.EL[0] + 2e5)*un, 1e-8*mag(F.rhoE[0]));
    EXPECT_NEAR(F.alpha[0], 2*0.7*un, 1e-10);
}

TEST_P(FluxSchemes, ContactAtUniformPressureVelocity)
{
    // A density/alpha jump at uniform p, u: momentum flux = rho-flux u + p n
    IStringStream is(std::string("flux ") + GetParam() + ";");
    autoPtr<fluxScheme> flux = fluxScheme::New(dictionary(is));
    blastFaceStates s;
    blastFaceFluxes F;
    s.setSize(1, true);
    F.setSize(1, true);
    const vectorField Sf(1, vector(1, 0, 0));
    const scalarField magSf(1, 1.0);
    const vector U(100, 0, 0);
    setState(s, true, 1000, U, 1e5, 1);
    setState(s, false, 1.2, U, 1e5, 0);
    flux->fluxes(0, 1, Sf, magSf, s, true, F);
    EXPECT_NEAR(F.uS[0], 100, 1e-9);
    EXPECT_NEAR(F.rhoU[0].x(), F.rho[0]*100 + 1e5, 1e-7*F.rhoU[0].x());
}

INSTANTIATE_TEST_SUITE_P
(
    All, FluxSchemes, ::testing::Values("HLLC", "Kurganov", "KurganovTadmor")
);


TEST(FluxSchemes, HLLCUpwindForContact)
{
    // HLLC resolves a stationary contact exactly: zero mass flux
    IStringStream is("flux HLLC;");
    autoPtr<fluxScheme> flux = fluxScheme::New(dictionary(is));
    blastFaceStates s;
    blastFaceFluxes F;
    s.setSize(1, true);
    F.setSize(1, true);
    setState(s, true, 1000, Zero, 1e5, 1);
    setState(s, false, 1.2, Zero, 1e5, 0);
    flux->fluxes
    (
        0, 1, vectorField(1, vector(1, 0, 0)), scalarField(1, 1.0), s, true, F
    );
    EXPECT_NEAR(F.rho[0], 0, 1e-12);
    EXPECT_NEAR(F.rhoU[0].x(), 1e5, 1e-7);
}


TEST(FluxSchemes, UnknownNameRejected)
{
    IStringStream is("flux HLLCC;");
    EXPECT_THROW(fluxScheme::New(dictionary(is)), Foam::error);
}


// Unit tests of the equations of state (libblastThermo)
#include <gtest/gtest.h>
#include "equationOfState.H"
#include "JWL.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{
    dictionary dictOf(const char* text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    autoPtr<equationOfState> make(const char* text)
    {
        return equationOfState::New("m", dictOf(text));
    }

    // (dp/drho) along the isentrope de = p/rho^2 drho, central difference
    scalar c2FiniteDifference
    (
        const equationOfState& eos,
        const scalar rho,
        const scalar p
    )
    {
        const scalar e = eos.e(rho, p);
        const scalar h = 1e-5*rho;
        const scalar pp = eos.p(rho + h, e + p/(rho*rho)*h);
        const scalar pm = eos.p(rho - h, e - p/(rho*rho)*h);
        return (pp - pm)/(2*h);
    }

    const char* eosTexts[] =
    {
        "equationOfState idealGas; gamma 1.4;",
        "equationOfState stiffenedGas; gamma 4.4; pInf 6e8;",
        "equationOfState JWL; explosive TNT;",
        "equationOfState JWL; explosive HMX;"
    };
}


TEST(EOS, RoundTripPressureEnergy)
{
    scalar worst = 0;
    for (const char* text : eosTexts)
    {
        autoPtr<equationOfState> eos = make(text);
        for (scalar rho : {0.5, 1.2, 100.0, 1000.0, 1630.0, 2500.0})
        {
            for (scalar p : {1e4, 1e5, 1e7, 1e9, 2e10})
            {
                const scalar p2 = eos->p(rho, eos->e(rho, p));
                worst = max(worst, mag(p2 - p)/p);
            }
        }
    }
    RecordProperty("maxRelativeRoundTripError", std::to_string(worst));
    EXPECT_LT(worst, 1e-9);
}


TEST(EOS, FieldFunctionsMatchScalar)
{
    for (const char* text : eosTexts)
    {
        autoPtr<equationOfState> eos = make(text);
        scalarField rho({1.2, 50.0, 1630.0});
        scalarField p({1e5, 3e7, 8e9});
        scalarField e(3), p2(3), c2(3);
        eos->e(rho, p, e);
        eos->p(rho, e, p2);
        eos->c2(rho, p, c2);
        scalarField f(3), df(3);
        eos->pRefAndDerivative(rho, f, df);
        forAll(rho, i)
        {
            EXPECT_NEAR(f[i], eos->pRef(rho[i]), 1e-12*mag(f[i]) + 1e-300);
            EXPECT_NEAR(df[i], eos->dpRefdRho(rho[i]), 1e-12*mag(df[i]) + 1e-300);
            EXPECT_NEAR(p2[i], p[i], 1e-9*p[i]);
            EXPECT_NEAR(c2[i], eos->c2(rho[i], p[i]), 1e-12*c2[i]);
        }
    }
}


TEST(EOS, SoundSpeedVsFiniteDifference)
{
    scalar worst = 0;
    for (const char* text : eosTexts)
    {
        autoPtr<equationOfState> eos = make(text);
        for (scalar rho : {1.2, 100.0, 1630.0})
        {
            for (scalar p : {1e5, 1e8, 8e9})
            {
                const scalar c2 = eos->c2(rho, p);
                if (c2 <= 0) continue;
                const scalar fd = c2FiniteDifference(eos(), rho, p);
                worst = max(worst, mag(fd - c2)/c2);
            }
        }
    }
    RecordProperty("maxRelativeC2Error", std::to_string(worst));
    EXPECT_LT(worst, 1e-6);
}


TEST(EOS, IdealGasValues)
{
    autoPtr<equationOfState> eos = make("equationOfState idealGas; gamma 1.4;");
    EXPECT_DOUBLE_EQ(eos->p(1.0, 2.5), 1.0);
    EXPECT_NEAR(eos->c2(1.2, 101325), 1.4*101325/1.2, 1e-9);
    EXPECT_DOUBLE_EQ(eos->Gamma(1.0), 0.4);
}


TEST(EOS, JWLPresetsConstantVolumeExplosion)
{
    // p(rho0, E0/rho0) = A(1 - w/R1)e^-R1 + B(1 - w/R2)e^-R2 + w E0
    const char* names[] = {"TNT", "PETN", "CompB", "HMX"};
    for (const char* name : names)
    {
        const std::string text =
            std::string("equationOfState JWL; explosive ") + name + ";";
        autoPtr<equationOfState> eos = make(text.c_str());
        const auto& jwl = dynamic_cast<const equationsOfState::JWL&>(eos());
        RecordProperty
        (
            std::string("pCV_") + name + "_GPa",
            std::to_string(jwl.pCV()/1e9)
        );
        EXPECT_GT(jwl.pCV(), 5e9);
        EXPECT_LT(jwl.pCV(), 20e9);
    }
    autoPtr<equationOfState> tnt = make("equationOfState JWL; explosive TNT;");
    const auto& jwl = dynamic_cast<const equationsOfState::JWL&>(tnt());
    EXPECT_DOUBLE_EQ(jwl.rho0(), 1630);
    EXPECT_DOUBLE_EQ(jwl.E0(), 7e9);
    // model.md: 8.38 GPa; independent evaluation of the formula
    const scalar A = 371.2e9, B = 3.231e9, R1 = 4.15, R2 = 0.95, w = 0.3;
    const scalar expected =
        A*(1 - w/R1)*Foam::exp(-R1) + B*(1 - w/R2)*Foam::exp(-R2) + w*7e9;
    EXPECT_NEAR(jwl.pCV(), expected, 1e-6*expected);
    EXPECT_NEAR(jwl.pCV(), 8.38e9, 0.005e9);
}


TEST(EOS, JWLSecondExponentialIsExpMinusR2V)
{
    // At V = 2 the B term is B(1 - w/(2 R2)) exp(-2 R2), not exp(-R2/2)
    autoPtr<equationOfState> eos =
        make("equationOfState JWL; rho0 1000; A 0; B 1e9; R1 4; R2 1; omega 0.3; E0 1e9;");
    const scalar rho = 500;     // V = 2
    const scalar expected = 1e9*(1 - 0.3/2)*Foam::exp(scalar(-2));
    EXPECT_NEAR(eos->pRef(rho), expected, 1e-9*expected);
}


TEST(EOS, JWLOverridePreset)
{
    autoPtr<equationOfState> a = make("equationOfState JWL; explosive TNT;");
    autoPtr<equationOfState> b =
        make("equationOfState JWL; explosive TNT; E0 8e9; rho0 1600;");
    const auto& ja = dynamic_cast<const equationsOfState::JWL&>(a());
    const auto& jb = dynamic_cast<const equationsOfState::JWL&>(b());
    EXPECT_DOUBLE_EQ(jb.E0(), 8e9);
    EXPECT_DOUBLE_EQ(jb.rho0(), 1600);
    EXPECT_NE(ja.pCV(), jb.pCV());
}


TEST(EOS, BadInputRejected)
{
    EXPECT_THROW(make("equationOfState JWL; explosive TNT; omega -0.1;"), Foam::error);
    EXPECT_THROW(make("equationOfState JWL; explosive XYZ;"), Foam::error);
    EXPECT_THROW(make("equationOfState JWL; rho0 1630; A 1; B 1; R1 4;"), Foam::error);
    EXPECT_THROW(make("equationOfState idealGas; gamma 0.9;"), Foam::error);
    EXPECT_THROW(make("equationOfState idealGass;"), Foam::error);
    EXPECT_THROW(make("gamma 1.4;"), Foam::error);
}

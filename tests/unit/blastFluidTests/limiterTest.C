// Unit tests of the run-time selected limiters (libblastFluid): every name
// of the entry 'limiter' selects its class, whose psi(r) is the textbook
// formula (written here independently of the classes), lies in Sweby's TVD
// region and is symmetric; an unknown name is refused naming the entry and
// the valid names
#include <gtest/gtest.h>
#include "blastLimiters.H"
#include "IStringStream.H"
#include <algorithm>

using namespace Foam;

namespace
{
    autoPtr<blastLimiter> select(const std::string& name)
    {
        IStringStream is("limiter " + name + ";");
        return blastLimiter::New(dictionary(is));
    }

    // Sweby (1984), van Leer (1974), van Albada et al. (1982), van Leer
    // (1977, monotonised central), Roe (1985, superbee); 0 for r <= 0
    double textbook(const std::string& name, const double r)
    {
        if (name == "none" || r <= 0) return 0;
        if (name == "minmod") return std::min(r, 1.0);
        if (name == "vanLeer") return 2*r/(1 + r);
        if (name == "vanAlbada") return (r*r + r)/(r*r + 1);
        if (name == "MC") return std::min({2*r, (1 + r)/2, 2.0});
        if (name == "superbee")
        {
            return std::max(std::min(2*r, 1.0), std::min(r, 2.0));
        }
        ADD_FAILURE() << "no textbook formula for " << name;
        return -1;
    }

    const double ratios[] =
        {-1e8, -3, -1, -0.5, 0, 1e-12, 0.1, 0.3, 0.5, 0.9, 1, 1.5, 2, 2.5,
         3, 7.3, 12, 1e3, 1e8};
}


class LimiterNames : public ::testing::TestWithParam<const char*> {};

TEST_P(LimiterNames, SelectedByNameAndTextbookFormula)
{
    const std::string name(GetParam());
    autoPtr<blastLimiter> lim = select(name);
    EXPECT_EQ(std::string(lim->type()), name);
    EXPECT_EQ(lim->secondOrder(), name != "none");
    double maxDiff = 0;
    for (const double r : ratios)
    {
        const double ref = textbook(name, r);
        const double diff = mag(lim->psi(r) - ref)/max(1.0, mag(ref));
        maxDiff = max(maxDiff, diff);
        EXPECT_LE(diff, 4e-16) << name << " psi(" << r << ") = "
            << lim->psi(r) << ", textbook " << ref;
    }
    ::testing::Test::RecordProperty("maxRelativeDifference", maxDiff);
}

TEST_P(LimiterNames, TVDRegionAndSymmetry)
{
    const std::string name(GetParam());
    autoPtr<blastLimiter> lim = select(name);
    for (const double r : ratios)
    {
        const double psi = lim->psi(r);
        EXPECT_GE(psi, 0);
        EXPECT_LE(psi, 2*max(r, 0.0) + 1e-14);
        EXPECT_LE(psi, 2 + 1e-14);
        if (r > 0)
        {
            // psi(r)/r = psi(1/r): backward and forward slopes alike
            EXPECT_NEAR(psi/r, lim->psi(1/r), 1e-14*max(1.0, psi/r));
        }
    }
    if (name != "none")
    {
        EXPECT_NEAR(lim->psi(1), 1, 1e-15);
    }
}

INSTANTIATE_TEST_SUITE_P
(
    All, LimiterNames,
    ::testing::Values
    (
        "none", "minmod", "vanLeer", "vanAlbada", "MC", "superbee"
    )
);


TEST(Limiters, DefaultIsVanLeer)
{
    EXPECT_EQ
    (
        std::string(blastLimiter::New(dictionary())->type()), "vanLeer"
    );
}


TEST(Limiters, UnknownNameNamesEntryAndValidNames)
{
    try
    {
        select("vanLeerr");
        ADD_FAILURE() << "limiter vanLeerr accepted";
    }
    catch (const Foam::IOerror& err)
    {
        const std::string msg(err.message());
        EXPECT_NE(msg.find("limiter"), std::string::npos) << msg;
        EXPECT_NE(msg.find("vanLeerr"), std::string::npos) << msg;
        for (const char* valid : {"none", "minmod", "vanAlbada", "MC", "superbee"})
        {
            EXPECT_NE(msg.find(valid), std::string::npos) << msg;
        }
    }
}


TEST(Limiters, MonotoneFaceValuesWithinNeighbours)
{
    // Monotone data (gradients of any size) stay within the neighbours
    for (const double g : {0.0, 0.5, 1.0, 5.0, -3.0})
    {
        scalar L, R;
        blastLimiters::limitedPair<blastLimiters::MC>(1, 2, g, g, 0.5, L, R);
        EXPECT_GE(L, 1); EXPECT_LE(L, 2); EXPECT_GE(R, 1); EXPECT_LE(R, 2);
        blastLimiters::limitedPair<blastLimiters::superbee>
        (
            1, 2, g, g, 0.5, L, R
        );
        EXPECT_GE(L, 1); EXPECT_LE(L, 2); EXPECT_GE(R, 1); EXPECT_LE(R, 2);
        blastLimiters::limitedPair<blastLimiters::none>(1, 2, g, g, 0.5, L, R);
        EXPECT_EQ(L, 1); EXPECT_EQ(R, 2);
    }
}


// ************************************************************************* //

// One joint driven kinematically: opening (mode I) and sliding at several
// normal stresses (mode II, Mohr-Coulomb with the tension cut-off). Peak
// traction and the work done on the joint up to breakage are measured from
// the nodal forces the cohesive law assembles.
#include <gtest/gtest.h>
#include "femdemTestTools.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    struct jointRun
    {
        scalar peakSigma = 0, peakTau = 0, work = 0, breakAt = -1;
        scalar sigmaDuringSlide = 0;
    };

    // Two triangles (unit square split on its diagonal), one joint;
    // triangle B is translated by o n + s t with (o, s) = path(lambda)
    template<class Path>
    jointRun drive(const word& law, const Path& path, const label nInc)
    {
        const triangleMesh mesh =
            triangleMesh::rectangle(vector2D(0, 0), vector2D(0.01, 0.01), 1, 1, "rock");
        femdemSolid solid
        (
            mesh,
            dict
            (
                "cohesiveLaw " + law + "; contactLaw none; materials { "
              + material("rock") + " }"
            )
        );
        EXPECT_EQ(solid.nJoints(), 1);
        const jointNodeList& jn = solid.topology().jointNodes()[0];
        const label tB = solid.topology().jointTriangleB()[0];
        const List<vector2D> X(solid.x());
        const vector2D e = X[jn[1]] - X[jn[0]];
        const scalar L = mag(e);
        const vector2D t = e/L, n(t.y(), -t.x());

        jointRun r;
        List<vector2D> f(solid.nNodes());
        scalar oPrev = 0, sPrev = 0, sigPrev = 0, tauPrev = 0;
        for (label i = 0; i <= nInc; ++i)
        {
            scalar o, s;
            path(scalar(i)/nInc, o, s);
            for (label k = 0; k < 3; ++k)
            {
                const label node = 3*tB + k;
                solid.xRef()[node] = X[node] + o*n + s*t;
            }
            f = Zero;
            const label nb = solid.cohesive().addForces(solid, f);
            vector2D FB(Zero);
            for (label k = 0; k < 3; ++k) FB += f[3*tB + k];
            // Traction the joint exerts to hold B back
            const scalar sig = -(FB & n)/L, tau = -(FB & t)/L;
            if (i > 0)
            {
                r.work += 0.5*(sig + sigPrev)*(o - oPrev)
                        + 0.5*(tau + tauPrev)*(s - sPrev);
            }
            r.peakSigma = max(r.peakSigma, sig);
            r.peakTau = max(r.peakTau, tau);
            r.sigmaDuringSlide = sig;
            oPrev = o; sPrev = s; sigPrev = sig; tauPrev = tau;
            if (nb > 0 || solid.jointBroken()[0])
            {
                r.breakAt = scalar(i)/nInc;
                // Broken: no traction any more, the last increment ends at 0
                r.work -= 0.5*(sig + 0)*(0);
                break;
            }
        }
        return r;
    }
}


TEST(femdemJoint, openingPeakAndModeIEnergy)
{
    const scalar ft = 2e6, GI = 50;
    for (const word law : {"munjiza", "bilinear"})
    {
        const scalar oMax = 1e-4;
        jointRun r = drive
        (
            law,
            [&](scalar l, scalar& o, scalar& s) { o = l*oMax; s = 0; },
            40000
        );
        ASSERT_GT(r.breakAt, 0) << law << ": joint did not break";
        RecordProperty(law + "_peakOverFt", std::to_string(r.peakSigma/ft));
        RecordProperty(law + "_workOverGI", std::to_string(r.work/GI));
        EXPECT_NEAR(r.peakSigma/ft, 1, 1e-3) << law;
        EXPECT_NEAR(r.work/GI, 1, 0.01) << law;
    }
}


TEST(femdemJoint, slidingMohrCoulombAndModeIIEnergy)
{
    const scalar c = 8e6, tanPhi = std::tan(30*constant::mathematical::pi/180);
    const scalar GII = 400, ft = 2e6, pn = 200*10e9, h = 0.01*std::sqrt(2.0);

    // Normal stress, compression positive; -1e6 is tension (below f_t)
    for (const scalar sn : {-1e6, 0.0, 2e6, 5e6, 10e6})
    {
        // Opening giving sigma_n: compression o = -sn h/p_n; tension on the
        // Munjiza pre-peak curve f_t (2x - x^2) = -sn
        scalar o0;
        if (sn >= 0)
        {
            o0 = -sn*h/pn;
        }
        else
        {
            const scalar op = 2*h*ft/pn;
            o0 = op*(1 - std::sqrt(1 + sn/ft));
        }
        const scalar sMax = 3e-4;
        jointRun r = drive
        (
            "munjiza",
            [&](scalar l, scalar& o, scalar& s) { o = o0; s = l*sMax; },
            60000
        );
        ASSERT_GT(r.breakAt, 0) << "sn " << sn << ": joint did not break";
        const scalar expected = c + sn*tanPhi;
        const std::string tag = "sigmaN_" + std::to_string(int(sn/1e6)) + "MPa";
        RecordProperty(tag + "_peakOverMC", std::to_string(r.peakTau/expected));
        RecordProperty(tag + "_workOverGII", std::to_string(r.work/GII));
        EXPECT_NEAR(r.peakTau/expected, 1, 2e-3) << "sn " << sn;
        EXPECT_NEAR(r.work/GII, 1, 0.01) << "sn " << sn;
    }

    // Tension cut-off: the normal traction never exceeds f_t, so the shear
    // strength never drops below c - f_t tan(phi); pulling beyond the peak
    // opening breaks the joint in tension (mode I) first.
    jointRun r = drive
    (
        "munjiza",
        [&](scalar l, scalar& o, scalar& s) { o = l*1e-4; s = 0.2*l*1e-4; },
        40000
    );
    RecordProperty("tensionCutOff_peakSigmaOverFt", std::to_string(r.peakSigma/ft));
    EXPECT_LE(r.peakSigma, ft*(1 + 1e-9));
    EXPECT_GT(r.breakAt, 0);
}


TEST(femdemJoint, compressionIsPenaltyNeverDamage)
{
    // Closing by 10x the peak opening: linear penalty, no damage
    jointRun r = drive
    (
        "munjiza",
        [&](scalar l, scalar& o, scalar& s) { o = -l*1e-4; s = 0; },
        1000
    );
    const scalar pn = 200*10e9, h = 0.01*std::sqrt(2.0);
    RecordProperty("compressiveStressOverPenalty", std::to_string(-r.sigmaDuringSlide/(pn*1e-4/h)));
    EXPECT_LT(r.breakAt, 0);
    EXPECT_NEAR(-r.sigmaDuringSlide, pn*1e-4/h, 1e-6*pn*1e-4/h);
}

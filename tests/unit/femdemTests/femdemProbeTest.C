// femdemProbes (the sampling of the solidProbes function object): exact
// for a linear velocity field, a 1D elastic wave in a laterally confined
// bar against the exact ramp solution, and a point outside the solid
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "femdemProbes.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    dictionary probeDict(const List<vector2D>& pts)
    {
        dictionary d;
        d.add("points", pts);
        return d;
    }
}


TEST(femdemProbe, linearVelocityFieldIsExact)
{
    // v = a + B X at every node (rigid translation + rotation + stretch):
    // the probe returns it exactly at any point, vertices and edges too
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.2, 0.1), 8, 4, "rock");
    femdemSolid solid(mesh, dict("materials { " + material("rock") + " }"));
    const List<vector2D> pts
    ({
        vector2D(0.0123, 0.0456), vector2D(0.1, 0.05), vector2D(0.2, 0.1),
        vector2D(0.05, 0.0), vector2D(0.1871, 0.0931)
    });
    const femdemProbes probes(solid, probeDict(pts));
    const List<vector2D>& X0 = solid.topology().initialPoints();
    const labelList& vertex = solid.topology().nodeVertex();
    struct field { vector2D a; tensor2D B; };
    const List<field> fields
    ({
        {vector2D(3, -2), tensor2D::zero},                  // translation
        {vector2D(0, 0), tensor2D(0, -50, 50, 0)},          // rotation
        {vector2D(1, 0.5), tensor2D(20, -7, 13, -40)}       // general
    });
    scalar maxErr = 0;
    for (const field& f : fields)
    {
        forAll(solid.vRef(), n)
        {
            solid.vRef()[n] = f.a + (f.B & X0[vertex[n]]);
        }
        const List<vector2D> v = probes.velocity(solid);
        forAll(pts, i)
        {
            const vector2D exact = f.a + (f.B & pts[i]);
            maxErr = max(maxErr, mag(v[i] - exact)/max(mag(exact), 1.0));
        }
    }
    RecordProperty("maxRelativeError", sci(maxErr));
    EXPECT_LT(maxErr, 1e-12);
}


TEST(femdemProbe, elasticWaveInConfinedBar)
{
    // Bar [0, 0.4] x [0, 0.01], rollers top and bottom (uniaxial strain),
    // left end driven at v0 with a linear ramp over tr: exact solution
    // v(x, t) = v0 clamp((t - x/c)/tr, 0, 1), c = sqrt((lambda + 2 mu)/rho).
    // Probes at x = 0.1, 0.2 (before the reflection from the free end)
    const scalar v0 = 0.5, tr = 2e-5;
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.4, 0.01), 80, 2, "rock");
    femdemSolid solid
    (
        mesh,
        dict
        (
            "contactLaw none; materials { rock { E 10e9; nu 0.25; rho 2500;"
            " tensileStrength 1e12; cohesion 1e12; frictionAngle 30; GI 1e9;"
            " GII 1e9; } } boundaryConditions {"
            " left { type velocity; value (0.5 0); components (x);"
            " rampTime 2e-5; }"
            " top { type velocity; value (0 0); components (y); }"
            " bottom { type velocity; value (0 0); components (y); } }"
        )
    );
    const scalar c = solid.materials()[0].waveSpeed();
    const List<vector2D> pts({vector2D(0.1, 0.005), vector2D(0.2, 0.0037)});
    const femdemProbes probes(solid, probeDict(pts));
    const scalar tEnd = 0.2/c + tr + 4e-5;
    scalar maxErr = 0, maxErrBefore = 0, plateauErr = 0;
    while (solid.time() < tEnd)
    {
        solid.step();
        const scalar t = solid.time();
        const List<vector2D> v = probes.velocity(solid);
        forAll(pts, i)
        {
            const scalar s = (t - pts[i].x()/c)/tr;
            const scalar exact = v0*min(max(s, 0.0), 1.0);
            const scalar err = mag(v[i].x() - exact)/v0;
            maxErr = max(maxErr, err);
            if (s < -0.5) maxErrBefore = max(maxErrBefore, err);
            if (s > 2) plateauErr = max(plateauErr, err);
        }
    }
    EXPECT_EQ(solid.nBrokenJoints(), 0);
    RecordProperty("waveSpeed", sci(c));
    RecordProperty("maxErrorOverV0", sci(maxErr));
    RecordProperty("maxErrorBeforeArrivalOverV0", sci(maxErrBefore));
    RecordProperty("maxErrorOnPlateauOverV0", sci(plateauErr));
    EXPECT_LT(maxErrBefore, 0.01);
    EXPECT_LT(plateauErr, 0.03);
    EXPECT_LT(maxErr, 0.1);
}


TEST(femdemProbe, pointOutsideTheSolidNamesEntry)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 2, 2, "rock");
    femdemSolid solid(mesh, dict("materials { " + material("rock") + " }"));
    try
    {
        femdemProbes probes
        (
            solid, probeDict(List<vector2D>({vector2D(0.5, 0.5), vector2D(1.5, 0.5)}))
        );
        ADD_FAILURE() << "a point outside the solid was accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        RecordProperty("message", msg);
        EXPECT_NE(msg.find("entry 'points': point 1"), std::string::npos) << msg;
    }
}

// Constant-strain triangles: patch tests (uniform strain, rigid rotation)
// and the P-wave speed of a laterally confined bar (plane strain)
#include <gtest/gtest.h>
#include "femdemTestTools.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    const std::string props =
        "cohesiveLaw munjiza; contactLaw none; materials { "
      + material("rock") + " }";

    // Maximum over triangles of |sigma - expected| / |expected| (or / E)
    scalar maxDeviation
    (
        const List<symmTensor2D>& s,
        const symmTensor2D& expected,
        const scalar scale
    )
    {
        scalar dev = 0;
        for (const symmTensor2D& st : s)
        {
            dev = max(dev, mag(st - expected)/scale);
        }
        return dev;
    }

    // Map every node with x -> A x + b
    void mapNodes(femdemSolid& solid, const tensor2D& A, const vector2D& b)
    {
        List<vector2D>& x = solid.xRef();
        for (vector2D& p : x) p = (A & p) + b;
    }

    // Cauchy stress of St Venant-Kirchhoff for F
    symmTensor2D svkStress(const femdemMaterial& m, const tensor2D& F)
    {
        const tensor2D E = 0.5*((F.T() & F) - tensor2D::I);
        const tensor2D S = m.lambda*tr(E)*tensor2D::I + 2*m.mu*E;
        const tensor2D s = (F & S & F.T())/det(F);
        return symmTensor2D(s.xx(), s.xy(), s.yy());
    }
}


TEST(femdemElement, patchTestUniformStrain)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 6, 4, "rock");
    femdemSolid solid(mesh, dict(props));
    const tensor2D F(1.001, 2e-4, -3e-4, 0.9995);
    mapNodes(solid, F, vector2D(0.3, -0.2));

    const symmTensor2D expected = svkStress(solid.materials()[0], F);
    const scalar dev = maxDeviation(solid.stress(), expected, mag(expected));
    RecordProperty("sigmaXX", std::to_string(expected.xx()));
    RecordProperty("maxRelativeDeviation", sci(dev));
    EXPECT_LT(dev, 1e-10);

    // Uniform stress: joints are closed, so the interior nodal forces of
    // the triangles are balanced across every joint (no joint force);
    // only boundary nodes carry a net force.
    solid.step(1e-30);
    const List<vector2D>& f = solid.force();
    const jointTopology& topo = solid.topology();
    scalar maxInterior = 0, fScale = 0;
    // Sum the forces of all nodes that started at the same vertex
    List<vector2D> vertexForce(mesh.nPoints(), Zero);
    forAll(f, n)
    {
        vertexForce[topo.nodeVertex()[n]] += f[n];
        fScale = max(fScale, mag(f[n]));
    }
    forAll(vertexForce, p)
    {
        const vector2D& X = mesh.points()[p];
        const bool interior =
            X.x() > 1e-9 && X.x() < 2 - 1e-9 && X.y() > 1e-9 && X.y() < 1 - 1e-9;
        if (interior) maxInterior = max(maxInterior, mag(vertexForce[p]));
    }
    RecordProperty("interiorForceImbalance", sci(maxInterior/fScale));
    EXPECT_LT(maxInterior/fScale, 1e-10);
}


TEST(femdemElement, patchTestRigidRotation)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 6, 4, "rock");
    femdemSolid solid(mesh, dict(props));
    const scalar E = solid.materials()[0].E;

    // 90 degrees, exactly
    mapNodes(solid, tensor2D(0, -1, 1, 0), vector2D(5, 7));
    const scalar dev90 = maxDeviation(solid.stress(), symmTensor2D::zero, E);
    RecordProperty("rotation90_maxStressOverE", sci(dev90));
    EXPECT_LT(dev90, 1e-10);

    // No joint or element force either
    solid.step(1e-30);
    scalar fMax = 0;
    for (const vector2D& fn : solid.force()) fMax = max(fMax, mag(fn));
    const scalar fScale = E*0.25;   // E times a triangle edge
    RecordProperty("rotation90_maxForceOverEh", sci(fMax/fScale));
    EXPECT_LT(fMax/fScale, 1e-10);

    // Strain then a 37 degree rotation: stress rotates with the body
    femdemSolid solid2(mesh, dict(props));
    const tensor2D U(1.002, 5e-4, 5e-4, 0.999);
    const scalar a = 37*constant::mathematical::pi/180;
    const tensor2D R(std::cos(a), -std::sin(a), std::sin(a), std::cos(a));
    mapNodes(solid2, R & U, vector2D::zero);
    const symmTensor2D s0 = svkStress(solid2.materials()[0], U);
    const tensor2D sr = R & tensor2D(s0.xx(), s0.xy(), s0.xy(), s0.yy()) & R.T();
    const symmTensor2D expected(sr.xx(), sr.xy(), sr.yy());
    const scalar devR = maxDeviation(solid2.stress(), expected, mag(expected));
    RecordProperty("strainedRotation37_relativeDeviation", sci(devR));
    EXPECT_LT(devR, 1e-10);
}


TEST(femdemElement, planeStrainWaveSpeed)
{
    // Bar 1 m x 1 cm, lateral displacement blocked (plane strain, 1D
    // strain): a velocity step on the left travels at sqrt(M/rho)
    const label nx = 200;
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 0.01), nx, 2, "rock");
    const scalar V0 = 0.1;
    femdemSolid solid
    (
        mesh,
        dict
        (
            props + " boundaryConditions {"
            " left { type velocity; value (0.1 0); }"
            " top { type velocity; value (0 0); components (y); }"
            " bottom { type velocity; value (0 0); components (y); } }"
        )
    );
    const femdemMaterial& m = solid.materials()[0];
    const scalar c = std::sqrt(m.E*(1 - m.nu)/((1 + m.nu)*(1 - 2*m.nu)*m.rho));

    // Probe: nodes at x = 0.75
    const scalar xProbe = 0.75;
    DynamicList<label> probe;
    forAll(solid.x(), n)
    {
        if (mag(solid.x()[n].x() - xProbe) < 1e-9) probe.append(n);
    }
    ASSERT_GT(probe.size(), 0);

    scalar tArrival = -1, vPrev = 0, tPrev = 0;
    const scalar tEnd = 1.3*xProbe/c;
    while (solid.time() < tEnd && tArrival < 0)
    {
        solid.step();
        scalar vMean = 0;
        for (const label n : probe) vMean += solid.v()[n].x();
        vMean /= probe.size();
        // v is a half-step velocity: time t - dt/2
        const scalar t = solid.time() - 0.5*solid.stableTimeStep();
        if (vMean >= 0.5*V0)
        {
            tArrival = tPrev + (0.5*V0 - vPrev)/(vMean - vPrev)*(t - tPrev);
        }
        vPrev = vMean;
        tPrev = t;
    }
    ASSERT_GT(tArrival, 0) << "no arrival";
    const scalar cMeasured = xProbe/tArrival;
    const scalar err = mag(cMeasured - c)/c;
    RecordProperty("waveSpeedTheory", std::to_string(c));
    RecordProperty("waveSpeedMeasured", std::to_string(cMeasured));
    RecordProperty("relativeError", std::to_string(err));
    RecordProperty("steps", std::to_string(solid.timeIndex()));
    EXPECT_LT(err, 0.02);
}

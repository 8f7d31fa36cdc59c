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

    //- The laws, as named in femdemProperties
    const wordList laws({"StVenantKirchhoff", "neoHookean"});

    std::string lawProps(const word& law)
    {
        return "elasticLaw " + law + "; " + props;
    }

    // Maximum over triangles of |sigma - expected| / scale
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

    // Largest net force on an interior vertex over the largest nodal force
    scalar interiorImbalance(const femdemSolid& solid, const triangleMesh& mesh)
    {
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
                X.x() > 1e-9 && X.x() < 2 - 1e-9
             && X.y() > 1e-9 && X.y() < 1 - 1e-9;
            if (interior) maxInterior = max(maxInterior, mag(vertexForce[p]));
        }
        return maxInterior/fScale;
    }
}


TEST(femdemElement, patchTestUniformStrain)
{
    // Both laws: a uniform F gives the law's closed-form stress in every
    // triangle and no net force on interior vertices
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 6, 4, "rock");
    const tensor2D F(1.001, 2e-4, -3e-4, 0.9995);
    for (const word& law : laws)
    {
        femdemSolid solid(mesh, dict(lawProps(law)));
        EXPECT_EQ(label(solid.materials()[0].law), elasticLaw::names[law]);
        mapNodes(solid, F, vector2D(0.3, -0.2));
        const symmTensor2D expected = lawStress(solid.materials()[0], F);
        const scalar dev =
            maxDeviation(solid.stress(), expected, mag(expected));
        RecordProperty(law + "_sigmaXX", std::to_string(expected.xx()));
        RecordProperty(law + "_maxRelativeDeviation", sci(dev));
        EXPECT_LT(dev, 1e-10) << law;

        // Uniform stress: joints are closed, so the interior nodal forces
        // of the triangles balance across every joint (no joint force)
        solid.step(1e-30);
        const scalar imbalance = interiorImbalance(solid, mesh);
        RecordProperty(law + "_interiorForceImbalance", sci(imbalance));
        EXPECT_LT(imbalance, 1e-10) << law;
    }

    // Mixed laws (left half St Venant-Kirchhoff, right half neo-Hookean):
    // each group of triangles follows its own law
    const triangleMesh mixed =
        splitMaterials(mesh, 1, wordList({"rock", "soft"}));
    const labelList& triMat = mixed.triangleMaterials();
    femdemSolid solid
    (
        mixed,
        dict
        (
            "contactLaw none; materials { "
          + material("rock", "elasticLaw StVenantKirchhoff;")
          + material("soft", "", "3e9", "0.3", "1500") + " }"
        )
    );
    mapNodes(solid, F, vector2D::zero);
    const List<symmTensor2D> sigma = solid.stress();
    scalar devMixed = 0;
    forAll(sigma, t)
    {
        const symmTensor2D ex = lawStress(solid.materials()[triMat[t]], F);
        devMixed = max(devMixed, mag(sigma[t] - ex)/mag(ex));
    }
    EXPECT_EQ(solid.materials()[0].law, elasticLaw::StVenantKirchhoff);
    EXPECT_EQ(solid.materials()[1].law, elasticLaw::neoHookean);
    RecordProperty("mixedLaws_maxRelativeDeviation", sci(devMixed));
    EXPECT_LT(devMixed, 1e-10);
}


TEST(femdemElement, patchTestRigidRotation)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 6, 4, "rock");
    for (const word& law : laws)
    {
        femdemSolid solid(mesh, dict(lawProps(law)));
        const scalar E = solid.materials()[0].E;

        // 90 degrees, exactly
        mapNodes(solid, tensor2D(0, -1, 1, 0), vector2D(5, 7));
        const scalar dev90 =
            maxDeviation(solid.stress(), symmTensor2D::zero, E);
        RecordProperty(law + "_rotation90_maxStressOverE", sci(dev90));
        EXPECT_LT(dev90, 1e-10) << law;

        // No joint or element force either
        solid.step(1e-30);
        scalar fMax = 0;
        for (const vector2D& fn : solid.force()) fMax = max(fMax, mag(fn));
        const scalar fScale = E*0.25;   // E times a triangle edge
        RecordProperty(law + "_rotation90_maxForceOverEh", sci(fMax/fScale));
        EXPECT_LT(fMax/fScale, 1e-10) << law;

        // Strain then a 37 degree rotation: stress rotates with the body
        femdemSolid solid2(mesh, dict(lawProps(law)));
        const tensor2D U(1.002, 5e-4, 5e-4, 0.999);
        const scalar a = 37*constant::mathematical::pi/180;
        const tensor2D R(std::cos(a), -std::sin(a), std::sin(a), std::cos(a));
        mapNodes(solid2, R & U, vector2D::zero);
        const symmTensor2D s0 = lawStress(solid2.materials()[0], U);
        const tensor2D sr =
            R & tensor2D(s0.xx(), s0.xy(), s0.xy(), s0.yy()) & R.T();
        const symmTensor2D expected(sr.xx(), sr.xy(), sr.yy());
        const scalar devR =
            maxDeviation(solid2.stress(), expected, mag(expected));
        RecordProperty
        (
            law + "_strainedRotation37_relativeDeviation", sci(devR)
        );
        EXPECT_LT(devR, 1e-10) << law;
    }
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

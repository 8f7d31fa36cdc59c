// femdemSolid as a whole: energy budget of a fracture test, restart
// bit-exactness, fragments, sub-cycling and input errors
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "OStringStream.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    // A notched-free bar pulled apart: left fixed, right pulled at 2 m/s
    const std::string pullProps =
        "trackEnergy true; cohesiveLaw munjiza; contactLaw potential; "
        "materials { " + material("rock", "dampingRatio 0.2;") + " } "
        "boundaryConditions { left { type fixed; } "
        "right { type velocity; value (2 0); rampTime 2e-5; } }";

    bool hasMessage(const Foam::error& err, const std::string& what)
    {
        return std::string(err.message()).find(what) != std::string::npos;
    }
}


TEST(femdemSolver, energyBudgetClosesInFracture)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.1, 0.02), 20, 4, "rock");
    femdemSolid solid(mesh, dict(pullProps));
    solid.resetEnergyBudget();
    while (solid.time() < 2e-4)
    {
        solid.step();
    }
    const femdemSolid::energyBudget e = solid.energies();
    const femdemSolid::fragmentData fr = solid.fragments();
    const scalar input = e.external + e.initial + e.gravity;
    const scalar closure = mag(e.residual())/input;
    RecordProperty("brokenJoints", std::to_string(solid.nBrokenJoints()));
    RecordProperty("fragments", std::to_string(fr.mass.size()));
    RecordProperty("externalWork", std::to_string(e.external));
    RecordProperty("kinetic", std::to_string(e.kinetic));
    RecordProperty("elastic", std::to_string(e.elastic));
    RecordProperty("jointStored", std::to_string(e.jointStored));
    RecordProperty("fracture", std::to_string(e.fracture));
    RecordProperty("damping", std::to_string(e.damping));
    RecordProperty("contact", std::to_string(e.contact));
    RecordProperty("residualOverInput", std::to_string(closure));
    EXPECT_GE(fr.mass.size(), 2) << "the bar did not break apart";
    EXPECT_GT(e.fracture, 0.05*input) << "fracture energy not significant";
    EXPECT_LT(closure, 0.01);
    // Broken joints dissipate between G_I and G_II per unit length
    scalar lengthBroken = 0;
    forAll(solid.jointBroken(), j)
    {
        if (solid.jointBroken()[j]) lengthBroken += solid.jointLength0()[j];
    }
    RecordProperty("fractureOverGIxLength", std::to_string(e.fracture/(50*lengthBroken)));
    EXPECT_GT(e.fracture, 0.99*50*lengthBroken);
}


TEST(femdemSolver, restartIsBitExact)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.1, 0.02), 20, 4, "rock");
    femdemSolid a(mesh, dict(pullProps));
    // Write in the middle of the fracture: some joints broken, some damaged
    while (a.nBrokenJoints() == 0 && a.time() < 1e-3) a.step();
    for (label i = 0; i < 20; ++i) a.step();

    OStringStream os;
    a.writeState(os);
    femdemSolid b(mesh, dict(pullProps));
    b.readState(dict(os.str()));

    for (label i = 0; i < 400; ++i) { a.step(); b.step(); }
    label differ = 0;
    forAll(a.x(), n)
    {
        if (a.x()[n] != b.x()[n] || a.v()[n] != b.v()[n]) ++differ;
    }
    RecordProperty("brokenJointsAtCompare", std::to_string(a.nBrokenJoints()));
    EXPECT_GT(a.nBrokenJoints(), 0);
    RecordProperty("nodesDiffering", std::to_string(differ));
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(a.nBrokenJoints(), b.nBrokenJoints());
    EXPECT_EQ(a.energies().fracture, b.energies().fracture);
}


TEST(femdemSolver, fragmentsMassCentroidVelocity)
{
    // 4 x 2 cells, joints on x = 0.5 broken: two halves
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 0.5), 4, 2, "rock");
    femdemSolid solid(mesh, dict("contactLaw none; materials { " + material("rock") + " }"));
    forAll(solid.topology().jointNodes(), j)
    {
        const jointNodeList& n = solid.topology().jointNodes()[j];
        if
        (
            mag(solid.x()[n[0]].x() - 0.5) < 1e-9
         && mag(solid.x()[n[1]].x() - 0.5) < 1e-9
        )
        {
            solid.setBroken(j);
        }
    }
    for (label t = 0; t < solid.nTriangles(); ++t)
    {
        const scalar xc =
            (solid.x()[3*t].x() + solid.x()[3*t + 1].x() + solid.x()[3*t + 2].x())/3;
        for (label k = 0; k < 3; ++k)
        {
            solid.vRef()[3*t + k] = xc < 0.5 ? vector2D(-1, 0) : vector2D(2, 1);
        }
    }
    const femdemSolid::fragmentData fr = solid.fragments();
    ASSERT_EQ(fr.mass.size(), 2);
    const label left = fr.centroid[0].x() < 0.5 ? 0 : 1, right = 1 - left;
    RecordProperty("fragmentMasses", std::to_string(fr.mass[0]) + " " + std::to_string(fr.mass[1]));
    EXPECT_NEAR(fr.mass[left], 2500*0.25, 1e-9);
    EXPECT_NEAR(fr.area[right], 0.25, 1e-12);
    EXPECT_NEAR(fr.centroid[left].x(), 0.25, 1e-12);
    EXPECT_NEAR(fr.centroid[right].y(), 0.25, 1e-12);
    EXPECT_NEAR(fr.velocity[left].x(), -1, 1e-12);
    EXPECT_NEAR(fr.velocity[right].y(), 1, 1e-12);
}


TEST(femdemSolver, subcyclingAndExternalForce)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.1, 0.1), 4, 4, "rock");
    femdemSolid solid(mesh, dict("contactLaw none; materials { " + material("rock") + " }"));
    // A uniform external force per unit mass: rigid acceleration a
    const vector2D a(3, -2);
    forAll(solid.externalForce(), n) solid.externalForce()[n] = a/solid.invMass()[n];
    const scalar interval = 7.3*solid.stableTimeStep();
    const label n = solid.advance(interval);
    const scalar T = solid.time();
    RecordProperty("substeps", std::to_string(n));
    EXPECT_EQ(n, 8);
    EXPECT_NEAR(T, interval, 1e-15*interval/solid.stableTimeStep());
    const vector2D vMean = solid.momentum()/(2500*0.01);
    EXPECT_LT(mag(vMean - a*T)/mag(a*T), 1e-12);
}


TEST(femdemSolver, badInputNamesEntry)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 2, 2, "rock");
    struct badCase { std::string text, expect; };
    const List<badCase> cases
    ({
        {"materials { rock { nu 0.2; rho 2000; tensileStrength 1e6; cohesion 1e6;"
         " frictionAngle 30; GI 10; GII 10; } }", "E"},
        {"materials { " + material("rock", "", "10e9", "0.25", "-1") + " }", "rho"},
        {"materials { " + material("rock", "", "0") + " }", "E"},
        {"materials { " + material("granite") + " }", "rock"},
        {"cohesiveLaw munjitza; materials { " + material("rock") + " }", "munjitza"},
        {"contactLaw penalty; materials { " + material("rock") + " }", "penalty"},
        {"materials { " + material("rock") + " } boundaryConditions"
         " { lfet { type fixed; } }", "lfet"},
        {"materials { " + material("rock") + " } boundaryConditions"
         " { left { type clamped; } }", "clamped"},
        {"elasticLaw neoHooke; materials { " + material("rock") + " }",
         "entry 'elasticLaw': unknown elastic law 'neoHooke'; valid"
         " elasticLaw names: (StVenantKirchhoff neoHookean)"},
        {"materials { " + material("rock", "elasticLaw linear;") + " }",
         "unknown elastic law 'linear'"}
    });
    label caught = 0;
    for (const badCase& c : cases)
    {
        try
        {
            femdemSolid solid(mesh, dict(c.text));
            ADD_FAILURE() << "accepted: " << c.text;
        }
        catch (const Foam::error& err)
        {
            ++caught;
            EXPECT_TRUE(hasMessage(err, c.expect))
                << "message does not name '" << c.expect << "': "
                << err.message();
        }
    }
    RecordProperty("rejected", std::to_string(caught) + "/" + std::to_string(cases.size()));
}


TEST(femdemSolver, inSituStressInEquilibriumWithPressure)
{
    // sigma0 = -5 MPa (isotropic) balanced by a 5 MPa pressure on every
    // side: the block must stay at rest, joints closed and intact
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.2, 0.1), 8, 4, "rock");
    femdemSolid solid
    (
        mesh,
        dict
        (
            "contactLaw potential; materials { "
          + material("rock", "initialStress (-5e6 0 -5e6);") + " }"
            " boundaryConditions { left { type pressure; value 5e6; }"
            " right { type pressure; value 5e6; } top { type pressure; value 5e6; }"
            " bottom { type pressure; value 5e6; } }"
        )
    );
    for (label i = 0; i < 500; ++i) solid.step();
    scalar vMax = 0;
    for (const vector2D& v : solid.v()) vMax = max(vMax, mag(v));
    // Velocity scale of a 5 MPa imbalance: sigma/(rho c)
    const femdemMaterial& m = solid.materials()[0];
    const scalar vScale = 5e6/(m.rho*m.waveSpeed());
    scalar sMax = 0;
    for (const symmTensor2D& s : solid.stress())
    {
        sMax = max(sMax, mag(s - symmTensor2D(-5e6, 0, -5e6)));
    }
    RecordProperty("maxVelocityOverSigmaOverRhoC", sci(vMax/vScale));
    RecordProperty("maxStressDeviationOverSigma0", sci(sMax/5e6));
    EXPECT_LT(vMax/vScale, 1e-8);
    EXPECT_LT(sMax/5e6, 1e-8);
    EXPECT_EQ(solid.nBrokenJoints(), 0);

    // Without the in-situ stress the same pressure compresses the block
    femdemSolid loaded
    (
        mesh,
        dict
        (
            "contactLaw potential; materials { " + material("rock") + " }"
            " boundaryConditions { left { type pressure; value 5e6; }"
            " right { type pressure; value 5e6; } }"
        )
    );
    for (label i = 0; i < 500; ++i) loaded.step();
    scalar vLoaded = 0;
    for (const vector2D& v : loaded.v()) vLoaded = max(vLoaded, mag(v));
    RecordProperty("withoutInSitu_maxVelocityOverScale", sci(vLoaded/vScale));
    EXPECT_GT(vLoaded/vScale, 0.1);
}


TEST(femdemSolver, twoMaterialsInterfaceRule)
{
    // Left half rock, right half steel: masses per material; joints across
    // the interface take the weaker strengths and the stiffer penalty
    const triangleMesh base =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.2, 0.1), 4, 2, "rock");
    const triangleMesh mesh =
        splitMaterials(base, 0.1, wordList({"rock", "steel"}));
    const labelList& triMat = mesh.triangleMaterials();
    femdemSolid solid
    (
        mesh,
        dict
        (
            "contactLaw none; materials { " + material("rock")
          + " steel { E 200e9; nu 0.3; rho 7800; tensileStrength 400e6;"
            " cohesion 300e6; frictionAngle 10; GI 1e4; GII 1e4; } }"
        )
    );
    label nInterface = 0;
    forAll(solid.jointClass(), j)
    {
        const label a = triMat[solid.topology().jointTriangleA()[j]];
        const label b = triMat[solid.topology().jointTriangleB()[j]];
        const femdemJointProperties& P = solid.jointClasses()[solid.jointClass()[j]];
        if (a != b)
        {
            ++nInterface;
            EXPECT_EQ(P.ft, 2e6);
            EXPECT_EQ(P.GI, 50);
            EXPECT_NEAR(P.tanPhi, std::tan(10*constant::mathematical::pi/180), 1e-15);
            EXPECT_EQ(P.pn, 200*200e9);
        }
    }
    scalar mass = 0;
    for (const scalar im : solid.invMass()) mass += 1/im;
    RecordProperty("interfaceJoints", std::to_string(nInterface));
    RecordProperty("massOverExpected", sci(mass/(0.01*2500 + 0.01*7800)));
    EXPECT_GT(nInterface, 0);
    EXPECT_NEAR(mass/(0.01*2500 + 0.01*7800), 1, 1e-12);
}


TEST(femdemSolver, velocityConditionHoldsEveryNodeOnItsPatch)
{
    // A block squeezed from the top on a symmetry-like bottom (v_y = 0):
    // the triangles that touch the bottom at one vertex only (every second
    // one of the structured mesh) must obey the condition too, exactly;
    // before, their nodes were held by the joints alone and drifted
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.04, 0.02), 8, 4, "rock");
    femdemSolid solid
    (
        mesh,
        dict
        (
            "cohesiveLaw munjiza; contactLaw potential; "
            "materials { " + material("rock") + " } "
            "boundaryConditions { bottom { type velocity; value (0 0);"
            " components (y); } top { type velocity; value (0 -1);"
            " components (y); rampTime 1e-5; } }"
        )
    );
    const jointTopology& topo = solid.topology();
    const List<vector2D>& points = topo.initialPoints();
    label nOnBottom = 0, nFan = 0;
    boolList onEdge(solid.x().size(), false);
    forAll(topo.boundaryPatch(), fi)
    {
        const label t = topo.boundaryTriangle()[fi], k = topo.boundaryEdge()[fi];
        onEdge[3*t + k] = onEdge[3*t + (k + 1) % 3] = true;
    }
    while (solid.time() < 2e-5)
    {
        solid.step();
    }
    scalar maxDrift = 0;
    forAll(solid.x(), n)
    {
        if (mag(points[topo.nodeVertex()[n]].y()) > 1e-12) continue;
        ++nOnBottom;
        if (!onEdge[n]) ++nFan;
        maxDrift = max(maxDrift, mag(solid.x()[n].y()));
    }
    RecordProperty("nodesOnBottom", std::to_string(nOnBottom));
    RecordProperty("fanNodes", std::to_string(nFan));
    RecordProperty("maxDrift", sci(maxDrift));
    EXPECT_GT(nFan, 0) << "the mesh has no triangle touching the patch at a vertex";
    EXPECT_EQ(maxDrift, 0);
}

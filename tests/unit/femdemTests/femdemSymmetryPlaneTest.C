// Symmetry planes (boundary condition symmetryPlane): a free block thrown at
// the plane of another body's patch bounces off it as off its mirror image
// (frictionless: normal velocity reversed, tangential kept, energy kept),
// with the plane along x and at 30 degrees to the axes; the nodes on the
// patch roll along it; rollers alone let the block cross; a bent patch is
// an error naming the entry
#include <gtest/gtest.h>
#include "femdemTestTools.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    const std::string strong =
        "tensileStrength 1e9; cohesion 1e9; GI 1e6; GII 1e6; friction 0.5;";

    struct bounce
    {
        scalar minDistance;     // least signed distance of a block node
        vector2D vBefore, vAfter;   // block mean velocity, plane frame
        scalar energyChange;    // kinetic + stored, relative
        scalar budgetResidual;  // femdem energy budget, largest, relative
        scalar maxRollerNormalSpeed;
    };

    // Body A: [0, 0.1] x [0, 0.1], its 'left' patch (x = 0) the condition
    // 'bc'; block B: [0.01, 0.05] x [0.2, 0.24] moving at (-20, 5) towards
    // the plane; everything (mesh, velocity, measuring frame) rotated by
    // thetaDeg about the origin: the plane's normal is R (1 0)
    bounce throwBlock(const std::string& bc, const scalar thetaDeg = 0)
    {
        const triangleMesh a = triangleMesh::rectangle
        (
            vector2D(0, 0), vector2D(0.1, 0.1), 4, 4, "rock"
        );
        const triangleMesh b = triangleMesh::rectangle
        (
            vector2D(0.01, 0.2), vector2D(0.04, 0.04), 2, 2, "rock"
        );
        const triangleMesh m0 = merge(a, b, "b_");
        const scalar th = thetaDeg*constant::mathematical::pi/180;
        const tensor2D R
        (
            std::cos(th), -std::sin(th), std::sin(th), std::cos(th)
        );
        List<vector2D> pts(m0.points());
        for (vector2D& p : pts) p = R & p;
        femdemSolid solid
        (
            triangleMesh
            (
                pts, m0.triangles(), m0.triangleMaterials(), m0.materials(),
                m0.patchNames(), m0.patchEdges()
            ),
            dict
            (
                "contactLaw potential; trackEnergy true; materials { "
              + material("rock", strong) + " } boundaryConditions { left "
              + bc + " }"
            )
        );
        const label nA = 3*a.nTriangles(), nN = solid.nNodes();
        const vector2D n = R & vector2D(1, 0), t = R & vector2D(0, 1);
        for (label i = nA; i < nN; ++i)
        {
            solid.vRef()[i] = -20*n + 5*t;
        }
        auto meanV = [&]()
        {
            const vector2D v = meanVelocity(solid, nA, nN);
            return vector2D(v & n, v & t);
        };
        bounce r;
        r.vBefore = meanV();
        solid.resetEnergyBudget();
        const scalar E0 = solid.kineticEnergy();
        r.minDistance = GREAT;
        r.maxRollerNormalSpeed = 0;
        r.budgetResidual = 0;
        const labelList& rollers = solid.patchNodes("left");
        while (solid.time() < 3e-3)
        {
            solid.step();
            for (label i = nA; i < nN; ++i)
            {
                r.minDistance = min(r.minDistance, solid.x()[i] & n);
            }
            for (const label i : rollers)
            {
                r.maxRollerNormalSpeed =
                    max(r.maxRollerNormalSpeed, mag(solid.v()[i] & n));
            }
            r.budgetResidual =
                max(r.budgetResidual, mag(solid.energies().residual())/E0);
        }
        r.vAfter = meanV();
        const scalar E1 = solid.kineticEnergy() + solid.elasticEnergy()
          + solid.cohesive().storedEnergy(solid);
        r.energyChange = (E1 - E0)/E0;
        return r;
    }
}


namespace
{
    // The reference: block B and its mirror image (x -> -x) thrown at each
    // other, no plane: B's mean velocity after the contact
    vector2D mirrorCollision(scalar& maxResidual)
    {
        const triangleMesh b = triangleMesh::rectangle
        (
            vector2D(0.01, 0.2), vector2D(0.04, 0.04), 2, 2, "rock"
        );
        const triangleMesh bm = triangleMesh::rectangle
        (
            vector2D(-0.05, 0.2), vector2D(0.04, 0.04), 2, 2, "rock"
        );
        femdemSolid solid
        (
            merge(b, bm, "m_"),
            dict
            (
                "contactLaw potential; trackEnergy true; materials { "
              + material("rock", strong + " friction 0;") + " }"
            )
        );
        const label nB = 3*b.nTriangles();
        for (label i = 0; i < solid.nNodes(); ++i)
        {
            solid.vRef()[i] = i < nB ? vector2D(-20, 5) : vector2D(20, 5);
        }
        solid.resetEnergyBudget();
        const scalar E0 = solid.kineticEnergy();
        maxResidual = 0;
        while (solid.time() < 3e-3)
        {
            solid.step();
            maxResidual =
                max(maxResidual, mag(solid.energies().residual())/E0);
        }
        return meanVelocity(solid, 0, nB);
    }
}


TEST(femdemSymmetryPlane, blockBouncesOffThePlane)
{
    const bounce r = throwBlock("{ type symmetryPlane; }");
    scalar mirrorResidual = 0;
    const vector2D vMirror = mirrorCollision(mirrorResidual);
    RecordProperty("vAfterMirrorCollision", sci(vMirror.x()) + " " + sci(vMirror.y()));
    RecordProperty("budgetResidualMirrorCollision", sci(mirrorResidual));
    RecordProperty("minDistance", sci(r.minDistance));
    RecordProperty("vBefore", sci(r.vBefore.x()) + " " + sci(r.vBefore.y()));
    RecordProperty("vAfter", sci(r.vAfter.x()) + " " + sci(r.vAfter.y()));
    RecordProperty("energyChange", sci(r.energyChange));
    RecordProperty("budgetResidual", sci(r.budgetResidual));
    RecordProperty("maxRollerNormalSpeed", sci(r.maxRollerNormalSpeed));
    // The block reaches the plane (0.01 m at 20 m/s: 0.5 ms) and comes back
    // as from the collision with its mirror image (the impact leaves part
    // of the energy in vibration: restitution of the mean velocity < 1)
    EXPECT_GT(r.vAfter.x(), 0.5*20) << "did not bounce";
    EXPECT_LT(mag(r.vAfter.x() - vMirror.x()), 0.05*20)
        << "plane and mirror image differ";
    // Frictionless, whatever the material's friction
    EXPECT_LT(mag(r.vAfter.y() - 5), 1e-9*20);
    // It never gets more than a small fraction of its size behind it
    EXPECT_GT(r.minDistance, -2e-4);
    EXPECT_LT(mag(r.energyChange), 0.02);
    // During the contact too: the wall's work is contact work (without it
    // the budget would miss the spring energy, up to the normal kinetic
    // energy, 94 % of E0); what is left is the staggering of the penalty
    // energy in the budget's work integral, as in the collision of the two
    // blocks through the contact law (1.1e-2 there)
    EXPECT_LT(r.budgetResidual, 1.5*mirrorResidual);
    EXPECT_EQ(r.maxRollerNormalSpeed, 0);
}


TEST(femdemSymmetryPlane, rollersAloneLetTheBlockCross)
{
    // The control: a velocity condition holds the patch's nodes only
    const bounce r =
        throwBlock("{ type velocity; value (0 0); components (x); }");
    RecordProperty("minDistance", sci(r.minDistance));
    EXPECT_LT(r.minDistance, -0.02) << "the block should fly through";
}


TEST(femdemSymmetryPlane, rotatedPlane)
{
    // The whole configuration at 30 degrees: the same bounce in the
    // plane's frame
    const bounce r = throwBlock("{ type symmetryPlane; }", 30);
    const scalar vn = r.vAfter.x(), vt = r.vAfter.y();
    RecordProperty("vAfter_n_t", sci(vn) + " " + sci(vt));
    RecordProperty("minDistance", sci(r.minDistance));
    RecordProperty("energyChange", sci(r.energyChange));
    RecordProperty("maxRollerNormalSpeed", sci(r.maxRollerNormalSpeed));
    // The same bounce as along the axis (the mesh and the velocities are
    // rotated exactly, round-off aside)
    const bounce r0 = throwBlock("{ type symmetryPlane; }");
    RecordProperty("vAfterAxisAligned", sci(r0.vAfter.x()));
    EXPECT_LT(mag(vn - r0.vAfter.x()), 1e-6*20);
    EXPECT_LT(mag(vt - 5), 1e-9*20);
    EXPECT_GT(r.minDistance, -2e-4);
    EXPECT_LT(mag(r.energyChange), 0.02);
    EXPECT_LT(r.maxRollerNormalSpeed, 1e-12*20);
}


TEST(femdemSymmetryPlane, bentPatchIsAnError)
{
    // 'left' and 'bottom' under one name: an L, not a plane
    const triangleMesh r = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(0.1, 0.1), 2, 2, "rock"
    );
    List<edgeList> edges(r.patchEdges());
    const label left = r.patchNames().find("left");
    const label bottom = r.patchNames().find("bottom");
    edgeList both(edges[left]);
    both.append(edges[bottom]);
    edges[left] = both;
    edges[bottom].clear();
    const triangleMesh mesh
    (
        r.points(), r.triangles(), r.triangleMaterials(), r.materials(),
        r.patchNames(), edges
    );
    FatalIOError.throwExceptions();
    std::string message;
    try
    {
        femdemSolid solid
        (
            mesh,
            dict
            (
                "materials { " + material("rock")
              + " } boundaryConditions { left { type symmetryPlane; } }"
            )
        );
    }
    catch (const Foam::IOerror& e)
    {
        message = e.message();
    }
    FatalIOError.dontThrowExceptions();
    RecordProperty("message", message);
    EXPECT_NE(message.find("symmetryPlane"), std::string::npos) << message;
    EXPECT_NE(message.find("left"), std::string::npos) << message;
    EXPECT_NE(message.find("straight"), std::string::npos) << message;
}

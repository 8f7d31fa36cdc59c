// Unit tests of the crack gas on a FEMDEM solid (libimmersedBody
// crackNetwork): gas in a broken joint line drives two blocks apart
#include <gtest/gtest.h>
#include "crackNetwork.H"
#include "femdemSolid.H"
#include "IStringStream.H"
#include <cstdio>
#include <string>

using namespace Foam;

namespace
{
    dictionary dictOf(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    void record(const std::string& key, const scalar v)
    {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.4g", v);
        ::testing::Test::RecordProperty(key, buf);
    }

    // Mass-weighted mean x velocity of the nodes whose triangles lie on
    // one side of x = xSplit
    scalar blockVelocity(const femdemSolid& s, const scalar xSplit, const bool right)
    {
        scalar p = 0, m = 0;
        for (label t = 0; t < s.nNodes()/3; ++t)
        {
            const scalar xc =
                (s.x()[3*t].x() + s.x()[3*t + 1].x() + s.x()[3*t + 2].x())/3;
            if ((xc > xSplit) != right) continue;
            for (label k = 0; k < 3; ++k)
            {
                const label n = 3*t + k;
                p += s.v()[n].x()/s.invMass()[n];
                m += 1/s.invMass()[n];
            }
        }
        return p/m;
    }
}


TEST(crackNetwork, gasInAGapDrivesTwoBlocksApart)
{
    // Two 10 x 10 mm blocks of one rectangle, the joints between them
    // broken and the right block moved 0.1 mm away: air at 10 bar in the
    // gap (closed at its ends) pushes them apart. Each block obeys
    //     M s'' = p0 (g0/g)^gamma H,  g = g0 + 2 s
    // (the gas adiabatic, the blocks stiff); the gas pays the work its
    // forces do
    const scalar H = 0.01, W = 0.02, g0 = 1e-4, rhoS = 2500;
    const scalar p0 = 1e6, rho0 = 10, gamma = 1.4;
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(W, H), 2, 4, "rock");
    femdemSolid solid
    (
        mesh,
        dictOf
        (
            "contactLaw none; trackEnergy true; materials { rock { E 1e11;"
            " nu 0.25; rho 2500; tensileStrength 1e10; cohesion 1e10;"
            " frictionAngle 30; GI 1e8; GII 1e8; } }"
        )
    );
    const jointTopology& topo = solid.topology();
    DynamicList<label> crack;
    forAll(topo.jointNodes(), j)
    {
        const jointNodeList& jn = topo.jointNodes()[j];
        if
        (
            mag(solid.x()[jn[0]].x() - 0.5*W) < 1e-12
         && mag(solid.x()[jn[1]].x() - 0.5*W) < 1e-12
        )
        {
            crack.append(j);
            solid.setBroken(j);
        }
    }
    ASSERT_EQ(crack.size(), 4);
    for (label t = 0; t < solid.nNodes()/3; ++t)
    {
        const scalar xc =
            (solid.x()[3*t].x() + solid.x()[3*t + 1].x() + solid.x()[3*t + 2].x())/3;
        if (xc > 0.5*W)
        {
            for (label k = 0; k < 3; ++k) solid.xRef()[3*t + k].x() += g0;
        }
    }
    solid.updateStableTimeStep();
    solid.resetEnergyBudget();
    solid.trackWorkDisplacement();

    blastMixture mix(dictOf("materials (air); air { equationOfState idealGas; gamma 1.4; }"));
    crackNetwork net(topo, mix, dictOf("RKorder 2;"));
    net.setJoints(crack, solid.x());
    net.fill(rho0, p0, solid.x());
    const scalar Egas0 = net.gas().energy();
    const scalar Esolid0 = solid.energies().initial;

    // The ODE, RK4 in time with the same step
    const scalar M = rhoS*H*0.5*W;
    scalar s = 0, v = 0;
    auto acc = [&](const scalar ss)
    {
        return p0*Foam::pow(g0/(g0 + 2*ss), gamma)*H/M;
    };

    const scalar dt = 5e-7, tEnd = 8e-5;
    const label nSteps = label(tEnd/dt + 0.5);
    List<vector2D> x1(solid.nNodes()), f(solid.nNodes());
    scalar paid = 0;
    for (label k = 0; k < nSteps; ++k)
    {
        forAll(x1, n) x1[n] = solid.x()[n] + dt*solid.v()[n];
        net.advance(solid.x(), x1, dt);
        f = Zero;
        net.addNodeForces(f);
        solid.externalForce() = f;
        solid.advance(dt);
        paid += net.payWork(solid.workDisplacement());

        const scalar k1s = v, k1v = acc(s);
        const scalar k2s = v + 0.5*dt*k1v, k2v = acc(s + 0.5*dt*k1s);
        const scalar k3s = v + 0.5*dt*k2v, k3v = acc(s + 0.5*dt*k2s);
        const scalar k4s = v + dt*k3v, k4v = acc(s + dt*k3s);
        s += dt*(k1s + 2*k2s + 2*k3s + k4s)/6;
        v += dt*(k1v + 2*k2v + 2*k3v + k4v)/6;
    }

    const scalar vL = blockVelocity(solid, 0.5*W + 0.5*g0, false);
    const scalar vR = blockVelocity(solid, 0.5*W + 0.5*g0, true);
    const femdemSolid::energyBudget b = solid.energies();
    const scalar stored =
        b.kinetic + b.elastic + b.jointStored + b.fracture + b.damping
      + b.contact;
    const scalar Egas = net.gas().energy();
    const scalar total = mag(Egas + stored - Egas0 - Esolid0)/Egas0;
    const scalar gasAccount = mag(Egas - Egas0 + b.external)/Egas0;
    const scalar eV = mag(0.5*(vR - vL)/v - 1);
    const scalar pGap = net.gas().p()[0];
    const scalar pOde = p0*Foam::pow(g0/(g0 + 2*s), gamma);
    record("steps", nSteps);
    record("odeBlockSpeed_m_per_s", v);
    record("blockSpeedLeft_m_per_s", vL);
    record("blockSpeedRight_m_per_s", vR);
    record("blockSpeedErrorVsOde", eV);
    record("gapPressureOverOde_minus1", pGap/pOde - 1);
    record("gapGrowthOverG0", 2*s/g0);
    record("gasEnergyChangePlusWorkOnSolid_overEgas0", gasAccount);
    record("gasPlusSolidEnergyChange_overEgas0", total);
    record("workPaid_J_per_m", paid);
    // Both blocks move apart alike, at the ODE's speed
    EXPECT_LT(eV, 0.02);
    EXPECT_LT(mag(vR + vL)/vR, 1e-6);
    EXPECT_GT(2*s/g0, 0.5);
    // The gas pays what the solid receives, to round-off; the total to
    // FEMDEM's own budget
    EXPECT_LT(gasAccount, 1e-12);
    EXPECT_LT(total, 1e-6);
}


TEST(crackNetwork, jointsJoiningAndLeavingKeepTheGas)
{
    // A line of 4 broken joints holding gas; two more join (they share the
    // content of the joint they touch), then the first leaves (its gas
    // goes to the joint it touches): mass and energy unchanged
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.02, 0.06), 2, 6, "rock");
    femdemSolid solid
    (
        mesh,
        dictOf
        (
            "contactLaw none; materials { rock { E 1e10; nu 0.25;"
            " rho 2500; tensileStrength 1e7; cohesion 1e7; frictionAngle 30;"
            " GI 100; GII 100; } }"
        )
    );
    const jointTopology& topo = solid.topology();
    // The joints on x = 0.01, bottom to top
    List<std::pair<scalar, label>> line;
    forAll(topo.jointNodes(), j)
    {
        const jointNodeList& jn = topo.jointNodes()[j];
        if
        (
            mag(solid.x()[jn[0]].x() - 0.01) < 1e-12
         && mag(solid.x()[jn[1]].x() - 0.01) < 1e-12
        )
        {
            line.append({solid.x()[jn[0]].y() + solid.x()[jn[1]].y(), j});
        }
    }
    std::sort(line.begin(), line.end());
    ASSERT_EQ(line.size(), 6);
    for (label t = 0; t < solid.nNodes()/3; ++t)
    {
        const scalar xc =
            (solid.x()[3*t].x() + solid.x()[3*t + 1].x() + solid.x()[3*t + 2].x())/3;
        if (xc > 0.01)
        {
            for (label k = 0; k < 3; ++k) solid.xRef()[3*t + k].x() += 5e-5;
        }
    }
    blastMixture mix(dictOf("materials (air); air { equationOfState idealGas; gamma 1.4; }"));
    crackNetwork net(topo, mix, dictOf(""));
    net.setJoints(labelList({line[0].second, line[1].second, line[2].second, line[3].second}), solid.x());
    net.fill(10, 1e6, solid.x());
    const scalar m0 = net.gas().mass(), E0 = net.gas().energy();
    net.setJoints
    (
        labelList({line[0].second, line[1].second, line[2].second,
            line[3].second, line[4].second, line[5].second}),
        solid.x()
    );
    const scalar m1 = net.gas().mass(), E1 = net.gas().energy();
    const scalar rhoNew = net.gas().massOf()[5];
    net.setJoints
    (
        labelList({line[1].second, line[2].second, line[3].second,
            line[4].second, line[5].second}),
        solid.x()
    );
    const scalar m2 = net.gas().mass(), E2 = net.gas().energy();
    record("massChangeOnJoining", mag(m1/m0 - 1));
    record("energyChangeOnJoining", mag(E1/E0 - 1));
    record("massChangeOnLeaving", mag(m2/m0 - 1));
    record("energyChangeOnLeaving", mag(E2/E0 - 1));
    EXPECT_LT(mag(m1/m0 - 1), 1e-14);
    EXPECT_LT(mag(E1/E0 - 1), 1e-14);
    EXPECT_LT(mag(m2/m0 - 1), 1e-14);
    EXPECT_LT(mag(E2/E0 - 1), 1e-14);
    EXPECT_GT(rhoNew, 0);
    EXPECT_EQ(net.createdMass(), 0);
    EXPECT_EQ(net.removedMass(), 0);
    // A joint that touches no gas gets the ambient state, and gas with
    // nowhere to go is removed: both counted
    net.setJoints(labelList({line[0].second}), solid.x());
    EXPECT_GT(net.createdMass(), 0);
    EXPECT_GT(net.removedMass(), 0);
}


// ************************************************************************* //

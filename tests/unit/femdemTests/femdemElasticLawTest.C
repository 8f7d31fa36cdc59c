// Elastic laws of the triangles: neo-Hookean small-strain limit, exact
// large-strain stress, energy conservation of a crushed free triangle,
// St Venant-Kirchhoff softening and inversion, the stable step of the
// current state and its guards
#include <gtest/gtest.h>
#include "femdemTestTools.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    // A single free triangle (no joints). The contact spring is made
    // negligible so that the element alone sets the stable step (with the
    // default 10 E it would dominate the estimate of a lone triangle).
    std::string props(const word& law)
    {
        return "elasticLaw " + law + "; contactLaw none; materials { "
          + material("rock", "contactPenalty 1e3;") + " }";
    }

    const scalar L = 0.01;

    //- Plane-strain uniaxial stretch J along x
    tensor2D uniaxial(const scalar J)
    {
        return tensor2D(J, 0, 0, 1);
    }

    //- Energy estimate of central differences at x_n:
    //  U(x_n) + (K(v_{n-1/2}) + K(v_{n+1/2}))/2
    struct energyRun
    {
        scalar maxDrift = 0, minJ = GREAT, maxJ = -GREAT;
    };

    energyRun runFixedStep(femdemSolid& solid, const scalar dt, const label n)
    {
        energyRun r;
        scalar E0 = 0;
        for (label i = 0; i < n; ++i)
        {
            const scalar U = solid.elasticEnergy();
            const scalar Km = solid.kineticEnergy();
            const scalar J = det(defGrad(solid, 0));
            r.minJ = min(r.minJ, J);
            r.maxJ = max(r.maxJ, J);
            solid.step(dt);
            const scalar E = U + 0.5*(Km + solid.kineticEnergy());
            if (i == 0) E0 = E;
            r.maxDrift = max(r.maxDrift, mag(E - E0)/E0);
        }
        return r;
    }
}


TEST(femdemElasticLaw, smallStrainLimitIsLinearElasticity)
{
    // F = I + e H (H with a rotation part): both laws differ from linear
    // elasticity by O(e^2), i.e. relatively by O(e)
    const tensor2D H(0.8, 0.3, -0.5, -0.6);
    const scalar strains[2] = {1e-4, 1e-3};
    scalar relNH[2], relSVK[2];
    for (label i = 0; i < 2; ++i)
    {
        const tensor2D F = tensor2D::I + strains[i]*H;
        const tensor2D eps = 0.5*(F + F.T()) - tensor2D::I;
        femdemSolid nh(oneTriangle(L), dict(props("neoHookean")));
        femdemSolid svk(oneTriangle(L), dict(props("StVenantKirchhoff")));
        const femdemMaterial& m = nh.materials()[0];
        const tensor2D lin = m.lambda*tr(eps)*tensor2D::I + 2*m.mu*eps;
        const symmTensor2D sLin(lin.xx(), lin.xy(), lin.yy());
        mapNodes(nh, F, vector2D::zero);
        mapNodes(svk, F, vector2D::zero);
        relNH[i] = mag(nh.stress()[0] - sLin)/mag(sLin);
        relSVK[i] = mag(svk.stress()[0] - sLin)/mag(sLin);
        const std::string e = i == 0 ? "1e-4" : "1e-3";
        RecordProperty("neoHookeanVsLinear_strain" + e, sci(relNH[i]));
        RecordProperty("StVenantKirchhoffVsLinear_strain" + e, sci(relSVK[i]));
        EXPECT_LT(relNH[i], 5*strains[i]);
        EXPECT_LT(relSVK[i], 5*strains[i]);
    }
    // Second order: ten times the strain, ten times the relative difference
    const scalar order = std::log10(relNH[1]/relNH[0]) + 1;
    RecordProperty("neoHookeanDifferenceOrder", std::to_string(order));
    EXPECT_NEAR(order, 2, 0.1);
}


TEST(femdemElasticLaw, uniaxialCompressionExactNeoHookean)
{
    // sigma_xx = (mu (J^2 - 1) + lambda ln J)/J, sigma_yy = lambda ln J/J,
    // also rotated by 30 degrees; nodal forces = -dU/dx (energy consistent)
    const scalar a = 30*constant::mathematical::pi/180;
    const tensor2D R(std::cos(a), -std::sin(a), std::sin(a), std::cos(a));
    for (const scalar J : {0.5, 0.1, 0.01})
    {
        femdemSolid solid(oneTriangle(L), dict(props("neoHookean")));
        const femdemMaterial& m = solid.materials()[0];
        const scalar lnJ = std::log(J);
        const symmTensor2D exact
        (
            (m.mu*(J*J - 1) + m.lambda*lnJ)/J, 0, m.lambda*lnJ/J
        );
        mapNodes(solid, uniaxial(J), vector2D::zero);
        const scalar err = mag(solid.stress()[0] - exact)/mag(exact);

        femdemSolid rotated(oneTriangle(L), dict(props("neoHookean")));
        mapNodes(rotated, R & uniaxial(J), vector2D::zero);
        const tensor2D sr =
            R & tensor2D(exact.xx(), 0, 0, exact.yy()) & R.T();
        const symmTensor2D exactR(sr.xx(), sr.xy(), sr.yy());
        const scalar errR = mag(rotated.stress()[0] - exactR)/mag(exactR);

        // Force on node 1 (x) against a central difference of the energy
        solid.step(1e-30);
        const scalar f = solid.force()[1].x();
        const scalar h = 1e-6*J*L;
        const vector2D x1 = solid.x()[1];
        solid.xRef()[1] = x1 + vector2D(h, 0);
        const scalar Up = solid.elasticEnergy();
        solid.xRef()[1] = x1 - vector2D(h, 0);
        const scalar Um = solid.elasticEnergy();
        const scalar errF = mag(f + (Up - Um)/(2*h))/mag(f);

        const std::string tag = "J" + std::to_string(J).substr(0, 4);
        RecordProperty(tag + "_sigmaXX", sci(exact.xx()));
        RecordProperty(tag + "_relativeError", sci(err));
        RecordProperty(tag + "_rotated30_relativeError", sci(errR));
        RecordProperty(tag + "_forceVsEnergyGradient", sci(errF));
        EXPECT_LT(err, 1e-10);
        EXPECT_LT(errR, 1e-10);
        EXPECT_LT(errF, 1e-5);
    }
}


TEST(femdemElasticLaw, crushedTriangleReboundsConservingEnergy)
{
    // Released at rest from J = 0.2 with the stable step of that state: it
    // rebounds (J > 1), never inverts, and the central-difference energy
    // error is bounded and second order in dt
    femdemSolid solid(oneTriangle(L), dict(props("neoHookean")));
    const scalar dt1 = solid.stableTimeStep();
    mapNodes(solid, uniaxial(0.2), vector2D::zero);
    solid.updateStableTimeStep();
    const scalar dt02 = solid.stableTimeStep();
    const List<vector2D> x0(solid.x());

    const energyRun a = runFixedStep(solid, dt02, 4000);
    solid.xRef() = x0;
    solid.vRef() = Zero;
    const energyRun b = runFixedStep(solid, 0.5*dt02, 8000);
    solid.xRef() = x0;
    solid.vRef() = Zero;
    const energyRun c = runFixedStep(solid, 0.25*dt02, 16000);
    const scalar order1 = std::log2(a.maxDrift/b.maxDrift);
    const scalar order2 = std::log2(b.maxDrift/c.maxDrift);

    RecordProperty("dtJ02_over_dtJ1", std::to_string(dt02/dt1));
    RecordProperty("minJ", std::to_string(a.minJ));
    RecordProperty("maxJ", std::to_string(a.maxJ));
    RecordProperty("maxEnergyError_dt", sci(a.maxDrift));
    RecordProperty("maxEnergyError_halfDt", sci(b.maxDrift));
    RecordProperty("maxEnergyError_quarterDt", sci(c.maxDrift));
    RecordProperty("energyErrorOrder_dt_halfDt", std::to_string(order1));
    RecordProperty("energyErrorOrder_halfDt_quarterDt", std::to_string(order2));
    EXPECT_LT(dt02/dt1, 0.5);
    EXPECT_GT(a.minJ, 0.15);
    EXPECT_GT(c.minJ, 0.19);
    EXPECT_GT(a.maxJ, 1.5);
    EXPECT_LT(a.maxDrift, 0.15);
    EXPECT_NEAR(order2, 2, 0.25);

    // The reference step is too large for the crushed state
    femdemSolid ref(oneTriangle(L), dict(props("neoHookean")));
    mapNodes(ref, uniaxial(0.2), vector2D::zero);
    bool diverged = false;
    scalar maxJ = 0;
    try
    {
        for (label i = 0; i < 400 && !diverged; ++i)
        {
            ref.step(dt1);
            const scalar J = det(defGrad(ref, 0));
            maxJ = max(maxJ, mag(J));
            diverged = !(mag(J) < 100);
        }
    }
    catch (const Foam::error&)
    {
        diverged = true;    // non-finite state stopped by the step guard
    }
    RecordProperty("referenceStepDiverges", diverged ? "yes" : "no");
    EXPECT_TRUE(diverged) << "max |J| " << maxJ;
}


TEST(femdemElasticLaw, StVenantKirchhoffSoftensAndInverts)
{
    // Static: uniaxial compression, |sigma_xx| of St Venant-Kirchhoff peaks
    // at J = 1/sqrt(3) and falls to 0 at J = 0; neo-Hookean keeps rising
    scalar s[2][3];
    const scalar Js[3] = {1/std::sqrt(3.0), 0.2, 0.05};
    for (label l = 0; l < 2; ++l)
    {
        for (label i = 0; i < 3; ++i)
        {
            femdemSolid solid
            (
                oneTriangle(L),
                dict(props(l == 0 ? "StVenantKirchhoff" : "neoHookean"))
            );
            mapNodes(solid, uniaxial(Js[i]), vector2D::zero);
            s[l][i] = -solid.stress()[0].xx()/solid.materials()[0].E;
        }
    }
    RecordProperty
    (
        "StVenantKirchhoff_minusSigmaXXoverE_J0.577_0.2_0.05",
        sci(s[0][0]) + " " + sci(s[0][1]) + " " + sci(s[0][2])
    );
    RecordProperty
    (
        "neoHookean_minusSigmaXXoverE_J0.577_0.2_0.05",
        sci(s[1][0]) + " " + sci(s[1][1]) + " " + sci(s[1][2])
    );
    EXPECT_GT(s[0][0], s[0][1]);
    EXPECT_GT(s[0][1], s[0][2]);
    EXPECT_LT(s[1][0], s[1][1]);
    EXPECT_LT(s[1][1], s[1][2]);

    // Dynamic: an equilateral triangle at J = 0.2 still closing at a
    // blast-like node speed of 0.2 c: St Venant-Kirchhoff, whose energy at
    // J = 0 is finite (A0 M/8, just above its energy at J = 0.2) goes
    // through J = 0 and inverts; neo-Hookean rebounds, advance() shrinking
    // its sub-steps as it stiffens (and as the deformation limit requires:
    // without it the first steps jump past J = 0). The energy deviation
    // printed is the naive K(v_{n+1/2}) + U(x_{n+1}), not the central-
    // difference estimate. At half the default step (timeStepSafety 0.25):
    // the collapse is not resolved at the default, where St Venant-
    // Kirchhoff's minimum J (converged: -1.53 at safety 0.0125) was -1.80
    // after a collapse to 115698 sub-steps with the velocity update over
    // dt, and 0.158 (a rebound) with the update over the mean step; at
    // 0.25 both give -1.51/-1.52, at 0.1 -1.54/-1.58 (measured 2026-12-06)
    scalar minJ[2], maxDrift[2];
    label steps[2];
    for (label l = 0; l < 2; ++l)
    {
        femdemSolid solid
        (
            equilateralTriangle(L),
            dict
            (
                props(l == 0 ? "StVenantKirchhoff" : "neoHookean")
              + " timeStepSafety 0.25;"
            )
        );
        const femdemMaterial& m = solid.materials()[0];
        const scalar interval = solid.stableTimeStep();
        const vector2D xc(0.5*L, 0);
        mapNodes(solid, uniaxial(0.2), vector2D::zero);
        solid.updateStableTimeStep();
        const scalar rate = 0.2*m.waveSpeed()/(0.5*0.2*L);
        forAll(solid.v(), k)
        {
            solid.vRef()[k] = vector2D(-rate*(solid.x()[k].x() - 0.1*L), 0);
        }
        const scalar E0 = solid.kineticEnergy() + solid.elasticEnergy();
        minJ[l] = 1;
        maxDrift[l] = 0;
        steps[l] = 0;
        for (label i = 0; i < 200; ++i)
        {
            try
            {
                steps[l] += solid.advance(interval);
            }
            catch (const Foam::error& err)
            {
                ADD_FAILURE() << "law " << l << ", interval " << i << ": "
                    << err.message();
                break;
            }
            minJ[l] = min(minJ[l], det(defGrad(solid, 0)));
            const scalar E = solid.kineticEnergy() + solid.elasticEnergy();
            maxDrift[l] = max(maxDrift[l], mag(E - E0)/E0);
        }
    }
    RecordProperty("closing_StVenantKirchhoff_minJ", std::to_string(minJ[0]));
    RecordProperty("closing_neoHookean_minJ", std::to_string(minJ[1]));
    RecordProperty
    (
        "closing_subSteps_SVK_NH_per200intervals",
        std::to_string(steps[0]) + " " + std::to_string(steps[1])
    );
    RecordProperty
    (
        "closing_maxEnergyDeviation_SVK_NH",
        sci(maxDrift[0]) + " " + sci(maxDrift[1])
    );
    EXPECT_LT(minJ[0], 0) << "St Venant-Kirchhoff did not invert";
    EXPECT_GT(minJ[1], 0) << "neo-Hookean inverted";
    EXPECT_GT(steps[1], 400) << "the neo-Hookean step did not shrink";

    // Inverted (J = -0.2): St Venant-Kirchhoff pushes further towards its
    // mirrored rest state J = -1, neo-Hookean back towards J > 0
    scalar dJ[2];
    for (label l = 0; l < 2; ++l)
    {
        femdemSolid solid
        (
            oneTriangle(L),
            dict(props(l == 0 ? "StVenantKirchhoff" : "neoHookean"))
        );
        mapNodes(solid, uniaxial(-0.2), vector2D::zero);
        solid.updateStableTimeStep();
        solid.step(0.1*solid.stableTimeStep());
        solid.step(0.1*solid.stableTimeStep());
        dJ[l] = det(defGrad(solid, 0)) + 0.2;
    }
    RecordProperty("inverted_dJ_SVK_NH", sci(dJ[0]) + " " + sci(dJ[1]));
    EXPECT_LT(dJ[0], 0);
    EXPECT_GT(dJ[1], 0);
}


TEST(femdemElasticLaw, stableStepGuards)
{
    // A triangle collapsed onto a line (J = 0) or inverted: finite forces
    // and a finite step (neo-Hookean continued below Jmin)
    for (const scalar J : {0.0, -0.5})
    {
        femdemSolid solid(oneTriangle(L), dict(props("neoHookean")));
        mapNodes(solid, uniaxial(J), vector2D::zero);
        solid.updateStableTimeStep();
        const scalar dt = solid.stableTimeStep();
        solid.step(dt);
        bool finite = std::isfinite(dt) && dt > 0;
        for (const vector2D& f : solid.force())
        {
            finite = finite && std::isfinite(f.x()) && std::isfinite(f.y());
        }
        for (const symmTensor2D& s : solid.stress())
        {
            finite = finite && std::isfinite(mag(s));
        }
        RecordProperty("J" + std::to_string(J).substr(0, 4) + "_dt", sci(dt));
        EXPECT_TRUE(finite) << "J = " << J;
    }

    // A non-finite position: FatalError naming the triangle, no SIGFPE
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 2, 2, "rock");
    femdemSolid solid(mesh, dict(props("neoHookean")));
    solid.xRef()[7] = vector2D(std::nan(""), 0);
    try
    {
        solid.updateStableTimeStep();
        ADD_FAILURE() << "a NaN position gave the step " << solid.stableTimeStep();
    }
    catch (const Foam::error& err)
    {
        const std::string msg(err.message());
        RecordProperty("message", msg.substr(0, 120));
        EXPECT_NE(msg.find("triangle 2"), std::string::npos) << msg;
    }
}

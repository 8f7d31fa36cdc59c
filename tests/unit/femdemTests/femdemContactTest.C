// Contact: frictionless elastic collision of two blocks (momentum and
// energy), and a block on an incline (stick below the friction angle,
// slide with a = g (sin th - mu cos th) above it)
#include <gtest/gtest.h>
#include "femdemTestTools.H"

using namespace Foam;
using namespace femdemTest;

namespace
{
    // Strong joints: the bodies stay intact
    const std::string strong =
        "tensileStrength 1e9; cohesion 1e9; GI 1e6; GII 1e6;";
}


TEST(femdemContact, frictionlessCollisionConservation)
{
    const triangleMesh a =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(0.1, 0.1), 4, 4, "rock");
    const triangleMesh b =
        triangleMesh::rectangle(vector2D(0.10001, 0.03), vector2D(0.1, 0.1), 4, 4, "rock");
    const triangleMesh mesh = merge(a, b, "b_");
    femdemSolid solid
    (
        mesh,
        dict
        (
            "contactLaw potential; materials { "
          + material("rock", strong + " friction 0;") + " }"
        )
    );
    const label nA = 3*a.nTriangles();
    for (label n = 0; n < solid.nNodes(); ++n)
    {
        solid.vRef()[n] = n < nA ? vector2D(1.0, 0.2) : vector2D(-0.5, 0);
    }
    const vector2D p0 = solid.momentum();
    const scalar E0 = solid.kineticEnergy();

    label contactSteps = 0;
    scalar minGapEnergy = E0;
    while (solid.time() < 4e-4)
    {
        solid.step();
        if (solid.contact().nActivePairs() > 0) ++contactSteps;
        minGapEnergy = min(minGapEnergy, solid.kineticEnergy());
    }
    const vector2D p1 = solid.momentum();
    const scalar E1 = solid.kineticEnergy() + solid.elasticEnergy()
      + solid.cohesive().storedEnergy(solid);
    const scalar dp = mag(p1 - p0)/mag(p0);
    const scalar dE = mag(E1 - E0)/E0;
    const vector2D va = meanVelocity(solid, 0, nA);
    const vector2D vb = meanVelocity(solid, nA, solid.nNodes());

    RecordProperty("contactSteps", std::to_string(contactSteps));
    // Separated: the right face of A is left of the left face of B
    scalar gap = GREAT;
    for (label n = nA; n < solid.nNodes(); ++n)
    {
        for (label m = 0; m < nA; ++m)
        {
            if (mag(solid.x()[n].y() - solid.x()[m].y()) < 0.1)
            {
                gap = min(gap, solid.x()[n].x() - solid.x()[m].x());
            }
        }
    }
    RecordProperty("momentumRelativeChange", sci(dp));
    RecordProperty("energyRelativeChange", sci(dE));
    RecordProperty("finalGap", sci(gap));
    RecordProperty("vxAfter_A_B", std::to_string(va.x()) + " " + std::to_string(vb.x()));
    EXPECT_GT(contactSteps, 10) << "bodies never touched";
    EXPECT_GT(gap, 0) << "still in contact";
    EXPECT_LT(va.x(), vb.x()) << "bodies did not bounce";
    EXPECT_LT(minGapEnergy, 0.9*E0) << "collision too weak to test";
    EXPECT_LT(dp, 1e-10);
    EXPECT_LT(dE, 0.01);
}


namespace
{
    // Block 0.1 x 0.05 on a fixed ground; gravity tilted by theta; returns
    // the mean displacement along the slope after slideTime and the
    // acceleration fitted on the second half
    void incline
    (
        const scalar thetaDeg,
        const scalar mu,
        const scalar slideTime,
        scalar& displacement,
        scalar& acceleration
    )
    {
        const triangleMesh ground = triangleMesh::rectangle
        (
            vector2D(-0.3, -0.05), vector2D(0.6, 0.05), 12, 1, "rock"
        );
        const triangleMesh block = triangleMesh::rectangle
        (
            vector2D(-0.05, 0), vector2D(0.1, 0.05), 2, 1, "rock"
        );
        const triangleMesh mesh = merge(ground, block, "block_");
        femdemSolid solid
        (
            mesh,
            dict
            (
                "contactLaw potential; materials { "
              + material("rock", strong + " friction " + std::to_string(mu) + ";")
              + " } boundaryConditions { bottom { type fixed; } }"
            )
        );
        const label first = 3*ground.nTriangles(), last = solid.nNodes();
        const scalar g = 9.81, th = thetaDeg*constant::mathematical::pi/180;

        // Settle under the normal component, damped
        solid.setGravity(vector2D(0, -g*std::cos(th)));
        solid.setMassDamping(2e4);
        solid.advance(2e-3);

        // Slide
        solid.setMassDamping(0);
        solid.setGravity(g*vector2D(std::sin(th), -std::cos(th)));
        const scalar t0 = solid.time();
        vector2D x0(Zero);
        for (label n = first; n < last; ++n) x0 += solid.x()[n];
        scalar sumT = 0, sumV = 0, sumTT = 0, sumTV = 0;
        label count = 0;
        while (solid.time() - t0 < slideTime)
        {
            solid.step();
            const scalar t = solid.time() - t0 - 0.5*solid.stableTimeStep();
            if (t > 0.5*slideTime)
            {
                const scalar vx = meanVelocity(solid, first, last).x();
                sumT += t; sumV += vx; sumTT += t*t; sumTV += t*vx;
                ++count;
            }
        }
        vector2D x1(Zero);
        for (label n = first; n < last; ++n) x1 += solid.x()[n];
        displacement = (x1 - x0).x()/(last - first);
        acceleration =
            (count*sumTV - sumT*sumV)/(count*sumTT - sumT*sumT);
    }
}


TEST(femdemContact, inclineStickAndSlide)
{
    const scalar mu = 0.5, g = 9.81, T = 0.02;
    const scalar phiDeg = std::atan(mu)*180/constant::mathematical::pi;

    // Below the friction angle (26.6 deg): sticks
    scalar dStick, aStick;
    incline(20, mu, T, dStick, aStick);
    const scalar dFree = 0.5*g*std::sin(20*constant::mathematical::pi/180)*T*T;
    RecordProperty("frictionAngleDeg", std::to_string(phiDeg));
    RecordProperty("theta20_displacementOverFrictionless", std::to_string(dStick/dFree));
    EXPECT_LT(mag(dStick)/dFree, 0.01);

    // Above: slides with a = g (sin - mu cos)
    scalar dSlide, aSlide;
    incline(35, mu, T, dSlide, aSlide);
    const scalar th = 35*constant::mathematical::pi/180;
    const scalar aTheory = g*(std::sin(th) - mu*std::cos(th));
    const scalar err = mag(aSlide - aTheory)/aTheory;
    RecordProperty("theta35_accelerationTheory", std::to_string(aTheory));
    RecordProperty("theta35_accelerationMeasured", std::to_string(aSlide));
    RecordProperty("theta35_relativeError", std::to_string(err));
    EXPECT_LT(err, 0.02);
}

// The AVX-512 code of the triangle, joint and contact loops (blocks of
// lanes: femdemSolidElastic.C, cohesiveLawTemplates.H, potentialContact.C)
// against their scalar loops: the same stable step, forces, damage, broken
// joints and trajectory bit for bit, on solids whose triangles are crushed
// below Jmin and inverted and whose joints open, slide, soften and break:
// one material (contiguous blocks, one joint class); two materials of
// different elastic laws, one damped, with Weibull joint strengths and an
// in-situ stress (law groups gathered by triangle ids, three joint classes,
// constants per lane); and the same two materials with every joint broken
// and potential contact between most neighbours, with friction between one
// material's triangles and none across
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "Random.H"
#include "mathematicalConstants.H"
#include <cstring>

using namespace Foam;
using namespace femdemTest;

namespace
{
    //- Distort the solid: a smooth displacement of up to 30 % of a cell
    //  (the joints stay closed), node offsets of 2 um (the joints open and
    //  slide into softening: peak openings are about 1e-8 m, softening
    //  spans about 1e-5 m); crush every 17th triangle to 2 % of its size
    //  (J = 4e-4 < Jmin) and invert every 23rd (their joints break); random
    //  velocities
    void distort(femdemSolid& s, const scalar h)
    {
        Random rnd(7);
        List<vector2D>& x = s.xRef();
        const scalar w = constant::mathematical::twoPi/0.07;
        for (vector2D& p : x)
        {
            p += 0.3*h*vector2D(std::sin(w*p.y()), std::cos(w*p.x()))
              + 2e-6*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
        }
        for (label t = 0; 3*t < x.size(); ++t)
        {
            const vector2D c = (x[3*t] + x[3*t + 1] + x[3*t + 2])/3;
            if (t % 17 == 0)
            {
                for (label k = 0; k < 3; ++k) x[3*t + k] = c + 0.02*(x[3*t + k] - c);
            }
            else if (t % 23 == 0)
            {
                std::swap(x[3*t + 1], x[3*t + 2]);
            }
        }
        for (vector2D& v : s.vRef())
        {
            v = vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
        }
    }

    //- Nodes whose x, v or force differ in any bit, plus joints whose
    //  damage or state differ
    label differing(const femdemSolid& a, const femdemSolid& b)
    {
        label n = 0;
        forAll(a.x(), i)
        {
            n += std::memcmp(&a.x()[i], &b.x()[i], sizeof(vector2D)) != 0
              || std::memcmp(&a.v()[i], &b.v()[i], sizeof(vector2D)) != 0
              || std::memcmp(&a.force()[i], &b.force()[i], sizeof(vector2D)) != 0;
        }
        forAll(a.jointDamage(), j)
        {
            n += std::memcmp
                (
                    &a.jointDamage()[j], &b.jointDamage()[j], sizeof(scalar)
                ) != 0
              || a.jointBroken()[j] != b.jointBroken()[j];
        }
        return n;
    }

    void compareCodes
    (
        const std::string& name,
        const std::string& props,
        const bool twoMaterials,
        const bool fragmented = false
    )
    {
        // 13 x 7 cells: 182 triangles, blocks of 64 with a partial one
        const scalar h = 0.1/13;
        const triangleMesh base = triangleMesh::rectangle
        (
            vector2D(0, 0), vector2D(0.1, 7*h), 13, 7, "rock"
        );
        const triangleMesh mesh = twoMaterials
          ? splitMaterials(base, 0.05, wordList({"rock", "soft"}))
          : base;
        femdemSolid scalarSolid(mesh, dict(props));
        femdemSolid laneSolid(mesh, dict(props));
        if (fragmented)
        {
            // Every triangle a body: the contact narrow phase everywhere
            for (label j = 0; j < scalarSolid.nJoints(); ++j)
            {
                scalarSolid.setBroken(j);
                laneSolid.setBroken(j);
            }
        }
        distort(scalarSolid, h);
        distort(laneSolid, h);

        femdemSolid::setVectorCode(femdemSolid::BASELINE);
        scalarSolid.updateStableTimeStep();
        femdemSolid::setVectorCode(femdemSolid::AVX512);
        laneSolid.updateStableTimeStep();
        const scalar dt0 = scalarSolid.stableTimeStep();
        const scalar dt1 = laneSolid.stableTimeStep();
        EXPECT_EQ(0, std::memcmp(&dt0, &dt1, sizeof(scalar)))
            << name << ": stable step " << dt0 << " vs " << dt1;

        label worst = 0, maxActive = 0;
        for (label i = 0; i < 20; ++i)
        {
            femdemSolid::setVectorCode(femdemSolid::BASELINE);
            scalarSolid.step();
            femdemSolid::setVectorCode(femdemSolid::AVX512);
            laneSolid.step();
            worst = max(worst, differing(scalarSolid, laneSolid));
            maxActive = max(maxActive, scalarSolid.contact().nActivePairs());
        }
        femdemSolid::setVectorCode(femdemSolid::cpuVectorCode());
        scalar minJ = GREAT;
        for (label t = 0; 3*t < scalarSolid.x().size(); ++t)
        {
            minJ = min(minJ, det(defGrad(scalarSolid, t)));
        }
        label nBroken = 0, nSoftening = 0;
        forAll(scalarSolid.jointDamage(), j)
        {
            nBroken += scalarSolid.jointBroken()[j];
            const scalar D = scalarSolid.jointDamage()[j];
            nSoftening += !scalarSolid.jointBroken()[j] && D > 0 && D < 1;
        }
        std::cout << "    " << name << ": " << mesh.nTriangles()
            << " triangles, " << scalarSolid.nJoints() << " joints, stable step "
            << dt0 << "; after 20 steps min J " << minJ << ", joints broken "
            << nBroken << ", softening " << nSoftening
            << ", active contact pairs (most in a step) " << maxActive
            << "; nodes and joints differing (any step): " << worst
            << std::endl;
        if (fragmented)
        {
            EXPECT_GT(maxActive, scalarSolid.nJoints()/2)
                << name << ": contact not active between most neighbours";
        }
        else
        {
            EXPECT_GT(nBroken, 0) << name << ": no joint broke";
            EXPECT_GT(nSoftening, 0) << name << ": no joint softening";
        }
        ::testing::Test::RecordProperty
        (
            name.substr(0, 3) + "_differing", std::to_string(worst)
        );
        EXPECT_EQ(0, worst) << name;
        EXPECT_LT(minJ, 0) << name << ": no inverted triangle was tested";
    }
}


TEST(femdemVectorCode, lanesGiveTheScalarBits)
{
    // (the contact narrow phase in lanes: the third case)
    const bool lanes = femdemSolid::cpuVectorCode() == femdemSolid::AVX512;
    std::cout << "    this CPU: "
        << (lanes
            ? "x86-64-v4 (AVX-512): the lanes are compared with the scalar loop"
            : "no AVX-512: both runs take the scalar loop (the lanes are not"
              " compiled for it), so the comparison checks only the switch")
        << std::endl;
    RecordProperty("cpu", lanes ? "AVX-512" : "scalar only");

    compareCodes
    (
        "one material (neo-Hookean, damped)",
        "elasticLaw neoHookean; contactLaw none; materials { "
      + material("rock", "dampingRatio 0.1;") + " }",
        false
    );
    compareCodes
    (
        "two materials (neo-Hookean damped with Weibull strengths, St"
        " Venant-Kirchhoff undamped with in-situ stress)",
        "contactLaw none; materials { "
      + material
        (
            "rock",
            "elasticLaw neoHookean; dampingRatio 0.1;"
            " strengthDistribution { type Weibull; modulus 4; seed 3; }"
        )
      + " "
      + material
        (
            "soft",
            "elasticLaw StVenantKirchhoff; initialStress (-5e6 1e6 -2e6);",
            "5e9", "0.3", "2000"
        )
      + " }",
        true
    );
    compareCodes
    (
        "fragmented, potential contact (friction between rock triangles,"
        " none between rock and soft)",
        "contactLaw potential; materials { "
      + material("rock", "elasticLaw neoHookean; dampingRatio 0.1;") + " "
      + material
        (
            "soft", "elasticLaw StVenantKirchhoff; friction 0;"
            " contactPenalty 2e10;", "5e9", "0.3", "2000"
        )
      + " }",
        true,
        true
    );
}

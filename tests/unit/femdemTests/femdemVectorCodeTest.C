// The triangle loop's AVX-512 code (blocks of lanes, femdemSolidElastic.C)
// against its scalar loop: the same stable step, forces and trajectory bit
// for bit, on solids whose triangles are crushed below Jmin and inverted,
// with one material (contiguous blocks) and with two materials of different
// elastic laws, one damped (law groups: blocks gathered by triangle ids,
// constants per lane)
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "Random.H"
#include <cstring>

using namespace Foam;
using namespace femdemTest;

namespace
{
    //- Distort every triangle (random node offsets of 30 % of a cell),
    //  crush every 17th to 2 % of its size (J = 4e-4 < Jmin) and invert
    //  every 23rd; random velocities
    void distort(femdemSolid& s, const scalar h)
    {
        Random rnd(7);
        List<vector2D>& x = s.xRef();
        for (vector2D& p : x)
        {
            p += 0.3*h*vector2D(rnd.sample01<scalar>() - 0.5, rnd.sample01<scalar>() - 0.5);
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

    //- Nodes whose x, v or force differ in any bit
    label differing(const femdemSolid& a, const femdemSolid& b)
    {
        label n = 0;
        forAll(a.x(), i)
        {
            n += std::memcmp(&a.x()[i], &b.x()[i], sizeof(vector2D)) != 0
              || std::memcmp(&a.v()[i], &b.v()[i], sizeof(vector2D)) != 0
              || std::memcmp(&a.force()[i], &b.force()[i], sizeof(vector2D)) != 0;
        }
        return n;
    }

    void compareCodes
    (
        const std::string& name,
        const std::string& props,
        const bool twoMaterials
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

        label worst = 0;
        for (label i = 0; i < 20; ++i)
        {
            femdemSolid::setVectorCode(femdemSolid::BASELINE);
            scalarSolid.step();
            femdemSolid::setVectorCode(femdemSolid::AVX512);
            laneSolid.step();
            worst = max(worst, differing(scalarSolid, laneSolid));
        }
        femdemSolid::setVectorCode(femdemSolid::cpuVectorCode());
        scalar minJ = GREAT;
        for (label t = 0; 3*t < scalarSolid.x().size(); ++t)
        {
            minJ = min(minJ, det(defGrad(scalarSolid, t)));
        }
        std::cout << "    " << name << ": " << mesh.nTriangles()
            << " triangles, stable step " << dt0 << ", min J after 20 steps "
            << minJ << ", nodes differing in x, v or force (any step): "
            << worst << std::endl;
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
        "two materials (neo-Hookean damped, St Venant-Kirchhoff undamped)",
        "contactLaw none; materials { "
      + material("rock", "elasticLaw neoHookean; dampingRatio 0.1;") + " "
      + material("soft", "elasticLaw StVenantKirchhoff;", "5e9", "0.3", "2000")
      + " }",
        true
    );
}

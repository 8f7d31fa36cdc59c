// Contact candidate list with a Verlet skin: on a moving, fully fragmented
// block (every triangle a body, the halves sliding past each other by cells,
// random velocities on top, many collisions) the
// forces and positions of runs with skins 0.2 and 1 are bitwise those of a
// run that rebuilds the list every step (skin 0), step by step, while the
// skinned runs rebuild it far less often. A list missing a pair, or forces
// depending on the build (pair order), would show here.
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "potentialContact.H"
#include "Random.H"
#include <memory>

using namespace Foam;
using namespace femdemTest;

namespace
{

//- The fragmented block with random velocities (same for every skin)
std::unique_ptr<femdemSolid> fragmentedBlock
(
    const triangleMesh& mesh,
    const scalar skin,
    const scalar speed,
    const label seed
)
{
    std::unique_ptr<femdemSolid> s
    (
        new femdemSolid
        (
            mesh,
            dict
            (
                "contactLaw potential; potentialCoeffs { skin "
              + std::to_string(skin) + "; } materials { "
              + material("rock", "", "1e8", "0.25", "2000") + " }"
            )
        )
    );
    for (label j = 0; j < s->nJoints(); ++j) s->setBroken(j);
    // The upper half at +speed, the lower half at -speed, plus random
    // velocities: the rows at the middle slide past each other by cells,
    // making new pairs all the time
    Random rnd(seed);
    forAll(s->vRef(), i)
    {
        const label t = i/3;
        const scalar yc =
            (s->x()[3*t].y() + s->x()[3*t + 1].y() + s->x()[3*t + 2].y())/3;
        const scalar rx = rnd.sample01<scalar>() - 0.5;
        const scalar ry = rnd.sample01<scalar>() - 0.5;
        const vector2D r(rx, ry);
        s->vRef()[i] = vector2D(yc > 0.05 ? speed : -speed, 0) + 0.5*speed*r;
    }
    return s;
}


//- Largest |a - b| over the entries (0 when bitwise equal)
scalar maxDiff(const UList<vector2D>& a, const UList<vector2D>& b)
{
    scalar d = 0;
    forAll(a, i) d = max(d, mag(a[i] - b[i]));
    return d;
}


//- Number of entries that differ in any bit
label nDiffering(const UList<vector2D>& a, const UList<vector2D>& b)
{
    label n = 0;
    forAll(a, i)
    {
        if (a[i].x() != b[i].x() || a[i].y() != b[i].y()) ++n;
    }
    return n;
}


const contactLaws::potential& potentialOf(const femdemSolid& s)
{
    return dynamic_cast<const contactLaws::potential&>(s.contact());
}


void compareSkins(const label n, const scalar speed, const label seed)
{
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(0.1, 0.1), n, n, "rock"
    );
    auto full = fragmentedBlock(mesh, 0, speed, seed);
    auto skin = fragmentedBlock(mesh, 0.2, speed, seed);
    auto wide = fragmentedBlock(mesh, 1.0, speed, seed);

    const label steps = 1000;
    label nDiffF = 0, nDiffX = 0, activeSteps = 0;
    scalar dF = 0, dX = 0, fMax = 0, moved = 0;
    const List<vector2D> x0(full->x());
    for (label i = 0; i < steps; ++i)
    {
        // The same step for all: a difference in forces is not hidden by
        // different step sizes
        const scalar dt = full->stableTimeStep();
        full->step(dt);
        skin->step(dt);
        wide->step(dt);
        for (const femdemSolid* s : {skin.get(), wide.get()})
        {
            nDiffF += nDiffering(s->force(), full->force());
            nDiffX += nDiffering(s->x(), full->x());
            dF = max(dF, maxDiff(s->force(), full->force()));
            dX = max(dX, maxDiff(s->x(), full->x()));
            EXPECT_EQ
            (
                s->contact().nCandidatePairs(),
                full->contact().nCandidatePairs()
            ) << "step " << i;
            EXPECT_EQ
            (
                s->contact().nActivePairs(), full->contact().nActivePairs()
            ) << "step " << i;
        }
        if (full->contact().nActivePairs() > 0) ++activeSteps;
        for (const vector2D& f : full->force()) fMax = max(fMax, mag(f));
    }
    moved = maxDiff(full->x(), x0);
    const label buildsFull = potentialOf(*full).nListBuilds();
    const label buildsSkin = potentialOf(*skin).nListBuilds();
    const label buildsWide = potentialOf(*wide).nListBuilds();
    const scalar h = 0.1/n;

    const std::string tag = std::to_string(n) + "x" + std::to_string(n) + "_";
    ::testing::Test::RecordProperty
    (
        tag + "largestNodeDisplacementInCells", sci(moved/h)
    );
    ::testing::Test::RecordProperty
    (
        tag + "listBuilds_skin0_skin0.2_skin1",
        std::to_string(buildsFull) + " " + std::to_string(buildsSkin) + " "
      + std::to_string(buildsWide)
    );
    ::testing::Test::RecordProperty
    (
        tag + "differingForces_positions",
        std::to_string(nDiffF) + " " + std::to_string(nDiffX)
    );
    ::testing::Test::RecordProperty
    (
        tag + "maxForceDifferenceOverMaxForce", sci(dF/fMax)
    );
    ::testing::Test::RecordProperty(tag + "maxPositionDifference", sci(dX));
    ::testing::Test::RecordProperty
    (
        tag + "stepsWithActiveContact",
        std::to_string(activeSteps) + "/" + std::to_string(steps)
    );
    EXPECT_EQ(nDiffF, 0) << "forces differ from the every-step rebuild";
    EXPECT_EQ(nDiffX, 0) << "positions differ from the every-step rebuild";
    EXPECT_EQ(buildsFull, steps);
    // The skin was exercised: rebuilt (things moved far enough), but not
    // every step
    EXPECT_GT(buildsSkin, 2) << "nothing moved far enough to test the skin";
    EXPECT_LT(buildsSkin, steps/4);
    EXPECT_LE(buildsWide, buildsSkin);
    EXPECT_GT(activeSteps, steps/2) << "too little contact to test";
    EXPECT_GT(moved, 0.5*h) << "the fragments hardly moved";
}

} // End anonymous namespace


TEST(femdemContactSkin, forcesEqualEveryStepRebuild)
{
    compareSkins(10, 10, 1234);
    compareSkins(16, 25, 99);
}


// ************************************************************************* //

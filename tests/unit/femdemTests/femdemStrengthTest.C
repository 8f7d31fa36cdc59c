// Random joint strengths (strengthDistribution): Weibull statistics on 1e5
// joints, independence of numbering / visiting order / restart, the
// two-material rule, and a bar in uniform tension that fails at its
// weakest joint.
#include <gtest/gtest.h>
#include "femdemTestTools.H"
#include "solidMeshRenumber.H"
#include <map>
#include <array>
#include <random>
#include <algorithm>

using namespace Foam;
using namespace femdemTest;

namespace
{

//- femdemProperties with one material 'rock' and a strengthDistribution
std::string strengthProps
(
    const std::string& distribution,
    const std::string& extra = "",
    const std::string& bcs = ""
)
{
    return "materials { " + material("rock", distribution + " " + extra)
      + " } boundaryConditions { " + bcs + " }";
}

std::string weibull(const scalar m, const label seed)
{
    return "strengthDistribution { type Weibull; modulus "
      + std::to_string(m) + "; seed " + std::to_string(seed) + "; }";
}

//- Maximum-likelihood Weibull modulus of a sample (bisection on the
//  likelihood equation sum x^k ln x / sum x^k - 1/k - <ln x> = 0, whose
//  left side increases with k)
scalar weibullModulusML(const scalarList& x)
{
    scalar meanLn = 0;
    for (const scalar v : x) meanLn += std::log(v)/x.size();
    auto g = [&](const scalar k)
    {
        scalar s = 0, sl = 0;
        for (const scalar v : x)
        {
            const scalar p = std::pow(v, k);
            s += p;
            sl += p*std::log(v);
        }
        return sl/s - 1/k - meanLn;
    };
    scalar lo = 0.05, hi = 200;
    for (label i = 0; i < 60; ++i)
    {
        const scalar mid = std::sqrt(lo*hi);
        (g(mid) > 0 ? hi : lo) = mid;
    }
    return std::sqrt(lo*hi);
}

//- Record tagged figures (RecordProperty) in one call
void record
(
    const std::string& tag,
    std::initializer_list<std::pair<const char*, std::string>> figures
)
{
    for (const auto& f : figures)
    {
        ::testing::Test::RecordProperty(tag + "_" + f.first, f.second);
    }
}

//- Joint key: its edge's end points in the source mesh, sorted
typedef std::array<double, 4> edgeKey;

edgeKey jointKey(const femdemSolid& s, const label j)
{
    const jointTopology& topo = s.topology();
    const jointNodeList& n = topo.jointNodes()[j];
    vector2D a = topo.initialPoints()[topo.nodeVertex()[n[0]]];
    vector2D b = topo.initialPoints()[topo.nodeVertex()[n[1]]];
    if (b.x() < a.x() || (b.x() == a.x() && b.y() < a.y())) std::swap(a, b);
    return {a.x(), a.y(), b.x(), b.y()};
}

std::map<edgeKey, scalar> strengthByEdge(const femdemSolid& s)
{
    std::map<edgeKey, scalar> m;
    for (label j = 0; j < s.nJoints(); ++j)
    {
        m[jointKey(s, j)] = s.jointTensileStrength(j);
    }
    return m;
}

} // namespace


TEST(femdemStrength, weibullMeanAndModulusOn1e5Joints)
{
    // 183 x 183 cells: 3 nx ny - nx - ny = 100101 joints
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(1, 1), 183, 183, "rock"
    );
    const scalar ft = 2e6;
    for (const scalar m : {3.0, 6.0, 12.0})
    {
        // A seed per modulus: otherwise the samples are one sample
        // rescaled and the fitted modulus has the same relative error
        femdemSolid solid
        (
            mesh, dict(strengthProps(weibull(m, 1234 + label(m))))
        );
        const label nJ = solid.nJoints();
        ASSERT_GE(nJ, 100000);
        scalarList x(nJ);
        scalar mean = 0, corr = 0, var = 0;
        for (label j = 0; j < nJ; ++j)
        {
            x[j] = solid.jointTensileStrength(j)/ft;
            mean += x[j]/nJ;
        }
        for (label j = 0; j < nJ; ++j)
        {
            var += sqr(x[j] - mean);
            if (j > 0) corr += (x[j] - mean)*(x[j - 1] - mean);
        }
        // Neighbouring joints (consecutive indices share a triangle)
        // must be uncorrelated: the hash, not a smooth field
        const scalar lag1 = corr/var;
        const scalar mFit = weibullModulusML(x);
        const std::string tag = "m" + std::to_string(label(m));
        record
        (
            tag,
            {
                {"nJoints", std::to_string(nJ)},
                {"meanOverFt", std::to_string(mean)},
                {"fittedModulus", std::to_string(mFit)},
                {"lag1Correlation", sci(lag1)}
            }
        );
        std::printf
        (
            ">> Weibull m %g on %d joints: mean/f_t %.5f, ML modulus %.4f"
            " (error %.3f %%), lag-1 correlation %.2e\n",
            m, int(nJ), mean, mFit, 100*(mFit/m - 1), lag1
        );
        EXPECT_NEAR(mean, 1, 0.03);
        EXPECT_NEAR(mFit/m, 1, 0.03);
        EXPECT_LT(mag(lag1), 0.02);
    }
}


TEST(femdemStrength, sameOnRenumberedMeshReverseOrderAndRestart)
{
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(0.4, 0.3), 40, 30, "rock"
    );
    // Triangles in reverse order, and shuffled then METIS-renumbered
    // (another numbering, as another decomposition would give)
    labelList reverse(mesh.nTriangles());
    forAll(reverse, t) reverse[t] = mesh.nTriangles() - 1 - t;
    labelList shuffle(identity(mesh.nTriangles()));
    std::mt19937 gen(3);
    std::shuffle(shuffle.begin(), shuffle.end(), gen);
    const triangleMesh reversed = solidMeshRenumber::reorder(mesh, reverse);
    const triangleMesh renumbered =
        solidMeshRenumber::renumber(solidMeshRenumber::reorder(mesh, shuffle));

    const std::string props = strengthProps(weibull(5, 987654321));
    femdemSolid a(mesh, dict(props));
    const std::map<edgeKey, scalar> ref = strengthByEdge(a);
    label differ = 0, nCompared = 0;
    for (const triangleMesh* other : {&reversed, &renumbered})
    {
        femdemSolid b(*other, dict(props));
        const std::map<edgeKey, scalar> s = strengthByEdge(b);
        EXPECT_EQ(s.size(), ref.size());
        for (const auto& kv : s)
        {
            const auto it = ref.find(kv.first);
            ++nCompared;
            if (it == ref.end() || it->second != kv.second) ++differ;
        }
    }
    // The joints visited in reverse order: the same factors
    const strengthDistribution sd(5, 987654321);
    for (label j = a.nJoints() - 1; j >= 0; --j)
    {
        const edgeKey k = jointKey(a, j);
        const scalar w =
            sd.factor(vector2D(k[2], k[3]), vector2D(k[0], k[1]));
        ++nCompared;
        if (w != a.jointStrength()[j]) ++differ;
    }
    // Restart: a solid read back from a written state
    OStringStream os;
    a.writeState(os);
    femdemSolid r(mesh, dict(props));
    r.readState(dict(os.str()));
    forAll(r.jointStrength(), j)
    {
        ++nCompared;
        if (r.jointStrength()[j] != a.jointStrength()[j]) ++differ;
    }
    // A different seed gives different strengths
    femdemSolid c(mesh, dict(strengthProps(weibull(5, 987654322))));
    label same = 0;
    forAll(c.jointStrength(), j)
    {
        if (c.jointStrength()[j] == a.jointStrength()[j]) ++same;
    }
    RecordProperty("jointsCompared", std::to_string(nCompared));
    RecordProperty("differing", std::to_string(differ));
    std::printf
    (
        ">> joint strengths compared bitwise over renumbered, reversed,"
        " reverse-visited and restarted solids: %d, differing %d;"
        " equal under another seed: %d of %d\n",
        int(nCompared), int(differ), int(same), int(a.nJoints())
    );
    EXPECT_EQ(differ, 0);
    EXPECT_GT(nCompared, 4*a.nJoints() - 1);
    EXPECT_EQ(same, 0);
}


TEST(femdemStrength, twoMaterialJointsTakeTheWeakerDistribution)
{
    const triangleMesh base = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(0.2, 0.1), 20, 10, "rock"
    );
    const triangleMesh mesh = splitMaterials(base, 0.1, {"weak", "strong"});
    // 'strong' listed with a stronger f_t: the interface uses 'weak'
    const std::string props =
        "materials { weak { E 10e9; nu 0.25; rho 2500; tensileStrength 1e6;"
        " cohesion 4e6; frictionAngle 30; GI 50; GII 400; "
      + weibull(4, 11) + " } "
        "strong { E 10e9; nu 0.25; rho 2500; tensileStrength 3e6;"
        " cohesion 9e6; frictionAngle 30; GI 50; GII 400; "
      + weibull(8, 12) + " } } boundaryConditions { }";
    femdemSolid solid(mesh, dict(props));
    const strengthDistribution weak(4, 11), strong(8, 12);
    label nInterface = 0, wrong = 0;
    for (label j = 0; j < solid.nJoints(); ++j)
    {
        const label ma = solid.triangleMaterial()[solid.topology().jointTriangleA()[j]];
        const label mb = solid.triangleMaterial()[solid.topology().jointTriangleB()[j]];
        const edgeKey k = jointKey(solid, j);
        const vector2D p(k[0], k[1]), q(k[2], k[3]);
        const bool bothStrong = (ma == 1 && mb == 1);
        const scalar w = bothStrong ? strong.factor(p, q) : weak.factor(p, q);
        if (ma != mb) ++nInterface;
        // The factor scales the class's f_t and c (the weaker material's
        // on an interface)
        const femdemJointProperties& P =
            solid.jointClasses()[solid.jointClass()[j]];
        if (solid.jointStrength()[j] != w) ++wrong;
        if (P.ft != (bothStrong ? 3e6 : 1e6)) ++wrong;
        if (P.c != (bothStrong ? 9e6 : 4e6)) ++wrong;
        if (solid.jointTensileStrength(j) != P.ft*w) ++wrong;
    }
    RecordProperty("interfaceJoints", std::to_string(nInterface));
    std::printf
    (
        ">> two materials: %d interface joints, %d joints with a strength"
        " other than the rule's\n", int(nInterface), int(wrong)
    );
    EXPECT_GT(nInterface, 0);
    EXPECT_EQ(wrong, 0);
}


TEST(femdemStrength, badInputStops)
{
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(0.1, 0.1), 2, 2, "rock"
    );
    const char* bad[] =
    {
        "strengthDistribution { type Weibull; modulus 0; }",
        "strengthDistribution { type Weibull; modulus -2; }",
        "strengthDistribution { type Gauss; modulus 6; }",
        "strengthDistribution { type Weibull; modulus 6; seed 1.5; }",
        "strengthDistribution { type Weibull; modulus 6; seed -1; }",
        "strengthDistribution { type Weibull; }",
    };
    const char* entry[] = {"modulus", "modulus", "type", "seed", "seed", "modulus"};
    label caught = 0;
    for (label i = 0; i < 6; ++i)
    {
        try
        {
            femdemSolid s(mesh, dict(strengthProps(bad[i])));
            ADD_FAILURE() << "accepted: " << bad[i];
        }
        catch (const Foam::IOerror& e)
        {
            const std::string msg = e.message();
            EXPECT_NE(msg.find(entry[i]), std::string::npos) << msg;
            ++caught;
        }
    }
    RecordProperty("badInputsCaught", std::to_string(caught));
    EXPECT_EQ(caught, 6);
    // type none: uniform strengths, no per-joint array
    femdemSolid s(mesh, dict(strengthProps("strengthDistribution { type none; }")));
    EXPECT_TRUE(s.jointStrength().empty());
}


namespace
{

//- Uniaxial bar stress at which joint j of a solid in uniform tension
//  sigma_xx reaches its peak: normal sigma n_x^2 = f_t, or sliding
//  sigma |n_x n_y| = c - sigma n_x^2 tan(phi) (Mohr-Coulomb, tension
//  lowering the shear strength); infinite for joints parallel to the load
scalar criticalBarStress(const femdemSolid& s, const label j)
{
    const jointNodeList& n = s.topology().jointNodes()[j];
    const vector2D t = (s.x()[n[1]] - s.x()[n[0]])/s.jointLength0()[j];
    const scalar nx = t.y(), ny = -t.x();
    const femdemJointProperties& P = s.jointClasses()[s.jointClass()[j]];
    const scalar w = s.jointStrength()[j];
    if (sqr(nx) < 1e-12) return GREAT;
    return min
    (
        w*P.ft/sqr(nx),
        w*P.c/(mag(nx*ny) + sqr(nx)*P.tanPhi)
    );
}

} // namespace


TEST(femdemStrength, barInTensionFailsAtItsWeakestJoint)
{
    // Bar 0.2 m x 0.02 m pulled slowly along x with both ends free in y:
    // uniform uniaxial stress, so the first joint to reach its peak is the
    // one with the smallest critical bar stress, the bar's stress then is
    // that critical stress (below the uniform f_t), and the crack forms
    // in its cross-section. (The first joint to BREAK may be the other
    // joint of that section: it takes the weakest's load as that softens.)
    const scalar Lx = 0.2, Ly = 0.02;
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(Lx, Ly), 20, 2, "rock"
    );
    const std::string bcs =
        "left { type velocity; value (0 0); components (x); } "
        "right { type velocity; value (0.02 0); components (x);"
        " rampTime 2e-4; }";
    const std::pair<scalar, label> cases[] = {{3, 1}, {6, 2}, {10, 3}};
    for (const auto& c : cases)
    {
        // Brittle joints (G_I 1 J/m2: characteristic length E G_I/f_t^2
        // = 2.5 mm, an eightieth of the bar), so that the weakest joint,
        // once past its peak, unloads the bar before another one peaks
        femdemSolid s
        (
            mesh,
            dict
            (
                "materials { rock { E 10e9; nu 0.25; rho 2500;"
                " tensileStrength 2e6; cohesion 8e6; frictionAngle 30;"
                " GI 1; GII 20; dampingRatio 0.2; "
              + weibull(c.first, c.second) + " } } boundaryConditions { "
              + bcs + " }"
            )
        );
        // Prediction and the runner-up margin
        label jPred = -1;
        scalar sMin = GREAT, sSecond = GREAT;
        for (label j = 0; j < s.nJoints(); ++j)
        {
            const scalar sc = criticalBarStress(s, j);
            if (sc < sMin) { sSecond = sMin; sMin = sc; jPred = j; }
            else if (sc < sSecond) { sSecond = sc; }
        }

        label jDamaged = -1, jBroken = -1;
        scalar sigmaAtDamage = 0;
        while (jBroken < 0 && s.time() < 0.02)
        {
            s.step();
            const scalar sigma = s.reaction("right").x()/Ly;
            for (label j = 0; jDamaged < 0 && j < s.nJoints(); ++j)
            {
                if (s.jointDamage()[j] > 0)
                {
                    jDamaged = j;
                    sigmaAtDamage = sigma;
                }
            }
            for (label j = 0; j < s.nJoints(); ++j)
            {
                if (s.jointBroken()[j]) { jBroken = j; break; }
            }
        }
        // The first breakage is in the weakest joint's cross-section
        // (itself, or the other joint of that section, which takes its
        // load as it softens)
        auto midX = [&s](const label j)
        {
            const jointNodeList& n = s.topology().jointNodes()[j];
            const List<vector2D>& X = s.topology().initialPoints();
            const labelList& v = s.topology().nodeVertex();
            return 0.5*(X[v[n[0]]].x() + X[v[n[1]]].x());
        };
        const scalar offset =
            (jPred >= 0 && jBroken >= 0) ? mag(midX(jBroken) - midX(jPred)) : GREAT;
        const std::string tag = "m" + std::to_string(label(c.first));
        const scalar err = sigmaAtDamage/sMin - 1;
        record
        (
            tag,
            {
                {"predictedJoint", std::to_string(jPred)},
                {"firstDamaged", std::to_string(jDamaged)},
                {"firstBroken", std::to_string(jBroken)},
                {"peakStressError", sci(err)},
                {"brokenOffset", sci(offset)}
            }
        );
        std::printf
        (
            ">> bar m %g seed %d: weakest joint %d (critical %.4g MPa,"
            " runner-up +%.2f %%), first damaged %d, first broken %d,"
            " bar stress at first damage %.4g MPa (error %.2f %%,"
            " uniform f_t 2 MPa); first broken %.3g m along the bar from"
            " the weakest\n",
            c.first, int(c.second), int(jPred), sMin/1e6,
            100*(sSecond/sMin - 1), int(jDamaged), int(jBroken),
            sigmaAtDamage/1e6, 100*err, offset
        );
        EXPECT_EQ(jDamaged, jPred);
        EXPECT_LT(offset, 1e-9);
        EXPECT_LT(mag(err), 0.03);
    }
}


TEST(femdemStrength, jointLoopUsesTheScaledCohesion)
{
    // One square cell: two triangles and one diagonal joint. Triangle B
    // slides rigidly along the joint to 0.8 of its scaled peak slip: the
    // pre-peak shear traction f_s g(s/s_p) (Munjiza g = 2x - x^2) depends
    // on c_j = w c, so the joint loop's force must equal the traction of
    // the scaled properties and differ from that of the unscaled ones
    const scalar L = 0.01;
    const triangleMesh mesh = triangleMesh::rectangle
    (
        vector2D(0, 0), vector2D(L, L), 1, 1, "rock"
    );
    scalar worst = 0, unscaledGap = GREAT;
    for (const label seed : {1, 2, 3})
    {
        femdemSolid s(mesh, dict(strengthProps(weibull(4, seed))));
        ASSERT_EQ(s.nJoints(), 1);
        const cohesiveLaw& law = s.cohesive();
        const femdemJointProperties& P = s.jointClasses()[s.jointClass()[0]];
        const scalar w = s.jointStrength()[0];
        femdemJointProperties Pw = P;
        Pw.ft *= w;
        Pw.c *= w;
        const scalar h = s.jointLength0()[0];
        const jointNodeList& n = s.topology().jointNodes()[0];
        const vector2D t = (s.x()[n[1]] - s.x()[n[0]])/h;
        const scalar slip = 0.8*law.slopeFactor()*h*Pw.c/Pw.ps;
        const label tB = s.topology().jointTriangleB()[0];
        for (label k = 0; k < 3; ++k) s.xRef()[3*tB + k] += slip*t;

        List<vector2D> f(s.nNodes(), Zero);
        law.addForces(s, f);
        scalar D = 0, sigma, tau, Du = 0, sigmaU, tauU;
        law.traction(Pw, h, 0, slip, D, sigma, tau);
        law.traction(P, h, 0, slip, Du, sigmaU, tauU);
        const scalar loop = (f[n[0]] & t)/(0.5*h);
        worst = max(worst, mag(loop/tau - 1));
        unscaledGap = min(unscaledGap, mag(loop/tauU - 1));
        std::printf
        (
            ">> joint loop, w = %.4f: shear traction %.6g Pa, scaled-law"
            " traction %.6g Pa, unscaled %.6g Pa\n", w, loop, tau, tauU
        );
    }
    std::printf
    (
        ">> joint loop vs scaled-law traction: worst relative %.2e;"
        " vs unscaled: at least %.2e\n", worst, unscaledGap
    );
    RecordProperty("loopVsScaledTraction", sci(worst));
    RecordProperty("loopVsUnscaledTraction", sci(unscaledGap));
    EXPECT_LT(worst, 1e-10);
    EXPECT_GT(unscaledGap, 1e-3);
}

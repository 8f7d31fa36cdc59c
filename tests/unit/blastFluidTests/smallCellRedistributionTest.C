// The cut cells' geometry of a step (cutCellGeometry, last test) and
// small-cell treatment (smallCellRedistribution, weighted
// state redistribution) on its own, on a blockMesh mesh with random fluid
// fractions, apertures and contents: every component conserved to
// round-off, a uniform state kept to round-off, positive density and
// internal energy kept (a convex combination), forcedOnly touching only
// the forced cells' neighbourhoods, and the content of a closing cell among
// closed ones (an orphan) going to the nearest gas or, out of reach,
// counted as lost
#include <gtest/gtest.h>
#include "fvMesh.H"
#include "Time.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "Random.H"
#include "smallCellRedistribution.H"
#include "cutCellGeometry.H"
#include "blockMeshCase.H"

using namespace Foam;
using blockMeshCase::sci;

namespace
{
    // The mesh, the solver's face addressing and a redistribution of
    // nComp components, with random fluid fractions, apertures and content
    struct srdCase
    :
        public blockMeshCase::timeAndMesh
    {
        volVectorField U;
        blastFaceAddressing addr;
        smallCellRedistribution srd;
        volScalarField phi;
        scalarField aperture;
        conservedFields c;
        label nComp;

        srdCase(const label n, const label nComponents)
        :
            timeAndMesh(blockMeshCase::unitSquare(n, "srdTest")),
            U
            (
                IOobject("U", runTime.timeName(), mesh),
                mesh,
                dimensionedVector(dimVelocity, Zero),
                "zeroGradient"
            ),
            addr(mesh, U),
            srd(mesh, addr, nComponents),
            phi
            (
                IOobject("fluidFraction", runTime.timeName(), mesh),
                mesh,
                dimensionedScalar("one", dimless, 1.0),
                "zeroGradient"
            ),
            aperture(addr.nFaces(), 1),
            nComp(nComponents)
        {}

        // Fluid fractions: a quarter of the cells small (down to 1e-10),
        // a tenth closed; apertures random, a tenth of the faces closed;
        // contents of random positive states (the closed cells none)
        void randomise(const label seed)
        {
            Random rnd(seed);
            scalarField& p = phi.primitiveFieldRef();
            forAll(p, i)
            {
                const scalar r = rnd.sample01<scalar>();
                p[i] =
                    r < 0.1 ? 0
                  : r < 0.2 ? Foam::pow(10.0, -10*rnd.sample01<scalar>())
                  : r < 0.35 ? 0.5*rnd.sample01<scalar>()
                  : 0.5 + 0.5*rnd.sample01<scalar>();
            }
            phi.correctBoundaryConditions();
            forAll(aperture, f)
            {
                aperture[f] =
                    rnd.sample01<scalar>() < 0.1 ? 0 : rnd.sample01<scalar>();
            }
            const label nc = p.size();
            c.rho.setSize(nc);
            c.rhoU.setSize(nc);
            c.rhoE.setSize(nc);
            c.alpha.setSize(nComp > 5 ? nc : 0);
            c.alphaRho1.setSize(nComp > 5 ? nc : 0);
            forAll(p, i)
            {
                const scalar rho = 1 + 10*rnd.sample01<scalar>();
                const vector u
                (
                    100*(rnd.sample01<scalar>() - 0.5),
                    100*(rnd.sample01<scalar>() - 0.5),
                    0
                );
                const scalar e = 1e5*(1 + rnd.sample01<scalar>());
                set(i, rho, u, e, rnd.sample01<scalar>());
            }
        }

        // Content per unit cell volume of intrinsic state (rho, u, e,
        // alpha) in cell i
        void set
        (
            const label i, const scalar rho, const vector& u,
            const scalar e, const scalar alpha
        )
        {
            const scalar p = phi[i];
            c.rho[i] = p*rho;
            c.rhoU[i] = p*rho*u;
            c.rhoE[i] = p*rho*(e + 0.5*magSqr(u));
            if (nComp > 5)
            {
                c.alpha[i] = p*alpha;
                c.alphaRho1[i] = p*alpha*rho;
            }
        }

        // Component k of cell i's content (0 rho, 1-3 rhoU, 4 rhoE,
        // 5 alphaRho1, 6 alpha)
        scalar component(const label k, const label i) const
        {
            return
                k == 0 ? c.rho[i]
              : k < 4 ? c.rhoU[i][k - 1]
              : k == 4 ? c.rhoE[i]
              : k == 5 ? c.alphaRho1[i]
              : c.alpha[i];
        }

        // Total of component k over the mesh (content times volume)
        scalar total(const label k) const
        {
            const scalarField& V = mesh.V();
            scalar s = 0;
            forAll(V, i)
            {
                s += component(k, i)*V[i];
            }
            return s;
        }

        // Scale of component k's total: sum over the cells of |content| V
        scalar scale(const label k) const
        {
            const scalarField& V = mesh.V();
            scalar s = 0;
            forAll(V, i)
            {
                s += mag(component(k, i))*V[i];
            }
            return s;
        }

        void redistribute
        (
            const boolList* force = nullptr,
            const bool forcedOnly = false
        )
        {
            const smallCellRedistribution::faceLinks links
            {
                aperture, nullptr, nullptr
            };
            srd.redistribute(phi, c, links, force, forcedOnly);
        }
    };
}


TEST(SmallCellRedistribution, ConservesEveryComponent)
{
    // Three meshes and seeds, one and two materials (5 and 7 components)
    scalar worst = 0;
    for (const label n : {8, 20, 41})
    {
        for (const label nComp : {5, 7})
        {
            srdCase s(n, nComp);
            s.randomise(17*n + nComp);
            scalarField before(nComp), scale(nComp);
            // Round-off scale: the sum of magnitudes
            for (label k = 0; k < nComp; ++k)
            {
                before[k] = s.total(k);
                scale[k] = s.scale(k);
            }
            s.redistribute();
            const scalar lostShare = s.srd.lostMass()/scale[0];
            for (label k = 0; k < nComp; ++k)
            {
                if (k == 3) continue;  // no z momentum
                // (mass and energy with what orphans lost, counted)
                const scalar lost =
                    k == 0 ? s.srd.lostMass()
                  : k == 4 ? s.srd.lostEnergy()
                  : 0;
                const scalar err =
                    mag(s.total(k) + lost - before[k])/scale[k];
                worst = max(worst, err);
                EXPECT_LT(err, 1e-13)
                    << "n " << n << " nComp " << nComp << " component " << k;
            }
            // Random closed cells (a tenth) leave few pockets without gas
            // within four rings: what is lost is counted, and small
            EXPECT_LT(lostShare, 1e-2);
        }
    }
    RecordProperty("max relative change of a component's total", sci(worst));
    std::cout << "    max relative change of a component's total (mass and"
              << " energy with the counted losses) = " << sci(worst)
              << " (tolerance 1e-13)" << std::endl;
}


// mixUntilPositive on random contents (two materials) with cells of
// negative internal energy: the seeds that a group of at most three rings
// can make positive end positive, with their groups at one intrinsic
// state; a hopeless seed (its deficit more than the rings hold) and a seed
// whose rings reach a skipped cell stay bitwise as they were, as does
// every cell not listed as mixed; every component's total is conserved
TEST(SmallCellRedistribution, MixUntilPositive)
{
    scalar worstTotal = 0, worstGroup = 0;
    label nMixed = 0, nFixed = 0, nSeeds = 0;
    for (const label n : {12, 30})
    {
        srdCase s(n, 7);
        s.randomise(91*n);
        scalarField& p = s.phi.primitiveFieldRef();
        const labelListList& cc = s.mesh.cellCells();
        const label nc = p.size();
        boolList seed(nc, false), skip(nc, false);
        // Seeds in the mesh's interior, apart from each other: e from
        // -1e5 to -4e5 J/kg against the others' 1e5 to 2e5
        Random rnd(3*n);
        labelList seeds;
        for (label i = 2*n + 2; i < nc - 2*n - 2; i += 7*n/3 + 5)
        {
            p[i] = 0.5 + 0.5*rnd.sample01<scalar>();
            s.set
            (
                i, 1 + 10*rnd.sample01<scalar>(), vector(30, -20, 0),
                -1e5*(1 + 3*rnd.sample01<scalar>()), 0.3
            );
            seed[i] = true;
            seeds.append(i);
        }
        // A hopeless seed, and one next to a skipped cell
        const label hopeless = seeds[0], blocked = seeds[1];
        s.set(hopeless, 5, vector(30, -20, 0), -1e12, 0.3);
        skip[cc[blocked][0]] = true;
        nSeeds += seeds.size();

        scalarField before(7), scale(7);
        for (label k = 0; k < 7; ++k)
        {
            before[k] = s.total(k);
            scale[k] = s.scale(k);
        }
        const conservedFields c0(s.c);
        const label nm = s.srd.mixUntilPositive(p, s.c, seed, skip, 3);
        nMixed += nm;
        for (label k = 0; k < 7; ++k)
        {
            if (k == 3) continue;
            worstTotal =
                max(worstTotal, mag(s.total(k) - before[k])/scale[k]);
        }
        boolList mixed(nc, false);
        for (const label j : s.srd.mixedCells()) mixed[j] = true;
        EXPECT_EQ(label(s.srd.mixedCells().size()), nm);
        const auto e = [&](const label i)
        {
            return (s.c.rhoE[i] - 0.5*magSqr(s.c.rhoU[i])/s.c.rho[i])/s.c.rho[i];
        };
        for (const label i : seeds)
        {
            if (i == hopeless || i == blocked)
            {
                EXPECT_FALSE(mixed[i]) << "cell " << i;
                continue;
            }
            EXPECT_TRUE(mixed[i]) << "cell " << i;
            EXPECT_GT(e(i), 0) << "cell " << i;
            if (e(i) > 0) ++nFixed;
            // Its group: the mixed cells around it share its state
            for (const label j : cc[i])
            {
                if (!mixed[j]) continue;
                worstGroup = max
                (
                    worstGroup,
                    mag(s.c.rho[j]/p[j] - s.c.rho[i]/p[i])/(s.c.rho[i]/p[i])
                );
            }
        }
        label untouchedChanged = 0;
        forAll(p, i)
        {
            if (mixed[i]) continue;
            if
            (
                s.c.rho[i] != c0.rho[i] || s.c.rhoU[i] != c0.rhoU[i]
             || s.c.rhoE[i] != c0.rhoE[i] || s.c.alpha[i] != c0.alpha[i]
             || s.c.alphaRho1[i] != c0.alphaRho1[i]
            )
            {
                ++untouchedChanged;
            }
        }
        EXPECT_EQ(untouchedChanged, 0);
    }
    std::cout << "    " << nSeeds << " seeds of e < 0 (one hopeless and one"
        << " near a skipped cell per mesh): " << nFixed << " made positive"
        << " (expected " << nSeeds - 4 << "), " << nMixed << " cells mixed;"
        << " max relative change of a component's total " << sci(worstTotal)
        << " (tolerance 1e-13); density spread within a group "
        << sci(worstGroup) << " (tolerance 1e-13)" << std::endl;
    EXPECT_EQ(nFixed, nSeeds - 4);
    EXPECT_LT(worstTotal, 1e-13);
    EXPECT_LT(worstGroup, 1e-13);
}


// mixUntilPositive with rings to take at least (the solver's repair of a
// state without a sound speed at a step's start, e > 0): a seed is mixed
// with its first minRings rings of cells with gas, whatever its internal
// energy, each of the group then at one intrinsic state; a seed with no
// gas within those rings is left bitwise, as is every cell not mixed;
// without minRings a seed with positive internal energy is not touched
TEST(SmallCellRedistribution, MixAtLeastRings)
{
    scalar worstTotal = 0, worstGroup = 0;
    label nGroups = 0;
    for (const label minRings : {0, 1, 2})
    {
        const label n = 15;
        srdCase s(n, 5);
        s.randomise(13);
        scalarField& p = s.phi.primitiveFieldRef();
        const labelListList& cc = s.mesh.cellCells();
        const label nc = p.size();
        // Every cell some gas, at states of its own, but the isolated
        // seed's neighbours
        p = max(p, scalar(0.3));
        forAll(p, i)
        {
            s.set(i, 1 + i % 7, vector(5 - i % 11, 3, 0), 1e5*(1 + i % 3), 0);
        }
        const label seedA = 4*n + 4, seedB = 10*n + 10;
        // seedB: no gas within two rings
        labelHashSet closed;
        for (const label j : cc[seedB])
        {
            closed.insert(j);
            for (const label k : cc[j]) closed.insert(k);
        }
        closed.erase(seedB);
        for (const label j : closed.toc()) p[j] = 0;
        for (const label i : {seedA, seedB})
        {
            // Ten times its neighbours' density, e > 0
            p[i] = 0.05;
            s.set(i, 60, vector(10, 0, 0), 1e4, 0);
        }
        for (const label j : closed.toc()) s.set(j, 0, Zero, 0, 0);
        boolList seed(nc, false), skip(nc, false);
        seed[seedA] = seed[seedB] = true;
        scalarField before(5), scale(5);
        for (label k = 0; k < 5; ++k)
        {
            before[k] = s.total(k);
            scale[k] = s.scale(k);
        }
        const conservedFields c0(s.c);
        const label nm =
            s.srd.mixUntilPositive(p, s.c, seed, skip, 3, minRings);
        boolList mixed(nc, false);
        for (const label j : s.srd.mixedCells()) mixed[j] = true;
        // The expected group of seedA: its rings up to minRings
        label expected = 0;
        if (minRings > 0)
        {
            labelHashSet group;
            group.insert(seedA);
            for (label r = 0; r < minRings; ++r)
            {
                for (const label i : group.toc())
                {
                    for (const label j : cc[i]) group.insert(j);
                }
            }
            expected = group.size();
            for (const label j : group.toc())
            {
                EXPECT_TRUE(mixed[j]) << "cell " << j;
                worstGroup = max
                (
                    worstGroup,
                    mag(s.c.rho[j]/p[j] - s.c.rho[seedA]/p[seedA])
                   /(s.c.rho[seedA]/p[seedA])
                );
            }
            ++nGroups;
        }
        EXPECT_EQ(nm, expected);
        EXPECT_FALSE(mixed[seedB]);
        label untouchedChanged = 0;
        forAll(p, i)
        {
            if (mixed[i]) continue;
            if
            (
                s.c.rho[i] != c0.rho[i] || s.c.rhoU[i] != c0.rhoU[i]
             || s.c.rhoE[i] != c0.rhoE[i]
            )
            {
                ++untouchedChanged;
            }
        }
        EXPECT_EQ(untouchedChanged, 0);
        for (label k = 0; k < 5; ++k)
        {
            if (k == 3) continue;
            worstTotal = max
            (
                worstTotal,
                mag(s.total(k) - before[k])/scale[k]
            );
        }
        std::cout << "    minRings " << minRings << ": " << nm
                  << " cells mixed (expected " << expected << ")"
                  << std::endl;
    }
    std::cout << "    " << nGroups << " groups at one state to "
              << sci(worstGroup) << ", totals to " << sci(worstTotal)
              << " (tolerances 1e-13)" << std::endl;
    EXPECT_LT(worstGroup, 1e-13);
    EXPECT_LT(worstTotal, 1e-13);
}


TEST(SmallCellRedistribution, KeepsUniformStateAndPositivity)
{
    // Uniform intrinsic state: every cell with gas keeps it; random
    // states: density and internal energy stay positive, within the
    // range of the states that were merged
    scalar worstUniform = 0;
    for (const label n : {10, 33})
    {
        srdCase s(n, 7);
        s.randomise(5*n);
        const scalar rho0 = 2.5, e0 = 3.1e5, a0 = 0.375;
        const vector u0(12.5, -7.25, 0);
        forAll(s.c.rho, i) s.set(i, rho0, u0, e0, a0);
        s.redistribute();
        forAll(s.c.rho, i)
        {
            const scalar p = s.phi[i];
            if (p <= 0) continue;
            worstUniform = max(worstUniform, mag(s.c.rho[i]/p - rho0)/rho0);
            worstUniform =
                max(worstUniform, mag(s.c.rhoU[i]/p - rho0*u0)/mag(rho0*u0));
            const scalar E0 = rho0*(e0 + 0.5*magSqr(u0));
            worstUniform = max(worstUniform, mag(s.c.rhoE[i]/p - E0)/E0);
            worstUniform = max(worstUniform, mag(s.c.alpha[i]/p - a0)/a0);
        }

        srdCase r(n, 5);
        r.randomise(7*n + 1);
        scalar rhoMin = GREAT, rhoMax = 0;
        forAll(r.c.rho, i)
        {
            if (r.phi[i] <= 0) continue;
            rhoMin = min(rhoMin, r.c.rho[i]/r.phi[i]);
            rhoMax = max(rhoMax, r.c.rho[i]/r.phi[i]);
        }
        r.redistribute();
        forAll(r.c.rho, i)
        {
            const scalar p = r.phi[i];
            if (p <= 0) continue;
            const scalar rho = r.c.rho[i]/p;
            const scalar e =
                (r.c.rhoE[i] - 0.5*magSqr(r.c.rhoU[i])/r.c.rho[i])/r.c.rho[i];
            EXPECT_GT(rho, (1 - 1e-12)*rhoMin) << "cell " << i;
            EXPECT_LT(rho, (1 + 1e-12)*rhoMax) << "cell " << i;
            EXPECT_GT(e, 0) << "cell " << i;
        }
    }
    EXPECT_LT(worstUniform, 1e-13);
    RecordProperty("uniform state: max relative change", sci(worstUniform));
    std::cout << "    uniform state: max relative change in a cell = "
              << sci(worstUniform) << " (tolerance 1e-13)" << std::endl;
}


TEST(SmallCellRedistribution, ForcedOnlyTouchesForcedNeighbourhoods)
{
    // Cells open (phi 0.7-1) but two small ones (phi 0.2) away from three
    // forced ones: with forcedOnly only the forced cells and their face
    // neighbours change, the small ones keep their content
    srdCase s(16, 5);
    s.randomise(99);
    scalarField& p = s.phi.primitiveFieldRef();
    Random rnd(4);
    forAll(p, i) p[i] = 0.7 + 0.3*rnd.sample01<scalar>();
    p[60] = 0.2;
    p[250] = 0.2;
    s.phi.correctBoundaryConditions();
    s.aperture = 1;
    forAll(p, i) s.set(i, 1 + i % 7, vector(i % 3, 1, 0), 1e5*(1 + i % 5), 0);
    const scalarField rho0(s.c.rho);
    boolList force(p.size(), false);
    for (const label i : {17, 100, 203}) force[i] = true;
    labelHashSet near;
    for (const label i : {17, 100, 203})
    {
        near.insert(i);
        near.insert(s.mesh.cellCells()[i]);
    }
    s.redistribute(&force, true);
    label changedFar = 0, changedNear = 0;
    forAll(p, i)
    {
        const bool changed = s.c.rho[i] != rho0[i];
        if (near.found(i)) changedNear += changed;
        else changedFar += changed;
    }
    EXPECT_EQ(changedFar, 0);
    EXPECT_GT(changedNear, 3);
    std::cout << "    forcedOnly, 3 forced cells: " << changedNear
              << " cells changed in their neighbourhoods, " << changedFar
              << " elsewhere (expected 0)" << std::endl;
}


TEST(SmallCellRedistribution, OrphansGoToNearestGasOrAreCounted)
{
    // A closing cell (phi 0, content left) in a block of closed cells:
    // with gas two rings away its content goes there; with none within
    // four rings it is lost and counted
    for (const label radius : {1, 5})
    {
        srdCase s(21, 5);
        scalarField& p = s.phi.primitiveFieldRef();
        const label n = 21, centre = 10*n + 10;
        const vectorField& C = s.mesh.C();
        forAll(p, i)
        {
            const scalar d =
                n*max
                (
                    mag(C[i].x() - C[centre].x()),
                    mag(C[i].y() - C[centre].y())
                );
            p[i] = d < radius + 0.5 ? 0 : 1;
        }
        s.phi.correctBoundaryConditions();
        s.aperture = 1;
        s.c.rho.setSize(p.size());
        s.c.rhoU.setSize(p.size());
        s.c.rhoE.setSize(p.size());
        forAll(p, i) s.set(i, 1.2, vector(3, 4, 0), 2e5, 0);
        // The closing cell's content (its gas volume went to zero)
        const scalar m = 0.25, E = 0.25*2.5e5;
        s.c.rho[centre] = m;
        s.c.rhoU[centre] = vector(1, 0, 0);
        s.c.rhoE[centre] = E;
        const scalar before = s.total(0), energyBefore = s.total(4);
        s.redistribute();
        const scalar mErr =
            mag(s.total(0) + s.srd.lostMass() - before)/before;
        const scalar eErr =
            mag(s.total(4) + s.srd.lostEnergy() - energyBefore)/energyBefore;
        EXPECT_LT(mErr, 1e-14);
        EXPECT_LT(eErr, 1e-14);
        EXPECT_EQ(s.c.rho[centre], 0);
        const scalar V = s.mesh.V()[centre];
        if (radius == 1)
        {
            EXPECT_EQ(s.srd.lostMass(), 0);
        }
        else
        {
            EXPECT_NEAR(s.srd.lostMass(), m*V, 1e-15*m*V);
            EXPECT_NEAR(s.srd.lostEnergy(), E*V, 1e-15*E*V);
        }
        std::cout << "    orphan in a closed block of radius " << radius
                  << " cells: lost mass " << sci(s.srd.lostMass()/(m*V))
                  << " of its content (expected " << (radius == 1 ? 0 : 1)
                  << "), mass and energy kept to " << sci(max(mErr, eErr))
                  << std::endl;
    }
}


// The step's geometry (cutCellGeometry) on random fluid fractions at both
// ends and random apertures: the faces of cells without gas at both ends
// are closed; every cell's wall vector closes its open faces (W_i + sum_f
// a_f S_f = 0, outward face vectors); the swept volume is (phi1 - phi0) V;
// a cell that opens with no open face to gas stays closed, one next to gas
// opens (and is a new cell)
TEST(CutCellGeometry, ClosesFacesAndWallsAndKeepsUnreachedCellsClosed)
{
    scalar worstClosure = 0;
    label nKept = 0, nOpened = 0;
    for (const label n : {9, 24})
    {
        srdCase s(n, 5);
        volScalarField& phi0 = s.phi;
        volScalarField phi1("phi1", phi0);
        Random rnd(31*n);
        scalarField& p0 = phi0.primitiveFieldRef();
        scalarField& p1 = phi1.primitiveFieldRef();
        forAll(p0, i)
        {
            const scalar r0 = rnd.sample01<scalar>();
            const scalar r1 = rnd.sample01<scalar>();
            p0[i] = r0 < 0.3 ? 0 : r0;
            p1[i] = r1 < 0.3 ? 0 : r1;
        }
        phi0.correctBoundaryConditions();
        phi1.correctBoundaryConditions();
        const scalarField p1Given(p1);
        surfaceScalarField ap
        (
            IOobject("aperture", s.runTime.timeName(), s.mesh),
            s.mesh,
            dimensionedScalar("one", dimless, 1.0)
        );
        forAll(ap, f) ap[f] = rnd.sample01<scalar>() < 0.2 ? 0 : 1;
        cutCellGeometry g(s.mesh, s.addr);
        g.set(phi0, phi1, ap);

        const blastFaceAddressing& a = s.addr;
        const scalarField& A = g.aperture();
        vectorField sumOpen(s.mesh.nCells(), Zero);
        scalar scale = 0;
        for (label f = 0; f < a.nFaces(); ++f)
        {
            const label P = a.own()[f];
            sumOpen[P] += A[f]*a.Sf()[f];
            scale = max(scale, mag(a.Sf()[f]));
            const bool shutP = p0[P] <= 0 && p1[P] <= 0;
            bool shutN = false;
            if (f < a.nInternal())
            {
                const label N = a.nei()[f];
                sumOpen[N] -= A[f]*a.Sf()[f];
                shutN = p0[N] <= 0 && p1[N] <= 0;
            }
            if (shutP || shutN)
            {
                EXPECT_EQ(A[f], 0) << "face " << f;
            }
        }
        const scalarField& V = s.mesh.V();
        forAll(V, i)
        {
            vector c = g.wallVector()[i] + sumOpen[i];
            c.z() = 0;
            worstClosure = max(worstClosure, mag(c)/scale);
            EXPECT_EQ(g.sweptVolume()[i], (p1[i] - p0[i])*V[i]);
            if (p0[i] <= 0 && p1Given[i] > 0)
            {
                // Opening: kept closed unless an open face leads to gas
                bool gasNext = false;
                for (const label f : s.mesh.cells()[i])
                {
                    if (f >= a.nInternal()) continue;
                    const label o = a.own()[f] == i ? a.nei()[f] : a.own()[f];
                    gasNext = gasNext || (ap[f] > 0 && p0[o] > 0);
                }
                if (gasNext)
                {
                    ++nOpened;
                    EXPECT_EQ(p1[i], p1Given[i]);
                    EXPECT_TRUE(g.newCell()[i]);
                }
                else
                {
                    ++nKept;
                    EXPECT_EQ(p1[i], 0);
                    EXPECT_FALSE(g.newCell()[i]);
                }
            }
        }
    }
    EXPECT_LT(worstClosure, 1e-14);
    EXPECT_GT(nKept, 0);
    EXPECT_GT(nOpened, 0);
    RecordProperty("wall closure: max |W + sum a S| / |S|", sci(worstClosure));
    std::cout << "    wall vectors close the open faces to " << sci(worstClosure)
              << " of a face area (tolerance 1e-14); opening cells: "
              << nOpened << " next to gas opened, " << nKept
              << " out of reach kept closed" << std::endl;
}

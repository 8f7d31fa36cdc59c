// The gas state of the solver (blastFluidState) on its own, on blockMesh
// meshes with random fields of two and three materials (stiffened-gas
// water, ideal-gas air and helium): the conservative state from the
// primitive fields and the primitives back from it reproduce p, U, the
// volume fractions and the phase densities to round-off; a non-physical
// cell is marked for a first-order retry (not fatal) or stops the run
// naming the cell (fatal); the primitives of a list of cells are bitwise
// those of the whole-mesh conversion; fields out of range stop with a
// FatalIOError naming the field and the cell. And the solver's repair of a
// state changed between steps (blastFluidSolver::repairState)
#include <gtest/gtest.h>
#include "fvMesh.H"
#include "Time.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "Random.H"
#include "blastFluidState.H"
#include "blastFluidSolver.H"
#include "blockMeshCase.H"

using namespace Foam;
using blockMeshCase::sci;

namespace
{
    // The materials' dictionaries (water a stiffened gas, air and helium
    // ideal gases)
    const char* const materialDicts =
        "water { equationOfState stiffenedGas; gamma 4.4; pInf 6e8; }\n"
        "air { equationOfState idealGas; gamma 1.4; Cv 718; }\n"
        "helium { equationOfState idealGas; gamma 1.667; Cv 3116; }\n";

    // Write a field of the start time: cell values at 17 digits, zero
    // gradient (slip for U) on the walls
    template<class Type>
    void writeField
    (
        const fileName& dir,
        const word& name,
        const word& cls,
        const char* dims,
        const UList<Type>& values
    )
    {
        mkDir(dir/"0");
        OFstream os(dir/"0"/name);
        os.precision(17);
        os  << "FoamFile { version 2.0; format ascii; class " << cls
            << "; object " << name << "; }\n"
            << "dimensions " << dims << ";\n"
            << "internalField nonuniform List<"
            << word(pTraits<Type>::typeName) << "> " << values.size()
            << " (";
        for (const Type& v : values) os << ' ' << v;
        os  << ");\nboundaryField { walls { type "
            << (cls == "volVectorField" ? "slip" : "zeroGradient")
            << "; } frontAndBack { type empty; } }\n";
    }

    // A case of nCells cells with random primitive fields of nMat
    // materials (water first); pBad, alphaBad: a value out of range in
    // cell 5 of p or of the first volume fraction
    struct stateCase
    {
        fileName dir;
        label nMat;
        scalarField p, alpha1, alpha2, r1, r2, r3;
        vectorField U;

        stateCase
        (
            const label n,
            const label nMaterials,
            const label seed,
            const std::string& prefix,
            const bool pBad = false,
            const bool alphaBad = false
        )
        :
            dir(blockMeshCase::unitSquare(n, prefix)),
            nMat(nMaterials)
        {
            if (isDir(dir/"0")) rmDir(dir/"0");
            const label nc = n*n;
            Random rnd(seed);
            p.setSize(nc); U.setSize(nc);
            alpha1.setSize(nc); alpha2.setSize(nc);
            r1.setSize(nc); r2.setSize(nc); r3.setSize(nc);
            for (label i = 0; i < nc; ++i)
            {
                // 1 MPa to 1 GPa
                p[i] = Foam::pow(10.0, 6 + 3*rnd.sample01<scalar>());
                U[i] = vector
                (
                    1000*(rnd.sample01<scalar>() - 0.5),
                    1000*(rnd.sample01<scalar>() - 0.5),
                    0
                );
                // pure cells of each material and mixed ones
                const scalar a = rnd.sample01<scalar>();
                const scalar b = rnd.sample01<scalar>();
                alpha1[i] = i % 4 == 0 ? 0 : i % 4 == 1 ? 1 : a;
                alpha2[i] = nMat == 3 ? (1 - alpha1[i])*b : 0;
                r1[i] = 900 + 200*rnd.sample01<scalar>();
                r2[i] = 1 + 50*rnd.sample01<scalar>();
                r3[i] = 0.2 + 5*rnd.sample01<scalar>();
            }
            if (pBad) p[5] = -1;
            if (alphaBad) alpha1[5] = 1.5;

            blockMeshCase::writeDict
            (
                dir/"constant"/"thermophysicalProperties",
                "thermophysicalProperties",
                std::string
                (
                    nMat == 1 ? "materials (air);\n"
                  : nMat == 2 ? "materials (water air);\n"
                  : "materials (water air helium);\n"
                )
              + materialDicts
            );
            const char* dP = "[1 -1 -2 0 0 0 0]";
            const char* dR = "[1 -3 0 0 0 0 0]";
            writeField(dir, "p", "volScalarField", dP, p);
            writeField(dir, "U", "volVectorField", "[0 1 -1 0 0 0 0]", U);
            if (nMat == 1)
            {
                writeField(dir, "rho", "volScalarField", dR, r2);
                return;
            }
            writeField
            (
                dir, "alpha.water", "volScalarField", "[0 0 0 0 0 0 0]",
                alpha1
            );
            writeField(dir, "rho.water", "volScalarField", dR, r1);
            writeField(dir, "rho.air", "volScalarField", dR, r2);
            if (nMat == 3)
            {
                writeField
                (
                    dir, "alpha.air", "volScalarField", "[0 0 0 0 0 0 0]",
                    alpha2
                );
                writeField(dir, "rho.helium", "volScalarField", dR, r3);
            }
        }
    };

    // The time, mesh and state of a case
    struct stateRun
    :
        public blockMeshCase::timeAndMesh
    {
        blastFluidState state;
        scalarField lowOrder;

        explicit stateRun(const fileName& dir)
        :
            timeAndMesh(dir),
            state(mesh),
            lowOrder(mesh.nCells(), 0)
        {}
    };

    // A unit-square case of n x n cells with the thermophysicalProperties
    // body thermo and no start time yet (the test writes its fields)
    fileName caseWithMaterials
    (
        const label n,
        const std::string& prefix,
        const std::string& thermo
    )
    {
        const fileName dir = blockMeshCase::unitSquare(n, prefix);
        if (isDir(dir/"0")) rmDir(dir/"0");
        blockMeshCase::writeDict
        (
            dir/"constant"/"thermophysicalProperties",
            "thermophysicalProperties", thermo
        );
        return dir;
    }

    // The message of the fatal conversion of s (empty if it passed),
    // printed
    std::string fatalConversion(blastFluidState& s, scalarField& lowOrder)
    {
        FatalError.throwExceptions();
        std::string message;
        try
        {
            s.primitivesFromConservative(true, lowOrder, nullptr);
        }
        catch (const Foam::error& e)
        {
            message = e.message();
        }
        FatalError.dontThrowExceptions();
        std::cout << "  fatal: " << message.substr(0, 150) << std::endl;
        return message;
    }

    scalar maxRelDiff(const scalarField& a, const scalarField& b)
    {
        scalar d = 0;
        forAll(a, i)
        {
            d = max(d, mag(a[i] - b[i])/max(mag(b[i]), VSMALL));
        }
        return d;
    }

    // The round trip primitive -> conservative -> primitive of a case:
    // p, U, the volume fractions and the densities of the phases present
    void roundTrip(const label nMat, const label seed)
    {
        const stateCase c(8, nMat, seed, "stateTest" + std::to_string(nMat));
        stateRun r(c.dir);
        blastFluidState& s = r.state;
        s.initialise(r.lowOrder, nullptr);
        EXPECT_TRUE(s.current());

        const scalar dp = maxRelDiff(s.p().primitiveField(), c.p);
        scalar du = 0;
        forAll(c.U, i)
        {
            du = max(du, mag(s.U()[i] - c.U[i])/mag(c.U[i]));
        }
        // The phase densities: relative error where the phase holds more
        // than 1e-6 of the volume (informative: a phase of small volume
        // fraction takes its density from a difference of partial
        // densities), and the error of alpha_k rho_k relative to the
        // mixture density (round-off whatever the fractions)
        scalar da = 0, dr = 0, dm = 0, dar = 0;
        const auto phase = [&]
        (
            const scalar a, const scalar rk, const scalar rkExact,
            const scalar rhoMix
        )
        {
            if (a > 1e-6) dr = max(dr, mag(rk - rkExact)/rkExact);
            dar = max(dar, a*mag(rk - rkExact)/rhoMix);
        };
        const scalarField& rho = s.rho().primitiveField();
        forAll(c.p, i)
        {
            // the mixture density of the phases
            const scalar rhoExact =
                nMat == 1 ? c.r2[i]
              : nMat == 2 ? c.alpha1[i]*c.r1[i] + (1 - c.alpha1[i])*c.r2[i]
              : c.alpha1[i]*c.r1[i] + c.alpha2[i]*c.r2[i]
              + (1 - c.alpha1[i] - c.alpha2[i])*c.r3[i];
            dm = max(dm, mag(rho[i] - rhoExact)/rhoExact);
            if (nMat == 1) continue;
            da = max(da, mag(s.alpha1Ptr()()[i] - c.alpha1[i]));
            phase(c.alpha1[i], s.rho1Ptr()()[i], c.r1[i], rhoExact);
            const scalar a2 = nMat == 3 ? c.alpha2[i] : 1 - c.alpha1[i];
            phase(a2, s.rho2Ptr()()[i], c.r2[i], rhoExact);
            if (nMat == 3)
            {
                da = max(da, mag(s.alpha2Ptr()()[i] - c.alpha2[i]));
                const scalar a3 = 1 - c.alpha1[i] - c.alpha2[i];
                phase(a3, s.rho3Ptr()()[i], c.r3[i], rhoExact);
            }
        }
        std::cout << "  " << nMat << " material(s), " << c.p.size()
            << " cells, p 1 MPa - 1 GPa: round trip max |dp|/p "
            << sci(dp) << " (tol 1e-9), |dU|/|U| " << sci(du)
            << " (tol 1e-12), |d alpha| " << sci(da)
            << " (tol 1e-14), |d rho_k|/rho_k " << sci(dr)
            << ", alpha_k |d rho_k|/rho " << sci(dar)
            << " (tol 1e-14), mixture density " << sci(dm)
            << " (tol 1e-14)" << std::endl;
        EXPECT_LT(dp, 1e-9);
        EXPECT_LT(du, 1e-12);
        EXPECT_LT(da, 1e-14);
        EXPECT_LT(dar, 1e-14);
        EXPECT_LT(dm, 1e-14);
    }
}


TEST(BlastFluidState, RoundTripOneMaterial)
{
    roundTrip(1, 11);
}


TEST(BlastFluidState, RoundTripTwoMaterials)
{
    roundTrip(2, 12);
}


TEST(BlastFluidState, RoundTripThreeMaterials)
{
    roundTrip(3, 13);
}


// A cell with negative internal energy and one with negative density:
// not fatal, exactly those two marked and false; fatal, a FatalError
// naming one of them; the state put back converts again
TEST(BlastFluidState, BadCells)
{
    const stateCase c(8, 2, 21, "stateTestBad");
    stateRun r(c.dir);
    blastFluidState& s = r.state;
    s.initialise(r.lowOrder, nullptr);

    scalarField& rhoE = s.rhoE().primitiveFieldRef();
    scalarField& rho = s.rho().primitiveFieldRef();
    const scalar rhoE13 = rhoE[13], rho40 = rho[40];
    rhoE[13] = -1e9;
    rho[40] = -1;
    s.invalidate();
    EXPECT_FALSE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
    EXPECT_FALSE(s.current());
    labelList marked;
    forAll(r.lowOrder, i)
    {
        if (r.lowOrder[i] > 0) marked.append(i);
    }
    std::cout << "  cells marked for a first-order retry: "
        << marked.size() << " (expected 2: 13 and 40)" << std::endl;
    ASSERT_EQ(marked.size(), 2);
    EXPECT_EQ(marked[0], 13);
    EXPECT_EQ(marked[1], 40);

    const std::string message = fatalConversion(s, r.lowOrder);
    // (the screening before the equation of state finds the negative
    // density first)
    EXPECT_TRUE
    (
        message.find("cell 13") != std::string::npos
     || message.find("cell 40") != std::string::npos
    );

    rhoE[13] = rhoE13;
    rho[40] = rho40;
    r.lowOrder = 0;
    EXPECT_TRUE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
    EXPECT_TRUE(s.current());
    EXPECT_LT(maxRelDiff(s.p().primitiveField(), c.p), 1e-9);
}


// Compressed detonation products (JWL, TNT, 1000 kg/m3, where the cold
// terms give pRef = 0.96 GPa): a cell of internal energy -2000 J/kg still
// has p > 0 and c^2 > 0, but no physical state has e <= 0; it is marked
// for a first-order retry (and only it: a cell of e = +1 J/kg is not),
// accepted once it is first order (what the flow gave it there), and not
// retried again in the steps after
TEST(BlastFluidState, NegativeEnergyRetried)
{
    const label n = 6, nc = n*n;
    const fileName dir = caseWithMaterials
    (
        n, "stateTestEnergy",
        "materials (products);\n"
        "products { equationOfState JWL; explosive TNT; }\n"
    );
    writeField
    (
        dir, "p", "volScalarField", "[1 -1 -2 0 0 0 0]",
        scalarField(nc, 1e9)
    );
    writeField
    (
        dir, "U", "volVectorField", "[0 1 -1 0 0 0 0]",
        vectorField(nc, vector(800, -300, 0))
    );
    writeField
    (
        dir, "rho", "volScalarField", "[1 -3 0 0 0 0 0]",
        scalarField(nc, 1000)
    );
    stateRun r(dir);
    blastFluidState& s = r.state;
    s.initialise(r.lowOrder, nullptr);
    ASSERT_TRUE(s.current());

    scalarField& rhoE = s.rhoE().primitiveFieldRef();
    const scalarField& rho = s.rho().primitiveField();
    const vectorField& rhoU = s.rhoU().primitiveField();
    const auto setE = [&](const label i, const scalar e)
    {
        rhoE[i] = rho[i]*e + 0.5*magSqr(rhoU[i])/rho[i];
    };
    setE(7, -2000);
    setE(11, 1);
    s.invalidate();
    EXPECT_FALSE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
    const scalar p7 = s.p()[7], c7 = s.c()[7];
    labelList marked;
    forAll(r.lowOrder, i)
    {
        if (r.lowOrder[i] > 0) marked.append(i);
    }
    std::cout << "  e = -2000 J/kg at 1000 kg/m3: p = " << sci(p7)
        << " Pa, c = " << c7 << " m/s; cells marked for a first-order "
        << "retry: " << marked.size() << " (expected 1: 7)" << std::endl;
    EXPECT_GT(p7, 0);
    EXPECT_GT(c7, 0);
    ASSERT_EQ(marked.size(), 1);
    EXPECT_EQ(marked[0], 7);

    // First order already: the state is accepted as it is
    EXPECT_TRUE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
    EXPECT_TRUE(s.current());
    EXPECT_GT(s.p()[7], 0);

    // Accepted without positive internal energy, the cell is not retried
    // in later steps (as a case that starts with such states is not)
    r.lowOrder = 0;
    s.invalidate();
    EXPECT_TRUE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
    EXPECT_EQ(sum(r.lowOrder), 0);

}


// The stop names what is wrong with the first bad cell: TNT products and
// air, one cell of products squeezed into 5 % of it (mass fraction 0.999,
// mixture 610 kg/m3, e = 8.6 J/kg, 960 m/s: p = 6.2e9 Pa but c^2 <= 0, the
// kind of state the full-resolution cylinder met), then one at negative
// pressure
TEST(BlastFluidState, StopNamesWhatIsWrong)
{
    const label n = 4, nc = n*n;
    const fileName dir = caseWithMaterials
    (
        n, "stateTestReason",
        "materials (products air);\n"
        "products { equationOfState JWL; explosive TNT; }\n"
        "air { equationOfState idealGas; gamma 1.4; Cv 718; }\n"
    );
    const auto scalars = [&](const scalar v) { return scalarField(nc, v); };
    writeField(dir, "p", "volScalarField", "[1 -1 -2 0 0 0 0]", scalars(1e7));
    writeField
    (
        dir, "U", "volVectorField", "[0 1 -1 0 0 0 0]",
        vectorField(nc, vector(862.26514, 429.16377, 0))
    );
    const char* dimless = "[0 0 0 0 0 0 0]";
    const char* dRho = "[1 -3 0 0 0 0 0]";
    writeField(dir, "alpha.products", "volScalarField", dimless, scalars(0.5));
    writeField(dir, "rho.products", "volScalarField", dRho, scalars(1000));
    writeField(dir, "rho.air", "volScalarField", dRho, scalars(10));
    stateRun r(dir);
    blastFluidState& s = r.state;
    s.initialise(r.lowOrder, nullptr);
    const auto stopMessage = [&]()
    {
        s.invalidate();
        return fatalConversion(s, r.lowOrder);
    };
    const label i = 5;
    scalarField& rho = s.rho().primitiveFieldRef();
    scalarField& rhoE = s.rhoE().primitiveFieldRef();
    const vectorField& rhoU = s.rhoU().primitiveField();
    const scalar rho0 = rho[i];
    const vector U = rhoU[i]/rho0;
    rho[i] = 610.04288;
    s.rhoU()[i] = rho[i]*U;
    s.alpha1Ptr()->primitiveFieldRef()[i] = 0.05;
    s.alphaRho1Ptr()->primitiveFieldRef()[i] = 0.999*rho[i];
    rhoE[i] = rho[i]*(8.64099 + 0.5*magSqr(U));
    const std::string noSound = stopMessage();
    EXPECT_NE(noSound.find("No sound speed"), std::string::npos);
    EXPECT_NE(noSound.find("in cell 5 "), std::string::npos);
    EXPECT_NE(noSound.find("non-physical state at time"), std::string::npos);
    EXPECT_GT(s.p()[i], 0);

    // Air at negative pressure (internal energy below zero)
    s.alpha1Ptr()->primitiveFieldRef()[i] = 0;
    s.alphaRho1Ptr()->primitiveFieldRef()[i] = 0;
    rho[i] = 1.2;
    s.rhoU()[i] = rho[i]*U;
    rhoE[i] = rho[i]*(-1e4 + 0.5*magSqr(U));
    const std::string negative = stopMessage();
    EXPECT_NE(negative.find("Negative or non-finite pressure"), std::string::npos);
    EXPECT_NE(negative.find("in cell 5 "), std::string::npos);
}


// primitivesOfCells on a random third of the cells after their state
// changed: every primitive bitwise that of the whole-mesh conversion
TEST(BlastFluidState, CellsAsWholeMesh)
{
    for (const label nMat : {1, 2, 3})
    {
        const stateCase c
        (
            8, nMat, 30 + nMat, "stateTestCells" + std::to_string(nMat)
        );
        stateRun r(c.dir);
        blastFluidState& s = r.state;
        s.initialise(r.lowOrder, nullptr);
        Random rnd(40 + nMat);
        DynamicList<label> cells;
        forAll(c.p, i)
        {
            if (rnd.sample01<scalar>() < 1.0/3)
            {
                cells.append(i);
                s.rhoE()[i] *= 1.1;
                s.rhoU()[i] *= 0.9;
            }
        }
        s.primitivesOfCells(cells, nullptr);
        const scalarField p(s.p().primitiveField());
        const vectorField U(s.U().primitiveField());
        const scalarField cs(s.c());
        ASSERT_TRUE(s.primitivesFromConservative(false, r.lowOrder, nullptr));
        label nDiff = 0;
        forAll(p, i)
        {
            if (p[i] != s.p()[i] || U[i] != s.U()[i] || cs[i] != s.c()[i])
            {
                ++nDiff;
            }
        }
        // Not fatal: a listed cell without a physical state (negative
        // density) makes it return false and leaves the primitives out of
        // date, instead of stopping the run
        const label badCell = cells[cells.size()/2];
        s.rho()[badCell] = -1;
        const bool converted = s.primitivesOfCells(cells, nullptr, false);
        std::cout << "  " << nMat << " material(s): " << cells.size()
            << " cells converted alone, " << nDiff
            << " primitives differing from the whole mesh's (expected 0);"
            << " with a bad listed cell, not fatal: returned " << converted
            << ", primitives current " << s.current() << " (expected 0 0)"
            << std::endl;
        EXPECT_GT(cells.size(), 10);
        EXPECT_EQ(nDiff, 0);
        EXPECT_FALSE(converted);
        EXPECT_FALSE(s.current());
    }
}


// Fields out of range as read: FatalIOError naming the field and the cell
TEST(BlastFluidState, InputOutOfRange)
{
    FatalIOError.throwExceptions();
    for (const bool pBad : {true, false})
    {
        const stateCase c
        (
            4, 2, 50, pBad ? "stateTestP" : "stateTestAlpha", pBad, !pBad
        );
        stateRun r(c.dir);
        std::string message;
        try
        {
            r.state.initialise(r.lowOrder, nullptr);
        }
        catch (const Foam::error& e)
        {
            message = e.message();
        }
        std::cout << "  " << (pBad ? "p = -1" : "alpha.water = 1.5")
            << " in cell 5: " << message.substr(0, 100) << std::endl;
        EXPECT_NE
        (
            message.find(pBad ? "p = -1" : "alpha.water = 1.5"),
            std::string::npos
        );
        EXPECT_NE(message.find("cell 5"), std::string::npos);
    }
    FatalIOError.dontThrowExceptions();
}


// The cut-cell step of the solver (blastFluidSolver::advance) on air at rest
// in a closed box (slip walls; fluid fraction and apertures 1): a state
// changed between steps so that a cell has no physical state (negative
// density, as a work correction or a vented pocket could leave it) is
// mixed with its gas neighbours at the step's start instead of stopping
// the run; the step then conserves mass and energy to round-off and every
// cell is physical. A step without such a cell mixes nothing
TEST(BlastFluidSolver, RepairsStateChangedBetweenSteps)
{
    const label n = 12, nc = n*n;
    const fileName dir = caseWithMaterials
    (
        n, "solverRepair", std::string("materials (air);\n") + materialDicts
    );
    writeField
    (
        dir, "p", "volScalarField", "[1 -1 -2 0 0 0 0]",
        scalarField(nc, 1e5)
    );
    writeField
    (
        dir, "U", "volVectorField", "[0 1 -1 0 0 0 0]",
        vectorField(nc, Zero)
    );
    writeField
    (
        dir, "rho", "volScalarField", "[1 -3 0 0 0 0 0]",
        scalarField(nc, 1.2)
    );
    blockMeshCase::timeAndMesh tm(dir);
    const fvMesh& mesh = tm.mesh;
    blastFluidSolver fluid(mesh);
    const scalarField phi(nc, 1);
    const surfaceScalarField aperture
    (
        IOobject("aperture", tm.runTime.timeName(), mesh),
        mesh,
        dimensionedScalar("one", dimless, 1.0)
    );
    fluid.enableCutCells(phi);
    const scalar dt = 0.5*fluid.maxDeltaT(0.5);
    const auto step = [&]()
    {
        fluid.setFluidFraction(phi, aperture);
        fluid.setEmbeddedBoundary(phi, aperture);
        return fluid.advance(dt, false);
    };
    ASSERT_TRUE(step());
    EXPECT_EQ(fluid.nRepaired(), 0);

    // An interior cell at negative density (its energy and momentum kept)
    const label bad = (n/2)*n + n/2;
    blastFluidState& s = fluid.stateRef();
    s.rho()[bad] = -0.1*s.rho()[bad];
    s.invalidate();
    const scalar m0 = fluid.totalMass(), E0 = fluid.totalEnergy();
    FatalError.throwExceptions();
    bool stopped = false, advanced = false;
    try
    {
        advanced = step();
    }
    catch (const Foam::error&)
    {
        stopped = true;
    }
    FatalError.dontThrowExceptions();
    const scalar dm = mag(fluid.totalMass() - m0)/m0;
    const scalar dE = mag(fluid.totalEnergy() - E0)/E0;
    const scalarField& rho = fluid.state().rho().primitiveField();
    const scalarField& p = fluid.state().p().primitiveField();
    std::cout << "    a cell at -0.12 kg/m3 between steps: stopped " << stopped
        << " (expected 0), cells mixed " << fluid.nRepaired()
        << " (expected 5: it and its 4 face neighbours), min density "
        << gMin(rho) << " kg/m3, min pressure " << gMin(p) << " Pa (> 0),"
        << " mass change " << sci(dm) << ", energy change " << sci(dE)
        << " (tolerances 1e-14)" << std::endl;
    EXPECT_FALSE(stopped);
    EXPECT_TRUE(advanced);
    EXPECT_EQ(fluid.nRepaired(), 5);
    EXPECT_GT(gMin(rho), 0);
    EXPECT_GT(gMin(p), 0);
    EXPECT_LT(dm, 1e-14);
    EXPECT_LT(dE, 1e-14);
}

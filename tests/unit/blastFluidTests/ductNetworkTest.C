// Unit tests of the gas in a network of narrow ducts (libblastFluid): the
// crack gas of issue 14, checked against exact solutions without a solid
#include <gtest/gtest.h>
#include "ductNetwork.H"
#include "exactRiemannSolver.H"
#include "IStringStream.H"
#include "mathematicalConstants.H"
#include <string>
#include <functional>
#include <cstdio>

using namespace Foam;

namespace
{
    dictionary dictOf(const std::string& text)
    {
        IStringStream is(text);
        return dictionary(is);
    }

    const char* airText =
        "materials (air); air { equationOfState idealGas; gamma 1.4; }";
    const char* productsAirText =
        "materials (products air);"
        "products { equationOfState JWL; explosive TNT; }"
        "air { equationOfState idealGas; gamma 1.4; }";

    void record(const char* key, const scalar v)
    {
        char buf[32];
        std::snprintf(buf, sizeof(buf), "%.4g", v);
        ::testing::Test::RecordProperty(key, buf);
    }

    // A straight duct along x of n control volumes over [0, L], width w
    // (per unit depth), closed ends; mouths at the ends if asked
    void straightDuct
    (
        ductNetwork& net, const label n, const scalar L, const scalar w,
        const bool mouths
    )
    {
        const label nf = n - 1 + (mouths ? 2 : 0);
        net.setSize(n, nf);
        ductNetwork::geometry& g = net.geom();
        const scalar dx = L/n;
        for (label i = 0; i < n; ++i)
        {
            g.V0[i] = g.V1[i] = w*dx;
            g.axis[i] = vector(1, 0, 0);
            g.wallArea[i] = 2*dx;
        }
        for (label f = 0; f < n - 1; ++f)
        {
            g.owner[f] = f;
            g.neighbour[f] = f + 1;
            g.Sf[f] = vector(w, 0, 0);
        }
        if (mouths)
        {
            g.owner[n - 1] = 0;
            g.neighbour[n - 1] = -1;
            g.Sf[n - 1] = vector(-w, 0, 0);
            g.owner[n] = n - 1;
            g.neighbour[n] = -1;
            g.Sf[n] = vector(w, 0, 0);
        }
    }

    // First x (linear between centres) where f crosses level, scanning
    // from the left; -1 if it never does
    scalar crossing(const scalarField& f, const scalar level, const scalar dx)
    {
        for (label i = 0; i + 1 < f.size(); ++i)
        {
            if ((f[i] - level)*(f[i + 1] - level) <= 0 && f[i] != f[i + 1])
            {
                const scalar s = (level - f[i])/(f[i + 1] - f[i]);
                return (i + 0.5 + s)*dx;
            }
        }
        return -1;
    }

    // Riemann problem at mid-duct: numerical versus exact wave positions
    // and star pressure; returns the worst position error over L
    void riemannAlongACrack
    (
        const std::string& mixtureText,
        const exactRiemannSolver::state& left,
        const exactRiemannSolver::state& right,
        const scalar tEnd,
        const char* tag
    )
    {
        blastMixture mix(dictOf(mixtureText));
        ductNetwork net(mix, dictOf("flux HLLC; RKorder 2;"));
        const label n = 800;
        const scalar L = 1, w = 1e-4, dx = L/n;
        straightDuct(net, n, L, w, false);
        for (label i = 0; i < n; ++i)
        {
            const bool l = i < n/2;
            const exactRiemannSolver::state& s = l ? left : right;
            net.setState(i, s.rho, Zero, s.p, l ? 1 : 0);
        }
        const equationOfState& eosL = mix.eos(0);
        const equationOfState& eosR = mix.eos(mix.twoPhase() ? 1 : 0);
        exactRiemannSolver rs(eosL, left, eosR, right);

        const scalar mass0 = net.mass(), energy0 = net.energy();
        scalar t = 0;
        label steps = 0;
        while (t < tEnd*(1 - 1e-12))
        {
            const scalar dt = min(net.maxDeltaT(0.5), tEnd - t);
            net.advance(dt);
            t += dt;
            ++steps;
        }

        // Exact profile at the centres, and the levels whose crossings
        // locate the shock (pressure halfway between p* and p_R), the
        // contact (density halfway across it) and the middle of the fan
        scalarField pEx(n), rhoEx(n);
        const scalar x0 = 0.5*L;
        for (label i = 0; i < n; ++i)
        {
            const exactRiemannSolver::state s =
                rs.sample(((i + 0.5)*dx - x0)/t);
            pEx[i] = s.p;
            rhoEx[i] = s.rho;
        }
        const scalar pShock = 0.5*(rs.pStar() + right.p);
        const scalar rhoContact = 0.5*(rs.rhoStarL() + rs.rhoStarR());
        const scalar pFan = 0.5*(rs.pStar() + left.p);
        const scalarField& p = net.p();
        const scalarField& rho = net.rho();
        // The contact: scan from the left for the star density level only
        // right of the fan
        const scalar xFanEx = crossing(pEx, pFan, dx);
        const scalar xFan = crossing(p, pFan, dx);
        auto rightOf = [&](const scalarField& f, const scalar level, const scalar xMin)
        {
            const label i0 = label(xMin/dx) + 2;
            scalarField part(SubList<scalar>(f, n - i0, i0));
            const scalar x = crossing(part, level, dx);
            return x < 0 ? x : x + i0*dx;
        };
        const scalar xMid = 0.5*(x0 + rs.uStar()*t + x0);
        const scalar xContactEx = rightOf(rhoEx, rhoContact, xFanEx);
        const scalar xContact = rightOf(rho, rhoContact, xFan);
        const scalar xShockEx = rightOf(pEx, pShock, xContactEx);
        const scalar xShock = rightOf(p, pShock, xContact);
        // Plateau: between contact and shock
        const label iPlateau = label(0.5*(xContactEx + xShockEx)/dx);
        const scalar pPlateau = p[iPlateau];
        (void)xMid;

        const scalar eFan = mag(xFan - xFanEx)/L;
        const scalar eContact = mag(xContact - xContactEx)/L;
        const scalar eShock = mag(xShock - xShockEx)/L;
        const scalar ePlateau = mag(pPlateau/rs.pStar() - 1);
        const scalar eMass = mag(net.mass() - mass0)/mass0;
        const scalar eEnergy = mag(net.energy() - energy0)/energy0;
        const std::string k(tag);
        record((k + "_steps").c_str(), steps);
        record((k + "_fanPositionErrorOverLength").c_str(), eFan);
        record((k + "_contactPositionErrorOverLength").c_str(), eContact);
        record((k + "_shockPositionErrorOverLength").c_str(), eShock);
        record((k + "_plateauPressureError").c_str(), ePlateau);
        record((k + "_massDrift").c_str(), eMass);
        record((k + "_energyDrift").c_str(), eEnergy);
        EXPECT_GT(xFan, 0);
        EXPECT_GT(xContact, 0);
        EXPECT_GT(xShock, 0);
        EXPECT_LT(eFan, 0.02);
        EXPECT_LT(eContact, 0.02);
        EXPECT_LT(eShock, 0.02);
        EXPECT_LT(ePlateau, 0.02);
        // Closed duct: mass and energy to round-off
        EXPECT_LT(eMass, 1e-13);
        EXPECT_LT(eEnergy, 1e-13);
    }
}


TEST(DuctNetwork, RiemannProblemAlongARigidCrackAir)
{
    // 10 bar against 1 bar, air
    riemannAlongACrack
    (
        airText, {10, 0, 1e6, 0}, {1.2, 0, 1e5, 1}, 4e-4, "air"
    );
}


TEST(DuctNetwork, RiemannProblemAlongARigidCrackProductsAir)
{
    // TNT products (100 kg/m3 at 50 MPa) against air at 1 bar
    riemannAlongACrack
    (
        productsAirText, {100, 0, 5e7, 0}, {1.2, 0, 1e5, 1}, 1e-4,
        "productsAir"
    );
}


namespace
{
    // A reservoir (p0, material-1 volume fraction a0) feeds a 1 m crack,
    // 2 mm wide, with wall friction f, that discharges into 0.05 p0; run to
    // a steady state. Returns the mass flow at the inlet (kg/s per metre),
    // and sets the flow at mid-duct, the net mass rate of the last 10 ms
    // and the mid-duct material-1 mass fraction
    scalar fannoRun
    (
        const std::string& mixtureText, const scalar f, const scalar a0,
        scalar& mMid, scalar& netRate, scalar& Y1Mid, label& steps
    )
    {
        const scalar L = 1, w = 2e-3, p0 = 5e5, rho0 = 5.0;
        blastMixture mix(dictOf(mixtureText));
        ductNetwork net
        (
            mix,
            dictOf("flux HLLC; RKorder 2; frictionFactor " + std::to_string(f) + ";")
        );
        const label n = 200;
        straightDuct(net, n, L, w, true);
        ductNetwork::plenumStates& pl = net.plenum();
        // Inlet: the reservoir; outlet: 0.05 p0 of the duct's first gas
        pl.rho[n - 1] = rho0; pl.p[n - 1] = p0;
        pl.alpha1[n - 1] = a0; pl.rho1[n - 1] = rho0; pl.rho2[n - 1] = rho0;
        pl.rho[n] = 0.05*rho0; pl.p[n] = 0.05*p0;
        pl.alpha1[n] = 0; pl.rho1[n] = 0.05*rho0; pl.rho2[n] = 0.05*rho0;
        for (label i = 0; i < n; ++i)
        {
            net.setState(i, 0.05*rho0, Zero, 0.05*p0, 0);
        }
        scalar t = 0, window = 0, windowMass = 0;
        steps = 0;
        const scalar tEnd = 0.06;
        while (t < tEnd)
        {
            const scalar dt = net.maxDeltaT(0.5);
            net.advance(dt);
            t += dt;
            ++steps;
            if (t > tEnd - 0.01)
            {
                window += dt;
                windowMass += net.mouthMass();
            }
        }
        netRate = windowMass/window;
        const ductNetwork::content c = net.contentOf(n/2);
        Y1Mid = mix.twoPhase() ? c.m1/c.m : 1;
        mMid = net.rho()[n/2]*net.U()[n/2].x()*w;
        return 0.5*(net.rho()[0]*net.U()[0].x() + net.rho()[1]*net.U()[1].x())*w;
    }
}


TEST(DuctNetwork, FannoFlowFromAReservoir)
{
    // The steady mass flow is set by Fanno choking,
    //     4 f L/D_h = (1 - M1^2)/(gamma M1^2)
    //               + (gamma + 1)/(2 gamma) ln[(gamma + 1) M1^2/(2 + (gamma - 1) M1^2)],
    // with D_h = 2 w for a slot and the inlet isentropic from the reservoir;
    // the same with the two-material gas carrying air only
    const scalar f = 0.005, L = 1, w = 2e-3, gamma = 1.4;
    const scalar p0 = 5e5, rho0 = 5.0;
    scalar mMid, netRate, Y1, mMid2, netRate2, Y12;
    label steps, steps2;
    const scalar mDuct = fannoRun(airText, f, 1, mMid, netRate, Y1, steps);
    const scalar mDuct2 =
        fannoRun(productsAirText, f, 0, mMid2, netRate2, Y12, steps2);

    // Fanno: solve for M1 by bisection on the subsonic branch
    const scalar target = 4*f*L/(2*w);
    auto fanno = [&](const scalar M)
    {
        const scalar M2 = M*M;
        return (1 - M2)/(gamma*M2)
          + (gamma + 1)/(2*gamma)*Foam::log((gamma + 1)*M2/(2 + (gamma - 1)*M2));
    };
    scalar lo = 1e-3, hi = 1;
    for (label k = 0; k < 200; ++k)
    {
        const scalar M = 0.5*(lo + hi);
        (fanno(M) > target ? lo : hi) = M;
    }
    const scalar M1 = 0.5*(lo + hi);
    const scalar c0 = Foam::sqrt(gamma*p0/rho0);
    const scalar T = 1 + 0.5*(gamma - 1)*M1*M1;
    const scalar rho1 = rho0*Foam::pow(T, -1/(gamma - 1));
    const scalar u1 = M1*c0/Foam::sqrt(T);
    const scalar mFanno = rho1*u1*w;

    const scalar eFanno = mag(mDuct/mFanno - 1);
    record("steps", steps);
    record("fannoInletMach", M1);
    record("fannoMassFlow_kg_per_s_m", mFanno);
    record("massFlowInlet", mDuct);
    record("massFlowMidDuct", mMid);
    record("relativeErrorVsFanno", eFanno);
    record("netMassRateLast10ms_over_flow", netRate/mFanno);
    record("twoMaterialGasAirOnly_massFlowOverOneMaterial_minus1", mDuct2/mDuct - 1);
    // Steady: in = out (the content no longer changes) and uniform flow
    EXPECT_LT(mag(netRate)/mFanno, 0.01);
    EXPECT_LT(mag(mMid/mDuct - 1), 0.01);
    EXPECT_LT(eFanno, 0.03);
    EXPECT_LT(mag(mDuct2/mDuct - 1), 1e-6);
    EXPECT_LT(mag(netRate2)/mFanno, 0.01);
}


TEST(DuctNetwork, MixedReservoirFillsTheCrackWithItsComposition)
{
    // A reservoir of TNT products and air (volume fraction 0.3 of
    // products, both at 5 kg/m3) feeds a crack first full of air: in the
    // steady state the crack carries the reservoir's mass fraction, and
    // the flow is steady
    scalar mMid, netRate, Y1;
    label steps;
    const scalar mDuct =
        fannoRun(productsAirText, 0.005, 0.3, mMid, netRate, Y1, steps);
    record("massFlowInlet", mDuct);
    record("midDuctProductsMassFraction", Y1);
    record("netMassRateLast10ms_over_flow", netRate/mDuct);
    EXPECT_LT(mag(Y1 - 0.3), 1e-3);
    EXPECT_LT(mag(mMid/mDuct - 1), 0.01);
    EXPECT_LT(mag(netRate)/mDuct, 0.01);
    EXPECT_GT(mDuct, 0);
}


namespace
{
    // Closed duct, uniform gas at rest, every volume grows linearly from
    // V0 to (1 + growth) V0 over tEnd (the walls moved apart); returns the
    // final pressure and the energy residual (gas change + wall work)
    // Pressure at density rho1 on the isentrope of a material through
    // (rho0, p0), integrated independently (de/drho = p/rho^2, RK4)
    scalar pOnIsentrope
    (
        const equationOfState& eos, const scalar rho0, const scalar p0,
        const scalar rho1
    )
    {
        scalar r = rho0, e = eos.e(rho0, p0);
        const label nr = 2000;
        const scalar h = (rho1 - rho0)/nr;
        auto dedr = [&](const scalar rr, const scalar ee)
        {
            return eos.p(rr, ee)/(rr*rr);
        };
        for (label k = 0; k < nr; ++k)
        {
            const scalar k1 = dedr(r, e);
            const scalar k2 = dedr(r + 0.5*h, e + 0.5*h*k1);
            const scalar k3 = dedr(r + 0.5*h, e + 0.5*h*k2);
            const scalar k4 = dedr(r + h, e + h*k3);
            e += h*(k1 + 2*k2 + 2*k3 + k4)/6;
            r += h;
        }
        return eos.p(rho1, e);
    }

    void expandClosedDuct
    (
        ductNetwork& net, const label n, const scalar rho0, const scalar p0,
        const scalar growth, const scalar tEnd, const label nSteps,
        const std::function<scalar(label)>& share,
        scalar& energyResidual, scalar& wallWork
    )
    {
        const scalar L = 0.1, w = 1e-4, dx = L/n;
        straightDuct(net, n, L, w, false);
        for (label i = 0; i < n; ++i)
        {
            net.setState(i, rho0, Zero, p0);
        }
        const scalar E0 = net.energy();
        wallWork = 0;
        ductNetwork::geometry& g = net.geom();
        const scalar dt = tEnd/nSteps;
        for (label s = 0; s < nSteps; ++s)
        {
            for (label i = 0; i < n; ++i)
            {
                const scalar r = growth*share(i);
                g.V0[i] = w*dx*(1 + r*s/nSteps);
                g.V1[i] = w*dx*(1 + r*(s + 1)/nSteps);
            }
            net.advance(dt);
            wallWork += net.wallWork();
        }
        energyResidual = mag(net.energy() - E0 + wallWork)/E0;
    }
}


TEST(DuctNetwork, GasInACrackOpeningFollowsTheIsentrope)
{
    // Uniform opening: every volume doubles; p = p0 (V0/V)^gamma for air,
    // and for TNT products the isentrope integrated independently
    // (de/drho = p/rho^2, RK4)
    for (const char* text : {airText, "materials (products);"
        "products { equationOfState JWL; explosive TNT; }"})
    {
        blastMixture mix(dictOf(text));
        ductNetwork net(mix, dictOf("RKorder 2;"));
        const bool air = mix.materials()[0] == "air";
        const scalar rho0 = air ? 10 : 500, p0 = air ? 1e6 : mix.p(1, 500, 500, 500*2e6);
        scalar residual, work;
        expandClosedDuct
        (
            net, 20, rho0, p0, 1.0, 1e-4, 400, [](label) { return 1.0; },
            residual, work
        );
        scalar pExact;
        if (air)
        {
            pExact = p0*Foam::pow(0.5, 1.4);
        }
        else
        {
            pExact = pOnIsentrope(mix.eos(0), rho0, p0, 0.5*rho0);
        }
        const scalar pEnd = net.p()[7];
        const scalar eP = mag(pEnd/pExact - 1);
        const std::string k(air ? "air" : "products");
        record((k + "_pressureOverIsentrope_minus1").c_str(), eP);
        record((k + "_energyChangePlusWallWork_overE0").c_str(), residual);
        record((k + "_wallWork_J_per_m").c_str(), work);
        EXPECT_LT(eP, 0.01);
        EXPECT_LT(residual, 1e-8);
        EXPECT_GT(work, 0);
    }
}


TEST(DuctNetwork, MixtureSqueezedInAGapFollowsEachMaterialsIsentrope)
{
    // One closed gap of TNT products and air (volume fraction a0, both
    // materials at rho0 and p0) squeezed to 1/s of its volume and opened
    // again. With the Kapila term each material follows its own isentrope
    // to the common pressure (air: p0 (rho2/rho0)^1.4; products: RK4 on
    // their JWL isentrope), and the round trip returns to p0; frozen alpha
    // (kapilaTerm false, the control) compresses both materials s-fold and
    // misses both isentropes. Two parameter sets
    blastMixture mix(dictOf(productsAirText));
    const scalar w = 1e-4, L = 0.01;
    const label nSteps = 400;
    struct caseSet { scalar rho0, p0, a0, s; };
    for (const caseSet& c : {caseSet{100, 1e8, 0.5, 10}, caseSet{20, 1e7, 0.9, 20}})
    {
        scalar airErr[2], productsErr[2], roundTrip[2], energyResidual[2];
        for (const bool kapila : {true, false})
        {
            ductNetwork net
            (
                mix,
                dictOf(std::string("RKorder 2; kapilaTerm ")
                  + (kapila ? "true;" : "false;"))
            );
            straightDuct(net, 1, L, w, false);
            net.setState(0, c.rho0, Zero, c.p0, c.a0);
            const scalar V0 = w*L, E0 = net.energy();
            const scalar m1 = c.a0*c.rho0*V0, m2 = (1 - c.a0)*c.rho0*V0;
            ductNetwork::geometry& g = net.geom();
            scalar work = 0;
            auto move = [&](const scalar from, const scalar to)
            {
                for (label k = 0; k < nSteps; ++k)
                {
                    g.V0[0] = V0*(from + (to - from)*k/nSteps);
                    g.V1[0] = V0*(from + (to - from)*(k + 1)/nSteps);
                    net.advance(1e-7);
                    work += net.wallWork();
                }
            };
            move(1, 1/c.s);
            const label k = kapila ? 0 : 1;
            const scalar p = net.p()[0], a = net.alpha1()[0], V = V0/c.s;
            const scalar rho1 = m1/(a*V), rho2 = m2/((1 - a)*V);
            airErr[k] = mag(p/(c.p0*Foam::pow(rho2/c.rho0, 1.4)) - 1);
            productsErr[k] =
                mag(p/pOnIsentrope(mix.eos(0), c.rho0, c.p0, rho1) - 1);
            move(1/c.s, 1);
            roundTrip[k] = mag(net.p()[0]/c.p0 - 1);
            energyResidual[k] = mag(net.energy() - E0 + work)/E0;
            std::printf
            (
                ">> a0 %g, rho0 %g, p0 %g, squeezed %gx, kapilaTerm %s: "
                "p/p0 %.4g, alpha1 %.4g; |p/p_isentrope - 1| air %.2e, "
                "products %.2e; reopened |p/p0 - 1| %.2e; |dE + W|/E0 %.1e"
                " (tolerances 1e-3, 1e-3, 1e-3, 1e-10)\n",
                c.a0, c.rho0, c.p0, c.s, kapila ? "true" : "false", p/c.p0,
                a, airErr[k], productsErr[k], roundTrip[k], energyResidual[k]
            );
        }
        EXPECT_LT(airErr[0], 1e-3);
        EXPECT_LT(productsErr[0], 1e-3);
        EXPECT_LT(roundTrip[0], 1e-3);
        EXPECT_LT(energyResidual[0], 1e-10);
        // The control: frozen alpha is far off an isentrope
        EXPECT_GT(max(airErr[1], productsErr[1]), 0.05);
        if (c.a0 == 0.5)
        {
            record("air_pressureOverIsentrope_minus1", airErr[0]);
            record("products_pressureOverIsentrope_minus1", productsErr[0]);
            record("frozenAlpha_air_pressureOverIsentrope_minus1", airErr[1]);
        }
    }
}


TEST(DuctNetwork, NonUniformOpeningPaysItsWorkExactly)
{
    // Only the left half opens: the gas flows, and gas energy change plus
    // wall work is zero to round-off
    blastMixture mix(dictOf(airText));
    ductNetwork net(mix, dictOf("RKorder 3;"));
    scalar residual, work;
    expandClosedDuct
    (
        net, 40, 10, 1e6, 0.5, 2e-4, 400,
        [](label i) { return i < 20 ? 1.0 : 0.0; }, residual, work
    );
    scalar uMax = 0;
    forAll(net.U(), i) uMax = max(uMax, mag(net.U()[i]));
    record("energyChangePlusWallWork_overE0", residual);
    record("maxSpeed_m_per_s", uMax);
    EXPECT_GT(uMax, 1);
    EXPECT_LT(residual, 1e-12);
}


TEST(DuctNetwork, UniformGasAtRestStaysAtRestInATaperedNetworkWithAJunction)
{
    // Three tapered ducts meeting at a junction void (no axis): walls
    // close every volume, so uniform pressure gives no flow
    blastMixture mix(dictOf(airText));
    ductNetwork net(mix, dictOf(""));
    const label nArm = 10, n = 3*nArm + 1;
    net.setSize(n, 3*nArm);
    ductNetwork::geometry& g = net.geom();
    const scalar dx = 0.01;
    label f = 0;
    for (label a = 0; a < 3; ++a)
    {
        const scalar th = 2*constant::mathematical::pi*a/3 + 0.3;
        const vector e(Foam::cos(th), Foam::sin(th), 0);
        for (label k = 0; k < nArm; ++k)
        {
            // Width from 1 mm at the junction to 0.2 mm at the tip
            const label i = 1 + a*nArm + k;
            const scalar w0 = 1e-3 - 8e-5*k, w1 = w0 - 8e-5;
            g.V0[i] = g.V1[i] = 0.5*(w0 + w1)*dx;
            g.axis[i] = e;
            g.wallArea[i] = 2*dx;
            g.owner[f] = k == 0 ? 0 : i - 1;
            g.neighbour[f] = i;
            g.Sf[f] = w0*e;
            ++f;
        }
    }
    g.V0[0] = g.V1[0] = 1e-6;
    for (label i = 0; i < n; ++i)
    {
        net.setState(i, 10, Zero, 1e6);
    }
    for (label s = 0; s < 200; ++s)
    {
        net.advance(net.maxDeltaT(0.5));
    }
    scalar uMax = 0, dp = 0;
    forAll(net.U(), i)
    {
        uMax = max(uMax, mag(net.U()[i]));
        dp = max(dp, mag(net.p()[i]/1e6 - 1));
    }
    record("maxSpeed_m_per_s", uMax);
    record("maxRelativePressureChange", dp);
    EXPECT_LT(uMax, 1e-9);
    EXPECT_LT(dp, 1e-13);
}


TEST(DuctNetwork, BadEntriesAreRefused)
{
    blastMixture mix(dictOf(airText));
    EXPECT_THROW(ductNetwork(mix, dictOf("RKorder 4;")), Foam::error);
    EXPECT_THROW(ductNetwork(mix, dictOf("frictionFactor -1;")), Foam::error);
    EXPECT_THROW(ductNetwork(mix, dictOf("flux nonsense;")), Foam::error);
    blastMixture two(dictOf(productsAirText));
    EXPECT_THROW(ductNetwork(two, dictOf("kapilaTerm maybe;")), Foam::error);
}


// ************************************************************************* //

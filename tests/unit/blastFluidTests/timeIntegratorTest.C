// Unit tests of blastTimeIntegrator (libblastFluid): the Shu-Osher tables of
// RKorder 1, 2, 3 against the consistency and order conditions of their
// Butcher form, SSP (non-negative coefficients), the low-storage weights
// the solvers use against the table, and the stage combination on
// u' = -u against the Taylor polynomial of the scheme's order, the stages
// on a nonlinear problem against the textbook SSP RK2 / RK3 formulas, the
// error ratio under halving dt (2^order) and the refusal of a bad RKorder
#include <gtest/gtest.h>
#include "blastTimeIntegrator.H"
#include "IStringStream.H"
#include "scalarField.H"
#include <cmath>
#include <cstdio>

using namespace Foam;

namespace
{
    //- A figure for RecordProperty with its significant digits (to_string
    //  prints six decimals only)
    std::string figure(const double x)
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", x);
        return buf;
    }

    blastTimeIntegrator integrator(const label order)
    {
        IStringStream is("RKorder " + std::to_string(order) + ";");
        return blastTimeIntegrator(dictionary(is));
    }

    //- Butcher form of the Shu-Osher table: u(i) = u0 + dt sum_j A_ij L(u(j))
    //  with A_ij = sum_k alpha_ik A_kj + beta_ij (A_0j = 0); row n is b
    void butcher
    (
        const blastTimeIntegrator& rk,
        double A[4][4]
    )
    {
        const label n = rk.nStages();
        for (label i = 0; i <= n; ++i)
        {
            for (label j = 0; j <= n; ++j) A[i][j] = 0;
        }
        for (label i = 1; i <= n; ++i)
        {
            for (label j = 0; j < i; ++j)
            {
                double a = rk.beta(i, j);
                for (label k = 0; k < i; ++k) a += rk.alpha(i, k)*A[k][j];
                A[i][j] = a;
            }
        }
    }
}


class TimeIntegratorTest : public ::testing::TestWithParam<int> {};

TEST_P(TimeIntegratorTest, ConsistencyAndOrderConditions)
{
    const label p = GetParam();
    const blastTimeIntegrator rk = integrator(p);
    EXPECT_EQ(rk.order(), p);
    EXPECT_EQ(rk.nStages(), p);
    const label n = rk.nStages();

    double A[4][4];
    butcher(rk, A);
    // b_j = A[n][j], c_j = sum_k A[j][k]
    double c[4] = {0, 0, 0, 0};
    for (label j = 0; j < n; ++j)
    {
        for (label k = 0; k < j; ++k) c[j] += A[j][k];
    }
    double sb = 0, sbc = 0, sbc2 = 0, sbAc = 0;
    for (label j = 0; j < n; ++j)
    {
        const double b = A[n][j];
        sb += b;
        sbc += b*c[j];
        sbc2 += b*c[j]*c[j];
        double Ac = 0;
        for (label k = 0; k < j; ++k) Ac += A[j][k]*c[k];
        sbAc += b*Ac;
        // The weight of stage j's residual in the result, as the solvers
        // accumulate it (ductNetwork, the outflow, the wall work)
        EXPECT_NEAR(rk.resultWeight(j), b, 1e-15);
    }
    ::testing::Test::RecordProperty("sumB", figure(sb));
    EXPECT_NEAR(sb, 1, 1e-15);
    if (p >= 2)
    {
        EXPECT_NEAR(sbc, 0.5, 1e-15);
    }
    if (p >= 3)
    {
        EXPECT_NEAR(sbc2, 1.0/3.0, 1e-15);
        EXPECT_NEAR(sbAc, 1.0/6.0, 1e-15);
    }
    // Not of a higher order than it claims (each is optimal for its order)
    if (p == 1)
    {
        EXPECT_GT(mag(sbc - 0.5), 0.1);
    }
    if (p == 2)
    {
        EXPECT_GT(mag(sbc2 - 1.0/3.0), 0.1);
    }
}

TEST_P(TimeIntegratorTest, SSPAndLowStorageWeights)
{
    const blastTimeIntegrator rk = integrator(GetParam());
    for (label i = 1; i <= rk.nStages(); ++i)
    {
        double sum = 0;
        for (label k = 0; k < i; ++k)
        {
            EXPECT_GE(rk.alpha(i, k), 0);
            EXPECT_GE(rk.beta(i, k), 0);
            // beta_ik > 0 needs alpha_ik > 0 (SSP with CFL coefficient 1)
            if (rk.beta(i, k) > 0)
            {
                EXPECT_GE(rk.alpha(i, k), rk.beta(i, k));
            }
            sum += rk.alpha(i, k);
        }
        EXPECT_EQ(sum, 1) << "stage " << i;
        // u(i) = a u(0) + b (u(i-1) + dt L(u(i-1)))
        const label s = i - 1;
        EXPECT_EQ(rk.b(s), rk.alpha(i, s));
        EXPECT_EQ(rk.b(s), rk.beta(i, s));
        EXPECT_EQ(rk.a(s), s == 0 ? 0 : rk.alpha(i, 0));
        EXPECT_EQ(rk.a(s) + rk.b(s), 1);
    }
}

TEST_P(TimeIntegratorTest, LinearDecayMatchesTaylorPolynomial)
{
    // u' = -u over one step dt: the p-stage SSP scheme of order p gives the
    // Taylor polynomial of exp(-dt) to degree p (linear problem)
    const label p = GetParam();
    const blastTimeIntegrator rk = integrator(p);
    const double dt = 0.1;
    const scalarField u0(2, 1.0);
    scalarField u(u0), R(2);
    double accumulated = 0;
    for (label s = 0; s < rk.nStages(); ++s)
    {
        R = -u;
        rk.accumulate(s, accumulated, dt*R[0]);
        rk.combine(s, dt, u0, u, R);
    }
    double taylor = 0, term = 1;
    for (label k = 0; k <= p; ++k)
    {
        taylor += term;
        term *= -dt/(k + 1);
    }
    ::testing::Test::RecordProperty("u", figure(u[0]));
    EXPECT_NEAR(u[0], taylor, 1e-15);
    EXPECT_EQ(u[0], u[1]);
    // A quantity accumulated like the state (the outflow) is the state's
    // change: u = u0 + sum of the weighted dt L
    EXPECT_NEAR(accumulated, u[0] - 1, 1e-15);
}

namespace
{
    //- A nonlinear right-hand side (u' = -u^2 + sin u)
    double L(const double u)
    {
        return -u*u + std::sin(u);
    }

    //- One step of the integrator's stages on u' = L(u) (as the solvers
    //  run them: combine with the step's start kept)
    double rkStep(const blastTimeIntegrator& rk, const double u0, const double dt)
    {
        const scalarField start(1, u0);
        scalarField u(start), R(1);
        for (label s = 0; s < rk.nStages(); ++s)
        {
            R[0] = L(u[0]);
            rk.combine(s, dt, start, u, R);
        }
        return u[0];
    }

    //- u' = -u from u(0) = 1 to t = 1 in n steps: the error at t = 1
    double decayError(const blastTimeIntegrator& rk, const label n)
    {
        const double dt = 1.0/n;
        scalarField u(1, 1.0), start(1), R(1);
        for (label step = 0; step < n; ++step)
        {
            start = u;
            for (label s = 0; s < rk.nStages(); ++s)
            {
                R = -u;
                rk.combine(s, dt, start, u, R);
            }
        }
        return mag(u[0] - std::exp(-1.0));
    }
}


TEST(TimeIntegratorTest, StagesMatchTextbookSSPFormulas)
{
    // Shu & Osher (1988), Gottlieb & Shu (1998) in their Shu-Osher form
    // and, independently, in their Butcher form (k_i the stage slopes)
    const double u0 = 0.7, dt = 0.13;
    {
        const double u1 = u0 + dt*L(u0);
        const double shuOsher = 0.5*u0 + 0.5*(u1 + dt*L(u1));
        const double k1 = L(u0), k2 = L(u0 + dt*k1);
        const double butcher = u0 + 0.5*dt*(k1 + k2);
        const double u = rkStep(integrator(2), u0, dt);
        ::testing::Test::RecordProperty("RK2", figure(u));
        EXPECT_EQ(u, shuOsher);
        EXPECT_NEAR(u, butcher, 1e-15);
    }
    {
        const double u1 = u0 + dt*L(u0);
        const double u2 = 0.75*u0 + 0.25*(u1 + dt*L(u1));
        const double shuOsher = u0/3 + 2.0/3.0*(u2 + dt*L(u2));
        const double k1 = L(u0);
        const double k2 = L(u0 + dt*k1);
        const double k3 = L(u0 + 0.25*dt*(k1 + k2));
        const double butcher = u0 + dt/6*(k1 + k2 + 4*k3);
        const double u = rkStep(integrator(3), u0, dt);
        ::testing::Test::RecordProperty("RK3", figure(u));
        // 2/3 is 1 - 1/3 in the table (one unit in the last place apart)
        EXPECT_NEAR(u, shuOsher, 1e-15);
        EXPECT_NEAR(u, butcher, 1e-15);
    }
    {
        const double u = rkStep(integrator(1), u0, dt);
        EXPECT_EQ(u, u0 + dt*L(u0));
    }
}


TEST_P(TimeIntegratorTest, ErrorRatioUnderHalvingIsTwoToTheOrder)
{
    // u' = -u to t = 1 with 20 and 40 steps: the global error of a scheme
    // of order p falls by 2^p
    const label p = GetParam();
    const blastTimeIntegrator rk = integrator(p);
    const double e20 = decayError(rk, 20), e40 = decayError(rk, 40);
    const double ratio = e20/e40;
    ::testing::Test::RecordProperty("error20", figure(e20));
    ::testing::Test::RecordProperty("ratio", figure(ratio));
    const double expected = std::pow(2.0, p);
    EXPECT_GT(ratio, 0.9*expected);
    EXPECT_LT(ratio, 1.1*expected);
}

INSTANTIATE_TEST_SUITE_P(All, TimeIntegratorTest, ::testing::Values(1, 2, 3));


TEST(TimeIntegratorTest, DefaultIsTwoAndBadValuesAreRefused)
{
    EXPECT_EQ(blastTimeIntegrator(dictionary()).order(), 2);
    for (const int bad : {0, 4, -1})
    {
        try
        {
            integrator(bad);
            ADD_FAILURE() << "RKorder " << bad << " accepted";
        }
        catch (const Foam::IOerror& err)
        {
            const std::string msg(err.message());
            EXPECT_NE(msg.find("'RKorder'"), std::string::npos) << msg;
        }
    }
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "blastTimeIntegrator.H"
#include "error.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::blastTimeIntegrator::table&
Foam::blastTimeIntegrator::tableOf(const label order)
{
    // Shu & Osher (1988): rows are stages, columns the earlier stages.
    // 2/3 is written 1 - 1/3 so that the stage's weights sum to one exactly
    // in floating point (2.0/3.0 is one unit in the last place lower) and
    // b_s is bitwise 1 - a_s, as the solvers had it
    static const table RK1 =
    {
        1,
        {{1, 0, 0}, {0, 0, 0}, {0, 0, 0}},
        {{1, 0, 0}, {0, 0, 0}, {0, 0, 0}}
    };
    static const table RK2 =
    {
        2,
        {{1, 0, 0}, {0.5, 0.5, 0}, {0, 0, 0}},
        {{1, 0, 0}, {0, 0.5, 0}, {0, 0, 0}}
    };
    static const table RK3 =
    {
        3,
        {{1, 0, 0}, {0.75, 0.25, 0}, {1.0/3.0, 0, 1 - 1.0/3.0}},
        {{1, 0, 0}, {0, 0.25, 0}, {0, 0, 1 - 1.0/3.0}}
    };
    return order == 1 ? RK1 : order == 2 ? RK2 : RK3;
}


Foam::label Foam::blastTimeIntegrator::readOrder(const dictionary& dict)
{
    const label order = dict.getOrDefault<label>("RKorder", 2);
    if (order < 1 || order > 3)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'RKorder' must be 1, 2 or 3, got " << order
            << exit(FatalIOError);
    }
    return order;
}


void Foam::blastTimeIntegrator::setWeights()
{
    // The solvers keep the step's start and the present stage only: each
    // stage may use u(0) and the stage before it, and the latter only
    // through its Euler update (alpha_{i,i-1} = beta_{i,i-1})
    const table& t = table_;
    for (label s = 0; s < t.nStages; ++s)
    {
        bool lowStorage = t.alpha[s][s] == t.beta[s][s];
        scalar sum = 0;
        for (label k = 0; k <= s; ++k)
        {
            sum += t.alpha[s][k];
            if (k < s && t.beta[s][k] != 0) lowStorage = false;
            if (k > 0 && k < s && t.alpha[s][k] != 0) lowStorage = false;
        }
        if (!lowStorage || mag(sum - 1) > 1e-15)
        {
            FatalErrorInFunction
                << "SSP RK" << order_ << ": stage " << s + 1 << " of the"
                << " coefficient table is not of the consistent low-storage"
                << " form" << abort(FatalError);
        }
        a_[s] = s == 0 ? 0 : t.alpha[s][0];
        b_[s] = t.alpha[s][s];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::blastTimeIntegrator::blastTimeIntegrator(const dictionary& dict)
:
    order_(readOrder(dict)),
    table_(tableOf(order_))
{
    setWeights();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::blastTimeIntegrator::resultWeight(const label s) const
{
    scalar w = b_[s];
    for (label k = s + 1; k < nStages(); ++k)
    {
        w *= b_[k];
    }
    return w;
}


// ************************************************************************* //

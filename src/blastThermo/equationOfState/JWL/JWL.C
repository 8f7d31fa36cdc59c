/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "JWL.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace equationsOfState
{
    defineTypeNameAndDebug(JWL, 0);
    addToRunTimeSelectionTable(equationOfState, JWL, dictionary);
}
}

const Foam::wordList Foam::equationsOfState::JWL::presets
({
    "TNT", "PETN", "CompB", "HMX"
});


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    // LLNL Explosives Handbook values (model.md section 3):
    // rho0 kg/m3, A B GPa, R1 R2 omega, E0 GPa, D m/s, PCJ GPa;
    // unreacted explosive (Murnaghan, see JWL.H): c0 m/s, s (Us = c0 + s up)
    struct jwlPreset
    {
        const char* name;
        double rho0, A, B, R1, R2, omega, E0, D, PCJ, c0, s;
    };

    const jwlPreset presetTable[] =
    {
        {"TNT",  1630, 371.2, 3.231, 4.15, 0.95, 0.30, 7.0, 6930, 21.0,
            2390, 2.05},
        {"PETN", 1770, 617.1, 16.926, 4.40, 1.20, 0.25, 10.1, 8300, 33.5,
            2420, 2.48},
        {"CompB", 1717, 524.2, 7.678, 4.20, 1.10, 0.34, 8.5, 7980, 29.5,
            3030, 1.73},
        {"HMX",  1891, 778.3, 7.071, 4.20, 1.00, 0.30, 10.5, 9110, 42.0,
            2900, 2.06}
    };
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationsOfState::JWL::JWL
(
    const word& name,
    const dictionary& dict
)
:
    mieGruneisenEOS<JWL>(name, dict),
    rho0_(0), A_(0), B_(0), R1_(0), R2_(0), omega_(0), E0_(0), D_(0), PCJ_(0),
    rhoSmall_(0)
{
    checkEntries
    (
        dict,
        wordList
        ({
            "explosive", "rho0", "A", "B", "R1", "R2", "omega", "E0", "D", "PCJ",
            "unreacted"
        })
    );

    word explosive;
    const jwlPreset* found = nullptr;
    if (dict.readIfPresent("explosive", explosive))
    {
        for (const jwlPreset& row : presetTable)
        {
            if (explosive == row.name) found = &row;
        }
        if (!found)
        {
            FatalIOErrorInFunction(dict)
                << "Unknown explosive '" << explosive << "' for material "
                << name << ". Presets: " << presets << exit(FatalIOError);
        }
        rho0_ = found->rho0;
        A_ = found->A*1e9;
        B_ = found->B*1e9;
        R1_ = found->R1;
        R2_ = found->R2;
        omega_ = found->omega;
        E0_ = found->E0*1e9;
        D_ = found->D;
        PCJ_ = found->PCJ*1e9;

        // Every coefficient may be overridden
        dict.readIfPresent("rho0", rho0_);
        dict.readIfPresent("A", A_);
        dict.readIfPresent("B", B_);
        dict.readIfPresent("R1", R1_);
        dict.readIfPresent("R2", R2_);
        dict.readIfPresent("omega", omega_);
        dict.readIfPresent("E0", E0_);
        dict.readIfPresent("D", D_);
        dict.readIfPresent("PCJ", PCJ_);
    }
    else
    {
        rho0_ = dict.get<scalar>("rho0");
        A_ = dict.get<scalar>("A");
        B_ = dict.get<scalar>("B");
        R1_ = dict.get<scalar>("R1");
        R2_ = dict.get<scalar>("R2");
        omega_ = dict.get<scalar>("omega");
        E0_ = dict.get<scalar>("E0");
        D_ = dict.getOrDefault<scalar>("D", 0);
        PCJ_ = dict.getOrDefault<scalar>("PCJ", 0);
    }

    const char* keys[] = {"rho0", "R1", "R2", "omega", "E0"};
    const scalar values[] = {rho0_, R1_, R2_, omega_, E0_};
    for (int i = 0; i < 5; ++i)
    {
        if (!(values[i] > 0))
        {
            FatalIOErrorInFunction(dict)
                << "JWL material " << name << ": entry '" << keys[i]
                << "' must be strictly positive, got " << values[i]
                << exit(FatalIOError);
        }
    }
    if (A_ < 0 || B_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "JWL material " << name << ": A and B must be >= 0, got A "
            << A_ << " B " << B_ << exit(FatalIOError);
    }

    rhoSmall_ = 1e-15*rho0_;
    readUnreacted(dict, found ? found->c0 : 0, found ? found->s : 0);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::equationsOfState::JWL::readUnreacted
(
    const dictionary& dict,
    const scalar c0,
    const scalar s
)
{
    const bool preset = c0 > 0;
    if (!preset && !dict.found("unreacted"))
    {
        return;
    }
    // The unreacted explosive has the JWL's rho0 and q = E0/rho0; the
    // preset's stiffness (K0 = rho0 c0^2 with the rho0 in use, n = 4 s - 1)
    // unless given
    const dictionary& u = dict.subOrEmptyDict("unreacted");
    for (const entry& e : u)
    {
        const word& key = e.keyword();
        if (key != "K0" && key != "n" && key != "Gamma" && key != "p0")
        {
            FatalIOErrorInFunction(u)
                << "JWL material " << name_ << ": unknown entry 'unreacted."
                << key << "'. Valid: K0 n Gamma p0 (rho0 and q = E0/rho0"
                << " are the JWL's)" << exit(FatalIOError);
        }
    }
    const scalar K0 =
        preset ? u.getOrDefault<scalar>("K0", rho0_*sqr(c0)) : u.get<scalar>("K0");
    const scalar n =
        preset ? u.getOrDefault<scalar>("n", 4*s - 1) : u.get<scalar>("n");
    unreacted_.reset
    (
        new Murnaghan
        (
            name_ + ".unreacted", u, rho0_, K0, n,
            u.getOrDefault<scalar>("Gamma", 1.0), E0_/rho0_,
            u.getOrDefault<scalar>("p0", 101325)
        )
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::equationsOfState::Murnaghan&
Foam::equationsOfState::JWL::unreacted() const
{
    if (!unreacted_.valid())
    {
        FatalErrorInFunction
            << "JWL material " << name_ << " has no unreacted explosive:"
            << " give an explosive preset or an 'unreacted' dictionary"
            << " (K0, n, Gamma)" << exit(FatalError);
    }
    return unreacted_();
}


void Foam::equationsOfState::JWL::chapmanJouguet
(
    const scalar p0,
    scalar& DCJ,
    scalar& pCJ,
    scalar& rhoCJ
) const
{
    // Hugoniot e - e0 = (p + p0)/2 (v0 - v) with p = omega e/v + pRef:
    // explicit in p. D^2 = (p - p0)/(rho0^2 (v0 - v)) is unimodal in
    // V = v/v0 on (0.5, 1): golden-section search for its minimum
    const scalar v0 = 1/rho0_, e0 = E0_/rho0_, w = omega_;
    auto hugoniot = [&](const scalar V)
    {
        const scalar v = V*v0;
        return
            (w/v*e0 + w*p0*(v0 - v)/(2*v) + pRefI(rho0_/V))
           /(1 - w*(v0 - v)/(2*v));
    };
    auto D2 = [&](const scalar V)
    {
        return (hugoniot(V) - p0)/(sqr(rho0_)*(v0 - V*v0));
    };
    const scalar g = 0.5*(sqrt(5.0) - 1);
    scalar a = 0.5, b = 0.999;
    scalar x1 = b - g*(b - a), x2 = a + g*(b - a);
    scalar f1 = D2(x1), f2 = D2(x2);
    for (label it = 0; it < 200 && b - a > 1e-13; ++it)
    {
        if (f1 < f2)
        {
            b = x2; x2 = x1; f2 = f1;
            x1 = b - g*(b - a); f1 = D2(x1);
        }
        else
        {
            a = x1; x1 = x2; f1 = f2;
            x2 = a + g*(b - a); f2 = D2(x2);
        }
    }
    const scalar V = 0.5*(a + b);
    DCJ = sqrt(D2(V));
    pCJ = hugoniot(V);
    rhoCJ = rho0_/V;
}


void Foam::equationsOfState::JWL::write(Ostream& os) const
{
    os  << name_ << ": JWL rho0 " << rho0_ << " A " << A_ << " B " << B_
        << " R1 " << R1_ << " R2 " << R2_ << " omega " << omega_
        << " E0 " << E0_ << " (constant-volume explosion pressure "
        << pCV() << " Pa)" << nl;
    if (unreacted_.valid())
    {
        os  << "    ";
        unreacted_->write(os);
    }
}


// ************************************************************************* //

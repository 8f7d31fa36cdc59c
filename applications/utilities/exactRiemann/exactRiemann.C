/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    exactRiemann

Description
    Writes the exact solution of a 1D Riemann problem (general equations of
    state: each side one material of constant/thermophysicalProperties) at
    the cell centres of the mesh, for the selected times, to
    postProcessing/exactRiemann/<time>/exact.dat with columns
        x  rho  u  p  side(0 left material, 1 right material)
    and prints p*, u*, the star densities and the wave-front positions.

    Dictionary system/exactRiemannDict:
    \verbatim
        x0      0.5;            // initial discontinuity (along direction)
        direction (1 0 0);
        left    { material products; rho 1630; u 0; p 8.38e9; }
        right   { material air;      rho 1.2;  u 0; p 1e5; }
    \endverbatim
    Instead of p, a side may give e (specific internal energy).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "caseChecks.H"
#include "timeSelector.H"
#include "exactRiemannSolver.H"
#include "OFstream.H"
#include "IOmanip.H"
#include <cmath>

using namespace Foam;

exactRiemannSolver::state readState
(
    const dictionary& dict,
    const PtrList<equationOfState>& eos,
    const wordList& names,
    label& index
)
{
    const word material(dict.get<word>("material"));
    index = names.find(material);
    if (index < 0)
    {
        FatalIOErrorInFunction(dict)
            << "Material '" << material << "' not in the materials "
            << names << " of constant/thermophysicalProperties"
            << exit(FatalIOError);
    }
    exactRiemannSolver::state s;
    s.rho = dict.get<scalar>("rho");
    s.u = dict.get<scalar>("u");
    // (before the equation of state sees it: a density <= 0 can trap)
    if (!(s.rho > 0 && std::isfinite(s.rho)))
    {
        FatalIOErrorInFunction(dict)
            << "entry 'rho' is " << s.rho << "; the density must be > 0"
            << exit(FatalIOError);
    }
    const word pEntry(dict.found("e") ? "e" : "p");
    if (pEntry == "e")
    {
        s.p = eos[index].p(s.rho, dict.get<scalar>("e"));
    }
    else
    {
        s.p = dict.get<scalar>("p");
    }
    s.side = 0;

    // A state the solver cannot start from (its iteration would diverge
    // or trap): name the entry
    const char* bad =
        !(s.rho > 0 && std::isfinite(s.rho)) ? "rho"
      : !std::isfinite(s.u) ? "u"
      : !std::isfinite(s.p) ? pEntry.c_str()
      : !(eos[index].c2(s.rho, s.p) > 0) ? pEntry.c_str()
      : nullptr;
    if (bad)
    {
        FatalIOErrorInFunction(dict)
            << "entry '" << bad << "' of the state '" << dict.dictName()
            << "': not a valid state of material '" << material << "' (rho "
            << s.rho << ", u " << s.u << ", p " << s.p << "): rho must be"
            << " positive and the squared sound speed positive, all finite"
            << exit(FatalIOError);
    }
    return s;
}


int main(int argc, char *argv[])
{
    argList::addNote("Exact Riemann solution (general EOS) at cell centres");
    timeSelector::addOptions();
    #include "setRootCase.H"
    #include "createTime.H"
    instantList timeDirs = timeSelector::select0(runTime, args);
    #include "createMesh.H"

    IOdictionary thermo
    (
        IOobject
        (
            "thermophysicalProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const wordList names(thermo.get<wordList>("materials"));
    PtrList<equationOfState> eos(names.size());
    forAll(names, i)
    {
        eos.set(i, equationOfState::New(names[i], thermo.subDict(names[i])));
    }

    IOdictionary dict
    (
        IOobject
        (
            "exactRiemannDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    caseChecks::checkInput(dict);
    const scalar x0 = dict.get<scalar>("x0");
    vector dir = dict.getOrDefault<vector>("direction", vector(1, 0, 0));
    dir /= mag(dir);
    label iL = 0, iR = 0;
    const exactRiemannSolver::state L =
        readState(dict.subDict("left"), eos, names, iL);
    const exactRiemannSolver::state R =
        readState(dict.subDict("right"), eos, names, iR);

    const exactRiemannSolver solver(eos[iL], L, eos[iR], R);

    Info<< setprecision(10)
        << "Exact Riemann solution: p* = " << solver.pStar()
        << " u* = " << solver.uStar()
        << " rho*L = " << solver.rhoStarL()
        << " rho*R = " << solver.rhoStarR() << nl
        << "    left front speed " << solver.leftFrontSpeed()
        << ", right front speed " << solver.rightFrontSpeed() << endl;

    forAll(timeDirs, timei)
    {
        runTime.setTime(timeDirs[timei], timei);
        const scalar t = runTime.value();
        const fileName dir0
        (
            runTime.globalPath()/"postProcessing"/"exactRiemann"
           /runTime.timeName()
        );
        mkDir(dir0);
        OFstream os(dir0/"exact.dat");
        os.precision(15);
        os  << "# x rho u p side  (p* " << solver.pStar() << " u* "
            << solver.uStar() << " leftFront "
            << x0 + solver.leftFrontSpeed()*t << " contact "
            << x0 + solver.uStar()*t << " rightFront "
            << x0 + solver.rightFrontSpeed()*t << ")" << nl;
        const vectorField& C = mesh.C();
        forAll(C, i)
        {
            const scalar x = C[i] & dir;
            exactRiemannSolver::state s;
            if (t > 0)
            {
                s = solver.sample((x - x0)/t);
            }
            else
            {
                s = (x < x0 ? L : R);
                s.side = (x < x0 ? 0 : 1);
            }
            os  << x << ' ' << s.rho << ' ' << s.u << ' ' << s.p << ' '
                << s.side << nl;
        }
        Info<< "Time " << runTime.timeName() << ": wrote " << os.name()
            << endl;
    }

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
-------------------------------------------------------------------------------
Application
    setCharge

Description
    Places explosive charges in the constant-volume explosion state (products
    at rho0, e = E0/rho0, at rest) into the fields of the start time of a
    two-material jwlIbFoam case, and reports the mass and energy of each
    charge (in the mesh volume: per unit depth of a 2D mesh, the wedge's
    share of an axisymmetric one).

    The products are the first material of constant/thermophysicalProperties
    and must use the JWL equation of state (rho0, E0). The fields already in
    the start time (p, U, alpha.<m1>, rho.<m1>, rho.<m2>) are the ambient.
    A cell covered by the fraction f (sub-sampled on nSample points per
    solved direction of its bounding box) gets, conserving mass and energy,
        alpha = f + (1 - f) alpha_a,  alpha rho1 = f rho0 + (1-f) alpha_a rho1_a,
        rho e = f E0 + (1 - f) (rho e)_a
    and the equilibrium pressure of the mixture rule.

    Dictionary system/setChargeDict:
    \verbatim
        nSample     8;                      // sub-samples per direction
        charges
        (
            box      { min (0 0 0); max (0.1 0.1 1); }
            circle   { centre (0 0 0); radius 0.05; axis (0 0 1); }
            cylinder { point1 (0 0 0); point2 (0 0 0.2); radius 0.02; }
            sphere   { centre (0 0 0); radius 0.05; }
        );
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "caseChecks.H"
#include "blastMixture.H"
#include "JWL.H"
#include "boundBox.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- A charge shape: bounding box and inside test
class chargeShape
{
    word type_;
    vector a_, b_, axis_;
    scalar radius_;

public:

    chargeShape(const word& type, const dictionary& dict)
    :
        type_(type), a_(Zero), b_(Zero), axis_(0, 0, 1), radius_(0)
    {
        if (type == "box")
        {
            a_ = dict.get<vector>("min");
            b_ = dict.get<vector>("max");
        }
        else if (type == "circle" || type == "sphere")
        {
            a_ = dict.get<vector>("centre");
            radius_ = dict.get<scalar>("radius");
            axis_ = dict.getOrDefault<vector>("axis", vector(0, 0, 1));
            if (!(mag(axis_) > 0))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'axis' must be a non-zero vector"
                    << exit(FatalIOError);
            }
            axis_ /= mag(axis_);
        }
        else if (type == "cylinder")
        {
            a_ = dict.get<vector>("point1");
            b_ = dict.get<vector>("point2");
            radius_ = dict.get<scalar>("radius");
            if (!(mag(b_ - a_) > 0))
            {
                FatalIOErrorInFunction(dict)
                    << "Entries 'point1' and 'point2' must differ"
                    << exit(FatalIOError);
            }
        }
        else
        {
            FatalIOErrorInFunction(dict)
                << "Unknown charge shape '" << type
                << "'. Valid: box circle cylinder sphere"
                << exit(FatalIOError);
        }
        if (type != "box" && !(radius_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'radius' must be > 0" << exit(FatalIOError);
        }
    }

    const word& type() const { return type_; }

    bool inside(const point& x) const
    {
        if (type_ == "box")
        {
            return
                x.x() >= a_.x() && x.x() <= b_.x()
             && x.y() >= a_.y() && x.y() <= b_.y()
             && x.z() >= a_.z() && x.z() <= b_.z();
        }
        if (type_ == "sphere")
        {
            return magSqr(x - a_) <= sqr(radius_);
        }
        if (type_ == "circle")
        {
            const vector d = x - a_;
            return magSqr(d - (d & axis_)*axis_) <= sqr(radius_);
        }
        // cylinder
        const vector ax = b_ - a_;
        const scalar L = mag(ax);
        const vector n = ax/L;
        const vector d = x - a_;
        const scalar s = d & n;
        return s >= 0 && s <= L && magSqr(d - s*n) <= sqr(radius_);
    }
};

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Place explosive charges in the constant-volume explosion state"
    );
    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    IOdictionary thermo
    (
        IOobject
        (
            "thermophysicalProperties", runTime.constant(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    const blastMixture mixture(thermo);
    if (!mixture.twoPhase())
    {
        FatalIOErrorInFunction(thermo)
            << "setCharge needs two materials (products first) in 'materials'"
            << exit(FatalIOError);
    }
    const auto* jwl =
        dynamic_cast<const equationsOfState::JWL*>(&mixture.eos(0));
    if (!jwl)
    {
        FatalIOErrorInFunction(thermo)
            << "entry 'materials' " << mixture.materials()
            << ": the first material ('" << mixture.materials()[0]
            << "') must be the detonation products (equationOfState JWL);"
            << " list the products first" << exit(FatalIOError);
    }
    const scalar rho0 = jwl->rho0();
    const scalar E0 = jwl->E0();
    const scalar aMin = mixture.alphaMin();

    IOdictionary dict
    (
        IOobject
        (
            "setChargeDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    caseChecks::checkInput(dict);
    const label nSample = dict.getOrDefault<label>("nSample", 8);
    if (nSample < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nSample' must be >= 1" << exit(FatalIOError);
    }

    // Each charge keeps its dictionary, named after setChargeDict, so that
    // errors name the file, the charge and its line
    PtrList<chargeShape> charges;
    PtrList<dictionary> chargeDicts;
    {
        // A charge's entry given twice is an error, as in the file's own
        // dictionaries (checkInput)
        const entry::inputMode oldMode = entry::globalInputMode;
        entry::globalInputMode = entry::inputMode::ERROR;
        const PtrList<entry> entries(dict.lookup("charges"));
        entry::globalInputMode = oldMode;
        if (entries.empty())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'charges' lists no charge" << exit(FatalIOError);
        }
        charges.setSize(entries.size());
        chargeDicts.setSize(entries.size());
        forAll(entries, i)
        {
            if (!entries[i].isDict())
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'charges': each charge is 'shape { ... }'"
                    << exit(FatalIOError);
            }
            chargeDicts.set(i, new dictionary(dict, entries[i].dict()));
            chargeDicts[i].name() =
                dict.objectPath() + ".charges." + entries[i].keyword();
            caseChecks::readNaming
            (
                chargeDicts[i],
                [&]()
                {
                    charges.set
                    (
                        i,
                        new chargeShape(entries[i].keyword(), chargeDicts[i])
                    );
                }
            );
        }
    }

    const word& m1 = mixture.materials()[0];
    const word& m2 = mixture.materials()[1];
    auto io = [&](const word& name)
    {
        return IOobject
        (
            name, runTime.timeName(), mesh,
            IOobject::MUST_READ, IOobject::AUTO_WRITE
        );
    };
    volScalarField p(io("p"), mesh);
    volVectorField U(io("U"), mesh);
    volScalarField alpha(io("alpha." + m1), mesh);
    volScalarField rho1(io("rho." + m1), mesh);
    volScalarField rho2(io("rho." + m2), mesh);

    // Solved directions: sample only those
    const Vector<label>& solD = mesh.solutionD();
    const pointField& pts = mesh.points();
    const scalarField& V = mesh.V();

    scalarList chargeMass(charges.size(), scalar(0));
    labelList nFull(charges.size(), label(0));
    labelList nPartial(charges.size(), label(0));
    scalar totalMass = 0;

    forAll(V, celli)
    {
        const boundBox bb(pts, mesh.cellPoints()[celli], false);
        const label ns[3] =
        {
            solD[0] > 0 ? nSample : 1,
            solD[1] > 0 ? nSample : 1,
            solD[2] > 0 ? nSample : 1
        };
        label nIn = 0, nTot = 0;
        labelList hits(charges.size(), label(0));
        for (label i = 0; i < ns[0]; ++i)
        for (label j = 0; j < ns[1]; ++j)
        for (label k = 0; k < ns[2]; ++k)
        {
            const point x
            (
                bb.min().x() + (i + 0.5)/ns[0]*bb.span().x(),
                bb.min().y() + (j + 0.5)/ns[1]*bb.span().y(),
                bb.min().z() + (k + 0.5)/ns[2]*bb.span().z()
            );
            ++nTot;
            forAll(charges, c)
            {
                if (charges[c].inside(x))
                {
                    ++nIn;
                    ++hits[c];
                    break;
                }
            }
        }
        if (nIn == 0) continue;

        const scalar f = scalar(nIn)/nTot;
        forAll(charges, c)
        {
            if (hits[c])
            {
                chargeMass[c] += scalar(hits[c])/nTot*V[celli]*rho0;
                (hits[c] == nTot ? nFull[c] : nPartial[c])++;
            }
        }
        totalMass += f*V[celli]*rho0;

        // Ambient state of the cell
        const scalar aA = alpha[celli];
        const scalar r1A = rho1[celli], r2A = rho2[celli];
        const scalar rhoA = aA*r1A + (1 - aA)*r2A;
        const scalar rhoeA = mixture.rhoe(aA, r1A, r2A, p[celli]);

        // Mixed state conserving mass and energy
        scalar a = min(max(f + (1 - f)*aA, aMin), 1 - aMin);
        const scalar m1c = f*rho0 + (1 - f)*aA*r1A;
        const scalar r1 = m1c/a;
        const scalar r2 = (f < 1) ? r2A : rho0;
        const scalar rho = a*r1 + (1 - a)*r2;
        const scalar rhoe = f*E0 + (1 - f)*rhoeA;

        alpha[celli] = a;
        rho1[celli] = r1;
        rho2[celli] = r2;
        p[celli] = mixture.p(a, r1, r2, rhoe);
        U[celli] = (1 - f)*rhoA*U[celli]/rho;
    }

    reduce(totalMass, sumOp<scalar>());
    forAll(charges, c)
    {
        reduce(chargeMass[c], sumOp<scalar>());
        reduce(nFull[c], sumOp<label>());
        reduce(nPartial[c], sumOp<label>());
        Info<< "Charge " << c << " (" << charges[c].type() << "): "
            << nFull[c] << " cells covered, " << nPartial[c]
            << " partially; mass " << chargeMass[c] << " kg, energy "
            << chargeMass[c]/rho0*E0 << " J" << endl;
    }
    // A charge that covers no cell is a mistake (outside the mesh, or too
    // small for nSample): stop before anything is written
    forAll(charges, c)
    {
        if (nFull[c] + nPartial[c] == 0)
        {
            FatalIOErrorInFunction(chargeDicts[c])
                << "Charge " << c << " (" << charges[c].type()
                << ") in entry 'charges' covers no cell of the mesh (bounds "
                << mesh.bounds() << "): check its position and size, or"
                << " raise 'nSample'" << exit(FatalIOError);
        }
    }

    Info<< "Explosive " << m1 << ": rho0 " << rho0 << " kg/m3, E0 " << E0
        << " J/m3, constant-volume explosion pressure " << jwl->pCV()
        << " Pa" << nl
        << "Total charge mass " << totalMass << " kg (in the mesh volume"
        << (mesh.nSolutionD() < 3 ? "; 2D: per mesh depth/wedge share" : "")
        << ")" << endl;

    p.write();
    U.write();
    alpha.write();
    rho1.write();
    rho2.write();

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

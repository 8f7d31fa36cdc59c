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
    Places explosive charges (and, before them, regions filled with another
    material, e.g. a water gap) into the fields of the start time of a
    two- or three-material jwlIbFoam case, and reports the mass and energy of each
    charge (in the mesh volume: per unit depth of a 2D mesh, the wedge's
    share of an axisymmetric one). A charge starts either in the
    constant-volume explosion state (products at rho0, e = E0/rho0, at rest;
    the default) or, with 'initiationTime', as unreacted explosive that a
    programmed burn (programmedBurn, doc/programmedBurn.md) converts to
    products when the detonation front arrives: lighting time
        t_b = t0 + |x - primer|/D    (no primer: t_b = t0 in the charge)
    at the cell centre, burn time tau_b = w dx/D (dx: the smallest extent
    of the cell in the solved directions, w = burnWidth cells), written as
    the fields lightingTime and burnTime (cells outside programmed-burn
    charges: tau_b = 0, burnt).

    The products are the first material of constant/thermophysicalProperties
    and must use the JWL equation of state (rho0, E0). The fields already in
    the start time (p, U, alpha.<m1>, rho.<m1>, rho.<m2>; three materials
    also alpha.<m2>, rho.<m3>) are the ambient.

    Fills (optional entry 'fills', the same shapes as the charges, applied
    first, each over the ambient and the fills before it): material m at
    density rho_F (entry 'rho', default the cell's rho.<m>) and the cell's
    pressure p_a, at rest. A cell covered by the fraction g gets, conserving
    mass,
        alpha_m = g + (1 - g) alpha_m,a,   alpha_j = (1 - g) alpha_j,a,
        alpha_m rho_m = g rho_F + (1 - g) alpha_m,a rho_m,a,
    every other alpha floored at alphaMin (the products' trace stays
    alphaMin), the floor taken from alpha_m, the momentum of the ambient
    kept, and the pressure p_a: with ideal and stiffened gases (Gamma, pRef
    independent of the density) this is the energy-conserving mix
        rho e = g (p_a - pRef_m)/Gamma_m + (1 - g) (rho e)_a,
    exactly but for the traces floored at alphaMin (and a trace's density,
    rho_F in a fully covered cell): taken at p_a too. (Mixed by energy
    instead, a water fill's pInf energy, 7.8e8 J/m3 at 1 atm, carried by
    1e-6 traces, put the water 0.3-16 kPa above 1 atm.) A charge placed in
    a fill replaces it where it covers (with three materials by the same
    rule, the products at rho0 and, conserving energy, rho e = E0; with two
    materials the charge rule above, unchanged).
    A cell covered by the fraction f (sub-sampled on nSample points per
    solved direction of its bounding box) gets, conserving mass,
        alpha = f + (1 - f) alpha_a,  alpha rho1 = f rho0 + (1-f) alpha_a rho1_a,
    and, constant-volume charges, conserving energy
        rho e = f E0 + (1 - f) (rho e)_a
    and the equilibrium pressure of the mixture rule; programmed-burn
    charges keep the ambient pressure (the unreacted explosive at rho0 holds
    E0 in its internal energy, Murnaghan). A cell may not hold charges of
    both kinds.

    Dictionary system/setChargeDict:
    \verbatim
        nSample     8;                      // sub-samples per direction
        burnWidth   2;                      // programmed burn: cells the
                                            // burn front spreads over (> 0)
        fills                               // optional, before the charges
        (
            circle { centre (0 0 0); radius 0.015; material water;
                     rho 1000; }            // rho: optional (kg/m3)
        );
        charges
        (
            box      { min (0 0 0); max (0.1 0.1 1); }
            circle   { centre (0 0 0); radius 0.05; axis (0 0 1); }
            cylinder { point1 (0 0 0); point2 (0 0 0.2); radius 0.02; }
            sphere
            {
                centre (0 0 0); radius 0.05;
                explosive products;         // optional: the explosive
                                            // material (the first one)
                initiationTime 1e-5;        // programmed burn from t0 (s)
                primer (0 0 0);             // optional primer point in the
                                            // charge (else the whole charge
                                            // is lit at t0: plan view)
                detonationVelocity 6930;    // optional, default the JWL's D
            }
        );
    \endverbatim

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "caseChecks.H"
#include "blastMixture.H"
#include "JWL.H"
#include "boundBox.H"
#include "programmedBurn.H"

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

    //- The entries of the shape
    wordList entries() const
    {
        if (type_ == "box") return wordList({"min", "max"});
        if (type_ == "cylinder")
        {
            return wordList({"point1", "point2", "radius"});
        }
        return wordList({"centre", "radius", "axis"});
    }

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



//- How a charge starts: constant-volume explosion or programmed burn
class chargeInitiation
{
    bool burn_;
    scalar t0_, D_;
    bool hasPrimer_;
    point primer_;

public:

    //- Read and check the entries of a charge's dictionary
    chargeInitiation
    (
        const dictionary& dict,
        const chargeShape& shape,
        const blastMixture& mixture,
        const equationsOfState::JWL& jwl,
        const scalar startTime
    )
    :
        burn_(dict.found("initiationTime")),
        t0_(0), D_(jwl.D()), hasPrimer_(dict.found("primer")),
        primer_(Zero)
    {
        const word m1 = mixture.materials()[0];
        const word explosive(dict.getOrDefault<word>("explosive", m1));
        if (explosive != m1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'explosive' " << explosive << ": the explosive"
                << " is the first material of thermophysicalProperties, "
                << m1 << " (one explosive per case)" << exit(FatalIOError);
        }
        if (!burn_)
        {
            for (const char* key : {"primer", "detonationVelocity"})
            {
                if (dict.found(key))
                {
                    FatalIOErrorInFunction(dict)
                        << "Entry '" << key << "' without 'initiationTime':"
                        << " a programmed burn needs its initiation time"
                        << " (a charge without it starts in the"
                        << " constant-volume explosion state)"
                        << exit(FatalIOError);
                }
            }
            return;
        }
        readBurn(dict, shape, mixture, jwl, startTime);
    }

    void readBurn
    (
        const dictionary& dict,
        const chargeShape& shape,
        const blastMixture& mixture,
        const equationsOfState::JWL& jwl,
        const scalar startTime
    )
    {
        if (!mixture.canBurn())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'initiationTime': the explosive "
                << mixture.materials()[0] << " has no unreacted state (give"
                << " it an explosive preset or an 'unreacted' dictionary in"
                << " constant/thermophysicalProperties)" << exit(FatalIOError);
        }
        t0_ = dict.get<scalar>("initiationTime");
        if (!(t0_ >= startTime))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'initiationTime' " << t0_ << " must be >= the start"
                << " time " << startTime << exit(FatalIOError);
        }
        D_ = dict.getOrDefault<scalar>("detonationVelocity", jwl.D());
        if (!(D_ > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'detonationVelocity' must be > 0, got " << D_
                << " (no default: the JWL material " << mixture.materials()[0]
                << " gives no D)" << exit(FatalIOError);
        }
        if (hasPrimer_)
        {
            primer_ = dict.get<point>("primer");
            if (!shape.inside(primer_))
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'primer' " << primer_ << " lies outside the "
                    << shape.type() << " charge" << exit(FatalIOError);
            }
        }
    }

    bool burn() const { return burn_; }
    scalar D() const { return D_; }

    //- Lighting time at x
    scalar lightingTime(const point& x) const
    {
        return hasPrimer_ ? t0_ + mag(x - primer_)/D_ : t0_;
    }

    //- Description for the log
    void report(Ostream& os) const
    {
        if (!burn_)
        {
            os  << "constant-volume explosion state";
            return;
        }
        os  << "programmed burn from t0 = " << t0_ << " s, D = " << D_
            << " m/s, ";
        if (hasPrimer_) os << "primer " << primer_;
        else os << "the whole charge lit at t0";
    }
};



//- Sample the bounding box of a cell: the number of points in each charge
//  (the first charge a point lies in) and the number of points
label sampleCell
(
    const boundBox& bb,
    const Vector<label>& solD,
    const label nSample,
    const PtrList<chargeShape>& charges,
    labelList& hits
)
{
    const label ns[3] =
    {
        solD[0] > 0 ? nSample : 1,
        solD[1] > 0 ? nSample : 1,
        solD[2] > 0 ? nSample : 1
    };
    hits = 0;
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
        forAll(charges, c)
        {
            if (charges[c].inside(x))
            {
                ++hits[c];
                break;
            }
        }
    }
    return ns[0]*ns[1]*ns[2];
}


//- Smallest extent of a bounding box in the solved directions
scalar cellSize(const boundBox& bb, const Vector<label>& solD)
{
    scalar dx = GREAT;
    for (direction d = 0; d < 3; ++d)
    {
        if (solD[d] > 0) dx = min(dx, bb.span()[d]);
    }
    return dx;
}


//- The entries of a list of shapes 'key' of setChargeDict (a shape's entry
//  given twice is an error, as in the file's own dictionaries: checkInput)
PtrList<entry> readShapeList(const dictionary& dict, const word& key)
{
    const entry::inputMode oldMode = entry::globalInputMode;
    entry::globalInputMode = entry::inputMode::ERROR;
    PtrList<entry> entries(dict.lookup(key));
    entry::globalInputMode = oldMode;
    return entries;
}


//- A fill: a region of one material at the ambient pressure
struct fillSpec
{
    label material;
    //- Density of the material (< 0: the cell's own)
    scalar rho;
};


//- Read the fills of setChargeDict (none if the entry is absent), each
//  with its dictionary named after the file (errors name file and fill)
void readFills
(
    const IOdictionary& dict,
    const blastMixture& mixture,
    PtrList<chargeShape>& shapes,
    List<fillSpec>& specs,
    PtrList<dictionary>& fillDicts
)
{
    if (!dict.found("fills"))
    {
        return;
    }
    const PtrList<entry> entries(readShapeList(dict, "fills"));
    shapes.setSize(entries.size());
    specs.setSize(entries.size());
    fillDicts.setSize(entries.size());
    forAll(entries, i)
    {
        if (!entries[i].isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'fills': each fill is 'shape { ... material m; }'"
                << exit(FatalIOError);
        }
        fillDicts.set(i, new dictionary(dict, entries[i].dict()));
        dictionary& fd = fillDicts[i];
        fd.name() = dict.objectPath() + ".fills." + entries[i].keyword();
        caseChecks::readNaming
        (
            fd,
            [&]()
            {
                shapes.set(i, new chargeShape(entries[i].keyword(), fd));
                wordList valid(shapes[i].entries());
                valid.append(wordList({"material", "rho"}));
                for (const entry& e : fd)
                {
                    if (!valid.found(e.keyword()))
                    {
                        FatalIOErrorInFunction(fd)
                            << "Unknown entry '" << e.keyword() << "' of a "
                            << shapes[i].type() << " fill. Valid: "
                            << flatOutput(valid) << exit(FatalIOError);
                    }
                }
                const word m(fd.get<word>("material"));
                specs[i].material = mixture.index(m);
                if (specs[i].material < 0)
                {
                    FatalIOErrorInFunction(fd)
                        << "Entry 'material' " << m << " of a fill is not"
                        << " one of the materials "
                        << flatOutput(mixture.materials())
                        << " of constant/thermophysicalProperties"
                        << exit(FatalIOError);
                }
                specs[i].rho = fd.getOrDefault<scalar>("rho", -1);
                if (fd.found("rho") && !(specs[i].rho > 0))
                {
                    FatalIOErrorInFunction(fd)
                        << "Entry 'rho' of a fill must be > 0, got "
                        << specs[i].rho << exit(FatalIOError);
                }
            }
        );
    }
}


//- Read the charges of setChargeDict: shape and initiation, each with its
//  dictionary named after the file so that errors name file and charge
void readCharges
(
    const IOdictionary& dict,
    const blastMixture& mixture,
    const equationsOfState::JWL& jwl,
    const scalar startTime,
    PtrList<chargeShape>& charges,
    PtrList<chargeInitiation>& initiations,
    PtrList<dictionary>& chargeDicts
)
{
    const PtrList<entry> entries(readShapeList(dict, "charges"));
    if (entries.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'charges' lists no charge" << exit(FatalIOError);
    }
    charges.setSize(entries.size());
    initiations.setSize(entries.size());
    chargeDicts.setSize(entries.size());
    const wordList initiationKeys
    ({
        "explosive", "initiationTime", "primer", "detonationVelocity"
    });
    forAll(entries, i)
    {
        if (!entries[i].isDict())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'charges': each charge is 'shape { ... }'"
                << exit(FatalIOError);
        }
        chargeDicts.set(i, new dictionary(dict, entries[i].dict()));
        dictionary& cd = chargeDicts[i];
        cd.name() = dict.objectPath() + ".charges." + entries[i].keyword();
        caseChecks::readNaming
        (
            cd,
            [&]()
            {
                charges.set(i, new chargeShape(entries[i].keyword(), cd));
                wordList valid(charges[i].entries());
                valid.append(initiationKeys);
                for (const entry& e : cd)
                {
                    if (!valid.found(e.keyword()))
                    {
                        FatalIOErrorInFunction(cd)
                            << "Unknown entry '" << e.keyword() << "' of a "
                            << charges[i].type() << " charge. Valid: "
                            << flatOutput(valid) << exit(FatalIOError);
                    }
                }
                initiations.set
                (
                    i,
                    new chargeInitiation
                    (
                        cd, charges[i], mixture, jwl, startTime
                    )
                );
            }
        );
    }
}


//- Read the top-level entries of setChargeDict
void readControls(const dictionary& dict, label& nSample, scalar& burnWidth)
{
    caseChecks::checkInput(dict);
    for (const entry& e : dict)
    {
        const word& key = e.keyword();
        if (key != "FoamFile" && key != "nSample" && key != "charges"
         && key != "burnWidth" && key != "fills")
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << key << "'. Valid entries: nSample"
                << " burnWidth fills charges" << exit(FatalIOError);
        }
    }
    nSample = dict.getOrDefault<label>("nSample", 8);
    if (nSample < 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'nSample' must be >= 1" << exit(FatalIOError);
    }
    burnWidth = dict.getOrDefault<scalar>("burnWidth", 2);
    if (!(burnWidth > 0) || burnWidth > 100)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'burnWidth' must be in (0, 100] cells, got "
            << burnWidth << exit(FatalIOError);
    }
}


//- The explosive: the first material, a JWL
const equationsOfState::JWL& explosiveOf
(
    const blastMixture& mixture,
    const dictionary& thermo
)
{
    if (!mixture.multiPhase())
    {
        FatalIOErrorInFunction(thermo)
            << "setCharge needs two or three materials (products first) in"
            << " 'materials'" << exit(FatalIOError);
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
    return *jwl;
}


//- The JWL set's CJ point; a burn velocity off D_CJ warned about
void reportCJ
(
    const equationsOfState::JWL& jwl,
    const PtrList<chargeInitiation>& initiations,
    const PtrList<dictionary>& chargeDicts
)
{
    scalar DCJ = 0, pCJ = 0, rhoCJ = 0;
    jwl.chapmanJouguet(101325, DCJ, pCJ, rhoCJ);
    Info<< "JWL CJ point (from 1 atm): D_CJ " << DCJ << " m/s, p_CJ " << pCJ
        << " Pa, rho_CJ " << rhoCJ << " kg/m3" << endl;
    forAll(initiations, c)
    {
        const scalar D = initiations[c].D();
        if (initiations[c].burn() && mag(D/DCJ - 1) > 0.005)
        {
            WarningInFunction
                << chargeDicts[c].name() << ": detonation velocity " << D
                << " m/s is " << 100*(D/DCJ - 1) << " % off the CJ velocity"
                << " of the JWL set, " << DCJ << " m/s: "
                << (D > DCJ
                    ? "the burn drives a weak detonation (front pressure"
                      " below p_CJ)"
                    : "the products outrun the burn (the front is not"
                      " a steady detonation)")
                << nl << "    (set detonationVelocity " << DCJ
                << " for a CJ detonation)" << endl;
        }
    }
}

//- Mass and cells of each charge
struct chargeTally
{
    scalarList mass;
    labelList nFull, nPartial;

    explicit chargeTally(const label n)
    :
        mass(n, scalar(0)), nFull(n, label(0)), nPartial(n, label(0))
    {}
};


//- Add a cell's samples (hits of nTot per charge) to the tally; returns
//  the number of samples in programmed-burn charges and sets the earliest
//  lighting time among those (tbCell, with its burn time tauCell)
label tallyCell
(
    const label celli,
    const boundBox& bb,
    const label nTot,
    const labelList& hits,
    const PtrList<chargeInitiation>& initiations,
    const scalar burnWidth,
    const fvMesh& mesh,
    const scalar rho0,
    chargeTally& tally,
    scalar& tbCell,
    scalar& tauCell
)
{
    label nBurn = 0;
    forAll(hits, c)
    {
        if (!hits[c]) continue;
        tally.mass[c] += scalar(hits[c])/nTot*mesh.V()[celli]*rho0;
        (hits[c] == nTot ? tally.nFull[c] : tally.nPartial[c])++;
        const chargeInitiation& ini = initiations[c];
        if (!ini.burn()) continue;
        nBurn += hits[c];
        const scalar t = ini.lightingTime(mesh.C()[celli]);
        if (t < tbCell)
        {
            tbCell = t;
            tauCell = burnWidth*cellSize(bb, mesh.solutionD())/ini.D();
        }
    }
    return nBurn;
}


//- Report each charge; stop if one covers no cell (before anything is
//  written)
void reportCharges
(
    const PtrList<chargeShape>& charges,
    const PtrList<chargeInitiation>& initiations,
    const PtrList<dictionary>& chargeDicts,
    chargeTally& tally,
    const equationsOfState::JWL& jwl,
    const fvMesh& mesh
)
{
    forAll(charges, c)
    {
        reduce(tally.mass[c], sumOp<scalar>());
        reduce(tally.nFull[c], sumOp<label>());
        reduce(tally.nPartial[c], sumOp<label>());
        Info<< "Charge " << c << " (" << charges[c].type() << "): "
            << tally.nFull[c] << " cells covered, " << tally.nPartial[c]
            << " partially; mass " << tally.mass[c] << " kg, energy "
            << tally.mass[c]/jwl.rho0()*jwl.E0() << " J; ";
        initiations[c].report(Info);
        Info<< endl;
    }
    // A charge that covers no cell is a mistake (outside the mesh, or too
    // small for nSample)
    forAll(charges, c)
    {
        if (tally.nFull[c] + tally.nPartial[c] == 0)
        {
            FatalIOErrorInFunction(chargeDicts[c])
                << "Charge " << c << " (" << charges[c].type()
                << ") in entry 'charges' covers no cell of the mesh (bounds "
                << mesh.bounds() << "): check its position and size, or"
                << " raise 'nSample'" << exit(FatalIOError);
        }
    }
}


//- The fields setCharge writes
struct chargeFields
{
    volScalarField& p;
    volVectorField& U;
    volScalarField& alpha;
    volScalarField& rho1;
    volScalarField& rho2;
    volScalarField& tb;
    volScalarField& tau;
    //- Three materials (null with two)
    volScalarField* alpha2;
    volScalarField* rho3;

    //- Volume fractions and densities of every material in cell i
    void get
    (
        const label i, const label n, FixedList<scalar, 3>& a,
        FixedList<scalar, 3>& r
    ) const
    {
        a[0] = alpha[i];
        r[0] = rho1[i];
        r[1] = rho2[i];
        if (n == 3)
        {
            a[1] = (*alpha2)[i];
            r[2] = (*rho3)[i];
            a[2] = 1 - a[0] - a[1];
        }
        else
        {
            a[1] = 1 - a[0];
        }
    }

    void set
    (
        const label i, const label n, const FixedList<scalar, 3>& a,
        const FixedList<scalar, 3>& r
    )
    {
        alpha[i] = a[0];
        rho1[i] = r[0];
        rho2[i] = r[1];
        if (n == 3)
        {
            (*alpha2)[i] = a[1];
            (*rho3)[i] = r[2];
        }
    }
};


//- Put the fraction g of material k at density rk and internal energy per
//  unit volume rhoeK, at rest, into cell i, conserving mass and energy
//  (any number of materials; fills, and charges with three materials).
//  keepP: keep the cell's pressure instead (fills: the material at the
//  ambient pressure; programmed-burn charges); rhoeK, F0 unused then
void mixMaterial
(
    const label i,
    const scalar g,
    const label k,
    const scalar rk,
    const scalar rhoeK,
    const bool keepP,
    const blastMixture& mixture,
    const scalar F0,
    chargeFields& fld
)
{
    const label n = mixture.size();
    const scalar aMin = mixture.alphaMin();
    FixedList<scalar, 3> a, r, m;
    fld.get(i, n, a, r);
    scalar rhoA = 0;
    for (label j = 0; j < n; ++j)
    {
        rhoA += a[j]*r[j];
    }
    const UList<scalar> aList(a.begin(), n), rList(r.begin(), n);
    const scalar rhoeA = keepP ? 0 : mixture.rhoeOf(aList, rList, fld.p[i], F0);

    // Masses and volumes after the mixing, the others floored at aMin
    scalar rest = 0;
    for (label j = 0; j < n; ++j)
    {
        m[j] = (1 - g)*a[j]*r[j] + (j == k ? g*rk : 0);
        if (j != k)
        {
            a[j] = max((1 - g)*a[j], aMin);
            // the trace of a fully covered cell at the fill's density
            r[j] = g < 1 ? r[j] : rk;
            rest += a[j];
        }
    }
    a[k] = 1 - rest;
    r[k] = m[k]/a[k];
    scalar rho = 0;
    for (label j = 0; j < n; ++j)
    {
        rho += a[j]*r[j];
    }
    fld.set(i, n, a, r);
    if (!keepP)
    {
        fld.p[i] = mixture.pOf(aList, rList, g*rhoeK + (1 - g)*rhoeA, F0);
    }
    fld.U[i] = (1 - g)*rhoA*fld.U[i]/rho;
}


//- Put the fraction f of explosive into cell i, conserving mass and, for a
//  constant-volume charge, energy; a programmed-burn charge keeps the
//  ambient pressure (unreacted explosive, holding E0) and gets its
//  lighting time tbCell and burn time tauCell
void mixCell
(
    const label i,
    const scalar f,
    const bool burn,
    const scalar tbCell,
    const scalar tauCell,
    const blastMixture& mixture,
    const equationsOfState::JWL& jwl,
    const scalar t,
    chargeFields& fld
)
{
    if (mixture.threePhase())
    {
        const scalar F0 = programmedBurn::fraction(t, fld.tb[i], fld.tau[i]);
        mixMaterial(i, f, 0, jwl.rho0(), jwl.E0(), burn, mixture, F0, fld);
        if (burn)
        {
            fld.tb[i] = tbCell;
            fld.tau[i] = tauCell;
        }
        return;
    }
    const scalar rho0 = jwl.rho0(), aMin = mixture.alphaMin();
    // Ambient state of the cell
    const scalar aA = fld.alpha[i];
    const scalar r1A = fld.rho1[i], r2A = fld.rho2[i];
    const scalar rhoA = aA*r1A + (1 - aA)*r2A;
    const scalar F0 = programmedBurn::fraction(t, fld.tb[i], fld.tau[i]);
    const scalar rhoeA = mixture.rhoe(aA, r1A, r2A, fld.p[i], F0);

    const scalar a = min(max(f + (1 - f)*aA, aMin), 1 - aMin);
    const scalar r1 = (f*rho0 + (1 - f)*aA*r1A)/a;
    const scalar r2 = (f < 1) ? r2A : rho0;
    const scalar rho = a*r1 + (1 - a)*r2;

    fld.alpha[i] = a;
    fld.rho1[i] = r1;
    fld.rho2[i] = r2;
    if (burn)
    {
        fld.tb[i] = tbCell;
        fld.tau[i] = tauCell;
    }
    else
    {
        const scalar rhoe = f*jwl.E0() + (1 - f)*rhoeA;
        fld.p[i] = mixture.p(a, r1, r2, rhoe, F0);
    }
    fld.U[i] = (1 - f)*rhoA*fld.U[i]/rho;
}

//- The fills, one after the other, before the charges; reports the volume
//  of each and stops if one covers no cell
void fillRegions
(
    const PtrList<chargeShape>& fills,
    const List<fillSpec>& specs,
    const PtrList<dictionary>& fillDicts,
    const blastMixture& mixture,
    const label nSample,
    chargeFields& fld,
    const fvMesh& mesh
)
{
    const Vector<label>& solD = mesh.solutionD();
    const pointField& pts = mesh.points();
    PtrList<chargeShape> one(1);
    labelList hits(1);
    forAll(fills, c)
    {
        one.set(0, new chargeShape(fills[c]));
        const label k = specs[c].material;
        const volScalarField& rhoField =
            k == 0 ? fld.rho1 : (k == 1 ? fld.rho2 : *fld.rho3);
        scalar volume = 0, mass = 0;
        forAll(mesh.V(), i)
        {
            const boundBox bb(pts, mesh.cellPoints()[i], false);
            const label nTot = sampleCell(bb, solD, nSample, one, hits);
            if (hits[0] == 0) continue;
            const scalar g = scalar(hits[0])/nTot;
            const scalar rk = specs[c].rho > 0 ? specs[c].rho : rhoField[i];
            // At the cell's pressure (keepP; rhoeK, F0 unused)
            mixMaterial(i, g, k, rk, 0, true, mixture, 1, fld);
            volume += g*mesh.V()[i];
            mass += g*mesh.V()[i]*rk;
        }
        reduce(volume, sumOp<scalar>());
        reduce(mass, sumOp<scalar>());
        Info<< "Fill " << c << " (" << fills[c].type() << "): "
            << mixture.materials()[k] << ", volume " << volume << " m3, mass "
            << mass << " kg" << endl;
        if (!(volume > 0))
        {
            FatalIOErrorInFunction(fillDicts[c])
                << "Fill " << c << " (" << fills[c].type() << ") in entry"
                << " 'fills' covers no cell of the mesh (bounds "
                << mesh.bounds() << ")" << exit(FatalIOError);
        }
    }
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Place explosive charges: constant-volume explosion state or"
        " unreacted explosive with a programmed burn"
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
    const equationsOfState::JWL& jwl = explosiveOf(mixture, thermo);
    const scalar rho0 = jwl.rho0();
    const scalar E0 = jwl.E0();

    IOdictionary dict
    (
        IOobject
        (
            "setChargeDict", runTime.system(), mesh,
            IOobject::MUST_READ, IOobject::NO_WRITE
        )
    );
    label nSample = 8;
    scalar burnWidth = 2;
    readControls(dict, nSample, burnWidth);

    PtrList<chargeShape> charges;
    PtrList<chargeInitiation> initiations;
    PtrList<dictionary> chargeDicts;
    readCharges
    (
        dict, mixture, jwl, runTime.value(), charges, initiations,
        chargeDicts
    );
    bool anyBurn = false;
    forAll(initiations, c)
    {
        anyBurn = anyBurn || initiations[c].burn();
    }
    if (anyBurn)
    {
        reportCJ(jwl, initiations, chargeDicts);
    }

    PtrList<chargeShape> fills;
    List<fillSpec> fillSpecs;
    PtrList<dictionary> fillDicts;
    readFills(dict, mixture, fills, fillSpecs, fillDicts);

    const word& m1 = mixture.materials()[0];
    const word& m2 = mixture.materials()[1];
    const bool three = mixture.threePhase();
    auto io = [&](const word& name, const IOobject::readOption r)
    {
        return IOobject
        (
            name, runTime.timeName(), mesh, r, IOobject::AUTO_WRITE
        );
    };
    volScalarField p(io("p", IOobject::MUST_READ), mesh);
    volVectorField U(io("U", IOobject::MUST_READ), mesh);
    volScalarField alpha(io("alpha." + m1, IOobject::MUST_READ), mesh);
    volScalarField rho1(io("rho." + m1, IOobject::MUST_READ), mesh);
    volScalarField rho2(io("rho." + m2, IOobject::MUST_READ), mesh);
    autoPtr<volScalarField> alpha2, rho3;
    if (three)
    {
        alpha2.reset
        (
            new volScalarField(io("alpha." + m2, IOobject::MUST_READ), mesh)
        );
        rho3.reset
        (
            new volScalarField
            (
                io("rho." + mixture.materials()[2], IOobject::MUST_READ),
                mesh
            )
        );
    }

    // Burn fields: those of an earlier setCharge run, else all burnt
    const bool hadBurn = programmedBurn::present(mesh);
    const dimensionedScalar zeroTime(dimTime, Zero);
    volScalarField tb
    (
        io("lightingTime", IOobject::READ_IF_PRESENT), mesh, zeroTime,
        "zeroGradient"
    );
    volScalarField tau
    (
        io("burnTime", IOobject::READ_IF_PRESENT), mesh, zeroTime,
        "zeroGradient"
    );

    // Solved directions: sample only those
    const Vector<label>& solD = mesh.solutionD();
    const pointField& pts = mesh.points();
    const scalarField& V = mesh.V();
    const vectorField& C = mesh.C();

    chargeTally tally(charges.size());
    scalar totalMass = 0;
    chargeFields fields
        {p, U, alpha, rho1, rho2, tb, tau, alpha2.get(), rho3.get()};
    labelList hits(charges.size(), label(0));

    fillRegions(fills, fillSpecs, fillDicts, mixture, nSample, fields, mesh);

    forAll(V, celli)
    {
        const boundBox bb(pts, mesh.cellPoints()[celli], false);
        const label nTot = sampleCell(bb, solD, nSample, charges, hits);
        const label nIn = sum(hits);
        if (nIn == 0) continue;

        const scalar f = scalar(nIn)/nTot;
        scalar tbCell = GREAT, tauCell = 0;
        const label nBurn = tallyCell
        (
            celli, bb, nTot, hits, initiations, burnWidth, mesh, rho0,
            tally, tbCell, tauCell
        );
        if (nBurn > 0 && nBurn < nIn)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'charges': cell " << celli << " (centre "
                << C[celli] << ") holds a constant-volume and a"
                << " programmed-burn charge: keep them a cell apart"
                << exit(FatalIOError);
        }
        totalMass += f*V[celli]*rho0;

        mixCell
        (
            celli, f, nBurn > 0, tbCell, tauCell, mixture, jwl,
            runTime.value(), fields
        );
    }

    reduce(totalMass, sumOp<scalar>());
    reportCharges(charges, initiations, chargeDicts, tally, jwl, mesh);

    Info<< "Explosive " << m1 << ": rho0 " << rho0 << " kg/m3, E0 " << E0
        << " J/m3, constant-volume explosion pressure " << jwl.pCV()
        << " Pa" << nl
        << "Total charge mass " << totalMass << " kg (in the mesh volume"
        << (mesh.nSolutionD() < 3 ? "; 2D: per mesh depth/wedge share" : "")
        << ")" << endl;

    p.write();
    U.write();
    alpha.write();
    rho1.write();
    rho2.write();
    if (three)
    {
        alpha2->write();
        rho3->write();
    }
    if (anyBurn || hadBurn)
    {
        tb.write();
        tau.write();
        Info<< "Programmed burn: wrote lightingTime and burnTime (burnWidth "
            << burnWidth << " cells)" << endl;
    }

    Info<< "End\n" << endl;
    return 0;
}


// ************************************************************************* //

/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemPartitionCheck

Description
    Test of femdemPartition (tests/regression/femdemPartition.sh): a
    rectangular FEMDEM plate loaded until it fractures, run on every rank
    twice, as the whole solid (the serial reference, the same on every
    rank) and partitioned over the ranks (METIS, or vertical stripes), over
    the same intervals (advance(), sub-cycled at the stable step). After
    each interval the owned nodes' positions of all ranks are gathered and
    compared with the serial ones. Prints per rank the owned and halo
    triangles and the bytes exchanged per step, then per interval the
    sub-steps, broken joints, the largest difference (relative to the
    largest displacement) and the number of differing nodes; the last line
    'max relative difference D, differing nodes N, broken joints B, steps
    S'.

    Options: -load tension|compression|shear|impact|pull, -nx, -ny, -intervals,
    -interval [s], -law neoHookean|StVenantKirchhoff, -contact
    potential|none, -weibull (Weibull joint strengths, m = 6),
    -owner metis|stripes, -haloWidth [m], -partitionEntries '<entries>'
    (more entries of the sub-dictionary partition, e.g. 'maxImbalance
    0.01;'), -extraWeights W (W added to the balancing weight of every
    triangle in the plate's right quarter, as a coupled model's work:
    femdemPartition::setExtraWeights). Before the last line: the owned
    triangles per rank and, of them, those in the right quarter.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "femdemPartition.H"
#include "IStringStream.H"
#include "Pstream.H"
#include "PstreamReduceOps.H"
#include "clockTime.H"
#include <cstring>

using namespace Foam;

namespace
{

std::string properties
(
    const word& load,
    const word& law,
    const word& contact,
    const bool weibull,
    const string& partitionEntries
)
{
    std::string bcs;
    if (load == "tension")
    {
        bcs = "left { type fixed; } right { type velocity; value (2 0);"
              " rampTime 2e-5; }";
    }
    else if (load == "compression")
    {
        bcs = "bottom { type fixed; } top { type velocity; value (0 -4);"
              " rampTime 2e-5; }";
    }
    else if (load == "shear")
    {
        bcs = "bottom { type fixed; } top { type velocity; value (3 -1);"
              " rampTime 1e-5; }";
    }
    else if (load == "impact")
    {
        // A fast platen: fragments fly, the halo is rebuilt as they go
        bcs = "bottom { type fixed; } top { type velocity; value (5 -40);"
              " rampTime 2e-6; }";
    }
    else if (load == "pull")
    {
        // Torn apart fast: the right part flies off across the partition
        bcs = "left { type fixed; } right { type velocity; value (30 5);"
              " rampTime 2e-6; }";
    }
    else
    {
        FatalErrorInFunction
            << "option -load: tension, compression, shear, impact or pull,"
               " got " << load
            << exit(FatalError);
    }
    std::string text =
        "elasticLaw " + law + "; cohesiveLaw munjiza; contactLaw "
      + contact + "; massDamping 0; timeStepSafety 0.5;"
        " materials { rock { E 10e9; nu 0.25; rho 2500;"
        " tensileStrength 2e6; cohesion 8e6; frictionAngle 30; GI 20;"
        " GII 200; dampingRatio 0.2;";
    if (weibull)
    {
        text += " strengthDistribution { type Weibull; modulus 6;"
                " seed 77; }";
    }
    text += " } } boundaryConditions { " + bcs + " }";
    if (!partitionEntries.empty())
    {
        text += " partition { " + partitionEntries + " }";
    }
    return text;
}

//- x of the centroid of triangle t (stripes, the weighted quarter)
scalar centroidX(const triangleMesh& mesh, const label t)
{
    const triangleVertices& v = mesh.triangles()[t];
    return
        (mesh.points()[v[0]].x() + mesh.points()[v[1]].x()
       + mesh.points()[v[2]].x())/3;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::noCheckProcessorDirectories();
    argList::addOption
    (
        "load", "word", "tension | compression | shear | impact | pull"
    );
    argList::addOption("nx", "label", "cells in x (default 40)");
    argList::addOption("ny", "label", "cells in y (default 20)");
    argList::addOption("intervals", "label", "intervals (default 10)");
    argList::addOption("interval", "scalar", "interval [s] (default 1e-5)");
    argList::addOption("law", "word", "neoHookean | StVenantKirchhoff");
    argList::addOption("contact", "word", "potential | none");
    argList::addBoolOption("weibull", "Weibull joint strengths");
    argList::addOption("owner", "word", "metis | stripes");
    argList::addOption("haloWidth", "scalar", "halo width [m]");
    argList::addOption
    (
        "partitionEntries", "string",
        "more entries of the partition sub-dictionary"
    );
    argList::addOption
    (
        "extraWeights", "label",
        "work weight added to the triangles of the plate's right quarter"
        " (femdemPartition::setExtraWeights, as a coupled model's)"
    );
    argList::addBoolOption("verbose", "list the first differing nodes");
    argList::addBoolOption
    (
        "noReference",
        "partitioned run only (timing, benchmarks/femdemScaling)"
    );
    argList args(argc, argv);

    const word load = args.getOrDefault<word>("load", "tension");
    const label nx = args.getOrDefault<label>("nx", 40);
    const label ny = args.getOrDefault<label>("ny", 20);
    const label nIntervals = args.getOrDefault<label>("intervals", 10);
    const scalar interval = args.getOrDefault<scalar>("interval", 1e-5);
    const word law = args.getOrDefault<word>("law", "neoHookean");
    const word contact = args.getOrDefault<word>("contact", "potential");
    const word ownerKind = args.getOrDefault<word>("owner", "metis");
    const string haloWidth = args.getOrDefault<string>("haloWidth", "");
    const string partitionEntries =
        (haloWidth.empty() ? string() : "haloWidth " + haloWidth + "; ")
      + args.getOrDefault<string>("partitionEntries", "");

    const scalar lx = 0.2, ly = 0.1;
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D::zero, vector2D(lx, ly), nx, ny, "rock");
    IStringStream is
    (
        properties(load, law, contact, args.found("weibull"), partitionEntries)
    );
    const dictionary dict(is);

    // Serial reference (every rank runs it) and the partitioned solid
    const bool reference = !args.found("noReference");
    autoPtr<femdemSolid> serialPtr;
    if (reference)
    {
        serialPtr.reset(new femdemSolid(mesh, dict));
    }
    autoPtr<femdemPartition> partPtr;
    if (ownerKind == "stripes")
    {
        labelList owner(mesh.nTriangles());
        forAll(owner, t)
        {
            const scalar xc = centroidX(mesh, t);
            owner[t] = min(label(xc/lx*Pstream::nProcs()), Pstream::nProcs() - 1);
        }
        partPtr.reset(new femdemPartition(mesh, dict, owner));
    }
    else
    {
        partPtr.reset(new femdemPartition(mesh, dict));
    }
    femdemPartition& part = partPtr();
    const label extraWeight = args.getOrDefault<label>("extraWeights", 0);
    if (extraWeight > 0)
    {
        labelList w(mesh.nTriangles(), Zero);
        forAll(w, t)
        {
            const scalar xc = centroidX(mesh, t);
            if (xc > 0.75*lx) w[t] = extraWeight;
        }
        part.setExtraWeights(w);
    }

    Pout<< "rank " << Pstream::myProcNo() << ": " << part.nOwned()
        << " owned, " << part.nHalo() << " halo triangles, neighbours "
        << part.neighbourRanks() << ", " << part.bytesPerStep()
        << " bytes sent per step, halo width " << part.haloWidth() << " m"
        << endl;

    if (!reference)
    {
        // Timed: the partitioned solid alone
        returnReduce(label(0), sumOp<label>());     // all ranks start together
        const clockTime wall;
        label steps = 0;
        for (label i = 0; i < nIntervals; ++i)
        {
            steps += part.advance(interval);
        }
        returnReduce(label(0), sumOp<label>());
        const scalar seconds = wall.elapsedTime();
        Pout<< "rank " << Pstream::myProcNo() << ": local solid "
            << part.localBytes() << " bytes ("
            << scalar(part.localBytes())/part.nOwned()
            << " per owned triangle), global copies " << part.globalBytes()
            << " bytes" << endl;
        Info<< "ranks " << Pstream::nProcs() << ", triangles "
            << mesh.nTriangles() << ", sub-steps " << steps << ", wall "
            << seconds << " s, triangle-steps per second "
            << scalar(mesh.nTriangles())*steps/seconds << ", halo rebuilds "
            << part.nRebuilds() << ", broken joints (rank 0's solid) "
            << part.solid().nBrokenJoints() << ", load-balancing repartitions "
            << part.nRepartitions() << " (" << part.nMigrated()
            << " triangles migrated)" << endl;
        return 0;
    }
    femdemSolid& serial = serialPtr();

    const List<vector2D> x0(serial.x());
    scalar worst = 0;
    label worstNodes = 0, steps = 0;
    for (label i = 0; i < nIntervals; ++i)
    {
        const label ns = serial.advance(interval);
        const label np = part.advance(interval);
        steps += ns;
        const List<vector2D> xp = part.gatherPositions();
        scalar dMax = 0, uMax = 0;
        label nDiff = 0;
        forAll(xp, n)
        {
            const vector2D& xs = serial.x()[n];
            uMax = max(uMax, mag(xs - x0[n]));
            dMax = max(dMax, mag(xp[n] - xs));
            if (std::memcmp(&xp[n], &xs, sizeof(vector2D)) != 0) ++nDiff;
        }
        const scalar rel = dMax/max(uMax, VSMALL);
        if (nDiff && !worstNodes && args.found("verbose"))
        {
            forAll(xp, n)
            {
                if (std::memcmp(&xp[n], &serial.x()[n], sizeof(vector2D)))
                {
                    Info<< "  node " << n << " triangle " << n/3 << " at "
                        << serial.x()[n] << " differs by "
                        << mag(xp[n] - serial.x()[n]) << endl;
                }
            }
        }
        worst = max(worst, rel);
        worstNodes = max(worstNodes, nDiff);
        Info<< "t " << serial.time() << " sub-steps " << ns << " / " << np
            << ", broken joints " << serial.nBrokenJoints()
            << ", largest displacement " << uMax << " m, max |x_p - x_s| "
            << dMax << " m (relative " << rel << "), differing nodes "
            << nDiff << endl;
        if (serial.stableTimeStep() != part.solid().stableTimeStep())
        {
            Info<< "  stable step " << serial.stableTimeStep() << " serial, "
                << part.solid().stableTimeStep() << " partitioned" << endl;
        }
        if (np != ns)
        {
            FatalErrorInFunction
                << "the partitioned solid took " << np << " sub-steps, the"
                << " serial one " << ns << exit(FatalError);
        }
    }
    // Owned triangles of every rank, and of them in the right quarter
    labelList owned(Pstream::nProcs(), Zero), right(Pstream::nProcs(), Zero);
    owned[Pstream::myProcNo()] = part.nOwned();
    forAll(part.globalTriangles(), t)
    {
        if (!part.owned(t)) continue;
        if (centroidX(mesh, part.globalTriangles()[t]) > 0.75*lx)
        {
            ++right[Pstream::myProcNo()];
        }
    }
    Pstream::listCombineGather(owned, plusEqOp<label>());
    Pstream::listCombineGather(right, plusEqOp<label>());
    Info<< "owned triangles per rank " << owned << ", of them in the right"
        << " quarter " << right << endl;
    Info<< "halo displacement checks " << part.nDisplacementChecks()
        << ", halo rebuilds " << part.nRebuilds()
        << ", load-balancing repartitions " << part.nRepartitions() << " ("
        << part.nMigrated() << " triangles migrated)" << nl
        << "max relative difference " << worst << ", differing nodes "
        << worstNodes << ", broken joints " << serial.nBrokenJoints()
        << ", steps " << steps << endl;
    return 0;
}


// ************************************************************************* //

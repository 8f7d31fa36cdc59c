/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemRenumber

Group
    grpMeshManipulationUtilities

Description
    Renumbers constant/solidMesh for memory locality with METIS (see
    solidMeshRenumber) and writes it back, or with -benchmark only measures
    the effect: the time per element of two loops typical of FEMDEM, each
    run on the mesh as it is, randomly shuffled and METIS-renumbered:
    - triangle loop: gather the 3 points of each triangle, scatter a force
      to them (continuous mesh, as the coupling's force distribution);
    - joint loop: gather the 4 discontinuous nodes (3t+k) of each joint,
      scatter opposite forces (as the FEMDEM joint forces).

Usage
    femdemRenumber [-case dir] [-blockSize 32] [-benchmark] [-repeat 20]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "triangleMesh.H"
#include "jointTopology.H"
#include "solidMeshRenumber.H"

#include <algorithm>
#include <chrono>
#include <random>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

double seconds()
{
    return std::chrono::duration<double>
    (
        std::chrono::steady_clock::now().time_since_epoch()
    ).count();
}

// Best time of 'repeat' runs of the triangle loop, per triangle [ns]
double triangleLoop(const triangleMesh& mesh, label repeat, scalar& checksum)
{
    const List<vector2D>& x = mesh.points();
    const List<triangleVertices>& tris = mesh.triangles();
    List<vector2D> f(x.size(), Zero);
    double best = GREAT;
    for (label r = 0; r < repeat; ++r)
    {
        const double t0 = seconds();
        for (const triangleVertices& t : tris)
        {
            const vector2D& a = x[t[0]];
            const vector2D& b = x[t[1]];
            const vector2D& c = x[t[2]];
            // Gradient of the area with respect to each vertex
            f[t[0]] += vector2D(b.y() - c.y(), c.x() - b.x());
            f[t[1]] += vector2D(c.y() - a.y(), a.x() - c.x());
            f[t[2]] += vector2D(a.y() - b.y(), b.x() - a.x());
        }
        best = min(best, seconds() - t0);
    }
    checksum = sum(mag(f));
    return 1e9*best/max(tris.size(), label(1));
}

// Best time of 'repeat' runs of the joint loop, per joint [ns]
double jointLoop(const triangleMesh& mesh, label repeat, scalar& checksum)
{
    const jointTopology topo(mesh);
    const List<vector2D> x = jointTopology::nodePositions(mesh);
    List<vector2D> f(x.size(), Zero);
    const List<jointNodeList>& joints = topo.jointNodes();
    double best = GREAT;
    for (label r = 0; r < repeat; ++r)
    {
        const double t0 = seconds();
        for (const jointNodeList& n : joints)
        {
            const vector2D d = x[n[1]] - x[n[0]];
            const vector2D open0 = x[n[2]] - x[n[0]];
            const vector2D open1 = x[n[3]] - x[n[1]];
            const vector2D g = 1e3*(open0 + open1) + 1e-3*d;
            f[n[0]] += g;
            f[n[1]] += g;
            f[n[2]] -= g;
            f[n[3]] -= g;
        }
        best = min(best, seconds() - t0);
    }
    checksum = sum(mag(f));
    return 1e9*best/max(joints.size(), label(1));
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Renumber constant/solidMesh for locality with METIS, or measure the"
        " effect on FEMDEM-like loops (-benchmark)"
    );
    argList::noParallel();
    argList::addOption("blockSize", "n", "Triangles per METIS block (32)");
    argList::addBoolOption("benchmark", "Measure loops only, write nothing");
    argList::addOption("repeat", "n", "Runs of each loop, best kept (20)");

    argList args(argc, argv);
    Time runTime(args.rootPath(), args.caseName(), "system", "constant", false, false);

    IOdictionary meshDict
    (
        IOobject
        (
            triangleMesh::meshFileName,
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const triangleMesh mesh(meshDict);
    const label blockSize = args.getOrDefault<label>("blockSize", 32);
    if (blockSize < 1)
    {
        FatalErrorInFunction
            << "option -blockSize " << blockSize << " must be >= 1 (triangles"
            << " per METIS block)" << exit(FatalError);
    }

    const double t0 = seconds();
    const triangleMesh renumbered = solidMeshRenumber::renumber(mesh, blockSize);
    const double renumberTime = seconds() - t0;
    Info<< "METIS renumbering of " << mesh.nTriangles() << " triangles in "
        << renumberTime << " s" << nl;

    if (!args.found("benchmark"))
    {
        renumbered.write(runTime, IOstream::ASCII);
        Info<< "Wrote " << runTime.constant()/triangleMesh::meshFileName
            << nl << "End" << endl;
        return 0;
    }

    labelList shuffle(identity(mesh.nTriangles()));
    std::mt19937 gen(1);
    std::shuffle(shuffle.begin(), shuffle.end(), gen);
    const triangleMesh shuffled = solidMeshRenumber::reorder(mesh, shuffle);

    const label repeat = args.getOrDefault<label>("repeat", 20);
    const triangleMesh* meshes[3] = {&mesh, &shuffled, &renumbered};
    const char* names[3] = {"as read", "shuffled", "METIS"};
    for (label i = 0; i < 3; ++i)
    {
        scalar c1 = 0, c2 = 0;
        const double tri = triangleLoop(*meshes[i], repeat, c1);
        const double joint = jointLoop(*meshes[i], repeat, c2);
        Info<< "numbering " << names[i] << ": neighbours closer than 64 in"
            << " index " << 100*solidMeshRenumber::localNeighbourFraction(*meshes[i])
            << " %, triangle loop " << tri << " ns/triangle, joint loop "
            << joint << " ns/joint (checksums " << c1 << ' ' << c2 << ")"
            << nl;
    }
    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //

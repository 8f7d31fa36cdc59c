/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    femdemMeshCheck

Group
    grpMeshManipulationUtilities

Description
    Checks the solid mesh constant/solidMesh and reports its quality, sizes,
    joint count and a stable time step estimate. Rejects (FatalError naming
    the elements, exit status 1) meshes with:
    - inverted or degenerate triangles (area <= 1e-12 (longest edge)^2),
    - duplicate points (closer than -mergeTol times the shortest edge),
    - non-manifold edges or neighbours traversing an edge the same way,
    - overlapping solids (triangles whose interiors overlap),
    using spatial hashing (no all-pairs search). Nothing is written unless
    -vtk is given and the mesh passes, so a rejected case is left unchanged.

    Stable time step: E, nu, rho (and jointPenalty if given) of each
    material from constant/femdemProperties::materials if present, else
    from -E -nu -rho for all materials (see solidMeshQuality).

Usage
    femdemMeshCheck [-case dir] [-E Pa -nu - -rho kg/m3] [-mergeTol 1e-6]
        [-vtk]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include <cmath>
#include <cstdlib>
#include "Time.H"
#include "IOdictionary.H"
#include "caseChecks.H"
#include "clockTime.H"
#include "triangleMesh.H"
#include "jointTopology.H"
#include "continuousView.H"
#include "solidMeshQuality.H"
#include "solidVtkWriter.H"
#include "OStringStream.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

// Triangles using each point, for messages
List<DynamicList<label>> pointTriangles(const triangleMesh& mesh)
{
    List<DynamicList<label>> result(mesh.nPoints());
    forAll(mesh.triangles(), t)
    {
        for (const label p : mesh.triangles()[t])
        {
            result[p].append(t);
        }
    }
    return result;
}

const label maxListed = 10;

// "3 7 9" for messages
std::string listed(const UList<label>& items)
{
    std::string s;
    for (const label i : items)
    {
        s += (s.empty() ? "" : " ") + std::to_string(i);
    }
    return s;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote("Check the solid mesh constant/solidMesh");
    argList::noParallel();
    argList::addOption("E", "Pa", "Young's modulus (no femdemProperties)");
    argList::addOption("nu", "value", "Poisson's ratio (no femdemProperties)");
    argList::addOption("rho", "kg/m3", "Density (no femdemProperties)");
    argList::addOption
    (
        "mergeTol", "value",
        "Points closer than this times the shortest edge are duplicates"
        " (default 1e-6)"
    );
    argList::addBoolOption("vtk", "Write VTK/solidMeshCheck_0.vtu if the mesh passes");

    argList args(argc, argv);
    // A tolerance <= 0 or NaN would make the duplicate search divide by it.
    // Parsed here: OpenFOAM's readDouble traps (FOAM_SIGFPE) on "NaN", and
    // so does comparing a NaN, hence std::isfinite first
    const std::string mergeTolString =
        args.getOrDefault<string>("mergeTol", "1e-6");
    char* end = nullptr;
    const scalar mergeTol = std::strtod(mergeTolString.c_str(), &end);
    if
    (
        end == mergeTolString.c_str() || *end != '\0'
     || !std::isfinite(mergeTol) || !(mergeTol > 0 && mergeTol < 1)
    )
    {
        FatalErrorInFunction
            << "option -mergeTol " << mergeTolString.c_str()
            << " must be a number in (0, 1) (a"
            << " fraction of the shortest edge)" << exit(FatalError);
    }
    Time runTime(args.rootPath(), args.caseName(), "system", "constant", false, false);

    clockTime clock;
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
    caseChecks::checkInput(meshDict);
    // Index ranges, inverted and zero-area triangles: FatalIOError naming
    // the file, the entry and the triangle
    const triangleMesh mesh(meshDict);
    const scalar readTime = clock.timeIncrement();

    OStringStream problems;
    label nProblems = 0;

    // Nearly degenerate triangles
    {
        const labelList bad = solidMeshQuality::badTriangles(mesh);
        if (bad.size())
        {
            problems<< "    " << bad.size() << " degenerate triangles"
                << " (area <= 1e-12 longest edge^2):";
            for (label i = 0; i < min(bad.size(), maxListed); ++i)
            {
                problems<< " triangle " << bad[i] << " area "
                    << mesh.area(bad[i]) << ';';
            }
            problems<< nl;
            nProblems += bad.size();
        }
    }

    // Duplicate points
    {
        const scalarList shortest = solidMeshQuality::shortestEdges(mesh);
        const scalar tol =
            mergeTol
           *(shortest.size() ? gMin(shortest) : scalar(1));
        const List<labelPair> dup =
            solidMeshQuality::duplicatePoints(mesh, tol);
        if (dup.size())
        {
            const List<DynamicList<label>> users = pointTriangles(mesh);
            problems<< "    " << dup.size() << " pairs of duplicate points"
                << " (closer than " << tol << "):" << nl;
            for (label i = 0; i < min(dup.size(), maxListed); ++i)
            {
                const label a = dup[i].first(), b = dup[i].second();
                problems<< "        points " << a << " and " << b << " at "
                    << mesh.points()[a] << " (distance "
                    << mag(mesh.points()[a] - mesh.points()[b])
                    << "), used by triangles (" << listed(users[a]).c_str()
                    << ") and (" << listed(users[b]).c_str() << ")" << nl;
            }
            nProblems += dup.size();
        }
    }

    if (nProblems)
    {
        FatalErrorInFunction
            << "Solid mesh " << meshDict.objectPath() << " rejected:" << nl
            << problems.str().c_str() << exit(FatalError);
    }

    // Non-manifold edges, neighbours traversing an edge the same way and
    // patch edges off the boundary: FatalError naming the triangles
    clock.timeIncrement();
    const jointTopology topo(mesh);
    continuousView view(topo);
    const scalar convertTime = clock.timeIncrement();

    // Overlapping solids (after the topology, whose errors are sharper)
    {
        const List<labelPair> over =
            solidMeshQuality::overlappingTriangles(mesh);
        if (over.size())
        {
            problems<< "    " << over.size() << " pairs of overlapping"
                << " triangles (overlapping solids):" << nl;
            for (label i = 0; i < min(over.size(), maxListed); ++i)
            {
                const label a = over[i].first(), b = over[i].second();
                problems<< "        triangles " << a << " ("
                    << mesh.materials()[mesh.triangleMaterials()[a]]
                    << ") and " << b << " ("
                    << mesh.materials()[mesh.triangleMaterials()[b]]
                    << ")" << nl;
            }
            nProblems += over.size();
        }
    }

    if (nProblems)
    {
        FatalErrorInFunction
            << "Solid mesh " << meshDict.objectPath() << " rejected:" << nl
            << problems.str().c_str() << exit(FatalError);
    }

    solidMeshQuality::report(mesh, Info);
    Info<< "    joints: " << topo.nJoints() << ", discontinuous nodes: "
        << topo.nNodes() << ", boundary faces: " << topo.nBoundaryFaces()
        << nl
        << "    fragments (connected solids): " << view.nFragments() << nl;

    // Stable time step
    List<solidMeshQuality::elasticProperties> props(mesh.materials().size());
    bool haveProps = false;
    IOobject propsIO
    (
        "femdemProperties",
        runTime.constant(),
        runTime,
        IOobject::MUST_READ,
        IOobject::NO_WRITE,
        false
    );
    if (propsIO.typeHeaderOk<IOdictionary>(false))
    {
        const IOdictionary propsDict(propsIO);
        const dictionary& mdict = propsDict.subDict("materials");
        forAll(mesh.materials(), m)
        {
            const dictionary& d = mdict.subDict(mesh.materials()[m]);
            props[m].E = d.get<scalar>("E");
            props[m].nu = d.get<scalar>("nu");
            props[m].rho = d.get<scalar>("rho");
            props[m].jointPenalty = d.getOrDefault<scalar>("jointPenalty", 0);
        }
        haveProps = true;
        Info<< "    materials from " << propsIO.objectPath() << nl;
    }
    else if (args.found("E") && args.found("nu") && args.found("rho"))
    {
        for (auto& p : props)
        {
            p.E = args.get<scalar>("E");
            p.nu = args.get<scalar>("nu");
            p.rho = args.get<scalar>("rho");
            p.jointPenalty = 0;
        }
        haveProps = true;
    }
    if (haveProps)
    {
        forAll(props, m)
        {
            if (!(props[m].E > 0 && props[m].rho > 0 && props[m].nu > -1
                && props[m].nu < 0.5))
            {
                FatalErrorInFunction
                    << "Material " << mesh.materials()[m] << ": need E > 0,"
                    << " rho > 0, -1 < nu < 0.5" << exit(FatalError);
            }
            Info<< "    material " << mesh.materials()[m] << ": P-wave speed "
                << solidMeshQuality::pWaveSpeed(props[m]) << " m/s" << nl;
        }
        label t = -1;
        const scalar dt = solidMeshQuality::stableTimeStep(mesh, props, t);
        Info<< "    stable time step estimate: " << dt << " s (triangle "
            << t << ", smallest altitude / fastest wave speed)" << nl;
    }
    else
    {
        Info<< "    stable time step: no constant/femdemProperties and no"
            << " -E -nu -rho given" << nl;
    }

    Info<< "Times: read " << readTime << " s, conversion (joints and"
        << " continuous view) " << convertTime << " s" << nl;

    if (args.found("vtk"))
    {
        solidVtkWriter vtk(runTime.path()/"VTK", "solidMeshCheck");
        solidMeshQuality::writeVtk(mesh, vtk);
        Info<< "Wrote " << vtk.stepFile(0) << nl;
    }

    Info<< "Mesh OK" << nl << "End" << endl;
    return 0;
}


// ************************************************************************* //

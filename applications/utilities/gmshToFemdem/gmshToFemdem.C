/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).

Application
    gmshToFemdem

Group
    grpMeshConversionUtilities

Description
    Converts a 2D gmsh mesh (.msh, ASCII 2.2 or 4.1) into the solid mesh
    constant/solidMesh: physical surfaces -> materials, physical curves ->
    boundary patches (see gmshReader). Nothing is written if the mesh is
    rejected (unreadable, unsupported elements, inverted or degenerate
    triangles, non-manifold edges).

    Joint traces: with a dictionary (system/gmshToFemdemDict when present,
    or -dict file) whose entry 'jointSets' names physical curves, the lines
    of those curves inside the mesh (curves embedded in a surface, e.g.
    'Curve{5} In Surface{1};' in the .geo) become the joint sets of the
    solid mesh, with the properties given (see jointSetStrengths.H):
    \verbatim
    jointSets
    {
        joints { tensileStrength 0.5e6; cohesion 1e6; frictionAngle 25; }
    }
    \endverbatim

Usage
    gmshToFemdem [-case dir] [-dict file] [-renumber] [-vtk] <file.msh>

    -dict       the dictionary with 'jointSets' (default
                system/gmshToFemdemDict, optional)

    -renumber   METIS renumbering of triangles and points (blocks of 32)
    -vtk        also write VTK/solidMesh_0.vtu (materials, quality)

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "clockTime.H"
#include "IOdictionary.H"
#include "caseChecks.H"
#include "gmshReader.H"
#include "jointTopology.H"
#include "solidMeshQuality.H"
#include "solidMeshRenumber.H"
#include "solidVtkWriter.H"

#include <fstream>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The mesh without the patches of joint-set curves that have no boundary
//  edge (a trace inside the solid is no patch)
triangleMesh withoutEmptyJointPatches
(
    const triangleMesh& mesh,
    const UList<triangleJointSet>& sets
)
{
    DynamicList<word> names;
    DynamicList<edgeList> edges;
    forAll(mesh.patchNames(), i)
    {
        bool isSet = false;
        for (const triangleJointSet& js : sets)
        {
            isSet = isSet || js.name == mesh.patchNames()[i];
        }
        if (!isSet || mesh.patchEdges()[i].size())
        {
            names.append(mesh.patchNames()[i]);
            edges.append(mesh.patchEdges()[i]);
        }
    }
    return triangleMesh
    (
        mesh.points(), mesh.triangles(), mesh.triangleMaterials(),
        mesh.materials(), names, edges
    );
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Convert a 2D gmsh mesh (.msh 2.2 or 4.1 ASCII) into constant/solidMesh"
    );
    argList::noParallel();
    argList::addArgument("msh", "The gmsh mesh file");
    argList::addOption("dict", "file", "Dictionary with jointSets");
    argList::addBoolOption("renumber", "METIS renumbering for locality");
    argList::addBoolOption("vtk", "Also write VTK/solidMesh_0.vtu");

    argList args(argc, argv);
    Time runTime(args.rootPath(), args.caseName(), "system", "constant", false, false);

    fileName mshFile(args.get<fileName>(1));
    if (!mshFile.isAbsolute() && !isFile(mshFile))
    {
        mshFile = runTime.path()/mshFile;
    }

    clockTime clock;
    std::ifstream is(mshFile);
    if (!is.good())
    {
        FatalErrorInFunction
            << "Cannot open gmsh file " << mshFile << exit(FatalError);
    }
    gmshReader reader(is, mshFile);
    triangleMesh mesh(reader.mesh());
    const fileName dictFile = args.getOrDefault<fileName>
    (
        "dict", runTime.system()/"gmshToFemdemDict"
    );
    if (args.found("dict") || isFile(runTime.path()/dictFile))
    {
        IOdictionary dict
        (
            IOobject
            (
                dictFile.isAbsolute() ? dictFile : runTime.path()/dictFile,
                runTime,
                IOobject::MUST_READ,
                IOobject::NO_WRITE,
                false
            )
        );
        caseChecks::checkInput(dict);
        const List<triangleJointSet> sets =
            reader.jointSets(dict.subDict("jointSets"));
        mesh = withoutEmptyJointPatches(mesh, sets);
        mesh.setJointSets(sets);
        for (const triangleJointSet& js : sets)
        {
            Info<< "    joint set " << js.name << ": " << js.edges.size()
                << " edges (lines of the physical curve inside the mesh)"
                << nl;
        }
    }
    Info<< "Read " << mshFile << " (format " << reader.version() << "): "
        << mesh.nTriangles() << " triangles, " << mesh.materials().size()
        << " materials, " << mesh.patchNames().size() << " patches" << nl;
    if (reader.flipped())
    {
        Info<< "    " << reader.flipped() << " clockwise triangles turned"
            << " counter-clockwise" << nl;
    }
    if (reader.droppedLines())
    {
        Info<< "    " << reader.droppedLines() << " lines of physical curves"
            << " not on the boundary of the triangles were dropped as patch"
            << " edges (joint-set traces are not patches)" << nl;
    }

    if (args.found("renumber"))
    {
        const scalar before = solidMeshRenumber::localNeighbourFraction(mesh);
        mesh = solidMeshRenumber::renumber(mesh);
        Info<< "    METIS renumbering: neighbours closer than 64 in index "
            << 100*before << " % -> "
            << 100*solidMeshRenumber::localNeighbourFraction(mesh) << " %"
            << nl;
    }

    // Non-manifold edges and overlapping neighbours stop here
    const jointTopology topo(mesh);
    solidMeshQuality::report(mesh, Info);
    Info<< "    joints: " << topo.nJoints() << nl
        << "Conversion time: " << clock.timeIncrement() << " s" << nl << endl;

    mesh.write
    (
        runTime,
        IOstream::ASCII
    );
    Info<< "Wrote " << runTime.constant()/triangleMesh::meshFileName << endl;

    if (args.found("vtk"))
    {
        solidVtkWriter vtk(runTime.path()/"VTK", "solidMesh");
        solidMeshQuality::writeVtk(mesh, vtk);
        Info<< "Wrote " << vtk.stepFile(0) << endl;
    }

    Info<< "End" << endl;
    return 0;
}


// ************************************************************************* //

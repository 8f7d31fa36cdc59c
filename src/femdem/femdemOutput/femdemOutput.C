/*---------------------------------------------------------------------------*\
  jwlIbFoam: blast in fractured solids, built on OpenFOAM v1912
-------------------------------------------------------------------------------
License
    GNU General Public License v3 or later (as OpenFOAM).
\*---------------------------------------------------------------------------*/

#include "femdemOutput.H"
#include "OFstream.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "edgeList.H"

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

void Foam::femdemOutput::writeState
(
    const femdemSolid& solid,
    const fileName& file
)
{
    mkDir(file.path());
    OFstream os(file);
    os  << "FoamFile" << nl << "{" << nl
        << "    version     2.0;" << nl
        << "    format      ascii;" << nl
        << "    class       dictionary;" << nl
        << "    object      " << file.name() << ";" << nl
        << "}" << nl << nl;
    solid.writeState(os);
}


bool Foam::femdemOutput::readState(femdemSolid& solid, const fileName& file)
{
    if (!isFile(file))
    {
        return false;
    }
    IFstream is(file);
    solid.readState(dictionary(is));
    return true;
}


void Foam::femdemOutput::writeVtk
(
    solidVtkWriter& writer,
    const femdemSolid& solid,
    const fileName& vtkDir,
    const scalar time
)
{
    const continuousView& view = solid.view();
    writer.beginStep(time, view.points(), view.triangles());
    writer.addTriangleField("stress", solid.stress());
    writer.addTriangleField("velocity", solid.triangleVelocity());
    writer.addTriangleField("damage", solid.triangleDamage());
    writer.addTriangleField("material", solid.triangleMaterial());
    writer.addTriangleField("fragment", view.fragmentOfTriangle());
    writer.endStep();

    // Broken joints as lines along their mid-line
    const List<jointNodeList>& jn = solid.topology().jointNodes();
    DynamicList<vector2D> pts;
    DynamicList<edge> lines;
    DynamicList<scalar> length;
    forAll(jn, j)
    {
        if (!solid.jointBroken()[j]) continue;
        const jointNodeList& n = jn[j];
        const label i = pts.size();
        pts.append(0.5*(solid.x()[n[0]] + solid.x()[n[2]]));
        pts.append(0.5*(solid.x()[n[1]] + solid.x()[n[3]]));
        lines.append(edge(i, i + 1));
        length.append(solid.jointLength0()[j]);
    }
    solidVtkWriter::writeLines
    (
        vtkDir/("cracks_" + Foam::name(writer.nSteps() - 1) + ".vtp"),
        pts,
        edgeList(lines),
        length
    );
}


void Foam::femdemOutput::writeCracks
(
    const femdemSolid& solid,
    const fileName& file
)
{
    OFstream os(file);
    os.precision(10);
    os  << "# broken joints: x0 y0 x1 y1 (initial positions of face p)" << nl;
    const List<jointNodeList>& jn = solid.topology().jointNodes();
    const List<vector2D>& X0 = solid.topology().initialPoints();
    const labelList& vertex = solid.topology().nodeVertex();
    forAll(jn, j)
    {
        if (!solid.jointBroken()[j]) continue;
        const vector2D& a = X0[vertex[jn[j][0]]];
        const vector2D& b = X0[vertex[jn[j][1]]];
        os  << a.x() << ' ' << a.y() << ' ' << b.x() << ' ' << b.y() << nl;
    }
}


// ************************************************************************* //

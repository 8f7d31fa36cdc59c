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
    // The first step of a run continues the series of an earlier run: a
    // restarted solid (timeIndex > 0, read from a femdemState) keeps the
    // frames up to the restart time and does not write that one again; a
    // fresh solid replaces the frames from its start time on
    if (writer.nSteps() == 0 && !writer.continued())
    {
        writer.setLinesName("cracks");
        if (writer.continueSeries(time, solid.timeIndex() > 0))
        {
            return;
        }
    }

    const continuousView& view = solid.view();
    writer.beginStep(time, view.points(), view.triangles());
    writer.addTriangleField("stress", solid.stress());
    writer.addTriangleField("velocity", solid.triangleVelocity());
    writer.addTriangleField("damage", solid.triangleDamage());
    writer.addTriangleField("material", solid.triangleMaterial());
    writer.addTriangleField("fragment", view.fragmentOfTriangle());

    // Broken joints as lines along their mid-line, with the joint's
    // initial length: VTK/cracks_<step>.vtp and cracks.vtp.series
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
    writer.addLines(pts, edgeList(lines), length, "initialJointLength");
    writer.endStep();
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

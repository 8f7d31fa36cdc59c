// VTK output of solid meshes and states (.vtu per step, .vtu.series, .pvd)
#include <gtest/gtest.h>
#include <fstream>
#include <sstream>
#include "solidVtkWriter.H"
#include "continuousView.H"
#include "OSspecific.H"

using namespace Foam;

namespace
{

std::string slurp(const fileName& f)
{
    std::ifstream is(f);
    std::stringstream ss;
    ss << is.rdbuf();
    return ss.str();
}

// The whitespace-separated numbers of the first DataArray called name
std::vector<double> dataArray(const std::string& xml, const std::string& name)
{
    const size_t at = xml.find("Name='" + name + "'") != std::string::npos
        ? xml.find("Name='" + name + "'") : xml.find("Name=\"" + name + "\"");
    std::vector<double> values;
    if (at == std::string::npos) return values;
    const size_t begin = xml.find('>', at) + 1;
    const size_t end = xml.find('<', begin);
    std::istringstream is(xml.substr(begin, end - begin));
    double v;
    while (is >> v) values.push_back(v);
    return values;
}

} // End anonymous namespace


TEST(solidVtkWriter, asciiStepsAndSeries)
{
    const fileName dir = "solidVtkWriterTest";
    if (isDir(dir)) rmDir(dir);
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(2, 1), 2, 1, "rock");
    solidVtkWriter writer(dir, "solid", vtk::formatType::INLINE_ASCII);

    for (label step = 0; step < 3; ++step)
    {
        const scalar time = 0.5*step;
        List<vector2D> pts(mesh.points());
        for (vector2D& p : pts) p.x() += time;
        writer.beginStep(time, pts, mesh.triangles());
        scalarList damage(mesh.nTriangles(), 0.25*step);
        List<vector2D> velocity(mesh.nTriangles(), vector2D(1, -2));
        List<symmTensor2D> stress(mesh.nTriangles(), symmTensor2D(1, 2, 3));
        writer.addPointField("speed", scalarList(pts.size(), 3.0));
        writer.addTriangleField("damage", damage);
        writer.addTriangleField("U", velocity);
        writer.addTriangleField("sigma", stress);
        writer.addTriangleField("material", mesh.triangleMaterials());
        writer.endStep();
    }
    EXPECT_EQ(writer.nSteps(), 3);

    const std::string xml = slurp(writer.stepFile(2));
    EXPECT_NE(xml.find("UnstructuredGrid"), std::string::npos);
    EXPECT_NE(xml.find("NumberOfPoints='6'"), std::string::npos) << xml.substr(0, 400);
    EXPECT_NE(xml.find("NumberOfCells='4'"), std::string::npos);

    const std::vector<double> xyz = dataArray(xml, "Points");
    ASSERT_EQ(xyz.size(), 18u);
    EXPECT_DOUBLE_EQ(xyz[3], 1.0 + 1.0);          // point 1 at x = 1, moved 1
    EXPECT_DOUBLE_EQ(xyz[5], 0.0);
    const std::vector<double> conn = dataArray(xml, "connectivity");
    ASSERT_EQ(conn.size(), 12u);
    for (label t = 0; t < 4; ++t)
        for (label k = 0; k < 3; ++k)
            EXPECT_EQ(conn[3*t + k], mesh.triangles()[t][k]);
    EXPECT_EQ(dataArray(xml, "types"), std::vector<double>(4, 5.0));
    EXPECT_EQ(dataArray(xml, "damage"), std::vector<double>(4, 0.5));
    EXPECT_EQ(dataArray(xml, "TimeValue"), std::vector<double>(1, 1.0));
    const std::vector<double> sigma = dataArray(xml, "sigma");
    ASSERT_EQ(sigma.size(), 24u);                  // xx yy zz xy yz xz
    EXPECT_EQ(std::vector<double>(sigma.begin(), sigma.begin() + 6),
              (std::vector<double>{1, 3, 0, 2, 0, 0}));
    EXPECT_EQ(dataArray(xml, "U").size(), 12u);
    EXPECT_EQ(dataArray(xml, "speed").size(), 6u);

    const std::string series = slurp(writer.seriesFile());
    EXPECT_NE(series.find("\"solid_2.vtu\""), std::string::npos) << series;
    EXPECT_NE(series.find("\"time\" : 1"), std::string::npos) << series;
    const std::string pvd = slurp(dir/"solid.pvd");
    EXPECT_NE(pvd.find("file='solid_1.vtu'"), std::string::npos) << pvd;
    EXPECT_NE(pvd.find("timestep='0.5'"), std::string::npos) << pvd;
}


TEST(solidVtkWriter, crackLinesAndMisuse)
{
    const fileName dir = "solidVtkWriterTest";
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(0, 0), vector2D(1, 1), 4, 2);
    const jointTopology topo(mesh);
    continuousView view(topo);
    boolList broken(topo.nJoints(), false);
    broken[3] = broken[7] = true;
    view.update(jointTopology::nodePositions(mesh), broken);

    DynamicList<edge> cracks;
    DynamicList<scalar> joint;
    forAll(view.boundaryEdges(), f)
    {
        if (view.boundaryEdgeJoint()[f] >= 0)
        {
            cracks.append(view.boundaryEdges()[f]);
            joint.append(view.boundaryEdgeJoint()[f]);
        }
    }
    solidVtkWriter::writeLines
    (
        dir/"cracks.vtp", view.points(), edgeList(cracks), joint,
        vtk::formatType::INLINE_ASCII
    );
    const std::string xml = slurp(dir/"cracks.vtp");
    EXPECT_NE(xml.find("NumberOfLines='4'"), std::string::npos) << xml.substr(0, 400);
    EXPECT_EQ(dataArray(xml, "value").size(), 4u);
    EXPECT_EQ(dataArray(xml, "connectivity").size(), 8u);

    // The same lines as part of a step series
    solidVtkWriter stepWriter(dir, "broken", vtk::formatType::INLINE_ASCII);
    stepWriter.beginStep(2e-3, view.points(), view.triangles());
    stepWriter.addTriangleField("fragment", view.fragmentOfTriangle());
    stepWriter.addLines(view.points(), edgeList(cracks), joint);
    stepWriter.endStep();
    EXPECT_NE(slurp(dir/"brokenLines_0.vtp").find("NumberOfLines='4'"), std::string::npos);
    EXPECT_NE(slurp(dir/"brokenLines.vtp.series").find("\"brokenLines_0.vtp\", \"time\" : 0.002"), std::string::npos)
        << slurp(dir/"brokenLines.vtp.series");

    // Wrong sizes and calls out of order name the field
    solidVtkWriter writer(dir, "bad");
    EXPECT_THROW(writer.addTriangleField("early", scalarList(8, 0.0)), Foam::error);
    writer.beginStep(0, mesh.points(), mesh.triangles());
    try
    {
        writer.addTriangleField("damage", scalarList(3, 0.0));
        FAIL() << "wrong size accepted";
    }
    catch (const Foam::error& err)
    {
        EXPECT_NE(std::string(err.message()).find("damage"), std::string::npos);
    }
    writer.endStep();
    EXPECT_TRUE(isFile(writer.stepFile(0)));
    EXPECT_GT(fileSize(writer.stepFile(0)), 100);
}

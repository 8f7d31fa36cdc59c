// gmsh .msh 2.2 and 4.1 ASCII reading: the same mesh in both formats gives
// the same solid mesh; unsupported elements are named
#include <gtest/gtest.h>
#include <sstream>
#include "gmshReader.H"

using namespace Foam;

namespace
{
// Unit square split into 2 triangles (the second clockwise), two materials,
// the bottom and a line inside the square as physical curves
const char* msh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
4
1 10 "bottom"
1 11 "diagonal"
2 20 "rock"
2 21 "steel"
$EndPhysicalNames
$Nodes
5
7 0 0 0
8 1 0 0
9 1 1 0
10 0 1 0
11 5 5 0
$EndNodes
$Elements
5
1 15 2 0 1 7
2 1 2 10 1 7 8
3 1 2 11 2 7 9
4 2 2 20 1 7 8 9
5 2 2 21 2 7 10 9
$EndElements
)";

const char* msh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
4
1 10 "bottom"
1 11 "diagonal"
2 20 "rock"
2 21 "steel"
$EndPhysicalNames
$Entities
1 2 2 0
1 0 0 0 0
1 0 0 0 1 0 0 1 10 2 1 -2
2 0 0 0 1 1 0 1 11 2 1 -3
1 0 0 0 1 1 0 1 20 0
2 0 0 0 1 1 0 1 21 0
$EndEntities
$Nodes
2 5 7 11
2 1 0 3
7
8
9
0 0 0
1 0 0
1 1 0
2 2 0 2
10
11
0 1 0
5 5 0
$EndNodes
$Elements
5 5 1 5
0 1 15 1
1 7
1 1 1 1
2 7 8
1 2 1 1
3 7 9
2 1 2 1
4 7 8 9
2 2 2 1
5 7 10 9
$EndElements
)";

triangleMesh readString(const char* text, label* flipped = nullptr, label* dropped = nullptr)
{
    std::istringstream is(text);
    gmshReader reader(is, "test.msh");
    triangleMesh mesh(reader.mesh());
    if (flipped) *flipped = reader.flipped();
    if (dropped) *dropped = reader.droppedLines();
    return mesh;
}
} // End anonymous namespace


TEST(gmshReader, formats22And41GiveTheSameMesh)
{
    label flipped = 0, dropped = 0;
    const triangleMesh a = readString(msh22, &flipped, &dropped);
    const triangleMesh b = readString(msh41);
    EXPECT_EQ(a.points(), b.points());
    EXPECT_EQ(a.triangles(), b.triangles());
    EXPECT_EQ(a.triangleMaterials(), b.triangleMaterials());
    EXPECT_EQ(a.materials(), b.materials());
    EXPECT_EQ(a.patchNames(), b.patchNames());
    EXPECT_TRUE(a.patchEdges() == b.patchEdges());

    // Unused node 11 dropped, node tags in order; clockwise triangle turned
    EXPECT_EQ(a.nPoints(), 4);
    EXPECT_EQ(a.points()[2], vector2D(1, 1));
    EXPECT_EQ(flipped, 1);
    EXPECT_GT(a.area(1), 0);
    EXPECT_EQ(a.materials(), wordList({"rock", "steel"}));
    EXPECT_EQ(a.triangleMaterials(), labelList({0, 1}));
    // 'diagonal' is inside the square: dropped; 'bottom' kept
    EXPECT_EQ(dropped, 1);
    ASSERT_EQ(a.patchNames(), wordList({"bottom", "diagonal"}));
    EXPECT_EQ(a.patchEdges()[0].size(), 1);
    EXPECT_EQ(a.patchEdges()[1].size(), 0);
}


TEST(gmshReader, rejectsQuadrangleNamingIt)
{
    std::string text(msh22);
    text.replace(text.find("5 2 2 21 2 7 10 9"), 17, "5 3 2 21 2 7 8 9 10");
    try
    {
        readString(text.c_str());
        FAIL() << "quadrangle accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg = err.message();
        EXPECT_NE(msg.find("element 5"), std::string::npos) << msg;
        EXPECT_NE(msg.find("quadrangle"), std::string::npos) << msg;
    }
    EXPECT_THROW(readString("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n"), Foam::error);
    EXPECT_THROW(readString("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"), Foam::error);
}

// Reading, validating and writing the continuous solid mesh
#include <gtest/gtest.h>
#include "triangleMesh.H"
#include "IStringStream.H"
#include "OStringStream.H"

using namespace Foam;

TEST(triangleMesh, dictionaryRoundTrip)
{
    const triangleMesh mesh =
        triangleMesh::rectangle(vector2D(-1, 2), vector2D(3, 1), 6, 4, "rock");
    OStringStream os;
    os << mesh.toDict();
    IStringStream is(os.str());
    const triangleMesh back{dictionary(is)};

    EXPECT_EQ(back.points(), mesh.points());
    EXPECT_EQ(back.triangles(), mesh.triangles());
    EXPECT_EQ(back.patchNames().size(), 4);
    scalar area = 0;
    for (const scalar a : back.areas()) { area += a; }
    EXPECT_NEAR(area, 3.0, 1e-12);
}

TEST(triangleMesh, rejectsInvertedTriangleNamingIt)
{
    IStringStream is
    (
        "materials (rock);"
        "points 4((0 0) (1 0) (1 1) (0 1));"
        "triangles 2((0 1 2) (0 3 2));"
        "triangleMaterials 2(0 0);"
        "boundary {}"
    );
    const dictionary dict(is);
    try
    {
        triangleMesh mesh(dict);
        FAIL() << "inverted triangle accepted";
    }
    catch (const Foam::error& err)
    {
        const std::string msg = err.message();
        EXPECT_NE(msg.find("triangle 1"), std::string::npos) << msg;
        EXPECT_NE(msg.find("inverted"), std::string::npos) << msg;
    }
}

TEST(triangleMesh, rejectsMissingEntry)
{
    IStringStream is("materials (rock); points 3((0 0) (1 0) (0 1));");
    const dictionary dict(is);
    EXPECT_THROW(triangleMesh mesh(dict), Foam::error);
}

TEST(triangleMesh, dictionaryRoundTripIsExactForAnyDouble)
{
    // Points that 6 printed digits would move (the OpenFOAM default)
    List<vector2D> pts({{0, 0}, {1.0/3, 0}, {1.0/3, 2.0/7}, {1e-9/3, 0.123456789012345}});
    List<triangleVertices> tris({triangleVertices({0, 1, 2}), triangleVertices({0, 2, 3})});
    const triangleMesh mesh(pts, tris, labelList(2, Zero), wordList({"rock"}));
    const dictionary dict(mesh.toDict());
    EXPECT_EQ(IOstream::defaultPrecision(), 6u);    // restored
    // As write() does: the dictionary printed with 17 digits
    IOstream::defaultPrecision(17);
    OStringStream os;
    IOstream::defaultPrecision(6);
    os << dict;
    IStringStream is(os.str());
    const triangleMesh back{dictionary(is)};
    EXPECT_EQ(back.points(), mesh.points());
    EXPECT_EQ(back.area(0), mesh.area(0));
}

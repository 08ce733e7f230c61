// WKT and the GeoJSON/project passthrough of the import dispatcher.
#include "ImportTestSupport.h"

#include <gtest/gtest.h>

namespace fc {
namespace {

TEST(WktImport, PolygonShellIsTheBoundaryAndHolesAreObstacles) {
    const auto dir = test::scratchDir("wkt");
    const std::string path = test::writeText(
        dir / "hall.wkt", "POLYGON ((0 0, 20 0, 20 10, 0 10, 0 0), (5 5, 6 5, 6 6, 5 6, 5 5))\n");
    const ImportResult r = importPlanFile(path);
    EXPECT_DOUBLE_EQ(test::freeArea(r.project.plan), 199);
    EXPECT_EQ(r.project.plan.obstacles.size(), 1u);
    EXPECT_EQ(r.project.plan.name, "hall");
}

TEST(WktImport, FurtherPolygonsAreRoomsAndSridIsKept) {
    const auto dir = test::scratchDir("wkt-multi");
    const std::string path = test::writeText(
        dir / "floor.wkt",
        "SRID=25832;MULTIPOLYGON (((0 0, 20 0, 20 10, 0 10, 0 0)), ((0 0, 10 0, 10 10, 0 10, 0 "
        "0)), ((10 0, 20 0, 20 10, 10 10, 10 0)))");
    const ImportResult r = importPlanFile(path);
    ASSERT_EQ(r.project.plan.rooms.size(), 2u);
    EXPECT_EQ(r.project.plan.rooms[0].name, "Room 2");
    EXPECT_EQ(r.project.plan.epsg, 25832);
}

TEST(WktImport, UnitsScaleTheCoordinates) {
    const auto dir = test::scratchDir("wkt-mm");
    const std::string path =
        test::writeText(dir / "mm.wkt", "POLYGON ((0 0, 20000 0, 20000 10000, 0 10000, 0 0))");
    ImportOptions options;
    options.metresPerUnit = 0.001;
    EXPECT_DOUBLE_EQ(test::freeArea(importPlanFile(path, options).project.plan), 200);
}

TEST(WktImport, BadTextGivesAnInputError) {
    const auto dir = test::scratchDir("wkt-bad");
    for (const std::string text :
         {"", "POLYGON ((0 0, 1 0", "LINESTRING (0 0, 1 1)", "POLYGON EMPTY",
          "POLYGON ((0 0, 10 10, 10 0, 0 10, 0 0))", "SRID=abc;POLYGON ((0 0, 1 0, 1 1, 0 0))",
          "POLYGON ((0 0, 1 0, 1 1, 0 0)) trailing", "POLYGON ((0 0, 1e400 0, 1 1, 0 0))"}) {
        const std::string path = test::writeText(dir / "bad.wkt", text);
        EXPECT_THROW(importPlanFile(path), InputError) << text;
    }
}

TEST(Import, GeoJsonAndProjectsGoThroughTheExistingReaders) {
    const ImportResult r = importPlanFile(std::string(FC_PLANS_DIR) + "/office.geojson");
    EXPECT_GT(test::freeArea(r.project.plan), 0);
    EXPECT_THROW(importPlanFile(std::string(FC_TEST_DATA_DIR) + "/truncated.geojson"), InputError);
    EXPECT_THROW(importPlanFile(std::string(FC_TEST_DATA_DIR) + "/bad-robot.fcproj"), InputError);
    const auto extensions = importableExtensions();
    EXPECT_NE(std::find(extensions.begin(), extensions.end(), "dxf"), extensions.end());
    EXPECT_NE(std::find(extensions.begin(), extensions.end(), "yaml"), extensions.end());
}

} // namespace
} // namespace fc

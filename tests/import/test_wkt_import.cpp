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

// A WKT in degrees (PostGIS's SRID=4326) or Web Mercator, or any import given --epsg 4326, is
// planned in metres in its UTM zone, with a warning saying so.
TEST(WktImport, DegreesAndWebMercatorArePlannedInMetres) {
    const auto dir = test::scratchDir("wkt-degrees");
    // 0.0002 x 0.0001 degrees at 48.137 N, 11.575 E: 14.88 x 11.12 m in UTM zone 32N.
    const std::string lonLat = test::writeText(
        dir / "lonlat.wkt", "SRID=4326;POLYGON ((11.575 48.137, 11.5752 48.137, 11.5752 48.1371, "
                            "11.575 48.1371, 11.575 48.137))");
    const ImportResult a = importPlanFile(lonLat);
    EXPECT_EQ(a.project.plan.epsg, 32632);
    EXPECT_NEAR(test::freeArea(a.project.plan), 165.5, 0.5);
    ASSERT_EQ(a.warnings.size(), 1u);
    EXPECT_NE(a.warnings[0].find("UTM zone 32N (EPSG:32632)"), std::string::npos) << a.warnings[0];
    const std::string bare = test::writeText(
        dir / "bare.wkt", "POLYGON ((11.575 48.137, 11.5752 48.137, 11.5752 48.1371, 11.575 "
                          "48.1371, 11.575 48.137))");
    ImportOptions degrees;
    degrees.epsg = 4326;
    EXPECT_NEAR(test::freeArea(importPlanFile(bare, degrees).project.plan), 165.5, 0.5);
    // The same corners in Web Mercator: its "metres" are 1.5 times the ground's here.
    const std::string mercator = test::writeText(
        dir / "mercator.wkt",
        "SRID=3857;POLYGON ((1288523.106 6129677.092, 1288545.370 6129677.092, 1288545.370 "
        "6129693.773, 1288523.106 6129693.773, 1288523.106 6129677.092))");
    const ImportResult m = importPlanFile(mercator);
    EXPECT_EQ(m.project.plan.epsg, 32632);
    EXPECT_NEAR(test::freeArea(m.project.plan), 165.5, 1.0);
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

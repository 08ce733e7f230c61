// Plan and project files: reading, writing, error messages and atomic writes.
#include "TestPlans.h"
#include "formats/Export.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "model/Validation.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fc;
using fc::test::rectangle;
using fc::test::shifted;
namespace fs = std::filesystem;

namespace {

const std::string kPlansDir = FC_PLANS_DIR;
const std::string kDataDir = FC_TEST_DATA_DIR;

// A fresh, empty directory per test, removed afterwards.
class ScratchDir {
public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("fc-formats-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() { fs::remove_all(path_); }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(path_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path path_;
};

std::string loadError(const std::string& path) {
    try {
        loadProjectFile(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string readError(const std::string& text, bool project) {
    try {
        if (project)
            readProject(text);
        else
            readGeoJsonPlan(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// The ring as a sorted vertex list: equal shapes whatever the start and orientation.
std::vector<std::pair<double, double>> vertexSet(const Ring& ring) {
    std::vector<std::pair<double, double>> vertices;
    for (const Vec2& p : ring)
        vertices.emplace_back(p.x, p.y);
    std::sort(vertices.begin(), vertices.end());
    return vertices;
}

void expectSamePlan(const Plan& a, const Plan& b) {
    EXPECT_EQ(vertexSet(a.boundary), vertexSet(b.boundary));
    ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
    for (size_t i = 0; i < a.obstacles.size(); ++i)
        EXPECT_EQ(vertexSet(a.obstacles[i]), vertexSet(b.obstacles[i]));
    ASSERT_EQ(a.rooms.size(), b.rooms.size());
    for (size_t i = 0; i < a.rooms.size(); ++i) {
        EXPECT_EQ(a.rooms[i].name, b.rooms[i].name);
        EXPECT_EQ(vertexSet(a.rooms[i].outline), vertexSet(b.rooms[i].outline));
    }
    EXPECT_EQ(a.epsg, b.epsg);
}

} // namespace

TEST(PlanIO, ReadsEverySamplePlan) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(kPlansDir)) {
        if (entry.path().extension() != ".geojson")
            continue;
        SCOPED_TRACE(entry.path().string());
        const Project project = loadProjectFile(entry.path().string());
        EXPECT_EQ(project.plan.name, entry.path().stem().string());
        EXPECT_GE(project.plan.boundary.size(), 3u);
        EXPECT_NE(project.plan.boundary.front(), project.plan.boundary.back())
            << "closing vertex must be dropped";
        ++count;
    }
    EXPECT_GE(count, 6);
    const Plan office = loadProjectFile(kPlansDir + "/office.geojson").plan;
    EXPECT_EQ(office.rooms.size(), 13u);
    const Plan ward = loadProjectFile(kPlansDir + "/ward.geojson").plan;
    EXPECT_EQ(ward.rooms.size(), 17u);
    EXPECT_EQ(ward.obstacles.size(), 33u);
    const Plan simple = loadProjectFile(kPlansDir + "/simple.geojson").plan;
    ASSERT_EQ(simple.obstacles.size(), 1u);
    EXPECT_EQ(simple.boundary.size(), 4u);
    EXPECT_DOUBLE_EQ(ringArea(simple.boundary), 96.0);
}

TEST(PlanIO, GeoJsonRoundTrip) {
    for (const char* name : {"simple", "office", "ward"}) {
        SCOPED_TRACE(name);
        const Plan original = loadProjectFile(kPlansDir + "/" + name + ".geojson").plan;
        const std::string written = writeGeoJsonPlan(original);
        const Plan reread = readGeoJsonPlan(written);
        expectSamePlan(original, reread);
        EXPECT_EQ(writeGeoJsonPlan(reread), written);
    }
}

TEST(PlanIO, WritesRfc7946OrientationAndClosedRings) {
    Plan plan;
    plan.boundary = rectangle(0, 0, 10, 8);
    std::reverse(plan.boundary.begin(), plan.boundary.end()); // clockwise on purpose
    plan.obstacles.push_back(rectangle(2, 2, 3, 3));          // counter-clockwise
    plan.rooms.push_back({"Hall", rectangle(0, 0, 10, 8)});
    const auto root = nlohmann::json::parse(writeGeoJsonPlan(plan));
    ASSERT_EQ(root["features"].size(), 2u);
    const auto& rings = root["features"][0]["geometry"]["coordinates"];
    ASSERT_EQ(rings.size(), 2u);
    auto toRing = [](const nlohmann::json& positions) {
        Ring ring;
        for (const auto& p : positions)
            ring.push_back({p[0].get<double>(), p[1].get<double>()});
        return ring;
    };
    const Ring outer = toRing(rings[0]), hole = toRing(rings[1]);
    EXPECT_EQ(outer.front(), outer.back());
    EXPECT_EQ(outer.size(), 5u);
    EXPECT_GT(signedArea(outer), 0.0);
    EXPECT_LT(signedArea(hole), 0.0);
    EXPECT_EQ(root["features"][1]["properties"]["name"], "Hall");
    EXPECT_EQ(root["features"][1]["properties"]["role"], "room");
}

TEST(PlanIO, BoundaryHolesBecomeObstacles) {
    const Plan plan = loadProjectFile(kDataDir + "/rooms-with-hole.geojson").plan;
    ASSERT_EQ(plan.obstacles.size(), 1u);
    EXPECT_EQ(plan.obstacles[0].size(), 4u);
    ASSERT_EQ(plan.rooms.size(), 2u);
    EXPECT_EQ(plan.rooms[0].name, "West");
    EXPECT_EQ(plan.rooms[1].name, "East");
}

TEST(PlanIO, LargeCoordinatesAndEpsgSurviveRoundTrip) {
    const Plan plan = loadProjectFile(kDataDir + "/utm-offset.geojson").plan;
    ASSERT_TRUE(plan.epsg.has_value());
    EXPECT_EQ(*plan.epsg, 32632);
    Plan shifted = plan;
    for (Vec2& p : shifted.boundary)
        p = p + Vec2{0.123456789, 0.987654321};
    const Plan reread = readGeoJsonPlan(writeGeoJsonPlan(shifted));
    expectSamePlan(shifted, reread); // bit-exact coordinates
    Project wrapped;
    wrapped.plan = shifted;
    const Project project = readProject(writeProject(wrapped));
    expectSamePlan(shifted, project.plan);
}

TEST(PlanIO, ReadsEpsgFromCrsNameVariants) {
    const std::string features = R"("features":[{"type":"Feature","properties":{"role":"boundary"},
        "geometry":{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4],[0,0]]]}}])";
    const Plan a = readGeoJsonPlan(R"({"type":"FeatureCollection","crs":{"type":"name",
        "properties":{"name":"EPSG:25832"}},)" +
                                   features + "}");
    EXPECT_EQ(a.epsg, 25832);
    const Plan b = readGeoJsonPlan(R"({"type":"FeatureCollection","epsg":2056,)" + features + "}");
    EXPECT_EQ(b.epsg, 2056);
    const Plan c = readGeoJsonPlan(R"({"type":"FeatureCollection",)" + features + "}");
    EXPECT_FALSE(c.epsg.has_value());
}

// The plan as RFC 7946 GeoJSON: longitude/latitude, with `crs` as given ("" for none).
std::string lonLatGeoJson(const Plan& plan, int epsg, const std::string& crs) {
    auto ring = [&](const Ring& r) {
        nlohmann::json coordinates = nlohmann::json::array();
        for (const Vec2& p : toWgs84(r, epsg))
            coordinates.push_back({p.x, p.y});
        coordinates.push_back(coordinates.front());
        return nlohmann::json::array({coordinates});
    };
    nlohmann::json root{{"type", "FeatureCollection"}, {"features", nlohmann::json::array()}};
    if (!crs.empty())
        root["crs"] = {{"type", "name"}, {"properties", {{"name", crs}}}};
    auto add = [&](const std::string& role, const Ring& r, const std::string& name) {
        nlohmann::json properties{{"role", role}};
        if (!name.empty())
            properties["name"] = name;
        root["features"].push_back({{"type", "Feature"},
                                    {"properties", properties},
                                    {"geometry", {{"type", "Polygon"}, {"coordinates", ring(r)}}}});
    };
    add("boundary", plan.boundary, "");
    for (const Ring& obstacle : plan.obstacles)
        add("obstacle", obstacle, "");
    for (const Room& room : plan.rooms)
        add("room", room.outline, room.name);
    return root.dump();
}

// A plan drawn in longitude/latitude (what GIS tools write as GeoJSON by default) is planned
// in metres: reprojected to its UTM zone, which becomes its EPSG, with a note.
TEST(PlanIO, LongitudeLatitudeAndWebMercatorAreReprojectedToMetres) {
    Plan utm = loadProjectFile(kDataDir + "/utm-offset.geojson").plan; // EPSG:32632, 12 x 8 m
    utm.rooms = {Room{"Hall", utm.boundary}};
    for (const std::string& crs :
         {std::string(), std::string("urn:ogc:def:crs:OGC:1.3:CRS84"), std::string("EPSG:4326")}) {
        std::vector<std::string> notes;
        const Plan read = readGeoJsonPlan(lonLatGeoJson(utm, 32632, crs), std::nullopt, &notes);
        ASSERT_EQ(read.epsg, 32632) << crs;
        ASSERT_EQ(notes.size(), 1u) << crs;
        EXPECT_NE(notes[0].find("EPSG:32632"), std::string::npos) << notes[0];
        ASSERT_EQ(read.boundary.size(), utm.boundary.size());
        for (size_t i = 0; i < utm.boundary.size(); ++i)
            EXPECT_LT(distance(read.boundary[i], utm.boundary[i]), 1e-3) << crs << " vertex " << i;
        ASSERT_EQ(read.obstacles.size(), utm.obstacles.size());
        ASSERT_EQ(read.rooms.size(), 1u);
        EXPECT_NEAR(ringArea(read.rooms[0].outline), ringArea(utm.boundary), 1e-3);
    }
    // South of the equator, zone 21S (Buenos Aires); a geographic crs other than WGS84.
    Plan south = utm;
    for (Ring* r : {&south.boundary, &south.rooms[0].outline})
        for (Vec2& p : *r)
            p = p - utm.boundary[0] + Vec2{373000, 6171000}; // EPSG:32721
    for (Ring& obstacle : south.obstacles)
        for (Vec2& p : obstacle)
            p = p - utm.boundary[0] + Vec2{373000, 6171000};
    EXPECT_EQ(readGeoJsonPlan(lonLatGeoJson(south, 32721, "")).epsg, 32721);
    EXPECT_EQ(readGeoJsonPlan(lonLatGeoJson(utm, 32632, "EPSG:4258")).epsg, 32632); // ETRS89
    // Web Mercator (what web maps draw in): its "metres" are 1/cos(latitude) of the ground's,
    // 1.41 at 45 degrees north; planned in true metres.
    Plan mercator = utm;
    auto toMercator = [&](Ring& ring) {
        const std::vector<Vec2> lonLat = toWgs84(ring, 32632);
        for (size_t i = 0; i < ring.size(); ++i) {
            const double lambda = lonLat[i].x * M_PI / 180, phi = lonLat[i].y * M_PI / 180;
            ring[i] = {6378137.0 * lambda, 6378137.0 * std::log(std::tan(M_PI / 4 + phi / 2))};
        }
    };
    toMercator(mercator.boundary);
    for (Ring& obstacle : mercator.obstacles)
        toMercator(obstacle);
    for (Room& room : mercator.rooms)
        toMercator(room.outline);
    mercator.epsg = 3857;
    EXPECT_NEAR(ringArea(mercator.boundary) / ringArea(utm.boundary), 2.0, 0.02);
    std::vector<std::string> mercatorNotes;
    const Plan fromMercator =
        readGeoJsonPlan(writeGeoJsonPlan(mercator), std::nullopt, &mercatorNotes);
    EXPECT_EQ(fromMercator.epsg, 32632);
    for (size_t i = 0; i < utm.boundary.size(); ++i)
        EXPECT_LT(distance(fromMercator.boundary[i], utm.boundary[i]), 1e-3) << "vertex " << i;
    ASSERT_EQ(mercatorNotes.size(), 1u);
    EXPECT_NE(mercatorNotes[0].find("Web Mercator (EPSG:3857)"), std::string::npos);
    // Plans in metres are left alone, with no note.
    std::vector<std::string> notes;
    const Plan metres = readGeoJsonPlan(readFile(kDataDir + "/utm-offset.geojson"), {}, &notes);
    EXPECT_EQ(metres.boundary, loadProjectFile(kDataDir + "/utm-offset.geojson").plan.boundary);
    const Plan office = readGeoJsonPlan(readFile(kPlansDir + "/office.geojson"), {}, &notes);
    EXPECT_FALSE(office.epsg.has_value());
    EXPECT_TRUE(notes.empty());
    // A geographic crs whose coordinates are not on the globe: one line saying so.
    try {
        readGeoJsonPlan(R"({"type":"FeatureCollection","crs":{"type":"name","properties":
            {"name":"EPSG:4326"}},"features":[{"type":"Feature","properties":{"role":"boundary"},
            "geometry":{"type":"Polygon","coordinates":[[[500000,5000000],[500012,5000000],
            [500012,5000008],[500000,5000000]]]}}]})");
        ADD_FAILURE() << "metres labelled EPSG:4326 were read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not on the globe"), std::string::npos) << e.what();
    }
}

TEST(PlanIO, ErrorFixturesNameTheFileAndTheProblem) {
    struct Case {
        const char* file;
        std::vector<std::string> keywords;
    };
    const std::vector<Case> cases = {
        {"empty.geojson", {"empty"}},
        {"truncated.geojson", {"truncated", "line"}},
        {"nan.geojson", {"invalid JSON", "line 1"}},
        {"huge-number.geojson", {"1e400", "out of range"}},
        {"not-feature-collection.geojson", {"not a GeoJSON FeatureCollection", "Feature"}},
        {"missing-role.geojson", {"feature 2", "role"}},
        {"unknown-role.geojson", {"unknown role", "wall"}},
        {"no-boundary.geojson", {"no boundary"}},
        {"two-boundaries.geojson", {"2 buildings", "--building K"}},
        {"string-coordinate.geojson", {"boundary", "non-numeric", "zero"}},
        {"null-coordinate.geojson", {"obstacle 1", "non-numeric", "null"}},
        {"short-ring.geojson", {"obstacle 1", "2 distinct points"}},
        {"unnamed-room.geojson", {"room", "no name"}},
        {"duplicate-room.geojson", {"duplicate room name", "Kitchen"}},
        {"multipolygon-room.geojson", {"Split", "MultiPolygon"}},
        {"newer-version.fcproj", {"version 2", "newer"}},
        {"foreign.json", {"not a FloorCover project", "something-else"}},
    };
    for (const Case& c : cases) {
        const std::string path = kDataDir + "/" + c.file;
        SCOPED_TRACE(path);
        const std::string message = loadError(path);
        ASSERT_FALSE(message.empty()) << "expected an InputError";
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        for (const std::string& keyword : c.keywords)
            EXPECT_NE(message.find(keyword), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.back(), '.') << message;
    }
}

TEST(PlanIO, RejectsMalformedStructure) {
    EXPECT_NE(readError("[1, 2]", false).find("not a GeoJSON FeatureCollection"),
              std::string::npos);
    EXPECT_NE(readError(R"({"type":"FeatureCollection"})", false).find("features"),
              std::string::npos);
    EXPECT_NE(readError(R"({"type":"FeatureCollection","features":[]})", false).find("no boundary"),
              std::string::npos);
    const std::string lineFeature =
        R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":
        {"role":"boundary"},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}}]})";
    EXPECT_NE(readError(lineFeature, false).find("LineString"), std::string::npos);
    const std::string noGeometry = R"({"type":"FeatureCollection","features":[{"type":"Feature",
        "properties":{"role":"boundary"},"geometry":null}]})";
    EXPECT_NE(readError(noGeometry, false).find("no geometry"), std::string::npos);
}

TEST(Project, RoundTrip) {
    Project project;
    project.plan.boundary = rectangle(0, 0, 20, 10);
    project.plan.obstacles.push_back(rectangle(4, 4, 6, 6));
    project.plan.rooms.push_back({"Kitchen", rectangle(0, 0, 10, 10)});
    project.plan.rooms.push_back({"Living \"room\" ü", rectangle(10, 0, 20, 10)});
    project.plan.epsg = 32633;
    project.robot.robotDiameter = 0.4;
    project.robot.cleaningDiameter = 0.9;
    project.robot.coverageWidth = 0.8;
    project.robot.speed = 0.3;
    project.robot.turnTime = 1.5;
    project.sweep.angleDeg = 30.0;
    project.sweep.automatic = true;
    project.solver = "exact";
    project.selectedRooms = {"Kitchen"};
    project.hasStart = true;
    project.start = {1.25, 2.5};

    const std::string text = writeProject(project);
    const Project reread = readProject(text);
    expectSamePlan(project.plan, reread.plan);
    EXPECT_EQ(reread.plan.rooms[1].name, "Living \"room\" ü");
    EXPECT_EQ(reread.robot.robotDiameter, 0.4);
    EXPECT_EQ(reread.robot.cleaningDiameter, 0.9);
    EXPECT_EQ(reread.robot.coverageWidth, 0.8);
    EXPECT_EQ(reread.robot.speed, 0.3);
    EXPECT_EQ(reread.robot.turnTime, 1.5);
    EXPECT_EQ(reread.sweep.angleDeg, 30.0);
    EXPECT_TRUE(reread.sweep.automatic);
    EXPECT_EQ(reread.solver, "exact");
    EXPECT_EQ(reread.selectedRooms, project.selectedRooms);
    EXPECT_TRUE(reread.hasStart);
    EXPECT_EQ(reread.start, project.start);
    EXPECT_FALSE(reread.hasEnd);
    EXPECT_EQ(writeProject(reread), text);

    const auto root = nlohmann::json::parse(text);
    EXPECT_EQ(root["format"], "floorcover-project");
    EXPECT_EQ(root["version"], kProjectFormatVersion);
    EXPECT_TRUE(root["end"].is_null());
}

TEST(Project, RefusesNewerVersionsAndForeignDocuments) {
    EXPECT_NE(readError(R"({"format":"floorcover-project","version":7,"plan":{}})", true)
                  .find("version 7 is newer"),
              std::string::npos);
    EXPECT_NE(readError(R"({"format":"other-tool","version":1})", true).find("not a FloorCover"),
              std::string::npos);
    EXPECT_NE(readError(R"({"type":"FeatureCollection","features":[]})", true)
                  .find("not a FloorCover project"),
              std::string::npos);
    EXPECT_NE(readError(R"({"format":"floorcover-project","version":1,"plan":{"boundary":
        [[0,0],[1,0],[1,1]]},"robot":{"speed":"fast"}})",
                        true)
                  .find("robot.speed"),
              std::string::npos);
    EXPECT_NE(readError(R"({"format":"floorcover-project","version":1,"plan":{"boundary":
        [[0,0],[1,0],[1,1]]},"start":[1]})",
                        true)
                  .find("start"),
              std::string::npos);
}

TEST(Project, LoadsByExtensionAndContent) {
    ScratchDir dir;
    Project project;
    project.plan.boundary = rectangle(0, 0, 5, 5);
    project.solver = "greedy";
    writeFileAtomically(dir.file("saved.fcproj"), writeProject(project));
    writeFileAtomically(dir.file("as-json.json"), writeProject(project));
    writeFileAtomically(dir.file("plan.json"), writeGeoJsonPlan(project.plan));

    const Project a = loadProjectFile(dir.file("saved.fcproj"));
    EXPECT_EQ(a.solver, "greedy");
    EXPECT_EQ(a.plan.name, "saved");
    const Project b = loadProjectFile(dir.file("as-json.json"));
    EXPECT_EQ(b.solver, "greedy");
    EXPECT_EQ(b.plan.name, "as-json");
    const Project c = loadProjectFile(dir.file("plan.json"));
    EXPECT_EQ(c.solver, "heuristic");
    EXPECT_EQ(vertexSet(c.plan.boundary), vertexSet(project.plan.boundary));

    const Project sample = loadProjectFile(kDataDir + "/simple.fcproj");
    EXPECT_EQ(sample.plan.obstacles.size(), 1u);
    EXPECT_TRUE(sample.hasStart);
    EXPECT_FALSE(sample.hasEnd);
}

TEST(Format, FileErrorsNameTheFile) {
    const std::string missing = kDataDir + "/does-not-exist.geojson";
    const std::string message = loadError(missing);
    EXPECT_EQ(message.rfind(missing + ": cannot open", 0), 0u) << message;
    ScratchDir dir;
    fs::create_directories(dir.file("folder.geojson"));
    EXPECT_NE(loadError(dir.file("folder.geojson")).find("is a directory"), std::string::npos);
    const std::string dxf = loadError("/tmp/plan.dxf");
    EXPECT_NE(dxf.find("/tmp/plan.dxf: unsupported file type \".dxf\""), std::string::npos) << dxf;
    EXPECT_THROW(readFile(missing), InputError);
}

TEST(Format, AtomicWriteReplacesContentAndLeavesNoTemporaryFile) {
    ScratchDir dir;
    const std::string path = dir.file("out.geojson");
    writeFileAtomically(path, "old content that is longer\n");
    writeFileAtomically(path, "new\n");
    EXPECT_EQ(readFile(path), "new\n");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.geojson"});

    const std::string unwritable = dir.file("missing-dir/out.geojson");
    try {
        writeFileAtomically(unwritable, "x");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(unwritable + ": cannot write", 0), 0u) << e.what();
    }
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.geojson"});
}

TEST(Format, AtomicWriteFailureKeepsTheOldFile) {
    ScratchDir dir;
    // Renaming a file over a non-empty directory fails after the temporary file is written.
    const std::string path = dir.file("target");
    fs::create_directories(path + "/inside");
    EXPECT_THROW(writeFileAtomically(path, "data"), InputError);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"target"});
    EXPECT_TRUE(fs::is_directory(path));
}

// A site of several buildings: boundary polygons as separate features and as MultiPolygon
// parts, at UTM coordinates. Refused as one plan with the buildings' areas; read one
// building at a time (1 = the largest) with its own holes, obstacles and rooms.
TEST(PlanIO, SiteOfSeveralBuildingsIsReadOneBuildingAtATime) {
    auto square = [](double x, double y, double w, double h) {
        char text[256];
        std::snprintf(text, sizeof text,
                      "[[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f],[%.1f,%.1f]]", x, y, x + w,
                      y, x + w, y + h, x, y + h, x, y);
        return std::string(text);
    };
    const double x0 = 600000.0, y0 = 5400000.0;
    auto feature = [](const std::string& properties, const std::string& geometry) {
        return R"({"type":"Feature","properties":)" + properties + R"(,"geometry":)" + geometry +
               "}";
    };
    const std::string site =
        R"({"type":"FeatureCollection","features":[)" +
        feature(R"({"role":"boundary"})",
                R"({"type":"MultiPolygon","coordinates":[[)" + square(x0, y0, 10, 8) + "],[" +
                    square(x0 + 30, y0, 20, 12) + "," + square(x0 + 34, y0 + 4, 2, 2) + "]]}") +
        "," +
        feature(R"({"role":"boundary"})",
                R"({"type":"Polygon","coordinates":[)" + square(x0, y0 + 40, 5, 5) + "]}") +
        "," +
        feature(R"({"role":"obstacle"})",
                R"({"type":"Polygon","coordinates":[)" + square(x0 + 4, y0 + 3, 2, 2) + "]}") +
        "," +
        feature(R"({"role":"room","name":"Annex"})",
                R"({"type":"Polygon","coordinates":[)" + square(x0, y0, 10, 8) + "]}") +
        "]}";
    std::string message;
    std::vector<double> areas;
    try {
        readGeoJsonPlan(site);
    } catch (const SiteError& e) { // an InputError that carries the areas, for the editor
        message = e.what();
        areas = e.buildingAreas();
    }
    EXPECT_NE(message.find("3 buildings (boundary polygons of 240, 80, 25 m2"), std::string::npos)
        << message;
    EXPECT_NE(message.find("--building K"), std::string::npos) << message;
    ASSERT_EQ(areas.size(), 3u);
    EXPECT_NEAR(areas[0], 240.0, 1e-6);
    EXPECT_NEAR(areas[1], 80.0, 1e-6);
    EXPECT_NEAR(areas[2], 25.0, 1e-6);

    const Plan largest = readGeoJsonPlan(site, 1);
    EXPECT_NEAR(ringArea(largest.boundary), 240.0, 1e-6);
    ASSERT_EQ(largest.obstacles.size(), 1u); // its hole, not the annex's obstacle
    EXPECT_NEAR(ringArea(largest.obstacles[0]), 4.0, 1e-6);
    EXPECT_TRUE(largest.rooms.empty());

    const Plan annex = readGeoJsonPlan(site, 2);
    EXPECT_NEAR(ringArea(annex.boundary), 80.0, 1e-6);
    ASSERT_EQ(annex.obstacles.size(), 1u);
    ASSERT_EQ(annex.rooms.size(), 1u);
    EXPECT_EQ(annex.rooms[0].name, "Annex");

    const Plan shed = readGeoJsonPlan(site, 3);
    EXPECT_NEAR(ringArea(shed.boundary), 25.0, 1e-6);
    EXPECT_TRUE(shed.obstacles.empty() && shed.rooms.empty());
    EXPECT_THROW(readGeoJsonPlan(site, 4), InputError);
    EXPECT_THROW(readGeoJsonPlan(site, 0), InputError);
    // A plan of one building takes building 1 and nothing else.
    EXPECT_EQ(readGeoJsonPlan(writeGeoJsonPlan(annex), 1).rooms.size(), 1u);
    EXPECT_THROW(readGeoJsonPlan(writeGeoJsonPlan(annex), 2), InputError);

    // An obstacle in no building is never dropped quietly: it stays, and the plan's checks
    // refuse it as lying outside the boundary.
    std::string orphan = site;
    orphan.insert(orphan.size() - 2,
                  "," + feature(R"({"role":"obstacle"})", R"({"type":"Polygon","coordinates":[)" +
                                                              square(x0 + 100, y0, 1, 1) + "]}"));
    const Plan withOrphan = readGeoJsonPlan(orphan, 1);
    EXPECT_EQ(withOrphan.obstacles.size(), 2u);
    EXPECT_THROW(validatePlan(withOrphan, RobotProfile{}), InputError);
}

// The issue-5 exports: Nav2 quaternions, Fields2Cover states, VDA 5050 sequence ids, zones,
// WKT, the WGS84 reprojection (checked against values computed with PROJ's cs2cs), and the
// SVG/PDF drawings (checked with xmllint and qpdf when installed).
#include "TestPlans.h"
#include "formats/Export.h"
#include "formats/FileIO.h"
#include "formats/PlanIO.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <unistd.h>

using namespace fc;
using fc::test::rectangle;
using nlohmann::json;

namespace {

Plan roomPlan() {
    Plan plan;
    plan.name = "two rooms";
    plan.boundary = rectangle(0, 0, 10, 4);
    plan.obstacles = {rectangle(2, 1, 3, 2)};
    plan.rooms = {{"west", rectangle(0, 0, 5, 4)}, {"east", rectangle(5, 0, 10, 4)}};
    return plan;
}

// Up, left, down: headings pi/2, pi, -pi/2; a repeated point in the middle.
CoveragePath turningPath() {
    CoveragePath path;
    path.points = {{1, 1}, {1, 3}, {1, 3}, {-1, 3}, {-1, 0}};
    path.kinds = {SegmentKind::Stripe, SegmentKind::Stripe, SegmentKind::Transit,
                  SegmentKind::Contour};
    return path;
}

PathExportInfo info() {
    PathExportInfo result;
    result.solver = "heuristic";
    result.robot.speed = 0.4;
    result.timestamp = "2026-01-02T03:04:05.000Z";
    result.metrics.overlaps = {{{1, 1}, {1, 2}}, {{0, 3}, {-1, 3}}};
    return result;
}

std::string shellOutput(const std::string& command, int& status) {
    std::string output;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) {
        status = -1;
        return output;
    }
    std::array<char, 4096> buffer{};
    size_t got;
    while ((got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        output.append(buffer.data(), got);
    const int raw = ::pclose(pipe);
    status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return output;
}

bool toolAvailable(const std::string& tool) {
    int status = 0;
    shellOutput("command -v " + tool, status);
    return status == 0;
}

std::string writeTemporary(const std::string& name, const std::string& contents) {
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("fc-export-" + std::to_string(::getpid()) + "-" + name))
                                 .string();
    writeFileAtomically(file, contents);
    return file;
}

std::vector<double> numbersIn(const std::string& text) {
    std::vector<double> numbers;
    static const std::regex number(R"(-?\d+(\.\d+)?)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
         it != std::sregex_iterator(); ++it)
        numbers.push_back(std::stod(it->str()));
    return numbers;
}

} // namespace

TEST(Export, FormatNamesExtensionsAndSubjects) {
    for (const std::string& name : exportFormatNames())
        EXPECT_EQ(exportFormatName(exportFormatNamed(name)), name);
    EXPECT_THROW(exportFormatNamed("shapefile"), InputError);
    EXPECT_EQ(exportFormatForExtension("a/b.GEOJSON"), ExportFormat::GeoJson);
    EXPECT_EQ(exportFormatForExtension("b.yml"), ExportFormat::RosPath);
    EXPECT_EQ(exportFormatForExtension("b.pdf"), ExportFormat::Pdf);
    EXPECT_FALSE(exportFormatForExtension("b.txt").has_value());
    EXPECT_EQ(defaultExportSubject(ExportFormat::Wgs84GeoJson), ExportSubject::Plan);
    EXPECT_EQ(defaultExportSubject(ExportFormat::Nav2), ExportSubject::Path);
    EXPECT_FALSE(exportSupports(ExportFormat::Vda5050, ExportSubject::Zones));
    EXPECT_THROW(exportSubjectNamed("robot"), InputError);
    EXPECT_THROW(exportToFormat(ExportFormat::Csv, ExportSubject::Plan, roomPlan(), {}, info()),
                 InputError);
}

TEST(Export, Nav2PosesCarryTheHeadingAsQuaternionXyzw) {
    const std::string yaml = pathToNav2Yaml(turningPath(), info());
    EXPECT_NE(yaml.find("# units: metres"), std::string::npos);
    std::vector<std::string> orientations, positions;
    std::istringstream in(yaml);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("      orientation: ", 0) == 0)
            orientations.push_back(line.substr(line.find('{')));
        if (line.rfind("      position: ", 0) == 0)
            positions.push_back(line.substr(line.find('{')));
    }
    ASSERT_EQ(orientations.size(), 4u) << "the repeated point is dropped";
    // heading pi/2: (0, 0, sin(pi/4), cos(pi/4)); pi: (0, 0, 1, 0); -pi/2: (0, 0, -sin, cos)
    EXPECT_EQ(orientations[0], "{x: 0.0, y: 0.0, z: 0.707106781, w: 0.707106781}");
    EXPECT_EQ(orientations[1], "{x: 0.0, y: 0.0, z: 1.0, w: 0.0}");
    EXPECT_EQ(orientations[2], "{x: 0.0, y: 0.0, z: -0.707106781, w: 0.707106781}");
    EXPECT_EQ(orientations[3], orientations[2]) << "the last pose keeps the last heading";
    EXPECT_EQ(positions[2], "{x: -1.0, y: 3.0, z: 0.0}");
}

TEST(Export, Fields2CoverStatesReadBackLikeItsLoader) {
    const std::string text = pathToFields2Cover(turningPath(), info());
    // Path::loadFile reads "x y z angle velocity len dir type" until a line does not parse.
    std::istringstream in(text);
    double x, y, z, angle, velocity, length, direction, type;
    std::vector<std::array<double, 8>> states;
    while (in >> x >> y >> z >> angle >> velocity >> length >> direction >> type)
        states.push_back({x, y, z, angle, velocity, length, direction, type});
    ASSERT_EQ(states.size(), 3u) << text;
    EXPECT_DOUBLE_EQ(states[0][0], 1.0);
    EXPECT_DOUBLE_EQ(states[0][1], 1.0);
    EXPECT_NEAR(states[0][3], M_PI / 2, 1e-9);
    EXPECT_NEAR(states[2][3], 3 * M_PI / 2, 1e-9) << "angles in [0, 2 pi)";
    EXPECT_DOUBLE_EQ(states[1][4], 0.4);
    EXPECT_DOUBLE_EQ(states[0][5] + states[1][5] + states[2][5], 2.0 + 2.0 + 3.0);
    EXPECT_EQ(states[1][7], 2.0) << "transit is a TURN section";
    EXPECT_EQ(states[2][7], 1.0) << "contour covers: a SWATH section";
    EXPECT_NE(text.find("# Fields2Cover path"), std::string::npos);
}

TEST(Export, Vda5050OrderHasEvenNodeAndOddEdgeSequenceIds) {
    const json order = json::parse(pathToVda5050(turningPath(), info()));
    EXPECT_EQ(order["version"], "2.0.0");
    EXPECT_EQ(order["timestamp"], "2026-01-02T03:04:05.000Z");
    const json& nodes = order["nodes"];
    const json& edges = order["edges"];
    ASSERT_EQ(nodes.size(), 4u);
    ASSERT_EQ(edges.size(), 3u);
    for (size_t i = 0; i < nodes.size(); ++i) {
        EXPECT_EQ(nodes[i]["sequenceId"], 2 * i);
        EXPECT_TRUE(nodes[i]["released"].get<bool>());
        EXPECT_LE(std::abs(nodes[i]["nodePosition"]["theta"].get<double>()), M_PI);
    }
    for (size_t i = 0; i < edges.size(); ++i) {
        EXPECT_EQ(edges[i]["sequenceId"], 2 * i + 1);
        EXPECT_EQ(edges[i]["startNodeId"], nodes[i]["nodeId"]);
        EXPECT_EQ(edges[i]["endNodeId"], nodes[i + 1]["nodeId"]);
    }
    EXPECT_DOUBLE_EQ(nodes[2]["nodePosition"]["x"].get<double>(), -1.0);
    EXPECT_DOUBLE_EQ(edges[2]["length"].get<double>(), 3.0);
    EXPECT_NE(nodes[0]["nodePosition"]["mapDescription"].get<std::string>().find("metres"),
              std::string::npos);
}

TEST(Export, ZonesAreTheRoomsOrTheWholeFloor) {
    const json rooms = json::parse(zonesToJson(roomPlan()));
    EXPECT_EQ(rooms["units"], "m");
    ASSERT_EQ(rooms["zones"].size(), 2u);
    EXPECT_EQ(rooms["zones"][1]["name"], "east");
    EXPECT_DOUBLE_EQ(rooms["zones"][1]["area"].get<double>(), 20.0);
    Plan floor = roomPlan();
    floor.rooms.clear();
    const json whole = json::parse(zonesToJson(floor));
    ASSERT_EQ(whole["zones"].size(), 1u);
    EXPECT_DOUBLE_EQ(whole["zones"][0]["area"].get<double>(), 40.0 - 1.0);
    EXPECT_EQ(whole["zones"][0]["holes"].size(), 1u);
    const json geo = json::parse(zonesToGeoJson(roomPlan()));
    EXPECT_EQ(geo["floorcover:crs"], "local metres");
    EXPECT_EQ(geo["features"][0]["properties"]["name"], "west");
}

TEST(Export, WktHoldsTheFloorThenTheRooms) {
    const std::string wkt = planToWkt(roomPlan());
    EXPECT_EQ(wkt.rfind("GEOMETRYCOLLECTION (POLYGON ((", 0), 0u) << wkt;
    size_t polygons = 0;
    for (size_t at = wkt.find("POLYGON"); at != std::string::npos; at = wkt.find("POLYGON", at + 1))
        ++polygons;
    EXPECT_EQ(polygons, 3u);
    const std::vector<double> numbers = numbersIn(wkt);
    // floor ring (5 closed positions), hole (5), two rooms (5 each): 20 positions
    ASSERT_EQ(numbers.size(), 40u);
    EXPECT_EQ(std::vector<double>(numbers.begin(), numbers.begin() + 4),
              (std::vector<double>{0, 0, 10, 0})); // counter-clockwise from (0, 0)
    Plan floor = roomPlan();
    floor.rooms.clear();
    EXPECT_EQ(planToWkt(floor).rfind("POLYGON ((", 0), 0u);
    EXPECT_EQ(pathToWkt(turningPath()), "LINESTRING (1.0 1.0, 1.0 3.0, -1.0 3.0, -1.0 0.0)\n");
}

TEST(Export, ReprojectsAKnownPointLikeCs2cs) {
    // echo "691875.632 6098907.825" | cs2cs -f %.9f EPSG:25832 EPSG:4326
    //   -> 55.000000000 11.999999998 (latitude, longitude)
    const std::vector<Vec2> lonLat = toWgs84({{691875.632, 6098907.825}}, 25832);
    ASSERT_EQ(lonLat.size(), 1u);
    EXPECT_NEAR(lonLat[0].x, 11.999999998, 2e-9);
    EXPECT_NEAR(lonLat[0].y, 55.000000000, 2e-9);
    EXPECT_THROW(toWgs84({{0, 0}}, 999999), InputError);
}

TEST(Export, Wgs84PlanGeoJsonIsRfc7946) {
    const Plan plan = readGeoJsonPlan(readFile(FC_TEST_DATA_DIR "/utm-offset.geojson"));
    ASSERT_EQ(plan.epsg, 32632);
    const json geo = json::parse(
        exportToFormat(ExportFormat::Wgs84GeoJson, ExportSubject::Plan, plan, {}, info()));
    EXPECT_FALSE(geo.contains("crs")) << "RFC 7946 has no crs member";
    EXPECT_EQ(geo["floorcover:source_crs"], "EPSG:32632");
    // echo "500012 5000000" | cs2cs -f %.9f EPSG:32632 EPSG:4326 -> 45.153477183 9.000152663
    const json& ring = geo["features"][0]["geometry"]["coordinates"][0];
    bool found = false;
    for (const json& position : ring)
        if (std::abs(position[0].get<double>() - 9.000152663) < 2e-9 &&
            std::abs(position[1].get<double>() - 45.153477183) < 2e-9)
            found = true;
    EXPECT_TRUE(found) << ring.dump();

    const json local = json::parse(
        exportToFormat(ExportFormat::Wgs84GeoJson, ExportSubject::Plan, roomPlan(), {}, info()));
    EXPECT_EQ(local["floorcover:crs"], "local metres");
    EXPECT_EQ(local["features"][0]["geometry"]["coordinates"][0][1][0], 10.0);
}

TEST(Export, SvgDrawsOverlapsInBlueAndPassesXmllint) {
    const std::string svg = planToSvg(roomPlan(), turningPath(), info());
    EXPECT_NE(svg.find("viewBox=\"-0.5 -4.5 11.0 5.0\""), std::string::npos) << svg.substr(0, 400);
    size_t blue = 0;
    for (size_t at = svg.find("#1a4df2"); at != std::string::npos; at = svg.find("#1a4df2", at + 1))
        ++blue;
    EXPECT_EQ(blue, 2u) << "one blue line per overlap segment";
    EXPECT_NE(svg.find(">west</text>"), std::string::npos);
    if (!toolAvailable("xmllint"))
        GTEST_SKIP() << "xmllint (libxml2-utils) is not installed";
    int status = 0;
    const std::string output =
        shellOutput("xmllint --noout " + writeTemporary("drawing.svg", svg), status);
    EXPECT_EQ(status, 0) << output;
}

TEST(Export, PdfCrossReferencesPointAtTheObjectsAndPassQpdf) {
    const std::string pdf = planToPdf(roomPlan(), turningPath(), info());
    ASSERT_EQ(pdf.rfind("%PDF-1.4", 0), 0u);
    const size_t xref = std::stoul(pdf.substr(pdf.rfind("startxref") + 10));
    ASSERT_EQ(pdf.compare(xref, 4, "xref"), 0);
    std::istringstream table(pdf.substr(xref));
    std::string word;
    int first = 0, count = 0;
    table >> word >> first >> count;
    ASSERT_EQ(count, 7);
    for (int object = 0; object < count; ++object) {
        std::string offset, generation, kind;
        table >> offset >> generation >> kind;
        if (object == 0)
            continue;
        const std::string header = std::to_string(object) + " 0 obj";
        EXPECT_EQ(pdf.compare(std::stoul(offset), header.size(), header), 0) << object;
    }
    if (!toolAvailable("qpdf"))
        GTEST_SKIP() << "qpdf is not installed";
    int status = 0;
    const std::string output =
        shellOutput("qpdf --check " + writeTemporary("drawing.pdf", pdf), status);
    EXPECT_EQ(status, 0) << output;
}

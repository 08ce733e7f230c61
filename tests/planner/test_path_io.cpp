// Path and graph exports: metrics line, GeoJSON (checked with GDAL's ogrinfo), CSV, JSON,
// ROS 2 YAML (checked with python3 yaml) and the corner graph JSON.
#include "formats/FileIO.h"
#include "formats/PathIO.h"
#include "formats/PlanIO.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace fc;
namespace fs = std::filesystem;

namespace {

CoveragePath squarePath(Vec2 origin) {
    CoveragePath path;
    path.points = {origin, origin + Vec2{4, 0}, origin + Vec2{4, 3}, origin + Vec2{0, 3},
                   origin + Vec2{0, 1}};
    path.kinds = {SegmentKind::Stripe, SegmentKind::Contour, SegmentKind::Stripe,
                  SegmentKind::Transit};
    return path;
}

PathExportInfo exportInfo() {
    PathExportInfo info;
    info.solver = "heuristic";
    info.metrics.length = 14.123456789;
    info.metrics.ideal = 12.0;
    info.metrics.extra = 2.123456789;
    info.metrics.turns = 3;
    info.metrics.coverage = 0.99876543;
    info.metrics.time = 34.1;
    info.metrics.cells = 5;
    info.metrics.graphCost = 17.5;
    info.metrics.seconds = 0.0123456;
    return info;
}

// Runs a shell command; returns its exit status and fills `output` with stdout+stderr.
int runCommand(const std::string& command, std::string& output) {
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe)
        return -1;
    std::array<char, 4096> buffer{};
    output.clear();
    size_t got;
    while ((got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
        output.append(buffer.data(), got);
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool commandAvailable(const std::string& check) {
    std::string ignored;
    return runCommand(check, ignored) == 0;
}

std::string temporaryFile(const std::string& name) {
    return (fs::temp_directory_path() / ("fc-pathio-" + std::to_string(::getpid()) + "-" + name))
        .string();
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

} // namespace

TEST(PathIO, MetricsLineHasTheSpecKeysInOrder) {
    const std::string line = metricsJsonLine("exact", exportInfo().metrics);
    EXPECT_EQ(line.find('\n'), std::string::npos);
    const auto object = nlohmann::ordered_json::parse(line);
    std::vector<std::string> keys;
    for (const auto& item : object.items())
        keys.push_back(item.key());
    const std::vector<std::string> expected = {
        "solver",         "length",           "ideal", "extra", "turns",      "coverage",
        "uncovered_area", "unreachable_area", "time",  "cells", "graph_cost", "seconds"};
    EXPECT_EQ(keys, expected);
    EXPECT_EQ(object["solver"], "exact");
    EXPECT_DOUBLE_EQ(object["length"].get<double>(), 14.1235);
    EXPECT_EQ(object["turns"], 3);
    EXPECT_EQ(object["cells"], 5);
    EXPECT_NEAR(object["coverage"].get<double>(), 0.998765, 1e-12);
    EXPECT_NE(line.find("\"length\":14.1235"), std::string::npos) << line;
}

TEST(PathIO, MetricsLineShowsAProvenLowerBoundAndGap) {
    Metrics metrics = exportInfo().metrics;
    metrics.graphCost = 110.0;
    metrics.lowerBound = 100.0;
    const auto object = nlohmann::ordered_json::parse(metricsJsonLine("heuristic", metrics));
    EXPECT_DOUBLE_EQ(object["lower_bound"].get<double>(), 100.0);
    EXPECT_NEAR(object["gap"].get<double>(), 0.1, 1e-9);
    EXPECT_EQ(std::prev(object.end()).key(), "gap"); // after the SPEC keys
}

TEST(PathIO, CsvHasHeaderOneRowPerWaypointAndHeadings) {
    const CoveragePath path = squarePath({0, 0});
    const auto rows = lines(pathToCsv(path));
    ASSERT_EQ(rows.size(), path.points.size() + 2);
    EXPECT_EQ(rows[0].rfind("# FloorCover path: x, y in metres, frame local metres", 0), 0u)
        << rows[0];
    EXPECT_EQ(rows[1], "x,y,heading,kind");
    EXPECT_EQ(rows[2], "0.0,0.0,0.0,stripe");
    EXPECT_EQ(rows[3], "4.0,0.0,1.570796,contour");
    EXPECT_EQ(rows[4], "4.0,3.0,3.141593,stripe");
    EXPECT_EQ(rows[5], "0.0,3.0,-1.570796,transit");
    EXPECT_EQ(rows[6], "0.0,1.0,-1.570796,transit") << "the last point keeps the heading";
    PathExportInfo utm;
    utm.epsg = 25832;
    EXPECT_NE(pathToCsv(path, utm).find("frame EPSG:25832;"), std::string::npos);
}

TEST(PathIO, JsonHoldsRobotMetricsAndWaypoints) {
    PathExportInfo info = exportInfo();
    info.robot.robotDiameter = 0.5;
    const auto root = nlohmann::json::parse(pathToJson(squarePath({0, 0}), info));
    EXPECT_EQ(root["solver"], "heuristic");
    EXPECT_EQ(root["units"], "m");
    EXPECT_EQ(root["robot"]["robot_diameter"], 0.5);
    EXPECT_EQ(root["metrics"]["turns"], 3);
    ASSERT_EQ(root["waypoints"].size(), 5u);
    EXPECT_EQ(root["waypoints"][1]["kind"], "contour");
    EXPECT_NEAR(root["waypoints"][1]["heading"].get<double>(), M_PI / 2, 1e-12);
}

TEST(PathIO, LargeCoordinatesKeepSubMillimetrePrecision) {
    const Vec2 origin{500000.123456, 5000000.654321};
    const CoveragePath path = squarePath(origin);
    const PathExportInfo info = exportInfo();
    const auto csvRow = lines(pathToCsv(path))[2];
    EXPECT_EQ(csvRow.rfind("500000.123456,5000000.654321,", 0), 0u) << csvRow;
    const auto json = nlohmann::json::parse(pathToJson(path, info));
    EXPECT_EQ(json["waypoints"][0]["x"].get<double>(), origin.x);
    EXPECT_EQ(json["waypoints"][0]["y"].get<double>(), origin.y);
    const auto geo = nlohmann::json::parse(pathToGeoJson(path, info));
    EXPECT_EQ(geo["features"][0]["geometry"]["coordinates"][0][1].get<double>(), origin.y);
    const std::string yaml = pathToRosYaml(path, info);
    EXPECT_NE(yaml.find("x: 500000.123456\n"), std::string::npos);
    EXPECT_NE(yaml.find("y: 5000000.654321\n"), std::string::npos);
}

TEST(PathIO, GeoJsonPassesOgrinfo) {
    if (!commandAvailable("command -v ogrinfo"))
        GTEST_SKIP() << "ogrinfo (gdal-bin) is not installed";
    for (const bool utm : {false, true}) {
        SCOPED_TRACE(utm ? "UTM coordinates with EPSG:32632" : "local coordinates");
        PathExportInfo info = exportInfo();
        if (utm)
            info.epsg = 32632;
        const std::string file = temporaryFile("path.geojson");
        const Vec2 origin = utm ? Vec2{500000, 5000000} : Vec2{1, 2};
        writeFileAtomically(file, pathToGeoJson(squarePath(origin), info));
        std::string output;
        const int status = runCommand("ogrinfo -ro -al -so '" + file + "'", output);
        fs::remove(file);
        EXPECT_EQ(status, 0) << output;
        EXPECT_NE(output.find("Line String"), std::string::npos) << output;
        EXPECT_NE(output.find("Feature Count: 1"), std::string::npos) << output;
        EXPECT_NE(output.find("graph_cost: Real"), std::string::npos) << output;
        EXPECT_NE(output.find("solver: String"), std::string::npos) << output;
        EXPECT_EQ(output.find("32632") != std::string::npos, utm) << output;
    }
}

TEST(PathIO, RosYamlParsesAsNavMsgsPath) {
    if (!commandAvailable("python3 -c 'import yaml'"))
        GTEST_SKIP() << "python3 with the yaml module is not available";
    PathExportInfo info = exportInfo();
    info.frameId = "map: \"odd\" frame";
    const CoveragePath path = squarePath({500000.5, 5000000.25});
    const std::string file = temporaryFile("path.yaml");
    writeFileAtomically(file, pathToRosYaml(path, info));
    const std::string script =
        "import math, sys, yaml\n"
        "d = yaml.safe_load(open(sys.argv[1]))\n"
        "assert d['header']['frame_id'] == 'map: \"odd\" frame', d['header']\n"
        "assert d['header']['stamp'] == {'sec': 0, 'nanosec': 0}\n"
        "poses = d['poses']\n"
        "assert len(poses) == 5, len(poses)\n"
        "p = poses[1]['pose']\n"
        "assert p['position'] == {'x': 500004.5, 'y': 5000000.25, 'z': 0.0}, p\n"
        "q = p['orientation']\n"
        "assert abs(q['z'] - math.sin(math.pi / 4)) < 1e-8 and q['x'] == 0.0, q\n"
        "assert abs(q['z'] ** 2 + q['w'] ** 2 - 1) < 1e-8\n"
        "assert poses[0]['header']['frame_id'] == d['header']['frame_id']\n";
    std::string output;
    const std::string scriptFile = temporaryFile("check.py");
    writeFileAtomically(scriptFile, script);
    const int checked = runCommand("python3 '" + scriptFile + "' '" + file + "'", output);
    fs::remove(file);
    fs::remove(scriptFile);
    EXPECT_EQ(checked, 0) << output;

    CoveragePath empty;
    EXPECT_NE(pathToRosYaml(empty, info).find("poses: []"), std::string::npos);
}

TEST(PathIO, FormatChosenByExtension) {
    const CoveragePath path = squarePath({0, 0});
    const PathExportInfo info = exportInfo();
    EXPECT_EQ(pathToFormat("out.geojson", path, info), pathToGeoJson(path, info));
    EXPECT_EQ(pathToFormat("dir/out.CSV", path, info), pathToCsv(path, info));
    EXPECT_EQ(pathToFormat("out.json", path, info), pathToJson(path, info));
    EXPECT_EQ(pathToFormat("out.yaml", path, info), pathToRosYaml(path, info));
    EXPECT_EQ(pathToFormat("out.yml", path, info), pathToRosYaml(path, info));
    try {
        pathToFormat("out.txt", path, info);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("\".txt\""), std::string::npos) << e.what();
    }
    EXPECT_THROW(pathToFormat("noextension", path, info), InputError);
}

TEST(PathIO, GraphJsonFollowsSpec) {
    Decomposition decomposition;
    decomposition.frame = Frame({100, 200}, 0.0); // horizontal stripes: a rotated frame
    decomposition.roomNames = {"Kitchen", "Hall"};
    CornerGraph graph;
    graph.cells.resize(2);
    graph.cells[0].id = 0;
    graph.cells[0].room = 0;
    graph.cells[1].id = 1;
    graph.cells[1].kind = CellKind::Transition;
    graph.cells[1].room = 1;
    const int lb = graph.addNode(0, CornerKind::LB, {0.5, 0.5});
    const int lt = graph.addNode(0, CornerKind::LT, {0.5, 3.5});
    const int bottom = graph.addNode(1, CornerKind::Bottom, {4.5, 0.5});
    GraphEdge coverage;
    coverage.u = lb;
    coverage.v = lt;
    coverage.kind = EdgeKind::Coverage;
    coverage.cell = 0;
    coverage.length = 10.0;
    graph.addEdge(coverage);
    GraphEdge contour = coverage;
    contour.kind = EdgeKind::Contour;
    contour.parallel = true;
    contour.length = 3.0;
    graph.addEdge(contour);
    GraphEdge inter;
    inter.u = lt;
    inter.v = bottom;
    inter.length = 5.0;
    graph.addEdge(inter);

    const auto root = nlohmann::json::parse(graphToJson(graph, decomposition));
    ASSERT_EQ(root["nodes"].size(), 3u);
    const Vec2 world = decomposition.frame.toWorld({0.5, 3.5});
    EXPECT_EQ(root["nodes"][1]["id"], 1);
    EXPECT_DOUBLE_EQ(root["nodes"][1]["x"].get<double>(), world.x);
    EXPECT_DOUBLE_EQ(root["nodes"][1]["y"].get<double>(), world.y);
    EXPECT_EQ(root["nodes"][2]["cell"], 1);
    ASSERT_EQ(root["cells"].size(), 2u);
    EXPECT_EQ(root["cells"][0]["kind"], "primary");
    EXPECT_EQ(root["cells"][0]["room"], "Kitchen");
    EXPECT_EQ(root["cells"][0]["coverage_edges"], nlohmann::json::array({0}));
    EXPECT_EQ(root["cells"][1]["kind"], "transition");
    EXPECT_EQ(root["cells"][1]["room"], "Hall");
    ASSERT_EQ(root["edges"].size(), 3u);
    EXPECT_EQ(root["edges"][0]["kind"], "coverage");
    EXPECT_EQ(root["edges"][0]["cost"], 0.0);
    EXPECT_EQ(root["edges"][1]["kind"], "contour");
    EXPECT_EQ(root["edges"][1]["parallel"], true);
    EXPECT_DOUBLE_EQ(root["edges"][1]["cost"].get<double>(), 9.0);
    EXPECT_EQ(root["edges"][2]["kind"], "inter");
    EXPECT_EQ(root["edges"][2]["u"], lt);
    EXPECT_EQ(root["edges"][2]["v"], bottom);
    EXPECT_DOUBLE_EQ(root["edges"][2]["cost"].get<double>(), 5.0);
    EXPECT_DOUBLE_EQ(root["edges"][2]["length"].get<double>(), 5.0);
}

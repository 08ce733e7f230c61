// Path exports (SPEC sect. 6-7): metrics line, GeoJSON, CSV, JSON and ROS 2 nav_msgs/Path.
#include "formats/PathIO.h"
#include "formats/WriterSupport.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fc {

using nlohmann::ordered_json;

namespace {

using formats::dumped;
using formats::fixedNumber;
using formats::headingsOf;
using formats::kindAt;
using formats::rounded;

ordered_json metricsObject(const std::string& solver, const Metrics& m) {
    ordered_json object;
    object["solver"] = solver;
    object["length"] = rounded(m.length, 4);
    object["ideal"] = rounded(m.ideal, 4);
    object["extra"] = rounded(m.extra, 4);
    object["turns"] = m.turns;
    object["coverage"] = rounded(m.coverage, 6);
    object["uncovered_area"] = rounded(m.uncoveredArea, 4);
    object["unreachable_area"] = rounded(m.unreachableArea, 4);
    object["time"] = rounded(m.time, 4);
    object["cells"] = m.cells;
    object["graph_cost"] = rounded(m.graphCost, 4);
    object["seconds"] = rounded(m.seconds, 6);
    if (m.lowerBound > 0.0) { // proven by the solver: graph_cost is within `gap` of optimal
        object["lower_bound"] = rounded(m.lowerBound, 4);
        object["gap"] = rounded(m.graphCost / m.lowerBound - 1.0, 6);
    }
    return object;
}

ordered_json robotObject(const RobotProfile& robot) {
    return {{"robot_diameter", robot.robotDiameter},
            {"cleaning_diameter", robot.cleaningDiameter},
            {"coverage_width", robot.coverageWidth},
            {"speed", robot.speed},
            {"turn_time", robot.turnTime}};
}

std::string lowerCaseExtension(const std::string& fileName) {
    std::string extension = std::filesystem::path(fileName).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

} // namespace

std::string metricsJsonLine(const std::string& solver, const Metrics& metrics) {
    return dumped(metricsObject(solver, metrics), -1);
}

std::string pathToGeoJson(const CoveragePath& path, const PathExportInfo& info) {
    ordered_json properties = metricsObject(info.solver, info.metrics);
    properties["W"] = info.robot.coverageWidth;
    properties["L"] = info.robot.robotDiameter;
    properties["D"] = info.robot.cleaningDiameter;
    properties["units"] = "m";

    ordered_json geometry; // null when there is no line to draw
    if (path.points.size() >= 2) {
        ordered_json coordinates = ordered_json::array();
        for (const Vec2& p : path.points)
            coordinates.push_back({p.x, p.y});
        geometry = {{"type", "LineString"}, {"coordinates", std::move(coordinates)}};
    }
    ordered_json feature;
    feature["type"] = "Feature";
    feature["properties"] = std::move(properties);
    feature["geometry"] = std::move(geometry);

    ordered_json root;
    root["type"] = "FeatureCollection";
    root["name"] = "coverage_path";
    if (info.epsg)
        root["crs"] = {
            {"type", "name"},
            {"properties", {{"name", "urn:ogc:def:crs:EPSG::" + std::to_string(*info.epsg)}}}};
    root["features"] = ordered_json::array({std::move(feature)});
    return dumped(root, -1) + "\n";
}

std::string pathToCsv(const CoveragePath& path, const PathExportInfo& info) {
    const std::vector<double> headings = headingsOf(path.points);
    std::ostringstream out;
    out << "# FloorCover path: x, y in metres, frame " << formats::frameDescription(info.epsg)
        << "; heading in radians counter-clockwise from +x; kind stripe|contour|transit\n";
    out << "x,y,heading,kind\n";
    for (size_t i = 0; i < path.points.size(); ++i) {
        const Vec2 p = path.points[i];
        out << fixedNumber(p.x, 6) << ',' << fixedNumber(p.y, 6) << ','
            << fixedNumber(headings[i], 6) << ',' << kindAt(path, i) << '\n';
    }
    return out.str();
}

std::string pathToJson(const CoveragePath& path, const PathExportInfo& info) {
    ordered_json metrics = metricsObject(info.solver, info.metrics);
    metrics.erase("solver");
    metrics["sweepable_area"] = rounded(info.metrics.sweepableArea, 4);
    metrics["covered_area"] = rounded(info.metrics.coveredArea, 4);

    const std::vector<double> headings = headingsOf(path.points);
    ordered_json waypoints = ordered_json::array();
    for (size_t i = 0; i < path.points.size(); ++i) {
        waypoints.push_back({{"x", path.points[i].x},
                             {"y", path.points[i].y},
                             {"heading", headings[i]},
                             {"kind", kindAt(path, i)}});
    }
    ordered_json root;
    root["solver"] = info.solver;
    root["units"] = "m";
    root["heading_units"] = "rad";
    root["frame"] = formats::frameDescription(info.epsg);
    root["robot"] = robotObject(info.robot);
    root["metrics"] = std::move(metrics);
    root["waypoints"] = std::move(waypoints);
    return dumped(root, -1) + "\n";
}

std::string pathToRosYaml(const CoveragePath& path, const PathExportInfo& info) {
    // A JSON string is a valid YAML double-quoted scalar, so any frame id is safe.
    const std::string frameId = dumped(ordered_json(info.frameId), -1);
    const std::vector<double> headings = headingsOf(path.points);
    std::ostringstream out;
    out << "# nav_msgs/msg/Path: robot-centre waypoints in metres (solver "
        << dumped(ordered_json(info.solver), -1) << ")\n";
    out << "# frame: " << formats::frameDescription(info.epsg)
        << "; orientation: quaternion x, y, z, w about +z\n";
    out << "header:\n  stamp:\n    sec: 0\n    nanosec: 0\n  frame_id: " << frameId << "\n";
    if (path.points.empty()) {
        out << "poses: []\n";
        return out.str();
    }
    out << "poses:\n";
    for (size_t i = 0; i < path.points.size(); ++i) {
        const Vec2 p = path.points[i];
        const double half = headings[i] / 2.0;
        out << "  - header:\n      stamp:\n        sec: 0\n        nanosec: 0\n"
            << "      frame_id: " << frameId << "\n"
            << "    pose:\n      position:\n"
            << "        x: " << fixedNumber(p.x, 6) << "\n"
            << "        y: " << fixedNumber(p.y, 6) << "\n"
            << "        z: 0.0\n"
            << "      orientation:\n        x: 0.0\n        y: 0.0\n"
            << "        z: " << fixedNumber(std::sin(half), 9) << "\n"
            << "        w: " << fixedNumber(std::cos(half), 9) << "\n";
    }
    return out.str();
}

std::string pathToFormat(const std::string& fileName, const CoveragePath& path,
                         const PathExportInfo& info) {
    const std::string extension = lowerCaseExtension(fileName);
    if (extension == ".geojson")
        return pathToGeoJson(path, info);
    if (extension == ".csv")
        return pathToCsv(path, info);
    if (extension == ".json")
        return pathToJson(path, info);
    if (extension == ".yaml" || extension == ".yml")
        return pathToRosYaml(path, info);
    requirePathFormat(fileName);
    return {};
}

void requirePathFormat(const std::string& fileName) {
    const std::string extension = lowerCaseExtension(fileName);
    for (const char* known : {".geojson", ".csv", ".json", ".yaml", ".yml"})
        if (extension == known)
            return;
    throw InputError(
        fileName + ": unsupported path format " +
        (extension.empty() ? std::string("(no file extension)") : "\"" + extension + "\"") +
        "; expected .geojson, .csv, .json, .yaml or .yml");
}

namespace formats {

double rounded(double value, int decimals) {
    if (!std::isfinite(value))
        return value;
    const double scale = std::pow(10.0, decimals);
    const double result = std::round(value * scale) / scale;
    return result == 0.0 ? 0.0 : result; // no "-0.0"
}

// Fixed-point text with trailing zeros trimmed ("12.5", "4.0"). Fixed notation keeps
// sub-millimetre precision for UTM-sized coordinates, where %g would drop digits.
std::string fixedNumber(double value, int decimals) {
    if (!std::isfinite(value))
        return std::isnan(value) ? ".nan" : (value > 0 ? ".inf" : "-.inf");
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded(value, decimals));
    std::string text = buffer;
    const size_t dot = text.find('.');
    if (dot != std::string::npos) {
        const size_t last = text.find_last_not_of('0');
        text.erase(std::max(last + 1, dot + 2));
    }
    return text;
}

std::string dumped(const ordered_json& value, int indent) {
    return value.dump(indent, ' ', false, ordered_json::error_handler_t::replace);
}

// Heading (radians) of travel from each point to the next. Zero-length steps and the
// last point keep the previous heading; leading zero-length steps take the first real one.
std::vector<double> headingsOf(const Polyline& points) {
    std::vector<double> headings(points.size(), 0.0);
    double current = 0.0;
    bool known = false;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
        const Vec2 step = points[i + 1] - points[i];
        if (step.x != 0.0 || step.y != 0.0) {
            current = std::atan2(step.y, step.x);
            if (!known)
                std::fill(headings.begin(), headings.begin() + i, current);
            known = true;
        }
        headings[i] = current;
    }
    if (!points.empty())
        headings.back() = current;
    return headings;
}

// Kind of the segment leaving point i; the last point keeps the kind of the last segment.
const char* kindAt(const CoveragePath& path, size_t i) {
    if (path.kinds.empty())
        return segmentKindName(SegmentKind::Transit);
    return segmentKindName(path.kinds[std::min(i, path.kinds.size() - 1)]);
}

std::string frameDescription(const std::optional<int>& epsg) {
    return epsg ? "EPSG:" + std::to_string(*epsg)
                : std::string("local metres (no coordinate reference)");
}

double ringArea(const Ring& ring) {
    double twice = 0.0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return std::abs(twice) / 2.0;
}

} // namespace formats

} // namespace fc

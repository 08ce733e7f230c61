// Path exports: GeoJSON, CSV, JSON, ROS 2 nav_msgs/Path YAML, Nav2 FollowWaypoints YAML,
// Fields2Cover path text and VDA 5050 orders; the corner graph as JSON. Coordinates stay in
// the plan's frame (metres); every file states its units and frame (docs/formats.md).
#pragma once

#include "graph/CornerGraph.h"
#include "metrics/Metrics.h"
#include "model/CoveragePath.h"

#include <optional>
#include <string>

namespace fc {

struct PathExportInfo {
    std::string solver;
    RobotProfile robot;
    Metrics metrics;
    std::string frameId = "map"; // ROS frame
    std::optional<int> epsg;     // the plan's coordinate reference, stated in every file
    // VDA 5050 order header; an empty timestamp means "now" (UTC, ISO 8601).
    std::string manufacturer = "FloorCover";
    std::string serialNumber = "robot-1";
    std::string orderId = "coverage";
    std::string mapId = "map";
    std::string timestamp;
};

std::string metricsJsonLine(const std::string& solver, const Metrics& metrics);
std::string pathToGeoJson(const CoveragePath& path, const PathExportInfo& info);
// A "# ..." comment line stating units and frame, then the header x,y,heading,kind.
std::string pathToCsv(const CoveragePath& path, const PathExportInfo& info = {});
std::string pathToJson(const CoveragePath& path, const PathExportInfo& info);
std::string pathToRosYaml(const CoveragePath& path, const PathExportInfo& info);
// nav2_msgs/action/FollowWaypoints goal: `poses` of geometry_msgs/PoseStamped, orientation
// as a quaternion x, y, z, w about the z axis (the heading of the segment leaving the pose).
std::string pathToNav2Yaml(const CoveragePath& path, const PathExportInfo& info);
// Fields2Cover 2.x Path::saveToFile: one state per segment, "x y z angle velocity len dir
// type" (dir 1 = forward; type 1 = swath, 2 = turn), then one "# ..." line with the units.
std::string pathToFields2Cover(const CoveragePath& path, const PathExportInfo& info);
// VDA 5050 2.0.0 order: one node per waypoint (sequenceId 0, 2, 4, ...) and one edge
// between consecutive nodes (1, 3, 5, ...), all released.
std::string pathToVda5050(const CoveragePath& path, const PathExportInfo& info);
// The path as a WKT LINESTRING in the plan's frame.
std::string pathToWkt(const CoveragePath& path);
// Throws InputError, naming the file, unless its extension is one pathToFormat writes (so a
// command can refuse it before it plans).
void requirePathFormat(const std::string& fileName);
// Chooses the writer from the file extension; throws InputError for an unknown one.
std::string pathToFormat(const std::string& fileName, const CoveragePath& path,
                         const PathExportInfo& info);

// SPEC sect. 7 graph JSON; node coordinates in the world frame.
std::string graphToJson(const CornerGraph& graph, const Decomposition& decomposition);

} // namespace fc

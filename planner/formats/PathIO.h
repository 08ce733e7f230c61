// Path exports: GeoJSON, CSV, JSON and ROS 2 nav_msgs/Path YAML; the corner graph as JSON.
#pragma once

#include "graph/CornerGraph.h"
#include "metrics/Metrics.h"
#include "path/CoveragePath.h"

#include <optional>
#include <string>

namespace fc {

struct PathExportInfo {
    std::string solver;
    RobotProfile robot;
    Metrics metrics;
    std::string frameId = "map"; // ROS frame
    std::optional<int> epsg;     // the plan's coordinate reference, written to GeoJSON
};

std::string metricsJsonLine(const std::string& solver, const Metrics& metrics);
std::string pathToGeoJson(const CoveragePath& path, const PathExportInfo& info);
std::string pathToCsv(const CoveragePath& path); // x,y,heading,kind
std::string pathToJson(const CoveragePath& path, const PathExportInfo& info);
std::string pathToRosYaml(const CoveragePath& path, const PathExportInfo& info);
// Chooses the writer from the file extension; throws InputError for an unknown one.
std::string pathToFormat(const std::string& fileName, const CoveragePath& path,
                         const PathExportInfo& info);

// SPEC sect. 7 graph JSON; node coordinates in the world frame.
std::string graphToJson(const CornerGraph& graph, const Decomposition& decomposition);

} // namespace fc

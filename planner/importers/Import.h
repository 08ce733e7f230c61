// Importing floor plans from other formats (issue 5): 2D CAD (DXF, via GDAL's OGR), robot
// occupancy maps (ROS map_server YAML + image), WKT, GeoJSON, and 3D building models (IFC,
// OBJ, glTF/GLB, STL, via assimp). Every importer turns its source into the same Project
// (plan in metres, the source's frame) and reports what it could not use instead of
// silently dropping it.
#pragma once

#include "formats/PlanIO.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

// Which source layers (DXF layers, 3D-model node/material names) feed which role. Empty
// lists mean "guess from the layer names" (e.g. WALL/BOUNDARY, OBST/COLUMN/FURN, ROOM/SPACE).
struct LayerMapping {
    std::vector<std::string> boundary;
    std::vector<std::string> obstacles;
    std::vector<std::string> rooms;
    std::vector<std::string> ignored;
};

struct ImportOptions {
    LayerMapping layers;
    std::optional<double> metresPerUnit; // overrides the file's own unit ($INSUNITS, ...)
    double gapTolerance = 0.05;          // m: open chains closed when ends are this close
    std::optional<int> epsg;             // coordinate reference to record on the plan
    // 3D building models
    std::string storey;           // IFC storey name (empty: the lowest one)
    double sliceHeight = 0.3;     // m above the storey's floor
    bool ignoreDoorLeaves = true; // door panels do not block the section
    // Occupancy maps
    double simplifyTolerance = 0.05; // m, Douglas-Peucker on the traced free-space outline
};

// What the source held, for an import dialog to offer before the final import.
struct ImportPreview {
    std::string format;               // "dxf", "ros-map", "wkt", "geojson", "ifc", "obj", ...
    std::vector<std::string> layers;  // source layers / node names, in file order
    std::vector<std::string> storeys; // IFC storeys, lowest first
    std::optional<double> metresPerUnit;
};

struct ImportResult {
    Project project;
    std::vector<std::string> warnings;  // stray segments, dropped entities, unit guesses...
    std::optional<Vec2> robotStartPose; // occupancy maps: the robot's recorded pose, if any
};

// Reads FILE, choosing the importer from its extension (or its content for .yaml/.json).
// Throws InputError("FILE: problem") for unreadable, corrupt, hostile or empty sources.
ImportResult importPlanFile(const std::string& path, const ImportOptions& options = {});
ImportPreview previewImport(const std::string& path);
// Boundary area minus the obstacles' (which do not overlap in a valid plan), m^2.
double freeAreaOf(const Plan& plan);

// The extensions importPlanFile accepts (lower case, without the dot).
std::vector<std::string> importableExtensions();
// The role a layer's name suggests when LayerMapping is empty: "boundary", "obstacles",
// "rooms", "ignored", or "" (no guess: the geometric rule decides). See docs/formats.md.
std::string guessLayerRole(const std::string& layer);

} // namespace fc

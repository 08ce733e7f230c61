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

// Occupancy maps (issue 15): how the SLAM map is cleaned before it is traced. Defaults suit
// 2-10 cm cells; every step can be switched off (a radius or area of 0).
struct MapCleaningOptions {
    bool enabled = true;          // false: every free cell is traced as it is
    bool unknownIsFree = false;   // unknown cells (between the thresholds) as floor, not wall
    double unknownGapArea = 0.15; // m^2: unknown patches inside the map smaller than this
                                  // become floor (with unknown as wall)
    double speckleArea = 0.15;    // m^2: obstacle specks smaller than this become floor
    bool smoothEdges = true;      // a 3 x 3 majority vote on ragged wall edges (on maps with
                                  // cells of at most a sixth of the robot's diameter)
    double fragmentArea = 0.5;    // m^2: free islands smaller than this are dropped
    double openingRadius = -1;    // m: free slivers and wall notches narrower than twice this
                                  // are filled; negative: the robot's radius (what its body
                                  // cannot enter; its swath still reaches W/2 from its centre)
    double closingRadius = 0;     // m: obstacles thinner than twice this vanish (0: off, as
                                  // interior walls in laser maps are often a cell or two thick)
    // The opening and closing radii are at most this (the import dialog's limit): beyond, a
    // disc of radius r / resolution cells made OpenCV allocate terabytes.
    static constexpr double kMaxMorphologyRadius = 5.0; // m
    double simplifyCells = 0.45;   // Douglas-Peucker tolerance in cells (below half a cell, so
                                   // that a wall keeps both ends of its traced corners), and
    double simplifyRobotShare = 0; // at least this share of the robot's diameter (0: off;
                                   // coarser outlines plan faster but tilt short walls)
    bool straightenWalls = true;   // walls fitted as lines along the map's two dominant wall
                                   // directions (when it has them), each within `wallBand`
    double wallBand = 1.0;         // cells: how far a straightened wall may lie from a traced
                                   // point it replaces (a tooth this thin becomes floor)
    double notchDepth = 0.1;       // m: notches into a straightened wall up to this deep are
                                   // filled (floor lost, reported)
};

// Occupancy maps: splitting the free space into rooms at doorways.
enum class RoomSegmentationMethod { None, Distance, Morphological };
struct RoomSegmentationOptions {
    RoomSegmentationMethod method = RoomSegmentationMethod::Distance;
    double minRoomArea = 1.0;  // m^2: smaller room cores (alcoves, door recesses) join a room
    double maxDoorWidth = 1.6; // m: rooms meeting along more than this are one room (0: off)
    // Rooms whose border spans most of the floor on both sides are one room too. The
    // importer turns it off on maps it did not clean: speckle shortens the widths measured.
    bool mergeAcrossNarrowings = true;
};

// What cleaning removed, for the import report.
struct MapCleaningReport {
    int width = 0, height = 0;
    double resolution = 0;
    long long unknownCells = 0;
    int gapsFilled = 0; // unknown patches that became floor
    double gapArea = 0; // m^2
    int specksRemoved = 0;
    double speckArea = 0; // m^2
    int fragmentsDropped = 0;
    double fragmentArea = 0; // m^2
    double openedArea = 0;   // m^2 of free space filled by the opening
    double closedArea = 0;   // m^2 of obstacle turned into floor by the closing
    // Obstacles joined to another or to a wall across a traced passage narrower than the
    // robot, and the floor those passages took (m^2).
    int obstaclesJoined = 0;
    double passageArea = 0;
    double smoothedArea = 0; // m^2 of floor gained (negative: lost) by smoothing the edges
    double freeAreaBefore = 0, freeAreaAfter = 0;
    int verticesTraced = 0, verticesKept = 0;
    std::optional<double> wallAngle; // degrees in [0, 90), map frame, when walls were straightened
    int wallsStraightened = 0;       // walls fitted as lines
    int notchesFilled = 0;
    double straightenedAdded = 0, straightenedRemoved = 0; // m^2 of floor
    int rooms = 0;
    int doorwaysAligned = 0; // rooms' borders in doorways moved onto a wall line
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
    double simplifyTolerance = -1; // m, Douglas-Peucker; negative: MapCleaningOptions' cells
    MapCleaningOptions cleaning;
    RoomSegmentationOptions roomSegmentation;
    double robotDiameter = 0.6; // m: ties the cleaning radii to the robot
    // An editor opens a plan that validatePlan refuses for repair (repairPlan); the
    // problem is then a warning, not an error. The CLI keeps refusing.
    bool keepInvalid = false;
    // GeoJSON sites of several buildings (boundary polygons): the one to import, 1 = the
    // largest (readGeoJsonPlan). Other formats keep their largest part and warn of the rest.
    std::optional<int> building;
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
    std::vector<std::string> warnings;         // stray segments, dropped entities, unit guesses...
    std::optional<Vec2> robotStartPose;        // occupancy maps: the robot's recorded pose, if any
    std::optional<MapCleaningReport> cleaning; // occupancy maps: what cleaning did
};

// Reads FILE, choosing the importer from its extension (or its content for .yaml/.json).
// Throws InputError("FILE: problem") for unreadable, corrupt, hostile or empty sources.
ImportResult importPlanFile(const std::string& path, const ImportOptions& options = {});
ImportPreview previewImport(const std::string& path);

// A plan that validatePlan refuses, made valid with GEOS (through GDAL's OGR): rings that
// cross or touch themselves are split at the crossings (MakeValid), the free space is the
// boundary minus the union of the obstacles (so obstacles that overlap, touch, cross the
// wall or lie outside are merged, clipped or dropped), and only its largest connected part
// is kept; rooms are made valid, clipped to the free space and to the rooms before them,
// renamed when unnamed or duplicated. `notes` says in plain words what changed and how much
// area it moved. Throws InputError when nothing plannable is left.
Plan repairPlan(const Plan& plan, std::vector<std::string>& notes);

// The extensions importPlanFile accepts (lower case, without the dot).
std::vector<std::string> importableExtensions();
// The role a layer's name suggests when LayerMapping is empty: "boundary", "obstacles",
// "rooms", "ignored", or "" (no guess: the geometric rule decides). See docs/formats.md.
std::string guessLayerRole(const std::string& layer);

} // namespace fc

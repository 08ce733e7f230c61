// Internal to the importers (formats/Import*.cpp, DxfImport.cpp, RosMapImport.cpp): the
// pieces a source is broken into before it becomes a plan, and the shared assembly step.
#pragma once

#include "importers/Import.h"

#include <string>
#include <vector>

namespace fc::importing {

// Limits against huge or hostile sources (each gives a clear InputError when exceeded).
constexpr size_t kMaxSourceBytes = 256u << 20;  // 256 MiB
constexpr size_t kMaxEntities = 200000;         // DXF features
constexpr size_t kMaxVertices = 4000000;        // all rings and lines together
constexpr size_t kMaxOpenPieces = 50000;        // open lines chained into outlines
constexpr long long kMaxMapPixels = 64ll << 20; // occupancy map width x height

enum class Role { Boundary, Obstacle, Room, Ignored, Unassigned };
Role roleOfLayer(const std::string& layer, const LayerMapping& mapping);

struct Outline { // a closed ring from the source, in metres
    Ring ring;
    std::string layer;
};
struct Piece { // an open line from the source, in metres
    Polyline line;
    std::string layer;
};
struct Label { // TEXT / MTEXT insertion point and contents
    Vec2 at;
    std::string text;
};

// Chains open pieces of the same layer end to end (ends within `gap`, either direction)
// and returns the chains that close; what stays open is counted into `warnings` per layer.
std::vector<Outline> closeChains(std::vector<Piece> pieces, double gap,
                                 std::vector<std::string>& warnings);

// The plan from classified outlines (PlanAssembly.cpp, GEOS through GDAL): the boundary is
// the largest boundary-layer outline (or, when there is none, the largest unassigned one);
// obstacle outlines, unassigned and other boundary-layer outlines inside it are merged and
// cut out of it; room outlines become rooms named by the label inside them.
Plan assemblePlan(const std::vector<Outline>& outlines, const std::vector<Label>& labels,
                  const LayerMapping& mapping, std::vector<std::string>& warnings);

// Free space polygons (shell + holes, metres) to a plan: the largest is the boundary.
struct Polygon2 {
    Ring shell;
    std::vector<Ring> holes;
};
Plan planFromPolygons(std::vector<Polygon2> polygons, const std::string& what,
                      std::vector<std::string>& warnings);

// The importers. Each throws InputError with a message WITHOUT the file name (the
// dispatcher adds it).
ImportResult importDxf(const std::string& path, const ImportOptions& options);
ImportPreview previewDxf(const std::string& path);
ImportResult importWkt(const std::string& text, const ImportOptions& options);
ImportResult importRosMap(const std::string& yamlPath, const ImportOptions& options);

// A ROS map_server map description (RosMapYaml.cpp). Keys: image, resolution, origin
// [x, y, yaw], occupied_thresh, free_thresh, negate, mode (trinary | scale | raw), and the
// robot's start: start_pose [x, y, yaw] or AMCL's initial_pose_x / initial_pose_y.
struct RosMapInfo {
    std::string image; // as written (relative to the YAML file's folder)
    double resolution = 0;
    Vec2 origin;
    double yaw = 0;
    double occupiedThresh = 0.65;
    double freeThresh = 0.196;
    bool negate = false;
    std::string mode = "trinary";
    std::optional<Vec2> start;
};
RosMapInfo parseRosMapYaml(const std::string& text);

// A grey image (0..255 per pixel, row 0 at the top), alpha kept when present.
struct GreyImage {
    int width = 0, height = 0;
    std::vector<unsigned char> grey;
    std::vector<unsigned char> alpha; // empty: opaque
};
// 1- to 16-bit images scaled to 0..255 (white = the largest value of the bit depth).
GreyImage readPgm(const std::string& bytes);          // PGM P2 / P5, PBM P1 / P4
GreyImage readImageWithGdal(const std::string& path); // PNG, BMP, TIFF: palettes expanded,
                                                      // colour channels averaged
GreyImage readMapImage(const std::string& path);      // by extension: .pgm/.pbm or GDAL

// GDAL's drivers registered once; its error handler silenced (messages are read back).
void ensureGdal();

} // namespace fc::importing

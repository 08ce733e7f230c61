// Internal to the occupancy-map importer: grids of cells traced into OGR polygons (GDAL's
// polygonizer), simplified, placed in the map frame, and the rooms of a segmentation.
// Include only from the importers' .cpp files.
#pragma once

#include "importers/OccupancyGrid.h"
#include "importers/OgrSupport.h"

#include <cstdint>
#include <map>
#include <optional>

namespace fc::importing {

// The cells of each value of `values` where `mask` is set, traced along the cell edges
// (4-connected), in pixel units (x right, y down): one multipolygon per value.
std::map<std::int32_t, GeometryPtr> traceCells(const std::vector<std::int32_t>& values,
                                               const std::vector<unsigned char>& mask, int width,
                                               int height);

// Douglas-Peucker within `tolerance` pixels (topology kept), then opened by a twentieth of a
// pixel so that a hole touching the outline at a pixel corner joins it.
GeometryPtr simplifiedCells(const OGRGeometry& traced, double tolerance);

// `g`'s polygons opened by `radius` (pixels; GEOS buffers, one segment per quarter circle).
// A polygon of many holes is opened in parts (SubpixelOpening.cpp): one buffer over all of an
// uncleaned laser map's speckle holes placed each hole against an index rebuilt for it (2 of
// a 3 s import).
GeometryPtr openedPolygons(const OGRGeometry& g, double radius);

// The free space without its passages narrower than 2 `radius` (pixels) between two walls:
// obstacles the robot cannot pass between become one, or part of the wall (a diagonal line of
// one-cell specks, traced through the cells' edge midpoints as a dotted line of diamonds,
// split a lab's floor into hundreds of sliver cells, each with its own stripe). A passage is
// what an opening by the robot's round body takes away and touches two separate walls; the
// rest of the outline is returned as it was (wedges and notches of one wall included).
struct PassageClosing {
    GeometryPtr free;
    int obstaclesJoined = 0; // to another or to the outline
    double area = 0;         // pixels taken from the floor
};
PassageClosing withoutNarrowPassages(const OGRGeometry& free, double radius);

// `g` eroded by `radius` (round joins with roundErosion, else mitred) and grown back with
// mitred joins (GEOS), so that corners the erosion kept come back where they were. Null
// where GEOS fails.
GeometryPtr openedMitred(const OGRGeometry& g, double radius, int quadSegments, bool roundErosion,
                         double mitreLimit);

int vertexCount(const OGRGeometry* g);

// Pixel units to the map frame: origin + resolution, y up, rotated by the origin's yaw.
void toMapFrame(std::vector<Polygon2>& polygons, int imageHeight, const RosMapInfo& info);

// Rooms "Room 1".."Room n" from a segmentation's labels, numbered top to bottom, left to
// right, as disjoint simple outlines inside `kept` (pixel units): obstacles inside a room are
// part of its outline, a room that encloses another is cut in two, a room outside `kept` (a
// dropped separate part) is left out. With `wallAngleDeg` (the floor's walls were
// straightened along it, pixel frame), each room is its territory cut by `kept`, so that it
// ends on those walls, and its doorway borders follow them (straightenDoorwayBorders; their
// number in `doorwaysAligned`).
std::vector<Room> roomsFromLabels(const std::vector<std::int32_t>& labels,
                                  const std::vector<unsigned char>& free, int width, int height,
                                  const OGRGeometry& kept, double tolerance, const RosMapInfo& info,
                                  std::optional<double> wallAngleDeg = std::nullopt,
                                  int* doorwaysAligned = nullptr);

// The corners of a floor (pixel units), to move points within `tolerance` of one onto it
// exactly: rooms cut through a jamb's corner meet it up to rounding, and a room missing the
// floor's corner by a hair starts cells at the sliver between them.
class FloorCorners {
public:
    FloorCorners(const OGRGeometry& floor, double tolerance);
    void snap(Ring& ring) const;
    void snap(OGRPolygon& polygon) const; // point by point, where the polygon stays valid

private:
    const Vec2* nearest(Vec2 p) const;
    double tolerance_;
    std::map<std::pair<long long, long long>, std::vector<Vec2>> cells_;
};

// Moves each doorway border between two of `rooms` (pixel units; pieces of `floor` that meet
// only in doorways) onto the wall line of the room with fewer doorways (the smaller on a
// tie), within a rectangle around the border, so that room keeps a straight wall and the
// other owns the passage. Borders wider than maxWidth or deeper than maxDepth across the wall
// (pixels) are not doorways; a door whose move would split a room keeps its border. Returns the
// number of doorways whose border moved.
int straightenDoorwayBorders(std::vector<GeometryPtr>& rooms, const OGRGeometry& floor,
                             double wallAngleDeg, double maxWidth, double maxDepth);

} // namespace fc::importing

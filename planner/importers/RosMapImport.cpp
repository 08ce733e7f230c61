// ROS map_server occupancy maps: the map read at its bit depth (MapImage.cpp), cleaned
// (MapCleaning.cpp), its free cells traced and simplified (MapTracing.cpp) into the plan in
// map coordinates, and split into rooms at doorways (RoomSegmentation.cpp, MapRooms.cpp).
#include "formats/FileIO.h"
#include "importers/MapTracing.h"
#include "importers/MapWalls.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

namespace fc::importing {

namespace {

// map_server's rule: p = (255 - grey) / 255 (or grey / 255 with negate); occupied above
// occupied_thresh, free below free_thresh, unknown between (trinary, scale; scale also needs
// an opaque pixel); raw: free where grey is 0, occupied where it is 100, unknown elsewhere.
OccupancyGrid gridOf(const GreyImage& image, const RosMapInfo& info) {
    OccupancyGrid grid;
    grid.width = image.width;
    grid.height = image.height;
    grid.resolution = info.resolution;
    grid.cells.assign(image.grey.size(), kUnknown);
    long long known = 0;
    for (size_t i = 0; i < grid.cells.size(); ++i) {
        const double grey = image.grey[i];
        unsigned char& cell = grid.cells[i];
        if (info.mode == "raw") {
            if (grey < info.freeThresh * 100)
                cell = kFree;
            else if (grey > info.occupiedThresh * 100 && grey <= 100)
                cell = kOccupied;
        } else {
            const double p = info.negate ? grey / 255.0 : (255.0 - grey) / 255.0;
            const bool transparent = !image.alpha.empty() && image.alpha[i] < 255;
            if (info.mode == "scale" && transparent)
                cell = kUnknown;
            else if (p > info.occupiedThresh)
                cell = kOccupied;
            else if (p < info.freeThresh)
                cell = kFree;
        }
        known += cell != kUnknown;
    }
    if (known == 0)
        throw InputError("every cell of the map is unknown: nothing was mapped");
    return grid;
}

constexpr double kChamferMinWall = 1.0; // m

double openingRadiusOf(const ImportOptions& options) {
    return options.cleaning.openingRadius >= 0 ? options.cleaning.openingRadius
                                               : options.robotDiameter / 2.0;
}

// The straightening of this map's walls (pixel units), or none when the map has no dominant
// wall direction (a round or irregular building).
std::optional<StraightenOptions> straightenOptions(const OGRGeometry& traced,
                                                   const OGRGeometry& fine,
                                                   const MapCleaningOptions& cleaning,
                                                   double openingRadius, double resolution) {
    const std::optional<double> angle =
        dominantWallDirection(traced, &fine, std::max(cleaning.wallBand, 0.0));
    if (!angle)
        return std::nullopt;
    StraightenOptions o;
    o.angleDeg = *angle;
    o.band = std::max(cleaning.wallBand, 0.0);
    o.notchDepth = std::max(cleaning.notchDepth / resolution, o.band);
    o.minRun = std::max(4.0, 2.0 * o.band + 2.0);
    o.cornerShift = 3.0 * std::max(o.band, 0.5);
    // The opening rounds a corner within its radius of it; between walls of a metre or more
    // the walls' intersection is the corner as built (an obstacle's corners cut by 0.2 m
    // cost the room-obstacle map 1.2 m of path and 3 turns). Not between shorter ones:
    // squared, the clutter of the real maps planned longer (the faculty 1,726 -> 1,749 m).
    o.chamferShift = openingRadius / resolution;
    o.chamferMinWall = kChamferMinWall / resolution;
    return o;
}

} // namespace

ImportResult importRosMap(const std::string& yamlPath, const ImportOptions& options) {
    ensureGdal();
    const RosMapInfo info = parseRosMapYaml(withoutByteOrderMark(readFile(yamlPath)));
    const std::filesystem::path imagePath =
        std::filesystem::path(yamlPath).parent_path() / info.image;
    if (!std::filesystem::is_regular_file(imagePath))
        throw InputError("map image " + info.image + " not found");
    const GreyImage image = readMapImage(imagePath.string());
    MapCleaningReport report;
    const std::vector<unsigned char> free =
        cleanOccupancyGrid(gridOf(image, info), options.cleaning, options.robotDiameter, report);
    if (report.freeAreaAfter <= 0)
        throw InputError(report.freeAreaBefore <= 0
                             ? "the map has no free cells"
                             : "cleaning left no free space (the map's free cells are specks)");
    const std::vector<std::int32_t> ones(free.begin(), free.end());
    auto traced = traceCells(ones, free, image.width, image.height);
    if (!traced.count(1))
        throw InputError("the map has no free space");
    const double tolerance =
        options.simplifyTolerance >= 0
            ? options.simplifyTolerance / info.resolution
            : (options.cleaning.enabled ? std::max({options.cleaning.simplifyCells,
                                                    options.cleaning.simplifyRobotShare *
                                                        options.robotDiameter / info.resolution,
                                                    0.0})
                                        : 0.0);
    report.verticesTraced = vertexCount(traced[1].get());
    GeometryPtr simple = simplifiedCells(*traced[1], tolerance);
    if (simple->IsEmpty())
        throw InputError("the free space is thinner than a pixel everywhere");
    std::optional<StraightenOptions> straighten =
        options.cleaning.enabled && options.cleaning.straightenWalls
            ? straightenOptions(*traced[1], *simple, options.cleaning, openingRadiusOf(options),
                                info.resolution)
            : std::nullopt;
    if (straighten) {
        StraightenResult straight = straightenOutlines(*simple, *straighten);
        simple = std::move(straight.geometry);
        const double cellArea = info.resolution * info.resolution;
        // Pixel rows run down the map: a direction in pixels is mirrored in the map frame.
        report.wallAngle = std::fmod(
            std::fmod(info.yaw * 180.0 / M_PI - straighten->angleDeg, 90.0) + 180.0, 90.0);
        report.wallsStraightened = straight.stats.walls;
        report.notchesFilled = straight.stats.notchesFilled;
        report.straightenedAdded = straight.floorAdded * cellArea;
        report.straightenedRemoved = straight.floorRemoved * cellArea;
    }
    if (options.cleaning.enabled) {
        const double opening = openingRadiusOf(options);
        // Half a cell less, so that a passage the raster opening kept (at least 2 radii wide,
        // to the cell) stays open.
        const double radius = opening / info.resolution - 0.5;
        PassageClosing closing = withoutNarrowPassages(*simple, radius);
        simple = std::move(closing.free);
        report.obstaclesJoined = closing.obstaclesJoined;
        report.passageArea = closing.area * info.resolution * info.resolution;
    }
    report.verticesKept = vertexCount(simple.get());
    std::vector<Polygon2> polygons;
    collectPolygons(simple.get(), polygons);
    // The part kept as the plan (the largest), in pixel units, to find the rooms inside it.
    const auto largest = std::max_element(polygons.begin(), polygons.end(), [](auto& a, auto& b) {
        return std::abs(ringArea(a.shell)) < std::abs(ringArea(b.shell));
    });
    // With its holes: a free island inside an obstacle is not part of the kept floor.
    OGRPolygon kept;
    kept.addRingDirectly(ogrRing(largest->shell));
    for (const Ring& hole : largest->holes)
        kept.addRingDirectly(ogrRing(hole));
    toMapFrame(polygons, image.height, info);
    ImportResult result;
    result.project.plan = planFromPolygons(std::move(polygons), "free space", result.warnings);
    int labelCount = 0;
    RoomSegmentationOptions segmentation = options.roomSegmentation;
    segmentation.mergeAcrossNarrowings =
        segmentation.mergeAcrossNarrowings && options.cleaning.enabled;
    const std::vector<std::int32_t> labels =
        segmentRooms(free, image.width, image.height, info.resolution, segmentation, labelCount);
    if (labelCount > 1)
        result.project.plan.rooms =
            roomsFromLabels(labels, free, image.width, image.height, kept, tolerance, info,
                            straighten ? std::optional<double>(straighten->angleDeg) : std::nullopt,
                            &report.doorwaysAligned);
    report.rooms = static_cast<int>(result.project.plan.rooms.size());
    result.robotStartPose = info.start;
    result.cleaning = report;
    return result;
}

} // namespace fc::importing

// Coverage metrics of SPEC sect. 6 on a raster in the sweep frame.
//
// Model: the robot centre keeps W/2 from walls (the planning model; L <= W, so the body
// fits). The sweepable area is what a head of width W can reach from the centre positions
// the path can get to; the swept area is the stroke of the path with a W-wide head held
// across the direction of travel: each segment sweeps its W-wide rectangle without
// extension, turns add the mitred wedge, and the path's two ends get square caps (W/2
// past the end, as a square line cap does), which SPEC's "square path ends" asks for and
// which lets a boustrophedon from W/2 inside a room sweep the room's end strips.
#include "metrics/Metrics.h"

#include "metrics/Raster.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

namespace fc {
namespace {

constexpr double kMaxPixels = 16e6;           // keeps memory and time bounded on huge plans
constexpr double kMitreLimitInWidths = 2.0;   // longer mitres are bevelled
constexpr double kOverlapSweptFraction = 0.8; // share of the head over already swept area
constexpr double kDegenerateLength = 1e-9;    // shorter segments carry no heading
constexpr float kNeverSwept = std::numeric_limits<float>::infinity();

// A non-degenerate path segment in the sweep frame, with its arc length from the start.
struct PathSegment {
    Vec2 a, b;
    Vec2 direction; // unit
    double length = 0.0;
    double arcStart = 0.0;
};

std::vector<PathSegment> sweepFrameSegments(const Polyline& world, const Frame& frame) {
    std::vector<PathSegment> segments;
    double arc = 0.0;
    for (size_t i = 1; i < world.size(); ++i) {
        const Vec2 a = frame.toLocal(world[i - 1]), b = frame.toLocal(world[i]);
        const double length = distance(a, b);
        if (length <= kDegenerateLength)
            continue;
        segments.push_back({a, b, (b - a) * (1.0 / length), length, arc});
        arc += length;
    }
    return segments;
}

Vec2 leftNormal(Vec2 direction) {
    return {-direction.y, direction.x};
}

double chooseResolution(const MetricsInput& input, const BoundingBox& bounds) {
    const double width = input.robot.coverageWidth;
    double resolution = input.resolution > 0.0 ? input.resolution : width / 20.0;
    auto pixelCount = [&](double res) {
        const double margin = width + 2.0 * res;
        return std::ceil((bounds.width() + 2.0 * margin) / res) *
               std::ceil((bounds.height() + 2.0 * margin) / res);
    };
    while (pixelCount(resolution) > kMaxPixels)
        resolution *= std::sqrt(pixelCount(resolution) / kMaxPixels) * 1.01;
    return resolution;
}

// Raster of the arc length at which each pixel is first swept (kNeverSwept if never).
class SweptRaster {
public:
    SweptRaster(const Grid& grid, double width)
        : grid_(grid), fill_(grid), halfWidth_(0.5 * width), width_(width),
          firstArc_(grid.size(), kNeverSwept) {}

    void sweep(const std::vector<PathSegment>& segments) {
        for (size_t i = 0; i < segments.size(); ++i) {
            // Square caps: the path's first and last segments reach W/2 past its ends.
            const double capBefore = i == 0 ? halfWidth_ : 0.0;
            const double capAfter = i + 1 == segments.size() ? halfWidth_ : 0.0;
            sweepRectangle(segments[i], capBefore, capAfter);
            if (i + 1 < segments.size())
                sweepJoin(segments[i], segments[i + 1]);
        }
    }

    const std::vector<float>& firstArc() const { return firstArc_; }

private:
    void sweepRectangle(const PathSegment& s, double capBefore, double capAfter) {
        const Vec2 side = leftNormal(s.direction) * halfWidth_;
        const Vec2 start = s.a - s.direction * capBefore, end = s.b + s.direction * capAfter;
        const Ring rectangle{start - side, end - side, end + side, start + side};
        for (const Span& span : fill_.spans(rectangle)) {
            for (int col = span.col0; col < span.col1; ++col) {
                const double along = dot(grid_.centre(col, span.row) - s.a, s.direction);
                markSwept(grid_.index(col, span.row),
                          s.arcStart + std::clamp(along, 0.0, s.length));
            }
        }
    }

    // The wedge on the outer side of a turn, between the two rectangles' corners, up to
    // the mitre point (or bevelled when the mitre would be longer than the limit).
    void sweepJoin(const PathSegment& in, const PathSegment& out) {
        const double turn = cross(in.direction, out.direction);
        if (std::abs(turn) < 1e-12)
            return; // straight on, or reversing: nothing sticks out
        const double outerSign = turn > 0.0 ? -1.0 : 1.0;
        const Vec2 n1 = leftNormal(in.direction) * outerSign;
        const Vec2 n2 = leftNormal(out.direction) * outerSign;
        const Vec2 vertex = in.b;
        const Vec2 c1 = vertex + n1 * halfWidth_, c2 = vertex + n2 * halfWidth_;
        const Vec2 bisector = n1 + n2;
        const double bisectorNorm2 = dot(bisector, bisector);
        Ring wedge{vertex, c1, c2};
        if (bisectorNorm2 > 0.0 &&
            2.0 * halfWidth_ / std::sqrt(bisectorNorm2) <= kMitreLimitInWidths * width_)
            wedge = {vertex, c1, vertex + bisector * (2.0 * halfWidth_ / bisectorNorm2), c2};
        for (const Span& span : fill_.spans(wedge))
            for (int col = span.col0; col < span.col1; ++col)
                markSwept(grid_.index(col, span.row), out.arcStart);
    }

    void markSwept(size_t pixel, double arc) {
        firstArc_[pixel] = std::min(firstArc_[pixel], static_cast<float>(arc));
    }

    const Grid& grid_;
    ScanlineFill fill_;
    double halfWidth_, width_;
    std::vector<float> firstArc_;
};

// Walks the path every half pixel. Marks where the head's cross-section lies mostly over
// area swept earlier (more than W of path before).
struct PathWalk {
    std::vector<Segment> overlaps; // sweep frame
};

PathWalk walkPath(const std::vector<PathSegment>& segments, const Grid& grid,
                  const std::vector<float>& firstArc, double width) {
    PathWalk walk;
    const double step = 0.5 * grid.resolution;
    const int crossSamples = std::max(1, static_cast<int>(std::ceil(width / grid.resolution)));
    // A run of overlapping samples may continue across vertices (one piece per segment);
    // runs shorter than a pixel in all are raster noise and dropped.
    const double minRunLength = grid.resolution;
    bool inRun = false;
    size_t runFirstPiece = 0;
    double runLength = 0.0;
    auto closeRun = [&]() {
        if (inRun && runLength < minRunLength)
            walk.overlaps.resize(runFirstPiece);
        inRun = false;
    };
    for (const PathSegment& s : segments) {
        const Vec2 across = leftNormal(s.direction);
        const int steps = static_cast<int>(std::ceil(s.length / step));
        bool inPiece = false;
        double pieceStart = 0.0, pieceEnd = 0.0;
        auto closePiece = [&]() {
            if (inPiece && pieceEnd - pieceStart > kDegenerateLength) {
                walk.overlaps.push_back(
                    {s.a + s.direction * pieceStart, s.a + s.direction * pieceEnd});
                runLength += pieceEnd - pieceStart;
            }
            inPiece = false;
        };
        for (int k = 0; k <= steps; ++k) {
            const double t = std::min(k * step, s.length);
            const Vec2 centre = s.a + s.direction * t;
            int col = 0, row = 0;
            // The last W of path is excluded so that the head never overlaps itself.
            const float sweptBefore = static_cast<float>(s.arcStart + t - width);
            int inside = 0, swept = 0;
            for (int j = 0; j < crossSamples; ++j) {
                const double offset = width * ((j + 0.5) / crossSamples - 0.5);
                if (!grid.pixelOf(centre + across * offset, col, row))
                    continue;
                ++inside;
                swept += firstArc[grid.index(col, row)] < sweptBefore;
            }
            if (inside > 0 && swept >= kOverlapSweptFraction * inside) {
                if (!inRun) {
                    inRun = true;
                    runFirstPiece = walk.overlaps.size();
                    runLength = 0.0;
                }
                if (!inPiece)
                    pieceStart = t;
                inPiece = true;
                pieceEnd = t;
            } else {
                closePiece();
                closeRun();
            }
        }
        closePiece(); // the run goes on if the next segment starts overlapping too
    }
    closeRun();
    return walk;
}

// Joins overlap pieces that continue each other in a straight line (split at vertices).
std::vector<Segment> mergeCollinear(const std::vector<Segment>& pieces, double tolerance) {
    std::vector<Segment> merged;
    for (const Segment& piece : pieces) {
        if (!merged.empty()) {
            Segment& last = merged.back();
            const Vec2 d1 = last.b - last.a, d2 = piece.b - piece.a;
            const bool continues = distance(last.b, piece.a) <= tolerance;
            const bool straight =
                std::abs(cross(d1, d2)) <= 1e-9 * norm(d1) * norm(d2) && dot(d1, d2) > 0.0;
            if (continues && straight) {
                last.b = piece.b;
                continue;
            }
        }
        merged.push_back(piece);
    }
    return merged;
}

bool roomRequired(const MetricsInput& input, int room) {
    if (input.requiredRooms.empty())
        return true;
    return room >= 0 && static_cast<size_t>(room) < input.requiredRooms.size() &&
           input.requiredRooms[static_cast<size_t>(room)] != 0;
}

// The floor's part of the metrics, the same for every path of one decomposition and robot:
// the grid, the free pixels and those a head of width W reaches from a centre position.
struct FloorRaster {
    std::vector<Ring> freeSpace; // what it was made of
    Grid grid;
    Mask free, headReach;
};

std::shared_ptr<const FloorRaster> makeFloorRaster(const MetricsInput& input) {
    const Decomposition& decomposition = *input.decomposition;
    const double width = input.robot.coverageWidth;
    auto floor = std::make_shared<FloorRaster>();
    floor->freeSpace = decomposition.freeSpace;
    BoundingBox bounds;
    for (const Ring& ring : decomposition.freeSpace)
        for (const Vec2& p : ring)
            bounds.add(p);
    const double resolution = chooseResolution(input, bounds);
    // The margin keeps a blocked border around the free space and holds the head's stroke.
    const Grid& grid = floor->grid = Grid::covering(bounds, width + 2.0 * resolution, resolution);
    ScanlineFill fill(grid);
    Mask& free = floor->free;
    free.assign(grid.size(), 0);
    fill.paint(decomposition.freeSpace.data(), decomposition.freeSpace.size(), free);

    // Centre positions of the robot disc (diameter L): the nearest blocked pixel centre
    // lies up to half a pixel beyond the wall, so require L/2 plus half a pixel; otherwise
    // gaps slightly narrower than L would count as passable.
    const std::vector<float> distance2 = squaredDistanceToBlocked(free, grid.cols, grid.rows);
    const double halfWidthPixels = 0.5 * width / resolution;
    const double robotRadius = 0.5 * std::min(input.robot.robotDiameter, width);
    const double minDistance = robotRadius / resolution + 0.5;
    const float minDistance2 = static_cast<float>(minDistance * minDistance - 1e-6);
    // Sweepable: what a head of width W reaches from any centre position (a disc of radius
    // W/2 around it), whether or not the path's start can get there: a part of the floor
    // that the start cannot reach is uncovered, never silently left out. The centre region
    // is half a pixel conservative, so the reach gets that half back.
    Mask notCentre(grid.size(), 1);
    bool anyCentre = false;
    for (size_t i = 0; i < grid.size(); ++i) {
        const bool centre = free[i] && distance2[i] >= minDistance2;
        notCentre[i] = centre ? 0 : 1;
        anyCentre = anyCentre || centre;
    }
    const std::vector<float> toCentre2 = squaredDistanceToBlocked(notCentre, grid.cols, grid.rows);
    const double reachPixels = halfWidthPixels + 0.5;
    const float reach2 = static_cast<float>(reachPixels * reachPixels + 1e-6);
    floor->headReach.assign(grid.size(), 0);
    for (size_t i = 0; i < grid.size(); ++i)
        floor->headReach[i] = free[i] && anyCentre && toCentre2[i] <= reach2;
    return floor;
}

// The floor raster of the input's decomposition, made once per decomposition, robot and
// resolution (DerivedCache) where the decomposition has a cache and is what it was made of.
std::shared_ptr<const FloorRaster> floorRasterOf(const MetricsInput& input) {
    const Decomposition& decomposition = *input.decomposition;
    if (!decomposition.derived)
        return makeFloorRaster(input);
    char key[160];
    std::snprintf(key, sizeof key, "metrics floor W=%.17g L=%.17g res=%.17g",
                  input.robot.coverageWidth, input.robot.robotDiameter, input.resolution);
    auto floor = decomposition.derived->get<FloorRaster>(
        key, [&] { return std::shared_ptr<const FloorRaster>(makeFloorRaster(input)); });
    // A copy whose free space was changed after decompose: measured afresh.
    return floor->freeSpace == decomposition.freeSpace ? floor : makeFloorRaster(input);
}

} // namespace

Metrics computeMetrics(const MetricsInput& input) {
    Metrics metrics;
    const double width = input.robot.coverageWidth;
    metrics.length = polylineLength(input.path.points);
    metrics.turns = countTurns(input.path.points);
    metrics.time = (input.robot.speed > 0.0 ? metrics.length / input.robot.speed : 0.0) +
                   metrics.turns * input.robot.turnTime;
    const Decomposition* decomposition = input.decomposition;
    if (decomposition == nullptr || decomposition->freeSpace.empty() || !(width > 0.0)) {
        metrics.extra = metrics.length;
        return metrics;
    }
    for (const Cell& cell : decomposition->cells)
        metrics.cells += roomRequired(input, cell.room) ? 1 : 0;

    const std::shared_ptr<const FloorRaster> floor = floorRasterOf(input);
    const Grid& grid = floor->grid;
    const double resolution = grid.resolution;
    const Mask& free = floor->free;
    Mask required(grid.size(), 0);
    ScanlineFill fill(grid);
    for (const Cell& cell : decomposition->cells) {
        if (roomRequired(input, cell.room)) {
            const Ring outline = cell.outline();
            fill.paint(&outline, 1, required);
        }
    }

    const std::vector<PathSegment> segments =
        sweepFrameSegments(input.path.points, decomposition->frame);
    SweptRaster swept(grid, width);
    swept.sweep(segments);

    double requiredPixels = 0.0, sweepablePixels = 0.0, coveredPixels = 0.0; // counts
    const std::vector<float>& firstArc = swept.firstArc();
    const Mask& headReach = floor->headReach;
    for (size_t i = 0; i < grid.size(); ++i) {
        if (!(free[i] && required[i]))
            continue;
        requiredPixels += 1.0;
        if (headReach[i]) {
            sweepablePixels += 1.0;
            coveredPixels += firstArc[i] != kNeverSwept ? 1.0 : 0.0;
        }
    }
    const size_t missed = static_cast<size_t>(sweepablePixels - coveredPixels);
    const size_t unreached = static_cast<size_t>(requiredPixels - sweepablePixels);
    const size_t stride = std::max<size_t>(1, missed / 20000 + 1);
    const size_t unreachedStride = std::max<size_t>(1, unreached / 20000 + 1);
    size_t seen = 0, seenUnreached = 0;
    for (int row = 0; row < grid.rows && (missed > 0 || unreached > 0); ++row)
        for (int col = 0; col < grid.cols; ++col) {
            const size_t i = grid.index(col, row);
            if (!(free[i] && required[i]))
                continue;
            if (headReach[i] && firstArc[i] == kNeverSwept && seen++ % stride == 0)
                metrics.uncovered.push_back(decomposition->frame.toWorld(grid.centre(col, row)));
            if (!headReach[i] && seenUnreached++ % unreachedStride == 0)
                metrics.unreachable.push_back(decomposition->frame.toWorld(grid.centre(col, row)));
        }
    metrics.requiredArea = requiredPixels * grid.pixelArea();
    metrics.sweepableArea = sweepablePixels * grid.pixelArea();
    metrics.coveredArea = coveredPixels * grid.pixelArea();
    metrics.uncoveredArea = metrics.sweepableArea - metrics.coveredArea;
    metrics.unreachableArea = metrics.requiredArea - metrics.sweepableArea;
    metrics.coverage = sweepablePixels > 0.0 ? coveredPixels / sweepablePixels : 0.0;
    metrics.ideal = metrics.sweepableArea / width;
    metrics.extra = metrics.length - metrics.ideal;

    if (!input.overlaps)
        return metrics;
    const PathWalk walk = walkPath(segments, grid, swept.firstArc(), width);
    for (const Segment& piece : mergeCollinear(walk.overlaps, 1e-6 * resolution))
        metrics.overlaps.push_back(
            {decomposition->frame.toWorld(piece.a), decomposition->frame.toWorld(piece.b)});
    return metrics;
}

} // namespace fc

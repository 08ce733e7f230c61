#include "PathChecker.h"

// Boost.Geometry's envelope and buffer code trip GCC 12's -Wmaybe-uninitialized (false
// positives inside the library).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/segment.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>
#include <stdexcept>

namespace fccheck {
namespace {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Pt = bg::model::d2::point_xy<double>;
using Poly = bg::model::polygon<Pt>; // clockwise, closed
using Multi = bg::model::multi_polygon<Poly>;
using Line = bg::model::linestring<Pt>;
using Seg = bg::model::segment<Pt>;
using Box = bg::model::box<Pt>;

// Path vertices closer than this (m) are merged before the swath is built.
constexpr double kDuplicateVertex = 1e-9;
// Segments per buffered piece of the path: the swath is the union of pieces that overlap by
// one segment, so every interior vertex gets its join in some piece.
constexpr std::size_t kSegmentsPerPiece = 48;

// Shifts caller coordinates to a local origin (the outer ring's first vertex).
struct Shift {
    double ox = 0.0, oy = 0.0;
    Pt operator()(const XY& p) const { return Pt(p.first - ox, p.second - oy); }
    XY back(const Pt& p) const { return {p.x() + ox, p.y() + oy}; }
};

Shift shiftFor(const FreeSpace& free) {
    if (free.outer.empty())
        throw std::invalid_argument("checker: the free space has no outer ring");
    return {free.outer.front().first, free.outer.front().second};
}

Poly polygonOf(const RingXY& ring, const Shift& shift) {
    Poly p;
    for (const XY& v : ring)
        p.outer().push_back(shift(v));
    if (!p.outer().empty() && !bg::equals(p.outer().front(), p.outer().back()))
        p.outer().push_back(p.outer().front());
    bg::correct(p);
    return p;
}

// Boost's set operations must not write into one of their inputs.
Multi unite(const Multi& a, const Multi& b) {
    Multi out;
    bg::union_(a, b, out);
    return out;
}

// Union of many pieces, pairwise (a balanced tree keeps the intermediate results small).
Multi uniteAll(std::vector<Multi> pieces) {
    if (pieces.empty())
        return {};
    while (pieces.size() > 1) {
        std::vector<Multi> next;
        for (std::size_t i = 0; i + 1 < pieces.size(); i += 2)
            next.push_back(unite(pieces[i], pieces[i + 1]));
        if (pieces.size() % 2 == 1)
            next.push_back(std::move(pieces.back()));
        pieces.swap(next);
    }
    return pieces.front();
}

Multi freeRegion(const FreeSpace& free, const Shift& shift) {
    Multi outer{polygonOf(free.outer, shift)};
    std::vector<Multi> holes;
    for (const RingXY& h : free.holes)
        holes.push_back(Multi{polygonOf(h, shift)});
    const Multi blocked = uniteAll(std::move(holes));
    if (blocked.empty())
        return outer;
    Multi out;
    bg::difference(outer, blocked, out);
    return out;
}

Multi requiredRegion(const Multi& freeArea, const std::vector<RingXY>& required,
                     const Shift& shift) {
    if (required.empty())
        return freeArea;
    std::vector<Multi> rooms;
    for (const RingXY& r : required)
        rooms.push_back(Multi{polygonOf(r, shift)});
    const Multi roomUnion = uniteAll(std::move(rooms));
    Multi out;
    bg::intersection(freeArea, roomUnion, out);
    return out;
}

Multi roundBuffer(const Multi& in, double distance) {
    Multi out;
    bg::buffer(in, out, bg::strategy::buffer::distance_symmetric<double>(distance),
               bg::strategy::buffer::side_straight(),
               bg::strategy::buffer::join_round(kPointsPerCircle),
               bg::strategy::buffer::end_round(kPointsPerCircle),
               bg::strategy::buffer::point_circle(kPointsPerCircle));
    return out;
}

struct Regions {
    Shift shift;
    Multi free, required, sweepable;
    int centreComponents = 0;
};

// The part of the eroded free space holding `start` (or the nearest part to it: the start
// may lie on the eroded boundary, up to the circle approximation).
Multi componentAt(const Multi& centres, const Pt& start) {
    if (centres.empty())
        return centres;
    std::size_t best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < centres.size(); ++i) {
        const double d = bg::distance(start, centres[i]);
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return Multi{centres[best]};
}

Regions regionsFor(const FreeSpace& free, const std::vector<RingXY>& required, double L,
                   double W, const XY* start) {
    Regions r;
    r.shift = shiftFor(free);
    r.free = freeRegion(free, r.shift);
    r.required = requiredRegion(r.free, required, r.shift);
    Multi centres = roundBuffer(r.free, -0.5 * L);
    r.centreComponents = static_cast<int>(centres.size());
    if (start)
        centres = componentAt(centres, r.shift(*start));
    const Multi reach = centres.empty() ? Multi{} : roundBuffer(centres, 0.5 * W);
    bg::intersection(r.required, reach, r.sweepable);
    return r;
}

Line cleanLine(const PolylineXY& path, const Shift& shift) {
    Line line;
    for (const XY& v : path) {
        const Pt p = shift(v);
        if (line.empty() || bg::distance(line.back(), p) > kDuplicateVertex)
            line.push_back(p);
    }
    return line;
}

// The W x W/2 rectangle beyond the path end `end`, reached along the unit direction (dx, dy).
Poly squareCap(const Pt& end, double dx, double dy, double halfWidth) {
    const double nx = -dy * halfWidth, ny = dx * halfWidth;
    const double fx = dx * halfWidth, fy = dy * halfWidth;
    const double x = end.x(), y = end.y();
    Poly cap;
    cap.outer() = {Pt(x + nx, y + ny), Pt(x + nx + fx, y + ny + fy), Pt(x - nx + fx, y - ny + fy),
                   Pt(x - nx, y - ny), Pt(x + nx, y + ny)};
    bg::correct(cap);
    return cap;
}

Multi swathOf(const Line& line, double W) {
    const double halfWidth = 0.5 * W;
    if (line.size() < 2)
        return {}; // a robot standing still sweeps no stroke
    std::vector<Multi> pieces;
    for (std::size_t first = 0; first + 1 < line.size(); first += kSegmentsPerPiece) {
        // Overlap by one segment: the vertex `first` is interior to the previous piece.
        const std::size_t from = first == 0 ? 0 : first - 1;
        const std::size_t to = std::min(line.size() - 1, first + kSegmentsPerPiece);
        Line piece(line.begin() + static_cast<std::ptrdiff_t>(from),
                   line.begin() + static_cast<std::ptrdiff_t>(to) + 1);
        Multi stroke;
        bg::buffer(piece, stroke, bg::strategy::buffer::distance_symmetric<double>(halfWidth),
                   bg::strategy::buffer::side_straight(),
                   bg::strategy::buffer::join_miter(kMitreLimit),
                   bg::strategy::buffer::end_flat(),
                   bg::strategy::buffer::point_square());
        pieces.push_back(std::move(stroke));
        if (to == line.size() - 1)
            break;
    }
    auto capAt = [&](const Pt& end, const Pt& before) {
        const double dx = end.x() - before.x(), dy = end.y() - before.y();
        const double n = std::sqrt(dx * dx + dy * dy);
        return Multi{squareCap(end, dx / n, dy / n, halfWidth)};
    };
    pieces.push_back(capAt(line.back(), line[line.size() - 2]));
    pieces.push_back(capAt(line.front(), line[1]));
    return uniteAll(std::move(pieces));
}

double coveredIn(const Multi& sweepable, const PolylineXY& path, double W, const Shift& shift) {
    const Multi swath = swathOf(cleanLine(path, shift), W);
    if (swath.empty())
        return 0.0;
    Multi covered;
    bg::intersection(swath, sweepable, covered);
    return bg::area(covered);
}

using WallEntry = Seg;

bgi::rtree<WallEntry, bgi::quadratic<16>> wallIndex(const FreeSpace& free, const Shift& shift) {
    std::vector<WallEntry> walls;
    auto addRing = [&](const RingXY& ring) {
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Pt a = shift(ring[i]), b = shift(ring[(i + 1) % ring.size()]);
            if (!bg::equals(a, b))
                walls.push_back(Seg(a, b));
        }
    };
    addRing(free.outer);
    for (const RingXY& h : free.holes)
        addRing(h);
    return bgi::rtree<WallEntry, bgi::quadratic<16>>(walls.begin(), walls.end());
}

} // namespace

Clearance minimumClearance(const FreeSpace& free, const PolylineXY& path) {
    Clearance out;
    if (path.empty())
        return out;
    const Shift shift = shiftFor(free);
    const Multi freeArea = freeRegion(free, shift);
    const auto walls = wallIndex(free, shift);
    if (walls.empty())
        return out;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (out.inside && !bg::covered_by(shift(path[i]), freeArea)) {
            out.inside = false;
            out.outsideVertex = i;
        }
    }
    // Path segments (a single point counts as a zero-length segment).
    std::vector<Seg> segments;
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
        segments.push_back(Seg(shift(path[i]), shift(path[i + 1])));
    if (segments.empty())
        segments.push_back(Seg(shift(path[0]), shift(path[0])));

    // Every wall within `radius` of a segment has its box within `radius` of the segment's
    // box; widen until some segment finds a wall.
    const auto wallBounds = walls.bounds();
    double radius = 1.0;
    for (;;) {
        for (std::size_t i = 0; i < segments.size(); ++i) {
            Box box;
            bg::envelope(segments[i], box);
            const double r = std::min(radius, out.minimum);
            Box query(Pt(box.min_corner().x() - r, box.min_corner().y() - r),
                      Pt(box.max_corner().x() + r, box.max_corner().y() + r));
            std::vector<WallEntry> near;
            walls.query(bgi::intersects(query), std::back_inserter(near));
            for (const WallEntry& w : near) {
                const double d = bg::distance(segments[i], w);
                if (d < out.minimum) {
                    out.minimum = d;
                    out.segment = i;
                    Pt closest;
                    bg::centroid(w, closest);
                    out.nearestWallPoint = shift.back(closest);
                }
            }
        }
        if (std::isfinite(out.minimum))
            break;
        radius *= 4.0;
        if (radius > 1e3 * (1.0 + bg::distance(wallBounds.min_corner(), wallBounds.max_corner())))
            break; // unreachable: there are walls, so some segment finds one
    }
    return out;
}

bool isCollisionFree(const Clearance& clearance, double robotDiameter) {
    return clearance.inside &&
           clearance.minimum >= 0.5 * robotDiameter - kClearanceTolerance * robotDiameter;
}

double floorArea(const FreeSpace& free, const std::vector<RingXY>& required) {
    const Shift shift = shiftFor(free);
    return bg::area(requiredRegion(freeRegion(free, shift), required, shift));
}

double sweepableArea(const FreeSpace& free, const std::vector<RingXY>& required,
                     double robotDiameter, double coverageWidth, const XY* start) {
    return bg::area(regionsFor(free, required, robotDiameter, coverageWidth, start).sweepable);
}

double coveredArea(const PolylineXY& path, double coverageWidth, const FreeSpace& free,
                   const std::vector<RingXY>& required, double robotDiameter) {
    const XY* start = path.empty() ? nullptr : &path.front();
    const Regions r = regionsFor(free, required, robotDiameter, coverageWidth, start);
    return coveredIn(r.sweepable, path, coverageWidth, r.shift);
}

double swathArea(const PolylineXY& path, double coverageWidth) {
    if (path.empty())
        return 0.0;
    const Shift shift{path.front().first, path.front().second};
    return bg::area(swathOf(cleanLine(path, shift), coverageWidth));
}

Report checkPath(const FreeSpace& free, const std::vector<RingXY>& required,
                 const PolylineXY& path, double robotDiameter, double coverageWidth) {
    Report out;
    const XY* start = path.empty() ? nullptr : &path.front();
    const Regions r = regionsFor(free, required, robotDiameter, coverageWidth, start);
    out.floorArea = bg::area(r.required);
    out.sweepableArea = bg::area(r.sweepable);
    out.coveredArea = coveredIn(r.sweepable, path, coverageWidth, r.shift);
    out.uncoveredArea = std::max(0.0, out.sweepableArea - out.coveredArea);
    out.unreachableArea = std::max(0.0, out.floorArea - out.sweepableArea);
    out.coverage = out.sweepableArea > 0.0 ? out.coveredArea / out.sweepableArea : 1.0;
    out.centreComponents = r.centreComponents;
    out.clearance = minimumClearance(free, path);
    out.collisionFree = isCollisionFree(out.clearance, robotDiameter);
    return out;
}

} // namespace fccheck

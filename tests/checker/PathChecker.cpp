#include "PathChecker.h"

// Boost 1.74 rescales overlay inputs to an integer grid by default; that loses about 1e-6 of
// the extent (measured: 2.75e-6 m^2 on a 21 m^2 L-shaped swath) and produced
// self-intersecting unions on swath pieces. Without it Boost uses its floating-point
// predicates. The point type below is not the planner's (point_xy), so no template
// instantiation is shared with the planner's Boost.Geometry code compiled with rescaling.
#define BOOST_GEOMETRY_NO_ROBUSTNESS
// Boost.Geometry's envelope and buffer code trip GCC 12's -Wmaybe-uninitialized (false
// positives inside the library).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point.hpp>
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
using Pt = bg::model::point<double, 2, bg::cs::cartesian>;
using Poly = bg::model::polygon<Pt>; // clockwise, closed
using Multi = bg::model::multi_polygon<Poly>;
using Line = bg::model::linestring<Pt>;
using Seg = bg::model::segment<Pt>;
using Box = bg::model::box<Pt>;

// Path vertices closer than this (m) are merged before the swath is built.
constexpr double kDuplicateVertex = 1e-12;
// Rows of the scanline that measures the swath: this far apart (m), fewer than kMaxRows.
constexpr double kRowSpacing = 0.005;
constexpr double kMaxRows = 200000;

// Shifts caller coordinates to a local origin (the outer ring's first vertex).
struct Shift {
    double ox = 0.0, oy = 0.0;
    Pt operator()(const XY& p) const { return Pt(p.first - ox, p.second - oy); }
    XY back(const Pt& p) const { return {bg::get<0>(p) + ox, bg::get<1>(p) + oy}; }
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

Regions regionsFor(const FreeSpace& free, const std::vector<RingXY>& required, double L, double W,
                   const XY* start) {
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

Poly quad(const Pt& a, const Pt& b, const Pt& c, const Pt& d) {
    Poly p;
    p.outer() = {a, b, c, d, a};
    bg::correct(p);
    return p;
}

Pt along(const Pt& p, double dx, double dy, double t) {
    return Pt(bg::get<0>(p) + dx * t, bg::get<1>(p) + dy * t);
}

// Turns smaller than this (radians) get no join wedge (it would be a sliver of at most
// (W/2)^2 x 1e-9 m^2).
constexpr double kMinTurn = 1e-9;

// The stroke of the path with a W-wide head held across the direction of travel, as
// convex pieces: each segment's W-wide rectangle (flat ends: what Boost's linestring buffer
// with end_flat gives for one segment), the mitre wedge on the outer side of each turn
// (bevelled when the mitre point is more than kMitreLimit half widths from the vertex, as
// the planner's metrics do), and a W x W/2 square cap beyond each end of the path.
std::vector<Poly> swathPieces(const Line& line, double W, bool caps) {
    std::vector<Poly> current;
    if (line.size() < 2)
        return current; // a robot standing still sweeps no stroke
    const std::size_t n = line.size() - 1;
    std::vector<double> ux(n), uy(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double dx = bg::get<0>(line[i + 1]) - bg::get<0>(line[i]),
                     dy = bg::get<1>(line[i + 1]) - bg::get<1>(line[i]);
        const double len = std::sqrt(dx * dx + dy * dy);
        ux[i] = dx / len;
        uy[i] = dy / len;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Pt& a = line[i];
        const Pt& b = line[i + 1];
        const double h = 0.5 * W;
        const double nx = -uy[i] * h, ny = ux[i] * h;
        current.push_back(quad(Pt(bg::get<0>(a) + nx, bg::get<1>(a) + ny),
                               Pt(bg::get<0>(b) + nx, bg::get<1>(b) + ny),
                               Pt(bg::get<0>(b) - nx, bg::get<1>(b) - ny),
                               Pt(bg::get<0>(a) - nx, bg::get<1>(a) - ny)));
        if (i + 1 < n) {
            const double turn = ux[i] * uy[i + 1] - uy[i] * ux[i + 1];
            if (std::abs(turn) > kMinTurn) {
                // The outer side: right of travel for a left turn, left for a right turn.
                const double sign = turn > 0.0 ? -1.0 : 1.0;
                const double n1x = -uy[i] * sign, n1y = ux[i] * sign;
                const double n2x = -uy[i + 1] * sign, n2y = ux[i + 1] * sign;
                const Pt c1 = along(b, n1x, n1y, h), c2 = along(b, n2x, n2y, h);
                const double bx = n1x + n2x, by = n1y + n2y, b2 = bx * bx + by * by;
                if (b2 > 0.0 && 2.0 / std::sqrt(b2) <= kMitreLimit) {
                    const Pt mitre(bg::get<0>(b) + bx * (2.0 * h / b2),
                                   bg::get<1>(b) + by * (2.0 * h / b2));
                    current.push_back(quad(b, c1, mitre, c2));
                } else {
                    Poly bevel;
                    bevel.outer() = {b, c1, c2, b};
                    bg::correct(bevel);
                    if (std::abs(bg::area(bevel)) > 0.0)
                        current.push_back(bevel);
                }
            }
        }
    }
    // Square caps: W/2 beyond the first and the last vertex.
    auto cap = [&](const Pt& end, double dx, double dy) {
        const double h = 0.5 * W;
        const double nx = -dy * h, ny = dx * h;
        return quad(Pt(bg::get<0>(end) + nx, bg::get<1>(end) + ny),
                    along(Pt(bg::get<0>(end) + nx, bg::get<1>(end) + ny), dx, dy, h),
                    along(Pt(bg::get<0>(end) - nx, bg::get<1>(end) - ny), dx, dy, h),
                    Pt(bg::get<0>(end) - nx, bg::get<1>(end) - ny));
    };
    if (caps) {
        current.push_back(cap(line.back(), ux[n - 1], uy[n - 1]));
        current.push_back(cap(line.front(), -ux[0], -uy[0]));
    }
    return current;
}

// Measures (swath pieces ∪) ∩ region row by row. Each row y = y0 + (k + 1/2) dy is cut
// exactly: a convex piece meets it in one interval, the region (a valid multipolygon) in the
// intervals between its sorted edge crossings; the row's covered length is the measure of
// (∪ piece intervals) ∩ (region intervals). Area = sum of lengths x dy (exact in x, midpoint
// rule in y). Boost's overlay is not used for the swath: on planner paths (thousands of
// segments, some a micrometre long, retraced transits, stripes that share an edge when
// rotated) Boost 1.74's union returned one operand alone or self-intersecting output,
// with or without its integer rescaling.
struct Scan {
    double swept = 0.0;  // m^2, pieces ∩ region (or the pieces alone without a region)
    double region = 0.0; // m^2, the region as the rows see it
};

struct Edge {
    double x0, y0, x1, y1;
};

// x where the edge crosses the row y (half-open in y, so a vertex counts once).
bool crossing(const Edge& e, double y, double& x) {
    if ((e.y0 <= y && y < e.y1) || (e.y1 <= y && y < e.y0)) {
        x = e.x0 + (y - e.y0) * (e.x1 - e.x0) / (e.y1 - e.y0);
        return true;
    }
    return false;
}

template <typename Ring> void addEdges(const Ring& ring, std::vector<Edge>& edges) {
    for (std::size_t i = 0; i + 1 < ring.size(); ++i)
        edges.push_back({bg::get<0>(ring[i]), bg::get<1>(ring[i]), bg::get<0>(ring[i + 1]),
                         bg::get<1>(ring[i + 1])});
}

// Items (pieces or edges) by row span, for a sweep over the rows.
struct RowSpans {
    std::vector<std::pair<long, long>> span; // first and last row per item
    std::vector<std::size_t> order;          // items by first row
};

Scan scanSwath(const std::vector<Poly>& pieces, const Multi* region) {
    Scan out;
    if (pieces.empty() && !region)
        return out;
    Box bounds;
    bg::assign_inverse(bounds);
    for (const Poly& p : pieces)
        bg::expand(bounds, bg::return_envelope<Box>(p));
    if (region && !region->empty())
        bg::expand(bounds, bg::return_envelope<Box>(*region));
    const double y0 = bg::get<bg::min_corner, 1>(bounds), y1 = bg::get<bg::max_corner, 1>(bounds);
    if (!(y1 > y0))
        return out;
    double dy = kRowSpacing;
    if ((y1 - y0) / dy > kMaxRows)
        dy = (y1 - y0) / kMaxRows;
    const long rows = static_cast<long>(std::ceil((y1 - y0) / dy));
    auto rowRange = [&](double lo, double hi) {
        // Rows k with lo <= y0 + (k + 0.5) dy <= hi.
        const long first = std::max(0L, static_cast<long>(std::ceil((lo - y0) / dy - 0.5)));
        const long last = std::min(rows - 1, static_cast<long>(std::floor((hi - y0) / dy - 0.5)));
        return std::make_pair(first, last);
    };
    // Pieces and region edges, each with its rows, swept in row order.
    std::vector<std::vector<Edge>> pieceEdges(pieces.size());
    std::vector<std::pair<long, long>> pieceRows(pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        addEdges(pieces[i].outer(), pieceEdges[i]);
        const Box b = bg::return_envelope<Box>(pieces[i]);
        pieceRows[i] = rowRange(bg::get<bg::min_corner, 1>(b), bg::get<bg::max_corner, 1>(b));
    }
    std::vector<Edge> regionEdges;
    if (region)
        for (const Poly& p : *region) {
            addEdges(p.outer(), regionEdges);
            for (const auto& inner : p.inners())
                addEdges(inner, regionEdges);
        }
    std::vector<std::pair<long, long>> edgeRows(regionEdges.size());
    for (std::size_t i = 0; i < regionEdges.size(); ++i)
        edgeRows[i] = rowRange(std::min(regionEdges[i].y0, regionEdges[i].y1),
                               std::max(regionEdges[i].y0, regionEdges[i].y1));
    auto byFirstRow = [](const std::vector<std::pair<long, long>>& spans) {
        std::vector<std::size_t> order(spans.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return spans[a].first < spans[b].first; });
        return order;
    };
    const std::vector<std::size_t> pieceOrder = byFirstRow(pieceRows);
    const std::vector<std::size_t> edgeOrder = byFirstRow(edgeRows);
    std::vector<std::size_t> activePieces, activeEdges;
    std::size_t nextPiece = 0, nextEdge = 0;
    std::vector<std::pair<double, double>> swept;
    std::vector<double> xs;
    double sweptLength = 0.0, regionLength = 0.0;
    for (long k = 0; k < rows; ++k) {
        const double y = y0 + (static_cast<double>(k) + 0.5) * dy;
        while (nextPiece < pieceOrder.size() && pieceRows[pieceOrder[nextPiece]].first <= k)
            activePieces.push_back(pieceOrder[nextPiece++]);
        while (nextEdge < edgeOrder.size() && edgeRows[edgeOrder[nextEdge]].first <= k)
            activeEdges.push_back(edgeOrder[nextEdge++]);
        activePieces.erase(std::remove_if(activePieces.begin(), activePieces.end(),
                                          [&](std::size_t i) { return pieceRows[i].second < k; }),
                           activePieces.end());
        activeEdges.erase(std::remove_if(activeEdges.begin(), activeEdges.end(),
                                         [&](std::size_t i) { return edgeRows[i].second < k; }),
                          activeEdges.end());
        // The swath's intervals on this row, merged.
        swept.clear();
        for (std::size_t i : activePieces) {
            double lo = INFINITY, hi = -INFINITY, x = 0.0;
            for (const Edge& e : pieceEdges[i])
                if (crossing(e, y, x))
                    lo = std::min(lo, x), hi = std::max(hi, x);
            if (hi > lo)
                swept.push_back({lo, hi});
        }
        std::sort(swept.begin(), swept.end());
        std::size_t merged = 0;
        for (std::size_t i = 0; i < swept.size(); ++i) {
            if (merged > 0 && swept[i].first <= swept[merged - 1].second)
                swept[merged - 1].second = std::max(swept[merged - 1].second, swept[i].second);
            else
                swept[merged++] = swept[i];
        }
        swept.resize(merged);
        if (!region) {
            for (const auto& s : swept)
                sweptLength += s.second - s.first;
            continue;
        }
        // The region's intervals: between consecutive crossings (even-odd).
        xs.clear();
        for (std::size_t i : activeEdges) {
            double x = 0.0;
            if (crossing(regionEdges[i], y, x))
                xs.push_back(x);
        }
        std::sort(xs.begin(), xs.end());
        std::size_t j = 0;
        for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
            const double lo = xs[i], hi = xs[i + 1];
            regionLength += hi - lo;
            while (j < swept.size() && swept[j].second <= lo)
                ++j;
            for (std::size_t m = j; m < swept.size() && swept[m].first < hi; ++m)
                sweptLength +=
                    std::max(0.0, std::min(hi, swept[m].second) - std::max(lo, swept[m].first));
        }
    }
    out.swept = sweptLength * dy;
    out.region = regionLength * dy;
    return out;
}

// Area of swath ∩ sweepable, scaled so that the rows' measure of the sweepable region equals
// its exact area (numerator and denominator of the coverage measured alike).
double coveredIn(const Multi& sweepable, const PolylineXY& path, double W, const Shift& shift) {
    const Line line = cleanLine(path, shift);
    const Scan scan = scanSwath(swathPieces(line, W, true), &sweepable);
    return scan.region > 0.0 ? scan.swept * bg::area(sweepable) / scan.region : 0.0;
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
            Box query(Pt(bg::get<0>(box.min_corner()) - r, bg::get<1>(box.min_corner()) - r),
                      Pt(bg::get<0>(box.max_corner()) + r, bg::get<1>(box.max_corner()) + r));
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
    // Every part the disc can sweep counts, also one the start cannot reach: SPEC sect. 6
    // measures coverage over all the required rooms, so such a part is uncovered, not excused.
    const XY* start = nullptr;
    const Regions r = regionsFor(free, required, robotDiameter, coverageWidth, start);
    return coveredIn(r.sweepable, path, coverageWidth, r.shift);
}

double swathArea(const PolylineXY& path, double coverageWidth) {
    if (path.empty())
        return 0.0;
    const Shift shift{path.front().first, path.front().second};
    return scanSwath(swathPieces(cleanLine(path, shift), coverageWidth, true), nullptr).swept;
}

Report checkPath(const FreeSpace& free, const std::vector<RingXY>& required, const PolylineXY& path,
                 double robotDiameter, double coverageWidth) {
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

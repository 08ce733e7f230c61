// The Tung & Liu model's cells: the classic Boustrophedon decomposition of the rooms' free
// space (slabs between the vertices' slices, joined where a slab's piece continues into
// exactly one piece of the next and that piece comes from it alone) and each cell's four
// boustrophedons. Boost.Geometry restricts the floor to the chosen rooms.
#include "baselines/BaselineModel.h"

// Boost.Geometry's envelope code trips GCC 12's -Wmaybe-uninitialized (a false positive
// inside the library); silence it for this file only.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <map>
#include <string>

namespace fc::baselines::detail {
namespace {

namespace bg = boost::geometry;
using BgPoint = bg::model::d2::point_xy<double>;
using BgPolygon = bg::model::polygon<BgPoint>;
using BgMulti = bg::model::multi_polygon<BgPolygon>;

BgPolygon toBg(const Ring& outer, const std::vector<Ring>& holes = {}) {
    BgPolygon p;
    for (const Vec2& v : outer)
        bg::append(p.outer(), BgPoint(v.x, v.y));
    p.inners().resize(holes.size());
    for (std::size_t h = 0; h < holes.size(); ++h)
        for (const Vec2& v : holes[h])
            bg::append(p.inners()[h], BgPoint(v.x, v.y));
    bg::correct(p);
    return p;
}

Ring fromBg(const bg::model::ring<BgPoint>& r) {
    Ring ring;
    for (const BgPoint& p : r)
        ring.push_back({p.x(), p.y()});
    if (ring.size() > 1 && distance(ring.front(), ring.back()) < 1e-12)
        ring.pop_back();
    return ring;
}

// The rings (sweep frame) of the floor to cover: the free space, within the chosen rooms.
std::vector<Ring> regionRings(const Plan& plan, const std::vector<std::string>& rooms,
                              const Frame& frame) {
    std::vector<Ring> holes;
    for (const Ring& o : plan.obstacles)
        holes.push_back(frame.toLocal(o));
    BgMulti free;
    free.push_back(toBg(frame.toLocal(plan.boundary), holes));
    if (!rooms.empty() && !plan.rooms.empty()) {
        BgMulti chosen;
        for (const Room& room : plan.rooms) {
            if (std::find(rooms.begin(), rooms.end(), room.name) == rooms.end())
                continue;
            BgMulti joined;
            bg::union_(chosen, toBg(frame.toLocal(room.outline)), joined);
            chosen = std::move(joined);
        }
        BgMulti clipped;
        bg::intersection(free, chosen, clipped);
        free = std::move(clipped);
    }
    std::vector<Ring> rings;
    for (const BgPolygon& p : free) {
        rings.push_back(fromBg(p.outer()));
        for (const auto& inner : p.inners())
            rings.push_back(fromBg(inner));
    }
    return rings;
}

struct Edge {
    Vec2 a, b; // a.x < b.x
    double yAt(double x) const { return a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x); }
};

// A free piece of one slab: between a lower and an upper edge, from xa to xb.
struct Trapezoid {
    double xa, xb;
    int lower, upper; // edges
    int cell = -1;
};

struct CellShape {
    std::vector<Trapezoid> pieces; // left to right
    double floorAt(const std::vector<Edge>& edges, double x) const {
        for (const Trapezoid& t : pieces)
            if (x <= t.xb + 1e-12)
                return edges[t.lower].yAt(std::clamp(x, t.xa, t.xb));
        return edges[pieces.back().lower].yAt(pieces.back().xb);
    }
    double ceilingAt(const std::vector<Edge>& edges, double x) const {
        for (const Trapezoid& t : pieces)
            if (x <= t.xb + 1e-12)
                return edges[t.upper].yAt(std::clamp(x, t.xa, t.xb));
        return edges[pieces.back().upper].yAt(pieces.back().xb);
    }
};

std::vector<CellShape> decompose(const std::vector<Ring>& rings, std::vector<Edge>& edges,
                                 std::vector<std::pair<int, int>>& links) {
    std::vector<double> xs;
    for (const Ring& ring : rings)
        for (std::size_t i = 0; i < ring.size(); ++i) {
            const Vec2 p = ring[i], q = ring[(i + 1) % ring.size()];
            xs.push_back(p.x);
            if (std::abs(p.x - q.x) > 1e-12)
                edges.push_back(p.x < q.x ? Edge{p, q} : Edge{q, p});
        }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end(), [](double a, double b) { return b - a < 1e-9; }),
             xs.end());
    std::vector<std::vector<Trapezoid>> slabs;
    for (std::size_t s = 0; s + 1 < xs.size(); ++s) {
        const double xa = xs[s], xb = xs[s + 1], xm = 0.5 * (xa + xb);
        std::vector<std::pair<double, int>> crossing;
        for (int e = 0; e < static_cast<int>(edges.size()); ++e)
            if (edges[e].a.x < xm && edges[e].b.x > xm)
                crossing.push_back({edges[e].yAt(xm), e});
        std::sort(crossing.begin(), crossing.end());
        std::vector<Trapezoid> slab;
        for (std::size_t k = 0; k + 1 < crossing.size(); k += 2)
            slab.push_back({xa, xb, crossing[k].second, crossing[k + 1].second});
        slabs.push_back(std::move(slab));
    }
    // Pieces of neighbouring slabs that share part of the slice between them.
    std::vector<CellShape> cells;
    auto overlap = [&](const Trapezoid& l, const Trapezoid& r) {
        const double x = l.xb;
        const double lo = std::max(edges[l.lower].yAt(x), edges[r.lower].yAt(x));
        const double hi = std::min(edges[l.upper].yAt(x), edges[r.upper].yAt(x));
        return hi - lo > 1e-9;
    };
    for (std::size_t s = 0; s < slabs.size(); ++s)
        for (Trapezoid& t : slabs[s]) {
            int continues = -1;
            std::vector<int> left;
            if (s > 0) {
                for (int k = 0; k < static_cast<int>(slabs[s - 1].size()); ++k)
                    if (overlap(slabs[s - 1][k], t))
                        left.push_back(k);
                if (left.size() == 1) {
                    const Trapezoid& l = slabs[s - 1][left.front()];
                    int rightOfL = 0;
                    for (const Trapezoid& r : slabs[s])
                        rightOfL += overlap(l, r);
                    if (rightOfL == 1)
                        continues = l.cell;
                }
            }
            if (continues < 0) {
                continues = static_cast<int>(cells.size());
                cells.emplace_back();
                for (int k : left)
                    links.push_back({slabs[s - 1][k].cell, continues});
            }
            t.cell = continues;
            cells[continues].pieces.push_back(t);
        }
    return cells;
}

// The y-range of the slice x within c of the segment (its capsule: the discs at its ends and
// the band along it; convex, so one interval). Empty when the slice misses it.
Interval capsuleOnSlice(double x, const Segment& w, double c) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2 p : {w.a, w.b}) {
        const double dx = x - p.x;
        if (std::abs(dx) < c) {
            const double h = std::sqrt(c * c - dx * dx);
            lo = std::min(lo, p.y - h), hi = std::max(hi, p.y + h);
        }
    }
    const double len = distance(w.a, w.b);
    if (len > 0) {
        const Vec2 u = (w.b - w.a) * (1.0 / len), n{-u.y, u.x};
        // Along the segment s(y) = s0 + u.y y in [0, len]; across it e(y) = e0 + n.y y in (-c, c).
        const double s0 = (x - w.a.x) * u.x - w.a.y * u.y;
        const double e0 = (x - w.a.x) * n.x - w.a.y * n.y;
        double bandLo = -INFINITY, bandHi = INFINITY;
        auto within = [&](double v0, double slope, double from, double to) {
            if (std::abs(slope) < 1e-12) {
                if (v0 < from || v0 > to)
                    bandLo = INFINITY, bandHi = -INFINITY;
                return;
            }
            double a = (from - v0) / slope, b = (to - v0) / slope;
            if (a > b)
                std::swap(a, b);
            bandLo = std::max(bandLo, a), bandHi = std::min(bandHi, b);
        };
        within(s0, u.y, 0.0, len);
        within(e0, n.y, -c, c);
        if (bandLo < bandHi)
            lo = std::min(lo, bandLo), hi = std::max(hi, bandHi);
    }
    return {lo, hi};
}

// The clear part of the slice x between y lo and hi: the robot centre at least the
// clearance from every wall; the longest piece.
Interval clearSpan(double x, double lo, double hi, const std::vector<Segment>& walls, double c) {
    std::vector<Interval> blocked;
    for (const Segment& w : walls) {
        const Interval b = capsuleOnSlice(x, w, c);
        if (b.lo < b.hi)
            blocked.push_back(b);
    }
    std::sort(blocked.begin(), blocked.end(),
              [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
    Interval best{0, -1};
    double from = lo;
    auto offer = [&](double a, double b) {
        if (b >= a && (best.empty() || b - a > best.hi - best.lo))
            best = {a, b};
    };
    for (const Interval& b : blocked) {
        if (b.hi <= from)
            continue;
        if (b.lo >= hi)
            break;
        offer(from, std::min(b.lo, hi));
        from = std::max(from, b.hi);
    }
    offer(from, hi);
    return best;
}

} // namespace

Model buildModel(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                 const Options& options, int maxCells, const char* what) {
    Model model;
    model.frame =
        Frame(plan.boundary.empty() ? Vec2{} : plan.boundary.front(), options.stripeAngleDeg);
    const double w = options.width, c = options.clearance;
    std::vector<Segment> walls;
    auto addWalls = [&](const Ring& ring) {
        const Ring local = model.frame.toLocal(ring);
        for (std::size_t i = 0; i < local.size(); ++i)
            walls.push_back({local[i], local[(i + 1) % local.size()]});
    };
    addWalls(plan.boundary);
    for (const Ring& o : plan.obstacles)
        addWalls(o);
    std::vector<Edge> edges;
    std::vector<std::pair<int, int>> links;
    const std::vector<CellShape> shapes =
        decompose(regionRings(plan, rooms, model.frame), edges, links);
    if (maxCells > 0 && static_cast<int>(shapes.size()) > maxCells)
        throw TourError(std::string(what) + ": " + std::to_string(shapes.size()) +
                        " cells exceed its limit of " + std::to_string(maxCells) +
                        " (its transits grow with the square of the cells); plan fewer rooms "
                        "at a time");
    model.transits = std::make_unique<Transits>(walls, c, options.cancelled);
    Transits& transits = *model.transits;
    model.cellCount = static_cast<int>(shapes.size());
    std::vector<int> kept(shapes.size(), -1); // shape -> model cell
    for (const CellShape& shape : shapes) {
        Cell cell;
        cell.x0 = shape.pieces.front().xa, cell.x1 = shape.pieces.back().xb;
        const double width = cell.x1 - cell.x0;
        const int n = std::max(1, static_cast<int>(std::ceil(width / w - 1e-9)));
        // Stripes W apart (evenly, at most W), the outer ones W/2 inside the cell.
        std::vector<double> xs;
        for (int i = 0; i < n; ++i)
            xs.push_back(n == 1 ? 0.5 * (cell.x0 + cell.x1)
                                : cell.x0 + 0.5 * w + i * (width - w) / (n - 1));
        std::vector<std::pair<double, Interval>> stripes;
        for (double x : xs) {
            const double xc = std::clamp(x, cell.x0 + 1e-9, cell.x1 - 1e-9);
            const Interval span =
                clearSpan(xc, shape.floorAt(edges, xc), shape.ceilingAt(edges, xc), walls, c);
            if (!span.empty())
                stripes.push_back({xc, span});
        }
        if (stripes.empty()) {
            ++model.unreachable;
            continue;
        }
        for (const auto& [x, span] : stripes)
            cell.stripes.push_back({x, span});
        for (int o = 0; o < 4; ++o) {
            const bool rightToLeft = o & 1, downFirst = o & 2;
            std::vector<std::pair<double, Interval>> order = stripes;
            if (rightToLeft)
                std::reverse(order.begin(), order.end());
            Polyline points;
            bool up = !downFirst, drivable = true;
            for (const auto& [x, span] : order) {
                const Vec2 a{x, up ? span.lo : span.hi}, b{x, up ? span.hi : span.lo};
                if (!points.empty()) {
                    // Along the floor or ceiling to the next stripe; around what is in the way.
                    const Polyline link = transits.route(points.back(), a);
                    if (link.empty()) {
                        drivable = false;
                        break;
                    }
                    points.insert(points.end(), link.begin() + 1, link.end());
                } else {
                    points.push_back(a);
                }
                points.push_back(b);
                up = !up;
            }
            CoverOption& option = cell.options[o];
            if (!drivable)
                continue;
            option.points = std::move(points);
            option.length = polylineLength(option.points);
            option.entry = transits.addPoint(option.points.front());
            option.exit = transits.addPoint(option.points.back());
        }
        kept[&shape - shapes.data()] = static_cast<int>(model.cells.size());
        model.cells.push_back(std::move(cell));
    }
    for (const auto& [a, b] : links)
        if (kept[a] >= 0 && kept[b] >= 0)
            model.links.push_back({kept[a], kept[b]});
    model.start = transits.addPoint(model.frame.toLocal(start));
    model.end = transits.addPoint(model.frame.toLocal(end));
    return model;
}

} // namespace fc::baselines::detail

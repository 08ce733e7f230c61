// Builds the corner graph (SPEC sect. 3) from a decomposition: four corners per primary
// cell, two per transition cell, coverage pairs by stripe parity, contour-following edges
// and inter-cell edges with collision-free geometry.
#include "decomposition/StripePlanner.h"
#include "graph/ComponentBridges.h"
#include "graph/CornerGraph.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace fc {
namespace {

constexpr std::size_t kMaxInterChecks = 50000; // segment tests per inter-cell search

using detail::traceBorder;

struct StripeRun {
    double x;
    Interval span;
};

class GraphBuilder {
public:
    explicit GraphBuilder(const Decomposition& dec) : dec_(dec), field_(dec.clearance()) {}

    CornerGraph build() {
        graph_.cells.resize(dec_.cells.size());
        for (const Cell& cell : dec_.cells)
            addCell(cell);
        for (const Adjacency& a : dec_.adjacencies)
            addAdjacency(a);
        return std::move(graph_);
    }

private:
    // The robot-centre path between two points inside a cell along its top or bottom.
    Polyline border(const Cell& cell, const StripeRun& from, const StripeRun& to, bool top) {
        const Vec2 a{from.x, top ? from.span.hi : from.span.lo};
        const Vec2 b{to.x, top ? to.span.hi : to.span.lo};
        // Between one-point stripes (a band lower than W) the step is the coverage itself.
        const bool band = from.span.hi - from.span.lo <= 1e-9 && to.span.hi - to.span.lo <= 1e-9;
        if (chordSweepsBorder(cell, a, b, top || band, !top || band))
            return {a, b};
        Polyline line = traceBorder(cell, from.x, to.x, top, field_);
        if (line.size() >= 2 && field_.polylineIsClear(line))
            return line;
        return field_.findPath(a, b, {}, 8 * dec_.coverageWidth() + distance(a, b));
    }

    // Whether the straight step from a to b keeps the robot clear and its head reaches the
    // cell's ceiling (reachCeiling) and floor (reachFloor) all along. The border trace keeps
    // W/2 from them and so bends round every tooth of a traced wall shallower than W/2 - L/2
    // (the map's ragged edge), where the straight step sweeps the same floor.
    bool chordSweepsBorder(const Cell& cell, Vec2 a, Vec2 b, bool reachCeiling,
                           bool reachFloor) const {
        if (a.x == b.x || !field_.segmentIsClear(a, b))
            return false;
        const double half = 0.5 * dec_.coverageWidth(), tolerance = 1e-3 * half;
        const double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
        std::vector<double> xs{x0, x1};
        for (const Polyline* f : {&cell.floor, &cell.ceiling})
            for (const Vec2& p : *f)
                if (p.x > x0 && p.x < x1)
                    xs.push_back(p.x);
        const int uniform = static_cast<int>(std::ceil((x1 - x0) / (0.25 * half)));
        for (int i = 1; i < uniform; ++i)
            xs.push_back(x0 + (x1 - x0) * i / uniform);
        for (double x : xs) {
            const double y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
            if (reachCeiling && y + half < cell.ceilingAt(x) - tolerance)
                return false;
            if (reachFloor && y - half > cell.floorAt(x) + tolerance)
                return false;
        }
        return true;
    }

    // A flat head end leaves a wedge under a slanted floor or ceiling. Where no connection
    // runs along the border on one side of a stripe end, drive half a column along the
    // border and back so the head reaches the wall there too.
    void sealEnd(Polyline& path, const Cell& cell, const StripeRun& run, bool top, int side,
                 bool evenIfFlat = false) {
        const int begin = static_cast<int>(path.size()) - 1;
        if (detail::appendStripeEndSeal(path, cell, run.x, top ? run.span.hi : run.span.lo, top,
                                        side, evenIfFlat, field_, dec_.coverageWidth()))
            excursions_.push_back({begin, static_cast<int>(path.size()) - 1, top});
    }

    Polyline boustrophedon(const Cell& cell, const std::vector<StripeRun>& runs, bool fromBottom) {
        Polyline path;
        bool up = fromBottom;
        const size_t last = runs.size() - 1;
        for (size_t i = 0; i < runs.size(); ++i) {
            const Vec2 a{runs[i].x, up ? runs[i].span.lo : runs[i].span.hi};
            const Vec2 b{runs[i].x, up ? runs[i].span.hi : runs[i].span.lo};
            if (path.empty() || path.back() != a)
                path.push_back(a);
            // The stripe's start end is joined on its left (from the previous stripe), its
            // finish end on its right (to the next one); seal the other sides.
            // The outer half-columns of the first and last stripes are sealed even under a
            // flat border: no turn of this pattern sweeps them (the path builder drops the
            // seal where the arriving or leaving transit already does).
            if (i == 0)
                sealEnd(path, cell, runs[i], !up, -1, true);
            sealEnd(path, cell, runs[i], !up, +1);
            if (b != a)
                path.push_back(b);
            sealEnd(path, cell, runs[i], up, -1);
            if (i == last)
                sealEnd(path, cell, runs[i], up, +1, true);
            if (i + 1 < runs.size()) {
                const Polyline step = border(cell, runs[i], runs[i + 1], up);
                if (step.empty())
                    return {};
                path.insert(path.end(), step.begin() + 1, step.end());
            }
            up = !up;
        }
        return path;
    }

    // A single stripe has no neighbour stripe whose connection sweeps the W/2 margin at
    // its ends: seal both sides of both ends (pruned later where the path covers them).
    Polyline transitionStripe(const Cell& cell, const StripeRun& run) {
        const Vec2 bottom{run.x, run.span.lo}, top{run.x, run.span.hi};
        Polyline path{bottom};
        sealEnd(path, cell, run, false, -1, true);
        sealEnd(path, cell, run, false, +1, true);
        if (top != bottom)
            path.push_back(top);
        sealEnd(path, cell, run, true, -1, true);
        sealEnd(path, cell, run, true, +1, true);
        return path;
    }

    void addEdge(int u, int v, EdgeKind kind, int cell, bool parallel, Polyline geometry) {
        std::vector<Excursion> excursions;
        excursions.swap(excursions_); // recorded while this edge's geometry was built
        if (geometry.empty())
            return; // no collision-free connection: the graph simply lacks this edge
        if (geometry.size() == 1)
            geometry.push_back(geometry.front());
        GraphEdge e;
        e.u = u, e.v = v, e.kind = kind, e.cell = cell, e.parallel = parallel;
        e.length = polylineLength(geometry);
        e.geometry = std::move(geometry);
        e.excursions = std::move(excursions);
        graph_.addEdge(std::move(e));
    }

    void addCell(const Cell& cell) {
        GraphCell& gc = graph_.cells[cell.id];
        gc.id = cell.id;
        gc.kind = cell.kind;
        gc.room = cell.room;
        std::vector<StripeRun> runs;
        for (size_t i = 0; i < cell.stripes.size(); ++i)
            if (!cell.stripeSpans[i].empty())
                runs.push_back({cell.stripes[i], cell.stripeSpans[i]});
        gc.reachable = !runs.empty();
        if (runs.empty()) {
            // Keep the cell's corners (for a uniform node layout) but connect nothing.
            const Vec2 c{0.5 * (cell.x0 + cell.x1),
                         0.5 * (cell.floorAt(0.5 * (cell.x0 + cell.x1)) +
                                cell.ceilingAt(0.5 * (cell.x0 + cell.x1)))};
            if (cell.kind == CellKind::Transition) {
                graph_.addNode(cell.id, CornerKind::Bottom, c);
                graph_.addNode(cell.id, CornerKind::Top, c);
            } else {
                for (CornerKind k :
                     {CornerKind::LB, CornerKind::LT, CornerKind::RB, CornerKind::RT})
                    graph_.addNode(cell.id, k, c);
            }
            return;
        }
        const StripeRun& first = runs.front();
        const StripeRun& last = runs.back();
        const Vec2 lb{first.x, first.span.lo}, lt{first.x, first.span.hi};
        const Vec2 rb{last.x, last.span.lo}, rt{last.x, last.span.hi};
        if (cell.kind == CellKind::Transition) {
            const int b = graph_.addNode(cell.id, CornerKind::Bottom, lb);
            const int t = graph_.addNode(cell.id, CornerKind::Top, lt);
            addEdge(b, t, EdgeKind::Coverage, cell.id, false, transitionStripe(cell, first));
            return;
        }
        const int LB = graph_.addNode(cell.id, CornerKind::LB, lb);
        const int LT = graph_.addNode(cell.id, CornerKind::LT, lt);
        const int RB = graph_.addNode(cell.id, CornerKind::RB, rb);
        const int RT = graph_.addNode(cell.id, CornerKind::RT, rt);
        // Parity rule: with an even number of stripes a pass starting at the bottom ends at
        // the bottom of the last stripe.
        const bool even = runs.size() % 2 == 0;
        addEdge(LB, even ? RB : RT, EdgeKind::Coverage, cell.id, false,
                boustrophedon(cell, runs, true));
        addEdge(LT, even ? RT : RB, EdgeKind::Coverage, cell.id, false,
                boustrophedon(cell, runs, false));
        addEdge(LB, RB, EdgeKind::Contour, cell.id, false, border(cell, first, last, false));
        addEdge(LT, RT, EdgeKind::Contour, cell.id, false, border(cell, first, last, true));
        addEdge(LB, LT, EdgeKind::Contour, cell.id, true, {lb, lt});
        addEdge(RB, RT, EdgeKind::Contour, cell.id, true, {rb, rt});
    }

    enum class Side { Left, Right, Top, Bottom, All };

    std::vector<int> sideNodes(int cellId, Side side) const {
        const GraphCell& gc = graph_.cells[cellId];
        if (!gc.reachable)
            return {};
        if (gc.kind == CellKind::Transition || side == Side::All)
            return gc.nodes;
        const auto& n = gc.nodes; // LB, LT, RB, RT
        switch (side) {
        case Side::Left:
            return {n[0], n[1]};
        case Side::Right:
            return {n[2], n[3]};
        case Side::Top:
            return {n[1], n[3]};
        case Side::Bottom:
            return {n[0], n[2]};
        case Side::All:
            break;
        }
        return n;
    }

    // Clear points on vertical lines across a shared border: waypoints through doorways
    // and gaps exactly as wide as the robot, where corner offsets cannot be placed.
    std::vector<Vec2> borderHints(const Adjacency& a) const {
        std::vector<Vec2> hints;
        const Cell& lo = dec_.cells[a.first];
        const Cell& hi = dec_.cells[a.second];
        auto sampleLine = [&](double x, double y0, double y1) {
            for (const Interval& piece : field_.clearPieces(x, y0, y1)) {
                hints.push_back({x, piece.lo});
                hints.push_back({x, 0.5 * (piece.lo + piece.hi)});
                hints.push_back({x, piece.hi});
            }
        };
        const double w = dec_.coverageWidth();
        if (a.kind == Adjacency::Kind::AcrossSweep) {
            sampleLine(a.shared.a.x, std::min(a.shared.a.y, a.shared.b.y),
                       std::max(a.shared.a.y, a.shared.b.y));
            return hints;
        }
        const double x0 = a.shared.a.x, x1 = a.shared.b.x;
        const int n = std::max(2, static_cast<int>(std::ceil((x1 - x0) / (0.125 * w))));
        for (int i = 0; i <= n; ++i) {
            const double x = x0 + (x1 - x0) * i / n;
            sampleLine(x, lo.floorAt(x), hi.ceilingAt(x));
        }
        return hints;
    }

    // Through the best single waypoint on the shared border when that is clear (cheap,
    // and what a robot would drive); otherwise the general path search.
    Polyline connect(Vec2 p, Vec2 q, const std::vector<Vec2>& hints) const {
        if (field_.segmentIsClear(p, q))
            return {p, q};
        std::vector<std::pair<double, Vec2>> byLength;
        for (const Vec2& h : hints)
            byLength.push_back({distance(p, h) + distance(h, q), h});
        std::sort(byLength.begin(), byLength.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (size_t i = 0; i < byLength.size() && i < 4; ++i) {
            const Vec2 h = byLength[i].second;
            // Straight to the waypoint, or first along the stripe direction (a long cell
            // reached through an opening in its side).
            for (const Polyline& route :
                 {Polyline{p, h, q}, Polyline{p, {p.x, h.y}, h, q}, Polyline{p, h, {q.x, h.y}, q},
                  Polyline{p, {p.x, h.y}, h, {q.x, h.y}, q}})
                if (field_.polylineIsClear(route))
                    return route;
        }
        // An inter-cell connection that needs a long detour is not one: the graph reaches
        // those corners through other cells. The search is bounded as well: one that fails
        // tests every pair of wall corners in its window (hundreds on a traced map).
        return field_.findPath(p, q, hints, 8 * dec_.coverageWidth() + distance(p, q),
                               kMaxInterChecks);
    }

    void addAdjacency(const Adjacency& a) {
        std::vector<int> from, to;
        if (a.kind == Adjacency::Kind::AcrossSweep) {
            const double x = a.shared.a.x;
            const Cell& l = dec_.cells[a.first];
            const Cell& r = dec_.cells[a.second];
            from = sideNodes(l.id, l.x1 == x ? Side::Right : Side::All);
            to = sideNodes(r.id, r.x0 == x ? Side::Left : Side::All);
        } else {
            from = sideNodes(a.first, Side::Top);
            to = sideNodes(a.second, Side::Bottom);
        }
        std::vector<Vec2> hints;
        bool hintsMade = false;
        for (int u : from) {
            for (int v : to) {
                if (!connected_.insert({std::min(u, v), std::max(u, v)}).second)
                    continue;
                const Vec2 p = graph_.nodes[u].position, q = graph_.nodes[v].position;
                if (!field_.segmentIsClear(p, q) && !hintsMade) {
                    hints = borderHints(a);
                    hintsMade = true;
                }
                addEdge(u, v, EdgeKind::Inter, -1, false, connect(p, q, hints));
            }
        }
    }

    const Decomposition& dec_;
    const ClearanceField& field_;
    CornerGraph graph_;
    std::set<std::pair<int, int>> connected_; // inter-cell pairs already joined
    std::vector<Excursion> excursions_;       // of the coverage pattern being built
};

} // namespace

CornerGraph buildCornerGraph(const Decomposition& decomposition) {
    CornerGraph graph = GraphBuilder(decomposition).build();
    bridgeComponents(graph, decomposition.clearance());
    return graph;
}

} // namespace fc

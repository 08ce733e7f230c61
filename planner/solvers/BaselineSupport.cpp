#include "solvers/BaselineSupport.h"

#include "decomposition/StripePlanner.h"
#include "solvers/SolverCommon.h"

#include <algorithm>
#include <string>

namespace fc {

namespace baseline_detail {
namespace {

std::vector<std::pair<double, Interval>> clearRuns(const Cell& cell) {
    std::vector<std::pair<double, Interval>> runs;
    for (size_t i = 0; i < cell.stripes.size(); ++i)
        if (!cell.stripeSpans[i].empty())
            runs.push_back({cell.stripes[i], cell.stripeSpans[i]});
    return runs;
}

} // namespace

BaselineWorld makeBaselineWorld(const PreparedPlan& prepared, const Query& query,
                                const char* solverName) {
    if (!prepared.classic)
        throw SolverError(std::string(solverName) +
                          ": the classic decomposition was not prepared (PreparedPlan::classic)");
    // The rooms of the required cells, and the start node's position.
    std::vector<char> requiredRooms(prepared.decomposition.roomNames.size(), 0);
    for (const GraphCell& c : prepared.graph.cells)
        if (c.id < static_cast<int>(query.required.size()) && query.required[c.id])
            requiredRooms[c.room] = 1;
    BaselineWorld world(prepared.classic->decomposition, prepared.classic->graph);
    if (world.decomposition.roomNames.size() != requiredRooms.size())
        throw SolverError(std::string(solverName) + ": the rooms of the plan changed");
    world.start = prepared.graph.nodes.at(query.startNode).position;
    world.seed = query.seed;
    const int startNode = nearestNode(world.graph, world.start);
    world.startCell = world.graph.nodes[startNode].cell;
    // Cells whose corners the start node reaches over the graph's edges.
    world.usable.assign(world.graph.cells.size(), 0);
    const std::vector<char> seen = solver_detail::reachableFrom(world.graph, startNode);
    for (const GraphNode& n : world.graph.nodes)
        world.usable[n.cell] = world.usable[n.cell] || seen[n.id];
    world.required.assign(world.graph.cells.size(), 0);
    for (const GraphCell& c : world.graph.cells) {
        world.usable[c.id] = world.usable[c.id] && c.reachable;
        world.required[c.id] =
            world.usable[c.id] && requiredRooms[c.room] && !c.coverageEdges.empty();
    }
    if (std::none_of(world.required.begin(), world.required.end(), [](char r) { return r; }))
        throw SolverError(std::string(solverName) +
                          ": no required area can be reached from the start");
    return world;
}

std::set<std::pair<int, int>> connectedCellPairs(const CornerGraph& graph) {
    std::set<std::pair<int, int>> pairs;
    for (const GraphEdge& e : graph.edges) {
        const int a = graph.nodes[e.u].cell, b = graph.nodes[e.v].cell;
        if (e.kind == EdgeKind::Inter && a != b)
            pairs.insert({std::min(a, b), std::max(a, b)});
    }
    return pairs;
}

Vec2 cellCentre(const Cell& cell) {
    const auto runs = clearRuns(cell);
    const auto& [x, span] = runs.at(runs.size() / 2);
    return {x, 0.5 * (span.lo + span.hi)};
}

namespace {

// Where a stripe of a band ends: y of its low and high end, and which of them are walls.
struct StripeEnds {
    double low, high;
    bool lowAtWall, highAtWall;
};

StripeEnds stripeEnds(Interval span, CellPart part) {
    const double middle = 0.5 * (span.lo + span.hi);
    switch (part) {
    case CellPart::Top:
        return {middle, span.hi, false, true};
    case CellPart::Bottom:
        return {span.lo, middle, true, false};
    case CellPart::Whole:
        break;
    }
    return {span.lo, span.hi, true, true};
}

} // namespace

Pattern boustrophedon(const Cell& cell, const ClearanceField& field, double width, CellPart part,
                      bool leftToRight, bool startLow) {
    auto runs = clearRuns(cell);
    if (!leftToRight)
        std::reverse(runs.begin(), runs.end());
    const int forward = leftToRight ? 1 : -1; // towards the next stripe, in x
    Pattern out;
    // Seals the wall end of a stripe on one side (see appendStripeEndSeal).
    auto seal = [&](double x, double wallY, bool top, int side, bool evenIfFlat) {
        const int begin = static_cast<int>(out.points.size()) - 1;
        const Vec2 end = out.points.back();
        if (detail::appendStripeEndSeal(out.points, cell, x, wallY, top, side * forward, evenIfFlat,
                                        field, width)) {
            out.excursions.push_back({begin, static_cast<int>(out.points.size()) - 1, top});
            return;
        }
        // The traced border needs one clear span across the cell where the seal turns; at a
        // slice split by an obstacle's side there are two, so drive straight along the wall.
        const Vec2 tip{std::clamp(x + side * forward * 0.5 * width, cell.x0, cell.x1), wallY};
        if (evenIfFlat && distance(tip, end) >= 0.125 * width && field.segmentIsClear(end, tip)) {
            out.points.push_back(tip);
            out.points.push_back(end);
            out.excursions.push_back({begin, static_cast<int>(out.points.size()) - 1, top});
        }
    };
    // A wall end is joined along the wall to the stripe behind (where the stripe starts) or
    // ahead (where it finishes); the turn onto that step sweeps the corner on the other
    // side under a flat wall. Sides no step joins are sealed where the wall is slanted, and
    // even under a flat wall where no step meets the end at all (no turn sweeps it).
    auto sealWallEnd = [&](double x, double wallY, bool top, bool stepBehind, bool stepAhead) {
        const bool turn = stepBehind || stepAhead;
        if (!stepBehind)
            seal(x, wallY, top, -1, !turn);
        if (!stepAhead)
            seal(x, wallY, top, +1, !turn);
    };
    bool up = startLow;
    const size_t last = runs.size() - 1;
    for (size_t i = 0; i < runs.size(); ++i) {
        const double x = runs[i].first;
        const StripeEnds ends = stripeEnds(runs[i].second, part);
        const Vec2 low{x, ends.low}, high{x, ends.high};
        const Vec2 a = up ? low : high, b = up ? high : low;
        const bool aAtWall = up ? ends.lowAtWall : ends.highAtWall;
        const bool bAtWall = up ? ends.highAtWall : ends.lowAtWall;
        if (out.points.empty() || out.points.back() != a)
            out.points.push_back(a);
        if (aAtWall)
            sealWallEnd(x, a.y, !up, i > 0, false);
        if (b != a)
            out.points.push_back(b);
        if (bAtWall)
            sealWallEnd(x, b.y, up, false, i < last);
        if (i == last)
            break;
        // The step to the next stripe: along the wall at a wall end, straight in the middle.
        const StripeEnds nextEnds = stripeEnds(runs[i + 1].second, part);
        const double nx = runs[i + 1].first;
        const Vec2 next{nx, up ? nextEnds.high : nextEnds.low};
        Polyline step = bAtWall ? detail::traceBorder(cell, x, nx, up, field) : Polyline{b, next};
        if (step.size() < 2 || !field.polylineIsClear(step))
            step = field.findPath(b, next);
        if (step.empty())
            throw SolverError("no collision-free step between two stripes of a cell");
        out.points.insert(out.points.end(), step.begin() + 1, step.end());
        up = !up;
    }
    return out;
}

TourBuilder::TourBuilder(Vec2 start, const ClearanceField& field, const CornerGraph& graph,
                         const char* solverName)
    : field_(field), graph_(graph), solverName_(solverName) {
    tour_.path.points.push_back(start);
}

void TourBuilder::append(Vec2 p, SegmentKind kind) {
    tour_.path.points.push_back(p);
    tour_.path.kinds.push_back(kind);
}

void TourBuilder::travelTo(Vec2 target) {
    const Vec2 from = position();
    if (distance(from, target) < 1e-9)
        return;
    Polyline route = field_.segmentIsClear(from, target) ? Polyline{from, target}
                                                         : field_.findPath(from, target);
    if (route.empty())
        route = routeOverGraph(from, target);
    if (route.empty())
        throw SolverError(std::string(solverName_) + ": no collision-free transit between cells");
    for (size_t i = 1; i < route.size(); ++i)
        append(route[i], SegmentKind::Transit);
}

Polyline TourBuilder::routeOverGraph(Vec2 from, Vec2 target) const {
    // The nearest corner joined to a point by a clear straight segment.
    auto nearestSeen = [&](Vec2 p) {
        int best = -1;
        for (const GraphNode& n : graph_.nodes)
            if ((best < 0 || distance(n.position, p) < distance(graph_.nodes[best].position, p)) &&
                field_.segmentIsClear(p, n.position))
                best = n.id;
        return best;
    };
    const int source = nearestSeen(from), goal = nearestSeen(target);
    if (source < 0 || goal < 0)
        return {};
    // Over contour and inter-cell edges (a coverage edge is a whole pattern).
    const ShortestPaths sp = shortestPaths(graph_.nodes.size(), {source}, [&](int u, auto&& visit) {
        for (int e : graph_.incident[u])
            if (graph_.edges[e].kind != EdgeKind::Coverage)
                visit(graph_.edges[e].other(u), graph_.edges[e].length, e);
    });
    if (sp.dist[goal] == INFINITY)
        return {};
    Polyline reversed{target};
    for (int v = goal; v != source; v = graph_.edges[sp.via[v]].other(v)) {
        const GraphEdge& edge = graph_.edges[sp.via[v]];
        if (edge.v == v)
            reversed.insert(reversed.end(), edge.geometry.rbegin(), edge.geometry.rend());
        else
            reversed.insert(reversed.end(), edge.geometry.begin(), edge.geometry.end());
    }
    reversed.push_back(graph_.nodes[source].position);
    reversed.push_back(from);
    return Polyline(reversed.rbegin(), reversed.rend());
}

void TourBuilder::follow(const Pattern& pattern) {
    travelTo(pattern.points.front());
    const int offset = static_cast<int>(tour_.path.points.size()) - 1;
    for (size_t i = 1; i < pattern.points.size(); ++i)
        append(pattern.points[i], SegmentKind::Stripe);
    for (const Excursion& x : pattern.excursions)
        tour_.excursions.push_back({x.begin + offset, x.end + offset, x.towardsCeiling});
}

Solution baselineSolution(const char* solverName, DirectPath tour) {
    Solution s;
    s.solver = solverName;
    s.directPath = std::move(tour);
    return s;
}

} // namespace baseline_detail
} // namespace fc

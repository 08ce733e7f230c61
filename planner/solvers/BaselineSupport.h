// Internal to the baselines (reeb-cpp, adjacency-ga): the classic decomposition they plan on,
// cell patterns and the tour they assemble as a robot-centre path.
#pragma once

#include "geometry/Clearance.h"
#include "solvers/Baselines.h"

#include <cmath>
#include <functional>
#include <queue>
#include <set>
#include <utility>
#include <vector>

namespace fc::baseline_detail {

constexpr double kInf = INFINITY; // a distance not reached

// The classic Boustrophedon decomposition and its corner graph (PreparedPlan::classic), which
// tells which cells are connected (its inter-cell edges), where the cells' corners are (the
// Reeb nodes' positions) and carries transits through gaps exactly W wide.
struct BaselineWorld {
    BaselineWorld(const Decomposition& d, const CornerGraph& g) : decomposition(d), graph(g) {}

    const Decomposition& decomposition;
    const CornerGraph& graph;
    std::vector<char> usable;   // per cell: sweepable and connected to the start
    std::vector<char> required; // per cell: usable and in a required room
    int startCell = -1;
    Vec2 start; // sweep frame
    std::uint64_t seed = 1;
};

// The query of the corner-graph solvers restated on the classic decomposition: the rooms of
// the required cells, and the start node's position (baselines always return to their start).
// Throws SolverError when the classic stages were not prepared or no required area is
// reachable from the start.
BaselineWorld makeBaselineWorld(const PreparedPlan& prepared, const Query& query,
                                const char* solverName);

// Pairs (lower id, higher id) of cells joined by at least one collision-free inter-cell
// edge of the graph.
std::set<std::pair<int, int>> connectedCellPairs(const CornerGraph& graph);

struct ShortestPaths {
    std::vector<double> dist;
    std::vector<int> via; // what reached each node (an edge id or the previous node), -1 at
                          // the sources and at nodes not reached
};

// Dijkstra from `sources`; forEachNeighbour(u, visit) calls visit(v, length, via) for every
// neighbour v of node u.
template <class ForEachNeighbour>
ShortestPaths shortestPaths(std::size_t nodeCount, const std::vector<int>& sources,
                            ForEachNeighbour forEachNeighbour) {
    ShortestPaths sp{std::vector<double>(nodeCount, INFINITY), std::vector<int>(nodeCount, -1)};
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (int s : sources) {
        sp.dist[s] = 0;
        queue.push({0.0, s});
    }
    while (!queue.empty()) {
        const double d = queue.top().first;
        const int u = queue.top().second;
        queue.pop();
        if (d > sp.dist[u])
            continue;
        forEachNeighbour(u, [&](int v, double length, int via) {
            if (d + length < sp.dist[v]) {
                sp.dist[v] = d + length;
                sp.via[v] = via;
                queue.push({sp.dist[v], v});
            }
        });
    }
    return sp;
}

// A clear point in the middle of a cell: the middle of its middle stripe's clear span.
Vec2 cellCentre(const Cell& cell);

// A piece of path in the sweep frame with the seal excursions it contains.
struct Pattern {
    Polyline points;
    std::vector<Excursion> excursions;
};

enum class CellPart { Whole, Top, Bottom };

// A cell's boustrophedon over its whole clear height, or over its top or bottom half (from
// the ceiling or floor to the middle of each stripe's clear span: how the Reeb-graph method
// covers a cell on a duplicated edge, with the turns in the middle that it causes). Stripes
// are visited left to right or right to left; the first runs up (startLow) or down. Steps
// follow the wall at wall ends and run straight in the middle; stripe ends at walls are
// sealed as the corner graph's patterns are (see appendStripeEndSeal).
Pattern boustrophedon(const Cell& cell, const ClearanceField& field, double width, CellPart part,
                      bool leftToRight, bool startLow);

// Accumulates a tour from a start point.
class TourBuilder {
public:
    // graph: the classic decomposition's corner graph, whose contour and inter-cell edges
    // carry transits through gaps exactly W wide that the clearance search cannot find.
    TourBuilder(Vec2 start, const ClearanceField& field, const CornerGraph& graph,
                const char* solverName);

    Vec2 position() const { return tour_.path.points.back(); }
    // Straight when clear, else the shortest path around the walls, else over the corner
    // graph's edges; throws SolverError when none exists.
    void travelTo(Vec2 target);
    // Travels to the pattern's first point, then follows it (kind Stripe).
    void follow(const Pattern& pattern);

    DirectPath take() { return std::move(tour_); }

private:
    void append(Vec2 p, SegmentKind kind);
    Polyline routeOverGraph(Vec2 from, Vec2 target) const;

    const ClearanceField& field_;
    const CornerGraph& graph_;
    const char* solverName_;
    DirectPath tour_;
};

// cellOrder stays empty: the baselines' cells are not the corner graph's.
Solution baselineSolution(const char* solverName, DirectPath tour);

} // namespace fc::baseline_detail

// Internal to the baselines (reeb-cpp, adjacency-ga): the classic decomposition they plan on,
// cell patterns and the tour they assemble as a robot-centre path.
#pragma once

#include "geometry/Clearance.h"
#include "solvers/Baselines.h"

#include <set>
#include <utility>
#include <vector>

namespace fc::baseline_detail {

// The classic Boustrophedon decomposition and its corner graph: the graph's coverage edges
// are the cells' full boustrophedon patterns, its corners the cells' entry/exit points.
struct BaselineWorld {
    Decomposition decomposition;
    CornerGraph graph;
    std::vector<char> usable;   // per cell: sweepable and connected to the start
    std::vector<char> required; // per cell: usable and in a required room
    int startCell = -1;
    Vec2 start; // sweep frame
    std::uint64_t seed = 1;
};

// Throws SolverError when no required area is reachable from the start.
BaselineWorld makeBaselineWorld(const BaselineQuery& query, const char* solverName);

// Pairs (lower id, higher id) of cells joined by at least one collision-free inter-cell
// edge of the graph.
std::set<std::pair<int, int>> connectedCellPairs(const CornerGraph& graph);

// A clear point in the middle of a cell: the middle of its middle stripe's clear span.
Vec2 cellCentre(const Cell& cell);

// A piece of path in the sweep frame with the seal excursions it contains.
struct Pattern {
    Polyline points;
    std::vector<Excursion> excursions;
};

// Half of a cell's boustrophedon: every stripe from the wall (floor, or ceiling for the top
// half) to the middle of its clear span, stripes visited left to right or right to left,
// the first stripe starting at the wall or in the middle. Split cells on the Reeb graph's
// duplicated edges are covered this way, with the turns in the middle that it causes.
Pattern halfBoustrophedon(const Cell& cell, const ClearanceField& field, double width, bool topHalf,
                          bool leftToRight, bool startAtWall);

// Accumulates a tour that starts at the world's start point.
class TourBuilder {
public:
    TourBuilder(const BaselineWorld& world, const ClearanceField& field, const char* solverName);

    Vec2 position() const { return tour_.path.points.back(); }
    // Straight when clear, else the shortest path around the walls; throws SolverError when
    // none exists.
    void travelTo(Vec2 target);
    // Travels to the pattern's first point, then follows it (kind Stripe).
    void follow(const Pattern& pattern);
    // The graph's coverage edge traversed from node `from`.
    void cover(int coverageEdge, int from);

    DirectPath take() { return std::move(tour_); }

private:
    void append(Vec2 p, SegmentKind kind);

    const BaselineWorld& world_;
    const ClearanceField& field_;
    const char* solverName_;
    DirectPath tour_;
};

// cellOrder stays empty: the baselines' cells are not the corner graph's.
Solution baselineSolution(const char* solverName, DirectPath tour);

} // namespace fc::baseline_detail

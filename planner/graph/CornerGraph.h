// The corner graph of SPEC sect. 3 and its state-dependent graph cost.
#pragma once

#include "decomposition/Decomposition.h"

#include <vector>

namespace fc {

enum class CornerKind { LB, LT, RB, RT, Bottom, Top };
enum class EdgeKind { Coverage, Contour, Inter };

struct GraphNode {
    int id = -1;
    int cell = -1;
    CornerKind corner = CornerKind::LB;
    Vec2 position; // sweep frame
};

// A there-and-back piece of a coverage pattern that sweeps the W/2 margin at a stripe end
// (geometry[begin] == geometry[end]); the path builder drops it where the rest of the path
// already sweeps that margin.
struct Excursion {
    int begin = 0, end = 0;
    bool towardsCeiling = false; // the wall is above the stripe end (sweep frame)
};

struct GraphEdge {
    int id = -1;
    int u = -1, v = -1;
    EdgeKind kind = EdgeKind::Inter;
    int cell = -1;         // owning cell for coverage and contour edges, -1 for inter
    bool parallel = false; // contour edge along a stripe (LB-LT, RB-RT)
    double length = 0.0;   // collision-free travel length (coverage: the whole pattern)
    Polyline geometry;     // robot-centre polyline from u to v, sweep frame
    std::vector<Excursion> excursions;

    int other(int node) const { return node == u ? v : u; }
};

struct GraphCell {
    int id = -1;
    CellKind kind = CellKind::Primary;
    int room = 0;
    std::vector<int> nodes;         // LB, LT, RB, RT or Bottom, Top
    std::vector<int> coverageEdges; // two for primary cells, one for transition cells
    bool reachable = true;          // false when no stripe fits (reported, never required)
};

struct CornerGraph {
    std::vector<GraphNode> nodes;
    std::vector<GraphEdge> edges;
    std::vector<GraphCell> cells;
    std::vector<std::vector<int>> incident; // node -> edge ids
    double maxEdgeLength = 0.0;

    int addNode(int cell, CornerKind corner, Vec2 position);
    int addEdge(GraphEdge edge); // assigns id, updates incident and maxEdgeLength
};

// Cost factor for overlap (SPEC sect. 3).
constexpr double kOverlapFactor = 3.0;

// Cost of traversing an edge given whether its cell is already covered
// (non-required cells count as covered). An edge of an uncovered cell's coverage pair
// costs 0: traversing it covers the cell.
inline double edgeCost(const GraphEdge& e, bool cellCovered) {
    switch (e.kind) {
    case EdgeKind::Coverage:
        return cellCovered ? kOverlapFactor * e.length : 0.0;
    case EdgeKind::Contour:
        return (e.parallel || cellCovered) ? kOverlapFactor * e.length : e.length;
    case EdgeKind::Inter:
        break;
    }
    return e.length;
}

CornerGraph buildCornerGraph(const Decomposition& decomposition);

// Nearest node to a point (sweep frame); prefers nodes of reachable cells.
int nearestNode(const CornerGraph& graph, Vec2 localPoint);

} // namespace fc

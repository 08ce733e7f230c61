// Hand-built corner graphs shared by the environment and agent tests.
#pragma once

#include "graph/CornerGraph.h"

#include <vector>

namespace fc::test {

inline int addEdge(CornerGraph& graph, int u, int v, EdgeKind kind, int cell, bool parallel,
                   double length) {
    GraphEdge e;
    e.u = u;
    e.v = v;
    e.kind = kind;
    e.cell = cell;
    e.parallel = parallel;
    e.length = length;
    return graph.addEdge(e);
}

inline int newCell(CornerGraph& graph, CellKind kind) {
    GraphCell cell;
    cell.id = static_cast<int>(graph.cells.size());
    cell.kind = kind;
    graph.cells.push_back(cell);
    return cell.id;
}

// addNode / addEdge record a cell's nodes and coverage edges.
// A primary cell: nodes LB, LT, RB, RT; coverage pair by stripe parity, sweep length
// stripes x height + width; contour edges along floor, ceiling and the two end stripes.
inline void primary(CornerGraph& g, double x0, double x1, double y0, double y1, int stripes) {
    const int cell = newCell(g, CellKind::Primary);
    const int lb = g.addNode(cell, CornerKind::LB, {x0, y0});
    const int lt = g.addNode(cell, CornerKind::LT, {x0, y1});
    const int rb = g.addNode(cell, CornerKind::RB, {x1, y0});
    const int rt = g.addNode(cell, CornerKind::RT, {x1, y1});
    const double sweep = stripes * (y1 - y0) + (x1 - x0);
    const bool even = stripes % 2 == 0;
    addEdge(g, lb, even ? rb : rt, EdgeKind::Coverage, cell, false, sweep);
    addEdge(g, lt, even ? rt : rb, EdgeKind::Coverage, cell, false, sweep);
    addEdge(g, lb, rb, EdgeKind::Contour, cell, false, x1 - x0);
    addEdge(g, lt, rt, EdgeKind::Contour, cell, false, x1 - x0);
    addEdge(g, lb, lt, EdgeKind::Contour, cell, true, y1 - y0);
    addEdge(g, rb, rt, EdgeKind::Contour, cell, true, y1 - y0);
}

inline void transition(CornerGraph& g, double x, double y0, double y1) {
    const int cell = newCell(g, CellKind::Transition);
    const int bottom = g.addNode(cell, CornerKind::Bottom, {x, y0});
    const int top = g.addNode(cell, CornerKind::Top, {x, y1});
    addEdge(g, bottom, top, EdgeKind::Coverage, cell, false, y1 - y0);
}

inline void join(CornerGraph& g, const std::vector<int>& a, const std::vector<int>& b) {
    for (int u : a)
        for (int v : b)
            addEdge(g, u, v, EdgeKind::Inter, -1, false,
                    distance(g.nodes[u].position, g.nodes[v].position));
}

// Cell 0: primary [0,2]x[0,2], 2 stripes (coverage LB-RB, LT-RT, length 6), nodes 0-3.
// Cell 1: transition at x = 3, y in [0,2] (coverage length 2), nodes 4 (bottom), 5 (top).
// Cell 2: primary [4,7]x[0,2], 3 stripes (coverage LB-RT, LT-RB, length 9), nodes 6-9.
// Inter edges: 1 straight across, sqrt(5) diagonally. Largest edge length 9.
inline CornerGraph threeCells() {
    CornerGraph g;
    primary(g, 0, 2, 0, 2, 2);
    transition(g, 3, 0, 2);
    primary(g, 4, 7, 0, 2, 3);
    join(g, {2, 3}, {4, 5});
    join(g, {4, 5}, {6, 7});
    return g;
}

} // namespace fc::test

#include "graph/CornerGraph.h"

#include <limits>

namespace fc {

int CornerGraph::addNode(int cell, CornerKind corner, Vec2 position) {
    GraphNode n;
    n.id = static_cast<int>(nodes.size());
    n.cell = cell;
    n.corner = corner;
    n.position = position;
    nodes.push_back(n);
    incident.emplace_back();
    if (cell >= 0 && cell < static_cast<int>(cells.size()))
        cells[cell].nodes.push_back(n.id);
    return n.id;
}

int CornerGraph::addEdge(GraphEdge edge) {
    edge.id = static_cast<int>(edges.size());
    incident[edge.u].push_back(edge.id);
    if (edge.v != edge.u)
        incident[edge.v].push_back(edge.id);
    if (edge.length > maxEdgeLength)
        maxEdgeLength = edge.length;
    if (edge.kind == EdgeKind::Coverage && edge.cell >= 0)
        cells[edge.cell].coverageEdges.push_back(edge.id);
    edges.push_back(std::move(edge));
    return edges.back().id;
}

int nearestNode(const CornerGraph& graph, Vec2 p) {
    int best = -1;
    double bestD = std::numeric_limits<double>::infinity();
    for (int pass = 0; pass < 2 && best < 0; ++pass) {
        for (const GraphNode& n : graph.nodes) {
            if (pass == 0 && !graph.cells[n.cell].reachable)
                continue;
            const double d = distance(n.position, p);
            if (d < bestD) {
                bestD = d;
                best = n.id;
            }
        }
    }
    return best;
}

} // namespace fc

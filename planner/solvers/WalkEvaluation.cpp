// The single implementation of the graph cost of a walk (SPEC sect. 3): every solver's
// reported cost comes from here, never from its own bookkeeping.
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"

namespace fc {

using solver_detail::isRequiredCell;

WalkEvaluation evaluateWalk(const CornerGraph& graph, const Query& query, const Walk& walk) {
    const int nodeCount = static_cast<int>(graph.nodes.size());
    const int edgeCount = static_cast<int>(graph.edges.size());
    auto validNode = [&](int node) { return node >= 0 && node < nodeCount; };

    WalkEvaluation result;
    bool connected = !walk.nodes.empty() && walk.nodes.size() == walk.edges.size() + 1 &&
                     walk.nodes.front() == query.startNode && walk.nodes.back() == query.endNode &&
                     validNode(query.startNode) && validNode(query.endNode);

    // Non-required cells count as covered from the start.
    std::vector<char> covered(graph.cells.size(), 0);
    for (const GraphCell& cell : graph.cells)
        covered[cell.id] = isRequiredCell(graph, query, cell.id) ? 0 : 1;

    for (std::size_t i = 0; i < walk.edges.size(); ++i) {
        const int id = walk.edges[i];
        if (id < 0 || id >= edgeCount) {
            connected = false;
            continue;
        }
        const GraphEdge& edge = graph.edges[id];
        if (i + 1 < walk.nodes.size()) {
            const int a = walk.nodes[i];
            const int b = walk.nodes[i + 1];
            if (!((edge.u == a && edge.v == b) || (edge.u == b && edge.v == a)))
                connected = false;
        }
        const bool cellCovered =
            edge.cell < 0 || edge.cell >= static_cast<int>(covered.size()) || covered[edge.cell];
        result.graphCost += edgeCost(edge, cellCovered);
        if (edge.kind == EdgeKind::Coverage && !cellCovered) {
            covered[edge.cell] = 1;
            result.cellOrder.push_back(edge.cell);
        }
    }
    for (int node : walk.nodes)
        if (!validNode(node))
            connected = false;

    result.connected = connected;
    result.coversAllRequired = true;
    for (char c : covered)
        if (!c)
            result.coversAllRequired = false;
    return result;
}

} // namespace fc

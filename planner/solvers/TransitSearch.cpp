#include "solvers/TransitSearch.h"

namespace fc::solver_detail {

TransitGraph::TransitGraph(const Problem& problem_) : problem(&problem_) {
    const CornerGraph& graph = *problem_.graph;
    const int nodes = static_cast<int>(graph.nodes.size());
    const int cellCount = static_cast<int>(graph.cells.size());

    positions.reserve(nodes);
    for (const GraphNode& node : graph.nodes)
        positions.push_back(node.position);

    adjacencyOffset.assign(nodes + 1, 0);
    for (int n = 0; n < nodes; ++n) {
        adjacencyOffset[n] = static_cast<int>(adjacencyEdge.size());
        for (int e : graph.incident[n]) {
            const int other = graph.edges[e].other(n);
            if (other == n && graph.edges[e].kind != EdgeKind::Coverage)
                continue; // a loop never shortens a walk (a coverage loop can cover a cell)
            adjacencyEdge.push_back(e);
            adjacencyNode.push_back(other);
        }
    }
    adjacencyOffset[nodes] = static_cast<int>(adjacencyEdge.size());

    const std::size_t edges = graph.edges.size();
    edgeSlot.resize(edges);
    truePrices.uncovered.resize(edges);
    truePrices.covered.resize(edges);
    heuristicScale = 1.0;
    for (const GraphEdge& edge : graph.edges) {
        const bool ownedByCell = edge.cell >= 0 && edge.cell < cellCount;
        edgeSlot[edge.id] = ownedByCell ? edge.cell : cellCount;
        truePrices.covered[edge.id] = edgeCost(edge, true);
        truePrices.uncovered[edge.id] =
            edge.kind == EdgeKind::Coverage ? kInfinity : edgeCost(edge, false);
        // Every finite price is at least the edge's length.
        const double straight = distance(positions[edge.u], positions[edge.v]);
        if (straight > 0.0)
            heuristicScale = std::min(heuristicScale, std::max(0.0, edge.length) / straight);
    }
    heuristicScale *= 1.0 - 1e-9; // keeps the estimate below the cost despite rounding
}

std::vector<char> TransitGraph::initialCoverage() const {
    std::vector<char> covered(problem->taskOfCell.size() + 1, 1);
    for (int cell : problem->taskCells)
        covered[cell] = 0;
    return covered;
}

TransitSearch::TransitSearch(const TransitGraph& graph)
    : graph_(graph), cost_(graph.nodeCount(), kInfinity), estimate_(graph.nodeCount(), 0.0),
      parentEdge_(graph.nodeCount(), -1), labelStamp_(graph.nodeCount(), 0),
      settledStamp_(graph.nodeCount(), 0), targetStamp_(graph.nodeCount(), 0) {}

void TransitSearch::begin(const std::vector<NodeCost>& sources) {
    if (++generation_ == 0) { // stamps wrapped: clear them once every 2^32 searches
        std::fill(labelStamp_.begin(), labelStamp_.end(), 0);
        std::fill(settledStamp_.begin(), settledStamp_.end(), 0);
        std::fill(targetStamp_.begin(), targetStamp_.end(), 0);
        generation_ = 1;
    }
    heap_.clear();
    for (const NodeCost& source : sources) {
        if (!(source.cost < kInfinity))
            continue;
        if (labelStamp_[source.node] == generation_ && source.cost >= cost_[source.node])
            continue;
        if (labelStamp_[source.node] != generation_) {
            labelStamp_[source.node] = generation_;
            estimate_[source.node] = estimate(source.node);
        }
        cost_[source.node] = source.cost;
        parentEdge_[source.node] = -1;
        heap_.push_back({source.cost + estimate_[source.node], source.cost, source.node});
        std::push_heap(heap_.begin(), heap_.end());
    }
}

double TransitSearch::estimate(int node) {
    if (targetPositions_.empty() || graph_.heuristicScale <= 0.0)
        return 0.0;
    const Vec2 p = graph_.positions[node];
    double nearestSquared = kInfinity;
    for (const Vec2& t : targetPositions_) {
        const Vec2 d = p - t;
        nearestSquared = std::min(nearestSquared, d.x * d.x + d.y * d.y);
    }
    return graph_.heuristicScale * std::sqrt(nearestSquared);
}

void TransitSearch::run(const EdgePrices& prices, const std::vector<char>& covered,
                        const std::vector<NodeCost>& sources, const std::vector<int>& targets) {
    targetPositions_.clear();
    for (int t : targets)
        targetPositions_.push_back(graph_.positions[t]);
    begin(sources);
    int remaining = 0;
    for (int t : targets) {
        if (targetStamp_[t] != generation_) {
            targetStamp_[t] = generation_;
            ++remaining;
        }
    }
    if (remaining == 0) {
        loop(prices, covered, [](int, double) { return false; });
        return;
    }
    loop(prices, covered,
         [&](int node, double) { return targetStamp_[node] == generation_ && --remaining == 0; });
}

int TransitSearch::sourceOf(int node) const {
    while (parentEdge_[node] >= 0)
        node = graph_.problem->graph->edges[parentEdge_[node]].other(node);
    return node;
}

std::vector<int> TransitSearch::edgesTo(int node) const {
    const CornerGraph& graph = *graph_.problem->graph;
    std::vector<int> edges;
    for (int at = node; parentEdge_[at] >= 0; at = graph.edges[parentEdge_[at]].other(at))
        edges.push_back(parentEdge_[at]);
    std::reverse(edges.begin(), edges.end());
    return edges;
}

void TransitSearch::appendWalkTo(int node, Walk& walk) const {
    const CornerGraph& graph = *graph_.problem->graph;
    for (int edge : edgesTo(node)) {
        walk.edges.push_back(edge);
        walk.nodes.push_back(graph.edges[edge].other(walk.nodes.back()));
    }
}

} // namespace fc::solver_detail

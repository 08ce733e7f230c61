#include "solvers/TransitSearch.h"

#include <functional>
#include <limits>

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
    chooseLandmarks(nodes > 64 ? 8 : 0);
}

void TransitGraph::chooseLandmarks(int count) {
    const int nodes = nodeCount();
    const CornerGraph& graph = *problem->graph;
    std::vector<double> minPrice(graph.edges.size());
    for (const GraphEdge& edge : graph.edges)
        minPrice[edge.id] = std::min(truePrices.uncovered[edge.id], truePrices.covered[edge.id]);
    auto dijkstra = [&](int source) {
        std::vector<double> dist(nodes, kInfinity);
        using Item = std::pair<double, int>;
        std::vector<Item> heap{{0.0, source}};
        dist[source] = 0.0;
        while (!heap.empty()) {
            std::pop_heap(heap.begin(), heap.end(), std::greater<Item>());
            const auto [d, u] = heap.back();
            heap.pop_back();
            if (d > dist[u])
                continue;
            for (int i = adjacencyOffset[u]; i < adjacencyOffset[u + 1]; ++i) {
                const int v = adjacencyNode[i];
                const double nd = d + minPrice[adjacencyEdge[i]];
                if (nd < dist[v]) {
                    dist[v] = nd;
                    heap.push_back({nd, v});
                    std::push_heap(heap.begin(), heap.end(), std::greater<Item>());
                }
            }
        }
        return dist;
    };
    // Farthest-point selection: each landmark is the node farthest from those chosen.
    std::vector<double> nearest(nodes, kInfinity);
    int next = 0;
    for (int k = 0; k < count && nodes > 0; ++k) {
        const std::vector<double> dist = dijkstra(next);
        landmarkDistance.push_back(dist);
        for (int n = 0; n < nodes; ++n)
            if (dist[n] < kInfinity)
                nearest[n] = std::min(nearest[n], dist[n]);
        double far = -1;
        for (int n = 0; n < nodes; ++n)
            if (nearest[n] < kInfinity && nearest[n] > far)
                far = nearest[n], next = n;
    }
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
    if (targetPositions_.empty())
        return 0.0;
    const Vec2 p = graph_.positions[node];
    double best = kInfinity; // lower bound to the nearest target
    for (size_t i = 0; i < targetNodes_.size(); ++i) {
        const Vec2 d = p - targetPositions_[i];
        double bound = graph_.heuristicScale > 0.0
                           ? graph_.heuristicScale * std::sqrt(d.x * d.x + d.y * d.y)
                           : 0.0;
        for (const std::vector<double>& dist : graph_.landmarkDistance) {
            const double a = dist[node], b = dist[targetNodes_[i]];
            if (a < kInfinity && b < kInfinity) // shrunk a little against rounding
                bound = std::max(bound, std::abs(a - b) * (1.0 - 1e-9));
        }
        best = std::min(best, bound);
    }
    return best < kInfinity ? best : 0.0;
}

void TransitSearch::run(const EdgePrices& prices, const std::vector<char>& covered,
                        const std::vector<NodeCost>& sources, const std::vector<int>& targets) {
    targetPositions_.clear();
    targetNodes_.clear();
    for (int t : targets) {
        targetPositions_.push_back(graph_.positions[t]);
        targetNodes_.push_back(t);
    }
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

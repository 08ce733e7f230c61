// Cheapest walks between corner-graph nodes whose edge costs depend on which cells are
// covered. A transit never crosses the coverage edge of an uncovered required cell: doing so
// would cover the cell, which is a step of the cell order, not travel.
#pragma once

#include "solvers/SolverCommon.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace fc::solver_detail {

struct NodeCost {
    int node = -1;
    double cost = 0.0;
};

// Each edge's cost while the cell that prices it is uncovered / covered.
struct EdgePrices {
    std::vector<double> uncovered;
    std::vector<double> covered;
};

// The graph in compact adjacency form, with the true (SPEC sect. 3) prices for transits.
class TransitGraph {
public:
    explicit TransitGraph(const Problem& problem);

    int nodeCount() const { return static_cast<int>(positions.size()); }
    // Coverage flags per cell plus one always-covered slot that prices inter edges:
    // non-required cells covered, tasks not.
    std::vector<char> initialCoverage() const;

    const Problem* problem;
    std::vector<int> adjacencyOffset; // node -> first index in adjacencyEdge/adjacencyNode
    std::vector<int> adjacencyEdge;
    std::vector<int> adjacencyNode;
    std::vector<int> edgeSlot; // coverage flag that prices the edge
    EdgePrices truePrices;     // uncovered coverage edges of tasks cost +inf (excluded)
    std::vector<Vec2> positions;
    // A* scale: scale * straight-line distance never exceeds an edge's cost, even if a
    // graph's lengths are shorter than the distance between their end nodes.
    double heuristicScale = 0.0;
    // ALT lower bounds: distances from a few far-apart landmark nodes under the cheapest
    // price every edge can have; |d(L, t) - d(L, n)| never exceeds the true transit cost.
    // Euclidean bounds are weak on floors where walls force detours through doors.
    std::vector<std::vector<double>> landmarkDistance; // landmark -> node -> distance

private:
    void chooseLandmarks(int count);
};

// Dijkstra / A* with reusable buffers (reset by generation stamps, not by clearing).
class TransitSearch {
public:
    explicit TransitSearch(const TransitGraph& graph);

    // Cheapest costs from the sources (each with a starting cost) until every target is
    // settled, steered by A* towards the targets; with no targets, the whole component.
    void run(const EdgePrices& prices, const std::vector<char>& covered,
             const std::vector<NodeCost>& sources, const std::vector<int>& targets);

    // Plain Dijkstra calling visit(node, cost) for each settled node in cost order; stops as
    // soon as visit returns true.
    template <class Visit>
    void explore(const EdgePrices& prices, const std::vector<char>& covered,
                 const std::vector<NodeCost>& sources, Visit&& visit);

    double cost(int node) const { return isSettled(node) ? cost_[node] : kInfinity; }
    bool isSettled(int node) const { return settledStamp_[node] == generation_; }
    int sourceOf(int node) const;
    // Edges of the cheapest walk from the node's source to `node`, in walking order.
    std::vector<int> edgesTo(int node) const;
    // Appends that walk to one that currently ends at the node's source.
    void appendWalkTo(int node, Walk& walk) const;
    // Nodes settled by all searches so far: a deterministic measure of work done.
    std::uint64_t settledTotal() const { return settledTotal_; }

private:
    struct HeapItem {
        double key;
        double cost;
        int node;
        bool operator<(const HeapItem& o) const { return key > o.key; } // min-heap
    };

    void begin(const std::vector<NodeCost>& sources);
    double estimate(int node);

    template <class Stop>
    void loop(const EdgePrices& prices, const std::vector<char>& covered, Stop&& stop);

    const TransitGraph& graph_;
    std::vector<double> cost_;
    std::vector<double> estimate_;
    std::vector<int> parentEdge_;
    std::vector<std::uint32_t> labelStamp_;
    std::vector<std::uint32_t> settledStamp_;
    std::vector<std::uint32_t> targetStamp_;
    std::vector<HeapItem> heap_;
    std::vector<Vec2> targetPositions_;
    std::vector<int> targetNodes_;
    std::uint32_t generation_ = 0;
    std::uint64_t settledTotal_ = 0;
};

template <class Stop>
void TransitSearch::loop(const EdgePrices& prices, const std::vector<char>& covered, Stop&& stop) {
    while (!heap_.empty()) {
        std::pop_heap(heap_.begin(), heap_.end());
        const HeapItem item = heap_.back();
        heap_.pop_back();
        const int node = item.node;
        if (settledStamp_[node] == generation_ || item.cost > cost_[node])
            continue;
        settledStamp_[node] = generation_;
        ++settledTotal_;
        if (stop(node, item.cost))
            return;
        const int end = graph_.adjacencyOffset[node + 1];
        for (int i = graph_.adjacencyOffset[node]; i < end; ++i) {
            const int next = graph_.adjacencyNode[i];
            if (settledStamp_[next] == generation_)
                continue;
            const int e = graph_.adjacencyEdge[i];
            const double price =
                covered[graph_.edgeSlot[e]] ? prices.covered[e] : prices.uncovered[e];
            const double candidate = item.cost + price;
            if (labelStamp_[next] == generation_ && candidate >= cost_[next])
                continue;
            if (!(candidate < kInfinity))
                continue;
            if (labelStamp_[next] != generation_) {
                labelStamp_[next] = generation_;
                estimate_[next] = estimate(next);
            }
            cost_[next] = candidate;
            parentEdge_[next] = e;
            heap_.push_back({candidate + estimate_[next], candidate, next});
            std::push_heap(heap_.begin(), heap_.end());
        }
    }
}

template <class Visit>
void TransitSearch::explore(const EdgePrices& prices, const std::vector<char>& covered,
                            const std::vector<NodeCost>& sources, Visit&& visit) {
    targetPositions_.clear();
    begin(sources);
    loop(prices, covered, [&](int node, double cost) { return visit(node, cost); });
}

} // namespace fc::solver_detail

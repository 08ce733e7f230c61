// Provably optimal graph cost (SPEC sect. 4): A* over (covered subset of the required cells
// x node). Moving along an edge costs its price under the current subset; the coverage edge
// of an uncovered required cell costs 0 and adds the cell. The greedy walk gives an upper
// bound that keeps hopeless states out of memory, and a consistent lower bound
// (cheapest-price distances to the end, and via every uncovered cell to the end) steers it.
#include "solvers/FlatHashMap.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TransitSearch.h"

#include <string>

namespace fc {

using namespace solver_detail;

namespace {

constexpr const char* kName = "exact";

std::string withThousands(std::uint64_t value) {
    std::string digits = std::to_string(value);
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
        digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

// The lowest price each edge can have in any covered state: distances under these prices
// bound the cost of any walk from below.
EdgePrices cheapestPrices(const TransitGraph& transit) {
    const CornerGraph& graph = *transit.problem->graph;
    EdgePrices prices;
    prices.uncovered.resize(graph.edges.size());
    for (const GraphEdge& edge : graph.edges) {
        const bool task = edge.cell >= 0 && transit.problem->taskOfCell[edge.cell] >= 0;
        prices.uncovered[edge.id] = task ? edgeCost(edge, false) : edgeCost(edge, true);
    }
    prices.covered = prices.uncovered;
    return prices;
}

struct LowerBound {
    std::vector<double> toEnd;               // node -> cheapest cost to the end
    std::vector<std::vector<double>> toTask; // task -> node -> cheapest cost to its corners
    std::vector<double> taskToEnd;           // task -> cheapest cost from it to the end

    // Consistent: each term is a shortest-path distance (plus a constant) under prices that
    // never exceed the true ones, and covering a task only drops its term.
    double at(std::uint64_t uncoveredTasks, int node) const {
        double bound = toEnd[node];
        for (std::uint64_t rest = uncoveredTasks; rest != 0; rest &= rest - 1) {
            const int task = __builtin_ctzll(rest);
            bound = std::max(bound, toTask[task][node] + taskToEnd[task]);
        }
        return bound;
    }
};

LowerBound makeLowerBound(const TransitGraph& transit, TransitSearch& search) {
    const Problem& problem = *transit.problem;
    const EdgePrices prices = cheapestPrices(transit);
    const std::vector<char> anyCoverage = transit.initialCoverage();
    auto distances = [&](const std::vector<NodeCost>& sources) {
        search.run(prices, anyCoverage, sources, {});
        std::vector<double> result(transit.nodeCount());
        for (int n = 0; n < transit.nodeCount(); ++n)
            result[n] = search.cost(n);
        return result;
    };
    LowerBound bound;
    bound.toEnd = distances({{problem.endNode, 0.0}});
    for (int task = 0; task < problem.taskCount(); ++task) {
        std::vector<NodeCost> corners;
        double toEnd = kInfinity;
        for (const CoverOption& option : problem.options[task]) {
            corners.push_back({option.entry, 0.0});
            toEnd = std::min(toEnd, bound.toEnd[option.entry]);
        }
        bound.toTask.push_back(distances(corners));
        bound.taskToEnd.push_back(toEnd);
    }
    return bound;
}

struct HeapItem {
    double key;
    double cost;
    std::uint32_t state;
    bool operator<(const HeapItem& o) const { return key > o.key; } // min-heap
};

} // namespace

Solution solveExact(const CornerGraph& graph, const Query& query, const ExactOptions& options,
                    const SolveControl& control) {
    const Problem problem = makeProblem(graph, query, kName);
    const int tasks = problem.taskCount();
    // Beyond 31 cells the state space could not be indexed (and never fits maxStates).
    const int cellLimit = std::min(options.maxRequiredCells, 31);
    if (tasks > cellLimit)
        throw SolverError("exact solver: " + std::to_string(tasks) +
                          " required cells exceed its limit of " + std::to_string(cellLimit) +
                          "; use `--solver heuristic` for this query");
    const std::uint64_t nodeCount = graph.nodes.size();
    const std::uint64_t stateSpace =
        (std::uint64_t{1} << tasks) * static_cast<std::uint64_t>(problem.reachableNodeCount);
    const std::uint64_t stateLimit = std::min<std::uint64_t>(options.maxStates, UINT32_MAX);
    if (stateSpace > stateLimit)
        throw SolverError("exact solver: " + std::to_string(tasks) + " required cells x " +
                          std::to_string(problem.reachableNodeCount) + " reachable nodes = " +
                          withThousands(stateSpace) + " states exceed its limit of " +
                          withThousands(stateLimit) + "; use `--solver heuristic` for this query");

    // Upper bound: any valid walk (the greedy one is instant and independent of the
    // heuristic); the search never keeps states that cannot beat it.
    Solution incumbent = solveGreedy(graph, query);
    const double upper = incumbent.graphCost * (1.0 + 1e-12) + 1e-9;

    const TransitGraph transit(problem);
    TransitSearch search(transit);
    const LowerBound lower = makeLowerBound(transit, search);
    std::vector<int> taskOfEdge(graph.edges.size(), -1);
    for (const GraphEdge& edge : graph.edges)
        if (edge.cell >= 0)
            taskOfEdge[edge.id] = problem.taskOfCell[edge.cell];

    const std::uint64_t allTasks = (std::uint64_t{1} << tasks) - 1;
    std::vector<std::uint64_t> stateKey;   // covered subset * nodeCount + node
    std::vector<double> stateCost;         // cheapest cost found so far
    std::vector<std::int64_t> stateParent; // 2 * edge + (1 if the edge covered its cell)
    std::vector<char> stateClosed;
    FlatHashMap<std::uint32_t> stateIndex(1024);
    std::vector<HeapItem> heap;

    auto reach = [&](std::uint64_t covered, int node, double cost, std::int64_t parent) {
        const double estimate = lower.at(allTasks & ~covered, node);
        if (!(cost + estimate <= upper))
            return;
        const std::uint64_t key = covered * nodeCount + static_cast<std::uint64_t>(node);
        const auto [slot, added] =
            stateIndex.emplace(key, static_cast<std::uint32_t>(stateKey.size()));
        const std::uint32_t state = *slot;
        if (added) {
            stateKey.push_back(key);
            stateCost.push_back(cost);
            stateParent.push_back(parent);
            stateClosed.push_back(0);
        } else if (stateClosed[state] || cost >= stateCost[state]) {
            return;
        }
        stateCost[state] = cost;
        stateParent[state] = parent;
        heap.push_back({cost + estimate, cost, state});
        std::push_heap(heap.begin(), heap.end());
    };

    const double initialBound = lower.at(allTasks, problem.startNode);
    reach(0, problem.startNode, 0.0, -1);
    std::int64_t goal = -1;
    for (std::uint64_t popped = 0; !heap.empty(); ++popped) {
        std::pop_heap(heap.begin(), heap.end());
        const HeapItem item = heap.back();
        heap.pop_back();
        if (stateClosed[item.state] || item.cost > stateCost[item.state])
            continue;
        stateClosed[item.state] = 1;
        const std::uint64_t covered = stateKey[item.state] / nodeCount;
        const int node = static_cast<int>(stateKey[item.state] % nodeCount);
        if (covered == allTasks && node == problem.endNode) {
            goal = item.state;
            break;
        }
        if ((popped & 4095) == 0) {
            throwIfCancelled(control, kName);
            // With a consistent bound the popped keys only grow, from the start's bound to
            // the optimum (at most the incumbent's cost).
            if (upper > initialBound)
                reportProgress(control, (item.key - initialBound) / (upper - initialBound));
        }
        for (int i = transit.adjacencyOffset[node]; i < transit.adjacencyOffset[node + 1]; ++i) {
            const int e = transit.adjacencyEdge[i];
            const int task = taskOfEdge[e];
            const bool uncovered = task >= 0 && !((covered >> task) & 1);
            if (uncovered && graph.edges[e].kind == EdgeKind::Coverage) {
                reach(covered | (std::uint64_t{1} << task), transit.adjacencyNode[i], item.cost,
                      2 * std::int64_t{e} + 1);
            } else {
                const double price =
                    uncovered ? transit.truePrices.uncovered[e] : transit.truePrices.covered[e];
                reach(covered, transit.adjacencyNode[i], item.cost + price, 2 * std::int64_t{e});
            }
        }
    }
    reportProgress(control, 1.0);
    incumbent.solver = kName;
    if (goal < 0) // only possible through rounding: the incumbent is then optimal
        return incumbent;

    std::vector<int> reversedEdges;
    for (std::uint64_t state = static_cast<std::uint64_t>(goal); stateParent[state] >= 0;) {
        const int e = static_cast<int>(stateParent[state] / 2);
        const bool coveredHere = stateParent[state] % 2 == 1;
        std::uint64_t covered = stateKey[state] / nodeCount;
        const int node = static_cast<int>(stateKey[state] % nodeCount);
        if (coveredHere)
            covered &= ~(std::uint64_t{1} << taskOfEdge[e]);
        reversedEdges.push_back(e);
        const std::uint64_t key =
            covered * nodeCount + static_cast<std::uint64_t>(graph.edges[e].other(node));
        state = *stateIndex.find(key);
    }
    Walk walk;
    walk.nodes.push_back(problem.startNode);
    for (auto it = reversedEdges.rbegin(); it != reversedEdges.rend(); ++it) {
        walk.edges.push_back(*it);
        walk.nodes.push_back(graph.edges[*it].other(walk.nodes.back()));
    }
    Solution optimal = finishSolution(graph, query, kName, std::move(walk));
    return incumbent.graphCost < optimal.graphCost ? incumbent : optimal; // equal but rounding
}

} // namespace fc

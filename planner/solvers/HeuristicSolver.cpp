// Near-optimal solver for any size (SPEC sect. 4). The decision is the cell order: for a
// given order the best corners follow exactly from OrderEvaluator's dynamic programme.
// Orders are searched with fast proxy costs (TourSearch), then judged and polished with the
// true state-dependent costs (OrderPolish). Every budget is a count of moves or of search
// work, never wall-clock time, so a seed always gives the same walk.
#include "solvers/OrderEvaluator.h"
#include "solvers/OrderPolish.h"
#include "solvers/ProxyDistances.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TourBound.h"
#include "solvers/TourSearch.h"
#include "solvers/TransitSearch.h"

#include <algorithm>

namespace fc {

using namespace solver_detail;

namespace {

constexpr const char* kName = "heuristic";

// Instances up to this many cells get complete neighbour lists and a second polish start.
constexpr int kSmallInstance = 40;
// Neighbours per cell considered by the moves on larger instances.
constexpr int kNeighbourCount = 10;
// Perturbations of the proxy search: a few per cell, within bounds.
// Each kick's local search touches O(tasks) cells, so large floors get fewer kicks: the
// product stays below ~3 million (a 1,000-room floor still gets a few hundred).
int proxyKicks(int tasks) {
    return std::clamp(std::min(25 * tasks, 3'000'000 / std::max(tasks, 1)), 100, 6000);
}
// Settled nodes the true-cost polish may spend per starting order: on small instances
// enough for many perturbations, on large ones for the moves at the costliest steps.
std::uint64_t polishWork(int tasks, int nodes, bool small) {
    const auto n = static_cast<std::uint64_t>(tasks);
    if (small)
        return std::min<std::uint64_t>(300'000 + 1'000 * n * static_cast<std::uint64_t>(nodes),
                                       2'000'000);
    return std::max<std::uint64_t>(600 * n, 2'000'000);
}

std::vector<int> tasksOf(const Problem& problem, const std::vector<int>& cells) {
    std::vector<int> order;
    for (int cell : cells)
        order.push_back(problem.taskOfCell[cell]);
    return order;
}

// The other local optima, cheapest first, distinct from `best` and from each other, within
// the polish's slack of the best cost.
std::vector<Walk> alternativeWalks(OrderEvaluator& evaluator,
                                   std::vector<OrderPolish::LocalOptimum> optima,
                                   const std::vector<int>& best, double bestCost) {
    std::stable_sort(optima.begin(), optima.end(),
                     [](const auto& a, const auto& b) { return a.cost < b.cost; });
    std::vector<std::vector<int>> kept{best};
    std::vector<Walk> out;
    for (const OrderPolish::LocalOptimum& o : optima) {
        if (out.size() + 1 >= OrderPolish::kKeptOptima ||
            o.cost > bestCost * (1.0 + OrderPolish::kOptimaSlack))
            break;
        if (std::find(kept.begin(), kept.end(), o.order) != kept.end())
            continue;
        kept.push_back(o.order);
        out.push_back(evaluator.walk(o.order));
    }
    return out;
}

} // namespace

Solution solveHeuristic(const CornerGraph& graph, const Query& query, const SolveControl& control) {
    const Problem problem = makeProblem(graph, query, kName);
    const int tasks = problem.taskCount();
    const TransitGraph transit(problem);
    TransitSearch search(transit);
    OrderEvaluator evaluator(transit, search);
    if (tasks == 0) {
        Solution solution = finishSolution(graph, query, kName, evaluator.walk({}));
        solution.lowerBound = solution.graphCost; // the cheapest transit to the end
        solution.provenOptimal = true;
        return solution;
    }

    reportProgress(control, 0.0);
    const bool small = tasks <= kSmallInstance;
    ProxyDistances distances(transit, search, small ? tasks - 1 : kNeighbourCount);
    throwIfCancelled(control, kName);
    reportProgress(control, 0.2);

    TourSearch tour(problem, distances, problem.seed);
    tour.buildNearestNeighbour();
    tour.optimise();
    tour.iterate(proxyKicks(tasks), control);
    reportProgress(control, 0.6);

    // Nearest uncovered cell next: a polish start, the fallback and an alternative.
    Solution greedy = solveGreedy(graph, query);
    // The true-cost polish of the proxy optimum and, on small instances, of the greedy walk
    // (which already reflects the covered state at every step); the cheaper walk wins.
    std::vector<int> best;
    double bestCost = kInfinity;
    std::vector<OrderPolish::LocalOptimum> optima; // of every start, for the path choice
    const std::uint64_t budget = polishWork(tasks, problem.reachableNodeCount, small);
    auto polishAndKeep = [&](std::vector<int> order, std::uint64_t seed) {
        OrderPolish polish(evaluator, distances, tasks, seed);
        const double cost = polish.improve(order, budget, control);
        optima.insert(optima.end(), polish.localOptima().begin(), polish.localOptima().end());
        if (cost < bestCost) {
            best = std::move(order);
            bestCost = cost;
        }
    };
    if (small) {
        polishAndKeep(tour.order(), problem.seed + 7919);
        reportProgress(control, 0.8);
        polishAndKeep(tasksOf(problem, greedy.cellOrder), problem.seed + 1);
    } else {
        // Large floors: the proxy ignores that crossing covered cells costs 3x, and there
        // the greedy order (which prices every step under the true covered state) can start
        // better. Polish whichever of the two starts cheaper.
        std::vector<int> start = tour.order();
        const double tourCost = evaluator.setBase(start);
        std::vector<int> greedyOrder = tasksOf(problem, greedy.cellOrder);
        if (evaluator.setBase(greedyOrder) < tourCost)
            start = std::move(greedyOrder);
        reportProgress(control, 0.7);
        polishAndKeep(std::move(start), problem.seed + 7919);
    }
    reportProgress(control, 0.95);
    if (!(bestCost < kInfinity)) {
        // The proxy can prefer an order the covered state forbids (a transit that only
        // existed through a cell's coverage edge); the greedy order is always feasible.
        best = tasksOf(problem, greedy.cellOrder);
    }
    Solution solution = finishSolution(graph, query, kName, evaluator.walk(best));
    solution.alternatives = alternativeWalks(evaluator, std::move(optima), best, bestCost);
    // The greedy walk too: it costs more on the graph, yet its path is sometimes faster
    // (office: 3% less estimated time), since it finishes each area before moving on.
    if (greedy.cellOrder != solution.cellOrder)
        solution.alternatives.push_back(std::move(greedy.walk));
    solution.lowerBound =
        std::min(provenLowerBound(transit, search, solution.graphCost), solution.graphCost);
    solution.provenOptimal = !(solution.lowerBound < solution.graphCost);
    reportProgress(control, 1.0);
    return solution;
}

Solution searchFromWalk(const CornerGraph& graph, const Query& query, const Solution& given,
                        const SolveControl& control) {
    const Problem problem = makeProblem(graph, query, kName);
    const int tasks = problem.taskCount();
    if (tasks == 0)
        return given;
    std::vector<int> order = taskOrderOf(problem, given);
    const TransitGraph transit(problem);
    TransitSearch search(transit);
    OrderEvaluator evaluator(transit, search);
    const bool small = tasks <= kSmallInstance;
    ProxyDistances distances(transit, search, small ? tasks - 1 : kNeighbourCount);
    throwIfCancelled(control, kName);
    const double cost = searchFromOrder(
        problem, evaluator, distances, order, evaluator.setBase(order), proxyKicks(tasks),
        polishWork(tasks, problem.reachableNodeCount, small), problem.seed + 7919, control);
    if (!(cost < given.graphCost - 1e-9))
        return given;
    return finishSolution(graph, query, given.solver.c_str(), evaluator.walk(order));
}

} // namespace fc

// Provably optimal graph cost (SPEC sect. 4): best-first search (A*) over (covered subset of
// the required cells x corner where the last cover ended). A step covers one more cell: the
// cheapest transit to one of its entry corners under the covered state of that moment (one
// search per expanded state), then its coverage edge (cost 0). This is the dynamic programme
// over covered set x corner, restricted to the states the bound cannot rule out.
//
// The heuristic solver's walk is the incumbent: no state whose cost so far plus the lower
// bound on finishing (TourBound: a Held-Karp penalised spanning tree over the uncovered
// cells) reaches it is ever stored. When the search ends without a cheaper walk, the
// incumbent is optimal. When the state budget runs out first, the smallest key left in the
// queue is a proven lower bound on the optimum.
#include "solvers/FlatHashMap.h"
#include "solvers/OrderEvaluator.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TourBound.h"
#include "solvers/TransitSearch.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace fc {

using namespace solver_detail;

namespace {

constexpr const char* kName = "exact";
constexpr int kHardTaskLimit = 48; // task set in the upper bits of a 64-bit state key
constexpr std::uint64_t kGoalTerminal = 0xFFFF;
constexpr int kGreedyIncumbentCells = 12;

std::string withThousands(std::uint64_t value) {
    std::string digits = std::to_string(value);
    for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3)
        digits.insert(static_cast<std::size_t>(i), ",");
    return digits;
}

struct HeapItem {
    double key;
    double cost;
    std::uint32_t state;
    bool operator<(const HeapItem& o) const { return key > o.key; } // min-heap
};

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g s", value);
    return text;
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", 100.0 * fraction);
    return text;
}

} // namespace

Solution solveExact(const CornerGraph& graph, const Query& query, const ExactOptions& options,
                    const SolveControl& control) {
    const Problem problem = makeProblem(graph, query, kName);
    const int tasks = problem.taskCount();
    const int cellLimit = std::min(options.maxRequiredCells, kHardTaskLimit);
    if (tasks > cellLimit)
        throw SolverError("exact solver: " + std::to_string(tasks) +
                          " required cells exceed its limit of " + std::to_string(cellLimit) +
                          "; use `--solver heuristic` for this query");
    reportProgress(control, 0.0);
    const auto started = std::chrono::steady_clock::now();

    // Incumbent: the heuristic's walk (deterministic, near-optimal on these sizes); on small
    // queries the instant greedy walk, the search being short anyway (DQN validation calls
    // exact many times on them).
    Solution incumbent = tasks <= kGreedyIncumbentCells
                             ? solveGreedy(graph, query)
                             : solveHeuristic(graph, query, {control.cancelled, {}});
    incumbent.solver = kName;
    // Exact answers one walk, optimal for the graph cost: the heuristic's alternatives (for a
    // path-time choice) would let the pipeline swap in a walk that is not.
    incumbent.alternatives.clear();
    const double upper = incumbent.graphCost * (1.0 + 1e-12) + 1e-9;
    throwIfCancelled(control, kName);

    const TransitGraph transit(problem);
    TransitSearch search(transit);
    TourBound bound(transit, search, incumbent.graphCost);
    const int startTerminal = bound.terminalOf(problem.startNode);
    const std::uint64_t allTasks = (std::uint64_t{1} << tasks) - 1;

    std::vector<std::uint64_t> stateKey; // covered set << 16 | terminal (kGoalTerminal: done)
    std::vector<double> stateCost;       // cheapest cost found so far
    std::vector<std::uint32_t> stateParent;
    std::vector<std::int8_t> stateTask; // task covered by the step into the state, -1 none
    FlatHashMap<std::uint32_t> stateIndex(1 << 16);
    std::vector<HeapItem> heap;
    bool outOfBudget = false;

    // Keys never fall below the parent's (pathmax): the parent's key bounds every walk
    // through it. So popped keys never decrease and the last one is a proven lower bound.
    auto reach = [&](std::uint64_t covered, std::uint64_t terminal, double cost, double estimate,
                     double floorKey, std::uint32_t parent, int task) {
        const double key = std::max(cost + estimate, floorKey);
        if (outOfBudget || !(key < upper))
            return;
        const std::uint64_t id = covered << 16 | terminal;
        const auto [slot, added] =
            stateIndex.emplace(id, static_cast<std::uint32_t>(stateKey.size()));
        const std::uint32_t state = *slot;
        if (added) {
            if (stateKey.size() >= options.maxStates) {
                outOfBudget = true;
                return; // the key stays in the index, unused: the search stops now
            }
            stateKey.push_back(id);
            stateCost.push_back(cost);
            stateParent.push_back(parent);
            stateTask.push_back(static_cast<std::int8_t>(task));
        } else if (cost >= stateCost[state]) {
            return;
        }
        stateCost[state] = cost; // cheaper: (re)opened, the bound need not be consistent
        stateParent[state] = parent;
        stateTask[state] = static_cast<std::int8_t>(task);
        heap.push_back({key, cost, state});
        std::push_heap(heap.begin(), heap.end());
    };

    const double rootBound = bound.at(allTasks, startTerminal);
    reach(0, static_cast<std::uint64_t>(startTerminal), 0.0, rootBound, 0.0, 0, -1);
    std::vector<char> covered = transit.initialCoverage();
    std::vector<int> targets;
    std::int64_t goal = -1;
    double lowerBound = rootBound;
    for (std::uint64_t popped = 0; !heap.empty() && !outOfBudget; ++popped) {
        std::pop_heap(heap.begin(), heap.end());
        const HeapItem item = heap.back();
        heap.pop_back();
        if (item.cost > stateCost[item.state])
            continue; // stale
        lowerBound = item.key;
        const std::uint64_t set = stateKey[item.state] >> 16;
        const std::uint64_t terminal = stateKey[item.state] & 0xFFFF;
        if (terminal == kGoalTerminal) {
            goal = item.state;
            break;
        }
        if ((popped & 1023) == 0) {
            throwIfCancelled(control, kName);
            if (options.timeLimitSeconds > 0.0 &&
                std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
                    options.timeLimitSeconds) {
                heap.push_back(item); // still open
                outOfBudget = true;
                break;
            }
            if (upper > rootBound)
                reportProgress(control, (item.key - rootBound) / (upper - rootBound));
        }
        const int node = bound.terminalNode(static_cast<int>(terminal));
        for (int task = 0; task < tasks; ++task)
            covered[problem.taskCells[task]] = (set >> task) & 1;
        if (set == allTasks) {
            search.run(transit.truePrices, covered, {{node, 0.0}}, {problem.endNode});
            const double cost = search.cost(problem.endNode);
            if (cost < kInfinity)
                reach(set, kGoalTerminal, item.cost + cost, 0.0, item.key, item.state, -1);
            continue;
        }
        targets.clear();
        for (int task = 0; task < tasks; ++task)
            if (!((set >> task) & 1))
                for (const CoverOption& option : problem.options[task])
                    targets.push_back(option.entry);
        search.run(transit.truePrices, covered, {{node, 0.0}}, targets);
        for (int task = 0; task < tasks; ++task) {
            if ((set >> task) & 1)
                continue;
            const std::uint64_t next = set | (std::uint64_t{1} << task);
            for (const CoverOption& option : problem.options[task]) {
                const double transitCost = search.cost(option.entry);
                if (!(transitCost < kInfinity))
                    continue;
                const int exit = bound.terminalOf(option.exit);
                const double cost = item.cost + transitCost;
                reach(next, static_cast<std::uint64_t>(exit), cost,
                      bound.at(allTasks & ~next, exit), item.key, item.state, task);
            }
        }
    }
    reportProgress(control, 1.0);

    if (goal < 0 && outOfBudget) {
        // The optimum is at least the last key popped: every key queued is at least as
        // large, and so is every state the budget left out (children of that state).
        lowerBound = std::min(lowerBound, incumbent.graphCost);
        if (!options.bestOnBudget)
            throw SolverError("exact solver: " + std::to_string(tasks) +
                              " required cells: no proof of optimality within its budget (" +
                              withThousands(options.maxStates) + " states" +
                              (options.timeLimitSeconds > 0.0
                                   ? " or " + seconds(options.timeLimitSeconds)
                                   : std::string()) +
                              "; the best walk known is within " +
                              percent(incumbent.graphCost / std::max(lowerBound, 1e-12) - 1.0) +
                              " of optimal); use `--solver heuristic` for this query");
        incumbent.lowerBound = lowerBound;
        incumbent.provenOptimal = incumbent.graphCost <= lowerBound;
        return incumbent;
    }
    incumbent.lowerBound = incumbent.graphCost;
    incumbent.provenOptimal = true;
    if (goal < 0) // nothing cheaper than the incumbent exists: it is optimal
        return incumbent;

    std::vector<int> order;
    for (std::uint32_t state = static_cast<std::uint32_t>(goal); stateKey[state] >> 16 != 0;
         state = stateParent[state])
        if (stateTask[state] >= 0)
            order.push_back(stateTask[state]);
    std::reverse(order.begin(), order.end());
    OrderEvaluator evaluator(transit, search);
    Solution optimal = finishSolution(graph, query, kName, evaluator.walk(order));
    if (!(optimal.graphCost < incumbent.graphCost))
        return incumbent; // equal up to rounding
    optimal.lowerBound = optimal.graphCost;
    optimal.provenOptimal = true;
    return optimal;
}

} // namespace fc

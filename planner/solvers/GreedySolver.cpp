// The naive reference (SPEC sect. 4): always cover the uncovered required cell whose entry
// corner is cheapest to reach from where the robot stands, then go to the end. With an order
// hint (Query::orderHint) also the hinted order, keeping the cheaper walk.
#include "solvers/OrderEvaluator.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TransitSearch.h"

namespace fc {

using namespace solver_detail;

Solution solveGreedy(const CornerGraph& graph, const Query& query) {
    const char* const name = "greedy";
    const Problem problem = makeProblem(graph, query, name);
    const TransitGraph transit(problem);
    TransitSearch search(transit);
    std::vector<char> covered = transit.initialCoverage();

    // node -> the ways to cover a task by entering at that node
    std::vector<std::vector<std::pair<int, int>>> entriesAt(graph.nodes.size());
    for (int task = 0; task < problem.taskCount(); ++task)
        for (std::size_t o = 0; o < problem.options[task].size(); ++o)
            entriesAt[problem.options[task][o].entry].push_back({task, static_cast<int>(o)});

    Walk walk;
    walk.nodes.push_back(problem.startNode);
    for (int remaining = problem.taskCount(); remaining > 0; --remaining) {
        int chosenTask = -1, chosenOption = -1, reachedNode = -1;
        search.explore(transit.truePrices, covered, {{walk.nodes.back(), 0.0}},
                       [&](int node, double) {
                           for (const auto& [task, option] : entriesAt[node]) {
                               if (!covered[problem.taskCells[task]]) {
                                   chosenTask = task;
                                   chosenOption = option;
                                   reachedNode = node;
                                   return true;
                               }
                           }
                           return false;
                       });
        if (chosenTask < 0)
            throw SolverError("greedy solver: internal error: no uncovered cell is reachable");
        search.appendWalkTo(reachedNode, walk);
        const CoverOption& option = problem.options[chosenTask][chosenOption];
        walk.edges.push_back(option.edge);
        walk.nodes.push_back(option.exit);
        covered[problem.taskCells[chosenTask]] = 1;
    }
    search.run(transit.truePrices, covered, {{walk.nodes.back(), 0.0}}, {problem.endNode});
    if (!search.isSettled(problem.endNode))
        throw SolverError("greedy solver: internal error: the end node is not reachable");
    search.appendWalkTo(problem.endNode, walk);
    Solution greedy = finishSolution(graph, query, name, std::move(walk));
    if (query.orderHint.size() != graph.cells.size() || problem.taskCount() < 2)
        return greedy;
    // The order of a plan made before (live replanning): the required cells in that order,
    // with the best corners for it. The cheaper walk on the graph is the solution, the other
    // its alternative: the path choice keeps whichever path takes less time.
    std::vector<int> order(static_cast<size_t>(problem.taskCount()));
    for (int task = 0; task < problem.taskCount(); ++task)
        order[task] = task;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return query.orderHint[problem.taskCells[a]] < query.orderHint[problem.taskCells[b]];
    });
    try {
        TransitSearch hintSearch(transit);
        OrderEvaluator evaluator(transit, hintSearch);
        Solution hinted = finishSolution(graph, query, name, evaluator.walk(order));
        if (hinted.cellOrder == greedy.cellOrder)
            return greedy;
        if (hinted.graphCost < greedy.graphCost)
            std::swap(hinted, greedy);
        greedy.alternatives.push_back(std::move(hinted.walk));
    } catch (const SolverError&) {
        // An order the covered state forbids (a transit only through a cell's coverage edge).
    }
    return greedy;
}

} // namespace fc

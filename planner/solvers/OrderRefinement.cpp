// Refinement of a given cell order (e.g. the DQN policy's): the exact corner choice of
// OrderEvaluator, then optionally the heuristic solver's true-cost local search.
#include "solvers/OrderEvaluator.h"
#include "solvers/OrderPolish.h"
#include "solvers/ProxyDistances.h"
#include "solvers/Solver.h"
#include "solvers/SolverCommon.h"
#include "solvers/TourSearch.h"
#include "solvers/TransitSearch.h"

namespace fc {

using namespace solver_detail;

namespace {

// Neighbours per cell the local search considers (as the heuristic solver on large floors).
constexpr int kNeighbourCount = 10;

} // namespace

Solution refineCellOrder(const CornerGraph& graph, const Query& query, const Solution& given,
                         OrderRefinement refinement, std::uint64_t workBudget,
                         const SolveControl& control) {
    if (refinement == OrderRefinement::None)
        return given;
    const char* name = given.solver.c_str();
    const Problem problem = makeProblem(graph, query, name);
    const int tasks = problem.taskCount();
    if (tasks == 0)
        return given;
    std::vector<int> order = taskOrderOf(problem, given);

    const TransitGraph transit(problem);
    TransitSearch search(transit);
    OrderEvaluator evaluator(transit, search);
    double cost = evaluator.setBase(order);
    if (refinement == OrderRefinement::LocalSearch && cost < kInfinity) {
        ProxyDistances distances(transit, search, std::min(tasks - 1, kNeighbourCount));
        // The given order's proxy local optimum (Or-opt, 2-opt, option changes; no kicks)
        // may start the true-cost polish cheaper; the proxy misses the covered state, so
        // both starts are priced exactly and the cheaper is polished.
        TourSearch tour(problem, distances, problem.seed);
        tour.startFrom(order);
        tour.optimise();
        std::vector<int> proxyOrder = tour.order();
        const double proxyCost = evaluator.setBase(proxyOrder);
        if (proxyCost < cost) {
            order = std::move(proxyOrder);
            cost = proxyCost;
        }
        OrderPolish polish(evaluator, distances, tasks, problem.seed);
        cost = polish.improve(order, workBudget, control);
    }
    if (!(cost < given.graphCost - 1e-9))
        return given; // e.g. infeasible under the covered state, or no better
    return finishSolution(graph, query, name, evaluator.walk(order));
}

} // namespace fc

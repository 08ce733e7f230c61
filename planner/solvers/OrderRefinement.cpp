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

namespace solver_detail {

double searchFromOrder(const Problem& problem, OrderEvaluator& evaluator, ProxyDistances& distances,
                       std::vector<int>& order, double cost, int kicks, std::uint64_t workBudget,
                       std::uint64_t polishSeed, const SolveControl& control) {
    TourSearch tour(problem, distances, problem.seed);
    tour.startFrom(order);
    tour.optimise();
    if (kicks > 0)
        tour.iterate(kicks, control);
    std::vector<int> proxyOrder = tour.order();
    const double proxyCost = evaluator.setBase(proxyOrder);
    if (proxyCost < cost) {
        order = std::move(proxyOrder);
        cost = proxyCost;
    }
    if (!(cost < kInfinity))
        return cost;
    OrderPolish polish(evaluator, distances, problem.taskCount(), polishSeed);
    return polish.improve(order, workBudget, control);
}

} // namespace solver_detail

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
        cost = searchFromOrder(problem, evaluator, distances, order, cost, 0, workBudget,
                               problem.seed, control);
    }
    if (!(cost < given.graphCost - 1e-9))
        return given; // e.g. infeasible under the covered state, or no better
    return finishSolution(graph, query, name, evaluator.walk(order));
}

} // namespace fc

#include "learning/dqn/PolicySearch.h"

#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/PolicyBeam.h"
#include "learning/torch/DqnTargets.h"

#include <algorithm>
#include <random>
#include <stdexcept>

namespace fc {
namespace {

// A walk that follows `prefix` (as far as its actions stay valid) and then the policy, which
// takes its best corner or, with probability exploration, one of its next best.
Solution perturbedRollout(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                          const EnvironmentOptions& environment, const std::vector<int>& prefix,
                          const PolicySearchOptions& options, std::mt19937_64& rng,
                          const SolveControl& control) {
    CoverageEnvironment env(graph, environment);
    std::vector<float> observation = env.reset(query);
    std::size_t next = 0;
    std::uniform_real_distribution<double> coin(0.0, 1.0);
    while (!env.done()) {
        if (control.cancelled && control.cancelled())
            throw SolverError("dqn: cancelled");
        const std::vector<char> mask = env.actionMask();
        int action = -1;
        if (next < prefix.size() && mask[static_cast<std::size_t>(prefix[next])])
            action = prefix[next++];
        else {
            next = prefix.size(); // the prefix ends at its first action the state forbids
            const std::vector<float> q = agent.qValues(observation, 1);
            std::vector<int> valid;
            for (std::size_t a = 0; a < mask.size(); ++a)
                if (mask[a])
                    valid.push_back(static_cast<int>(a));
            if (valid.empty())
                throw SolverError("dqn: no corner of an uncovered cell can be reached");
            const std::size_t keep =
                std::min(valid.size(), static_cast<std::size_t>(std::max(1, options.alternatives)));
            std::partial_sort(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(keep),
                              valid.end(), [&q](int x, int y) {
                                  return q[static_cast<std::size_t>(x)] >
                                         q[static_cast<std::size_t>(y)];
                              });
            std::size_t pick = 0;
            if (keep > 1 && coin(rng) < options.exploration)
                pick = std::uniform_int_distribution<std::size_t>(1, keep - 1)(rng);
            action = valid[pick];
        }
        const StepResult result = env.step(action);
        if (result.done && !result.info.reachedGoal)
            throw SolverError("dqn: the policy ran out of steps");
        observation = env.observation();
    }
    return policyWalkSolution(graph, query, env.walk());
}

} // namespace

std::vector<int> entryActions(const CornerGraph& graph, const Query& query, const Walk& walk) {
    std::vector<char> covered(graph.cells.size(), 1);
    for (std::size_t c = 0; c < covered.size() && c < query.required.size(); ++c)
        covered[c] = query.required[c] ? 0 : 1;
    std::vector<int> actions;
    for (std::size_t i = 0; i < walk.edges.size() && i < walk.nodes.size(); ++i) {
        const GraphEdge& e = graph.edges[static_cast<std::size_t>(walk.edges[i])];
        if (e.kind != EdgeKind::Coverage || e.cell < 0 || covered[static_cast<std::size_t>(e.cell)])
            continue;
        covered[static_cast<std::size_t>(e.cell)] = 1;
        actions.push_back(walk.nodes[i]);
    }
    return actions;
}

Solution policyGuidedSearch(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                            const EnvironmentOptions& environment, OrderRefinement refinement,
                            const SolveControl& control, const PolicySearchOptions& options,
                            const Solution* start) {
    if (options.maxMoves <= 0 && !control.cancelled)
        throw std::invalid_argument("policyGuidedSearch: no move limit and no cancellation");
    // Thorough: the policy's walk, searched by the heuristic's search with the move's seed.
    auto search = [&](const Solution& walk, std::uint64_t move) {
        Query seeded = query;
        seeded.seed = options.seed * 1000003ULL + move;
        return searchFromWalk(graph, seeded, walk, control);
    };
    const Solution first =
        start != nullptr ? *start
                         : solveWithPolicy(agent, graph, query, environment,
                                           options.thorough ? OrderRefinement::None : refinement,
                                           control, options.beamWidth);
    Solution best = first;
    try {
        best = options.thorough   ? search(first, 0)
               : start != nullptr ? refineCellOrder(graph, query, first, refinement,
                                                    kPolicyRefinementBudget, control)
                                  : first;
    } catch (const SolverError&) {
        if (!(control.cancelled && control.cancelled()))
            throw;
        best.solver = "dqn"; // cut short: the policy's own walk
        return best;
    }
    std::mt19937_64 rng(options.seed);
    for (int move = 0; options.maxMoves <= 0 || move < options.maxMoves; ++move) {
        if (control.cancelled && control.cancelled())
            break;
        const std::vector<int> order = entryActions(graph, query, best.walk);
        if (order.size() < 2)
            break; // nothing to rearrange
        const std::size_t keep =
            std::uniform_int_distribution<std::size_t>(0, order.size() - 1)(rng);
        const std::vector<int> prefix(order.begin(),
                                      order.begin() + static_cast<std::ptrdiff_t>(keep));
        try {
            const Solution walk =
                perturbedRollout(agent, graph, query, environment, prefix, options, rng, control);
            const Solution refined = options.thorough
                                         ? search(walk, static_cast<std::uint64_t>(move) + 1)
                                         : refineCellOrder(graph, query, walk, refinement,
                                                           kPolicyRefinementBudget, control);
            if (refined.graphCost < best.graphCost - 1e-9)
                best = refined;
        } catch (const SolverError&) {
            if (control.cancelled && control.cancelled())
                break; // the move was cut short; keep the best complete walk
            throw;
        }
    }
    best.solver = "dqn";
    return best;
}

} // namespace fc

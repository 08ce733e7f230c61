// Inference with a trained agent (solver "dqn"), and the random queries that training
// evaluates it on.
#pragma once

#include "learning/CoverageEnvironment.h"
#include "learning/torch/DqnAgent.h"
#include "solvers/Solver.h"

#include <cstdint>
#include <vector>

namespace fc {

// Settled search nodes the dqn solver's refinement may spend (OrderRefinement::LocalSearch).
// Most of its gain comes from the proxy local optimum of the learnt order, which this budget
// does not count; 100,000 keeps a query on office near 20 ms (max ~32 ms) on a 2-core VM,
// where 200,000 gained 0.3 points of gap for 70% more time (docs/dqn.md).
constexpr std::uint64_t kPolicyRefinementBudget = 100'000;

// Greedy rollout of the policy from the query's start to its end, covering the required
// cells (the others count as covered). Actions are always masked to corners of uncovered
// reachable cells, whatever the agent was trained with, so the rollout always finishes.
// Throws SolverError for a query the environment cannot take (e.g. the end in another part
// of the floor) or a graph of another size than the agent's.
// `environment` must be the options the agent was trained with (they define the image).
// beamWidth > 1: the walk is the policy's beam search's (PolicyBeam.h) instead of the greedy
// rollout's, then refined the same way.
Solution solveWithPolicy(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                         const EnvironmentOptions& environment,
                         OrderRefinement refinement = OrderRefinement::None,
                         const SolveControl& control = {}, int beamWidth = 1);

// A complete walk of the policy as a Solution (solver "dqn", cell order, graph cost); throws
// SolverError when it does not cover the query (an internal error: masking forbids it).
Solution policyWalkSolution(const CornerGraph& graph, const Query& query, const Walk& walk);

enum class QuerySet {
    AllCells,   // every reachable cell of the start's part of the floor
    RoomSubsets // a random non-empty subset of the rooms there
};

// `count` queries with random start and end corners in one connected part of the floor;
// the same seed gives the same queries.
std::vector<Query> randomQueries(const CornerGraph& graph, int count, std::uint64_t seed,
                                 QuerySet kind);

// Rooms with at least one reachable cell.
int roomCount(const CornerGraph& graph);

} // namespace fc

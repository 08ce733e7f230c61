// The policy as a search guide (issue 17, item 3): a beam search over the masked Q values.
// Q(s, a) of the cost-reward settings is minus the walk's remaining graph cost in units of
// the longest edge (immediate transit plus the cost to go), so `cost so far - Q x unit`
// estimates the whole walk through a; the beam keeps the `width` best such partial walks.
// Width 1 is the greedy rollout.
#pragma once

#include "learning/CoverageEnvironment.h"
#include "learning/torch/DqnAgent.h"
#include "solvers/Solver.h"

namespace fc {

// The beam width the reports measure (docs/dqn.md): 4 walks and the greedy rollout cost
// about 5 rollouts (a step's walks share one batch of Q values).
constexpr int kPolicyBeamWidth = 4;

// The cheapest complete walk of the final beam (its cell order and graph cost), or the
// greedy rollout's where that is cheaper (the beam ranks by estimates and may drop it), so
// a wider beam is never worse than width 1. Throws SolverError as solveWithPolicy;
// cancellable between steps.
Solution policyBeamWalk(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                        const EnvironmentOptions& environment, int width,
                        const SolveControl& control = {});

} // namespace fc

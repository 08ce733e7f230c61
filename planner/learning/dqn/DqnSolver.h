// Makes the trained Double-DQN policy available as solver "dqn" to runSolver/planCoverage
// (SPEC sect. 4): the planner core cannot link LibTorch, so applications call this once at
// start-up.
#pragma once

namespace fc {

// Registers "dqn": loads the model named by the request's model path (cached while the file
// is unchanged), refuses a model trained for another graph, plans with masked greedy
// inference and the model's refinement, and plans at the model's sweep angle when the
// request asks for "auto".
// Also registers "dqn-search": the policy as the guide of an anytime search (PolicySearch.h,
// thorough moves) that runs for kDqnSearchSeconds per query and keeps its cheapest walk; on
// large floors it beats heuristic at equal time (docs/dqn.md).
void registerDqnSolver();

constexpr double kDqnSearchSeconds = 2.0;

} // namespace fc

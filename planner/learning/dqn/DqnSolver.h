// Makes the trained Double-DQN policy available as solver "dqn" to runSolver/planCoverage
// (SPEC sect. 4): the planner core cannot link LibTorch, so applications call this once at
// start-up.
#pragma once

namespace fc {

// Registers "dqn": loads the model named by the request's model path (cached while the file
// is unchanged), refuses a model trained for another graph, plans with masked greedy
// inference and the model's refinement, and plans at the model's sweep angle when the
// request asks for "auto".
void registerDqnSolver();

} // namespace fc

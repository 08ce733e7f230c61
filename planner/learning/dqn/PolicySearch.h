// The policy as the move of a search (issue 17, item 3): an anytime large-neighbourhood
// search whose every move is a partial rollout of the learnt policy. Start: the beam's walk,
// refined (PolicyBeam.h). Move: keep a random prefix of the best walk's cell order, let the
// policy choose the rest (mostly its best corner, sometimes one of its next best by Q), refine
// that walk as solver dqn does, and keep it when cheaper. Runs until control.cancelled says
// stop or maxMoves moves are made.
#pragma once

#include "learning/CoverageEnvironment.h"
#include "learning/torch/DqnAgent.h"
#include "solvers/Solver.h"

#include <cstdint>

namespace fc {

struct PolicySearchOptions {
    int beamWidth = 4;
    int maxMoves = 0;         // <= 0: until cancelled (then control.cancelled is required)
    double exploration = 0.3; // chance of one of the next best corners instead of the best
    int alternatives = 3;     // how many of the best corners such a choice draws from
    std::uint64_t seed = 1;
    // Each walk (the start and every move's) searched by the heuristic's whole search from
    // its order (searchFromWalk, a new seed per move) instead of the light refinement: the
    // policy then chooses where the heuristic's search starts.
    bool thorough = false;
};

// The best walk found; a move cancelled half-way is dropped, so a cancellation ends the
// search with its best complete walk instead of an error (unless the start itself was
// cancelled: SolverError). Throws std::invalid_argument without any way to stop.
// start: the policy's walk to begin from when the caller already has it (e.g. made under
// the user's cancellation only, so that a deadline cannot leave it without any walk).
Solution policyGuidedSearch(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                            const EnvironmentOptions& environment, OrderRefinement refinement,
                            const SolveControl& control, const PolicySearchOptions& options = {},
                            const Solution* start = nullptr);

// The corners a walk enters its required cells by, in order: the actions that make the
// environment repeat the walk's cell order (each cell's first coverage traversal).
std::vector<int> entryActions(const CornerGraph& graph, const Query& query, const Walk& walk);

} // namespace fc

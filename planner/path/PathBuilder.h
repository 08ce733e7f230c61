// Turns a walk over the corner graph into the robot-centre path (world frame).
#pragma once

#include "graph/CornerGraph.h"
#include "model/CoveragePath.h"
#include "solvers/Solver.h"

#include <optional>

namespace fc {

// startPoint/endPoint (world frame): free points joined to the walk's first/last node by
// a collision-free transit. Throws SolverError if such a point cannot be joined.
CoveragePath buildCoveragePath(const Decomposition& decomposition, const CornerGraph& graph,
                               const Walk& walk, std::optional<Vec2> startPoint = {},
                               std::optional<Vec2> endPoint = {});

// The path of any solver's answer: its walk, or the path it planned itself (directPath).
CoveragePath buildCoveragePath(const Decomposition& decomposition, const CornerGraph& graph,
                               const Solution& solution, std::optional<Vec2> startPoint = {},
                               std::optional<Vec2> endPoint = {});

// The same for a path a solver planned itself (Solution::directPath, sweep frame): joined to
// the free start/end points, seal excursions pruned, converted to the world frame.
CoveragePath buildCoveragePath(const Decomposition& decomposition, const DirectPath& direct,
                               std::optional<Vec2> startPoint = {},
                               std::optional<Vec2> endPoint = {});

} // namespace fc

// The paper's baselines as solvers (SPEC sect. 4). `reeb-cpp` and `adjacency-ga` are
// written apart from the planner (baselines/IndependentBaselines.h: their own decomposition,
// boustrophedons and visibility-graph transits); the adapters here hand them the query's
// rooms, start and end. `adjacency-ga-centres` keeps the first paper's reading of Tung & Liu
// on the planner's classic decomposition (PreparedPlan::classic, which must be set): cell
// adjacency graph, genetic-algorithm TSP over cells with four entry/exit options per cell,
// the start cell first, transits between cells that are not neighbours through the centres
// of the cells on the way (the one left and the one entered included).
// None walks the corner graph: each returns Solution::directPath (sweep frame), from and back
// to the query's start node, then to its end node.
#pragma once

#include "graph/PreparedPlan.h"
#include "solvers/Solver.h"

namespace fc {

// All throw SolverError when no collision-free tour exists.
// reeb-cpp: the query planned by baselines/IndependentBaselines.h (Reeb graph + Chinese
// Postman); the path as Solution::directPath.
Solution solveReebPostman(const PreparedPlan& prepared, const Query& query,
                          const SolveControl& control = {});
// Cancellable between generations (SolverError when control.cancelled() says so).
Solution solveAdjacencyGa(const PreparedPlan& prepared, const Query& query,
                          const SolveControl& control = {});
// adjacency-ga: the query's rooms, start and end planned by baselines/IndependentBaselines.h (GA);
// the path as Solution::directPath. Cancellable between generations.
Solution solveTungLiuGa(const PreparedPlan& prepared, const Query& query,
                        const SolveControl& control = {});

} // namespace fc

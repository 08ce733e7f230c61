// The two earlier methods the paper compares against (SPEC sect. 4), planned on the classic
// Boustrophedon decomposition they were published with (no transition cells):
// * reeb-cpp: Reeb graph (critical slices as nodes, cells as edges), Chinese Postman tour
//   (minimum-weight perfect matching of odd nodes), cells on duplicated edges covered in two
//   halves (top half on the first pass, bottom half on the second), back to the start
//   (Mannadiar & Rekleitis 2010; Xu et al. 2014);
// * adjacency-ga-centres: cell adjacency graph, genetic-algorithm TSP over cells with four
// entry/exit
//   options per cell, the start cell first, transits between cells that are not neighbours
//   through the centres of the cells on the way (the one left and the one entered included),
//   back to the start (Tung & Liu 2019).
// Neither walks the corner graph: both return Solution::directPath. Both plan on the prepared
// plan's classic decomposition and graph (PreparedPlan::classic, which must be set), answering
// the corner-graph query: the rooms of its required cells, from and back to its start
// node's position.
#pragma once

#include "graph/PreparedPlan.h"
#include "solvers/Solver.h"

namespace fc {

// `adjacency-ga` itself is the independent implementation of Tung & Liu's own code
// (baselines/TungLiu.h, adapted by solveTungLiuGa); adjacency-ga-centres keeps the reading
// of the first paper above.
//
// All throw SolverError when no collision-free tour exists.
Solution solveReebPostman(const PreparedPlan& prepared, const Query& query);
// Cancellable between generations (SolverError when control.cancelled() says so).
Solution solveAdjacencyGa(const PreparedPlan& prepared, const Query& query,
                          const SolveControl& control = {});
// adjacency-ga: the query's rooms, start and end planned by baselines/TungLiu.h (GA); the
// path as Solution::directPath. Cancellable between generations.
Solution solveTungLiuGa(const PreparedPlan& prepared, const Query& query,
                        const SolveControl& control = {});

} // namespace fc

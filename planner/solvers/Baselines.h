// The two earlier methods the paper compares against (SPEC sect. 4), planned on the classic
// Boustrophedon decomposition they were published with (no transition cells):
// * reeb-cpp: Reeb graph (critical slices as nodes, cells as edges), Chinese Postman tour
//   (minimum-weight perfect matching of odd nodes), cells on duplicated edges covered in two
//   halves (top half on the first pass, bottom half on the second), back to the start
//   (Mannadiar & Rekleitis 2010; Xu et al. 2014);
// * adjacency-ga: cell adjacency graph, genetic-algorithm TSP over cells with four entry/exit
//   options per cell, the start cell first, transits between cells that are not neighbours
//   through the centres of the cells on the way (the one left and the one entered included),
//   back to the start (Tung & Liu 2019).
// Neither walks the corner graph: both return Solution::directPath.
#pragma once

#include "decomposition/Decomposition.h"
#include "graph/CornerGraph.h"
#include "model/Plan.h"
#include "solvers/Solver.h"

#include <cstdint>
#include <vector>

namespace fc {

struct BaselineQuery {
    const Plan* plan = nullptr; // normalized and validated
    double coverageWidth = 1.0;
    double robotDiameter = 0.0; // L (0: L = W)
    double stripeAngleDeg = 90.0;
    std::vector<char> requiredRooms; // per room of the decomposition
    Vec2 start;                      // sweep frame; the tour returns here
    std::uint64_t seed = 1;
};

// The query of the corner-graph solvers restated for a baseline: the rooms of the required
// cells, and the start node's position (baselines always return to their start).
BaselineQuery makeBaselineQuery(const Plan& plan, const Decomposition& decomposition,
                                const CornerGraph& graph, const Query& query);

// Both throw SolverError when no collision-free tour exists.
Solution solveReebPostman(const BaselineQuery& query);
Solution solveAdjacencyGa(const BaselineQuery& query);

} // namespace fc

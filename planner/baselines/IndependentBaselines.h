// The paper's two baselines written apart from the planner. Both plan on one classic
// Boustrophedon decomposition of their own (no transition cells) with their own
// boustrophedon in each cell (stripes W apart, the outer ones W/2 inside, connectors along
// the cell's floor and ceiling, nothing pruned) and transits as shortest paths on a
// visibility graph of the walls grown by the robot's clearance (Boost.Graph).
// * adjacency-ga (Tung & Liu 2019, their GA-TSPCPP code): four entry/exit options per cell
//   (start corner x direction) and a seeded genetic algorithm over cell order and options
//   (order crossover, swap and inversion, option mutation); planTungLiuDp is their dynamic
//   programme over cells x options for the same model, the optimum the GA is measured
//   against.
// * reeb-cpp (Mannadiar & Rekleitis 2010; Xu et al. 2014): the Reeb graph (cells as edges
//   between the slices where cells meet), a Chinese Postman tour (odd nodes paired by an
//   exact minimum-weight perfect matching, LEMON's blossom algorithm), a cell on a
//   duplicated edge covered as its top half on the first pass and its bottom half on the
//   second.
//
// Independence: the files of this folder include only the plan model (model/), the plain
// geometry (geometry/Geometry.h) and each other (BaselineIndependence test). Nothing of the
// planner's decomposition, graph, solvers or path building.
#pragma once

#include "geometry/Geometry.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fc::baselines {

struct Options {
    double width = 1.0;           // W: stripe spacing
    double clearance = 0.3;       // L/2: how far the robot centre keeps from walls
    double stripeAngleDeg = 90.0; // stripe direction in the world frame
    std::uint64_t seed = 1;
    int population = 80;
    int generations = 10000;         // at most
    int stallGenerations = 3000;     // stops after this many without a better tour
    std::function<bool()> cancelled; // checked between generations; may be empty
};

struct Tour {
    CoveragePath path;        // world frame, from the start to the end point
    double length = 0.0;      // of path
    std::vector<int> order;   // the cells in visiting order
    std::vector<int> options; // per visited cell: 0..3 (bit 0: right to left, bit 1: down first)
    int cells = 0;            // cells of the decomposition
    int unreachableCells = 0; // cells where no stripe keeps the clearance (left out)
    double modelCost = 0.0;   // the tour's length in the GA/DP model (== length)
};

// No tour: nothing to cover, a cell the robot cannot reach, or cancelled.
class TourError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// rooms: the names of the rooms to cover; empty: the whole floor. start, end: world frame,
// free points the robot fits at.
Tour planTungLiuGa(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                   const Options& options);

// The same model solved exactly (Held-Karp over visited cells x last cell x option); nullopt
// when the rooms decompose into more than maxCells cells.
std::optional<Tour> planTungLiuDp(const Plan& plan, const std::vector<std::string>& rooms,
                                  Vec2 start, Vec2 end, const Options& options, int maxCells = 16);

// The Reeb-graph Chinese Postman tour from the start, back to it, then to the end. Uses
// width, clearance and stripeAngleDeg of the options.
Tour planReebPostman(const Plan& plan, const std::vector<std::string>& rooms, Vec2 start, Vec2 end,
                     const Options& options);

} // namespace fc::baselines

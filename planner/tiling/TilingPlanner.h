// The tiling robot's pipeline: plan -> triangle lattice -> tile set -> waypoint order,
// with the metrics the CLI prints and the waypoint list it exports.
#pragma once

#include "model/Plan.h"
#include "tiling/Tiling.h"
#include "tiling/TriangleGrid.h"
#include "tiling/WaypointOrder.h"

#include <cstdint>
#include <functional>
#include <string>

namespace fc::tiling {

struct TilingRequest {
    Plan plan;
    TilingRobotProfile robot;
    std::string solver = "greedy";
    std::uint64_t seed = 1;
    TilingOptions tiling;
    // May be empty: planTiling stops (OrderingCancelled) after tiling and within aco and ga.
    std::function<bool()> cancelled;
};

struct TilingPlan {
    std::string solver;
    TriangleGrid grid;
    TilingResult tiling;
    OrderingProblem problem; // one waypoint per tile, in tile order
    Tour tour;
    EnergyTerms energy;
    double length = 0.0;
    int shapeChanges = 0;
    double tilingSeconds = 0.0;
    double orderingSeconds = 0.0; // the paper's Table 3 running time
};

// Validates the plan and the robot (InputError), tiles the floor and orders the tiles.
TilingPlan planTiling(const TilingRequest& request);
// Lattice and tile set only (ordering left empty), e.g. to reuse them across solvers.
TilingPlan tilePlan(const TilingRequest& request);
void orderTiles(TilingPlan& plan, const std::string& solver, std::uint64_t seed,
                const std::function<bool()>& cancelled = {});

// One JSON line: energy, length, shape_changes, waypoints, seconds, then details.
std::string tilingMetricsJson(const TilingPlan& plan);
// The ordered waypoints (x, y, shape, heading in degrees), by the file's extension:
// .csv or .json (which also lists the centres of unreachable and untiled cells); throws
// InputError for another extension.
std::string waypointsToFormat(const std::string& path, const TilingPlan& plan);

} // namespace fc::tiling

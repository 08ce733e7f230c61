// The planning pipeline as one call, and its steps for clients that show intermediate
// results (the editor updates cells and graph overlays without planning a path).
#pragma once

#include "decomposition/Decomposition.h"
#include "formats/PlanIO.h"
#include "graph/CornerGraph.h"
#include "metrics/Metrics.h"
#include "model/Plan.h"
#include "path/CoveragePath.h"
#include "solvers/Solver.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

struct PlanRequest {
    Plan plan;
    RobotProfile robot;
    SweepOptions sweep;
    std::string solver = "heuristic";
    std::vector<std::string> rooms; // names; empty = every room
    std::optional<Vec2> start, end; // world frame; default start: a corner of the first
                                    // required cell; default end: the start
    std::uint64_t seed = 1;
    std::string modelPath; // for learnt solvers
    bool transitionCells = true;
};

// The request a project file describes (its plan, robot, sweep, solver, rooms, start, end).
PlanRequest planRequestFor(const Project& project);

// Plan -> validated plan -> decomposition -> corner graph.
struct PreparedPlan {
    Plan plan; // normalized
    RobotProfile robot;
    Decomposition decomposition;
    CornerGraph graph;
};

struct PlanResult {
    PreparedPlan prepared;
    Query query;
    Solution solution;
    CoveragePath path;
    Metrics metrics;
    std::vector<std::string> warnings;
    double stripeAngleDeg = 90.0;
};

// Validates (throws InputError) and builds decomposition and graph for one sweep angle.
PreparedPlan preparePlan(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                         bool transitionCells = true);

// Required cells from room names, start/end snapped to the nearest corners. Cells that
// cannot be reached from the start are left out with a warning. Throws InputError for
// unknown rooms or an end that cannot be reached.
Query makeQuery(const PreparedPlan& prepared, const std::vector<std::string>& rooms,
                std::optional<Vec2> start, std::optional<Vec2> end, std::uint64_t seed,
                std::vector<std::string>& warnings);

// Solver names accepted by runSolver, in the order the CLI lists them.
std::vector<std::string> solverNames();
Solution runSolver(const std::string& name, const PreparedPlan& prepared, const Query& query,
                   const std::string& modelPath = {}, const SolveControl& control = {});

// Sweep angles tried by "auto": 0, 90 and the plan's dominant wall directions.
std::vector<double> candidateAngles(const Plan& plan);

PlanResult planCoverage(const PlanRequest& request, const SolveControl& control = {});

} // namespace fc

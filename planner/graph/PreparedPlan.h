// What every solver receives: the plan prepared for one robot and sweep angle (validated
// plan -> decomposition -> corner graph). pipeline/Planner.h prepares it (preparePlan).
#pragma once

#include "decomposition/Decomposition.h"
#include "graph/CornerGraph.h"
#include "model/Plan.h"

#include <memory>

namespace fc {

// A decomposition and the corner graph built on it.
struct PlanStages {
    Decomposition decomposition;
    CornerGraph graph;
};

// Decomposes a normalized, validated plan for the robot's W and L at one sweep angle (with or
// without transition cells) and builds its corner graph. Throws InputError as decompose.
// floorCache (optional): see DecompositionOptions::floorCache.
PlanStages buildPlanStages(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                           bool transitionCells,
                           const std::shared_ptr<FloorCache>& floorCache = nullptr,
                           LatticeMode stripeLattice = LatticeMode::Own,
                           Headland headland = Headland::None);

struct PreparedPlan {
    Plan plan; // normalized
    RobotProfile robot;
    Decomposition decomposition;
    CornerGraph graph;
    // The classic Boustrophedon decomposition (no transition cells) of the same plan, robot
    // and sweep angle with its corner graph: what the baselines (reeb-cpp, adjacency-ga) plan
    // on. Prepared only for solvers that ask for it (RegisteredSolver::classicStages), else
    // null.
    std::shared_ptr<const PlanStages> classic;
};

} // namespace fc

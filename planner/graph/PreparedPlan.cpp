#include "graph/PreparedPlan.h"

namespace fc {

PlanStages buildPlanStages(const Plan& plan, const RobotProfile& robot, double stripeAngleDeg,
                           bool transitionCells, const std::shared_ptr<FloorCache>& floorCache,
                           LatticeMode stripeLattice, Headland headland) {
    DecompositionOptions options;
    options.robot = robot;
    options.stripeAngleDeg = stripeAngleDeg;
    options.transitionCells = transitionCells;
    options.floorCache = floorCache;
    options.stripeLattice = stripeLattice;
    options.headland = headland;
    PlanStages stages;
    stages.decomposition = decompose(plan, options);
    stages.graph = buildCornerGraph(stages.decomposition);
    return stages;
}

} // namespace fc

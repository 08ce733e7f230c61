// An integrator's program: a 10 m x 6 m room with a pillar, planned with the installed
// core. Exits 0 when the path covers the room; prints the metrics.
#include "pipeline/Planner.h"

#include <cstdio>

int main() {
    fc::PlanRequest request;
    request.plan.boundary = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
    request.plan.obstacles = {{{4, 2}, {5, 2}, {5, 3}, {4, 3}}};
    request.robot.coverageWidth = 0.8;
    request.robot.robotDiameter = 0.5;
    request.robot.cleaningDiameter = 0.8;
    const fc::PlanResult result = fc::planCoverage(request);
    std::printf("length %.2f m, turns %d, coverage %.4f, %zu waypoints\n", result.metrics.length,
                result.metrics.turns, result.metrics.coverage, result.path.points.size());
    return result.metrics.coverage >= 0.99 && result.path.points.size() > 10 ? 0 : 1;
}

// Validation of a plan against the robot profile (uses CGAL's exact predicates).
#pragma once

#include "model/Plan.h"

#include <string>
#include <vector>

namespace fc {

// A defect of the plan's own rings that repairPlan mends: rings that cross or touch
// themselves or each other, obstacles outside, inside or on top of one another, rooms that
// overlap. Front ends may point to the repair (`floorcover-cli import --repair`).
class RepairablePlanError : public InputError {
public:
    using InputError::InputError;
};

// Throws InputError with one line naming the problem, e.g.
//   "obstacle 3 crosses the boundary near (12.5, 4.0)".
// Checks: at least 3 distinct vertices per ring, finite coordinates, no duplicate
// consecutive vertices or collinear spikes that make a ring degenerate, simple rings
// (no self-intersection), obstacles inside the boundary and not overlapping each other,
// rooms simple and overlapping the free space, free area larger than the robot.
void validatePlan(const Plan& plan, const RobotProfile& robot);

// One defect of a plan, for an editor that lists and highlights them.
struct PlanProblem {
    std::string message; // as validatePlan would say it
    bool hasLocation = false;
    Vec2 location; // where to look (a crossing, a spike, the ring's first vertex)
};

// Every geometric defect validatePlan would stop at (ring shapes, self-intersections and
// spikes, obstacles crossing, touching or overlapping the boundary or each other), at most
// `limit` of them, in a stable order; when there are none, the first remaining problem
// validatePlan reports (placement, free area, rooms), if any. Empty for a valid plan.
std::vector<PlanProblem> planProblems(const Plan& plan, const RobotProfile& robot,
                                      size_t limit = 200);

// Light clean-up done before validation: drops repeated consecutive vertices and
// vertices on a straight line between their neighbours. Returns the cleaned plan.
Plan normalizedPlan(const Plan& plan);

} // namespace fc

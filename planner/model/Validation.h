// Validation of a plan against the robot profile (uses CGAL's exact predicates).
#pragma once

#include "model/Plan.h"

namespace fc {

// Throws InputError with one line naming the problem, e.g.
//   "obstacle 3 crosses the boundary near (12.5, 4.0)".
// Checks: at least 3 distinct vertices per ring, finite coordinates, no duplicate
// consecutive vertices or collinear spikes that make a ring degenerate, simple rings
// (no self-intersection), obstacles inside the boundary and not overlapping each other,
// rooms simple and overlapping the free space, free area larger than the robot.
void validatePlan(const Plan& plan, const RobotProfile& robot);

// Light clean-up done before validation: drops repeated consecutive vertices and
// vertices on a straight line between their neighbours. Returns the cleaned plan.
Plan normalizedPlan(const Plan& plan);

} // namespace fc

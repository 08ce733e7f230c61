// Per-room sweep directions (SPEC sect. 1): each room's stripes follow its own walls, so a
// building drawn at any rotation, or a site of buildings at different rotations, is swept
// along its walls rather than across them.
#pragma once

#include "pipeline/Planner.h"
#include "pipeline/RoomAngles.h"

#include <map>
#include <string>
#include <vector>

namespace fc {

// Plans each group of rooms that shares one angle of `angles` in its own frame, in turn (the
// start's group first, then the nearest group), joined by collision-free transits; metrics
// over the whole path. With one angle this is planAtAngle. `prepared`: of request.plan and
// request.robot.
PlanResult planWithRoomAngles(const PlanRequest& request,
                              const std::map<std::string, double>& angles,
                              const SolveControl& control, const PreparedPlans& prepared);

// The per-room plan (SPEC sect. 1): the family plan, and on small floors (rooms, obstacles) the
// rooms' own angles and turned groups, keeping the best. `prepared` (optional): of request.plan and
// request.robot, shared with other requests (the editor's live replanning).
// Both are steps of planCoverage and leave Metrics::overlaps empty (withOverlaps fills them).
PlanResult planPerRoom(const PlanRequest& request, const SolveControl& control = {},
                       const PreparedPlans* prepared = nullptr);

} // namespace fc

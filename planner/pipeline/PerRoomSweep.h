// Per-room sweep directions (SPEC sect. 1): each room's stripes follow its own walls, so a
// building drawn at any rotation, or a site of buildings at different rotations, is swept
// along its walls rather than across them.
#pragma once

#include "pipeline/Planner.h"

#include <map>
#include <string>
#include <vector>

namespace fc {

// The stripe angle of every room of the plan, degrees in [0, 180): its override in
// sweep.roomAngles, or, from the room's own walls (its outline and the obstacles inside it),
// the dominant wall family, stripes along the room's longer extent in that family's frame.
// The entry under the empty name is for free space outside every room ("Floor" when the
// plan has no rooms): the same rule over the whole floor.
std::map<std::string, double> roomSweepAngles(const Plan& plan, const SweepOptions& sweep);

// The angle a decomposition room name sweeps at (rooms the plan does not name, such as
// "Floor" or "Unassigned 1", take the floor's entry).
double sweepAngleOfRoom(const std::map<std::string, double>& angles, const std::string& room);

// The rooms' angles with the building's main wall family swept as one: every room whose own
// angle lies along or across the family of most rooms takes that family's angle; rooms of
// other families and fixed angles (sweep.roomAngles) keep theirs. What large floors plan.
std::map<std::string, double> familyAngles(const Plan& plan, const SweepOptions& sweep);

// The angle each room of the plan was swept at in `result` (its part's angle; rooms the plan
// does not name under the empty name, as roomSweepAngles keys them). Rooms it did not plan
// are absent.
std::map<std::string, double> roomAnglesOf(const PlanResult& result, const Plan& plan);

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

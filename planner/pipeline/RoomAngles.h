// The sweep angle of each room: from its own walls, the building's family, or what a plan
// used (SPEC sect. 1, per-room angles).
#pragma once

#include "pipeline/Planner.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fc {

// `deg` in [0, 180).
double normalizedAngle(double deg);
// The angle between two stripe directions, in [0, 90] degrees.
double angleDistance(double a, double b);

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
// (None for a plan of rings, PlanResult::rings: no room is swept at an angle.)

// The groups of the rooms' angles in `angles`, the one with the most rooms first: each an
// angle and its room count.
std::vector<std::pair<double, int>> angleGroups(const std::map<std::string, double>& angles);

// For each room whose walls have a second family at least half as long as its first (a
// slanted side, a trapezoid), the angle along its longer extent in that family's frame.
// Rooms with a fixed angle in sweep.roomAngles are absent. A plan without rooms has its
// entry, if any, under the empty name (the floor, as roomSweepAngles keys it).
std::map<std::string, double> roomSecondAngles(const Plan& plan, const SweepOptions& sweep);

} // namespace fc

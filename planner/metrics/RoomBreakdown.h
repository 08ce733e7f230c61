// Where the path spends its time, room by room: the report's room table (visit order, free
// area, length, turns, estimated time). Rows add up to the path's metrics.
#pragma once

#include "decomposition/Decomposition.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"

#include <string>
#include <vector>

namespace fc {

struct RoomVisit {
    std::string room;  // empty: moves outside every room
    int order = 0;     // 1 = the room the path sweeps first; 0: never swept (or outside)
    double area = 0;   // m^2, free floor of the room (its cells in the decomposition)
    double length = 0; // m of path inside the room
    int turns = 0;     // turns made inside the room (countTurns' rule)
    double time = 0;   // s, length / speed + turns * turn time
};

// One row per room of the plan, in visit order (rooms never swept after those that are),
// then a row for the path outside every room when there is any. A piece of path belongs
// to the first room of the plan containing its midpoint; the path is cut into pieces of at
// most 0.25 m so that a move through a doorway is split between the rooms it joins.
// decomposition: its cells give the rooms' free area (by the decomposition's room names);
// may be null (areas 0).
std::vector<RoomVisit> roomBreakdown(const Plan& plan, const CoveragePath& path,
                                     const RobotProfile& robot, const Decomposition* decomposition);

} // namespace fc

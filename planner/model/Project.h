// The native project: the plan with everything needed to plan it again (robot profile, sweep
// options and the planning selection). Its file format is in formats/PlanIO.h.
#pragma once

#include "model/Plan.h"

#include <string>
#include <vector>

namespace fc {

struct Project {
    Plan plan;
    RobotProfile robot;
    SweepOptions sweep;
    std::string solver = "heuristic";
    std::vector<std::string> selectedRooms; // empty = all
    bool hasStart = false, hasEnd = false;
    Vec2 start, end;
    // What reading the file did that a user should hear of (e.g. longitude/latitude
    // reprojected to metres); not saved.
    std::vector<std::string> notes;
};

} // namespace fc

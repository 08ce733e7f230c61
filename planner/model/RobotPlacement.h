// Where a robot of diameter L can stand: a clicked start or end point moved to the nearest
// position whose centre keeps L/2 from every wall (SPEC sect. 1), so that what the user
// places is what the planner can use, and a click in an obstacle is answered at once.
#pragma once

#include "model/Plan.h"

#include <optional>

namespace fc {

enum class PlacementProblem {
    None,
    OutsideFloor,   // outside the boundary
    InsideObstacle, // inside an obstacle
    NoRoom,         // no position within the search radius where the robot fits
};

struct RobotPlacement {
    PlacementProblem problem = PlacementProblem::None;
    Vec2 position;      // when problem == None: the clicked point or the nearest fit
    double moved = 0.0; // distance from the clicked point, m
};

// Distance from p to the nearest wall (boundary and obstacle edges).
double distanceToWalls(const Plan& plan, Vec2 p);

// The clicked point when the robot fits there, else the nearest point within searchRadius
// (sampled every 2.5 cm along rings 2.5 cm apart) where its centre is in the free space and
// at least L/2 from every wall.
RobotPlacement placeRobot(const Plan& plan, Vec2 clicked, double robotDiameter,
                          double searchRadius = 1.5);

} // namespace fc

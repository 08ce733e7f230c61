// The wall-following loop of a floor (issue 15): the robot centre drives once around the
// outer walls at its clearance, as a robot vacuum's edge mode does, and what the loop's head
// leaves unswept is what stripes must still cover. On a traced map the walls are ragged: a
// loop enters every niche the robot fits into on its way, where stripes ending at each bump
// would each turn, seal and leave again (the corridor map: 454 m of path for 200 m^2).
#pragma once

#include "geometry/Geometry.h"
#include "model/Plan.h"

#include <optional>
#include <string>
#include <vector>

namespace fc {

struct WallLoop {
    Ring loop;           // world frame, the robot centre's closed path, first point = last
    double length = 0.0; // m
    // With aroundHoles: closed loops round the obstacles inside the loop, at the same
    // clearance, each starting at its vertex nearest `near`; their bands are swept too.
    std::vector<Ring> holeLoops;
    std::vector<Ring> rest; // outer rings of the floor pieces the loop's head leaves unswept
    std::vector<std::vector<Ring>> restHoles; // per piece: its holes (obstacles it surrounds)
    std::vector<int> restRoom; // per piece: index into Plan::rooms, -1 outside every room
    double restArea = 0.0;     // m^2, pieces kept
    double droppedArea = 0.0;  // m^2, pieces smaller than the minimum (left to the touch-ups)
};

// The loop around the outer walls of the part of plan's free space (boundary minus
// obstacles) that holds `near` (else the nearest part; without `near`, the largest part),
// `clearance` from every wall, and the floor outside the band of `headWidth` it sweeps,
// split by the plan's rooms and where the robot cannot pass inside a piece. Pieces below
// `minPieceArea` are dropped (counted in droppedArea); the pieces' outlines are simplified
// by simplifyTolerance (Douglas-Peucker, never inwards), then cut back to the free floor.
// Empty when the robot fits nowhere.
// The loop starts and ends at its vertex nearest `near` (without it, the vertex farthest
// from the part's centre). It keeps a few millimetres more than `clearance` from the walls,
// so that the chords of its round corners keep the clearance.
std::optional<WallLoop> wallLoop(const Plan& plan, double clearance, double headWidth,
                                 std::optional<Vec2> near, double minPieceArea,
                                 double simplifyTolerance = 0.0, bool aroundHoles = false);

// The point of the floor `outline` minus `holes` nearest `near` where the robot centre keeps
// `clearance` (and a centimetre) from their edges; empty where the robot fits nowhere.
std::optional<Vec2> clearPointNear(const Ring& outline, const std::vector<Ring>& holes,
                                   double clearance, Vec2 near);

} // namespace fc

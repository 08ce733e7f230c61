// The floor plan and robot profile: the planner's inputs, as plain values.
#pragma once

#include "geometry/Geometry.h"

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fc {

// Bad input (file, geometry, parameters). The message names the problem in one line;
// the CLI prefixes the file name and exits with code 2.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Room {
    std::string name;
    Ring outline;
};

struct Plan {
    Ring boundary;               // outer wall, any orientation
    std::vector<Ring> obstacles; // holes
    std::vector<Room> rooms;     // optional named regions
    std::string name;            // display name (file stem)
    std::optional<int> epsg;     // coordinate reference, when known

    BoundingBox bounds() const { return boundsOf(boundary); }
};

// Boundary area minus the obstacles' (which do not overlap in a valid plan), m^2.
double freeAreaOf(const Plan& plan);

struct RobotProfile {
    double robotDiameter = 0.6;    // L, m
    double cleaningDiameter = 1.0; // D, m
    double coverageWidth = 1.0;    // W, m (stripe spacing)
    double speed = 0.5;            // m/s
    double turnTime = 2.0;         // s per 90 degree turn

    // Throws InputError when the combination is impossible (L <= W <= D, all positive).
    void validate() const;
};

// Sweep direction. Per room (the default): each room's stripes follow its own walls (or its
// entry in roomAngles). Fixed (perRoom and automatic false): one angle for the whole floor,
// angleDeg (90 = vertical stripes, as in the paper). Auto: angles searched for the whole
// floor, the shortest estimated time among plans that cover everything reachable.
struct SweepOptions {
    double angleDeg = 90.0;
    bool automatic = false;
    bool perRoom = true;
    std::map<std::string, double> roomAngles; // per-room overrides, degrees, by room name
};

} // namespace fc

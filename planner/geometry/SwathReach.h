// What a swath leaves of a piece of floor (Boost.Geometry): the parts farther than the head's
// reach from the line the robot drives.
#pragma once

#include "geometry/Geometry.h"

#include <vector>

namespace fc {

struct FloorPart {
    Ring outline;
    std::vector<Ring> holes;
};

struct SwathLeftovers {
    std::vector<FloorPart> parts; // those of at least the minimum area
    double area = 0.0;            // m^2, all of what the swath leaves, small parts included
};

// The floor `outline` minus `holes` farther than `reach` from `line`. Empty parts and an
// area of -1 where Boost.Geometry's overlay gives up (nothing is claimed swept).
SwathLeftovers swathLeftovers(const Ring& outline, const std::vector<Ring>& holes,
                              const Polyline& line, double reach, double minPartArea);

} // namespace fc

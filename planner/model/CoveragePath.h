// The robot-centre path (SPEC sect. 6), world frame: a plain value that solvers, path
// building, metrics and the formats share.
#pragma once

#include "geometry/Geometry.h"

#include <vector>

namespace fc {

// What the robot does on the segment from points[i] to points[i+1].
enum class SegmentKind {
    Stripe,  // boustrophedon stripe or the short step between stripes (covering)
    Contour, // contour-following along a cell's floor/ceiling/first or last stripe
    Transit, // inter-cell travel, lead-in from a free start point, lead-out to the end
};

struct CoveragePath {
    Polyline points;                // world frame
    std::vector<SegmentKind> kinds; // size = points.size() - 1

    bool empty() const { return points.size() < 2; }
};

const char* segmentKindName(SegmentKind kind);

} // namespace fc

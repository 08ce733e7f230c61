// Internal: drops seal excursions whose stripe-end margin the rest of the path already
// sweeps (head of width W across the direction of travel, mitred joins; SPEC sect. 6).
#pragma once

#include "geometry/Geometry.h"

#include <vector>

namespace fc::detail {

struct PathExcursion {
    int begin = 0, end = 0; // point indices; points[begin] == points[end]
    bool towardsCeiling = false;
};

// points: the whole path in the sweep frame. Returns, per point, whether to keep it.
std::vector<char> prunableExcursions(const Polyline& points,
                                     const std::vector<PathExcursion>& excursions, double width);

} // namespace fc::detail

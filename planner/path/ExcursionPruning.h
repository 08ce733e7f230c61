// Internal: drops seal excursions whose stripe-end margin the rest of the path already
// sweeps (head of width W across the direction of travel, mitred joins; SPEC sect. 6).
#pragma once

#include "geometry/Clearance.h"
#include "geometry/Geometry.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"

#include <vector>

namespace fc::detail {

struct PathExcursion {
    int begin = 0, end = 0; // point indices; points[begin] == points[end]
    bool towardsCeiling = false;
};

// points: the whole path in the sweep frame. Returns, per point, whether to keep it.
std::vector<char> prunableExcursions(const Polyline& points,
                                     const std::vector<PathExcursion>& excursions, double width);

// A seal excursion kept next to a transit is folded into it: the transit runs straight to
// the excursion's far end and the robot drives the margin once, back to the stripe end (or
// it drives out once and leaves from the far end). The robot sweeps the same margin, the
// route is never longer (triangle inequality) and one out-and-back reversal is gone. Applied
// only where the new segment is clear and the estimated time (robot's speed and turn time)
// of the neighbourhood drops. `keep` comes from prunableExcursions and is updated;
// arriving[i] is the kind of the segment that ends at point i.
void foldExcursionsIntoTransits(const Polyline& points,
                                const std::vector<PathExcursion>& excursions,
                                const ClearanceField& field, const RobotProfile& robot,
                                std::vector<char>& keep, std::vector<SegmentKind>& arriving);

} // namespace fc::detail

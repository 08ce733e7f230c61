// Internal to pipeline/: collision-free transits on a whole floor, for the offers that join
// loops and pieces of their own making (the wall loop, the rings).
#pragma once

#include "geometry/Clearance.h"
#include "model/CoveragePath.h"
#include "model/Plan.h"

#include <cstddef>
#include <vector>

namespace fc::detail {

// The floor's walls as the planner's clearance field sees them, in a frame at the plan's
// first corner (UTM-sized coordinates keep their digits; 90 degrees: not turned).
struct FloorField {
    FloorField(const Plan& plan, double radius);

    static std::vector<Ring> ringsOf(const Plan& plan, const Frame& frame);
    // Whether the robot centre may drive along `world` (world frame).
    bool isClear(const Polyline& world) const;

    Frame frame;
    ClearanceField field;
};

// The segment tests one transit may spend before the open regions' grid routes it instead:
// on the faculty map at half its cell size with its clutter's corners squared, the transits
// to a pocket behind a closed gap, which the regions did not prove apart, searched for 70 s.
inline constexpr std::size_t kEdgeTransitChecks = 200'000;

// Appends a collision-free transit from the path's last point to `to` (nothing when there);
// false, and the path unchanged, where there is none.
bool tryAppendTransit(const FloorField& floor, CoveragePath& path, Vec2 to);

// The same; throws InputError where there is none.
void appendTransit(const FloorField& floor, CoveragePath& path, Vec2 to);

} // namespace fc::detail

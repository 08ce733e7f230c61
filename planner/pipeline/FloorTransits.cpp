#include "pipeline/FloorTransits.h"

#include <algorithm>
#include <cmath>

namespace fc::detail {

FloorField::FloorField(const Plan& plan, double radius)
    : frame(plan.boundary.front(), 90.0), field(ringsOf(plan, frame), radius) {}

std::vector<Ring> FloorField::ringsOf(const Plan& plan, const Frame& frame) {
    std::vector<Ring> rings{frame.toLocal(plan.boundary)};
    if (signedArea(rings.front()) < 0.0)
        std::reverse(rings.front().begin(), rings.front().end());
    for (const Ring& obstacle : plan.obstacles) {
        rings.push_back(frame.toLocal(obstacle));
        if (signedArea(rings.back()) > 0.0)
            std::reverse(rings.back().begin(), rings.back().end());
    }
    return rings;
}

bool FloorField::isClear(const Polyline& world) const {
    Polyline local;
    local.reserve(world.size());
    for (const Vec2& p : world)
        local.push_back(frame.toLocal(p));
    return field.polylineIsClear(local);
}

bool tryAppendTransit(const FloorField& floor, CoveragePath& path, Vec2 to) {
    const Vec2 from = path.points.back();
    if (norm(to - from) < 1e-9)
        return true;
    const Vec2 a = floor.frame.toLocal(from), b = floor.frame.toLocal(to);
    // Provably apart (a pocket behind a gap narrower than the robot): no search, which
    // would test every pair of wall corners on the floor before it gave up.
    const int regionA = floor.field.openRegionOf(a), regionB = floor.field.openRegionOf(b);
    if (regionA >= 0 && regionB >= 0 && regionA != regionB)
        return false;
    const Polyline local = floor.field.findPath(a, b, {}, INFINITY, kEdgeTransitChecks);
    if (local.size() < 2)
        return false;
    const Polyline world = floor.frame.toWorld(local);
    for (size_t i = 1; i < world.size(); ++i) {
        path.points.push_back(i + 1 == world.size() ? to : world[i]);
        path.kinds.push_back(SegmentKind::Transit);
    }
    return true;
}

void appendTransit(const FloorField& floor, CoveragePath& path, Vec2 to) {
    if (!tryAppendTransit(floor, path, to))
        throw InputError("the wall loop's pieces cannot be joined without collision");
}

} // namespace fc::detail

#include "model/RobotPlacement.h"

#include "geometry/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fc {

namespace {

double ringDistance(const Ring& ring, Vec2 p) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < ring.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]));
    return best;
}

bool inFreeSpace(const Plan& plan, Vec2 p) {
    if (!pointInRing(plan.boundary, p))
        return false;
    return std::none_of(plan.obstacles.begin(), plan.obstacles.end(),
                        [p](const Ring& o) { return pointInRing(o, p); });
}

} // namespace

double distanceToWalls(const Plan& plan, Vec2 p) {
    double best = ringDistance(plan.boundary, p);
    for (const Ring& o : plan.obstacles)
        best = std::min(best, ringDistance(o, p));
    return best;
}

RobotPlacement placeRobot(const Plan& plan, Vec2 clicked, double robotDiameter,
                          double searchRadius) {
    RobotPlacement out;
    if (!pointInRing(plan.boundary, clicked)) {
        out.problem = PlacementProblem::OutsideFloor;
        return out;
    }
    for (const Ring& o : plan.obstacles)
        if (pointInRing(o, clicked)) {
            out.problem = PlacementProblem::InsideObstacle;
            return out;
        }
    // A hair more than L/2, so that the planner's own clearance test accepts it.
    const double needed = 0.5 * robotDiameter * (1.0 + 1e-6) + 1e-9;
    auto fits = [&](Vec2 p) { return inFreeSpace(plan, p) && distanceToWalls(plan, p) >= needed; };
    out.position = clicked;
    if (fits(clicked))
        return out;
    const double step = 0.025;
    for (double r = step; r <= searchRadius + 1e-12; r += step) {
        const int samples = std::max(8, static_cast<int>(std::ceil(2.0 * M_PI * r / step)));
        for (int k = 0; k < samples; ++k) {
            const double a = 2.0 * M_PI * k / samples;
            const Vec2 p{clicked.x + r * std::cos(a), clicked.y + r * std::sin(a)};
            if (fits(p)) {
                out.position = p;
                out.moved = r;
                return out;
            }
        }
    }
    out.problem = PlacementProblem::NoRoom;
    return out;
}

} // namespace fc

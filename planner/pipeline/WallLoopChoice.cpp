// The wall loop's whether (EdgePass.h): where planCoverage drafts a loop at all.
#include "pipeline/EdgePass.h"
#include "pipeline/LayoutOffers.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace fc::detail {

double averageWallPiece(const Plan& plan) {
    constexpr double kStraight = 1e-3; // sine of the turn below which a corner is no corner
    double length = 0.0;
    size_t pieces = 0;
    auto add = [&](const Ring& ring) {
        const size_t n = ring.size();
        for (size_t i = 0; i < n; ++i) {
            const Vec2 in = ring[i] - ring[(i + n - 1) % n], out = ring[(i + 1) % n] - ring[i];
            length += norm(out);
            const double lengths = norm(in) * norm(out);
            if (lengths > 0.0 &&
                (dot(in, out) < 0.0 || std::abs(cross(in, out)) > kStraight * lengths))
                ++pieces;
        }
    };
    add(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        add(obstacle);
    return pieces ? length / static_cast<double>(pieces) : 0.0;
}

bool everyRoomAsked(const PlanRequest& request) {
    if (request.rooms.empty())
        return true;
    const double floor = freeAreaOf(request.plan);
    double rooms = 0.0;
    for (const Room& room : request.plan.rooms) {
        if (std::find(request.rooms.begin(), request.rooms.end(), room.name) == request.rooms.end())
            return false;
        rooms += std::abs(signedArea(room.outline));
    }
    // A name that is no room is the planner's to report.
    for (const std::string& name : request.rooms)
        if (std::none_of(request.plan.rooms.begin(), request.plan.rooms.end(),
                         [&](const Room& room) { return room.name == name; }))
            return false;
    return rooms >= (1.0 - kEdgeRoomsCoverFloorSlack) * floor;
}

bool wantsWallLoop(const PlanRequest& request) {
    const double width = request.robot.coverageWidth;
    const bool ragged = averageWallPiece(request.plan) < kEdgeRaggedWallInWidths * width;
    // Pillars and furniture small enough to be driven round (IslandDetours.h) in a hall: the
    // first plan parts its stripes at each one, whatever its walls. Not on floors of several
    // rooms, each a piece of its own: the ward's beds drafted a loop that never won, and its
    // 0.8 s of planning became 2.2 s.
    const bool islands = request.plan.rooms.size() <= 1 &&
                         std::any_of(request.plan.obstacles.begin(), request.plan.obstacles.end(),
                                     [&](const Ring& obstacle) {
                                         return std::abs(signedArea(obstacle)) <=
                                                kEdgeIslandInWidths2 * width * width;
                                     });
    return request.wallLoop && everyRoomAsked(request) && plansAnyGraph(request.solver) &&
           request.solver != "exact" && (ragged || islands);
}

} // namespace fc::detail

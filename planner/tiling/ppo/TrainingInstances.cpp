#include "tiling/ppo/TrainingInstances.h"

#include "tiling/RandomInstances.h"
#include "tiling/TilingPlanner.h"

#include <algorithm>
#include <cmath>

namespace fc::tiling {
namespace {

Ring turned(const Ring& ring, double angle, Vec2 centre) {
    Ring result;
    const double c = std::cos(angle), s = std::sin(angle);
    for (const Vec2& p : ring) {
        const Vec2 d = p - centre;
        result.push_back({centre.x + c * d.x - s * d.y, centre.y + s * d.x + c * d.y});
    }
    return result;
}

Plan randomRoom(RandomSource& random) {
    const double w = 3.0 + 4.0 * random.uniform(), h = 3.0 + 4.0 * random.uniform();
    Plan plan;
    plan.name = "training-room";
    const int kind = random.below(3);
    if (kind == 2) { // chamfered corner: a slanted wall at 45 degrees
        const double cut = 0.8 + 0.3 * std::min(w, h) * random.uniform();
        plan.boundary = {{0, 0}, {w - cut, 0}, {w, cut}, {w, h}, {0, h}};
    } else {
        plan.boundary = {{0, 0}, {w, 0}, {w, h}, {0, h}};
    }
    if (random.uniform() < 0.5) { // a box in the middle third
        const double side = 0.4 + 0.8 * random.uniform();
        const Vec2 centre{w / 3 + w / 3 * random.uniform(), h / 3 + h / 3 * random.uniform()};
        Ring box{{centre.x - side / 2, centre.y - side / 2},
                 {centre.x + side / 2, centre.y - side / 2},
                 {centre.x + side / 2, centre.y + side / 2},
                 {centre.x - side / 2, centre.y + side / 2}};
        plan.obstacles.push_back(random.uniform() < 0.5 ? box : turned(box, M_PI / 4, centre));
    }
    if (kind == 1) { // the whole room turned by 45 degrees, as simple-diamond
        const Vec2 centre{w / 2, h / 2};
        plan.boundary = turned(plan.boundary, M_PI / 4, centre);
        for (Ring& ring : plan.obstacles)
            ring = turned(ring, M_PI / 4, centre);
    }
    return plan;
}

} // namespace

TrainingInstances::TrainingInstances(std::uint64_t seed, int rooms, int minTiles) : random_(seed) {
    TilingRequest request;
    request.tiling.nodeBudget = 200'000;
    while (static_cast<int>(rooms_.size()) < rooms) {
        request.plan = randomRoom(random_);
        OrderingProblem problem = tilePlan(request).problem;
        if (problem.size() >= std::max(minTiles, 16))
            rooms_.push_back(std::move(problem));
    }
}

OrderingProblem TrainingInstances::roomWindow(int waypoints) {
    const OrderingProblem& room = rooms_[random_.below(static_cast<int>(rooms_.size()))];
    const Vec2 centre = room.poses[random_.below(room.size())].waypoint();
    std::vector<std::pair<double, int>> byDistance;
    for (int w = 0; w < room.size(); ++w) {
        const Vec2 d = room.poses[w].waypoint() - centre;
        byDistance.emplace_back(d.x * d.x + d.y * d.y, w);
    }
    const int count = std::min(waypoints, room.size());
    std::partial_sort(byDistance.begin(), byDistance.begin() + count, byDistance.end());
    OrderingProblem window;
    window.robot = room.robot;
    for (int k = 0; k < count; ++k)
        window.poses.push_back(room.poses[byDistance[k].second]);
    std::sort(window.poses.begin(), window.poses.end(), [](const Pose& a, const Pose& b) {
        return std::make_pair(a.waypoint().y, a.waypoint().x) <
               std::make_pair(b.waypoint().y, b.waypoint().x);
    });
    return window;
}

OrderingProblem TrainingInstances::scattered(int waypoints) {
    const auto seed = static_cast<std::uint64_t>(random_.uniform() * 9007199254740992.0);
    return randomOrderingProblem(waypoints, seed);
}

} // namespace fc::tiling

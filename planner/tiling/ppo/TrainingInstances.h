// Training instances for the PPO ordering policy, drawn like the real floors but never from
// the sample plans: windows of waypoints from tiled random rooms (rectangles, some turned
// by 45 degrees or with a chamfered corner, some with a box obstacle), and, for the small
// instances of the report's gaps, the scattered tiles of tiling/RandomInstances.
#pragma once

#include "tiling/RandomSource.h"
#include "tiling/WaypointOrder.h"

#include <cstdint>
#include <vector>

namespace fc::tiling {

class TrainingInstances {
public:
    // `rooms` random rooms of at least `minTiles` tiles each.
    TrainingInstances(std::uint64_t seed, int rooms, int minTiles);
    // min(waypoints, the room's tiles) tiles of one random room around a random tile,
    // waypoint 0 the lowest, as on a real floor.
    OrderingProblem roomWindow(int waypoints);
    // Tiles of random shapes anywhere in a 6 x 6 m square (randomOrderingProblem).
    OrderingProblem scattered(int waypoints);

private:
    RandomSource random_;
    std::vector<OrderingProblem> rooms_;
};

} // namespace fc::tiling

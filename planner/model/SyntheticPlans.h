// Generated floor plans for benchmarks and tests (deterministic per seed).
#pragma once

#include "model/Plan.h"

#include <cstdint>

namespace fc {

// An office floor of about `rooms` rooms: wings of rooms on both sides of a corridor
// (0.2 m walls, 1.2 m doors), wings joined by a spine corridor, some furniture.
Plan generateOfficeFloor(int rooms, std::uint64_t seed = 1);

// A width x height hall with `obstacles` random non-overlapping boxes (the comparison case
// of polygon_coverage_planning: 150 x 100 m with 15 obstacles).
Plan generateHallWithObstacles(double width, double height, int obstacles, std::uint64_t seed = 1);

} // namespace fc

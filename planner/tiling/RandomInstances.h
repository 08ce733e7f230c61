// Small random ordering problems (tests and the report's gaps to the optimum): tiles of
// random shapes and orientations at random places in a 6 x 6 m square.
#pragma once

#include "tiling/WaypointOrder.h"

#include <cstdint>

namespace fc::tiling {

// Reproducible per seed; tiles may overlap (the ordering does not care).
OrderingProblem randomOrderingProblem(int waypoints, std::uint64_t seed,
                                      const TilingRobotProfile& robot = {});

} // namespace fc::tiling

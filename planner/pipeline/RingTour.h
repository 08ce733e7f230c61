// Internal to pipeline/: the order in which the rings visit the loops and pieces inside a
// loop (pipeline/RingsOffer.cpp).
#pragma once

#include "geometry/Geometry.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace fc::detail {

// Corners of a ring sampled when the gaps between rings are estimated.
inline constexpr std::size_t kRingTourSamples = 32;

// An order of the rings from `from`: nearest first, then improved by reversing stretches
// (2-opt on the least gaps between the rings' sampled corners; the last ring's gap to `to`
// counted where there is one). Nearest first alone crosses the floor back and forth between
// the slivers round a column.
std::vector<std::size_t> tourOrder(const std::vector<Ring>& rings, Vec2 from,
                                   std::optional<Vec2> to);

} // namespace fc::detail

// Merging and splitting rooms (issue 15: rooms found in a map are reshaped in the editor):
// plain functions on outlines, so the editor's undo commands and the tests share them.
#pragma once

#include "geometry/Geometry.h"

#include <utility>

namespace fc {

// The outline of two rooms as one: their union, which must be one piece without holes.
// Throws InputError when the rooms do not share a stretch of border (they are apart or touch
// at a point only) or when together they would enclose a hole.
Ring mergedRoomOutline(const Ring& first, const Ring& second);

// The room cut in two along the line through `from` and `to`: the part left of the line
// (looking from `from` to `to`) first. Throws InputError when the line does not cross the
// room, crosses it more than once (the cut would make three or more rooms) or cuts off a
// sliver (under 1% of the room and under 0.05 m^2).
std::pair<Ring, Ring> splitRoomOutline(const Ring& outline, Vec2 from, Vec2 to);

} // namespace fc

// The spine of a thin piece of floor: the longest path through its straight skeleton
// (CGAL), the line a robot drives to sweep a strip narrower than its head in one pass.
#pragma once

#include "geometry/Geometry.h"

namespace fc {

// The longest path, by length, through the interior nodes of the straight skeleton of the
// simple polygon `outline` (either orientation), from one end to the other. Empty where
// CGAL builds no skeleton (a degenerate outline) or it has fewer than two interior nodes
// (a triangle, a regular polygon: no line to follow).
Polyline skeletonSpine(const Ring& outline);

} // namespace fc

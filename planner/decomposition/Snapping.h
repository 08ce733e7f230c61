// Coordinate snapping in the sweep frame before the slab sweep: equal slices must be
// bit-identical, and near-vertical edges where rooms meet the walls exactly vertical.
#pragma once

#include "geometry/Geometry.h"

#include <cstddef>
#include <vector>

namespace fc::detail {

// Snaps coordinates (x, or y with `alongY`) closer than eps onto one value, rounded to a
// dyadic grid of about eps, so that near-vertical and near-horizontal edges of rotated
// rectilinear plans become exactly axis-parallel, shared slices are bit-identical, and a
// plan drawn at any rotation decomposes as the same plan drawn axis-parallel.
void snapCoordinates(std::vector<Ring*>& rings, double eps, bool alongY);

// Merges coordinates (x, or y with `alongY`) lying within eps of each other onto the most
// frequent of them, without rounding: the jitter of drawing tools and reprojections (tens of
// micrometres) leaned walls at the sweep angle and cut sliver slices. Coordinates farther
// than eps from any other keep their values (snapCoordinates' dyadic rounding, at this
// scale, would move every vertex by up to half the grid).
void mergeCloseCoordinates(std::vector<Ring*>& rings, double eps, bool alongY);

// Makes edges within `eps` of vertical (across the sweep) exactly vertical where a room's
// outline takes part: the x values joined by such edges, in any ring, become the most
// frequent of them where they all lie within eps and one is a vertex of a room (rings from
// `firstRoom` on). A traced doorway's jamb leans by a fraction of a millimetre, and a room
// cut along it ends on it at another x: the slices between them hold slivers that end
// where the room's cell would go on, and start cells of their own at every jamb (a noisy
// ward's office swept in three pieces, eight stripes for six). Walls alone keep their
// values (a slab there changes no cell, and moving them changes plans for nothing), and so
// do groups wider than eps (the vertices of a finely drawn round wall near its tangent).
void straightenNearVertical(std::vector<Ring*>& rings, std::size_t firstRoom, double eps);

} // namespace fc::detail

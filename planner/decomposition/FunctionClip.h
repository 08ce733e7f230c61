// Internal: piecewise-linear functions over x (floors and ceilings) with vertical jumps.
#pragma once

#include "geometry/Geometry.h"

namespace fc::detail {

// Value just right of x (after a jump at x) and just left of x (before it).
double rightLimit(const Polyline& f, double x);
double leftLimit(const Polyline& f, double x);
// The part of f over [xa, xb].
Polyline clipFunction(const Polyline& f, double xa, double xb);
// Appends a trapezoid side (xa, ya)-(xb, yb), inserting a jump where needed.
void appendPiece(Polyline& f, double xa, double ya, double xb, double yb);

} // namespace fc::detail

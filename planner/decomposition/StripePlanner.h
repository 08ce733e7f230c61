// Where the robot centre runs inside a cell: clear spans of stripes and traced borders.
#pragma once

#include "decomposition/Decomposition.h"
#include "geometry/Clearance.h"

namespace fc::detail {

// The clear part of the vertical line x inside the cell: at least W/2 from walls and
// W/2 inside the cell's floor and ceiling; the longest piece. Empty when none.
Interval spanAt(const Cell& cell, double x, const ClearanceField& field, double margin = 0.0);

// The robot-centre polyline along the bottom (top = false) or top of the cell's clear
// region from xa to xb (either order). Adaptive sampling keeps chords within ~W/1000 of
// the exact offset curve. Empty when the clear region is interrupted.
Polyline traceBorder(const Cell& cell, double xa, double xb, bool top, const ClearanceField& field);

// A flat head end leaves a wedge under a slanted floor or ceiling, and the outer half-column
// of a cell's first and last stripe. `path` ends at a stripe end (x, endY) on the cell's
// bottom (top = false) or top; this appends a drive half a column along that border towards
// `side` (-1 left, +1 right) and back, so the head reaches the wall there too. Appends
// nothing and returns false where the border deviates less than W/5 from the end's height
// (unless evenIfFlat), lies outside the cell, or is not clear.
bool appendStripeEndSeal(Polyline& path, const Cell& cell, double x, double endY, bool top,
                         int side, bool evenIfFlat, const ClearanceField& field, double width);

// Fills Cell::stripeSpans for every cell and Decomposition::unreachable.
void planStripeSpans(Decomposition& decomposition);

} // namespace fc::detail

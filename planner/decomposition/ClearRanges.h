// Internal: how the robot's clear region runs through one Boustrophedon cell along x.
// A cell's slice may hold no clear span (a passage narrower than W), one (the normal
// case) or several stacked ones (e.g. below and above a bed standing 0.9 m from a wall).
#pragma once

#include "decomposition/Decomposition.h"
#include "geometry/Clearance.h"

#include <limits>
#include <vector>

namespace fc::detail {

struct ClearRange {
    double x0 = 0, x1 = 0;
    int layers = 1;                // clear spans per slice; 0 = no room for the robot
    std::vector<Polyline> pinches; // layers - 1 lines between the spans, bottom to top
};

// Every clear span of the vertical line x inside the cell (W/2 from walls, inside the
// cell's floor and ceiling), bottom to top.
std::vector<Interval> spansAt(const Cell& cell, double x, const ClearanceField& field,
                              double margin = 0.0);

// Where the single stripe of a cell narrower than W goes (see ClearRanges.cpp).
// Ties go to the x nearest `preferred` (NaN: the cell's middle), e.g. where the stripe
// layout placed it to sweep a neighbour's sliver too (StripeLattice's hand-off).
double narrowStripeX(const Cell& cell, const ClearanceField& field,
                     double preferred = std::numeric_limits<double>::quiet_NaN());

// Splits [cell.x0, cell.x1] where the number of clear spans changes. Margins next to the
// cell's own ends where nothing is clear belong to the neighbouring range.
// placed: where the stripe of a cell narrower than W is placed (a lattice line), used where
// the robot fits there; NaN: the x of narrowStripeX.
std::vector<ClearRange> clearRanges(const Cell& cell, const ClearanceField& field,
                                    double placed = std::numeric_limits<double>::quiet_NaN());

} // namespace fc::detail

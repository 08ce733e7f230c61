// Internal to pipeline/: contour-parallel coverage ("rings") as one more candidate of
// planCoverage. The robot drives the wall loop at L/2, then loops inside it W further in each
// time, as long as it fits, each loop around the floor its last loop left, and the touch-ups
// sweep what no loop reached. Where the walls curve (a curved corridor, a rotunda, a floor
// wrapped round a stair well) every stripe of a boustrophedon plan is short and ends in two
// turns: a corridor of 2.1 m on an arc of 117 degrees planned 114 m with 131 turns for 47 m^2
// of floor. Chosen by estimated time like every candidate, so it stays out of rectilinear
// rooms, where the stripes turn less.
#pragma once

#include "pipeline/EdgePass.h"

#include <optional>
#include <vector>

namespace fc::detail {

// Drafted on floors up to this free area (in W^2): each loop costs buffers of the whole
// piece inside it, and a large hall is many loops.
// The faculty map (1,169 m^2 of traced walls) drafted rings for 5 s on 2 cores, beside a
// first plan of 2 s, and they lost.
inline constexpr double kRingsMaxAreaInWidths2 = 1000.0;
// ... and of at most this many wall corners (a traced map: the wall loop's draft is there).
inline constexpr std::size_t kRingsMaxCorners = 4000;

// A thin piece's loop is driven along one side only where that leaves at most this much of
// the piece (in W^2) unswept, for the touch-ups.
inline constexpr double kRingsHalfMissInWidths2 = 0.05;

// A piece is swept along its spine where the spine's swath leaves at most this share of it.
inline constexpr double kRingsSpineMissShare = 0.1;
// ... and only a piece at most this wide on average (in W) is tried.
inline constexpr double kRingsSpineMaxMeanWidth = 1.25;

// Whether planCoverage drafts rings for `request` (cheap: decided before any thread starts):
// every room asked for, a solver that plans any graph (not exact), the wall loop allowed
// (PlanRequest::wallLoop; the rings are wall loops all the way in), no sweep angle fixed by
// the user, a floor within the limits above.
bool wantsRings(const PlanRequest& request);

// The rings' paths from request.start (without one, from the wall loop's start) to
// request.end (else back to the start), every loop checked clear of the walls, in up to three
// variants (those that differ): loops only with the nearest stop next; pieces narrower than
// W swept along their spines where faster, nearest stop next; the same with the stops in a
// tour (pipeline/RingTour.h). None where the robot fits nowhere along the walls. Throws
// SolverError when cancelled.
std::vector<WallLoopDraft> draftRings(const PlanRequest& request, const SolveControl& control);

} // namespace fc::detail

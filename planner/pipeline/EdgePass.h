// Internal to pipeline/: the wall-loop offer (issue 15). The robot first drives once around
// the outer walls (geometry/WallFollowing.h), as a robot vacuum's edge mode does, then
// stripes cover what that loop's head left, each piece of it planned as a floor of its own
// (its outline is the band's smooth edge, not the ragged wall) and joined by transits.
// planCoverage drafts it beside its first plan, on walls ragged enough to be worth it.
#pragma once

#include "pipeline/Planner.h"

#include <future>
#include <optional>

namespace fc::detail {

// Pieces of floor smaller than this (in W^2) are left to the touch-ups: a floor of its own
// would cost a visit of its own.
inline constexpr double kEdgeMinPieceInWidths2 = 0.25;
// The rest's outlines are simplified by this much (in W): they are the band's edge, which
// the stripes need not follow bump by bump.
inline constexpr double kEdgeSimplifyInWidths = 0.1;
// Drafted only where the walls are ragged: a traced map's outline, whose wall pieces
// average less than this (in W). Drawn floors' walls run metres between corners. A 10 cm
// map, traced and simplified within a cell, averages 0.51 to 0.58 W (0.3 to 0.45 at 5 cm).
inline constexpr double kEdgeRaggedWallInWidths = 0.75;
// Kept planning only where driving the loop plus stripes over the rest (estimated as its
// area / W times kEdgeStripeFactor) at the robot's speed, turns not counted, takes less than
// this share of the first plan's estimated time: plans are chosen by time, and the first
// plan's turns are what the loop saves on cluttered floors. The estimate errs both ways
// (measured: 10% over on a traced hall with a corridor, 144 m drafted for 160 m estimated;
// 25% under on the real corridor map; 36% over on a hall of 96 round pillars, 2,614 m
// drafted for 3,554 m estimated), so a share below 1 stopped drafts that would have won
// (that hall: 175 m kept instead of 144 m). Compared with the first plan's length instead,
// the pillar hall drawn upright kept its first plan, 9,078 s against 5,751 s, and drawn at
// 23 degrees, whose first plan came out 3.5% longer, got the loop.
inline constexpr double kEdgeEstimateGain = 1.0;
inline constexpr double kEdgeStripeFactor = 1.5;
// Islands of the rest up to this area (in W^2) are driven round by the stripes that meet
// them (decomposition/IslandDetours.h) instead of parting them into cells.
inline constexpr double kEdgeIslandInWidths2 = 4.0;

// The loop breaks off for the rest where that is estimated to save at least this (in W)
// over driving the whole loop first.
inline constexpr double kEdgeSplitMinGainInWidths = 2.0;

struct WallLoopDraft {
    CoveragePath path; // world frame, from the start to the end
    double graphCost = 0.0;
    double lowerBound = 0.0; // the pieces' bounds added up; -1 where one has none
    int cells = 0;
};

// Rooms may leave this share of the floor outside them and still count as covering it.
inline constexpr double kEdgeRoomsCoverFloorSlack = 0.01;

// Whether `request` asks for the whole floor: no rooms named, or every room of the plan named
// where the rooms cover the floor (an imported map's rooms; the editor with every room picked).
bool everyRoomAsked(const PlanRequest& request);

// The mean length of the wall pieces of the boundary and the obstacles, m. Pieces end where
// the wall turns: a straight wall that a CAD export or an editor split into short segments is
// one piece (the ward with every wall cut every 0.2 m drafted a loop for nothing, 0.7 s of
// planning became 1.8 s).
double averageWallPiece(const Plan& plan);

// Whether planCoverage drafts a wall loop for `request`: every room asked for (a subset
// would need a loop around its walls alone), a solver that plans any graph (not exact: the
// rest's many small floors would take it to its limit), and ragged walls or, in a hall of at
// most one room, obstacles small enough to be driven round.
bool wantsWallLoop(const PlanRequest& request);

// Plans the loop from request.start (without one, from the loop's point farthest from the
// floor's centre) and the rest, to request.end (else back to the start). Each piece of the
// rest is swept as an excursion from the loop where it passes nearest the piece, back to that
// point. Where the path ends away from where the loop closes, the rest toured from one point
// of the loop (the loop's end, or a point where that is estimated shorter,
// kEdgeSplitMinGainInWidths) is drafted too, and the faster kept. `estimate` is
// set as soon as the loop is known (the estimated length, see kEdgeEstimateGain; infinity
// where the robot fits nowhere) so that the caller may cancel the rest through `control`.
// Throws InputError where it cannot be planned, SolverError when cancelled.
WallLoopDraft draftWallLoop(const PlanRequest& request, const SolveControl& control,
                            std::promise<double>& estimate);

// The draft as a plan of the floor `first` planned: its metrics over every room of it
// after the wall touch-ups, first's warnings of other kinds.
PlanResult wallLoopPlan(const PlanRequest& request, const PlanResult& first, WallLoopDraft draft);

} // namespace fc::detail

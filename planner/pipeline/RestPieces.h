// Internal to pipeline/: the pieces of floor a wall loop leaves (EdgePass.h), each prepared
// once as a floor of its own and planned from wherever the loop meets it.
#pragma once

#include "decomposition/IslandDetours.h"
#include "decomposition/WallFollowing.h"
#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

#include <memory>
#include <optional>
#include <vector>

namespace fc::detail {

// A piece's floor prepared in the layout LatticeMode::Auto picks, and in either layout for
// where the pick is close (alternative()).
struct PieceLayouts {
    std::unique_ptr<PreparedPlans> automatic, dense, own;

    PieceLayouts(const Plan& plan, const RobotProfile& robot, bool transitionCells);

    // The other layout where Auto's pick was within kPieceLayoutMargin of kDenseAutoSaving
    // (null elsewhere): the estimate behind the pick (the stripes' length) moves by several
    // percent with a piece's outline, and a rest piece's outline moves with how the plan is
    // turned (Boost's overlays start and split its rings differently). The faculty map's
    // main piece saved 27.1% upright and 24.8% turned by 180 degrees: 69 cells against 97,
    // 5,194 s against 5,379 s for the whole map.
    const PreparedPlans* alternative(const Decomposition& chosen) const;
};

// What planning a piece of the rest needs whatever its start and end: the piece as a floor
// of its own and its plans prepared per angle, built once and shared by both drafts (each
// then only runs the solver; the second draft had cost the faculty map 1.2 -> 1.5 s).
struct PreparedPiece {
    PlanRequest request; // without start and end
    IslandDetours islands;
    std::unique_ptr<PieceLayouts> open; // the islands left out (where there are any)
    std::unique_ptr<PieceLayouts> full;
};

std::vector<PreparedPiece> preparedPieces(const PlanRequest& request, const WallLoop& walls);

// Plans one piece of the rest as a floor of its own, from the point of it nearest `from`
// to the point nearest `towards`, in both layouts where Auto's pick is close (the better
// kept). Empty where the robot fits nowhere in it.
std::optional<PlanResult> planPiece(const PlanRequest& request, const WallLoop& walls,
                                    const PreparedPiece& prepared, size_t index, Vec2 from,
                                    Vec2 towards, const SolveControl& control);

} // namespace fc::detail

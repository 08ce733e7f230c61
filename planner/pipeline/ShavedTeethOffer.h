// Internal to pipeline/: the floor planned with its wall teeth cut back (model/WallTeeth.h)
// as one more candidate of planCoverage. A pilaster 5 cm deep on the walls of a 12 x 9 m room
// cost 8% more time (its corners start cells and break the headland band), although the
// stripes W/2 from the wall pass it with room to spare.
#pragma once

#include "pipeline/Planner.h"

#include <optional>

namespace fc::detail {

// Teeth up to this share of (W - L) / 2 deep are cut: a stripe W/2 from the wall line keeps
// L/2 from a tooth's face with a margin.
inline constexpr double kToothDepthShare = 0.9;
// ... and up to this many coverage widths long (a radiator, a door frame).
inline constexpr double kToothSpanInWidths = 1.5;

// The request for the floor with its teeth cut back, where it has some and `request` allows
// it (PlanRequest::shaveTeeth; not on ragged traced walls, whose wall loop runs L/2 from
// every tooth); empty where there is nothing to offer. Cheap: decided before any thread
// starts.
struct ShavedTeethRequest {
    PlanRequest request; // shaveTeeth and wallLoop off
    int teeth = 0;
    double depth = 0.0; // m
};
std::optional<ShavedTeethRequest> shavedTeethRequest(const PlanRequest& request);

// Its plan (PlanResult::shavedTeeth set); empty where it cannot be planned. Its metrics are
// still those of the shaved floor (keepShavedTeethPlan). Runs beside the first plan;
// cancellation is rethrown.
std::optional<PlanResult> planShavedTeeth(const ShavedTeethRequest& flat,
                                          const SolveControl& control);

// Whether that plan's path keeps L/2 from the walls as drawn; if so its metrics become those
// of the floor as drawn (measured as `first`'s) and its coverage warnings follow them.
bool keepShavedTeethPlan(const PlanRequest& request, const PlanResult& first, PlanResult& shaved);

} // namespace fc::detail

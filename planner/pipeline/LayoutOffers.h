// Internal to pipeline/: the other stripe layouts planCoverage offers beside its first plan
// (the corner lattice, the dense lattice, headlands), and what they share with Planner.cpp.
#pragma once

#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

#include <string>
#include <vector>

namespace fc::detail {

// Solvers that plan whatever corner graph they are given (not learnt on one, not bound to
// their own decomposition).
bool plansAnyGraph(const std::string& solver);

// The plan at one sweep angle for the whole floor (Planner.cpp), without touch-ups.
PlanResult planOneAngle(const PlanRequest& request, double angle, const SolveControl& control,
                        const PreparedPlans* prepared);

// Plans the layouts that may beat `first` (each with its touch-ups); the caller keeps the
// best (choosePlan). Layouts that cannot be planned (an InputError, a solver's limit) are
// left out; cancellation is rethrown.
std::vector<PlanResult> planLayoutOffers(const PlanRequest& request, const PlanResult& first,
                                         const SolveControl& control,
                                         const PreparedPlans& prepared);

} // namespace fc::detail

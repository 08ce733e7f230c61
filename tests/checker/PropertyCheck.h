// One plan through fc::planCoverage and the independent checker, with the verdicts of the
// issue 13 properties (shared by property_tests and floorcover-property-bench):
//   (a) collision-free: every waypoint in the free space, clearance >= L/2 - 1e-3 L;
//   (b) the checker's coverage >= 99.5 % of its sweepable area, or the planner's
//       metrics.uncoveredArea within 0.2 % of the floor area of the checker's uncovered
//       area (a loss the planner reports);
//   (c) no exception but fc::InputError with a message, and no run longer than the limit.
#pragma once

#include "PathChecker.h"
#include "pipeline/Planner.h"

#include <string>

namespace fcgen {

constexpr double kRequiredCoverage = 0.995;
constexpr double kUncoveredAgreement = 0.002; // of the floor area
constexpr double kSecondsPerPlan = 30.0;      // a longer plan counts as a hang

// W = 1, L = 0.6, D = 1, solver heuristic, every room, the request's default sweep.
fc::PlanRequest defaultRequest(const fc::Plan& plan);

struct Outcome {
    bool planned = false;      // planCoverage returned
    bool inputError = false;   // planCoverage threw fc::InputError
    bool otherError = false;   // it threw anything else
    std::string error;         // the exception's message (and type, for other errors)
    double seconds = 0.0;      // planCoverage wall time (the checker's is not counted)
    double checkSeconds = 0.0; // the checker's wall time
    fc::Metrics metrics;       // when planned
    std::vector<std::string> warnings;
    fccheck::Report check; // when planned

    bool collisionFree = false; // (a)
    bool covers = false;        // (b), first half
    bool reportsLoss = false;   // (b), second half
    bool inTime = false;        // (c), time limit
    // (a), (b) and (c) together; an InputError with a message passes (c) and has nothing
    // for (a) and (b) to check.
    bool passed() const;
    // One line of the figures for failure messages and the bench.
    std::string summary() const;
};

// Plans `request` and checks the path against request.plan (all rooms: the whole floor).
Outcome planAndCheck(const fc::PlanRequest& request);

} // namespace fcgen

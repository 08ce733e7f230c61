#include "PropertyCheck.h"

#include "PlanGenerator.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <typeinfo>

namespace fcgen {

fc::PlanRequest defaultRequest(const fc::Plan& plan) {
    fc::PlanRequest r;
    r.plan = plan;
    r.solver = "heuristic";
    r.robot.robotDiameter = 0.6;
    r.robot.coverageWidth = 1.0;
    r.robot.cleaningDiameter = 1.0;
    return r;
}

bool Outcome::passed() const {
    if (otherError)
        return false;
    if (inputError)
        return !error.empty();
    return collisionFree && (covers || reportsLoss) && inTime;
}

std::string Outcome::summary() const {
    char buf[640];
    if (!planned) {
        std::snprintf(buf, sizeof buf, "%s after %.2f s: %s",
                      inputError ? "InputError" : "exception", seconds, error.c_str());
        return buf;
    }
    std::snprintf(buf, sizeof buf,
                  "coverage checker %.2f%% (covered %.2f of sweepable %.2f m^2, floor %.2f, "
                  "uncovered %.2f, unreachable %.2f), planner coverage %.2f%% "
                  "uncovered %.2f unreachable %.2f m^2; clearance %.4f m%s; length %.1f m, "
                  "%d turns, %.2f s (+%.2f s check), %zu warnings",
                  100.0 * check.coverage, check.coveredArea, check.sweepableArea, check.floorArea,
                  check.uncoveredArea, check.unreachableArea, 100.0 * metrics.coverage,
                  metrics.uncoveredArea, metrics.unreachableArea, check.clearance.minimum,
                  check.clearance.inside ? "" : " (waypoint outside)", metrics.length,
                  metrics.turns, seconds, checkSeconds, warnings.size());
    return buf;
}

Outcome planAndCheck(const fc::PlanRequest& request) {
    Outcome out;
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    // A deadline for the solver: past it the run is a hang whatever it returns.
    fc::SolveControl control;
    control.cancelled = [t0] {
        return std::chrono::duration<double>(Clock::now() - t0).count() > 2.0 * kSecondsPerPlan;
    };
    fc::PlanResult result;
    try {
        result = fc::planCoverage(request, control);
        out.planned = true;
    } catch (const fc::InputError& e) {
        out.inputError = true;
        out.error = e.what();
    } catch (const std::exception& e) {
        out.otherError = true;
        out.error = std::string(typeid(e).name()) + ": " + e.what();
    } catch (...) {
        out.otherError = true;
        out.error = "a non-standard exception";
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    out.inTime = out.seconds <= kSecondsPerPlan;
    if (!out.planned)
        return out;
    out.metrics = result.metrics;
    out.warnings = result.warnings;
    const auto t1 = Clock::now();
    const double L = request.robot.robotDiameter, W = request.robot.coverageWidth;
    out.check =
        fccheck::checkPath(freeSpaceOf(request.plan), {}, polylineOf(result.path.points), L, W);
    out.checkSeconds = std::chrono::duration<double>(Clock::now() - t1).count();
    out.collisionFree = out.check.collisionFree;
    out.covers = out.check.coverage >= kRequiredCoverage;
    out.reportsLoss = std::abs(out.metrics.uncoveredArea - out.check.uncoveredArea) <=
                      kUncoveredAgreement * out.check.floorArea;
    return out;
}

} // namespace fcgen

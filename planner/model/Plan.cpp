#include "model/Plan.h"

#include <cmath>
#include <sstream>

namespace fc {

double freeAreaOf(const Plan& plan) {
    double area = ringArea(plan.boundary);
    for (const Ring& obstacle : plan.obstacles)
        area -= ringArea(obstacle);
    return area;
}

void RobotProfile::validate() const {
    auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
    std::ostringstream msg;
    // W first: a width of 0 also lowers L to it, and the message should name what was given.
    if (!finitePositive(coverageWidth))
        msg << "coverage width W must be a positive number (got " << coverageWidth << ")";
    else if (!finitePositive(robotDiameter))
        msg << "robot diameter L must be a positive number (got " << robotDiameter << ")";
    else if (!finitePositive(cleaningDiameter))
        msg << "cleaning diameter D must be a positive number (got " << cleaningDiameter << ")";
    else if (!finitePositive(speed))
        msg << "speed must be a positive number (got " << speed << ")";
    else if (!std::isfinite(turnTime) || turnTime < 0.0)
        msg << "turn time must be zero or positive (got " << turnTime << ")";
    else if (robotDiameter > coverageWidth + 1e-12)
        msg << "robot diameter L = " << robotDiameter
            << " m exceeds coverage width W = " << coverageWidth << " m (need L <= W <= D)";
    else if (coverageWidth > cleaningDiameter + 1e-12)
        msg << "coverage width W = " << coverageWidth
            << " m exceeds cleaning diameter D = " << cleaningDiameter << " m (need L <= W <= D)";
    else if (coverageWidth > 1000.0)
        msg << "coverage width W = " << coverageWidth << " m is not a plausible robot size";
    // Beyond these the estimated time overflows or means nothing ("time": null in the
    // metrics for a speed of 1e-308 m/s).
    else if (speed < 1e-3 || speed > 100.0)
        msg << "speed " << speed << " m/s is not a plausible robot speed (0.001 to 100 m/s)";
    else if (turnTime > 3600.0)
        msg << "turn time " << turnTime << " s is not plausible (at most an hour per turn)";
    if (!msg.str().empty())
        throw InputError(msg.str());
}

} // namespace fc

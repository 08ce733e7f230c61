// Internal to plan validation: the shared length tolerance and message formatting.
#pragma once

#include "model/Plan.h"

#include <string>

namespace fc::validation {

// Length tolerance for a plan: 1e-9 of its size, but never below the rounding noise of
// its coordinates (UTM-sized values carry ~1e-9 m of it). Non-finite values are ignored.
double planTolerance(const Plan& plan);

// Finite coordinates, at least 3 distinct vertices, no repeated consecutive vertex, not
// all on one line. `name` names the ring in the message ("obstacle 3").
void checkRingShape(const Ring& ring, const std::string& name, double tolerance);

std::string formatNumber(double value); // "4.0", "12.5", "0.125"
std::string formatPoint(Vec2 p);        // "(12.5, 4.0)"
std::string formatArea(double area);    // "2.50 m^2"

} // namespace fc::validation

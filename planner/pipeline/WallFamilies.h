// Wall families: the directions a plan's walls run in, which the sweep angles follow.
#pragma once

#include "model/Plan.h"

#include <vector>

namespace fc {

struct WallFamily {
    double angleDeg = 0.0; // in [0, 90): a wall and its normal are one family
    double length = 0.0;   // metres of wall within half a degree of the family's bin
};

// The plan's wall families, strongest first (walls of the boundary, obstacles and rooms vote
// with their length), families within 2 degrees of a stronger one left out; at most
// `families` of them.
std::vector<WallFamily> wallFamilies(const Plan& plan, int families);

// The directions of wallFamilies, strongest first.
std::vector<double> dominantWallAngles(const Plan& plan, int families);

// Sweep angles tried by "auto": along and across the two dominant wall families, 90, 0.
std::vector<double> candidateAngles(const Plan& plan);

} // namespace fc

// Wall teeth: short, shallow bumps of a wall into the floor (a pilaster, a radiator, a door
// frame, a traced wall's speck). A stripe W/2 from the wall passes a tooth up to (W - L)/2
// deep with L/2 to spare, yet the tooth's corners start cells and break the bands along the
// wall, which costs turns. shaveWallTeeth gives the floor with such teeth cut back to their
// wall's line, for planning a candidate that must still be checked against the real walls.
#pragma once

#include "model/Plan.h"

namespace fc {

struct ShavedTeeth {
    Plan plan;         // the plan with the teeth cut back (rooms unchanged)
    int teeth = 0;     // how many were cut
    double area = 0.0; // floor they added, m^2
};

// Teeth at most maxDepth deep (off their wall's line) and maxSpan long (along it), on a
// straight wall: the ring's vertices before and after the tooth lie on the line through its
// ends. Only floor is added: every vertex cut lies on the floor's side of that line, over the
// line between the tooth's ends. A plan whose shaved rings would not be simple keeps them as
// they are.
ShavedTeeth shaveWallTeeth(const Plan& plan, double maxDepth, double maxSpan);

} // namespace fc

// Joins parts of the corner graph that the cell adjacencies leave apart although the robot
// can drive between them (a door beside an obstacle, a slanted passage whose cells meet
// only at a point): cells are unreachable only when the disc cannot get there.
#pragma once

#include "geometry/Clearance.h"
#include "graph/CornerGraph.h"

#include <vector>

namespace fc {

// The connected component of every node (0 .. count-1), by breadth-first search.
std::vector<int> graphComponents(const CornerGraph& graph, int& count);

// Adds a collision-free inter edge from each component with corners of reachable cells to
// the rest, between the nearest corners a clear path joins. Returns the edges added.
int bridgeComponents(CornerGraph& graph, const ClearanceField& field);

} // namespace fc

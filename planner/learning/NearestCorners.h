// The k nearest corners of every corner, for the graph network's message rounds
// (learning/torch/DqnNetwork). An R-tree (Boost.Geometry) instead of all pairwise distances:
// a 1,500-cell floor has thousands of valid corners at every step of a rollout.
#pragma once

#include <vector>

namespace fc {

struct NearestCorners {
    std::vector<int> index;    // corners x k: the corner itself first, then by distance
    double meanDistance = 0.0; // over the neighbours other than the corner itself (0: none)
};

// xy: x0, y0, x1, y1, ... (n corners). Fewer than k corners: each row is filled up with the
// corner itself. Deterministic: the same input gives the same neighbours, ties included.
NearestCorners nearestCorners(const float* xy, int n, int k);

} // namespace fc

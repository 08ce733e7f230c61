// Buckets of waypoints by the robot's centre of mass, to find the cheapest moves without
// scanning every pair. Eq. 1 bounds a move's energy from below by the total mass times
// the distance its centre of mass travels, so a ring search can stop early and exactly.
#pragma once

#include "tiling/WaypointOrder.h"

#include <vector>

namespace fc::tiling {

class WaypointIndex {
public:
    explicit WaypointIndex(const OrderingProblem& problem);

    void remove(int waypoint);
    bool empty() const { return remaining_ == 0; }
    // The cheapest move from `from` to a waypoint still in the index; -1 when empty.
    int cheapestFrom(int from) const;
    // Up to `count` cheapest moves from `from` (excluding itself), cheapest first.
    std::vector<int> cheapestMoves(int from, int count) const;

private:
    int bucketOf(int waypoint) const;
    // Visits the buckets at Chebyshev ring r around the bucket (bx, by).
    template <class Visit> void visitRing(int bx, int by, int r, Visit&& visit) const;

    const OrderingProblem& problem_;
    std::vector<Vec2> centres_;
    double cellSize_ = 1.0;
    double minX_ = 0.0, minY_ = 0.0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> buckets_;
    std::vector<int> slot_; // position of each waypoint in its bucket, -1 once removed
    int remaining_ = 0;
    double totalMass_ = 1.0;
};

} // namespace fc::tiling

// Spatial index over wall segments (Boost.Geometry R-tree) for clearance queries.
#pragma once

#include "geometry/Geometry.h"

#include <memory>
#include <vector>

namespace fc {

class SegmentIndex {
public:
    SegmentIndex();
    explicit SegmentIndex(const std::vector<Ring>& rings);
    ~SegmentIndex();
    SegmentIndex(SegmentIndex&&) noexcept;
    SegmentIndex& operator=(SegmentIndex&&) noexcept;

    void build(const std::vector<Ring>& rings);
    const std::vector<Segment>& segments() const { return segments_; }

    // Indices of segments whose bounding box meets the box.
    void query(const BoundingBox& box, std::vector<int>& out) const;
    // Distance from a point to the nearest wall (infinity when there are none).
    double distanceToWalls(Vec2 p) const;
    // Smallest distance from the segment ab to any wall.
    double segmentClearance(Vec2 a, Vec2 b) const;
    // True when every wall is at least d away from p (one box query, early exit).
    bool pointKeepsDistance(Vec2 p, double d) const;
    // True when every wall is at least d away from the segment ab (fast: one box query,
    // stops at the first wall that is closer).
    bool segmentKeepsDistance(Vec2 a, Vec2 b, double d) const;
    // Smallest distance from any piece of the polyline to any wall.
    double polylineClearance(const Polyline& line) const;

private:
    struct Tree;
    std::vector<Segment> segments_;
    std::unique_ptr<Tree> tree_;
};

} // namespace fc

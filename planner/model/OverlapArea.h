// Internal to plan validation: the area shared by two regions given by their boundary
// edges, without building the intersection polygon (Green's theorem over the boundary
// pieces of one region inside the other). Floating point, with a length tolerance for
// edges that run along each other (rooms drawn along walls are the normal case).
#pragma once

#include "geometry/Geometry.h"

#include <functional>
#include <vector>

namespace fc::overlap {

// A boundary edge oriented with the region's interior on its left.
struct DirectedEdge {
    Vec2 a, b;
};

std::vector<DirectedEdge> edgesOf(const Ring& ring, bool interiorOnLeft = true);

// Even-odd point location against many edges, bucketed into horizontal bands so that a
// query only looks at the edges spanning its y.
class EvenOddIndex {
public:
    explicit EvenOddIndex(const std::vector<DirectedEdge>& edges);
    bool contains(Vec2 p) const;

private:
    std::vector<DirectedEdge> edges_;
    std::vector<std::vector<int>> bands_;
    double minY_ = 0.0, maxY_ = -1.0, bandHeight_ = 1.0;
};

struct OverlapResult {
    double area = 0.0;
    Vec2 sample; // a point on the boundary of the shared part
    bool hasSample = false;
};

// Area of A ∩ B. edgesA: all edges of A; edgesB: the edges of B near A (at least all that
// intersect A's bounding box); insideA/insideB: point location. `origin` is a point near
// the plan that keeps the shoelace sums precise at UTM-sized coordinates.
OverlapResult overlapArea(const std::vector<DirectedEdge>& edgesA,
                          const std::function<bool(Vec2)>& insideA,
                          const std::vector<DirectedEdge>& edgesB,
                          const std::function<bool(Vec2)>& insideB, Vec2 origin, double tolerance);

} // namespace fc::overlap

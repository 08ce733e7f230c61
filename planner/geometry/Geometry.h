// Plain value types for planar geometry: points, rings, polygons with holes.
// Everything in the planner core is in metres, +x right, +y up.
#pragma once

#include <cmath>
#include <vector>

namespace fc {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    Vec2() = default;
    Vec2(double x_, double y_) : x(x_), y(y_) {}
    Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
    Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
    Vec2 operator*(double s) const { return {x * s, y * s}; }
    bool operator==(Vec2 o) const { return x == o.x && y == o.y; }
    bool operator!=(Vec2 o) const { return !(*this == o); }
};

inline double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
inline double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
// sqrt, not hypot: coordinates are metres near the origin, and hypot is several times slower.
inline double norm(Vec2 a) {
    return std::sqrt(a.x * a.x + a.y * a.y);
}
inline double distance(Vec2 a, Vec2 b) {
    return norm(a - b);
}

// A closed ring; the closing vertex is NOT repeated.
using Ring = std::vector<Vec2>;
using Polyline = std::vector<Vec2>;

struct Interval {
    double lo = 0, hi = 0;
    double length() const { return hi - lo; }
    bool empty() const { return !(hi >= lo); }
};

struct Segment {
    Vec2 a;
    Vec2 b;
};

struct BoundingBox {
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    void add(Vec2 p) {
        minX = std::min(minX, p.x);
        minY = std::min(minY, p.y);
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    bool empty() const { return minX > maxX; }
    double width() const { return maxX - minX; }
    double height() const { return maxY - minY; }
};

double signedArea(const Ring& ring);
double ringArea(const Ring& ring); // absolute value
double polylineLength(const Polyline& line);
// Turns of a polyline (SPEC sect. 6): interior vertices where the heading changes by >= 45
// degrees; segments of 1 nm or less carry no heading.
int countTurns(const Polyline& points);
BoundingBox boundsOf(const Ring& ring);
bool pointInRing(const Ring& ring, Vec2 p); // even-odd, boundary undefined
double pointSegmentDistance(Vec2 p, Vec2 a, Vec2 b);
double segmentSegmentDistance(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
// Where to write a name inside `outline` and outside `holes`: its area centroid where that
// is at least a fifth of the way to the best from every edge, else the point farthest from
// every edge that a grid search finds (an L-shaped room's centroid lies outside it, a room
// drawn round a pillar has it in the pillar). Holes are ignored beyond the outline's box.
Vec2 interiorLabelPoint(const Ring& outline, const std::vector<Ring>& holes = {});

// A rigid transform used to work in the "sweep frame": the plan is shifted to a
// local origin (so UTM-sized coordinates keep full precision) and rotated so that
// stripes run along +y (the slice sweeps along +x).
class Frame {
public:
    Frame() = default;
    // stripeAngleDeg: direction of the stripes in the world frame (90 = vertical).
    Frame(Vec2 origin, double stripeAngleDeg);

    Vec2 toLocal(Vec2 world) const;
    Vec2 toWorld(Vec2 local) const;
    Ring toLocal(const Ring& ring) const;
    Polyline toWorld(const Polyline& line) const;
    Vec2 origin() const { return origin_; }
    double stripeAngleDeg() const { return angleDeg_; }

private:
    Vec2 origin_;
    double angleDeg_ = 90.0;
    double c_ = 1.0, s_ = 0.0; // rotation world->local
};

} // namespace fc

// An independent checker of coverage paths (issue 13, item 6): Boost.Geometry only, no code
// or header of the planner. It answers two questions about a robot-centre polyline on a
// floor plan:
//   - is it collision-free for a disc robot of diameter L (centre at least L/2 from every
//     wall, every waypoint inside the free space)?
//   - how much of the area that such a disc can sweep with a W-wide head does it sweep?
//
// Model (SPEC sect. 1 and 6):
//   free       = outer ring minus the holes;
//   required   = free ∩ union(required rings) (no rings: the whole free space);
//   centres    = erode(free, L/2) (negative round buffer), every connected part (checkPath;
//                a part the start cannot reach is uncovered, not excused);
//   sweepable  = required ∩ dilate(centres, W/2) (round buffer);
//   swath      = the path's stroke with a head of width W held across the direction of
//                travel: per segment the W-wide rectangle with flat ends (Boost's buffer of
//                that segment with end_flat), at each turn the mitre wedge on the outer side
//                (join_miter; bevelled beyond a mitre limit of 2 W, as the planner's metrics
//                do), and a W x W/2 square cap beyond each end of the path (Boost has no
//                square end strategy: end_flat stops at the end point, end_round would add
//                half discs; SPEC's "square path ends" means the W/2 square caps);
//   covered    = swath ∩ sweepable (area outside the sweepable region does not count);
//   uncovered  = sweepable - covered; unreachable = area(required) - sweepable.
//
// Areas: the regions (free, required, sweepable) are Boost.Geometry polygons (difference,
// union, intersection, round buffers), measured with bg::area. The swath ∩ sweepable area
// is measured by a scanline over those polygons and the swath's convex pieces, rows 5 mm
// apart, each row cut exactly (see PathChecker.cpp for why not Boost's union of the
// pieces: it fails on real paths), and scaled so that the rows' measure of the sweepable
// region equals its exact area. Accuracy on the unit tests: 1e-9 m^2 on axis-parallel
// swaths, 0.05 % on rotated random walks.
// Circles are approximated by kPointsPerCircle-gons. All computation happens in a frame
// shifted to the first vertex of the outer ring, so UTM-sized coordinates (5e6 m) keep
// their precision; inputs and reported points are in the caller's coordinates.
#pragma once

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace fccheck {

using XY = std::pair<double, double>;
// A ring: at least three vertices, any orientation; the closing vertex may or may not be
// repeated.
using RingXY = std::vector<XY>;
using PolylineXY = std::vector<XY>;

struct FreeSpace {
    RingXY outer;
    std::vector<RingXY> holes;
};

// Collision tolerance: a path is collision-free when its clearance is at least
// L/2 - kClearanceTolerance * L (0.6 mm for a 0.6 m robot).
constexpr double kClearanceTolerance = 1e-3;
// Vertices of the polygons that stand for circles (round joins of the buffers).
constexpr int kPointsPerCircle = 90;
// Mitre limit of the swath's joins, in half widths (2 W).
constexpr double kMitreLimit = 4.0;

struct Clearance {
    double minimum = std::numeric_limits<double>::infinity(); // path to nearest wall, m
    bool inside = true;            // every waypoint inside the free space or on its boundary
    std::size_t segment = 0;       // index of the path segment closest to a wall
    XY nearestWallPoint{};         // a point of that wall near the closest approach
    std::size_t outsideVertex = 0; // first waypoint outside the free space, when !inside
};

// Smallest distance from any point of the path (vertices and segments) to any wall (edges
// of the outer ring and of the holes), and whether every waypoint is inside the free space.
// A path of one point is measured as that point; an empty path has infinite clearance.
Clearance minimumClearance(const FreeSpace& free, const PolylineXY& path);

// inside && minimum >= L/2 - kClearanceTolerance * L.
bool isCollisionFree(const Clearance& clearance, double robotDiameter);

// Area of free ∩ required.
double floorArea(const FreeSpace& free, const std::vector<RingXY>& required);

// Area of the sweepable region (see above). `start`: the robot's start; only the part of the
// eroded free space connected to it counts. nullptr: every part counts.
double sweepableArea(const FreeSpace& free, const std::vector<RingXY>& required,
                     double robotDiameter, double coverageWidth, const XY* start = nullptr);

// Area of the path's swath inside the sweepable region (start: the path's first point).
double coveredArea(const PolylineXY& path, double coverageWidth, const FreeSpace& free,
                   const std::vector<RingXY>& required, double robotDiameter);

// Area of the swath itself (no clipping), for tests of the stroke model.
double swathArea(const PolylineXY& path, double coverageWidth);

struct Report {
    double floorArea = 0.0;       // m^2, free ∩ required
    double sweepableArea = 0.0;   // m^2
    double coveredArea = 0.0;     // m^2, swath ∩ sweepable
    double uncoveredArea = 0.0;   // m^2, sweepable - covered
    double unreachableArea = 0.0; // m^2, floor - sweepable
    double coverage = 1.0;        // covered / sweepable (1 when nothing is sweepable)
    int centreComponents = 0;     // connected parts of the eroded free space
    Clearance clearance;
    bool collisionFree = false;
};

// Everything above in one pass (the regions are computed once).
Report checkPath(const FreeSpace& free, const std::vector<RingXY>& required, const PolylineXY& path,
                 double robotDiameter, double coverageWidth);

} // namespace fccheck

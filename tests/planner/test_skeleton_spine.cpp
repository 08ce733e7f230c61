// The spine of a thin piece (CGAL's straight skeleton) and what a swath along it leaves
// (Boost.Geometry), as the rings sweep a corridor's middle (pipeline/RingsOffer.cpp).
#include "geometry/SkeletonSpine.h"
#include "geometry/SwathReach.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace fc;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Local (u along, v across) to world: turned by `degrees`, shifted to UTM-sized coordinates.
Vec2 placed(Vec2 local, double degrees) {
    const double a = degrees * kPi / 180.0;
    return {512345.0 + local.x * std::cos(a) - local.y * std::sin(a),
            5412345.0 + local.x * std::sin(a) + local.y * std::cos(a)};
}

Ring placedRing(const Ring& local, double degrees) {
    Ring out;
    for (const Vec2& p : local)
        out.push_back(placed(p, degrees));
    return out;
}

double distanceToLine(const Polyline& line, Vec2 p) {
    double nearest = INFINITY;
    for (size_t i = 1; i < line.size(); ++i)
        nearest = std::min(nearest, pointSegmentDistance(p, line[i - 1], line[i]));
    return nearest;
}

} // namespace

TEST(SkeletonSpine, AThinStripHasItsCentreLine) {
    for (const double degrees : {0.0, 33.0, 90.0}) {
        const Ring strip = placedRing({{0, 0}, {10, 0}, {10, 0.8}, {0, 0.8}}, degrees);
        const Polyline spine = skeletonSpine(strip);
        ASSERT_GE(spine.size(), 2u) << degrees;
        // The skeleton's inner nodes of a rectangle: its long axis, 0.4 in from each end.
        EXPECT_NEAR(polylineLength(spine), 9.2, 1e-6) << degrees;
        for (const Vec2& p : spine)
            EXPECT_NEAR(distanceToLine({placed({0, 0.4}, degrees), placed({10, 0.4}, degrees)}, p),
                        0.0, 1e-6)
                << degrees;
        // Clockwise outlines give the same line.
        EXPECT_NEAR(polylineLength(skeletonSpine(Ring(strip.rbegin(), strip.rend()))), 9.2, 1e-6);
    }
}

TEST(SkeletonSpine, AnLShapedStripIsFollowedRoundItsCorner) {
    // Arms 8 m and 5 m long, 0.6 m wide: the spine runs from one arm's end to the other's.
    const Ring bend{{0, 0}, {8, 0}, {8, 5}, {7.4, 5}, {7.4, 0.6}, {0, 0.6}};
    const Polyline spine = skeletonSpine(bend);
    ASSERT_GE(spine.size(), 3u);
    const Vec2 a = spine.front(), b = spine.back();
    const bool alongX = a.x < b.x;
    const Vec2 west = alongX ? a : b, north = alongX ? b : a;
    EXPECT_NEAR(west.x, 0.3, 1e-6);
    EXPECT_NEAR(west.y, 0.3, 1e-6);
    EXPECT_NEAR(north.x, 7.7, 1e-6);
    EXPECT_NEAR(north.y, 4.7, 1e-6);
    // Along both arms' centre lines: never more than half the width from either.
    for (const Vec2& p : spine)
        EXPECT_LE(std::min(std::abs(p.y - 0.3), std::abs(p.x - 7.7)), 1e-6);
}

TEST(SkeletonSpine, NoLineWhereThereIsNoneToFollow) {
    // A triangle's skeleton meets in one node; a bow tie is no simple polygon; a ring too
    // short to be a polygon.
    EXPECT_TRUE(skeletonSpine({{0, 0}, {4, 0}, {2, 3}}).empty());
    EXPECT_TRUE(skeletonSpine({{0, 0}, {4, 4}, {4, 0}, {0, 4}}).empty());
    EXPECT_TRUE(skeletonSpine({{0, 0}, {4, 0}}).empty());
}

TEST(SwathReach, AStripDownTheMiddleLeavesBothEdges) {
    // A 10 x 2 m floor, a line down its middle, a head reaching 0.5 m either side: two edges
    // 10 x 0.5 m are left, whatever the turn and offset.
    for (const double degrees : {0.0, 57.0}) {
        const Ring floor = placedRing({{0, 0}, {10, 0}, {10, 2}, {0, 2}}, degrees);
        const Polyline middle{placed({0, 1}, degrees), placed({10, 1}, degrees)};
        const SwathLeftovers left = swathLeftovers(floor, {}, middle, 0.5, 1.0);
        EXPECT_NEAR(left.area, 10.0, 0.01) << degrees;
        ASSERT_EQ(left.parts.size(), 2u) << degrees;
        for (const FloorPart& part : left.parts)
            EXPECT_NEAR(ringArea(part.outline), 5.0, 0.01) << degrees;
        // Parts below the minimum are counted, not returned.
        const SwathLeftovers small = swathLeftovers(floor, {}, middle, 0.5, 6.0);
        EXPECT_TRUE(small.parts.empty());
        EXPECT_NEAR(small.area, 10.0, 0.01);
        // Reaching the walls, nothing is left.
        EXPECT_NEAR(swathLeftovers(floor, {}, middle, 1.0, 0.0).area, 0.0, 1e-6);
    }
}

TEST(SwathReach, AHoleIsNoFloorToLeave) {
    const Ring floor{{0, 0}, {10, 0}, {10, 2}, {0, 2}};
    const Ring pillar{{4, 0.1}, {5, 0.1}, {5, 0.4}, {4, 0.4}}; // in the lower edge
    const SwathLeftovers left = swathLeftovers(floor, {pillar}, {{0, 1}, {10, 1}}, 0.5, 0.0);
    EXPECT_NEAR(left.area, 10.0 - 0.3, 0.01);
}

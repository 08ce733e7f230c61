// The independent checker on cases computed by hand: a 10 x 10 m room, straight paths,
// a full boustrophedon, a hole, a door too narrow for the robot, UTM-sized coordinates.
#include "PathChecker.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace fccheck;

namespace {

constexpr double kPi = 3.14159265358979323846;
// The swath is measured row by row (exact along rows): exact on axis-parallel swaths.
constexpr double kSwathTolerance = 1e-9;
// Circles are 90-gons: an inscribed 90-gon misses 0.08 % of a disc's area.
constexpr double kArcTolerance = 2e-3;

RingXY square(double x0, double y0, double size) {
    return {{x0, y0}, {x0 + size, y0}, {x0 + size, y0 + size}, {x0, y0 + size}};
}

FreeSpace room10() {
    return {square(0, 0, 10), {}};
}

// Vertical stripes x = 0.5, 1.5, ..., 9.5 from y = 0.5 to 9.5, joined at the ends.
PolylineXY boustrophedon(double dx = 0.0, double dy = 0.0) {
    PolylineXY path;
    for (int i = 0; i < 10; ++i) {
        const double x = 0.5 + i + dx;
        const bool up = i % 2 == 0;
        path.push_back({x, (up ? 0.5 : 9.5) + dy});
        path.push_back({x, (up ? 9.5 : 0.5) + dy});
    }
    return path;
}

} // namespace

TEST(Checker, SquareRoomAreas) {
    // L = 0.6: the eroded room is [0.3, 9.7]^2; its corners are 0.42 m from the room's
    // corners, within W/2 = 0.5 m, so the whole room is sweepable.
    EXPECT_NEAR(floorArea(room10(), {}), 100.0, 1e-9);
    EXPECT_NEAR(sweepableArea(room10(), {}, 0.6, 1.0), 100.0, 1e-9);
    // L = W = 1: each corner keeps the part of [0, 0.5]^2 outside the quarter disc of
    // radius 0.5 about (0.5, 0.5): 0.25 - pi / 16.
    const double expected = 100.0 - 4.0 * (0.25 - kPi / 16.0);
    EXPECT_NEAR(sweepableArea(room10(), {}, 1.0, 1.0), expected, kArcTolerance);
}

TEST(Checker, StraightPathSweepsItsStripWithSquareEnds) {
    // 9 m of stripe plus a W/2 square cap at each end: [0, 10] x [4.5, 5.5] (10 m^2).
    const PolylineXY path{{0.5, 5.0}, {9.5, 5.0}};
    EXPECT_NEAR(swathArea(path, 1.0), 10.0, kSwathTolerance);
    const Report r = checkPath(room10(), {}, path, 0.6, 1.0);
    EXPECT_NEAR(r.floorArea, 100.0, 1e-9);
    EXPECT_NEAR(r.sweepableArea, 100.0, 1e-9);
    EXPECT_NEAR(r.coveredArea, 10.0, kSwathTolerance);
    EXPECT_NEAR(r.uncoveredArea, 90.0, kSwathTolerance);
    EXPECT_NEAR(r.unreachableArea, 0.0, 1e-9);
    EXPECT_NEAR(r.coverage, 0.1, 1e-5);
    EXPECT_NEAR(r.clearance.minimum, 0.5, 1e-12);
    EXPECT_TRUE(r.clearance.inside);
    EXPECT_TRUE(r.collisionFree);
    EXPECT_EQ(r.centreComponents, 1);
}

TEST(Checker, TurnsAreMitred) {
    // (0,0) -> (10,0) -> (10,10), W = 1: two 10.5 m^2 strips (with their caps) overlapping
    // in [9.5, 10] x [0, 0.5], plus the mitre [10, 10.5] x [-0.5, 0]: 21 m^2.
    EXPECT_NEAR(swathArea({{0, 0}, {10, 0}, {10, 10}}, 1.0), 21.0, kSwathTolerance);
    // Repeated vertices change nothing.
    EXPECT_NEAR(swathArea({{0, 0}, {10, 0}, {10, 0}, {10, 10}}, 1.0), 21.0, kSwathTolerance);
    // A robot that does not move sweeps nothing.
    EXPECT_EQ(swathArea({{3, 3}}, 1.0), 0.0);
}

TEST(Checker, BoustrophedonCoversTheRoom) {
    const Report r = checkPath(room10(), {}, boustrophedon(), 0.6, 1.0);
    EXPECT_NEAR(r.coveredArea, 100.0, kSwathTolerance);
    EXPECT_NEAR(r.coverage, 1.0, 1e-5);
    EXPECT_NEAR(r.clearance.minimum, 0.5, 1e-12);
    EXPECT_TRUE(r.collisionFree);
}

TEST(Checker, LongPathsWithManyVertices) {
    // 2,000 vertices along the same stripes.
    PolylineXY path;
    for (int i = 0; i < 10; ++i) {
        const double x = 0.5 + i;
        for (int k = 0; k <= 199; ++k) {
            const double t = 0.5 + 9.0 * k / 199.0;
            path.push_back({x, i % 2 == 0 ? t : 10.0 - t});
        }
    }
    const Report r = checkPath(room10(), {}, path, 0.6, 1.0);
    EXPECT_NEAR(r.coveredArea, 100.0, kSwathTolerance);
}

TEST(Checker, RequiredRegionLimitsTheFloor) {
    const std::vector<RingXY> left{{{0, 0}, {5, 0}, {5, 10}, {0, 10}}};
    const Report r = checkPath(room10(), left, {{0.5, 5.0}, {9.5, 5.0}}, 0.6, 1.0);
    EXPECT_NEAR(r.floorArea, 50.0, 1e-9);
    EXPECT_NEAR(r.sweepableArea, 50.0, 1e-9);
    EXPECT_NEAR(r.coveredArea, 5.0, kSwathTolerance);
}

TEST(Checker, HolesAreWalls) {
    FreeSpace free = room10();
    free.holes.push_back(square(4, 4, 2));
    EXPECT_NEAR(floorArea(free, {}), 96.0, 1e-9);
    // Passing 0.5 m below the hole: clearance 0.5 (the hole), collision-free.
    Clearance below = minimumClearance(free, {{0.5, 3.5}, {9.5, 3.5}});
    EXPECT_NEAR(below.minimum, 0.5, 1e-12);
    EXPECT_TRUE(below.inside);
    // Through the hole: both ends inside the free space, the segment crosses walls.
    Clearance through = minimumClearance(free, {{0.5, 5.0}, {9.5, 5.0}});
    EXPECT_NEAR(through.minimum, 0.0, 1e-12);
    EXPECT_TRUE(through.inside);
    EXPECT_FALSE(isCollisionFree(through, 0.6));
    // A waypoint in the hole is outside the free space.
    Clearance into = minimumClearance(free, {{0.5, 5.0}, {5.0, 5.0}});
    EXPECT_FALSE(into.inside);
    EXPECT_EQ(into.outsideVertex, 1u);
    // The swath over the hole is not counted: [0,10] x [4.5,5.5] minus [4,6] x [4.5,5.5].
    const Report r = checkPath(free, {}, {{0.5, 5.0}, {9.5, 5.0}}, 0.6, 1.0);
    EXPECT_NEAR(r.coveredArea, 8.0, kSwathTolerance);
    EXPECT_FALSE(r.collisionFree);
}

TEST(Checker, ClearanceTolerance) {
    // L = 0.6: collision-free down to 0.3 - 0.0006 m.
    EXPECT_TRUE(isCollisionFree(minimumClearance(room10(), {{0.2995, 5}, {9, 5}}), 0.6));
    EXPECT_FALSE(isCollisionFree(minimumClearance(room10(), {{0.299, 5}, {9, 5}}), 0.6));
    EXPECT_FALSE(isCollisionFree(minimumClearance(room10(), {{0.2, 5}, {9, 5}}), 0.6));
    // Clearance of a segment is measured along it, not only at its ends: this one passes
    // 0.1 m above a hole's top edge half way, its ends are 2 m from the hole.
    FreeSpace free = room10();
    free.holes.push_back(square(4, 4, 2));
    const Clearance c = minimumClearance(free, {{2, 6.1}, {8, 6.1}});
    EXPECT_NEAR(c.minimum, 0.1, 1e-9);
    EXPECT_EQ(c.segment, 0u);
    // An empty path has nothing to collide.
    EXPECT_TRUE(std::isinf(minimumClearance(room10(), {}).minimum));
}

TEST(Checker, DoorNarrowerThanTheRobotCutsOffTheRoomBehindIt) {
    // Two 5 x 5 rooms joined by a 1 m long, 0.5 m wide passage; L = 0.6 does not fit.
    const FreeSpace free{{{0, 0},
                          {5, 0},
                          {5, 2.25},
                          {6, 2.25},
                          {6, 0},
                          {11, 0},
                          {11, 5},
                          {6, 5},
                          {6, 2.75},
                          {5, 2.75},
                          {5, 5},
                          {0, 5}},
                         {}};
    const Report r = checkPath(free, {}, {{0.5, 0.5}, {4.5, 0.5}}, 0.6, 1.0);
    EXPECT_NEAR(r.floorArea, 50.5, 1e-9);
    EXPECT_EQ(r.centreComponents, 2);
    // The start room, and the passage's mouth: the eroded room bulges into the doorway up
    // to x = 5 - sqrt(0.3^2 - 0.25^2) = 4.834 (0.3 m from both door jambs), so the head
    // reaches at most 5.334 into the passage: 25.1 <= sweepable <= 25 + 0.334 * 0.5.
    EXPECT_GE(r.sweepableArea, 25.1);
    EXPECT_LE(r.sweepableArea, 25.0 + (0.5 - std::sqrt(0.3 * 0.3 - 0.25 * 0.25)) * 0.5);
    EXPECT_NEAR(r.unreachableArea, 50.5 - r.sweepableArea, 1e-9);
    // Without a start both rooms count: the two mouths do not meet, so twice as much.
    EXPECT_NEAR(sweepableArea(free, {}, 0.6, 1.0), 2.0 * r.sweepableArea, 1e-6);
    // L = 0.4 fits through the 0.5 m passage: one component, everything sweepable.
    EXPECT_EQ(checkPath(free, {}, {{0.5, 0.5}, {4.5, 0.5}}, 0.4, 1.0).centreComponents, 1);
    EXPECT_NEAR(sweepableArea(free, {}, 0.4, 1.0), 50.5, 1e-9);
}

TEST(Checker, UtmSizedCoordinatesKeepTheirPrecision) {
    const double x0 = 512345.678, y0 = 5432109.876;
    const FreeSpace free{square(x0, y0, 10), {}};
    PolylineXY path = boustrophedon(x0, y0);
    const Report r = checkPath(free, {}, path, 0.6, 1.0);
    EXPECT_NEAR(r.floorArea, 100.0, 1e-6);
    EXPECT_NEAR(r.sweepableArea, 100.0, 1e-6);
    EXPECT_NEAR(r.coverage, 1.0, 1e-5);
    EXPECT_NEAR(r.clearance.minimum, 0.5, 1e-6);
    EXPECT_TRUE(r.collisionFree);
}

TEST(Checker, RotatedRoomGivesTheSameFigures) {
    const double a = 17.0 * kPi / 180.0, c = std::cos(a), s = std::sin(a);
    auto rotate = [&](XY p) { return XY{c * p.first - s * p.second, s * p.first + c * p.second}; };
    FreeSpace free;
    for (const XY& p : square(0, 0, 10))
        free.outer.push_back(rotate(p));
    PolylineXY path;
    for (const XY& p : boustrophedon())
        path.push_back(rotate(p));
    const Report r = checkPath(free, {}, path, 0.6, 1.0);
    EXPECT_NEAR(r.floorArea, 100.0, 1e-9);
    EXPECT_NEAR(r.sweepableArea, 100.0, 1e-6);
    EXPECT_NEAR(r.coverage, 1.0, 1e-5);
    EXPECT_NEAR(r.clearance.minimum, 0.5, 1e-9);
}

TEST(Checker, RoundPillarLeavesWedgesOnlyWhereTheDiscCannotReach) {
    // A 64-gon pillar of radius 1 in the middle: the room minus the pillar is all
    // sweepable (the disc rolls around it; L/2 + W/2 > 0 everywhere).
    FreeSpace free = room10();
    RingXY pillar;
    for (int k = 0; k < 64; ++k)
        pillar.push_back({5 + std::cos(2 * kPi * k / 64), 5 + std::sin(2 * kPi * k / 64)});
    free.holes.push_back(pillar);
    const double floor = floorArea(free, {});
    EXPECT_NEAR(floor, 100.0 - 32.0 * std::sin(2 * kPi / 64), 1e-9);
    EXPECT_NEAR(sweepableArea(free, {}, 0.6, 1.0), floor, kArcTolerance);
}

TEST(Checker, SwathAreaDoesNotDependOnTheFrame) {
    // A random walk with reversals, micrometre hops and retraced runs, measured in three
    // rotations and at a UTM-sized offset: the same area to 0.05 %.
    PolylineXY walk{{0, 0}};
    unsigned state = 12345;
    auto next = [&] {
        state = state * 1103515245u + 12345u;
        return static_cast<double>((state >> 8) & 0xFFFF) / 65536.0;
    };
    double heading = 0.0;
    for (int i = 0; i < 400; ++i) {
        const double r = next();
        heading += r < 0.2 ? kPi : (r < 0.5 ? kPi / 2 : (next() - 0.5));
        const double step = r > 0.9 ? 1e-6 : 0.05 + 2.0 * next();
        walk.push_back({walk.back().first + step * std::cos(heading),
                        walk.back().second + step * std::sin(heading)});
    }
    const double reference = swathArea(walk, 1.0);
    EXPECT_GT(reference, 10.0);
    for (double deg : {33.0, 71.0, 90.0}) {
        const double a = deg * kPi / 180.0, c = std::cos(a), s = std::sin(a);
        PolylineXY moved;
        for (const XY& p : walk)
            moved.push_back(
                {c * p.first - s * p.second + 512345.0, s * p.first + c * p.second + 5432100.0});
        EXPECT_NEAR(swathArea(moved, 1.0), reference, 5e-4 * reference) << deg << " degrees";
    }
}

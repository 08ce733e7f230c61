#include "geometry/Clearance.h"
#include "geometry/Geometry.h"
#include "geometry/OpenRegions.h"
#include "geometry/RingOverlap.h"
#include "geometry/SegmentIndex.h"

#include <gtest/gtest.h>
#include <random>

using namespace fc;

TEST(Geometry, AreaAndOrientation) {
    Ring sq{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_DOUBLE_EQ(signedArea(sq), 4.0);
    Ring cw(sq.rbegin(), sq.rend());
    EXPECT_DOUBLE_EQ(signedArea(cw), -4.0);
}

TEST(Geometry, AreaKeepsPrecisionAtUtmOffsets) {
    const double ox = 500000.0, oy = 5000000.0;
    Ring sq{{ox, oy}, {ox + 0.5, oy}, {ox + 0.5, oy + 0.5}, {ox, oy + 0.5}};
    EXPECT_NEAR(ringArea(sq), 0.25, 1e-9);
}

TEST(Geometry, FrameRoundTripAndExactQuarterTurns) {
    Frame f({10, 20}, 0.0); // horizontal stripes: world x maps onto local y
    const Vec2 l = f.toLocal({13, 20});
    EXPECT_DOUBLE_EQ(l.x, 0.0);
    EXPECT_DOUBLE_EQ(l.y, 3.0);
    Frame g({5, 5}, 37.0);
    const Vec2 w = g.toWorld(g.toLocal({1.25, -7.5}));
    EXPECT_NEAR(w.x, 1.25, 1e-12);
    EXPECT_NEAR(w.y, -7.5, 1e-12);
}

TEST(Geometry, SegmentIndexClearance) {
    SegmentIndex idx({Ring{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
    EXPECT_NEAR(idx.distanceToWalls({3, 4}), 3.0, 1e-12);
    EXPECT_NEAR(idx.segmentClearance({2, 5}, {8, 5}), 2.0, 1e-12);
    EXPECT_NEAR(idx.polylineClearance({{1, 1}, {5, 5}, {9, 9}}), 1.0, 1e-12);
}

namespace {

// Checked against every wall, not through the index the field uses.
bool keepsClearOfEveryWall(const ClearanceField& field, const Polyline& line) {
    for (size_t i = 1; i < line.size(); ++i)
        for (const Segment& s : field.walls().segments())
            if (segmentSegmentDistance(line[i - 1], line[i], s.a, s.b) <
                field.radius() - field.acceptance() - 1e-9)
                return false;
    return true;
}

BoundingBox extentOf(const std::vector<Ring>& rings) {
    BoundingBox extent;
    for (const Ring& ring : rings)
        for (const Vec2& p : ring)
            extent.add(p);
    return extent;
}

// A ragged ring (a traced wall: many short edges, jittered) around a square of side `size`.
Ring raggedSquare(std::mt19937& rng, double size, int perSide) {
    std::uniform_real_distribution<double> jitter(-0.08, 0.08);
    Ring ring;
    const Vec2 corners[4] = {{0, 0}, {size, 0}, {size, size}, {0, size}};
    for (int side = 0; side < 4; ++side)
        for (int k = 0; k < perSide; ++k) {
            const Vec2 p = corners[side] + (corners[(side + 1) % 4] - corners[side]) *
                                               (static_cast<double>(k) / perSide);
            ring.push_back({p.x + jitter(rng), p.y + jitter(rng)});
        }
    return ring;
}

} // namespace

// The index asks several small boxes along a slanted segment instead of its whole bounding
// box: the answer must still be that of testing every wall.
TEST(Geometry, SegmentKeepsDistanceAgreesWithAFullScan) {
    std::mt19937 rng(11);
    std::vector<Ring> rings{raggedSquare(rng, 20.0, 120)};
    std::uniform_real_distribution<double> at(1.0, 19.0), side(0.2, 0.6);
    for (int k = 0; k < 12; ++k) { // pillars
        const Vec2 c{at(rng), at(rng)};
        const double s = side(rng);
        rings.push_back(
            {{c.x - s, c.y - s}, {c.x + s, c.y - s}, {c.x + s, c.y + s}, {c.x, c.y + 1.5 * s}});
    }
    const SegmentIndex index(rings);
    std::uniform_real_distribution<double> anywhere(0.3, 19.7), distance(0.05, 0.8);
    int blocked = 0, clear = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vec2 a{anywhere(rng), anywhere(rng)};
        const Vec2 b =
            trial % 3 == 0 ? Vec2{a.x + 0.3, anywhere(rng)} : Vec2{anywhere(rng), anywhere(rng)};
        const double d = distance(rng);
        bool expected = true;
        for (const Segment& s : index.segments())
            expected = expected && segmentSegmentDistance(a, b, s.a, s.b) >= d;
        ASSERT_EQ(index.segmentKeepsDistance(a, b, d), expected)
            << "segment (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << "), d " << d;
        (expected ? clear : blocked)++;
    }
    EXPECT_GT(clear, 100); // both answers were asked
    EXPECT_GT(blocked, 100);
}

// Paths round a long wall on a floor with traced (ragged) walls and many pillars: the
// visibility search remembers blocked pairs within one search; its paths must stay clear
// and short, and a point in a closed room must get no path at all.
TEST(Geometry, FindPathOnARaggedFloorIsClearAndShort) {
    std::mt19937 rng(5);
    std::vector<Ring> rings{raggedSquare(rng, 20.0, 100)};
    rings.push_back({{9.8, 0.5}, {10.2, 0.5}, {10.2, 15.0}, {9.8, 15.0}}); // the long wall
    std::uniform_real_distribution<double> at(1.5, 18.5);
    for (int k = 0; k < 25; ++k) {
        const Vec2 c{at(rng), at(rng)};
        if (std::abs(c.x - 10.0) < 1.0 || (c.x > 15.5 && c.y > 15.5))
            continue; // keep the wall's end passable and the closed room apart
        rings.push_back({{c.x - 0.2, c.y - 0.2},
                         {c.x + 0.2, c.y - 0.2},
                         {c.x + 0.2, c.y + 0.2},
                         {c.x - 0.2, c.y + 0.2}});
    }
    rings.push_back({{16, 16}, {19, 16}, {19, 19}, {16, 19}}); // a closed room's outer wall
    rings.push_back({{16.2, 16.2}, {16.2, 18.8}, {18.8, 18.8}, {18.8, 16.2}}); // its inside
    const double r = 0.3;
    const ClearanceField field(rings, r);
    auto clearOfEveryWall = [&](const Polyline& line) {
        return keepsClearOfEveryWall(field, line);
    };
    const BoundingBox extent = extentOf(rings);
    const OpenRegions regions(field.walls(), extent, r - field.acceptance());
    int found = 0;
    for (double y : {2.0, 5.0, 9.0}) {
        const Vec2 a{4.0, y}, b{16.0, y};
        if (!field.isClear(a) || !field.isClear(b))
            continue;
        const Polyline path = field.findPath(a, b);
        ASSERT_GE(path.size(), 3u) << y; // it must bend round the wall
        EXPECT_EQ(path.front().x, a.x);
        EXPECT_EQ(path.back().y, b.y);
        EXPECT_TRUE(clearOfEveryWall(path)) << y;
        // Round the wall's end (10, 15) at the robot's radius: a path over it is at least
        // this long; pillars may add a little, never a detour of metres.
        const Vec2 tip{10.0, 15.0 + r};
        const double over = distance(a, tip) + distance(tip, b);
        EXPECT_GE(polylineLength(path), over - 0.05) << y;
        EXPECT_LE(polylineLength(path), over * 1.08) << y;
        // The grid's route (what crowded windows use): clear, and within 3% of the search's
        // path (shorter at times: pulled tight, it passes corners closer than the corner
        // waypoints do).
        const Polyline route = regions.clearRoute(
            a, b, extent, [&](Vec2 p, Vec2 q) { return field.segmentIsClear(p, q); });
        EXPECT_TRUE(clearOfEveryWall(route)) << y;
        EXPECT_LE(polylineLength(route), 1.03 * polylineLength(path)) << y;
        EXPECT_GE(polylineLength(route), 0.97 * polylineLength(path)) << y;
        // The grid's proof: a window round the path may hold it; one that stops short of
        // the wall's end cannot, and is then not searched.
        BoundingBox around;
        for (const Vec2& p : path)
            around.add(p);
        EXPECT_TRUE(regions.mayJoinWithin(a, b, around)) << y;
        BoundingBox below = around;
        below.maxY = 14.0;
        EXPECT_FALSE(regions.mayJoinWithin(a, b, below)) << y;
        ++found;
    }
    EXPECT_GE(found, 2);
    EXPECT_TRUE(field.findPath({4.0, 17.0}, {17.5, 17.5}).empty());
    EXPECT_FALSE(regions.mayJoinWithin({4.0, 17.0}, {17.5, 17.5}, extent));
    // Asked again once the grid exists (the first failure builds it): still no path.
    EXPECT_TRUE(field.findPath({4.0, 17.5}, {17.5, 17.0}).empty());
}

namespace {

// A traced floor as an uncleaned laser map gives it: ragged outer walls, a long wall in the
// middle, a closed room, and small squares of sensor noise strewn over the floor every
// 0.8 m or so (the robot passes between them).
std::vector<Ring> speckledFloor(std::mt19937& rng) {
    std::vector<Ring> rings{raggedSquare(rng, 20.0, 100)};
    rings.push_back({{9.8, -0.5}, {10.2, -0.5}, {10.2, 15.0}, {9.8, 15.0}}); // meets the outer wall
    rings.push_back({{16, 16}, {19, 16}, {19, 19}, {16, 19}});
    rings.push_back({{16.2, 16.2}, {16.2, 18.8}, {18.8, 18.8}, {18.8, 16.2}});
    std::uniform_real_distribution<double> jitter(-0.06, 0.06);
    for (double x = 0.9; x < 19.2; x += 0.8)
        for (double y = 0.9; y < 19.2; y += 0.8) {
            const Vec2 c{x + jitter(rng), y + jitter(rng)};
            if (std::abs(c.x - 10.0) < 0.9 || (c.x > 15.3 && c.y > 15.3) ||
                (std::abs(c.x - 10.0) < 2.0 && c.y > 14.0))
                continue; // the wall's end stays open
            rings.push_back({{c.x - 0.03, c.y - 0.03},
                             {c.x + 0.03, c.y - 0.03},
                             {c.x + 0.03, c.y + 0.03},
                             {c.x - 0.03, c.y + 0.03}});
        }
    return rings;
}

} // namespace

// Among thousands of speck corners the path search takes the grid's route (the visibility
// search would spend its budget there): the route must be clear of every wall, close to the
// shortest way round the long wall, and absent where the grid holds none.
TEST(Geometry, GridRouteAmongThousandsOfSpecksIsClearAndNearlyShortest) {
    std::mt19937 rng(23);
    const std::vector<Ring> rings = speckledFloor(rng);
    const double r = 0.2;
    const ClearanceField field(rings, r);
    auto clearOfEveryWall = [&](const Polyline& line) {
        return keepsClearOfEveryWall(field, line);
    };
    const BoundingBox extent = extentOf(rings);
    const OpenRegions regions(field.walls(), extent, r - field.acceptance());
    auto sees = [&](Vec2 p, Vec2 q) { return field.segmentIsClear(p, q); };
    int routes = 0;
    for (double y : {2.1, 5.3, 10.1}) { // between rows of specks
        for (double dx : {0.0, 0.05, 0.11}) {
            const Vec2 a{4.5 + dx, y}, b{15.7 - dx, y + 0.8};
            if (!field.isClear(a) || !field.isClear(b))
                continue;
            const Vec2 tip{10.0, 15.0 + r}; // no specks round the wall's end
            const double over = distance(a, tip) + distance(tip, b);
            for (const Polyline& path :
                 {regions.clearRoute(a, b, extent, sees), field.findPath(a, b)}) {
                ASSERT_GE(path.size(), 3u) << y;
                EXPECT_EQ(path.front().x, a.x);
                EXPECT_EQ(path.back().x, b.x);
                EXPECT_TRUE(clearOfEveryWall(path)) << y;
                EXPECT_GE(polylineLength(path), over - 0.05) << y;
                // Weaving between the specks adds a few per cent to the way round the wall's
                // end; how close the grid's route comes to the shortest path is checked on
                // the floor without specks (FindPathOnARaggedFloorIsClearAndShort).
                EXPECT_LE(polylineLength(path), over * 1.10) << y;
                ++routes;
            }
            BoundingBox below = extent;
            below.maxY = 14.0; // stops short of the wall's end
            EXPECT_TRUE(regions.clearRoute(a, b, below, sees).empty()) << y;
        }
    }
    EXPECT_GE(routes, 12);
    EXPECT_TRUE(regions.clearRoute({4.0, 17.0}, {17.5, 17.5}, extent, sees).empty());
    EXPECT_TRUE(field.findPath({4.0, 17.0}, {17.5, 17.5}).empty());
}

// Among thousands of speck corners with the long wall's only opening a doorway barely wider
// than the robot: the grid's surely clear nodes do not fit in it, so the grid alone has no
// route, and the visibility search over the window's 8,000 corner points took 220 s to
// find the way round through it. The doorway is a portal of the field's grid: its route
// goes through the doorway in well under a second, clear of every wall and nearly shortest.
TEST(Geometry, FindPathAmongThousandsOfSpecksThroughATightDoorway) {
    std::mt19937 rng(29);
    std::vector<Ring> rings = speckledFloor(rng);
    const double r = 0.2, h = 1.01 * r, door = 10.0;
    rings[1] = {{9.8, -0.5}, {10.2, -0.5}, {10.2, door - h}, {9.8, door - h}};
    rings.push_back({{9.8, door + h}, {10.2, door + h}, {10.2, 20.5}, {9.8, 20.5}});
    const ClearanceField field(rings, r);
    const BoundingBox extent = extentOf(rings);
    const OpenRegions regions(field.walls(), extent, r - field.acceptance());
    const Vec2 a{4.5, 2.1}, b{15.7, 2.9};
    ASSERT_TRUE(field.isClear(a) && field.isClear(b));
    EXPECT_TRUE(
        regions.clearRoute(a, b, extent, [&](Vec2 p, Vec2 q) { return field.segmentIsClear(p, q); })
            .empty());
    // The grid with the doorway as a portal: a route through it, clear of every wall.
    OpenRegions withPortal(field.walls(), extent, r - field.acceptance());
    withPortal.addPortals({{{10.0, door}, {1.0, 0.0}}},
                          [&](Vec2 p, Vec2 q) { return field.segmentIsClear(p, q); });
    const Polyline route = withPortal.clearRoute(
        a, b, extent, [&](Vec2 p, Vec2 q) { return field.segmentIsClear(p, q); });
    ASSERT_GE(route.size(), 3u);
    EXPECT_TRUE(keepsClearOfEveryWall(field, route));
    const Polyline path = field.findPath(a, b);
    ASSERT_GE(path.size(), 3u);
    EXPECT_TRUE(keepsClearOfEveryWall(field, path));
    const Vec2 gap{10.0, door};
    EXPECT_LE(polylineLength(route), (distance(a, gap) + distance(gap, b)) * 1.10);
    const double through = distance(a, gap) + distance(gap, b);
    EXPECT_GE(polylineLength(path), through - 0.05);
    EXPECT_LE(polylineLength(path), through * 1.10);
    // The same question asked the other way round finds a path as short.
    EXPECT_NEAR(polylineLength(field.findPath(b, a)), polylineLength(path), 0.05 * through);
}

// Searches are remembered by all their arguments: a search whose window is too small to go
// round the wall fails, the unbounded one then succeeds, and the small one still fails.
TEST(Geometry, RememberedSearchesAnswerOnlyTheSameQuestion) {
    const std::vector<Ring> rings{{{0, 0}, {20, 0}, {20, 20}, {0, 20}},
                                  {{9.8, 0.5}, {10.2, 0.5}, {10.2, 15.0}, {9.8, 15.0}}};
    const ClearanceField field(rings, 0.3);
    const Vec2 a{4, 2}, b{16, 2};
    for (int round = 0; round < 2; ++round) {
        EXPECT_TRUE(field.findPath(a, b, {}, 3.0).empty()) << round;
        const Polyline path = field.findPath(a, b);
        ASSERT_GE(path.size(), 3u) << round;
        EXPECT_TRUE(field.polylineIsClear(path));
        EXPECT_TRUE(field.findPath(a, b, {}, 3.0, 1).empty()) << round;
        EXPECT_EQ(field.findPath(b, a).size(), path.size()) << round;
    }
}

// Two rooms joined by a channel a hair wider than the robot (2.01 r, a traced doorway), at
// an angle: the robot may drive it, so a path is found through it and keeps clear of every
// wall. The corner points keep 1.01 r from walls and none fits in the channel; its middle
// and the points along it are waypoints of their own.
TEST(Geometry, FindPathThroughAGapBarelyWiderThanTheRobot) {
    const double r = 0.3;
    for (double width : {2.01 * r, 2.04 * r}) {
        const double h = 0.5 * width;
        const Ring flat{{0, 0},    {5, 0},   {5, 2.5 - h},   {6.2, 2.5 - h}, {6.2, 0}, {11.2, 0},
                        {11.2, 5}, {6.2, 5}, {6.2, 2.5 + h}, {5, 2.5 + h},   {5, 5},   {0, 5}};
        const Frame frame({0, 0}, 90.0 + 23.0); // flat's x axis turned by 23 degrees
        Ring ring;
        for (const Vec2& p : flat)
            ring.push_back(frame.toWorld(p));
        const ClearanceField field({ring}, r);
        // From a corner of one room to the far corner of the other: the path turns at
        // both ends of the channel.
        const Vec2 a = frame.toWorld({1.0, 4.5}), b = frame.toWorld({10.2, 0.5});
        const Polyline path = field.findPath(a, b);
        ASSERT_GE(path.size(), 4u) << width;
        EXPECT_TRUE(keepsClearOfEveryWall(field, path)) << width;
        const double shortest = distance({1.0, 4.5}, {5.0, 2.5 + h - r}) + 1.2 +
                                distance({6.2, 2.5 - h + r}, {10.2, 0.5});
        EXPECT_LT(polylineLength(path), shortest + 0.3) << width;
    }
}

// Room names are written where a person looks for them: inside the room, clear of its
// walls and of the obstacles in it, also far from the origin (UTM coordinates).
TEST(Geometry, LabelPointsLieWellInsideTheRoom) {
    for (const Vec2 offset : {Vec2{0, 0}, Vec2{512345.0, 5412345.0}}) {
        auto at = [&](std::initializer_list<Vec2> points) {
            Ring ring;
            for (Vec2 p : points)
                ring.push_back(p + offset);
            return ring;
        };
        // A rectangle keeps its centroid.
        const Ring hall = at({{0, 0}, {10, 0}, {10, 4}, {0, 4}});
        const Vec2 c = interiorLabelPoint(hall) - offset;
        EXPECT_NEAR(c.x, 5.0, 1e-6);
        EXPECT_NEAR(c.y, 2.0, 1e-6);
        // An L whose centroid lies outside it (arms 1 m wide): inside, at least 0.4 m from
        // every wall.
        const Ring ell = at({{0, 0}, {10, 0}, {10, 1}, {1, 1}, {1, 10}, {0, 10}});
        const Vec2 inL = interiorLabelPoint(ell);
        EXPECT_TRUE(pointInRing(ell, inL));
        for (size_t i = 0; i < ell.size(); ++i)
            EXPECT_GT(pointSegmentDistance(inL, ell[i], ell[(i + 1) % ell.size()]), 0.4);
        // A room drawn round a pillar at its centre: beside the pillar, not on it.
        const Ring pillar = at({{4, 1}, {6, 1}, {6, 3}, {4, 3}});
        const Vec2 beside = interiorLabelPoint(hall, {pillar});
        EXPECT_TRUE(pointInRing(hall, beside));
        EXPECT_FALSE(pointInRing(pillar, beside));
        for (size_t i = 0; i < pillar.size(); ++i)
            EXPECT_GT(pointSegmentDistance(beside, pillar[i], pillar[(i + 1) % pillar.size()]),
                      0.5);
        // A corridor with a desk at its middle: beside the desk, not at either end.
        const Ring corridor = at({{0, 0}, {40, 0}, {40, 2.5}, {0, 2.5}});
        const Ring desk = at({{16, 0.5}, {24, 0.5}, {24, 2}, {16, 2}});
        const Vec2 name = interiorLabelPoint(corridor, {desk}) - offset;
        EXPECT_GT(std::abs(name.x - 20.0), 4.0); // beside the desk, on either side
        EXPECT_LT(std::abs(name.x - 20.0), 8.0);
        EXPECT_NEAR(name.y, 1.25, 0.3);
    }
}

// Two buildings of a site drawn overlapping (formats/GeoJsonPlan.cpp notes it).
TEST(RingOverlap, SharedAreaOfTwoOutlines) {
    const Ring a{{0, 0}, {10, 0}, {10, 8}, {0, 8}}, b{{5, 0}, {15, 0}, {15, 8}, {5, 8}};
    EXPECT_NEAR(ringOverlapArea(a, b), 40.0, 1e-9);
    Ring reversed(b.rbegin(), b.rend()); // either orientation
    EXPECT_NEAR(ringOverlapArea(a, reversed), 40.0, 1e-9);
    const Ring touching{{10, 0}, {20, 0}, {20, 8}, {10, 8}};
    EXPECT_EQ(ringOverlapArea(a, touching), 0.0);
    const Ring bowTie{{0, 0}, {10, 8}, {10, 0}, {0, 8}};
    EXPECT_EQ(ringOverlapArea(a, bowTie), 0.0); // not a polygon: its own checks name it
    // At UTM coordinates the digits are kept.
    Ring ua = a, ub = b;
    for (Vec2& p : ua)
        p = p + Vec2{512345.0, 5412345.0};
    for (Vec2& p : ub)
        p = p + Vec2{512345.0, 5412345.0};
    EXPECT_NEAR(ringOverlapArea(ua, ub), 40.0, 1e-6);
}

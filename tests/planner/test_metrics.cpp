#include "TestPlans.h"
#include "decomposition/Decomposition.h"
#include "metrics/Metrics.h"
#include "metrics/Raster.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>
#include <random>
#include <string>

using namespace fc;
using fc::test::rectangle;
using fc::test::shifted;

namespace {

Cell rectangleCell(int id, int room, double x0, double y0, double x1, double y1, double width) {
    Cell cell;
    cell.id = id;
    cell.room = room;
    cell.x0 = x0;
    cell.x1 = x1;
    cell.floor = {{x0, y0}, {x1, y0}};
    cell.ceiling = {{x0, y1}, {x1, y1}};
    const int count = std::max(1, static_cast<int>(std::round((x1 - x0) / width)));
    for (int k = 0; k < count; ++k)
        cell.stripes.push_back(x0 + (x1 - x0) * (k + 0.5) / count);
    return cell;
}

// A free-space rectangle made of one cell per room, split at the given x positions.
Decomposition rooms(double x0, double y0, double x1, double y1, std::vector<double> splits = {},
                    Frame frame = Frame({0, 0}, 90.0)) {
    Decomposition d;
    d.frame = frame;
    d.freeSpace = {rectangle(x0, y0, x1, y1)};
    splits.insert(splits.begin(), x0);
    splits.push_back(x1);
    for (size_t i = 0; i + 1 < splits.size(); ++i) {
        d.roomNames.push_back("Room " + std::to_string(i));
        d.cells.push_back(rectangleCell(static_cast<int>(i), static_cast<int>(i), splits[i], y0,
                                        splits[i + 1], y1, 1.0));
    }
    return d;
}

// Stripes W = 1 apart from x0 + 0.5 to x1 - 0.5, alternately up and down, in the
// sweep frame (mapped to the world by `frame`).
CoveragePath boustrophedon(double x0, double x1, double y0, double y1,
                           const Frame& frame = Frame({0, 0}, 90.0)) {
    CoveragePath path;
    bool up = true;
    for (double x = x0 + 0.5; x < x1; x += 1.0, up = !up) {
        path.points.push_back(frame.toWorld(Vec2{x, up ? y0 + 0.5 : y1 - 0.5}));
        path.points.push_back(frame.toWorld(Vec2{x, up ? y1 - 0.5 : y0 + 0.5}));
    }
    path.kinds.assign(path.points.size() - 1, SegmentKind::Stripe);
    return path;
}

MetricsInput inputFor(const Decomposition& d, const CoveragePath& path) {
    MetricsInput input;
    input.decomposition = &d;
    input.robot.robotDiameter = 0.6;
    input.robot.coverageWidth = 1.0;
    input.robot.speed = 0.5;
    input.robot.turnTime = 2.0;
    input.path = path;
    return input;
}

double overlapLength(const Metrics& m) {
    double total = 0.0;
    for (const Segment& s : m.overlaps)
        total += distance(s.a, s.b);
    return total;
}

} // namespace

TEST(RasterScanline, FillsByPixelCentresWithEvenOdd) {
    const Grid grid{0.0, 0.0, 1.0, 10, 10};
    ScanlineFill fill(grid);
    const std::vector<Ring> rings{rectangle(2, 2, 5, 7), rectangle(3, 3, 4, 4)};
    Mask mask(grid.size(), 0);
    fill.paint(rings.data(), rings.size(), mask);
    int count = 0;
    for (uint8_t v : mask)
        count += v;
    EXPECT_EQ(count, 3 * 5 - 1);
    EXPECT_EQ(mask[grid.index(2, 2)], 1);
    EXPECT_EQ(mask[grid.index(3, 3)], 0); // the hole
    EXPECT_EQ(mask[grid.index(5, 2)], 0); // right edge is exclusive
}

TEST(RasterDistance, MatchesBruteForce) {
    const int cols = 37, rows = 23;
    std::mt19937 random(7);
    Mask mask(static_cast<size_t>(cols * rows), 0);
    for (int r = 1; r + 1 < rows; ++r)
        for (int c = 1; c + 1 < cols; ++c)
            mask[static_cast<size_t>(r * cols + c)] = random() % 13 != 0;
    const std::vector<float> d2 = squaredDistanceToBlocked(mask, cols, rows);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            int best = 1 << 30;
            for (int rr = 0; rr < rows; ++rr)
                for (int cc = 0; cc < cols; ++cc)
                    if (!mask[static_cast<size_t>(rr * cols + cc)])
                        best = std::min(best, (rr - r) * (rr - r) + (cc - c) * (cc - c));
            ASSERT_EQ(d2[static_cast<size_t>(r * cols + c)], static_cast<float>(best))
                << c << "," << r;
        }
    }
}

TEST(RasterDilate, SquareIsClippedAtTheBorder) {
    const int cols = 9, rows = 7;
    Mask mask(static_cast<size_t>(cols * rows), 0);
    mask[static_cast<size_t>(3 * cols + 4)] = 1;
    mask[0] = 1;
    const Mask out = dilateSquare(mask, cols, rows, 2);
    int count = 0;
    for (uint8_t v : out)
        count += v;
    EXPECT_EQ(count, 25 + 9 - 2); // the corner square shares column 2, rows 1-2 with the other
}

TEST(RasterFlood, KeepsOnlySeededComponents) {
    const int cols = 6, rows = 1;
    const Mask region{1, 1, 0, 1, 1, 1};
    const Mask out = floodFill(region, cols, rows, {4});
    EXPECT_EQ(out, (Mask{0, 0, 0, 1, 1, 1}));
}

TEST(Turns, SquarePathHasThreeInteriorTurns) {
    EXPECT_EQ(countTurns({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}), 3);
}

TEST(Turns, ThirtyDegreesIsNotATurnButFortyFiveIs) {
    auto bend = [](double degrees) {
        const double r = degrees * M_PI / 180.0;
        return countTurns({{0, 0}, {1, 0}, {1 + std::cos(r), std::sin(r)}});
    };
    EXPECT_EQ(bend(30.0), 0);
    EXPECT_EQ(bend(44.0), 0);
    EXPECT_EQ(bend(45.0), 1);
    EXPECT_EQ(bend(-90.0), 1);
    EXPECT_EQ(bend(180.0), 1);
}

TEST(Turns, ZeroLengthSegmentsAreIgnored) {
    EXPECT_EQ(countTurns({{0, 0}, {1, 0}, {1, 0}, {2, 0}}), 0);
    EXPECT_EQ(countTurns({{0, 0}, {1, 0}, {1, 0}, {1, 1}}), 1);
    EXPECT_EQ(countTurns({{0, 0}}), 0);
}

TEST(Metrics, FullBoustrophedonCoversTheRectangle) {
    const Decomposition d = rooms(0, 0, 10, 6);
    const Metrics m = computeMetrics(inputFor(d, boustrophedon(0, 10, 0, 6)));
    EXPECT_GT(m.coverage, 0.99);
    EXPECT_NEAR(m.sweepableArea, 60.0, 0.6);
    EXPECT_NEAR(m.ideal, 60.0, 0.6);
    EXPECT_NEAR(m.length, 10 * 5.0 + 9 * 1.0, 1e-9);
    EXPECT_NEAR(m.extra, m.length - m.ideal, 1e-9);
    EXPECT_EQ(m.turns, 2 * (10 - 1));
    EXPECT_EQ(m.cells, 1);
    EXPECT_TRUE(m.overlaps.empty()) << overlapLength(m);
}

TEST(Metrics, TimeIsLengthOverSpeedPlusTurnTimes) {
    const Decomposition d = rooms(0, 0, 10, 6);
    const Metrics m = computeMetrics(inputFor(d, boustrophedon(0, 10, 0, 6)));
    EXPECT_NEAR(m.time, 59.0 / 0.5 + 18 * 2.0, 1e-9);
}

TEST(Metrics, MissingTheLastStripeLeavesATenth) {
    const Decomposition d = rooms(0, 0, 10, 6);
    const Metrics m = computeMetrics(inputFor(d, boustrophedon(0, 9, 0, 6)));
    EXPECT_NEAR(m.coverage, 0.9, 0.01);
    EXPECT_NEAR(m.coveredArea, 54.0, 0.6);
}

TEST(Metrics, StripeRunTwiceIsReportedAsOverlap) {
    const Decomposition d = rooms(0, 0, 10, 6);
    CoveragePath path = boustrophedon(0, 10, 0, 6); // ends going down at x = 9.5
    path.points.push_back({9.5, 5.5});              // and runs the last stripe again
    path.kinds.push_back(SegmentKind::Transit);
    const Metrics m = computeMetrics(inputFor(d, path));
    ASSERT_EQ(m.overlaps.size(), 1u);
    const Segment& s = m.overlaps[0];
    EXPECT_NEAR(s.a.x, 9.5, 1e-9);
    EXPECT_NEAR(s.b.x, 9.5, 1e-9);
    // The first W/2 after reversing is still the head's own recent trail.
    EXPECT_NEAR(distance(s.a, s.b), 4.5, 0.2);
    EXPECT_GT(m.coverage, 0.99);
}

TEST(Metrics, OverlapOverManyShortSegmentsIsOnePiece) {
    const Decomposition d = rooms(0, 0, 10, 6);
    CoveragePath path = boustrophedon(0, 10, 0, 6);
    for (int k = 1; k <= 100; ++k) // back up the last stripe in 5 cm steps
        path.points.push_back({9.5, 0.5 + 0.05 * k});
    path.kinds.resize(path.points.size() - 1, SegmentKind::Transit);
    const Metrics m = computeMetrics(inputFor(d, path));
    ASSERT_EQ(m.overlaps.size(), 1u);
    EXPECT_NEAR(distance(m.overlaps[0].a, m.overlaps[0].b), 4.5, 0.2);
}

TEST(Metrics, DeadEndCorridorNarrowerThanTheRobotIsUnreachable) {
    // 0.5 m wide: the robot disc (L = 0.6 m) cannot enter it.
    Decomposition d = rooms(0, 0, 10, 6);
    d.freeSpace = {
        {{0, 0}, {10, 0}, {10, 2.75}, {13, 2.75}, {13, 3.25}, {10, 3.25}, {10, 6}, {0, 6}}};
    d.cells.push_back(rectangleCell(1, 0, 10, 2.75, 13, 3.25, 1.0));
    const Metrics m = computeMetrics(inputFor(d, boustrophedon(0, 10, 0, 6)));
    EXPECT_EQ(m.cells, 2);
    EXPECT_GT(m.sweepableArea, 59.4);
    EXPECT_LT(m.sweepableArea, 60.4); // the 1.5 m^2 corridor is out, bar its mouth
    EXPECT_NEAR(m.unreachableArea, m.requiredArea - m.sweepableArea, 1e-9);
    EXPECT_GT(m.unreachableArea, 1.0);
    EXPECT_GT(m.coverage, 0.99);
    EXPECT_FALSE(m.unreachable.empty());
}

TEST(Metrics, DeadEndCorridorTheRobotFitsIntoIsSweepableAndMissed) {
    // 0.8 m wide: narrower than the swath, wider than the robot; a path that stays in the
    // room leaves it uncovered, and says so (no silent loss).
    Decomposition d = rooms(0, 0, 10, 6);
    d.freeSpace = {{{0, 0}, {10, 0}, {10, 2.6}, {13, 2.6}, {13, 3.4}, {10, 3.4}, {10, 6}, {0, 6}}};
    d.cells.push_back(rectangleCell(1, 0, 10, 2.6, 13, 3.4, 1.0));
    const Metrics m = computeMetrics(inputFor(d, boustrophedon(0, 10, 0, 6)));
    EXPECT_NEAR(m.sweepableArea, 62.4, 0.3);
    EXPECT_NEAR(m.uncoveredArea, 2.4, 0.3);
    EXPECT_LT(m.unreachableArea, 0.3);
    EXPECT_LT(m.coverage, 0.97);
}

TEST(Metrics, OnlyRequiredRoomsCount) {
    const Decomposition d = rooms(0, 0, 10, 6, {5.0});
    MetricsInput input = inputFor(d, boustrophedon(0, 5, 0, 6));
    input.requiredRooms = {1, 0};
    const Metrics onlyFirst = computeMetrics(input);
    EXPECT_GT(onlyFirst.coverage, 0.99);
    EXPECT_NEAR(onlyFirst.sweepableArea, 30.0, 0.3);
    EXPECT_EQ(onlyFirst.cells, 1);

    input.requiredRooms.clear(); // all rooms
    const Metrics all = computeMetrics(input);
    EXPECT_NEAR(all.coverage, 0.5, 0.01);
    EXPECT_EQ(all.cells, 2);
}

TEST(Metrics, LargeCoordinatesAndRotatedFramesGiveTheSameNumbers) {
    const Decomposition near = rooms(0, 0, 10, 6);
    CoveragePath path = boustrophedon(0, 10, 0, 6);
    path.points.push_back({9.5, 5.5});
    path.kinds.push_back(SegmentKind::Transit);
    const Metrics reference = computeMetrics(inputFor(near, path));

    for (const Frame& frame : {Frame({500000.0, 5000000.0}, 90.0),
                               Frame({500000.0, 5000000.0}, 0.0), Frame({-20.0, 7.0}, 33.0)}) {
        const Decomposition far = rooms(0, 0, 10, 6, {}, frame);
        CoveragePath farPath = path;
        farPath.points = frame.toWorld(path.points);
        const Metrics m = computeMetrics(inputFor(far, farPath));
        EXPECT_NEAR(m.coverage, reference.coverage, 1e-6);
        EXPECT_NEAR(m.sweepableArea, reference.sweepableArea, 1e-6);
        EXPECT_NEAR(m.length, reference.length, 1e-6);
        EXPECT_EQ(m.turns, reference.turns);
        ASSERT_EQ(m.overlaps.size(), reference.overlaps.size());
        const Vec2 a = frame.toLocal(m.overlaps[0].a), b = frame.toLocal(m.overlaps[0].b);
        EXPECT_NEAR(distance(a, reference.overlaps[0].a), 0.0, 1e-6);
        EXPECT_NEAR(distance(b, reference.overlaps[0].b), 0.0, 1e-6);
    }
}

TEST(Metrics, SingleSegmentSweepsItsRectangleWithSquareCaps) {
    const Decomposition d = rooms(0, 0, 10, 6);
    CoveragePath path;
    path.points = {{2, 3}, {7, 3}};
    path.kinds = {SegmentKind::Transit};
    const Metrics m = computeMetrics(inputFor(d, path));
    // 5 m x W, plus the square caps (W/2 past each end of the path).
    EXPECT_NEAR(m.coveredArea, 5.0 + 1.0, 0.02 * 6.0);
    EXPECT_TRUE(m.overlaps.empty());
}

TEST(Metrics, RightAngleTurnIsMitred) {
    const Decomposition d = rooms(0, 0, 10, 6);
    CoveragePath path;
    path.points = {{1, 1}, {5, 1}, {5, 5}};
    path.kinds = {SegmentKind::Transit, SegmentKind::Transit};
    const Metrics m = computeMetrics(inputFor(d, path));
    // Two 4.5 m x W rectangles (with end caps), their 0.5 x 0.5 overlap at the inner
    // corner, and the 0.5 x 0.5 mitre square at the outer corner.
    EXPECT_NEAR(m.coveredArea, 4.5 + 4.5 - 0.25 + 0.25, 0.02 * 9.0);
}

TEST(Metrics, SharpTurnIsBevelled) {
    const Decomposition d = rooms(0, 0, 10, 6);
    const double r = 170.0 * M_PI / 180.0; // heading change; the mitre would be ~5.7 W
    CoveragePath path;
    path.points = {{2, 3}, {6, 3}, {6 + 3 * std::cos(r), 3 + 3 * std::sin(r)}};
    path.kinds = {SegmentKind::Transit, SegmentKind::Transit};
    const Metrics m = computeMetrics(inputFor(d, path));
    // At most both rectangles plus the bevel triangle; far less than a mitre spike.
    const double bevel = 0.5 * 0.5 * 0.5 * std::sin(r);
    EXPECT_LT(m.coveredArea, 4.5 + 3.5 + bevel + 0.1);
    EXPECT_GT(m.coveredArea, 4.5 + 0.5);
}

TEST(Metrics, WithoutDecompositionOnlyPathNumbers) {
    MetricsInput input;
    input.path.points = {{0, 0}, {3, 0}, {3, 4}};
    input.path.kinds = {SegmentKind::Transit, SegmentKind::Transit};
    const Metrics m = computeMetrics(input);
    EXPECT_NEAR(m.length, 7.0, 1e-12);
    EXPECT_EQ(m.turns, 1);
    EXPECT_EQ(m.coverage, 0.0);
}

TEST(Metrics, LargePlanIsFast) {
    const Decomposition d = rooms(0, 0, 150, 100);
    const MetricsInput input = inputFor(d, boustrophedon(0, 150, 0, 100));
    const auto start = std::chrono::steady_clock::now();
    const Metrics m = computeMetrics(input);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    RecordProperty("seconds", std::to_string(seconds));
    std::printf("150 m x 100 m plan, W = 1: %.3f s\n", seconds);
    EXPECT_GT(m.coverage, 0.99);
    EXPECT_NEAR(m.ideal, 15000.0, 150.0);
    EXPECT_LT(seconds, 2.0); // typically a few hundred milliseconds; slack for loaded CI
}

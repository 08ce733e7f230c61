// The wall loop's geometry (geometry/WallFollowing.h): where the loop runs, what its head
// leaves for the stripes, and how parts the robot cannot pass between are told apart.
#include "decomposition/WallFollowing.h"

#include <gtest/gtest.h>

namespace fc {
namespace {

Plan rectangle(Vec2 at, double width, double depth) {
    Plan plan;
    plan.boundary = {at, at + Vec2{width, 0}, at + Vec2{width, depth}, at + Vec2{0, depth}};
    return plan;
}

double distanceToRing(const Ring& ring, Vec2 p) {
    double best = INFINITY;
    for (size_t i = 0; i < ring.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]));
    return best;
}

TEST(WallFollowing, TheLoopRunsAtTheClearanceAndLeavesTheMiddleToTheStripes) {
    for (const Vec2 origin : {Vec2{0, 0}, Vec2{512345.0, 5432109.0}}) {
        const Plan hall = rectangle(origin, 10, 6);
        const std::optional<WallLoop> walls = wallLoop(hall, 0.3, 1.0, origin + Vec2{9, 5}, 0.25);
        ASSERT_TRUE(walls);
        // Around a 9.4 x 5.4 m rectangle, from the corner nearest (9, 5), closed.
        EXPECT_NEAR(walls->length, 2 * (9.4 + 5.4), 0.05);
        EXPECT_LT(norm(walls->loop.front() - (origin + Vec2{9.7, 5.7})), 0.02);
        EXPECT_LT(norm(walls->loop.back() - walls->loop.front()), 1e-9);
        for (const Vec2& p : walls->loop) {
            EXPECT_GE(distanceToRing(hall.boundary, p), 0.3);
            EXPECT_LE(distanceToRing(hall.boundary, p), 0.31);
        }
        // The loop runs 5 mm beyond the clearance; its head sweeps 0.5 m either side, less
        // the 2 cm kept as overlap with the stripes: 0.785 m from the walls.
        ASSERT_EQ(walls->rest.size(), 1u);
        EXPECT_EQ(walls->restRoom.front(), -1);
        EXPECT_NEAR(walls->restArea, (10 - 1.57) * (6 - 1.57), 0.02);
        EXPECT_NEAR(ringArea(walls->rest.front()), walls->restArea, 1e-6);
    }
}

TEST(WallFollowing, PartsTheRobotCannotPassBetweenHaveTheirOwnLoops) {
    // Two halls joined by a 0.4 m gap: the loop of the one asked for, or of the larger.
    Plan plan;
    plan.boundary = {{0, 0},  {8, 0},   {8, 2.8},   {8.5, 2.8}, {8.5, 0}, {12, 0},
                     {12, 6}, {8.5, 6}, {8.5, 3.2}, {8, 3.2},   {8, 6},   {0, 6}};
    const std::optional<WallLoop> small = wallLoop(plan, 0.3, 1.0, Vec2{11, 1}, 0.25);
    const std::optional<WallLoop> large = wallLoop(plan, 0.3, 1.0, std::nullopt, 0.25);
    ASSERT_TRUE(small && large);
    EXPECT_NEAR(small->length, 2 * (2.9 + 5.4), 0.05);
    EXPECT_NEAR(large->length, 2 * (7.4 + 5.4), 0.05);
    for (const Vec2& p : small->loop)
        EXPECT_GT(p.x, 8.5);
    // Without a start, the loop starts at the corner farthest from the hall's centre.
    const Vec2 first = large->loop.front();
    EXPECT_NEAR(norm(first - Vec2{4, 3}), std::hypot(3.7, 2.7), 0.02);
}

TEST(WallFollowing, TheRestIsSplitByRoomsAndWherePiecesAreSmall) {
    Plan plan = rectangle({0, 0}, 12, 6);
    plan.rooms = {{"West", {{0, 0}, {6, 0}, {6, 6}, {0, 6}}},
                  {"East", {{6, 0}, {12, 0}, {12, 6}, {6, 6}}}};
    const std::optional<WallLoop> walls = wallLoop(plan, 0.3, 1.0, Vec2{1, 1}, 0.25);
    ASSERT_TRUE(walls);
    ASSERT_EQ(walls->rest.size(), 2u);
    EXPECT_NE(walls->restRoom[0], walls->restRoom[1]);
    // A hall too small for anything but the loop leaves nothing worth a floor of its own.
    const std::optional<WallLoop> booth =
        wallLoop(rectangle({0, 0}, 2, 1.8), 0.3, 1.0, Vec2{1, 1}, 0.25);
    ASSERT_TRUE(booth);
    EXPECT_TRUE(booth->rest.empty());
    EXPECT_LT(booth->droppedArea, 0.25);
}

TEST(WallFollowing, AClearPointKeepsTheClearanceFromEveryEdge) {
    const Plan hall = rectangle({0, 0}, 4, 3);
    const std::optional<Vec2> p = clearPointNear(hall.boundary, {}, 0.3, Vec2{-1, -1});
    ASSERT_TRUE(p);
    EXPECT_GE(distanceToRing(hall.boundary, *p), 0.3);
    EXPECT_LT(norm(*p - Vec2{0.31, 0.31}), 0.05);
    EXPECT_FALSE(clearPointNear(rectangle({0, 0}, 0.5, 3).boundary, {}, 0.3, Vec2{0, 0}));
}

} // namespace
} // namespace fc

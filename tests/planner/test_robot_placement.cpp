// Start and end points placed where the robot fits (issue 16): moved off walls, refused in
// obstacles and outside the floor.
#include "model/RobotPlacement.h"

#include <gtest/gtest.h>

namespace fc {
namespace {

Plan roomWithPillar() {
    Plan plan;
    plan.boundary = {{0, 0}, {10, 0}, {10, 6}, {0, 6}};
    plan.obstacles = {{{4, 2}, {6, 2}, {6, 4}, {4, 4}}};
    return plan;
}

TEST(RobotPlacement, AClearPointStays) {
    const RobotPlacement p = placeRobot(roomWithPillar(), {2, 3}, 0.6);
    EXPECT_EQ(p.problem, PlacementProblem::None);
    EXPECT_EQ(p.moved, 0.0);
    EXPECT_DOUBLE_EQ(p.position.x, 2.0);
}

TEST(RobotPlacement, APointAtAWallMovesToWhereTheRobotFits) {
    const Plan plan = roomWithPillar();
    const RobotPlacement p = placeRobot(plan, {0.1, 3}, 0.6);
    ASSERT_EQ(p.problem, PlacementProblem::None);
    EXPECT_GE(distanceToWalls(plan, p.position), 0.3);
    EXPECT_NEAR(p.moved, 0.2, 0.03); // straight off the wall, not further
    EXPECT_NEAR(p.position.y, 3.0, 0.05);
}

TEST(RobotPlacement, ObstaclesAndOutsideAreRefused) {
    EXPECT_EQ(placeRobot(roomWithPillar(), {5, 3}, 0.6).problem, PlacementProblem::InsideObstacle);
    EXPECT_EQ(placeRobot(roomWithPillar(), {11, 3}, 0.6).problem, PlacementProblem::OutsideFloor);
}

TEST(RobotPlacement, AGapNarrowerThanTheRobotHasNoRoom) {
    Plan plan;
    plan.boundary = {{0, 0}, {10, 0}, {10, 0.5}, {0, 0.5}}; // a 0.5 m slot
    EXPECT_EQ(placeRobot(plan, {5, 0.25}, 0.6).problem, PlacementProblem::NoRoom);
    EXPECT_EQ(placeRobot(plan, {5, 0.25}, 0.4).problem, PlacementProblem::None);
}

} // namespace
} // namespace fc

// Wall teeth (model/WallTeeth.h): which bumps of a wall are cut back to its line, and
// that only floor is added.
#include "model/WallTeeth.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace fc;

namespace {

// A 12 x 9 m room; `teeth` are inserted on its left wall (x = 0) from the top down.
Ring roomWithLeftWall(const std::vector<Vec2>& leftWall) {
    Ring ring{{0, 0}, {12, 0}, {12, 9}, {0, 9}};
    ring.insert(ring.end(), leftWall.begin(), leftWall.end());
    return ring;
}

Ring turned(const Ring& ring, double deg, Vec2 offset) {
    const double c = std::cos(deg * M_PI / 180.0), s = std::sin(deg * M_PI / 180.0);
    Ring out;
    for (const Vec2& p : ring)
        out.push_back(Vec2{c * p.x - s * p.y, s * p.x + c * p.y} + offset);
    return out;
}

TEST(WallTeeth, APilasterIsCutBackToItsWall) {
    Plan plan;
    plan.boundary = roomWithLeftWall({{0, 6.3}, {0.08, 6.3}, {0.08, 6.0}, {0, 6.0}});
    const ShavedTeeth shaved = shaveWallTeeth(plan, 0.18, 1.5);
    EXPECT_EQ(shaved.teeth, 1);
    EXPECT_NEAR(shaved.area, 0.08 * 0.3, 1e-9);
    EXPECT_NEAR(std::abs(signedArea(shaved.plan.boundary)), 12.0 * 9.0, 1e-9);
    // The room's corners stay.
    for (const Vec2 corner : {Vec2{0, 0}, Vec2{12, 0}, Vec2{12, 9}, Vec2{0, 9}})
        EXPECT_NE(std::find(shaved.plan.boundary.begin(), shaved.plan.boundary.end(), corner),
                  shaved.plan.boundary.end());
}

TEST(WallTeeth, OnlyShallowShortBumpsOfAStraightWallAreCut) {
    Plan plan;
    // Too deep (0.3 m), too long (2 m), a notch into the wall, a jog (the wall goes on 5 cm
    // further in) and a traced tooth of three points.
    plan.boundary = roomWithLeftWall({{0, 8.5},
                                      {0.3, 8.5},
                                      {0.3, 8.2},
                                      {0, 8.2},
                                      {0, 7.8},
                                      {0.1, 7.8},
                                      {0.1, 5.8},
                                      {0, 5.8},
                                      {0, 5.5},
                                      {-0.1, 5.5},
                                      {-0.1, 5.2},
                                      {0, 5.2},
                                      {0, 4.0},
                                      {0.04, 3.9},
                                      {0.02, 3.75},
                                      {0, 3.6},
                                      {0, 2.0},
                                      {0.05, 2.0},
                                      {0.05, 0.0}});
    plan.boundary.erase(plan.boundary.begin()); // the jog replaces the corner (0, 0)
    const ShavedTeeth shaved = shaveWallTeeth(plan, 0.18, 1.5);
    EXPECT_EQ(shaved.teeth, 1); // the traced tooth only
    EXPECT_EQ(shaved.plan.boundary.size(), plan.boundary.size() - 2);
}

TEST(WallTeeth, ObstaclesAndTurnedPlansLoseTheirTeethToo) {
    Plan plan;
    plan.boundary = roomWithLeftWall({{0, 6.3}, {0.08, 6.3}, {0.08, 6.0}, {0, 6.0}});
    // A 2 x 2 m pillar with a 6 cm bump on its right face, either orientation.
    plan.obstacles.push_back(
        {{5, 3}, {7, 3}, {7, 3.8}, {7.06, 3.8}, {7.06, 4.2}, {7, 4.2}, {7, 5}, {5, 5}});
    for (const bool reversed : {false, true}) {
        Plan p = plan;
        if (reversed)
            std::reverse(p.obstacles[0].begin(), p.obstacles[0].end());
        for (const double deg : {0.0, 33.0, 90.0}) {
            Plan q = p;
            const Vec2 utm{512345.0, 5412345.0};
            q.boundary = turned(q.boundary, deg, utm);
            q.obstacles[0] = turned(q.obstacles[0], deg, utm);
            const ShavedTeeth shaved = shaveWallTeeth(q, 0.18, 1.5);
            EXPECT_EQ(shaved.teeth, 2) << deg << (reversed ? " reversed" : "");
            EXPECT_NEAR(shaved.area, 0.08 * 0.3 + 0.06 * 0.4, 1e-6) << deg;
            EXPECT_NEAR(std::abs(signedArea(shaved.plan.obstacles[0])), 4.0, 1e-6) << deg;
        }
    }
}

TEST(WallTeeth, NothingIsCutWhereTheDepthOrSpanIsZero) {
    Plan plan;
    plan.boundary = roomWithLeftWall({{0, 6.3}, {0.08, 6.3}, {0.08, 6.0}, {0, 6.0}});
    EXPECT_EQ(shaveWallTeeth(plan, 0.0, 1.5).teeth, 0);
    EXPECT_EQ(shaveWallTeeth(plan, 0.18, 0.0).teeth, 0);
    EXPECT_EQ(shaveWallTeeth(plan, std::nan(""), 1.5).teeth, 0);
}

} // namespace

// Wall teeth cut back for planning (pipeline/ShavedTeethOffer.h), checked by the independent
// checker against the walls as drawn: pilasters and a radiator on every wall of a room at any
// rotation plan as the room without them, and where the path would pass a tooth closer than
// L/2, the floor as drawn is planned instead.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "pipeline/Planner.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace fcgen {
namespace {

fc::Ring turned(const fc::Ring& ring, double deg, fc::Vec2 offset) {
    const double c = std::cos(deg * M_PI / 180.0), s = std::sin(deg * M_PI / 180.0);
    fc::Ring out;
    for (const fc::Vec2& p : ring)
        out.push_back(fc::Vec2{c * p.x - s * p.y, s * p.x + c * p.y} + offset);
    return out;
}

// A 12 x 9 m room; depth > 0: pilasters 0.3 m wide that deep on every wall, 3 m apart, and a
// radiator 1.2 m long on the top wall.
fc::Ring pilasterRoom(double depth) {
    fc::Ring r{{0, 0}};
    if (depth > 0)
        for (double x : {3.0, 6.0, 9.0})
            r.insert(r.end(), {{x, 0}, {x, depth}, {x + 0.3, depth}, {x + 0.3, 0}});
    r.push_back({12, 0});
    if (depth > 0)
        for (double y : {3.0, 6.0})
            r.insert(r.end(), {{12, y}, {12 - depth, y}, {12 - depth, y + 0.3}, {12, y + 0.3}});
    r.push_back({12, 9});
    if (depth > 0) {
        r.insert(r.end(), {{9.3, 9}, {9.3, 9 - depth}, {8.1, 9 - depth}, {8.1, 9}});
        r.insert(r.end(), {{3.3, 9}, {3.3, 9 - depth}, {3, 9 - depth}, {3, 9}});
    }
    r.push_back({0, 9});
    if (depth > 0)
        for (double y : {6.0, 3.0})
            r.insert(r.end(), {{0, y + 0.3}, {depth, y + 0.3}, {depth, y}, {0, y}});
    return r;
}

void expectClearAndCovered(const fc::PlanRequest& request, const fc::PlanResult& result) {
    const fccheck::Report check =
        fccheck::checkPath(freeSpaceOf(request.plan), {}, polylineOf(result.path.points),
                           request.robot.robotDiameter, request.robot.coverageWidth);
    EXPECT_TRUE(check.collisionFree);
    EXPECT_GE(check.coverage, 0.99);
}

TEST(TeethChecked, PilastersOnEveryWallPlanAsTheRoomWithoutThem) {
    for (const double deg : {0.0, 27.0}) {
        const fc::Vec2 utm = deg > 0 ? fc::Vec2{512345.0, 5412345.0} : fc::Vec2{};
        fc::Plan plain;
        plain.boundary = turned(pilasterRoom(0), deg, utm);
        const fc::PlanResult room = fc::planCoverage(defaultRequest(plain));
        for (const double depth : {0.05, 0.1}) {
            fc::Plan toothed;
            toothed.boundary = turned(pilasterRoom(depth), deg, utm);
            const fc::PlanRequest request = defaultRequest(toothed);
            const fc::PlanResult result = fc::planCoverage(request);
            fc::PlanRequest asDrawn = request;
            asDrawn.shaveTeeth = false;
            const fc::PlanResult drawn = fc::planCoverage(asDrawn);
            std::printf("%.0f deg, teeth %.2f m: %.1f s (%d teeth cut), as drawn %.1f s, the "
                        "room without them %.1f s\n",
                        deg, depth, result.metrics.time, result.shavedTeeth, drawn.metrics.time,
                        room.metrics.time);
            EXPECT_EQ(result.shavedTeeth, 9);
            EXPECT_LE(result.metrics.time, 1.005 * room.metrics.time);
            EXPECT_LT(result.metrics.time, 0.97 * drawn.metrics.time);
            EXPECT_GE(result.metrics.coverage, 0.995);
            expectClearAndCovered(request, result);
        }
    }
}

TEST(TeethChecked, APathThatWouldGrazeAToothPlansTheFloorAsDrawn) {
    // A passage 0.75 m wide between two 4 m rooms, with a 10 cm tooth in it: cut back, the
    // passage's middle runs 0.275 m from the tooth, under L/2 = 0.3 m.
    fc::Plan plan;
    plan.boundary = {{0, 0},       {4, 0},    {4, 1.6},  {6, 1.6},     {6, 0},       {10, 0},
                     {10, 4},      {6, 4},    {6, 2.35}, {5.15, 2.35}, {5.15, 2.25}, {4.85, 2.25},
                     {4.85, 2.35}, {4, 2.35}, {4, 4},    {0, 4}};
    const fc::PlanRequest request = defaultRequest(plan);
    const fc::PlanResult result = fc::planCoverage(request);
    EXPECT_EQ(result.shavedTeeth, 0);
    expectClearAndCovered(request, result);
}

} // namespace
} // namespace fcgen

// Rings (pipeline/RingsOffer.h), checked by the independent checker: a curved corridor with a
// room off it plans as loops along its walls, far faster than stripes, clear of the walls and
// covered; a rectilinear room and a fixed sweep angle keep their stripes.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "pipeline/Planner.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace fcgen {
namespace {

// A corridor 2.2 m wide on an arc of 120 degrees (inner radius 6 m, drawn with 10 cm
// segments), turned and shifted; a 3 x 3 m room off its outer wall through a 1.2 m door
// (without: no room).
fc::Plan curvedCorridor(double deg, fc::Vec2 offset, double width = 2.2, bool withRoom = true) {
    const double inner = 6.0, outer = inner + width, sweep = 2.0 * M_PI / 3.0;
    fc::Plan plan;
    const int steps = static_cast<int>(std::ceil(sweep * outer / 0.1));
    const double middle = 0.5 * sweep, doorHalf = 0.6 / outer;
    bool roomDrawn = !withRoom;
    for (int k = 0; k <= steps; ++k) {
        const double a = sweep * k / steps;
        if (!withRoom || std::abs(a - middle) > doorHalf) {
            plan.boundary.push_back({outer * std::cos(a), outer * std::sin(a)});
            continue;
        }
        if (roomDrawn)
            continue;
        // The room round the middle of the arc, from the door's near jamb to its far one.
        const fc::Vec2 u{std::cos(middle), std::sin(middle)}, t{-u.y, u.x};
        for (const auto& [r, s] : {std::pair{outer, -0.6},
                                   {outer + 0.2, -0.6},
                                   {outer + 0.2, -1.5},
                                   {outer + 3.2, -1.5},
                                   {outer + 3.2, 1.5},
                                   {outer + 0.2, 1.5},
                                   {outer + 0.2, 0.6},
                                   {outer, 0.6}})
            plan.boundary.push_back(u * r + t * s);
        roomDrawn = true;
    }
    for (int k = steps; k >= 0; --k) {
        const double a = sweep * k / steps;
        plan.boundary.push_back({inner * std::cos(a), inner * std::sin(a)});
    }
    return transformPlan(plan, deg, offset);
}

fccheck::Report check(const fc::PlanRequest& request, const fc::PlanResult& result) {
    return fccheck::checkPath(freeSpaceOf(request.plan), {}, polylineOf(result.path.points),
                              request.robot.robotDiameter, request.robot.coverageWidth);
}

TEST(RingsChecked, ACurvedCorridorPlansAsLoopsAlongItsWalls) {
    for (const double deg : {0.0, 33.0}) {
        const fc::Vec2 utm = deg > 0 ? fc::Vec2{512345.0, 5412345.0} : fc::Vec2{};
        const fc::PlanRequest request = defaultRequest(curvedCorridor(deg, utm));
        const fc::PlanResult result = fc::planCoverage(request);
        fc::PlanRequest striped = request;
        striped.wallLoop = false; // no wall loop, no rings
        const fc::PlanResult stripes = fc::planCoverage(striped);
        std::printf("%.0f deg: rings %d, %.1f m, %d turns, %.1f s; stripes %.1f m, %d turns, "
                    "%.1f s\n",
                    deg, result.rings, result.metrics.length, result.metrics.turns,
                    result.metrics.time, stripes.metrics.length, stripes.metrics.turns,
                    stripes.metrics.time);
        EXPECT_TRUE(result.rings);
        EXPECT_FALSE(stripes.rings);
        EXPECT_LT(result.metrics.time, 0.8 * stripes.metrics.time);
        EXPECT_GE(result.metrics.coverage, 0.995);
        const fccheck::Report report = check(request, result);
        EXPECT_TRUE(report.collisionFree);
        EXPECT_GE(report.coverage, 0.995);
    }
}

// A corridor 2.5 m wide: the loop along each wall sweeps 0.8 m of it, and the 0.9 m between
// them is driven once along its spine (geometry/SkeletonSpine.h), not round by a loop.
TEST(RingsChecked, TheMiddleOfACorridorIsDrivenOnceAlongItsSpine) {
    for (const double deg : {0.0, 47.0}) {
        const fc::Vec2 utm = deg > 0 ? fc::Vec2{512345.0, 5412345.0} : fc::Vec2{};
        const fc::PlanRequest request = defaultRequest(curvedCorridor(deg, utm, 2.5, false));
        const fc::PlanResult result = fc::planCoverage(request);
        double spine = 0.0;
        const fc::CoveragePath& path = result.path;
        for (size_t i = 1; i < path.points.size(); ++i)
            if (path.kinds[i - 1] == fc::SegmentKind::Stripe)
                spine += fc::norm(path.points[i] - path.points[i - 1]);
        const double middleArc = 7.25 * 2.0 * M_PI / 3.0;
        std::printf("%.0f deg: rings %d, %.1f m, %d turns, %.1f s, spine %.1f m of a %.1f m arc\n",
                    deg, result.rings, result.metrics.length, result.metrics.turns,
                    result.metrics.time, spine, middleArc);
        EXPECT_TRUE(result.rings);
        EXPECT_GT(spine, 0.8 * middleArc);
        EXPECT_LT(spine, 1.05 * middleArc);
        const fccheck::Report report = check(request, result);
        EXPECT_TRUE(report.collisionFree);
        EXPECT_GE(report.coverage, 0.995);
    }
}

// A rotunda round a column with a pillar beside it (the generator's round walls, seed 12):
// the slivers the loops leave round the column are taken in one tour round it
// (pipeline/RingTour.h), where nearest first crossed back and forth (99.3 m, 290.6 s).
TEST(RingsChecked, TheSliversRoundAColumnAreTakenInOneTour) {
    const GeneratedPlan generated = generatePlan(Family::RoundWalls, 12);
    const fc::PlanRequest request = defaultRequest(generated.plan);
    const fc::PlanResult result = fc::planCoverage(request);
    std::printf("%s: rings %d, %.1f m, %d turns, %.1f s\n", generated.description.c_str(),
                result.rings, result.metrics.length, result.metrics.turns, result.metrics.time);
    EXPECT_TRUE(result.rings);
    EXPECT_LT(result.metrics.time, 260.0);
    const fccheck::Report report = check(request, result);
    EXPECT_TRUE(report.collisionFree);
    EXPECT_GE(report.coverage, 0.995);
}

TEST(RingsChecked, StripesWhereTheyAreFasterOrTheAngleIsFixed) {
    fc::Plan room;
    room.boundary = {{0, 0}, {12, 0}, {12, 9}, {0, 9}};
    EXPECT_FALSE(fc::planCoverage(defaultRequest(room)).rings);
    fc::PlanRequest fixed = defaultRequest(curvedCorridor(0.0, {}));
    fixed.sweep.perRoom = false;
    fixed.sweep.angleDeg = 90.0;
    const fc::PlanResult result = fc::planCoverage(fixed);
    EXPECT_FALSE(result.rings);
    EXPECT_TRUE(check(fixed, result).collisionFree);
}

} // namespace
} // namespace fcgen

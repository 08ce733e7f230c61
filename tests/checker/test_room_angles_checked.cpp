// Rooms whose walls run two ways (pipeline/RoomAngles.h, roomSecondAngles) on generated
// slanted rooms, checked by the independent checker: trying a room along its second wall
// family never costs the plan the building's family, which stays on the layouts' offer.
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "pipeline/Planner.h"
#include "pipeline/RoomAngles.h"

#include <cstdio>
#include <gtest/gtest.h>

namespace fcgen {
namespace {

TEST(RoomAnglesChecked, ASecondFamilyNeverLosesTheBuildingsFamily) {
    int twoWay = 0;
    for (std::uint64_t seed = 51; seed <= 55; ++seed) {
        const GeneratedPlan generated = generatePlan(Family::SlantedRooms, seed);
        const fc::PlanRequest request = defaultRequest(generated.plan);
        if (fc::roomSecondAngles(request.plan, request.sweep).empty())
            continue;
        ++twoWay;
        const fc::PlanResult chosen = fc::planCoverage(request);
        fc::PlanRequest familyOnly = request;
        familyOnly.sweep.roomAngles = fc::familyAngles(request.plan, request.sweep);
        familyOnly.sweep.roomAngles.erase("");
        const fc::PlanResult family = fc::planCoverage(familyOnly);
        std::printf("%-70s %.1f s, family alone %.1f s\n", generated.description.c_str(),
                    chosen.metrics.time, family.metrics.time);
        // Within choosePlan's 1% time tie, where the shorter path wins.
        EXPECT_LE(chosen.metrics.time, 1.01 * family.metrics.time) << generated.description;
        const double L = request.robot.robotDiameter, W = request.robot.coverageWidth;
        const fccheck::Report check =
            fccheck::checkPath(freeSpaceOf(request.plan), {}, polylineOf(chosen.path.points), L, W);
        EXPECT_TRUE(check.collisionFree) << generated.description;
        EXPECT_GE(check.coverage, 0.99) << generated.description;
    }
    EXPECT_GE(twoWay, 3); // the generator's convex rooms have no two walls parallel
}

} // namespace
} // namespace fcgen

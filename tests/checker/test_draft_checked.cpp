// The live replanning draft (fc::draftCoverage) checked by the independent checker on
// generated floors of every family (rotated offices, 0.9 m doors, slanted rooms, a star
// room, a pillar hall): its path keeps clear of the walls, and the loss it reports agrees
// with the checker's (the draft skips the wall touch-ups, so it may leave more).
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/PreparedPlans.h"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace fcgen {
namespace {

TEST(DraftChecked, ClearOfTheWallsAndReportsWhatItMisses) {
    for (Family family : allFamilies()) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            const GeneratedPlan generated = generatePlan(family, seed);
            const fc::PlanRequest request = defaultRequest(generated.plan);
            const fc::PreparedPlans plans(request.plan, request.robot, true);
            fc::PlanResult draft;
            try {
                draft = fc::draftCoverage(request, plans);
            } catch (const fc::InputError& e) {
                ADD_FAILURE() << generated.description << ": " << e.what();
                continue;
            }
            const double L = request.robot.robotDiameter, W = request.robot.coverageWidth;
            const fccheck::Report check = fccheck::checkPath(freeSpaceOf(request.plan), {},
                                                             polylineOf(draft.path.points), L, W);
            EXPECT_TRUE(check.collisionFree) << generated.description;
            EXPECT_NEAR(draft.metrics.uncoveredArea, check.uncoveredArea,
                        kUncoveredAgreement * check.floorArea)
                << generated.description;
            EXPECT_GE(check.coverage, 0.9) << generated.description;
            std::printf("%-70s draft coverage %.4f, length %.1f m\n", generated.description.c_str(),
                        check.coverage, draft.metrics.length);
        }
    }
}

// The warm-started sketch (live replanning after a room is unticked, following the path shown
// before) on the same generated floors: still clear of the walls by the independent checker,
// and never slower than the cold sketch of the same query.
TEST(DraftChecked, WarmStartedSketchStaysClearAndIsNeverSlower) {
    int checked = 0;
    for (Family family : allFamilies()) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            const GeneratedPlan generated = generatePlan(family, seed);
            const fc::PlanRequest request = defaultRequest(generated.plan);
            if (request.plan.rooms.size() < 2)
                continue;
            const fc::PreparedPlans plans(request.plan, request.robot, true);
            fc::PlanRequest edited = request;
            for (size_t i = 1; i < request.plan.rooms.size(); ++i)
                edited.rooms.push_back(request.plan.rooms[i].name);
            fc::PlanResult before, cold, warm;
            try {
                before = fc::draftCoverage(request, plans);
                cold = fc::draftCoverage(edited, plans);
                edited.previousPath = before.path;
                edited.previousAngles = fc::roomAnglesOf(before, request.plan);
                warm = fc::draftCoverage(edited, plans);
            } catch (const fc::InputError& e) {
                ADD_FAILURE() << generated.description << ": " << e.what();
                continue;
            }
            const fccheck::Report check =
                fccheck::checkPath(freeSpaceOf(request.plan), {}, polylineOf(warm.path.points),
                                   request.robot.robotDiameter, request.robot.coverageWidth);
            EXPECT_TRUE(check.collisionFree) << generated.description;
            ++checked;
            std::printf("%-70s warm sketch %.0f s, cold %.0f s\n", generated.description.c_str(),
                        warm.metrics.time, cold.metrics.time);
            EXPECT_LE(warm.metrics.time, cold.metrics.time * (1 + 1e-9)) << generated.description;
            EXPECT_NEAR(warm.metrics.requiredArea, cold.metrics.requiredArea,
                        1e-6 * cold.metrics.requiredArea)
                << generated.description;
        }
    }
    EXPECT_GE(checked, 4); // the families with rooms
}

} // namespace
} // namespace fcgen

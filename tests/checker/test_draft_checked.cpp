// The live replanning draft (fc::draftCoverage) checked by the independent checker on
// generated floors of every family (rotated offices, 0.9 m doors, slanted rooms, a star
// room, a pillar hall): its path keeps clear of the walls, and the loss it reports agrees
// with the checker's (the draft skips the wall touch-ups, so it may leave more).
#include "PlanGenerator.h"
#include "PropertyCheck.h"
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

} // namespace
} // namespace fcgen

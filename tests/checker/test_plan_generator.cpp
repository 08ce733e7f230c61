// The random plan generator: valid, deterministic per seed, the hard features it promises.
#include "PlanGenerator.h"
#include "model/Validation.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace fcgen;

namespace {

double planArea(const fc::Plan& plan) {
    double area = fc::ringArea(plan.boundary);
    for (const fc::Ring& o : plan.obstacles)
        area -= fc::ringArea(o);
    return area;
}

} // namespace

TEST(PlanGenerator, EveryFamilyMakesValidPlansDeterministically) {
    for (Family family : allFamilies()) {
        int utm = 0;
        for (std::uint64_t seed = 1; seed <= 12; ++seed) {
            const GeneratedPlan g = generatePlan(family, seed);
            SCOPED_TRACE(g.description);
            EXPECT_NO_THROW(fc::validatePlan(fc::normalizedPlan(g.plan), fc::RobotProfile{}));
            const GeneratedPlan again = generatePlan(family, seed);
            ASSERT_EQ(again.plan.boundary.size(), g.plan.boundary.size());
            EXPECT_EQ(again.plan.boundary.front(), g.plan.boundary.front());
            EXPECT_EQ(again.description, g.description);
            // The checker's floor is the planner's free area.
            const double area = planArea(g.plan);
            EXPECT_GT(area, 5.0);
            EXPECT_NEAR(fccheck::floorArea(freeSpaceOf(g.plan), {}), area, 1e-6 * area);
            utm += g.offset.x > 4e5;
        }
        EXPECT_GT(utm, 0) << familyName(family) << ": no draw with a UTM-sized offset";
        EXPECT_LT(utm, 12) << familyName(family) << ": every draw with a UTM-sized offset";
    }
}

TEST(PlanGenerator, TransformKeepsShapes) {
    const GeneratedPlan g = generatePlan(Family::DoorRooms, 3);
    const fc::Plan moved = transformPlan(g.plan, 123.4, {1000.0, -2000.0});
    EXPECT_NEAR(planArea(moved), planArea(g.plan), 1e-6);
    const fc::Plan back = transformPlan(transformPlan(moved, 0.0, {-1000.0, 2000.0}), -123.4, {});
    for (std::size_t i = 0; i < back.boundary.size(); ++i)
        EXPECT_NEAR(fc::distance(back.boundary[i], g.plan.boundary[i]), 0.0, 1e-6);
}

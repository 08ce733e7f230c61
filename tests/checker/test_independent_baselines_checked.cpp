// The independent baselines (baselines/IndependentBaselines.h: adjacency-ga, reeb-cpp)
// checked by the independent checker: their paths keep L/2 from every wall and sweep at least 99%
// of what the disc can sweep, on the sample plans and on generated floors at odd rotations (slanted
// walls, stars with obstacles, doors, UTM-sized offsets).
#include "PlanGenerator.h"
#include "PropertyCheck.h"
#include "formats/PlanIO.h"

#include <gtest/gtest.h>

namespace fcgen {
namespace {

void expectValid(const fc::Plan& plan, const std::string& what) {
    for (const char* solver : {"adjacency-ga", "reeb-cpp"}) {
        fc::PlanRequest request = defaultRequest(plan);
        request.solver = solver;
        const Outcome o = planAndCheck(request);
        ASSERT_TRUE(o.planned) << solver << ", " << what << ": " << o.error;
        EXPECT_TRUE(o.collisionFree) << solver << ", " << what << ": " << o.summary();
        EXPECT_GE(o.check.coverage, 0.99) << solver << ", " << what << ": " << o.summary();
    }
}

TEST(IndependentBaselinesChecked, SamplePlans) {
    for (const char* name : {"simple", "room-obstacle", "room-notches", "simple-diamond", "office"})
        expectValid(fc::loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan,
                    name);
}

TEST(IndependentBaselinesChecked, GeneratedFloorsAtAnyRotation) {
    for (Family family : allFamilies())
        for (std::uint64_t seed : {21u, 22u}) {
            const GeneratedPlan g = generatePlan(family, seed);
            expectValid(g.plan, g.description);
        }
}

} // namespace
} // namespace fcgen

// PreparedPlans: one build per sweep angle, shared by every caller (the per-room search
// plans the same angles many times); the plans it hands out are preparePlan's.
#include "formats/PlanIO.h"
#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

#include <future>
#include <gtest/gtest.h>
#include <memory>
#include <vector>

namespace fc {
namespace {

Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

void expectSame(const PreparedPlan& a, const PreparedPlan& b) {
    ASSERT_EQ(a.decomposition.cells.size(), b.decomposition.cells.size());
    for (size_t i = 0; i < a.decomposition.cells.size(); ++i) {
        EXPECT_EQ(a.decomposition.cells[i].x0, b.decomposition.cells[i].x0);
        EXPECT_EQ(a.decomposition.cells[i].stripes, b.decomposition.cells[i].stripes);
    }
    ASSERT_EQ(a.graph.nodes.size(), b.graph.nodes.size());
    ASSERT_EQ(a.graph.edges.size(), b.graph.edges.size());
    EXPECT_EQ(a.decomposition.frame.stripeAngleDeg(), b.decomposition.frame.stripeAngleDeg());
}

TEST(PreparedPlans, HandsOutWhatPreparePlanBuilds) {
    const Plan plan = samplePlan("room-obstacle");
    const RobotProfile robot;
    const PreparedPlans plans(plan, robot, true);
    expectSame(plans.at(30.0, false), preparePlan(plan, robot, 30.0));
    // With the baselines' classic stages only when asked.
    EXPECT_FALSE(plans.at(30.0, false).classic);
    EXPECT_TRUE(plans.at(30.0, true).classic);
}

TEST(PreparedPlans, AnglesApartByRoundingShareOneBuild) {
    const Plan plan = samplePlan("simple");
    const PreparedPlans plans(plan, RobotProfile{}, true);
    const double turned = 97.15 + 3e-12; // as a sum of angles may come out
    ASSERT_NE(turned, 97.15);
    EXPECT_EQ(PreparedPlans::roundedAngle(turned), PreparedPlans::roundedAngle(97.15));
    expectSame(plans.at(turned, false), plans.at(97.15, false));
}

TEST(PreparedPlans, ConcurrentCallersGetOnePlan) {
    const Plan plan = samplePlan("office");
    const PreparedPlans plans(plan, RobotProfile{}, true);
    std::vector<std::future<PreparedPlan>> calls;
    for (int i = 0; i < 4; ++i)
        calls.push_back(std::async(std::launch::async, [&plans] { return plans.at(90.0, false); }));
    const PreparedPlan first = calls.front().get();
    for (size_t i = 1; i < calls.size(); ++i)
        expectSame(calls[i].get(), first);
}

TEST(PreparedPlans, ABadPlanThrowsToEveryCaller) {
    Plan plan = samplePlan("simple");
    plan.boundary.resize(2); // not a polygon
    const PreparedPlans plans(plan, RobotProfile{}, true);
    EXPECT_THROW(plans.at(0.0, false), InputError);
    EXPECT_THROW(plans.at(0.0, false), InputError); // the stored failure, again
}

TEST(PreparedPlans, OwnTheirPlanSoTheCallerMayMoveOn) {
    auto plan = std::make_unique<Plan>(samplePlan("simple"));
    const PreparedPlans plans(*plan, RobotProfile{}, true);
    plan.reset(); // the editor's document changes while a task still plans
    EXPECT_FALSE(plans.at(90.0, false).graph.nodes.empty());
}

// The editor keeps one PreparedPlans across requests (live replanning): a plan made with it
// is the plan made without it, for every sweep mode.
TEST(PreparedPlans, SharedAcrossRequestsPlanAsWithout) {
    PlanRequest request =
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/room-obstacle.geojson"));
    request.solver = "greedy";
    const PreparedPlans plans(request.plan, request.robot, true);
    for (int mode = 0; mode < 3; ++mode) {
        request.sweep.perRoom = mode == 0;
        request.sweep.automatic = mode == 1;
        request.sweep.angleDeg = 90.0;
        const PlanResult alone = planCoverage(request);
        const PlanResult shared = planCoverage(request, {}, &plans);
        EXPECT_NEAR(shared.metrics.length, alone.metrics.length, 1e-6) << "mode " << mode;
        EXPECT_EQ(shared.metrics.turns, alone.metrics.turns) << "mode " << mode;
    }
}

// The draft of live replanning: the greedy solver at the family angles, a plan of the same
// floor and query that covers it, made from the shared cells and graphs.
TEST(PreparedPlans, DraftPlansTheSameQueryQuickly) {
    for (const char* name : {"office", "ward"}) {
        PlanRequest request =
            planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson"));
        request.solver = "exact"; // the draft never runs the requested solver
        const PreparedPlans plans(request.plan, request.robot, true);
        const PlanResult draft = draftCoverage(request, plans);
        EXPECT_FALSE(draft.path.empty()) << name;
        EXPECT_GE(draft.metrics.coverage, 0.98) << name;
        PlanRequest greedy = request;
        greedy.solver = "greedy";
        const PlanResult full = planCoverage(greedy, {}, &plans);
        EXPECT_NEAR(draft.metrics.requiredArea, full.metrics.requiredArea,
                    1e-6 * full.metrics.requiredArea)
            << name;
        // A room left out of the query is left out of the draft.
        request.rooms = {request.plan.rooms.front().name};
        const PlanResult one = draftCoverage(request, plans);
        EXPECT_LT(one.metrics.requiredArea, 0.8 * draft.metrics.requiredArea) << name;
    }
}

} // namespace
} // namespace fc

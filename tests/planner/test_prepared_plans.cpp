// PreparedPlans: one build per sweep angle, shared by every caller (the per-room search
// plans the same angles many times); the plans it hands out are preparePlan's.
#include "decomposition/FloorCache.h"
#include "formats/PlanIO.h"
#include "pipeline/PerRoomSweep.h"
#include "pipeline/Planner.h"
#include "pipeline/PreparedPlans.h"

#include <algorithm>
#include <cmath>
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

// Live replanning's sketch is warm-started from the path shown before the edit: the same query
// gives back that plan's walk (its cells at its angles, in its order), and another query a
// path never slower than the cold sketch's (greedy also walks the hinted order; the faster
// path is kept), here mostly faster.
TEST(DraftWarmStart, FollowsThePlanShownBeforeTheEdit) {
    const PlanRequest request =
        planRequestFor(loadProjectFile(std::string(FC_PLANS_DIR) + "/ward.geojson"));
    const PreparedPlans plans(request.plan, request.robot, true);
    const PlanResult full = planCoverage(request, {}, &plans);

    PlanRequest same = request;
    same.previousPath = full.path;
    same.previousAngles = roomAnglesOf(full, request.plan);
    const PlanResult again = draftCoverage(same, plans);
    EXPECT_NEAR(again.metrics.time, full.metrics.time, 1e-6 * full.metrics.time);
    EXPECT_LT(again.metrics.time, draftCoverage(request, plans).metrics.time);

    int faster = 0, rooms = 0;
    for (const Room& left : request.plan.rooms) {
        PlanRequest edited = request; // `left` unticked
        for (const Room& room : request.plan.rooms)
            if (room.name != left.name)
                edited.rooms.push_back(room.name);
        const double cold = draftCoverage(edited, plans).metrics.time;
        edited.previousPath = same.previousPath;
        edited.previousAngles = same.previousAngles;
        const double warm = draftCoverage(edited, plans).metrics.time;
        EXPECT_LE(warm, cold * (1 + 1e-9)) << left.name;
        faster += warm < 0.99 * cold;
        ++rooms;
    }
    EXPECT_GE(faster, rooms / 2);
}

// The hint maps a path to the cells of any decomposition of the floor: cells the path swept
// in its order, the others right after their nearest swept neighbour.
TEST(DraftWarmStart, OrderHintRanksCellsAlongThePath) {
    const Plan plan = samplePlan("office");
    const PreparedPlan prepared = preparePlan(plan, RobotProfile{}, 90.0);
    PlanRequest request;
    request.plan = plan;
    request.solver = "greedy";
    const PlanResult planned = planAtAngle(request, 90.0);
    const std::vector<double> rank = orderHintFrom(prepared, planned.path);
    ASSERT_EQ(rank.size(), prepared.decomposition.cells.size());
    // Cells in the walk's order have increasing ranks.
    double last = -1.0;
    for (int cell : planned.solution.cellOrder) {
        EXPECT_GT(rank[cell], last) << "cell " << cell;
        last = rank[cell];
    }
    for (double r : rank)
        EXPECT_TRUE(std::isfinite(r));
    EXPECT_TRUE(orderHintFrom(prepared, CoveragePath{}).empty());
}

// Live replanning keeps one FloorCache across edits: an edit of the rooms leaves the free space
// as it was, so its clearance field and metrics raster are reused; a wall edit makes new ones.
TEST(FloorCache, ARoomEditReusesTheFloorAndAWallEditDoesNot) {
    const Plan plan = samplePlan("office");
    const RobotProfile robot;
    auto cache = std::make_shared<FloorCache>();
    const PreparedPlans before(plan, robot, true, cache);
    const PreparedPlan a = before.at(90.0, false);

    Plan roomEdited = plan;
    Ring& outline = roomEdited.rooms.front().outline;
    Vec2 centre;
    for (const Vec2& p : outline)
        centre = centre + p * (1.0 / static_cast<double>(outline.size()));
    outline[0] = outline[0] + (centre - outline[0]) * (0.1 / distance(centre, outline[0]));
    const PreparedPlan b = PreparedPlans(roomEdited, robot, true, cache).at(90.0, false);
    EXPECT_EQ(a.decomposition.clearanceField, b.decomposition.clearanceField);
    EXPECT_EQ(a.decomposition.derived, b.decomposition.derived);
    // The decomposition itself is of the edited rooms: what a fresh preparation builds.
    expectSame(b, preparePlan(roomEdited, robot, 90.0));

    Plan wallEdited = plan;
    wallEdited.boundary[0] = wallEdited.boundary[0] + Vec2{-0.1, -0.1};
    const PreparedPlan c = PreparedPlans(wallEdited, robot, true, cache).at(90.0, false);
    EXPECT_NE(a.decomposition.clearanceField, c.decomposition.clearanceField);
    EXPECT_NE(a.decomposition.derived, c.decomposition.derived);
    // Another robot radius is another clearance field.
    RobotProfile larger = robot;
    larger.robotDiameter = 0.8;
    const PreparedPlan d = PreparedPlans(plan, larger, true, cache).at(90.0, false);
    EXPECT_NE(a.decomposition.clearanceField, d.decomposition.clearanceField);
}

TEST(FloorCache, KeepsTheMostRecentFloors) {
    FloorCache cache;
    auto square = [](double size) {
        return std::vector<Ring>{{{0, 0}, {size, 0}, {size, size}, {0, size}}};
    };
    const auto first = cache.partsFor(square(10), 0.3, 0.5).clearance;
    EXPECT_EQ(cache.partsFor(square(10), 0.3, 0.5).clearance, first);
    EXPECT_NE(cache.partsFor(square(10), 0.3, 0.4).clearance, first);
    for (size_t i = 0; i < FloorCache::kCapacity; ++i)
        cache.partsFor(square(11.0 + static_cast<double>(i)), 0.3, 0.5);
    EXPECT_NE(cache.partsFor(square(10), 0.3, 0.5).clearance, first); // evicted, made again
}

// Metrics measured with the cached floor raster equal those measured afresh, for every path
// of the floor (the raster holds the floor only; the rooms asked for are painted per call).
TEST(FloorCache, MetricsWithTheCachedRasterEqualFreshOnes) {
    const Plan plan = samplePlan("ward");
    PlanRequest request;
    request.plan = plan;
    request.solver = "greedy";
    auto cache = std::make_shared<FloorCache>();
    const PreparedPlans plans(plan, request.robot, true, cache);
    for (const std::vector<std::string>& rooms :
         {std::vector<std::string>{}, std::vector<std::string>{plan.rooms.front().name},
          std::vector<std::string>{plan.rooms.back().name, plan.rooms.front().name}}) {
        request.rooms = rooms;
        const PlanResult cached = planAtAngle(request, 90.0, {}, &plans);
        PreparedPlan uncached = cached.prepared;
        uncached.decomposition.derived.reset();
        const std::vector<std::string> required =
            rooms.empty() ? uncached.decomposition.roomNames : rooms;
        const Metrics fresh = measurePath(uncached, required, cached.path);
        const Metrics again = measurePath(cached.prepared, required, cached.path);
        for (const Metrics* m : {&fresh, &again}) {
            EXPECT_EQ(m->requiredArea, cached.metrics.requiredArea);
            EXPECT_EQ(m->sweepableArea, cached.metrics.sweepableArea);
            EXPECT_EQ(m->coveredArea, cached.metrics.coveredArea);
            EXPECT_EQ(m->uncovered.size(), cached.metrics.uncovered.size());
            EXPECT_TRUE(m->overlaps.empty()); // measured for ranking only
        }
        // The overlaps handed out with the plan are those of the path on either raster.
        PlanResult refreshed = cached;
        refreshed.prepared = uncached;
        withOverlaps(refreshed);
        EXPECT_FALSE(cached.metrics.overlaps.empty());
        EXPECT_EQ(refreshed.metrics.overlaps.size(), cached.metrics.overlaps.size());
    }
}

// On the dense lattice a sliver between two slices has no stripe; the corner the graph keeps
// at its middle joins nothing. An end point placed there still ends the path: it is joined to
// the nearest corner of a cell the robot sweeps.
TEST(PreparedPlans, AnEndBesideASweptSliverJoinsASweptCell) {
    Plan plan;
    plan.boundary = {{0, 0}, {10, 0}, {10, 8}, {0, 8}};
    plan.obstacles = {{{3.0, 2.0}, {3.0, 2.2}, {3.2, 2.2}, {3.2, 2.0}},
                      {{3.4, 5.0}, {3.4, 5.2}, {3.6, 5.2}, {3.6, 5.0}}};
    PlanRequest request;
    request.plan = plan;
    request.robot.robotDiameter = 0.6;
    request.solver = "greedy";
    const PreparedPlans dense(plan, request.robot, true, nullptr, LatticeMode::Dense);
    const Decomposition& d = dense.shared(90.0, false)->decomposition;
    int tried = 0;
    for (const Cell& c : d.cells) {
        if (!c.sweptByNeighbours)
            continue;
        const double x = 0.5 * (c.x0 + c.x1);
        request.end = d.frame.toWorld({x, 0.5 * (c.floorAt(x) + c.ceilingAt(x))});
        PlanResult result;
        ASSERT_NO_THROW(result = planAtAngle(request, 90.0, {}, &dense)) << c.id;
        EXPECT_LT(distance(result.path.points.back(), *request.end), 1e-6) << c.id;
        ++tried;
    }
    EXPECT_GT(tried, 0);
}

// planCoverage's first plan beside a wall loop on a large floor (singleFinalist) plans only
// the per-room search's best screened candidate: one finalist instead of the family and the
// two best, and at most kTimeTie faster than what the whole search keeps (the search's
// finalists include that candidate).
TEST(PerRoomSearch, ASingleFinalistIsTheBestScreenedCandidateAlone) {
    PlanRequest request;
    request.plan = samplePlan("office");
    const PreparedPlans plans(request.plan, request.robot, true);
    std::vector<double> fractions;
    SolveControl control;
    control.progress = [&fractions](double fraction) { fractions.push_back(fraction); };
    auto finalistSteps = [&fractions] { // a report as each finalist after the first is taken
        return std::count_if(fractions.begin(), fractions.end(),
                             [](double f) { return f > 0.5 && f < 1.0; });
    };
    const PlanResult all = planPerRoom(request, control, &plans);
    EXPECT_GT(finalistSteps(), 0);
    fractions.clear();
    request.singleFinalist = true;
    const PlanResult one = planPerRoom(request, control, &plans);
    EXPECT_EQ(finalistSteps(), 0);
    EXPECT_TRUE(completePlan(one.metrics));
    EXPECT_LE(all.metrics.time, one.metrics.time * (1 + kTimeTie) + 1e-9);
}

} // namespace
} // namespace fc

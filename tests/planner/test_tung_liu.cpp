// The independent adjacency-ga (baselines/IndependentBaselines.h): independent of the planner below
// the plan model, its GA against its own dynamic programme, and its answers through the pipeline.
#include "baselines/IndependentBaselines.h"
#include "formats/PlanIO.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <set>

using namespace fc;

namespace {

Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

baselines::Options defaultOptions() {
    baselines::Options o;
    o.width = 1.0;
    o.clearance = 0.3;
    o.stripeAngleDeg = 90.0;
    o.seed = 3;
    return o;
}

bool allowed(const std::string& header) {
    return header.rfind("baselines/", 0) == 0 || header.rfind("model/", 0) == 0 ||
           header == "geometry/Geometry.h";
}

} // namespace

// Every header the baseline reaches through quoted includes, followed through the headers it
// includes in turn, is its own, the plan model's or the plain geometry's: nothing of the
// planner's decomposition, graph, solvers or path building.
TEST(BaselineIndependence, IncludesOnlyThePlanModelAndGeometry) {
    const std::filesystem::path root = FC_PLANNER_SOURCE_DIR;
    const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::vector<std::string> pending;
    for (const auto& entry : std::filesystem::directory_iterator(root / "baselines"))
        pending.push_back("baselines/" + entry.path().filename().string());
    ASSERT_GE(pending.size(), 4u);
    std::set<std::string> seen(pending.begin(), pending.end());
    while (!pending.empty()) {
        const std::string file = pending.back();
        pending.pop_back();
        std::ifstream in(root / file);
        ASSERT_TRUE(in) << file;
        std::string line;
        std::smatch m;
        while (std::getline(in, line)) {
            if (!std::regex_search(line, m, include))
                continue;
            const std::string header = m[1];
            EXPECT_TRUE(allowed(header)) << file << " includes " << header;
            if (allowed(header) && seen.insert(header).second)
                pending.push_back(header);
        }
    }
    EXPECT_TRUE(seen.count("model/Plan.h"));
}

// Tung & Liu report that their GA reaches their DP's optimum on every map; on the small
// sample plans ours does, and stays within 2% of it on every plan the DP solves.
TEST(TungLiu, GeneticAlgorithmReachesItsDynamicProgrammeOnSmallPlans) {
    for (const char* name : {"simple", "room-obstacle", "room-notches", "simple-diamond"}) {
        const Plan plan = samplePlan(name);
        const Vec2 corner = plan.bounds().minX < INFINITY
                                ? Vec2{plan.bounds().minX + 0.5, plan.bounds().minY + 0.5}
                                : Vec2{};
        const baselines::Tour ga =
            baselines::planTungLiuGa(plan, {}, corner, corner, defaultOptions());
        const std::optional<baselines::Tour> dp =
            baselines::planTungLiuDp(plan, {}, corner, corner, defaultOptions(), 16);
        ASSERT_TRUE(dp) << name << ": " << ga.cells << " cells";
        EXPECT_GE(ga.modelCost, dp->modelCost - 1e-3) << name << ": the DP is optimal";
        EXPECT_LE(ga.modelCost, dp->modelCost * 1.02) << name;
        EXPECT_NEAR(ga.length, ga.modelCost, 1e-6) << name << ": the path is the model's tour";
        EXPECT_EQ(ga.order.size(), static_cast<size_t>(ga.cells - ga.unreachableCells)) << name;
        EXPECT_LT(distance(ga.path.points.front(), corner), 1e-9);
        EXPECT_LT(distance(ga.path.points.back(), corner), 1e-9);
    }
}

// Larger instances where the DP still runs: halves of the office (rooms with furniture).
TEST(TungLiu, GeneticAlgorithmWithinTwoPercentOfItsDynamicProgramme) {
    const Plan office = samplePlan("office");
    int compared = 0;
    for (const std::vector<std::string>& rooms :
         {std::vector<std::string>{"S01", "S02", "S03", "S04", "S05", "S06"},
          {"N01", "N02", "N03", "N04", "N05", "N06"},
          {"S01", "S02", "S03", "N01", "N02", "N03", "Corridor"},
          {"S04", "S05", "S06", "N04", "N05", "N06", "Corridor"}}) {
        const Vec2 p{1, 1};
        const std::optional<baselines::Tour> dp =
            baselines::planTungLiuDp(office, rooms, p, p, defaultOptions(), 16);
        if (!dp)
            continue;
        ++compared;
        const baselines::Tour ga = baselines::planTungLiuGa(office, rooms, p, p, defaultOptions());
        EXPECT_GE(ga.modelCost, dp->modelCost - 1e-3);
        EXPECT_LE(ga.modelCost, dp->modelCost * 1.02) << ga.cells << " cells";
        std::printf("%zu rooms, %d cells: GA %.2f m, DP %.2f m\n", rooms.size(), ga.cells,
                    ga.modelCost, dp->modelCost);
    }
    EXPECT_GE(compared, 2);
    // A generated office floor of 16 cells: the DP's largest default size.
    const Plan floor = generateOfficeFloor(3, 2);
    const Vec2 p{floor.bounds().minX + 0.5, floor.bounds().minY + 0.5};
    const std::optional<baselines::Tour> dp =
        baselines::planTungLiuDp(floor, {}, p, p, defaultOptions(), 16);
    ASSERT_TRUE(dp);
    const baselines::Tour ga = baselines::planTungLiuGa(floor, {}, p, p, defaultOptions());
    EXPECT_GE(ga.cells, 12);
    EXPECT_GE(ga.modelCost, dp->modelCost - 1e-3);
    EXPECT_LE(ga.modelCost, dp->modelCost * 1.02) << ga.cells << " cells";
}

TEST(TungLiu, SeededAndCancellable) {
    const Plan plan = samplePlan("room-obstacle");
    const Vec2 p{0.5, 0.5};
    const baselines::Tour a = baselines::planTungLiuGa(plan, {}, p, p, defaultOptions());
    const baselines::Tour b = baselines::planTungLiuGa(plan, {}, p, p, defaultOptions());
    EXPECT_EQ(a.path.points, b.path.points);
    baselines::Options cancelled = defaultOptions();
    cancelled.cancelled = [] { return true; };
    EXPECT_THROW(baselines::planTungLiuGa(plan, {}, p, p, cancelled), baselines::TourError);
    // Above the DP's size limit there is no reference rather than a wrong one.
    EXPECT_FALSE(baselines::planTungLiuDp(samplePlan("office"), {}, Vec2{1, 1}, Vec2{1, 1},
                                          defaultOptions(), 16));
}

// Floors beyond a baseline's size refuse at once, with the reason, instead of running for
// minutes where nothing could stop them.
TEST(TungLiu, LargeFloorsAreRefusedAtOnce) {
    const Plan floor = generateOfficeFloor(200, 1);
    const Vec2 p{floor.bounds().minX + 1.0, floor.bounds().minY + 1.0};
    for (auto plan : {baselines::planTungLiuGa, baselines::planReebPostman}) {
        try {
            plan(floor, {}, p, p, defaultOptions());
            ADD_FAILURE() << "planned a floor of 200 rooms";
        } catch (const baselines::TourError& e) {
            EXPECT_NE(std::string(e.what()).find("exceed its limit"), std::string::npos)
                << e.what();
        }
    }
}

// A room subset: only the chosen rooms' floor is swept, every transit stays clear.
TEST(TungLiu, RoomSubsetsSweepOnlyTheirRooms) {
    const Plan plan = samplePlan("office");
    const baselines::Tour all =
        baselines::planTungLiuGa(plan, {}, Vec2{1, 1}, Vec2{1, 1}, defaultOptions());
    const baselines::Tour some =
        baselines::planTungLiuGa(plan, {"S01", "N03"}, Vec2{1, 1}, Vec2{1, 1}, defaultOptions());
    EXPECT_LT(some.cells, all.cells);
    EXPECT_LT(some.length, 0.5 * all.length);
    EXPECT_GT(some.length, 10.0);
}

// Through the pipeline (`--solver adjacency-ga`): its own path, from and back to the start.
TEST(TungLiu, AnswersThePipelinesQueryWithItsOwnPath) {
    PlanRequest r;
    r.plan = samplePlan("simple");
    r.solver = "adjacency-ga";
    r.sweep.perRoom = false;
    r.sweep.angleDeg = 90.0;
    const PlanResult ga = planCoverage(r);
    EXPECT_EQ(ga.solution.solver, "adjacency-ga");
    EXPECT_TRUE(ga.solution.walk.nodes.empty());
    EXPECT_GE(ga.metrics.coverage, 0.99);
    EXPECT_LT(distance(ga.path.points.front(), ga.path.points.back()), 1e-9);
    r.solver = "adjacency-ga-centres";
    EXPECT_EQ(planCoverage(r).solution.solver, "adjacency-ga-centres");
}

// The paper's baselines (reeb-cpp, adjacency-ga): the matching behind the Chinese Postman
// tour is minimal, the tours are deterministic per seed, honour free start and end points,
// and the comparison ratios are what the paper defines. Collision-freedom and coverage on
// every sample plan are checked with the other solvers in test_pipeline.cpp.
#include "TestPlans.h"
#include "formats/PlanIO.h"
#include "geometry/SegmentIndex.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Comparison.h"
#include "pipeline/Planner.h"
#include "baselines/PerfectMatching.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <string>

using namespace fc;
using namespace fc::baselines;

namespace {

using CostMatrix = std::vector<std::vector<double>>;

// Every perfect matching, enumerated: the reference for the minimal one.
double bruteForceMinimum(const CostMatrix& cost, std::vector<char>& used) {
    const int n = static_cast<int>(cost.size());
    int i = 0;
    while (i < n && used[i])
        ++i;
    if (i == n)
        return 0;
    double best = INFINITY;
    used[i] = 1;
    for (int j = i + 1; j < n; ++j) {
        if (used[j])
            continue;
        used[j] = 1;
        best = std::min(best, cost[i][j] + bruteForceMinimum(cost, used));
        used[j] = 0;
    }
    used[i] = 0;
    return best;
}

CostMatrix randomPoints(int n, std::mt19937& random) {
    std::uniform_real_distribution<double> coordinate(0, 20);
    std::vector<Vec2> points;
    for (int i = 0; i < n; ++i)
        points.push_back({coordinate(random), coordinate(random)});
    CostMatrix cost(n, std::vector<double>(n, 0));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            cost[i][j] = distance(points[i], points[j]);
    return cost;
}

bool isPerfect(const std::vector<int>& mate) {
    for (size_t i = 0; i < mate.size(); ++i)
        if (mate[i] < 0 || mate[i] == static_cast<int>(i) || mate[mate[i]] != static_cast<int>(i))
            return false;
    return true;
}

// The least distance from a wall of the robot centre along the path (sweep frame).
double worstClearance(const PlanResult& r) {
    const Decomposition& d = r.prepared.decomposition;
    const SegmentIndex walls(d.freeSpace);
    double worst = INFINITY;
    for (size_t i = 1; i < r.path.points.size(); ++i)
        worst = std::min(worst, walls.segmentClearance(d.frame.toLocal(r.path.points[i - 1]),
                                                       d.frame.toLocal(r.path.points[i])));
    return worst;
}

PlanRequest requestFor(const std::string& plan, const std::string& solver) {
    PlanRequest r;
    r.plan = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + plan + ".geojson").plan;
    r.solver = solver;
    r.sweep.perRoom = false; // the paper's setting: one angle (90 degrees) for the floor
    return r;
}

} // namespace

TEST(PerfectMatching, HandMadeGraphs) {
    // A path a-b-c-d with unit steps: pairing neighbours (a-b, c-d) costs 2, a-d + b-c 4.
    const CostMatrix line{{0, 1, 2, 3}, {1, 0, 1, 2}, {2, 1, 0, 1}, {3, 2, 1, 0}};
    EXPECT_EQ(exactPerfectMatching(line), (std::vector<int>{1, 0, 3, 2}));
    EXPECT_DOUBLE_EQ(matchingCost(line, exactPerfectMatching(line)), 2.0);
    // Greedy's cheapest first pair (b-c, cost 1) forces a-d (cost 10): 11; optimum a-b, c-d
    // costs 4. The pair swap repairs it.
    const CostMatrix trap{{0, 2, 9, 10}, {2, 0, 1, 9}, {9, 1, 0, 2}, {10, 9, 2, 0}};
    EXPECT_DOUBLE_EQ(matchingCost(trap, exactPerfectMatching(trap)), 4.0);
    EXPECT_DOUBLE_EQ(matchingCost(trap, greedyPerfectMatching(trap)), 4.0);
    EXPECT_TRUE(exactPerfectMatching({}).empty());
}

TEST(PerfectMatching, ExactEqualsBruteForceOnRandomPoints) {
    std::mt19937 random(5);
    for (int n = 2; n <= 12; n += 2) {
        for (int trial = 0; trial < 20; ++trial) {
            const CostMatrix cost = randomPoints(n, random);
            std::vector<char> used(n, 0);
            const std::vector<int> mate = minimumWeightPerfectMatching(cost);
            ASSERT_TRUE(isPerfect(mate)) << n;
            EXPECT_NEAR(matchingCost(cost, mate), bruteForceMinimum(cost, used), 1e-9) << n;
            const std::vector<int> greedy = greedyPerfectMatching(cost);
            ASSERT_TRUE(isPerfect(greedy)) << n;
            EXPECT_GE(matchingCost(cost, greedy), matchingCost(cost, mate) - 1e-9);
        }
    }
}

// Above the dynamic programme's limit the blossom algorithm (LEMON) matches exactly: it agrees
// with the programme wherever both run, and is never beaten by greedy with pair swaps.
TEST(PerfectMatching, BlossomEqualsTheDynamicProgrammeAndScales) {
    std::mt19937 random(9);
    for (int n = 2; n <= kExactMatchingLimit; n += 2) {
        for (int trial = 0; trial < 5; ++trial) {
            const CostMatrix cost = randomPoints(n, random);
            const std::vector<int> blossom = blossomPerfectMatching(cost);
            ASSERT_TRUE(isPerfect(blossom)) << n;
            EXPECT_NEAR(matchingCost(cost, blossom), matchingCost(cost, exactPerfectMatching(cost)),
                        1e-9)
                << n;
        }
    }
    for (int n : {kExactMatchingLimit + 10, 200}) {
        const CostMatrix cost = randomPoints(n, random);
        const std::vector<int> mate = minimumWeightPerfectMatching(cost);
        ASSERT_TRUE(isPerfect(mate)) << n;
        EXPECT_LE(matchingCost(cost, mate), matchingCost(cost, greedyPerfectMatching(cost)) + 1e-9);
    }
    EXPECT_TRUE(blossomPerfectMatching({}).empty());
}

TEST(Baselines, ListedAndDeterministicPerSeed) {
    const std::vector<std::string> names = solverNames();
    for (const char* solver : {"reeb-cpp", "adjacency-ga"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), solver), names.end()) << solver;
        PlanRequest r = requestFor("room-obstacle", solver);
        r.seed = 11;
        const PlanResult a = planCoverage(r);
        const PlanResult b = planCoverage(r);
        EXPECT_EQ(a.path.points, b.path.points) << solver;
        EXPECT_EQ(a.solution.solver, solver);
        EXPECT_TRUE(a.solution.walk.nodes.empty()) << "baselines do not walk the corner graph";
    }
}

TEST(Baselines, FreeStartAndEndPointsAndRoomSubsets) {
    for (const char* solver : {"reeb-cpp", "adjacency-ga"}) {
        PlanRequest r = requestFor("office", solver);
        r.rooms = {"S01", "N03", "Corridor"};
        r.start = Vec2{1, 1};
        r.end = Vec2{29, 19};
        const PlanResult res = planCoverage(r);
        EXPECT_LT(distance(res.path.points.front(), *r.start), 1e-9) << solver;
        EXPECT_LT(distance(res.path.points.back(), *r.end), 1e-9) << solver;
        EXPECT_GE(res.metrics.coverage, 0.99) << solver;
        EXPECT_GE(worstClearance(res), 0.5 * r.robot.robotDiameter - 2e-3 * r.robot.robotDiameter)
            << solver;
    }
}

TEST(Baselines, ReebPostmanCoversACellItCrossesTwiceInTwoHalves) {
    // One rectangle: a Reeb graph of one edge between two odd nodes, so the Chinese Postman
    // duplicates it and the cell is covered as a top half, then a bottom half.
    PlanRequest r;
    r.plan.boundary = test::rectangle(0, 0, 10, 6);
    r.solver = "reeb-cpp";
    r.sweep.perRoom = false;
    const PlanResult reeb = planCoverage(r);
    EXPECT_GE(reeb.metrics.coverage, 0.99);
    EXPECT_EQ(reeb.path.points.front(), reeb.path.points.back());
    // Each of the 10 stripes turns in the middle of its clear span (y = 3) in each half; the
    // second half may start where the first ended.
    const auto middle = std::count_if(reeb.path.points.begin(), reeb.path.points.end(),
                                      [](Vec2 p) { return std::abs(p.y - 3.0) < 1e-6; });
    EXPECT_GE(middle, 19);
    r.solver = "adjacency-ga";
    const PlanResult ga = planCoverage(r);
    EXPECT_GT(reeb.metrics.turns, ga.metrics.turns) << "the halves' turns in the middle";
}

TEST(Baselines, AdjacencyGaCentresCoversItsStartCellFirst) {
    // As a TSP tour from its start node: on `simple` (12 x 8 m, a 2 x 2 m obstacle at
    // x = 5..7) the start cell is the classic cell left of the obstacle; all five of its
    // stripes (x = 0.5 .. 4.5) come before the robot first goes right of x = 5.
    PlanRequest r = requestFor("simple", "adjacency-ga-centres");
    const PlanResult res = planCoverage(r);
    const auto& pts = res.path.points;
    const auto firstRight =
        std::find_if(pts.begin(), pts.end(), [](Vec2 p) { return p.x > 5.0 + 1e-6; });
    ASSERT_NE(firstRight, pts.end());
    for (double x : {0.5, 1.5, 2.5, 3.5, 4.5})
        EXPECT_NE(std::find_if(pts.begin(), firstRight,
                               [x](Vec2 p) { return std::abs(p.x - x) < 1e-6 && p.y > 7; }),
                  firstRight)
            << "stripe x = " << x << " before leaving the start cell";
    EXPECT_LT(distance(pts.back(), pts.front()), 1e-9) << "back to the start";
}

TEST(Baselines, GeneratedFloorsAndASlantedSweep) {
    struct Floor {
        const char* name;
        Plan plan;
        double angle;
    };
    const std::vector<Floor> floors{
        {"office 6 rooms", generateOfficeFloor(6, 4), 90.0},
        {"hall with obstacles", generateHallWithObstacles(40, 30, 5, 3), 90.0},
        {"room-obstacle at 30 degrees", requestFor("room-obstacle", "").plan, 30.0}};
    for (const Floor& floor : floors) {
        for (const char* solver : {"reeb-cpp", "adjacency-ga"}) {
            PlanRequest r;
            r.plan = floor.plan;
            r.solver = solver;
            r.sweep.perRoom = false;
            r.sweep.angleDeg = floor.angle;
            const PlanResult res = planCoverage(r);
            EXPECT_GE(res.metrics.coverage, 0.99) << floor.name << " " << solver;
            EXPECT_EQ(res.path.points.front(), res.path.points.back()) << floor.name;
            // The robot disc (L = 0.6 m by default) keeps L/2 from walls.
            EXPECT_GE(worstClearance(res), 0.3 - 1e-3) << floor.name << " " << solver;
        }
    }
}

TEST(Baselines, RatiosAreOursOverEachBaseline) {
    Metrics ours, worse, reeb, ga;
    ours.extra = 2, ours.turns = 10;
    worse.extra = 3, worse.turns = 8;
    reeb.extra = 8, reeb.turns = 20;
    ga.extra = 0, ga.turns = 0;
    const auto ratios = baselineRatios(
        {{"heuristic", ours}, {"greedy", worse}, {"reeb-cpp", reeb}, {"adjacency-ga", ga}});
    ASSERT_EQ(ratios.size(), 2u);
    EXPECT_EQ(ratios[0].ours, "heuristic");
    EXPECT_EQ(ratios[0].baseline, "reeb-cpp");
    EXPECT_DOUBLE_EQ(ratios[0].extraRatio, 0.25);
    EXPECT_DOUBLE_EQ(ratios[0].turnsRatio, 0.5);
    EXPECT_TRUE(std::isnan(ratios[1].extraRatio)) << "no extra distance to divide by";
    EXPECT_TRUE(baselineRatios({{"reeb-cpp", reeb}}).empty());
}

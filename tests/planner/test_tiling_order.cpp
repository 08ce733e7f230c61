// Waypoint ordering for the tiling robot: every method returns a valid tour, Held-Karp is
// optimal (against brute force), seeded methods are deterministic, and the heuristics'
// gaps to the optimum on small random instances stay bounded.
#include "TestPlans.h"
#include "model/Plan.h"
#include "tiling/RandomInstances.h"
#include "tiling/TilingPlanner.h"
#include "tiling/WaypointOrder.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <numeric>

using namespace fc;
using namespace fc::tiling;

namespace {

OrderingProblem randomProblem(int n, unsigned seed) {
    return randomOrderingProblem(n, seed);
}

double bruteForceOptimum(const OrderingProblem& problem) {
    Tour tour(problem.size());
    std::iota(tour.begin(), tour.end(), 0);
    double best = INFINITY;
    do
        best = std::min(best, tourCost(problem, tour));
    while (std::next_permutation(tour.begin() + 1, tour.end()));
    return best;
}

} // namespace

TEST(TilingOrder, HeldKarpMatchesBruteForce) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const OrderingProblem problem = randomProblem(8, seed);
        const Tour exact = orderExact(problem);
        ASSERT_TRUE(isTour(exact, problem.size()));
        EXPECT_NEAR(tourCost(problem, exact), bruteForceOptimum(problem), 1e-9) << seed;
    }
}

TEST(TilingOrder, EveryMethodVisitsEachTileOnce) {
    const OrderingProblem problem = randomProblem(60, 11);
    for (const std::string& solver : orderingSolverNames()) {
        if (solver == "exact")
            continue;
        const Tour tour = solveOrdering(solver, problem, 3);
        EXPECT_TRUE(isTour(tour, problem.size())) << solver;
    }
    EXPECT_THROW(orderExact(problem), InputError);
    EXPECT_THROW(solveOrdering("ppo-typo", problem, 1), InputError);
}

// The editor's Cancel: aco and ga stop between iterations; the others ignore the callback.
TEST(TilingOrder, CancelledOrderingStops) {
    const OrderingProblem problem = randomProblem(60, 11);
    int calls = 0;
    const auto cancelAfterThree = [&calls] { return ++calls > 3; };
    for (const std::string solver : {"aco", "aco+2opt", "ga"}) {
        calls = 0;
        EXPECT_THROW(solveOrdering(solver, problem, 1, cancelAfterThree), OrderingCancelled)
            << solver;
        EXPECT_EQ(calls, 4) << solver;
    }
    EXPECT_TRUE(isTour(solveOrdering("greedy", problem, 1, [] { return true; }), problem.size()));
}

TEST(TilingOrder, TinyProblems) {
    for (int n = 0; n <= 3; ++n) {
        const OrderingProblem problem = randomProblem(n, 2);
        for (const std::string& solver : orderingSolverNames())
            EXPECT_TRUE(isTour(solveOrdering(solver, problem, 1), n)) << solver << " n=" << n;
    }
}

TEST(TilingOrder, SeededMethodsAreDeterministic) {
    const OrderingProblem problem = randomProblem(80, 5);
    for (const std::string solver : {"aco", "ga"}) {
        EXPECT_EQ(solveOrdering(solver, problem, 9), solveOrdering(solver, problem, 9)) << solver;
    }
}

TEST(TilingOrder, EnergyTermsAddUpToTheTourCost) {
    const OrderingProblem problem = randomProblem(30, 8);
    const Tour tour = orderGreedy(problem);
    EXPECT_NEAR(tourEnergy(problem, tour).total(), tourCost(problem, tour), 1e-9);
    EXPECT_EQ(startingAtZero({3, 1, 0, 2}), (Tour{0, 2, 3, 1}));
}

// Mean gap to Held-Karp on 12-waypoint random instances; bounds leave room for the
// search's randomness but catch a broken method.
TEST(TilingOrder, GapsToTheOptimumOnSmallInstances) {
    const int instances = 8;
    std::map<std::string, double> meanGap;
    for (int k = 0; k < instances; ++k) {
        const OrderingProblem problem = randomProblem(12, 100 + k);
        const double optimum = tourCost(problem, orderExact(problem));
        for (const std::string solver : {"greedy", "aco", "ga", "zigzag", "spiral"}) {
            const double cost = tourCost(problem, solveOrdering(solver, problem, 1));
            EXPECT_GE(cost, optimum - 1e-9) << solver;
            meanGap[solver] += (cost / optimum - 1.0) / instances;
        }
    }
    EXPECT_LE(meanGap["aco"], 0.02);
    EXPECT_LE(meanGap["ga"], 0.05);
    EXPECT_LE(meanGap["aco"], meanGap["greedy"] + 1e-12);
}

// The energy-aware 2-opt / Or-opt polish keeps a valid tour from waypoint 0, never makes it
// dearer, and removes most of the zigzag's half turns.
TEST(TilingOrder, PolishNeverWorsensATour) {
    const OrderingProblem problem = randomProblem(120, 21);
    for (const Tour& start : {orderGreedy(problem), orderZigzag(problem), orderSpiral(problem)}) {
        const Tour polished = polishTour(problem, start);
        ASSERT_TRUE(isTour(polished, problem.size()));
        EXPECT_LE(tourCost(problem, polished), tourCost(problem, start) + 1e-9);
    }
    const Tour zigzag = orderZigzag(problem);
    EXPECT_LT(tourCost(problem, polishTour(problem, zigzag)), 0.8 * tourCost(problem, zigzag));
    EXPECT_EQ(polishTour(problem, {0, 1}), (Tour{0, 1})); // not a tour of the problem: kept
    const OrderingProblem small = randomProblem(9, 4);
    const double optimum = tourCost(small, orderExact(small));
    EXPECT_GE(tourCost(small, polishTour(small, orderGreedy(small))), optimum - 1e-9);
}

TEST(TilingPlanner, PlansARectangleEndToEnd) {
    TilingRequest request;
    request.plan.boundary = test::rectangle(0, 0, 2.1, 1.26);
    request.solver = "aco";
    const TilingPlan plan = planTiling(request);
    EXPECT_EQ(plan.tour.size(), 30u);
    EXPECT_TRUE(isTour(plan.tour, 30));
    EXPECT_GT(plan.energy.total(), 0.0);
    EXPECT_GT(plan.length, 0.0);
    const std::string csv = waypointsToFormat("w.csv", plan);
    EXPECT_EQ(csv.rfind("x,y,shape,heading\n", 0), 0u);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 31);
    EXPECT_NE(waypointsToFormat("w.json", plan).find("\"shape\""), std::string::npos);
    EXPECT_THROW(waypointsToFormat("w.txt", plan), InputError);
    EXPECT_NE(tilingMetricsJson(plan).find("\"shape_changes\""), std::string::npos);
}

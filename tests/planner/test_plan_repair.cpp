// Repair instead of refuse (issue 16, item 4): every defect of a broken plan is listed with
// where it is, and the GEOS-based repair gives a plan the validator accepts, saying what it
// changed.
#include "formats/FileIO.h"
#include "formats/PlanIO.h"
#include "importers/Import.h"
#include "model/Validation.h"

#include <gtest/gtest.h>
#include <random>

namespace fc {
namespace {

Plan brokenPlan(const std::string& file) {
    return readGeoJsonPlan(readFile(std::string(FC_TEST_DATA_DIR) + "/" + file));
}

void expectRepaired(const Plan& broken, const std::string& what) {
    const RobotProfile robot;
    const auto problems = planProblems(broken, robot);
    ASSERT_FALSE(problems.empty()) << what << " should have problems";
    std::vector<std::string> notes;
    Plan repaired;
    ASSERT_NO_THROW(repaired = repairPlan(broken, notes)) << what;
    EXPECT_FALSE(notes.empty()) << what << ": a repair says what it changed";
    EXPECT_NO_THROW(validatePlan(normalizedPlan(repaired), robot)) << what;
    EXPECT_TRUE(planProblems(normalizedPlan(repaired), robot).empty()) << what;
}

TEST(PlanRepair, ListsEveryCrossingWithItsLocation) {
    Plan plan;
    plan.boundary = {{0, 0}, {20, 0}, {20, 10}, {0, 10}};
    // Two obstacles crossing the wall at both ends, one crossing another.
    plan.obstacles = {{{-1, 4}, {2, 4}, {2, 6}, {-1, 6}},
                      {{18, 4}, {21, 4}, {21, 6}, {18, 6}},
                      {{8, 2}, {12, 2}, {12, 5}, {8, 5}},
                      {{10, 3}, {14, 3}, {14, 7}, {10, 7}}};
    const auto problems = planProblems(plan, RobotProfile{});
    ASSERT_GE(problems.size(), 3u);
    int nearLeft = 0, nearRight = 0, between = 0;
    for (const PlanProblem& problem : problems) {
        ASSERT_TRUE(problem.hasLocation) << problem.message;
        nearLeft += problem.location.x < 1;
        nearRight += problem.location.x > 19;
        between += problem.location.x > 9 && problem.location.x < 13;
    }
    EXPECT_GT(nearLeft, 0);
    EXPECT_GT(nearRight, 0);
    EXPECT_GT(between, 0);
    expectRepaired(plan, "crossing obstacles");
}

TEST(PlanRepair, RepairsTheBrokenTestFiles) {
    for (const char* file :
         {"selfintersecting.geojson", "hole-crossing.geojson", "hole-outside.geojson",
          "overlapping-holes.geojson", "duplicate-holes.geojson", "overlapping-rooms.geojson",
          "spike.geojson", "room-outside.geojson", "room-in-obstacle.geojson"}) {
        Plan broken;
        try {
            broken = brokenPlan(file);
        } catch (const InputError& e) {
            ADD_FAILURE() << file << " does not parse: " << e.what();
            continue;
        }
        expectRepaired(broken, file);
    }
}

TEST(PlanRepair, KeepsTheFreeAreaOfAFoldedWall) {
    // A wall drawn with a small loop (a vertex dragged across its neighbour): the repair
    // keeps the floor and drops only the loop.
    Plan plan;
    plan.boundary = {{0, 0},     {12, 0},    {12, 8}, {6, 8}, {6.5, 7.5},
                     {5.5, 7.5}, {5.5, 8.5}, {5, 8},  {0, 8}};
    std::vector<std::string> notes;
    const Plan repaired = repairPlan(plan, notes);
    EXPECT_NO_THROW(validatePlan(normalizedPlan(repaired), RobotProfile{}));
    EXPECT_NEAR(ringArea(repaired.boundary), 96.0, 1.0);
}

TEST(PlanRepair, SeededRandomCrossingsAlwaysComeOutValid) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-2.0, 32.0), size(0.5, 6.0);
    for (int trial = 0; trial < 40; ++trial) {
        Plan plan;
        plan.boundary = {{0, 0}, {30, 0}, {30, 20}, {0, 20}};
        const int count = 3 + trial % 6;
        for (int k = 0; k < count; ++k) {
            const double x = coordinate(random), y = coordinate(random) * 0.6;
            const double w = size(random), h = size(random);
            plan.obstacles.push_back({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}});
        }
        plan.rooms = {{"West", {{0, 0}, {16, 0}, {16, 20}, {0, 20}}},
                      {"East", {{14, 0}, {30, 0}, {30, 20}, {14, 20}}}}; // overlapping
        std::vector<std::string> notes;
        Plan repaired;
        try {
            repaired = repairPlan(plan, notes);
        } catch (const InputError& e) {
            ADD_FAILURE() << "trial " << trial << ": " << e.what();
            continue;
        }
        EXPECT_NO_THROW(validatePlan(normalizedPlan(repaired), RobotProfile{}))
            << "trial " << trial;
        EXPECT_EQ(repaired.rooms.size(), 2u) << "trial " << trial;
    }
}

} // namespace
} // namespace fc

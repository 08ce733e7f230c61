// floorcover-exact-bench: how far the exact solver proves optimality, and how tight the
// lower bound every heuristic plan carries is (issue 13, item 5).
//   floorcover-exact-bench [--seconds S] [--quick]
// Part 1: exact on room subsets of the sample plans (26 to 30 required cells): required
// cells, seconds, graph cost, whether optimality was proven, and the bound reached.
// Part 2: heuristic on whole floors: graph cost, proven lower bound and the gap between.
// W = 1 m, L = 0.6 m, stripes at 90 degrees, start and end at the default corner.
#include "formats/PlanIO.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace fc;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

PreparedPlan prepare(const Plan& plan) {
    RobotProfile robot;
    robot.robotDiameter = 0.6;
    robot.coverageWidth = 1.0;
    robot.cleaningDiameter = 1.0;
    return preparePlan(plan, robot, 90.0);
}

Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

// The query for these rooms, keeping only the first `cells` required cells (by cell id).
Query roomQuery(const PreparedPlan& prepared, const std::vector<std::string>& rooms, int cells) {
    std::vector<std::string> warnings;
    Query query = makeQuery(prepared, rooms, std::nullopt, std::nullopt, 1, warnings);
    int kept = 0;
    for (char& required : query.required)
        if (required && ++kept > cells)
            required = 0;
    return query;
}

int requiredCount(const Query& query) {
    return static_cast<int>(std::count(query.required.begin(), query.required.end(), 1));
}

void exactRow(const char* name, const PreparedPlan& prepared, const Query& query, double seconds) {
    ExactOptions options;
    options.bestOnBudget = true;
    options.timeLimitSeconds = seconds;
    options.maxStates = 60'000'000;
    const auto t0 = Clock::now();
    const Solution heuristic = solveHeuristic(prepared.graph, query);
    const double tHeuristic = since(t0);
    const auto t1 = Clock::now();
    const Solution exact = solveExact(prepared.graph, query, options);
    const double tExact = since(t1);
    std::printf("| %s | %d | %.2f | %.4f | %s | %.4f | %.3f%% | %.4f | %.3f%% | %.2f |\n", name,
                requiredCount(query), tExact, exact.graphCost, exact.provenOptimal ? "yes" : "no",
                exact.lowerBound, 100.0 * (exact.graphCost / exact.lowerBound - 1.0),
                heuristic.graphCost, 100.0 * (heuristic.graphCost / exact.lowerBound - 1.0),
                tHeuristic);
    std::fflush(stdout);
}

void boundRow(const char* name, const PreparedPlan& prepared) {
    std::vector<std::string> warnings;
    const Query query = makeQuery(prepared, {}, std::nullopt, std::nullopt, 1, warnings);
    const auto t0 = Clock::now();
    const Solution s = solveHeuristic(prepared.graph, query);
    const double t = since(t0);
    std::printf("| %s | %d | %zu | %.3f | %.3f | %.3f | %.2f%% |\n", name, requiredCount(query),
                prepared.graph.nodes.size(), t, s.graphCost, s.lowerBound,
                100.0 * (s.graphCost / s.lowerBound - 1.0));
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    double seconds = 60.0;
    bool quick = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc)
            seconds = std::atof(argv[++i]);
        else if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
    }
    const PreparedPlan office = prepare(samplePlan("office"));
    const PreparedPlan ward = prepare(samplePlan("ward"));

    std::printf("## exact (time limit %.0f s, single thread)\n\n", seconds);
    std::printf("| query | cells | seconds | graph cost | proven | lower bound | gap | "
                "heuristic cost | heuristic gap | heuristic s |\n"
                "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|\n");
    const std::vector<std::string> officeRooms{"S01", "N01", "S02", "N02", "S03", "N03"};
    const std::vector<std::string> wardRooms{"S01", "N01", "S02"};
    for (int cells : quick ? std::vector<int>{22, 26} : std::vector<int>{22, 26, 28, 30}) {
        const std::string name = "office S01-N03, first " + std::to_string(cells);
        exactRow(name.c_str(), office, roomQuery(office, officeRooms, cells), seconds);
    }
    for (int cells : quick ? std::vector<int>{22, 26} : std::vector<int>{22, 26, 28}) {
        const std::string name = "ward S01-S02, first " + std::to_string(cells);
        exactRow(name.c_str(), ward, roomQuery(ward, wardRooms, cells), seconds);
    }
    for (int cells : quick ? std::vector<int>{} : std::vector<int>{26}) {
        const std::string name = "office corridor + S01, first " + std::to_string(cells);
        exactRow(name.c_str(), office, roomQuery(office, {"Corridor", "S01"}, cells), seconds);
    }

    std::printf("\n## heuristic lower bound on whole floors\n\n");
    std::printf("| plan | cells | nodes | heuristic s | graph cost | lower bound | gap |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    boundRow("office", office);
    boundRow("ward", ward);
    boundRow("office 100 rooms", prepare(generateOfficeFloor(100, 1)));
    if (!quick)
        boundRow("office 1000 rooms", prepare(generateOfficeFloor(1000, 1)));
    return 0;
}

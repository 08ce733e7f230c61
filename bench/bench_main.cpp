// floorcover-bench: times decomposition, graph and each solver on the sample plans and on
// generated floors, with path metrics and peak memory, as a Markdown report.
//   floorcover-bench [--quick] > docs/benchmarks.md
// Each case runs in a child process so its peak memory (ru_maxrss) is its own.
#include "formats/PlanIO.h"
#include "model/SyntheticPlans.h"
#include "model/Validation.h"
#include "path/PathBuilder.h"
#include "pipeline/Planner.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace fc;
using Clock = std::chrono::steady_clock;

namespace {

double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct Case {
    std::string name;
    std::function<Plan()> make;
};

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0)
            return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

// Runs one case; returns Markdown table rows (one per solver).
std::string runCase(const Case& c) {
    std::ostringstream rows;
    RobotProfile robot;
    robot.robotDiameter = 0.6;
    robot.coverageWidth = 1.0;
    robot.cleaningDiameter = 1.0;
    const Plan plan = c.make();
    auto t0 = Clock::now();
    PreparedPlan prepared;
    try {
        prepared.plan = normalizedPlan(plan);
        prepared.robot = robot;
        validatePlan(prepared.plan, robot);
        DecompositionOptions options;
        options.robot = robot;
        options.robot.robotDiameter = robot.coverageWidth; // L = W, as this report always had
        prepared.decomposition = decompose(prepared.plan, options);
    } catch (const std::exception& e) {
        rows << "| " << c.name << " | – | – | – | – | failed: " << e.what() << " |||||||\n";
        return rows.str();
    }
    const double tDecompose = since(t0);
    t0 = Clock::now();
    prepared.graph = buildCornerGraph(prepared.decomposition);
    const double tGraph = since(t0);
    const double tPrepare = tDecompose + tGraph;
    std::vector<std::string> warnings;
    const Query query = makeQuery(prepared, {}, std::nullopt, std::nullopt, 1, warnings);
    for (const char* solver : {"exact", "heuristic", "greedy"}) {
        t0 = Clock::now();
        Solution s;
        try {
            s = runSolver(solver, prepared, query);
        } catch (const SolverError&) {
            continue; // exact refuses above its limit: no row
        }
        const double tSolve = since(t0);
        t0 = Clock::now();
        const CoveragePath path = buildCoveragePath(prepared.decomposition, prepared.graph, s.walk);
        const double tPath = since(t0);
        MetricsInput in;
        in.decomposition = &prepared.decomposition;
        in.robot = robot;
        in.path = path;
        const Metrics m = computeMetrics(in);
        char buf[512];
        std::snprintf(buf, sizeof buf,
                      "| %s | %zu | %zu | %.3f | %.3f | %s | %.3f | %.3f | %.1f | %.1f | %d | "
                      "%.2f%% | %.2f |\n",
                      c.name.c_str(), prepared.decomposition.cells.size(),
                      prepared.graph.nodes.size(), tDecompose, tGraph, solver, tSolve,
                      tPrepare + tSolve + tPath, m.length, m.extra, m.turns, 100 * m.coverage,
                      s.graphCost);
        rows << buf;
    }
    return rows.str();
}

// Forks, runs the case in the child and returns its rows and peak RSS in MiB.
std::string runIsolated(const Case& c, double& peakMiB) {
    int fds[2];
    if (pipe(fds) != 0)
        return runCase(c);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        const std::string rows = runCase(c);
        if (write(fds[1], rows.data(), rows.size()) < 0)
            _exit(1);
        _exit(0);
    }
    close(fds[1]);
    std::string out;
    char buf[4096];
    ssize_t n;
    while ((n = read(fds[0], buf, sizeof buf)) > 0)
        out.append(buf, n);
    close(fds[0]);
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    peakMiB = usage.ru_maxrss / 1024.0;
    return out;
}

} // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    const std::string plans = FC_PLANS_DIR;
    std::vector<Case> cases;
    for (const char* name :
         {"simple", "simple-diamond", "room-obstacle", "room-notches", "office", "ward"})
        cases.push_back({name, [plans, name] {
                             return loadProjectFile(plans + "/" + name + ".geojson").plan;
                         }});
    cases.push_back(
        {"hall 150x100, 15 obstacles", [] { return generateHallWithObstacles(150, 100, 15, 1); }});
    for (int rooms : quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000})
        cases.push_back({"office " + std::to_string(rooms) + " rooms",
                         [rooms] { return generateOfficeFloor(rooms, 1); }});

    std::cout << "# Benchmarks\n\n"
              << "Produced by `build/bench/floorcover-bench > docs/benchmarks.md` (one process "
                 "per case, single-threaded) on "
              << cpuModel() << ".\n"
              << "W = 1 m, L = 0.6 m, sweep angle 90°, all rooms, start and end at the default "
                 "corner. Times in seconds: *decompose* includes validation; *total* is "
                 "decomposition + graph + solver + path synthesis. Coverage is measured on a "
                 "W/20 raster (SPEC sect. 6).\n\n"
              << "| plan | cells | nodes | decompose s | graph s | solver | solve s | total s "
                 "| length m | extra m | turns | coverage | graph cost |\n"
              << "|---|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<std::pair<std::string, double>> memory;
    for (const Case& c : cases) {
        double peak = 0;
        std::cout << runIsolated(c, peak) << std::flush;
        memory.push_back({c.name, peak});
    }
    std::cout << "\n| plan | peak memory MiB |\n|---|---:|\n";
    for (const auto& [name, mib] : memory)
        std::cout << "| " << name << " | " << static_cast<int>(mib + 0.5) << " |\n";
    return 0;
}

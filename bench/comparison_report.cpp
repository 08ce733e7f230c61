// floorcover-comparison-report: every solver, the paper's two baselines included, on every
// sample plan, with the paper's ratios beside ours, as Markdown.
//   floorcover-comparison-report > docs/comparison.md
#include "formats/PlanIO.h"
#include "pipeline/Comparison.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using namespace fc;

namespace {

const std::vector<std::string> kSolvers{"exact", "heuristic", "greedy", "reeb-cpp", "adjacency-ga"};

struct PlanRun {
    std::string plan;
    std::vector<std::pair<std::string, Metrics>> answered;
    std::vector<std::pair<std::string, std::string>> refused;
    std::vector<BaselineRatio> ratios;
};

std::vector<std::string> samplePlans() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(FC_PLANS_DIR))
        if (entry.path().extension() == ".geojson")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The plan with its own settings and the default query (every room, start at the first
// cell's lower-left corner, back to it), as `floorcover-cli compare PLAN` runs it.
PlanRun runPlan(const std::string& name) {
    const Project project = loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson");
    PlanRequest request;
    request.plan = project.plan;
    request.robot = project.robot;
    request.sweep = project.sweep;
    PlanRun run{name, {}, {}, {}};
    for (const std::string& solver : kSolvers) {
        request.solver = solver;
        try {
            run.answered.push_back({solver, planCoverage(request).metrics});
        } catch (const SolverError& e) {
            run.refused.push_back({solver, e.what()});
        }
    }
    run.ratios = baselineRatios(run.answered);
    return run;
}

std::string percent(double ratio) {
    if (!std::isfinite(ratio))
        return "n/a";
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", 100.0 * ratio);
    return text;
}

const BaselineRatio* ratioFor(const PlanRun& run, const std::string& baseline) {
    for (const BaselineRatio& r : run.ratios)
        if (r.baseline == baseline)
            return &r;
    return nullptr;
}

const Metrics* metricsOf(const PlanRun& run, const std::string& solver) {
    for (const auto& [name, m] : run.answered)
        if (name == solver)
            return &m;
    return nullptr;
}

void printPlan(const PlanRun& run) {
    std::printf("### %s\n\n", run.plan.c_str());
    std::printf("| solver | length m | ideal m | extra m | turns | coverage | time s | "
                "planning s |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const auto& [solver, m] : run.answered)
        std::printf("| %s | %.1f | %.1f | %.1f | %d | %.2f%% | %.0f | %.3f |\n", solver.c_str(),
                    m.length, m.ideal, m.extra, m.turns, 100.0 * m.coverage, m.time, m.seconds);
    for (const auto& [solver, why] : run.refused)
        std::printf("| %s | refused: %s | | | | | | |\n", solver.c_str(), why.c_str());
    std::printf("\n");
    for (const BaselineRatio& r : run.ratios)
        std::printf("Ours (`%s`) vs `%s`: extra distance ratio **%s**, turns ratio **%s**.  \n",
                    r.ours.c_str(), r.baseline.c_str(), percent(r.extraRatio).c_str(),
                    percent(r.turnsRatio).c_str());
    std::printf("\n");
}

void printSummary(const std::vector<PlanRun>& runs) {
    std::printf("## The paper's ratios beside ours\n\n");
    std::printf(
        "Ratio = our best solver's figure / the baseline's (smaller is better for us).\n\n");
    std::printf("| plan | ours | extra vs reeb-cpp | turns vs reeb-cpp | extra vs adjacency-ga | "
                "turns vs adjacency-ga |\n|---|---|---:|---:|---:|---:|\n");
    for (const PlanRun& run : runs) {
        const BaselineRatio* reeb = ratioFor(run, "reeb-cpp");
        const BaselineRatio* ga = ratioFor(run, "adjacency-ga");
        std::printf("| %s | %s | %s | %s | %s | %s |\n", run.plan.c_str(),
                    run.ratios.empty() ? "-" : run.ratios.front().ours.c_str(),
                    reeb ? percent(reeb->extraRatio).c_str() : "-",
                    reeb ? percent(reeb->turnsRatio).c_str() : "-",
                    ga ? percent(ga->extraRatio).c_str() : "-",
                    ga ? percent(ga->turnsRatio).c_str() : "-");
    }
    std::printf("| **paper**, simple environment | DQN | 5%% | 65%% | 3.6%% | similar |\n");
    std::printf("| **paper**, complex environment | DQN | 42%% | 45%% | 43%% | similar |\n\n");
    std::printf("The paper's conclusion: extra distance 3.6%% to 43%% of the baselines', turns "
                "45%% to 65%% of reeb-cpp's.\n\n");
    int within = 0, total = 0;
    for (const PlanRun& run : runs)
        for (const BaselineRatio& r : run.ratios)
            ++total, within += r.extraRatio <= kPaperExtraRatio.high ? 1 : 0;
    std::printf("Extra distance ratio at or below the paper's worst (43%%): %d of %d plan and "
                "baseline pairs.\n\n",
                within, total);
}

// The acceptance on `simple`: ours <= 43% of each baseline's extra distance, and
// no more turns than reeb-cpp.
void printSimpleCheck(const std::vector<PlanRun>& runs) {
    std::printf("## On `simple` (what issue 6 asks)\n\n");
    for (const PlanRun& run : runs) {
        if (run.plan != "simple")
            continue;
        for (const BaselineRatio& r : run.ratios) {
            const Metrics* ours = metricsOf(run, r.ours);
            const Metrics* base = metricsOf(run, r.baseline);
            const bool extraMet = r.extraRatio <= kPaperExtraRatio.high;
            std::printf(
                "- extra distance vs `%s`: %.2f m / %.2f m = %s: %s the required <= 43%%.\n",
                r.baseline.c_str(), ours->extra, base->extra, percent(r.extraRatio).c_str(),
                extraMet ? "meets" : "**does not meet**");
            if (r.baseline == "reeb-cpp")
                std::printf("- turns vs `reeb-cpp`: %d vs %d: %s.\n", ours->turns, base->turns,
                            ours->turns <= base->turns ? "at most reeb-cpp's (met)"
                                                       : "**more than reeb-cpp's (not met)**");
        }
        std::printf("\n");
        return;
    }
    std::printf("- no sample plan named `simple`\n\n");
}

// Every plan and baseline where our ratio is worse than the paper's worst, with numbers.
void printShortfalls(const std::vector<PlanRun>& runs) {
    std::printf("## Where we do not reach the paper's ratios\n\n");
    int count = 0;
    for (const PlanRun& run : runs) {
        for (const BaselineRatio& r : run.ratios) {
            const Metrics* ours = metricsOf(run, r.ours);
            const Metrics* base = metricsOf(run, r.baseline);
            if (!(r.extraRatio <= kPaperExtraRatio.high)) {
                std::printf("- `%s` vs `%s`: extra %.1f m vs %.1f m (%s, paper at most 43%%)\n",
                            run.plan.c_str(), r.baseline.c_str(), ours->extra, base->extra,
                            percent(r.extraRatio).c_str());
                ++count;
            }
            if (r.baseline == "reeb-cpp" && !(r.turnsRatio <= kPaperTurnsRatioReeb.high)) {
                std::printf("- `%s` vs `reeb-cpp`: turns %d vs %d (%s, paper at most 65%%)\n",
                            run.plan.c_str(), ours->turns, base->turns,
                            percent(r.turnsRatio).c_str());
                ++count;
            }
        }
    }
    if (count == 0)
        std::printf("- none\n");
    std::printf(
        "\nHow to read these (this implementation's behaviour, not the paper's): "
        "`adjacency-ga` covers its start cell first, then goes from a cell straight to a "
        "neighbouring cell and passes cell centres only between cells that are not "
        "neighbours. On the small plans its genetic algorithm finds a closed tour in which "
        "consecutive cells are neighbours, and on `simple`, `room-obstacle` and "
        "`room-notches` that tour is the very path our `exact` solver finds on the corner "
        "graph (the same length and turns): a closed tour there has nothing left to gain, so "
        "no solver can reach the paper's 3.6%% against such a baseline. The paper's figure "
        "14B shows its adjacency-graph robot returning through the middle of cells; a "
        "baseline doing that everywhere would be far worse, but the paper does not say that "
        "it does, so ours takes the straight transit where cells touch. On the large plans "
        "(office, ward) its transits through cell centres dominate. `reeb-cpp` pays for the "
        "halves of duplicated cells (turns in the middle of cells) as the paper describes.\n\n");
}

} // namespace

int main() {
    std::vector<PlanRun> runs;
    for (const std::string& name : samplePlans())
        runs.push_back(runPlan(name));
    std::printf("# Comparison with the paper's baselines\n\n");
    std::printf(
        "Generated by `build/bench/floorcover-comparison-report > docs/comparison.md` over "
        "every plan in `resources/plans`, each with its own settings (W = 1 m, L = 0.6 m, "
        "each room's stripes along its own walls (per room, the default), 0.5 m/s, 2 s per "
        "turn), all rooms, the default start (the corner farthest from the centre of the "
        "floor) and back to it: what `floorcover-cli compare PLAN` runs. "
        "Every metric comes from the same `computeMetrics`; planning time is wall-clock "
        "seconds on the machine that generated this file. \"Ours\" is the corner-graph solver "
        "with the least extra distance (`exact` where it runs; the DQN needs a trained model "
        "per plan and is not included).\n\n");
    std::printf(
        "The baselines plan on the classic Boustrophedon decomposition (no transition cells): "
        "`reeb-cpp` is the Reeb graph with a Chinese Postman tour (odd nodes paired by a "
        "minimum-weight perfect matching, cells on duplicated edges covered as a top half, "
        "then a bottom half); `adjacency-ga` is a genetic-algorithm TSP over the cell adjacency "
        "graph with four entry/exit options per cell, straight transits between neighbouring cells "
        "and, between other cells, transits through the centres of the cells left, crossed and "
        "entered. Both return to the start. See `planner/solvers/Baselines.h` and "
        "`docs/architecture.md`.\n\n");
    printSummary(runs);
    printSimpleCheck(runs);
    printShortfalls(runs);
    std::printf("## Per plan\n\n");
    for (const PlanRun& run : runs)
        printPlan(run);
    return 0;
}

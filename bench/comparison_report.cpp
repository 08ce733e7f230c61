// floorcover-comparison-report: every solver, the paper's two baselines included, on every
// sample plan, with the paper's ratios beside ours, as Markdown.
//   floorcover-comparison-report > docs/comparison.md
#include "baselines/IndependentBaselines.h"
#include "baselines/PerfectMatching.h"
#include "formats/PlanIO.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Comparison.h"
#include "pipeline/Planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

using namespace fc;

namespace {

const std::vector<std::string> kSolvers{"exact",    "heuristic",    "greedy",
                                        "reeb-cpp", "adjacency-ga", "adjacency-ga-centres"};
const std::vector<std::string> kBaselines{"reeb-cpp", "adjacency-ga", "adjacency-ga-centres"};
constexpr int kDpMaxCells = 16;
// Generated floors are planned once each: the DP may take 150 MB there.
constexpr int kDpMaxCellsGenerated = 18;

// Where a path's length goes: transits, and the rest (stripes, the steps between them and
// contour passes).
struct LengthSplit {
    double transit = 0, covering = 0;
};

LengthSplit splitOf(const CoveragePath& path) {
    LengthSplit split;
    for (std::size_t i = 0; i + 1 < path.points.size(); ++i)
        (path.kinds[i] == SegmentKind::Transit ? split.transit : split.covering) +=
            distance(path.points[i], path.points[i + 1]);
    return split;
}

// adjacency-ga's GA against its dynamic programme, on the query the pipeline gave it.
struct DpRow {
    int cells = 0;
    double ga = 0, gaSeconds = 0;
    std::optional<double> dp;
    double dpSeconds = 0;
};

struct PlanRun {
    std::string plan;
    std::vector<std::pair<std::string, Metrics>> answered;
    std::vector<std::pair<std::string, std::string>> refused;
    std::vector<std::pair<std::string, LengthSplit>> splits;
    std::vector<BaselineRatio> ratios;
    std::optional<DpRow> dp;
};

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

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
    PlanRun run{name, {}, {}, {}, {}, {}};
    for (const std::string& solver : kSolvers) {
        request.solver = solver;
        try {
            const PlanResult result = planCoverage(request);
            run.answered.push_back({solver, result.metrics});
            run.splits.push_back({solver, splitOf(result.path)});
            if (solver == "adjacency-ga" && !result.path.empty()) {
                // The same query (whole floor, its angle, start and end) solved by the GA
                // and by the DP of baselines/IndependentBaselines.h.
                baselines::Options options;
                options.width = request.robot.coverageWidth;
                options.clearance = 0.5 * request.robot.robotDiameter;
                options.stripeAngleDeg = result.stripeAngleDeg;
                options.seed = request.seed;
                const Vec2 start = result.path.points.front(), end = result.path.points.back();
                DpRow row;
                auto t0 = std::chrono::steady_clock::now();
                const baselines::Tour ga =
                    baselines::planTungLiuGa(request.plan, {}, start, end, options);
                row.gaSeconds = secondsSince(t0);
                row.ga = ga.modelCost;
                row.cells = ga.cells - ga.unreachableCells;
                t0 = std::chrono::steady_clock::now();
                if (const auto dp = baselines::planTungLiuDp(request.plan, {}, start, end, options,
                                                             kDpMaxCells))
                    row.dp = dp->modelCost;
                row.dpSeconds = secondsSince(t0);
                run.dp = row;
            }
        } catch (const SolverError& e) {
            run.refused.push_back({solver, e.what()});
        }
    }
    run.ratios = baselineRatios(run.answered);
    return run;
}

const LengthSplit* splitOf(const PlanRun& run, const std::string& solver) {
    for (const auto& [name, split] : run.splits)
        if (name == solver)
            return &split;
    return nullptr;
}

std::string percent(double ratio) {
    if (!std::isfinite(ratio))
        return "n/a";
    char text[32];
    // A path as long as the ideal has an extra of a few micrometres either way: not "-0.0%".
    std::snprintf(text, sizeof text, "%.1f%%", std::abs(ratio) < 5e-4 ? 0.0 : 100.0 * ratio);
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
                    m.length, m.ideal, std::abs(m.extra) < 0.05 ? 0.0 : m.extra, m.turns,
                    100.0 * m.coverage, m.time, m.seconds);
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
    std::printf("| plan | ours |");
    for (const std::string& b : kBaselines)
        std::printf(" extra vs %s | turns vs %s |", b.c_str(), b.c_str());
    std::printf("\n|---|---|");
    for (std::size_t i = 0; i < kBaselines.size(); ++i)
        std::printf("---:|---:|");
    std::printf("\n");
    for (const PlanRun& run : runs) {
        std::printf("| %s | %s |", run.plan.c_str(),
                    run.ratios.empty() ? "-" : run.ratios.front().ours.c_str());
        for (const std::string& b : kBaselines) {
            const BaselineRatio* r = ratioFor(run, b);
            std::printf(" %s | %s |", r ? percent(r->extraRatio).c_str() : "-",
                        r ? percent(r->turnsRatio).c_str() : "-");
        }
        std::printf("\n");
    }
    std::printf("| **paper**, simple environment | DQN | 5%% | 65%% | 3.6%% | similar | | |\n");
    std::printf("| **paper**, complex environment | DQN | 42%% | 45%% | 43%% | similar | | |\n\n");
    std::printf("The paper's conclusion: extra distance 3.6%% to 43%% of the baselines', turns "
                "45%% to 65%% of reeb-cpp's (the paper has no cell-centre variant; its "
                "adjacency-graph figures are in the adjacency-ga columns).\n\n");
    int within = 0, total = 0;
    for (const PlanRun& run : runs)
        for (const BaselineRatio& r : run.ratios)
            if (r.baseline != "adjacency-ga-centres")
                ++total, within += r.extraRatio <= kPaperExtraRatio.high ? 1 : 0;
    std::printf("Extra distance ratio at or below the paper's worst (43%%) against the paper's "
                "two baselines: %d of %d plan and baseline pairs.\n\n",
                within, total);
}

// adjacency-ga's genetic algorithm against its own optimum, as their paper measures it.
void printDpTable(const std::vector<PlanRun>& runs) {
    std::printf("## adjacency-ga against its dynamic programme\n\n");
    std::printf(
        "The query `adjacency-ga` answered above (its sweep angle, start and end, the "
        "whole floor) solved by its genetic algorithm and by the dynamic programme over "
        "cells x options of the same model (`baselines::planTungLiuDp`, Held-Karp, run up to %d "
        "cells; on the generated office floors below, from their lower-left corner and "
        "back, up to %d). Lengths are the model's tour lengths.\n\n",
        kDpMaxCells, kDpMaxCellsGenerated);
    std::printf("| plan | cells | GA m | DP m | GA over DP | GA s | DP s |\n"
                "|---|---:|---:|---:|---:|---:|---:|\n");
    int compared = 0, equal = 0, withinTwo = 0;
    for (const PlanRun& run : runs) {
        if (!run.dp)
            continue;
        const DpRow& d = *run.dp;
        if (d.dp) {
            const double over = d.ga / *d.dp - 1.0;
            ++compared, equal += over < 1e-6, withinTwo += over <= 0.02;
            std::printf("| %s | %d | %.1f | %.1f | %+.2f%% | %.2f | %.2f |\n", run.plan.c_str(),
                        d.cells, d.ga, *d.dp, 100.0 * over, d.gaSeconds, d.dpSeconds);
        } else {
            std::printf("| %s | %d | %.1f | not run (over %d cells) | | %.2f | |\n",
                        run.plan.c_str(), d.cells, d.ga, kDpMaxCells, d.gaSeconds);
        }
    }
    // Generated office floors (model/SyntheticPlans.h) of the DP's reach, from a corner.
    for (int rooms : {3, 4})
        for (std::uint64_t seed : {1u, 2u, 3u}) {
            const Plan plan = generateOfficeFloor(rooms, seed);
            const Vec2 corner{plan.bounds().minX + 0.5, plan.bounds().minY + 0.5};
            baselines::Options options;
            DpRow d;
            // The DP first: where it does not run, the GA is not needed either.
            auto t0 = std::chrono::steady_clock::now();
            const auto dp =
                baselines::planTungLiuDp(plan, {}, corner, corner, options, kDpMaxCellsGenerated);
            d.dpSeconds = secondsSince(t0);
            if (!dp)
                continue;
            t0 = std::chrono::steady_clock::now();
            const baselines::Tour ga = baselines::planTungLiuGa(plan, {}, corner, corner, options);
            d.gaSeconds = secondsSince(t0);
            d.ga = ga.modelCost;
            d.cells = ga.cells - ga.unreachableCells;
            const double over = d.ga / dp->modelCost - 1.0;
            ++compared, equal += over < 1e-6, withinTwo += over <= 0.02;
            std::printf(
                "| generated office, %d rooms, seed %d | %d | %.1f | %.1f | %+.2f%% | %.2f | "
                "%.2f |\n",
                rooms, static_cast<int>(seed), d.cells, d.ga, dp->modelCost, 100.0 * over,
                d.gaSeconds, d.dpSeconds);
        }
    std::printf("\nWhere the DP runs (%d plans), the GA equals it on %d and is within 2%% on %d. "
                "tests/planner/test_tung_liu.cpp checks both on the small sample plans, on "
                "halves of the office and on a generated floor of 16 cells.\n\n",
                compared, equal, withinTwo);
}

// The acceptance on `simple` and `office`: ours <= 43% of each baseline's extra
// distance, or by how much we miss it and where the lengths go.
void printTargetPlans(const std::vector<PlanRun>& runs) {
    std::printf("## On `simple` and `office`\n\n");
    for (const char* plan : {"simple", "office"}) {
        const auto it = std::find_if(runs.begin(), runs.end(),
                                     [&](const PlanRun& r) { return r.plan == plan; });
        if (it == runs.end()) {
            std::printf("- no sample plan named `%s`\n", plan);
            continue;
        }
        for (const BaselineRatio& r : it->ratios) {
            if (r.baseline == "adjacency-ga-centres")
                continue;
            const Metrics* ours = metricsOf(*it, r.ours);
            const Metrics* base = metricsOf(*it, r.baseline);
            const bool met = r.extraRatio <= kPaperExtraRatio.high;
            std::printf("- `%s`, extra distance vs `%s`: %.2f m / %.2f m = %s: %s the required "
                        "<= 43%%",
                        plan, r.baseline.c_str(), std::abs(ours->extra) < 5e-3 ? 0.0 : ours->extra,
                        base->extra, percent(r.extraRatio).c_str(),
                        met ? "meets" : "**does not meet**");
            if (!met)
                std::printf(" (ours would need at most %.2f m, %.2f m less)",
                            kPaperExtraRatio.high * base->extra,
                            ours->extra - kPaperExtraRatio.high * base->extra);
            std::printf(".\n");
        }
    }
    std::printf("\n");
}

// Every plan and baseline where our ratio is worse than the paper's worst, with numbers, and
// where the two paths' lengths go.
void printShortfalls(const std::vector<PlanRun>& runs) {
    std::printf("## Where we do not reach the paper's ratios\n\n");
    int count = 0;
    for (const PlanRun& run : runs) {
        for (const BaselineRatio& r : run.ratios) {
            const Metrics* ours = metricsOf(run, r.ours);
            const Metrics* base = metricsOf(run, r.baseline);
            const LengthSplit* ourSplit = splitOf(run, r.ours);
            const LengthSplit* baseSplit = splitOf(run, r.baseline);
            if (!(r.extraRatio <= kPaperExtraRatio.high)) {
                std::printf("- `%s` vs `%s`: extra %.1f m vs %.1f m (%s, paper at most 43%%)",
                            run.plan.c_str(), r.baseline.c_str(), ours->extra, base->extra,
                            percent(r.extraRatio).c_str());
                if (ourSplit && baseSplit)
                    std::printf("; transits %.1f m vs %.1f m, sweeping %.1f m vs %.1f m "
                                "(ideal %.1f m)",
                                ourSplit->transit, baseSplit->transit, ourSplit->covering,
                                baseSplit->covering, ours->ideal);
                std::printf("\n");
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
    // What the numbers say, plan by plan: a baseline whose sweeping alone (stripes, steps
    // and contours, no transits) is already within 43% of ideal + our extra cannot be
    // beaten by that ratio; say so where it holds.
    std::printf("\n");
    for (const PlanRun& run : runs)
        for (const BaselineRatio& r : run.ratios) {
            const Metrics* ours = metricsOf(run, r.ours);
            const Metrics* base = metricsOf(run, r.baseline);
            if (r.extraRatio <= kPaperExtraRatio.high || !ours || !base || base->extra <= 0)
                continue;
            const double needed = ours->extra / kPaperExtraRatio.high;
            std::printf("- `%s` vs `%s`: the ratio needs the baseline's extra distance to be at "
                        "least %.1f m (%.1f%% of the ideal %.1f m); it is %.1f m (%.1f%%).\n",
                        run.plan.c_str(), r.baseline.c_str(), needed, 100.0 * needed / ours->ideal,
                        ours->ideal, base->extra, 100.0 * base->extra / ours->ideal);
        }
    std::printf("\n");
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
        "The baselines: `reeb-cpp` and `adjacency-ga` are written apart from the planner "
        "(`planner/baselines/`, which includes nothing of ours below the plan model; a test "
        "follows its includes). Both plan on their own classic Boustrophedon decomposition (no "
        "transition cells), stripes W apart with connectors along each cell's floor and "
        "ceiling, and transits as shortest paths on a visibility graph of the walls grown by "
        "L/2 (Boost.Graph). `reeb-cpp`: the Reeb graph (cells as edges between the slices "
        "where cells meet) with a Chinese Postman tour whose odd nodes are paired by an exact "
        "minimum-weight perfect matching at every size (a dynamic programme up to %d odd "
        "nodes, LEMON's Edmonds blossom above), a cell on a duplicated edge covered as its top "
        "half on the first pass and its bottom half on the second. `adjacency-ga`: Tung & "
        "Liu's four entry/exit options per cell and a seeded genetic algorithm (order "
        "crossover, swap and inversion, option mutation). `adjacency-ga-centres` is the first "
        "paper's reading of Tung & Liu on our classic decomposition: transits through the "
        "centres of the cells on the way. All return to the start.\n\n",
        fc::baselines::kExactMatchingLimit);
    printSummary(runs);
    printDpTable(runs);
    printTargetPlans(runs);
    printShortfalls(runs);
    std::printf("## Per plan\n\n");
    for (const PlanRun& run : runs)
        printPlan(run);
    return 0;
}

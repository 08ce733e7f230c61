// floorcover-dqn-budget: solver dqn against heuristic at equal CPU budgets (issue 17,
// item 3). Both are run as anytime methods by restarts, and each keeps the cheapest walk it
// finished within the budget; a run still going at the deadline is cancelled and does not
// count:
//   heuristic  solveHeuristic with seeds 1, 2, 3, ... (each a different proxy search);
//   dqn        the policy-guided search (PolicySearch.h), as solver dqn-search runs it: the
//              policy's walk searched by the heuristic's whole search from its order
//              (searchFromWalk), then partial rollouts of the policy from random prefixes of
//              the best walk, each searched likewise with a new seed; it stops at the
//              deadline with its best complete walk. --thorough off: each walk only refined
//              as solver dqn refines it (the earlier search).
// Cost is the graph cost both optimise; queries are random room subsets with random start
// and end corners (seeded).
//   floorcover-dqn-budget [--cases ward,generated-office-100] [--budgets 1,5] [--queries N]
//                         [--seed N] [--model FILE]   (default: the built-in generalist)
//                         [--beam N]   (the search's first walk: beam width, default 1)
//                         [--thorough on|off]   (default on)
#include "BenchSupport.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/GeneralistModel.h"
#include "learning/dqn/PolicySearch.h"
#include "model/SyntheticPlans.h"
#include "pipeline/Planner.h"

#include <cstdio>
#include <ctime>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace fc;

namespace {

using fc::bench::threadCpuSeconds;

using fc::bench::splitList;

Plan loadCase(const std::string& name, std::uint64_t seed) {
    const std::string generated = "generated-office-";
    if (name.rfind(generated, 0) == 0)
        return generateOfficeFloor(std::stoi(name.substr(generated.size())), seed);
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

struct Anytime {
    double cost = std::numeric_limits<double>::infinity(); // inf: nothing finished in time
    int runs = 0;                                          // finished within the budget
};

// Runs attempt(i, control) for i = 0, 1, ... until the budget is spent; a run still going
// at the deadline is cancelled (SolverError) and does not count.
template <typename Attempt> Anytime withinBudget(double budget, Attempt attempt) {
    const double deadline = threadCpuSeconds() + budget;
    SolveControl control;
    control.cancelled = [deadline] { return threadCpuSeconds() >= deadline; };
    Anytime best;
    for (int i = 0; threadCpuSeconds() < deadline; ++i) {
        try {
            const double cost = attempt(i, control);
            if (threadCpuSeconds() > deadline)
                break; // finished after the deadline without looking at the clock
            best.cost = std::min(best.cost, cost);
            ++best.runs;
        } catch (const SolverError&) {
            break; // cancelled at the deadline
        }
    }
    return best;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> cases{"ward", "generated-office-100"};
    std::vector<double> budgets{1.0, 5.0};
    int queryCount = 10;
    std::uint64_t seed = 1;
    std::string modelPath;
    PolicySearchOptions search;
    search.thorough = true;
    search.beamWidth = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--cases")
            cases = splitList(value);
        else if (key == "--budgets") {
            budgets.clear();
            for (const std::string& b : splitList(value))
                budgets.push_back(std::stod(b));
        } else if (key == "--queries")
            queryCount = std::stoi(value);
        else if (key == "--seed")
            seed = std::stoull(value);
        else if (key == "--model")
            modelPath = value;
        else if (key == "--thorough")
            search.thorough = value == "1" || value == "on";
        else if (key == "--beam")
            search.beamWidth = std::stoi(value);
        else {
            std::cerr << "unknown option " << key << "\n";
            return 2;
        }
    }
    const std::shared_ptr<const DqnModel> model =
        modelPath.empty() ? generalistModel()
                          : std::make_shared<DqnModel>(loadDqnModelFile(modelPath));
    std::printf("| plan | cells | budget (CPU s) | heuristic: mean cost | runs | dqn: mean cost | "
                "searches | dqn vs heuristic | dqn cheaper | none in time (h / dqn) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const std::string& name : cases) {
        const PreparedPlan prepared = preparePlan(loadCase(name, seed), RobotProfile{}, 90.0);
        const CornerGraph& graph = prepared.graph;
        checkModelFitsGraph(model->info, graph, modelPath.empty() ? "generalist" : modelPath);
        const std::vector<Query> queries =
            randomQueries(graph, queryCount, seed * 7919ULL + 3ULL, QuerySet::RoomSubsets);
        for (double budget : budgets) {
            double heuristicSum = 0.0, dqnSum = 0.0, ratioSum = 0.0;
            int heuristicRuns = 0, dqnRuns = 0, both = 0, dqnCheaper = 0;
            int heuristicNone = 0, dqnNone = 0;
            for (const Query& query : queries) {
                const Anytime h = withinBudget(budget, [&](int i, const SolveControl& control) {
                    Query q = query;
                    q.seed = static_cast<std::uint64_t>(i) + 1;
                    return solveHeuristic(graph, q, control).graphCost;
                });
                Anytime d;
                {
                    const double deadline = threadCpuSeconds() + budget;
                    SolveControl control;
                    control.cancelled = [deadline] { return threadCpuSeconds() >= deadline; };
                    try {
                        d.cost =
                            policyGuidedSearch(*model->agent, graph, query, model->info.environment,
                                               model->info.refinement, control, search)
                                .graphCost;
                        d.runs = 1;
                    } catch (const SolverError&) {
                        // its first walk did not finish in time
                    }
                }
                heuristicRuns += h.runs;
                dqnRuns += d.runs;
                heuristicNone += h.runs == 0 ? 1 : 0;
                dqnNone += d.runs == 0 ? 1 : 0;
                if (h.runs > 0 && d.runs > 0) {
                    ++both;
                    heuristicSum += h.cost;
                    dqnSum += d.cost;
                    ratioSum += d.cost / h.cost - 1.0;
                    dqnCheaper += d.cost < h.cost - 1e-9 ? 1 : 0;
                }
            }
            const double n = std::max(1, both);
            std::printf("| %s | %zu | %.0f | %.1f | %.1f | %.1f | %.1f | %+.2f%% | %d/%d | %d / "
                        "%d |\n",
                        name.c_str(), graph.cells.size(), budget, heuristicSum / n,
                        static_cast<double>(heuristicRuns) / static_cast<double>(queries.size()),
                        dqnSum / n,
                        static_cast<double>(dqnRuns) / static_cast<double>(queries.size()),
                        100.0 * ratioSum / n, dqnCheaper, both, heuristicNone, dqnNone);
            std::fflush(stdout);
        }
    }
    return 0;
}

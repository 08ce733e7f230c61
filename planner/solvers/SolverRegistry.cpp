#include "solvers/SolverRegistry.h"

#include "solvers/Baselines.h"

#include <algorithm>
#include <mutex>

namespace fc {
namespace {

struct Registry {
    std::mutex mutex;
    std::vector<RegisteredSolver> solvers = builtInSolvers(); // once, on first use
};

Registry& registry() {
    static Registry instance;
    return instance;
}

} // namespace

std::vector<RegisteredSolver> builtInSolvers() {
    std::vector<RegisteredSolver> solvers(6);
    solvers[0].name = "exact";
    solvers[0].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl& control) {
        // A user waits at most this long for a proof; then the refusal names the gap.
        ExactOptions options;
        options.timeLimitSeconds = kExactTimeLimitSeconds;
        return solveExact(prepared.graph, query, options, control);
    };
    solvers[1].name = "heuristic";
    solvers[1].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl& control) {
        return solveHeuristic(prepared.graph, query, control);
    };
    solvers[2].name = "greedy";
    solvers[2].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl&) { return solveGreedy(prepared.graph, query); };
    solvers[3].name = "reeb-cpp";
    solvers[3].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl& control) {
        return solveReebPostman(prepared, query, control);
    };
    solvers[4].name = "adjacency-ga";
    solvers[4].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl& control) {
        return solveTungLiuGa(prepared, query, control);
    };
    solvers[5].name = "adjacency-ga-centres";
    solvers[5].solve = [](const PreparedPlan& prepared, const Query& query, const std::string&,
                          const SolveControl& control) {
        return solveAdjacencyGa(prepared, query, control);
    };
    solvers[5].classicStages = true;
    return solvers;
}

void registerSolver(RegisteredSolver solver) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    auto it = std::find_if(r.solvers.begin(), r.solvers.end(),
                           [&](const RegisteredSolver& s) { return s.name == solver.name; });
    if (it != r.solvers.end())
        *it = std::move(solver);
    else
        r.solvers.push_back(std::move(solver));
}

std::optional<RegisteredSolver> findRegisteredSolver(const std::string& name) {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    for (const RegisteredSolver& s : r.solvers)
        if (s.name == name)
            return s;
    return std::nullopt;
}

std::vector<std::string> registeredSolverNames() {
    Registry& r = registry();
    std::lock_guard<std::mutex> lock(r.mutex);
    std::vector<std::string> names;
    for (const RegisteredSolver& s : r.solvers)
        names.push_back(s.name);
    return names;
}

} // namespace fc

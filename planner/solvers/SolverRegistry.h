// Every solver is registered here by name; the pipeline's runSolver and solverNames look them
// up. The built-in ones (exact, heuristic, greedy, reeb-cpp, adjacency-ga) are registered by
// the core on first use of the registry; solvers that live outside the planner core (the
// learnt ones link LibTorch, which the core must not depend on) are registered by the
// applications at start-up (e.g. fc::registerDqnSolver()).
#pragma once

#include "graph/PreparedPlan.h"
#include "solvers/Solver.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fc {

struct RegisteredSolver {
    std::string name;
    std::function<Solution(const PreparedPlan&, const Query&, const std::string& modelPath,
                           const SolveControl&)>
        solve;
    // For solvers bound to one graph (a trained model): the sweep angle that graph was built
    // with, used instead of "auto". May be empty.
    std::function<std::optional<double>(const std::string& modelPath)> sweepAngle;
    // Plans on PreparedPlan::classic (the classic decomposition), which is then prepared too.
    bool classicStages = false;
};

// Replaces a registration of the same name (in its place), else appends. Thread-safe.
void registerSolver(RegisteredSolver solver);
std::optional<RegisteredSolver> findRegisteredSolver(const std::string& name);
// In registration order: the built-in ones (exact, heuristic, greedy, reeb-cpp,
// adjacency-ga), then the others as they were registered.
std::vector<std::string> registeredSolverNames();

// The core's solvers in the order listed above; the registry registers them once, lazily.
std::vector<RegisteredSolver> builtInSolvers();

} // namespace fc

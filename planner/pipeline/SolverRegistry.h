// Solvers that live outside the planner core (the learnt ones link LibTorch, which the core
// must not depend on) register here; runSolver and solverNames then treat them like the
// built-in ones. Applications register at start-up (e.g. fc::registerDqnSolver()).
#pragma once

#include "solvers/Solver.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fc {

struct PreparedPlan;

struct RegisteredSolver {
    std::string name;
    std::function<Solution(const PreparedPlan&, const Query&, const std::string& modelPath,
                           const SolveControl&)>
        solve;
    // For solvers bound to one graph (a trained model): the sweep angle that graph was built
    // with, used instead of "auto". May be empty.
    std::function<std::optional<double>(const std::string& modelPath)> sweepAngle;
};

// Replaces a registration of the same name. Thread-safe.
void registerSolver(RegisteredSolver solver);
std::optional<RegisteredSolver> findRegisteredSolver(const std::string& name);
std::vector<std::string> registeredSolverNames();

} // namespace fc

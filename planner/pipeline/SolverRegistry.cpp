#include "pipeline/SolverRegistry.h"

#include <algorithm>
#include <mutex>

namespace fc {
namespace {

struct Registry {
    std::mutex mutex;
    std::vector<RegisteredSolver> solvers;
};

Registry& registry() {
    static Registry instance;
    return instance;
}

} // namespace

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

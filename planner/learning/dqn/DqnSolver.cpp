#include "learning/dqn/DqnSolver.h"

#include "graph/PreparedPlan.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/GeneralistModel.h"
#include "learning/dqn/PolicySearch.h"
#include "model/Plan.h"
#include "solvers/SolverRegistry.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

namespace fc {
namespace {

struct CachedModel {
    std::filesystem::file_time_type modified;
    std::uintmax_t size = 0;
    std::shared_ptr<const DqnModel> model;
};

// Loading the weights costs more than a query; the GUI and the benchmarks plan many
// queries with one model.
// No path: the generalist compiled in (GeneralistModel.h).
std::shared_ptr<const DqnModel> cachedModel(const std::string& path) {
    if (path.empty())
        return generalistModel();
    static std::mutex mutex;
    static std::map<std::string, CachedModel> cache;
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(path, error);
    const std::uintmax_t size = error ? 0 : std::filesystem::file_size(path, error);
    if (error)
        throw InputError(path + ": cannot open the model file");
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(path);
    if (it != cache.end() && it->second.modified == modified && it->second.size == size)
        return it->second.model;
    auto model = std::make_shared<DqnModel>(loadDqnModelFile(path));
    cache[path] = CachedModel{modified, size, model};
    return model;
}

Solution solveDqn(const PreparedPlan& prepared, const Query& query, const std::string& modelPath,
                  const SolveControl& control) {
    const std::shared_ptr<const DqnModel> model = cachedModel(modelPath);
    checkModelFitsGraph(model->info, prepared.graph,
                        modelPath.empty() ? kGeneralistModelName : modelPath);
    return solveWithPolicy(*model->agent, prepared.graph, query, model->info.environment,
                           model->info.refinement, control);
}

Solution solveDqnSearch(const PreparedPlan& prepared, const Query& query,
                        const std::string& modelPath, const SolveControl& control) {
    const std::shared_ptr<const DqnModel> model = cachedModel(modelPath);
    checkModelFitsGraph(model->info, prepared.graph,
                        modelPath.empty() ? kGeneralistModelName : modelPath);
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(kDqnSearchSeconds));
    auto userCancelled = [&control] { return control.cancelled && control.cancelled(); };
    SolveControl timed;
    timed.cancelled = [deadline, userCancelled] {
        return userCancelled() || std::chrono::steady_clock::now() >= deadline;
    };
    timed.progress = control.progress;
    PolicySearchOptions options;
    options.beamWidth = 1;
    options.thorough = true;
    options.seed = query.seed;
    // The first walk under the user's cancellation only: the search then always has one.
    const Solution rollout =
        solveWithPolicy(*model->agent, prepared.graph, query, model->info.environment,
                        OrderRefinement::None, control, options.beamWidth);
    Solution best =
        policyGuidedSearch(*model->agent, prepared.graph, query, model->info.environment,
                           model->info.refinement, timed, options, &rollout);
    if (userCancelled()) // the search returns its best walk; a cancelled plan is not wanted
        throw SolverError("dqn-search: cancelled");
    best.solver = "dqn-search";
    return best;
}

} // namespace

void registerDqnSolver() {
    RegisteredSolver search;
    search.name = "dqn-search";
    search.solve = solveDqnSearch;
    RegisteredSolver solver;
    solver.name = "dqn";
    solver.solve = solveDqn;
    solver.sweepAngle = [](const std::string& modelPath) -> std::optional<double> {
        // A generalist plans at whatever angle the floor is swept at (per room by default).
        if (modelPath.empty())
            return std::nullopt;
        const DqnModelInfo info = loadDqnModelInfo(modelPath);
        if (info.generalist)
            return std::nullopt;
        return info.stripeAngleDeg;
    };
    search.sweepAngle = solver.sweepAngle;
    registerSolver(std::move(solver));
    registerSolver(std::move(search));
}

} // namespace fc

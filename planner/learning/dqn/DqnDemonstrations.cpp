// DqnTrainer's learning from demonstrations (DQfD, Hester et al. 2018): expert walks of the
// exact solver or the heuristic, replayed through the environment into the agent's
// demonstration set, and pre-training on them. Kept apart from the episode loop.
#include "learning/dqn/DqnPolicy.h"
#include "learning/dqn/DqnTrainer.h"
#include "learning/dqn/PolicySearch.h"

#include <algorithm>
#include <stdexcept>

namespace fc {
namespace {

constexpr int kExactDemonstrationCells = 12;

// The expert's walk for `query`: exact where that is quick, else the heuristic.
Solution expertSolution(const CornerGraph& graph, const Query& query, const SolveControl& control) {
    const long cells = std::count(query.required.begin(), query.required.end(), 1);
    return cells <= kExactDemonstrationCells ? solveExact(graph, query, {}, control)
                                             : solveHeuristic(graph, query, control);
}

} // namespace

long DqnTrainer::addDemonstrations(int perFloor, const SolveControl& control) {
    if (!options_.environment.graphState || !agent_->sizeFree())
        throw std::invalid_argument("DqnTrainer::addDemonstrations: graph setting only");
    long added = 0;
    for (std::size_t f = 0; f < floors_.size(); ++f) {
        const CornerGraph& graph = *floors_[f];
        CoverageEnvironment& env = *environments_[f];
        const int ofEvaluationKind = perFloor / 2;
        std::vector<Query> queries =
            ofEvaluationKind > 0
                ? randomQueries(graph, ofEvaluationKind,
                                (options_.agent.seed ^ 0xde70ULL) * 7919ULL + f,
                                roomCount(graph) > 1 ? QuerySet::RoomSubsets : QuerySet::AllCells)
                : std::vector<Query>{};
        for (int i = ofEvaluationKind; i < perFloor; ++i) {
            env.reset(rng_);
            queries.push_back(env.episodeQuery());
        }
        for (const Query& query : queries) {
            if (control.cancelled && control.cancelled())
                return added;
            const Solution expert = expertSolution(graph, query, control);
            std::vector<float> observation = env.reset(query);
            for (int action : entryActions(graph, query, expert.walk)) {
                if (env.done() || !env.actionMask()[static_cast<std::size_t>(action)])
                    break; // cannot happen for a complete walk; keep what was replayed
                const StepResult result = env.step(action);
                Transition t;
                t.observation = std::move(observation);
                t.action = action;
                t.reward = static_cast<float>(result.reward);
                observation = env.observation();
                t.nextObservation = observation;
                t.nextMask = env.actionMask();
                t.done = result.done;
                agent_->rememberDemonstration(std::move(t));
                ++added;
            }
        }
    }
    return added;
}

double DqnTrainer::pretrain(long steps) {
    double sum = 0.0;
    for (long i = 1; i <= steps; ++i) {
        sum += agent_->trainStep(true);
        if (i % options_.agent.targetSyncInterval == 0)
            agent_->syncTarget();
    }
    agent_->syncTarget();
    return steps > 0 ? sum / static_cast<double>(steps) : 0.0;
}

} // namespace fc

#include "learning/dqn/PolicyBeam.h"

#include "learning/dqn/DqnPolicy.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace fc {
namespace {

struct Partial {
    CoverageEnvironment env;
    std::vector<float> observation;
    double cost = 0.0; // graph cost of the walk so far
};

struct Extension {
    std::size_t from = 0;
    int action = 0;
    double estimate = 0.0; // cost so far + the policy's estimate of the rest
};

} // namespace

Solution policyBeamWalk(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                        const EnvironmentOptions& environment, int width,
                        const SolveControl& control) {
    if (width < 1)
        throw std::invalid_argument("policyBeamWalk: the width must be at least 1");
    // Q in cost units: the reward is -cost / maxEdgeLength x costScale per step.
    const double unit = environment.rewardIsNegativeGraphCost && environment.costScale > 0.0
                            ? std::max(graph.maxEdgeLength, 1e-9) / environment.costScale
                            : 0.0; // paper rewards: rank by Q alone
    std::vector<Partial> beam;
    {
        Partial first{CoverageEnvironment(graph, environment), {}, 0.0};
        try {
            first.observation = first.env.reset(query);
        } catch (const std::invalid_argument& e) {
            throw SolverError(std::string("dqn: ") + e.what());
        }
        beam.push_back(std::move(first));
    }
    while (!beam.front().env.done()) {
        if (control.cancelled && control.cancelled())
            throw SolverError("dqn: cancelled");
        // One batch for the Q values of every walk in the beam (same graph, same size).
        std::vector<float> batch;
        for (const Partial& p : beam)
            batch.insert(batch.end(), p.observation.begin(), p.observation.end());
        const std::vector<float> q = agent.qValues(batch, static_cast<int>(beam.size()));
        const std::size_t actions = q.size() / beam.size();
        std::vector<Extension> extensions;
        for (std::size_t b = 0; b < beam.size(); ++b) {
            const std::vector<char> mask = beam[b].env.actionMask();
            std::vector<Extension> own;
            for (std::size_t a = 0; a < actions; ++a)
                if (mask[a]) {
                    const double value = q[b * actions + a];
                    own.push_back({b, static_cast<int>(a),
                                   unit > 0.0 ? beam[b].cost - value * unit : -value});
                }
            // Each walk offers its `width` best corners, so one walk cannot fill the beam
            // with near-copies of itself before the others are looked at.
            const std::size_t keep = std::min(own.size(), static_cast<std::size_t>(width));
            std::partial_sort(
                own.begin(), own.begin() + static_cast<std::ptrdiff_t>(keep), own.end(),
                [](const Extension& x, const Extension& y) { return x.estimate < y.estimate; });
            extensions.insert(extensions.end(), own.begin(),
                              own.begin() + static_cast<std::ptrdiff_t>(keep));
        }
        if (extensions.empty())
            throw SolverError("dqn: no corner of an uncovered cell can be reached");
        std::stable_sort(
            extensions.begin(), extensions.end(),
            [](const Extension& x, const Extension& y) { return x.estimate < y.estimate; });
        extensions.resize(std::min(extensions.size(), static_cast<std::size_t>(width)));
        std::vector<Partial> next;
        for (const Extension& e : extensions) {
            Partial p = beam[e.from]; // a copy: several extensions may share a parent
            const StepResult result = p.env.step(e.action);
            if (result.done && !result.info.reachedGoal)
                throw SolverError("dqn: the policy ran out of steps"); // masked: cannot happen
            p.cost += result.info.graphCost;
            p.observation = p.env.observation();
            next.push_back(std::move(p));
        }
        beam = std::move(next);
    }
    // Every walk covers one cell per step, so all end together; keep the cheapest.
    Solution best;
    best.graphCost = std::numeric_limits<double>::infinity();
    for (const Partial& p : beam) {
        Solution walk = policyWalkSolution(graph, query, p.env.walk());
        if (walk.graphCost < best.graphCost)
            best = std::move(walk);
    }
    best.solver = "dqn";
    if (width > 1) {
        // The estimates may steer the whole beam off the greedy walk; never answer worse.
        Solution greedy = policyBeamWalk(agent, graph, query, environment, 1, control);
        if (greedy.graphCost < best.graphCost)
            return greedy;
    }
    return best;
}

} // namespace fc

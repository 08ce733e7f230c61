#include "learning/dqn/DqnPolicy.h"

#include "learning/CoverageEnvironment.h"
#include "learning/dqn/PolicyBeam.h"
#include "learning/torch/DqnTargets.h"

#include <algorithm>
#include <queue>
#include <set>
#include <stdexcept>

namespace fc {

Solution solveWithPolicy(const DqnAgent& agent, const CornerGraph& graph, const Query& query,
                         const EnvironmentOptions& environment, OrderRefinement refinement,
                         const SolveControl& control, int beamWidth) {
    CoverageEnvironment env(graph, environment);
    if (environment.graphState != (agent.parameters().network == QNetworkKind::Graph))
        throw SolverError("dqn: the model's network does not fit its state kind (image/graph)");
    const bool sizeFits = agent.sizeFree() || (env.size() == agent.imageSize() &&
                                               env.actionCount() == agent.actionCount() &&
                                               env.observationSize() == agent.observationSize());
    if (!sizeFits || env.channelCount() != agent.parameters().inputChannels)
        throw SolverError("dqn: the model was trained on a graph of another size");
    if (beamWidth > 1)
        return refineCellOrder(graph, query,
                               policyBeamWalk(agent, graph, query, environment, beamWidth, control),
                               refinement, kPolicyRefinementBudget, control);
    std::vector<float> observation;
    try {
        observation = env.reset(query);
    } catch (const std::invalid_argument& e) {
        throw SolverError(std::string("dqn: ") + e.what());
    }
    while (!env.done()) {
        if (control.cancelled && control.cancelled())
            throw SolverError("dqn: cancelled");
        const std::vector<char> mask = env.actionMask();
        const std::vector<float> q = agent.qValues(observation, 1);
        const int action = maskedArgmax(q.data(), mask.data(), env.actionCount());
        if (action < 0)
            throw SolverError("dqn: no corner of an uncovered cell can be reached");
        const StepResult result = env.step(action);
        if (result.done && !result.info.reachedGoal)
            throw SolverError("dqn: the policy ran out of steps"); // masked: cannot happen
        observation = env.observation();
    }
    return refineCellOrder(graph, query, policyWalkSolution(graph, query, env.walk()), refinement,
                           kPolicyRefinementBudget, control);
}

Solution policyWalkSolution(const CornerGraph& graph, const Query& query, const Walk& walk) {
    Solution solution;
    solution.solver = "dqn";
    solution.walk = walk;
    const WalkEvaluation evaluation = evaluateWalk(graph, query, solution.walk);
    if (!evaluation.connected || !evaluation.coversAllRequired)
        throw SolverError("dqn: the policy's walk does not cover the query (internal error)");
    solution.cellOrder = evaluation.cellOrder;
    solution.graphCost = evaluation.graphCost;
    return solution;
}

namespace {

std::vector<char> componentOf(const CornerGraph& graph, int start) {
    std::vector<char> seen(graph.nodes.size(), 0);
    std::queue<int> open;
    seen[static_cast<std::size_t>(start)] = 1;
    open.push(start);
    while (!open.empty()) {
        const int node = open.front();
        open.pop();
        for (int e : graph.incident[static_cast<std::size_t>(node)]) {
            const int next = graph.edges[static_cast<std::size_t>(e)].other(node);
            if (!seen[static_cast<std::size_t>(next)]) {
                seen[static_cast<std::size_t>(next)] = 1;
                open.push(next);
            }
        }
    }
    return seen;
}

} // namespace

int roomCount(const CornerGraph& graph) {
    std::set<int> rooms;
    for (const GraphCell& c : graph.cells)
        if (c.reachable)
            rooms.insert(c.room);
    return static_cast<int>(rooms.size());
}

std::vector<Query> randomQueries(const CornerGraph& graph, int count, std::uint64_t seed,
                                 QuerySet kind) {
    std::vector<int> startNodes;
    for (const GraphNode& n : graph.nodes)
        if (graph.cells[static_cast<std::size_t>(n.cell)].reachable)
            startNodes.push_back(n.id);
    if (startNodes.empty())
        throw std::invalid_argument("randomQueries: the graph has no reachable cell");
    std::mt19937_64 rng(seed);
    auto pick = [&rng](std::size_t size) {
        return std::uniform_int_distribution<std::size_t>(0, size - 1)(rng);
    };
    std::vector<Query> queries;
    while (static_cast<int>(queries.size()) < count) {
        Query q;
        q.seed = seed;
        q.startNode = startNodes[pick(startNodes.size())];
        const std::vector<char> part = componentOf(graph, q.startNode);
        std::vector<int> ends;
        std::vector<int> rooms;
        for (int node : startNodes)
            if (part[static_cast<std::size_t>(node)]) {
                ends.push_back(node);
                rooms.push_back(graph
                                    .cells[static_cast<std::size_t>(
                                        graph.nodes[static_cast<std::size_t>(node)].cell)]
                                    .room);
            }
        q.endNode = ends[pick(ends.size())];
        std::sort(rooms.begin(), rooms.end());
        rooms.erase(std::unique(rooms.begin(), rooms.end()), rooms.end());
        std::vector<char> chosenRoom(rooms.empty() ? 0 : rooms.back() + 1, 1);
        if (kind == QuerySet::RoomSubsets && rooms.size() > 1) {
            std::shuffle(rooms.begin(), rooms.end(), rng);
            const std::size_t keep = 1 + pick(rooms.size());
            std::fill(chosenRoom.begin(), chosenRoom.end(), 0);
            for (std::size_t i = 0; i < keep; ++i)
                chosenRoom[static_cast<std::size_t>(rooms[i])] = 1;
        }
        q.required.assign(graph.cells.size(), 0);
        for (const GraphCell& c : graph.cells) {
            const int firstNode = c.nodes.front();
            if (c.reachable && part[static_cast<std::size_t>(firstNode)] && c.room >= 0 &&
                c.room < static_cast<int>(chosenRoom.size()) &&
                chosenRoom[static_cast<std::size_t>(c.room)])
                q.required[static_cast<std::size_t>(c.id)] = 1;
        }
        queries.push_back(std::move(q));
    }
    return queries;
}

} // namespace fc

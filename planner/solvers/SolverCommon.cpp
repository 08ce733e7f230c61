#include "solvers/SolverCommon.h"

#include <algorithm>
#include <string>

namespace fc::solver_detail {

namespace {

std::string prefix(const char* solverName) {
    return std::string(solverName) + " solver: ";
}

} // namespace

std::vector<char> reachableFrom(const CornerGraph& graph, int start) {
    std::vector<char> seen(graph.nodes.size(), 0);
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
        const int node = stack.back();
        stack.pop_back();
        for (int e : graph.incident[node]) {
            const int next = graph.edges[e].other(node);
            if (!seen[next]) {
                seen[next] = 1;
                stack.push_back(next);
            }
        }
    }
    return seen;
}

bool isRequiredCell(const CornerGraph& graph, const Query& query, int cell) {
    return cell >= 0 && cell < static_cast<int>(query.required.size()) &&
           cell < static_cast<int>(graph.cells.size()) && query.required[cell] &&
           graph.cells[cell].reachable;
}

Problem makeProblem(const CornerGraph& graph, const Query& query, const char* solverName) {
    const int nodeCount = static_cast<int>(graph.nodes.size());
    if (query.startNode < 0 || query.startNode >= nodeCount || query.endNode < 0 ||
        query.endNode >= nodeCount)
        throw SolverError(prefix(solverName) + "start node " + std::to_string(query.startNode) +
                          " or end node " + std::to_string(query.endNode) +
                          " is not a node of the graph (" + std::to_string(nodeCount) + " nodes)");
    if (query.required.size() != graph.cells.size())
        throw SolverError(prefix(solverName) + "the query lists " +
                          std::to_string(query.required.size()) + " cells but the graph has " +
                          std::to_string(graph.cells.size()));
    if (graph.incident.size() != graph.nodes.size())
        throw SolverError(prefix(solverName) + "graph adjacency does not match its nodes");

    Problem problem;
    problem.graph = &graph;
    problem.startNode = query.startNode;
    problem.endNode = query.endNode;
    problem.seed = query.seed;
    problem.taskOfCell.assign(graph.cells.size(), -1);

    const std::vector<char> seen = reachableFrom(graph, query.startNode);
    problem.reachableNodeCount = static_cast<int>(std::count(seen.begin(), seen.end(), 1));
    int cutOff = 0;
    for (const GraphCell& cell : graph.cells) {
        if (!isRequiredCell(graph, query, cell.id))
            continue;
        if (cell.coverageEdges.empty())
            throw SolverError(prefix(solverName) + "required cell " + std::to_string(cell.id) +
                              " has no coverage edge");
        std::vector<CoverOption> options;
        for (int e : cell.coverageEdges) {
            const GraphEdge& edge = graph.edges[e];
            options.push_back({edge.u, edge.v, e});
            options.push_back({edge.v, edge.u, e});
        }
        if (!seen[options.front().entry]) {
            ++cutOff;
            continue;
        }
        problem.taskOfCell[cell.id] = problem.taskCount();
        problem.taskCells.push_back(cell.id);
        problem.options.push_back(std::move(options));
    }
    if (cutOff > 0)
        throw SolverError(prefix(solverName) + std::to_string(cutOff) +
                          " required cell(s) cannot be reached from the start node " +
                          std::to_string(query.startNode) + " (separate part of the graph)");
    if (!seen[query.endNode])
        throw SolverError(prefix(solverName) + "the end node " + std::to_string(query.endNode) +
                          " cannot be reached from the start node " +
                          std::to_string(query.startNode));
    return problem;
}

std::vector<int> taskOrderOf(const Problem& problem, const Solution& given) {
    const int tasks = problem.taskCount();
    std::vector<int> order;
    std::vector<char> seen(static_cast<std::size_t>(tasks), 0);
    for (int cell : given.cellOrder) {
        const int task = problem.taskOfCell[static_cast<std::size_t>(cell)];
        if (task < 0 || seen[static_cast<std::size_t>(task)])
            continue; // not required, or covered again later: not a new task
        seen[static_cast<std::size_t>(task)] = 1;
        order.push_back(task);
    }
    if (static_cast<int>(order.size()) != tasks)
        throw SolverError(given.solver + ": the walk to improve does not cover every cell once");
    return order;
}

Solution finishSolution(const CornerGraph& graph, const Query& query, const char* solverName,
                        Walk walk) {
    const WalkEvaluation evaluation = evaluateWalk(graph, query, walk);
    if (!evaluation.connected || !evaluation.coversAllRequired)
        throw SolverError(prefix(solverName) + "internal error: the walk it built is " +
                          (evaluation.connected ? "missing a required cell" : "not connected"));
    Solution solution;
    solution.solver = solverName;
    solution.walk = std::move(walk);
    solution.cellOrder = evaluation.cellOrder;
    solution.graphCost = evaluation.graphCost;
    return solution;
}

void throwIfCancelled(const SolveControl& control, const char* solverName) {
    if (control.cancelled && control.cancelled())
        throw SolverError(prefix(solverName) + "cancelled");
}

void reportProgress(const SolveControl& control, double fraction) {
    if (control.progress)
        control.progress(std::clamp(fraction, 0.0, 1.0));
}

SeededRandom::SeededRandom(std::uint64_t seed) : state_(seed) {}

std::uint64_t SeededRandom::next() {
    // splitmix64: tiny, fast and identical on every platform.
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

int SeededRandom::below(int bound) {
    return static_cast<int>((next() >> 33) % static_cast<std::uint64_t>(bound));
}

} // namespace fc::solver_detail

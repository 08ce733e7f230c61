#include "solvers/ProxyDistances.h"

#include <algorithm>

namespace fc::solver_detail {

namespace {

constexpr int kNoMark = -3;

// Neighbourhood searches run until this many more tasks than the neighbour count are met,
// so that the lists drawn from a cell's different corners overlap well.
constexpr int kSearchMargin = 4;

} // namespace

ProxyDistances::ProxyDistances(const TransitGraph& graph, TransitSearch& search, int neighbourCount)
    : graph_(graph), search_(search), anyCoverage_(graph.initialCoverage()),
      markOfNode_(graph.nodeCount(), kNoMark), taskSeen_(graph.problem->taskCount(), 0),
      searched_(graph.nodeCount(), 0), reachedFrom_(graph.nodeCount()),
      neighbourCount_(neighbourCount), cache_(1024) {
    const Problem& problem = *graph.problem;
    const CornerGraph& corner = *problem.graph;
    tasksPerSearch_ = std::min(problem.taskCount(), neighbourCount + 1 + kSearchMargin);

    prices_.uncovered.resize(corner.edges.size());
    for (const GraphEdge& edge : corner.edges) {
        const bool task = edge.cell >= 0 && problem.taskOfCell[edge.cell] >= 0;
        double price = edgeCost(edge, true); // covered: coverage and contour edges 3x
        if (task && edge.kind == EdgeKind::Contour)
            price = edgeCost(edge, false); // floor/ceiling of a cell still to cover: 1x
        prices_.uncovered[edge.id] = price;
    }
    prices_.covered = prices_.uncovered;

    for (int task = 0; task < problem.taskCount(); ++task)
        for (const CoverOption& option : problem.options[task])
            markOfNode_[option.entry] = task;
    for (int node = 0; node < graph.nodeCount(); ++node)
        if (markOfNode_[node] >= 0 || node == problem.startNode || node == problem.endNode)
            ++terminalCount_;

    neighbours_.resize(problem.taskCount());
    neighbourCosts_.resize(problem.taskCount());
    for (int task = 0; task < problem.taskCount(); ++task) {
        std::vector<int> corners;
        for (const CoverOption& option : problem.options[task])
            corners.push_back(option.entry);
        listNeighbours(corners, task, neighbours_[task], neighbourCosts_[task]);
    }
    std::vector<int> marks;
    std::vector<double> costs;
    listNeighbours({problem.startNode}, kStartMark, marks, costs);
    for (int mark : marks)
        if (mark >= 0)
            nearStart_.push_back(mark);
}

std::uint64_t ProxyDistances::keyOf(int a, int b) const {
    const auto low = static_cast<std::uint64_t>(std::min(a, b));
    const auto high = static_cast<std::uint64_t>(std::max(a, b));
    return low * static_cast<std::uint64_t>(graph_.nodeCount()) + high;
}

void ProxyDistances::searchAround(int node, std::vector<Reached>& reached) {
    const Problem& problem = *graph_.problem;
    if (++searchStamp_ == 0) {
        std::fill(taskSeen_.begin(), taskSeen_.end(), 0);
        searchStamp_ = 1;
    }
    int tasksMet = 0, terminalsMet = 0;
    search_.explore(prices_, anyCoverage_, {{node, 0.0}}, [&](int settled, double cost) {
        const int task = markOfNode_[settled];
        const bool start = settled == problem.startNode;
        const bool end = settled == problem.endNode;
        if (task == kNoMark && !start && !end)
            return false;
        cache_.emplace(keyOf(node, settled), cost);
        if (start)
            reached.push_back({kStartMark, cost});
        if (end)
            reached.push_back({kEndMark, cost});
        if (task >= 0 && taskSeen_[task] != searchStamp_) {
            taskSeen_[task] = searchStamp_;
            reached.push_back({task, cost});
            ++tasksMet;
        }
        ++terminalsMet;
        return terminalsMet == terminalCount_ ||
               (tasksMet >= tasksPerSearch_ && tasksPerSearch_ < problem.taskCount());
    });
}

void ProxyDistances::listNeighbours(const std::vector<int>& nodes, int exclude,
                                    std::vector<int>& marks, std::vector<double>& costs) {
    std::vector<Reached> all;
    for (int node : nodes) {
        if (!searched_[node]) {
            searched_[node] = 1;
            searchAround(node, reachedFrom_[node]);
        }
        for (const Reached& r : reachedFrom_[node])
            if (r.mark != exclude)
                all.push_back(r);
    }
    std::sort(all.begin(), all.end(), [](const Reached& a, const Reached& b) {
        return a.cost != b.cost ? a.cost < b.cost : a.mark < b.mark;
    });
    int tasks = 0;
    for (const Reached& r : all) {
        if (tasks >= neighbourCount_)
            break;
        if (std::find(marks.begin(), marks.end(), r.mark) != marks.end())
            continue;
        marks.push_back(r.mark);
        costs.push_back(r.cost);
        if (r.mark >= 0)
            ++tasks;
    }
}

double ProxyDistances::between(int from, int to) {
    if (from == to)
        return 0.0;
    const std::uint64_t key = keyOf(from, to);
    if (const double* known = cache_.find(key))
        return *known;
    // Beyond both neighbourhoods. On large graphs a targeted search per pair dominates the
    // whole solve, so use the landmark upper bound min_L d(from, L) + d(L, to): the
    // landmarks are priced like the proxy, and an upper bound never makes a move look
    // better than it is.
    if (graph_.nodeCount() > kLargeGraph && !graph_.landmarkDistance.empty()) {
        double bound = kInfinity;
        for (const std::vector<double>& d : graph_.landmarkDistance)
            bound = std::min(bound, d[from] + d[to]);
        if (bound < kInfinity) {
            cache_.emplace(key, bound);
            return bound;
        }
    }
    // Otherwise one targeted search (cheaper than widening the neighbourhoods).
    search_.run(prices_, anyCoverage_, {{from, 0.0}}, {to});
    const double cost = search_.cost(to);
    cache_.emplace(key, cost);
    return cost;
}

} // namespace fc::solver_detail

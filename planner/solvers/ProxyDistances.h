// Static stand-in for the state-dependent transit costs, used to rank cell orders quickly:
// prices as if every required cell were still uncovered along its floor and ceiling (1x)
// and every coverage edge were already covered (3x). Distances come from searches bounded
// around each corner and are cached, so large graphs never need all pairs.
#pragma once

#include "solvers/FlatHashMap.h"
#include "solvers/TransitSearch.h"

#include <vector>

namespace fc::solver_detail {

// Neighbour list entries that stand for the walk's start and end rather than a task.
constexpr int kStartMark = -1;
constexpr int kEndMark = -2;
// Graphs with more nodes than this answer far proxy pairs from landmarks, not searches.
constexpr int kLargeGraph = 6000;

class ProxyDistances {
public:
    // neighbourCount: how many nearest tasks (and start/end marks when as near) to list.
    ProxyDistances(const TransitGraph& graph, TransitSearch& search, int neighbourCount);

    // Proxy cost of the cheapest walk between two nodes (symmetric).
    double between(int from, int to);

    // Nearest tasks to `task`, nearest first; may contain kStartMark / kEndMark. Cost i is
    // the cheapest proxy cost found between a corner of the task and entry i (what a link
    // between the two costs at least, unless a corner's search stopped short of it).
    const std::vector<int>& neighbours(int task) const { return neighbours_[task]; }
    const std::vector<double>& neighbourCosts(int task) const { return neighbourCosts_[task]; }
    // Nearest tasks to the start node, nearest first.
    const std::vector<int>& nearStart() const { return nearStart_; }

private:
    struct Reached {
        int mark; // task index, kStartMark or kEndMark
        double cost;
    };

    // Searches outward from `node` until enough tasks are met (or every terminal: task
    // corner, start, end), caching the cost of each terminal it settles and listing the
    // nearest cost per mark in `reached`.
    void searchAround(int node, std::vector<Reached>& reached);
    void listNeighbours(const std::vector<int>& nodes, int exclude, std::vector<int>& marks,
                        std::vector<double>& costs);
    std::uint64_t keyOf(int a, int b) const;

    const TransitGraph& graph_;
    TransitSearch& search_;
    EdgePrices prices_;
    std::vector<char> anyCoverage_;       // prices are static, so the covered state is irrelevant
    std::vector<int> markOfNode_;         // task of a corner, else kNoMark
    std::vector<std::uint32_t> taskSeen_; // stamp per task for the current search
    std::uint32_t searchStamp_ = 0;
    std::vector<char> searched_;                    // node -> its neighbourhood search has run
    std::vector<std::vector<Reached>> reachedFrom_; // per corner searched for neighbours
    int neighbourCount_;
    int tasksPerSearch_;
    int terminalCount_ = 0;
    FlatHashMap<double> cache_;
    std::vector<std::vector<int>> neighbours_;
    std::vector<std::vector<double>> neighbourCosts_;
    std::vector<int> nearStart_;
};

} // namespace fc::solver_detail

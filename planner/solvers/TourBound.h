// Proven lower bounds on the graph cost (SPEC sect. 3) of covering a set of required cells
// from a node and then reaching the end node.
//
// Between two consecutive first coverages a walk is a transit: it never crosses the coverage
// edge of an uncovered cell, so every edge costs at least its cheapest transit price
// (coverage edges 3x, contour edges their uncovered price, inter edges their length). With D
// the distances under those prices, a walk x -> t1 -> ... -> tk -> end costs at least the
// sum of D over its k + 1 transits, and these transits form a spanning tree of {x, tasks,
// end} in which x and end are leaves: a minimum spanning tree bounds the walk from below.
//
// The bound is strengthened as in Held and Karp: each cell is entered at the entry corner of
// one cover option and left at its exit corner, so those two corners carry one transit each
// and the others none. A penalty pi per corner added to every transit that uses it, minus,
// per cell, the largest penalty sum of an option's two corners, keeps the tree a lower
// bound for any pi; subgradient steps on pi at the root raise it. The penalties found at the
// root stay valid for every sub-problem (any pi is valid).
#pragma once

#include "solvers/FlatHashMap.h"
#include "solvers/TransitSearch.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace fc::solver_detail {

class TourBound {
public:
    // Dense version: distances between all task corners (one search per corner). `upper`
    // (the cost of a known walk, or +inf) scales the subgradient steps.
    TourBound(const TransitGraph& transit, TransitSearch& search, double upper,
              int subgradientIterations = 400);

    // Whether the dense version is affordable (corner searches x graph size).
    static bool affordable(const Problem& problem);

    // Bound for the whole query (all tasks uncovered, at the start node).
    double root() const { return root_; }

    // Index of a node among the start node and the task corners, -1 for any other node.
    int terminalOf(int node) const { return terminalOfNode_[node]; }
    int terminalCount() const { return static_cast<int>(terminalNodes_.size()); }
    int terminalNode(int terminal) const { return terminalNodes_[terminal]; }

    // Bound on finishing from `terminal` with the tasks of `uncovered` (bit per task, at
    // most 63 tasks) still to cover. Cached per task set.
    double at(std::uint64_t uncovered, int terminal);

private:
    struct Tree {
        double weight = 0.0;
        std::vector<int> portDegree;
    };
    void computeDistances(const TransitGraph& transit, TransitSearch& search);
    void buildPorts(const Problem& problem);
    // Tree over {x, tasks, end} with x and end as leaves under penalties pi; fills degrees.
    // target: transits each port carries in the option that maximises its penalties.
    double lagrangian(const std::vector<double>& pi, std::vector<int>* degree,
                      std::vector<int>* target) const;
    std::pair<int, int> heaviestOption(int task, const std::vector<double>& pi) const;
    void optimisePenalties(double upper, int iterations);
    void tabulate(); // per-task-pair and leaf weights under the root penalties and under none

    int tasks_ = 0;
    std::vector<int> terminalNodes_;  // start node first, then every task corner
    std::vector<int> terminalOfNode_; // node -> terminal, -1
    int endNode_ = 0;
    std::vector<std::vector<double>> terminalDistance_; // terminal -> terminal
    std::vector<double> toEnd_;                         // terminal -> end node

    std::vector<std::vector<int>> portTerminals_;               // port -> its corners (terminals)
    std::vector<std::vector<int>> taskPorts_;                   // task -> its ports (corners)
    std::vector<std::vector<std::pair<int, int>>> taskOptions_; // task -> (entry, exit) ports
    std::vector<std::vector<double>> portDistance_;             // port -> port
    std::vector<std::vector<double>> fromTerminal_;             // terminal -> port
    std::vector<double> portToEnd_;

    std::vector<double> pi_; // root penalties per port
    double root_ = 0.0;

    // Tabulated weights, [0] under pi_ and [1] without penalties.
    std::vector<double> pair_[2];     // task * tasks + task
    std::vector<double> leafFrom_[2]; // terminal * tasks + task
    std::vector<double> leafEnd_[2];  // task
    std::vector<double> offset_[2];   // task: minus its ports' penalties x target

    FlatHashMap<std::uint32_t> treeIndex_{1024}; // task set -> index into treeWeights_
    std::vector<double> treeWeights_;            // pairs: [penalised, plain]
    std::vector<int> scratchTasks_;
    std::vector<double> scratchKey_;
    std::vector<char> scratchIn_;
};

// A proven lower bound on the graph cost of any walk answering the query; cheap on any
// size. `upper` is the cost of a known walk (or +inf). Uses TourBound where affordable, else
// spanningTreeBound.
double provenLowerBound(const TransitGraph& transit, TransitSearch& search, double upper);

// The unpenalised spanning-tree bound for any size, without all-pairs distances: one search
// from every task corner at once (Mehlhorn's construction).
double spanningTreeBound(const TransitGraph& transit, TransitSearch& search);

} // namespace fc::solver_detail

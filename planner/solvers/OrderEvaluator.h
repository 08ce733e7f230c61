// The true graph cost of a cell order. Given the order, the covered set before each transit
// is fixed (the cells already covered), so the best entry/exit corner per cell follows from
// a dynamic programme along the order: one multi-source search per step, seeded with the
// cost of standing at each exit corner of the previous cell.
//
// Local changes are evaluated incrementally against a base order: the steps before the
// change are reused, and once past it, as soon as a step's costs equal the base's up to a
// constant, every later step does too (same covered set, same cells), so the search stops.
#pragma once

#include "solvers/TransitSearch.h"

#include <vector>

namespace fc::solver_detail {

class OrderEvaluator {
public:
    OrderEvaluator(const TransitGraph& graph, TransitSearch& search);

    // Makes `order` (tasks, each once) the base; returns its cost, +inf if infeasible.
    double setBase(const std::vector<int>& order);
    const std::vector<int>& baseOrder() const { return base_; }
    double baseCost() const { return baseCost_; }
    // What the base spends getting to the cell at `position` (roughly: its transit cost).
    double baseStepCost(int position) const;

    // Exact cost of `candidate`, a reordering of the base within positions [first, last];
    // +inf when infeasible or once it provably reaches `bound`.
    double candidateCost(const std::vector<int>& candidate, int first, int last,
                         double bound = kInfinity);
    // Makes the candidate evaluated last the base (its cost must have been finite).
    void acceptCandidate();

    // The cheapest walk for the order (throws SolverError if the order is infeasible).
    Walk walk(const std::vector<int>& order);

    std::uint64_t work() const { return search_.settledTotal(); }
    const Problem* problem() const { return graph_.problem; }

private:
    // Cheapest cost of standing at each exit corner right after covering a step's cell.
    struct StepLabels {
        std::vector<NodeCost> exits;
        std::vector<int> optionOfExit; // option index that reached each exit
    };

    // Runs the transit from `sources` into the cell of `task` and fills `step`.
    void coverStep(const std::vector<NodeCost>& sources, int task, StepLabels& step);
    double finish(const std::vector<NodeCost>& sources); // transit to the end node
    const std::vector<NodeCost>& baseSources(int position) const;
    void setCoveredPrefix(int position); // covered_ = base cells before `position`
    void cover(int task, bool covered);
    struct Comparison {
        bool comparable = false; // same exit corners as the base at this position
        bool synced = false;     // costs equal the base's up to a constant
        double lowerBound = 0.0; // on the final cost
    };
    // Valid once the candidate's cells before and at `position` are the base's as a set.
    Comparison compareWithBase(const StepLabels& step, int position) const;

    const TransitGraph& graph_;
    TransitSearch& search_;
    std::vector<char> covered_;
    int coveredPrefix_ = 0;
    std::vector<NodeCost> startSource_;
    std::vector<int> targets_;

    std::vector<int> base_;
    std::vector<StepLabels> baseSteps_;
    double baseCost_ = kInfinity;

    // The last candidate: its window, recomputed steps [first, stop) and how it ended.
    std::vector<int> candidateWindow_;
    std::vector<StepLabels> candidateSteps_;
    int candidateFirst_ = 0, candidateStop_ = 0;
    bool candidateSynced_ = false;
    double candidateOffset_ = 0.0, candidateCost_ = kInfinity;
};

} // namespace fc::solver_detail

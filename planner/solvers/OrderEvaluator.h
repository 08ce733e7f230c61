// The true graph cost of a cell order. Given the order, the covered set before each transit
// is fixed (the cells already covered), so the best entry/exit corner per cell follows from
// a dynamic programme along the order: one multi-source search per step, seeded with the
// cost of standing at each exit corner of the previous cell.
#pragma once

#include "solvers/TransitSearch.h"

#include <vector>

namespace fc::solver_detail {

class OrderEvaluator {
public:
    OrderEvaluator(const TransitGraph& graph, TransitSearch& search);

    // Cost of the cheapest walk that covers the tasks in `order` (each task exactly once)
    // and ends at the end node; +inf when infeasible or once it provably reaches `bound`.
    // Reuses the steps shared with the previous call's order prefix.
    double cost(const std::vector<int>& order, double bound = kInfinity);

    // The cheapest walk for the order (throws SolverError if the order is infeasible).
    Walk walk(const std::vector<int>& order);

    std::uint64_t work() const { return search_.settledTotal(); }

private:
    // Cheapest cost of standing at each exit corner right after covering a step's cell.
    struct StepLabels {
        std::vector<NodeCost> exits;
        std::vector<int> optionOfExit; // option index that reached each exit
    };

    // Runs the transit into step `position` (the end node when position == order size)
    // from the previous step's labels and fills labels_[position].
    void advance(const std::vector<int>& order, std::size_t position);
    const std::vector<NodeCost>& sourcesFor(std::size_t position);

    const TransitGraph& graph_;
    TransitSearch& search_;
    std::vector<char> covered_;
    std::vector<int> cachedOrder_;
    std::vector<StepLabels> labels_; // valid for cachedOrder_[0..validSteps_)
    std::size_t validSteps_ = 0;
    std::vector<NodeCost> startSource_;
    std::vector<int> targets_;
};

} // namespace fc::solver_detail

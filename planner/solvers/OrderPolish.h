// Local search on the cell order under the TRUE state-dependent graph cost (each candidate
// order re-evaluated by OrderEvaluator, reusing the unchanged prefix and abandoning it as
// soon as it cannot win). Used on small instances, where the proxy's blindness to the
// covered state matters most; budgeted by search work so results do not depend on timing.
#pragma once

#include "solvers/OrderEvaluator.h"
#include "solvers/ProxyDistances.h"

#include <vector>

namespace fc::solver_detail {

class OrderPolish {
public:
    OrderPolish(OrderEvaluator& evaluator, const ProxyDistances& distances, int taskCount,
                std::uint64_t seed);

    // Improves `order` (whose true cost is `cost`) by Or-opt, 2-opt and swap moves, then
    // seeded perturbations while `workBudget` settled nodes remain; returns the new cost.
    double improve(std::vector<int>& order, double cost, std::uint64_t workBudget,
                   const SolveControl& control);

private:
    // One pass of first-improvement moves; returns whether any move was applied.
    bool improvingPass(std::vector<int>& order, double& cost);
    bool tryCandidate(std::vector<int>& order, double& cost);
    bool exhausted() const { return evaluator_.work() >= workLimit_; }
    // Insertion points and reversal ends worth trying for the task at `index`.
    std::vector<int> partnerIndices(const std::vector<int>& order, int index) const;

    OrderEvaluator& evaluator_;
    const ProxyDistances& distances_;
    int count_;
    bool everyPair_; // small enough to try every move, not just those near neighbours
    SeededRandom random_;
    std::vector<int> candidate_;
    std::vector<int> indexOf_;
    std::uint64_t workLimit_ = 0;
};

} // namespace fc::solver_detail

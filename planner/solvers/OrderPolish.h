// Local search on the cell order under the TRUE state-dependent graph cost: each candidate
// is a change evaluated exactly and incrementally by OrderEvaluator. The proxy costs miss
// what the covered state does to transits (the way back across cells covered long before
// costs 3x along their floors), so this pass fixes what they get wrong: cover-on-the-way
// moves (a cell a transit crosses is covered right there), then Or-opt, 2-opt and swaps
// near each cell's nearest neighbours. Budgeted by search work, never by time.
#pragma once

#include "solvers/OrderEvaluator.h"
#include "solvers/ProxyDistances.h"

#include <vector>

namespace fc::solver_detail {

class OrderPolish {
public:
    OrderPolish(OrderEvaluator& evaluator, const ProxyDistances& distances, int taskCount,
                std::uint64_t seed);

    // Improves `order` (cover-on-the-way, Or-opt, 2-opt and swap moves); on small instances
    // then perturbs and descends again while `workBudget` settled nodes remain. Returns the
    // new cost (+inf, order unchanged, if the order is infeasible).
    double improve(std::vector<int>& order, std::uint64_t workBudget, const SolveControl& control);

    // The distinct local optima `improve` reached (its result among them), cheapest first,
    // at most kKeptOptima, each within kOptimaSlack of the cheapest: the graph cost is a
    // proxy, so the pipeline judges these as paths (estimated time) before choosing.
    struct LocalOptimum {
        double cost = 0.0;
        std::vector<int> order;
    };
    static constexpr std::size_t kKeptOptima = 6;
    static constexpr double kOptimaSlack = 0.05;
    const std::vector<LocalOptimum>& localOptima() const { return optima_; }

private:
    // First-improvement moves around the queued tasks until none improves or the budget is
    // spent; an accepted move queues the tasks around it.
    void descend(const SolveControl& control);
    void markDirty(int task);
    void rebase(const std::vector<int>& order); // after the evaluator's base was replaced
    bool improveAt(int index);
    // Moves that reorder more than kLongestWindow positions are only tried when anyLength.
    bool tryMoveSegment(int index, int length, int gap, bool reversed, bool anyLength = false);
    bool tryWindow(int first, int last, bool anyLength = false);
    // Moves each cell that a transit of the base walk crosses to that transit's step;
    // returns whether any move was kept. The rounds alternate it with descents.
    bool coverOnTheWay(const SolveControl& control);
    void coverOnTheWayRounds(const SolveControl& control);
    bool exhausted() const { return evaluator_.work() >= workLimit_; }
    std::vector<int> partnerGaps(int index) const;
    void keepLocalOptimum(); // the evaluator's base, if distinct and cheap enough

    OrderEvaluator& evaluator_;
    const ProxyDistances& distances_;
    int count_;
    SeededRandom random_;
    std::vector<int> candidate_; // equals the evaluator's base outside a move being tried
    std::vector<int> indexOf_;   // task -> position in the base order
    std::vector<char> dirty_;
    std::vector<int> queue_;
    std::uint64_t workLimit_ = 0;
    std::vector<LocalOptimum> optima_;
};

// A given order improved as the solvers do: its proxy local optimum (TourSearch from it,
// then `kicks` perturbations), priced exactly against the order itself (`cost`, its exact
// cost; the proxy misses the covered state), and the cheaper polished under the true cost
// within `workBudget`. `order` becomes the result; returns its cost. Shared by
// refineCellOrder (no kicks, a small budget) and searchFromWalk (the heuristic's effort).
double searchFromOrder(const Problem& problem, OrderEvaluator& evaluator, ProxyDistances& distances,
                       std::vector<int>& order, double cost, int kicks, std::uint64_t workBudget,
                       std::uint64_t polishSeed, const SolveControl& control);

} // namespace fc::solver_detail

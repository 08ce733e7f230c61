// Fast local search over the cell order and each cell's cover option under the proxy costs
// (ProxyDistances): nearest-neighbour construction, then Or-opt, 2-opt and option changes
// driven by each cell's nearest neighbours, an exact option pass along the order, and
// iterated local search with seeded segment swaps.
#pragma once

#include "solvers/ProxyDistances.h"

#include <vector>

namespace fc::solver_detail {

class TourSearch {
public:
    TourSearch(const Problem& problem, ProxyDistances& distances, std::uint64_t seed);

    void buildNearestNeighbour();
    // Starts from a given order of all tasks (e.g. a learnt policy's), best options for it.
    void startFrom(const std::vector<int>& order);
    // Moves to a local optimum of the proxy cost.
    void optimise();
    // Iterated local search: `kicks` perturbations, each kept only if the result improves.
    void iterate(int kicks, const SolveControl& control);

    std::vector<int> order() const;
    double cost() const { return cost_; }

private:
    const CoverOption& optionOf(int task) const { return problem_.options[task][option_[task]]; }
    int exitAt(int position) const;
    int entryAt(int position) const;
    double gap(int position) { return distances_.between(exitAt(position), entryAt(position + 1)); }
    int positionOf(int mark) const;
    double fullCost();

    bool improve(int task);
    bool tryOptionChange(int task);
    bool tryOrOpt(int task);
    bool tryTwoOpt(int task);
    void optimiseOptions(); // exact choice of options for the current order (Viterbi)

    void moveSegment(int first, int last, int gapAfter, bool reversed, int singleOption);
    void reverseRange(int first, int last);
    void refreshPositions(int from, int to);
    void activateAround(int position);
    void runQueue();

    const Problem& problem_;
    ProxyDistances& distances_;
    SeededRandom random_;
    int count_;
    std::vector<int> tour_; // [0] start mark, [1..n] tasks, [n+1] end mark
    std::vector<int> position_;
    std::vector<int> option_; // per task
    double cost_ = 0.0;
    std::vector<int> queue_;
    std::size_t queueHead_ = 0;
    std::vector<char> queued_;
};

} // namespace fc::solver_detail

#include "solvers/OrderPolish.h"

#include <algorithm>

namespace fc::solver_detail {

namespace {

constexpr double kImprovement = 1e-7;
constexpr int kEveryPairLimit = 14; // up to here every move is tried, not just near ones

} // namespace

OrderPolish::OrderPolish(OrderEvaluator& evaluator, const ProxyDistances& distances,
                         int taskCount, std::uint64_t seed)
    : evaluator_(evaluator), distances_(distances), count_(taskCount),
      everyPair_(taskCount <= kEveryPairLimit), random_(seed), indexOf_(taskCount, 0) {}

bool OrderPolish::tryCandidate(std::vector<int>& order, double& cost) {
    const double candidateCost = evaluator_.cost(candidate_, cost - kImprovement);
    if (!(candidateCost < cost - kImprovement))
        return false;
    order = candidate_;
    cost = candidateCost;
    return true;
}

std::vector<int> OrderPolish::partnerIndices(const std::vector<int>& order, int index) const {
    // Gaps g in [0, n]: g sits between order[g - 1] and order[g].
    std::vector<int> gaps;
    if (everyPair_) {
        for (int g = 0; g <= count_; ++g)
            gaps.push_back(g);
        return gaps;
    }
    for (int mark : distances_.neighbours(order[index])) {
        if (mark == kStartMark) {
            gaps.push_back(0);
        } else if (mark == kEndMark) {
            gaps.push_back(count_);
        } else {
            gaps.push_back(indexOf_[mark]);
            gaps.push_back(indexOf_[mark] + 1);
        }
    }
    std::sort(gaps.begin(), gaps.end());
    gaps.erase(std::unique(gaps.begin(), gaps.end()), gaps.end());
    return gaps;
}

bool OrderPolish::improvingPass(std::vector<int>& order, double& cost) {
    // Late positions first: their candidates share the longest prefix with the order.
    for (int i = count_ - 1; i >= 0 && !exhausted(); --i) {
        for (int k = 0; k < count_; ++k)
            indexOf_[order[k]] = k;
        const std::vector<int> gaps = partnerIndices(order, i);

        // Or-opt: move order[i .. i+length) to another gap, either way round.
        for (int length = 1; length <= 3 && i + length <= count_; ++length) {
            for (int g : gaps) {
                if (g >= i && g <= i + length)
                    continue;
                for (int reversed = 0; reversed < (length == 1 ? 1 : 2); ++reversed) {
                    candidate_.clear();
                    const int target = g < i ? g : g - length;
                    for (int k = 0; k < count_; ++k) {
                        if (k >= i && k < i + length)
                            continue;
                        if (static_cast<int>(candidate_.size()) == target)
                            for (int s = 0; s < length; ++s)
                                candidate_.push_back(order[reversed ? i + length - 1 - s : i + s]);
                        candidate_.push_back(order[k]);
                    }
                    if (static_cast<int>(candidate_.size()) == target)
                        for (int s = 0; s < length; ++s)
                            candidate_.push_back(order[reversed ? i + length - 1 - s : i + s]);
                    if (tryCandidate(order, cost))
                        return true;
                }
            }
        }

        // 2-opt (reverse a stretch so order[i] meets a partner, the start or the end) and
        // swaps.
        for (int g : gaps) {
            const int j = std::min(g, count_ - 1);
            const int low = std::min(i, j), high = std::max(i, j);
            std::vector<std::pair<int, int>> stretches{{low + 1, high}, {low, high - 1}};
            if (g == 0)
                stretches.push_back({0, i});
            if (g == count_)
                stretches.push_back({i, count_ - 1});
            for (const auto& [first, last] : stretches) {
                if (last - first < 1)
                    continue;
                candidate_ = order;
                std::reverse(candidate_.begin() + first, candidate_.begin() + last + 1);
                if (tryCandidate(order, cost))
                    return true;
            }
            if (j != i && std::abs(j - i) > 1) {
                candidate_ = order;
                std::swap(candidate_[i], candidate_[j]);
                if (tryCandidate(order, cost))
                    return true;
            }
        }
    }
    return false;
}

double OrderPolish::improve(std::vector<int>& order, double cost, std::uint64_t workBudget,
                            const SolveControl& control) {
    workLimit_ = evaluator_.work() + workBudget;
    auto descend = [&](std::vector<int>& current, double& currentCost) {
        while (!exhausted() && improvingPass(current, currentCost))
            throwIfCancelled(control, "heuristic");
    };
    descend(order, cost);
    if (count_ < 4)
        return cost;
    while (!exhausted()) {
        // Perturb: swap two adjacent stretches, sometimes reversing one (a double bridge).
        std::vector<int> trial = order;
        const int a = random_.below(count_ - 2);
        const int b = a + 1 + random_.below(std::min(count_ - a - 2, 5));
        const int c = b + 1 + random_.below(std::min(count_ - b, 5));
        std::rotate(trial.begin() + a, trial.begin() + b, trial.begin() + c);
        if (random_.below(2) == 1)
            std::reverse(trial.begin() + a, trial.begin() + a + (c - b));
        double trialCost = evaluator_.cost(trial);
        descend(trial, trialCost);
        if (trialCost < cost - kImprovement) {
            order = trial;
            cost = trialCost;
        }
        throwIfCancelled(control, "heuristic");
    }
    return cost;
}

} // namespace fc::solver_detail

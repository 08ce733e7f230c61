#include "solvers/OrderPolish.h"

#include <algorithm>

namespace fc::solver_detail {

namespace {

constexpr double kImprovement = 1e-7;
// Moves bring a cell next to one of its few nearest: a narrow neighbourhood leaves more of
// the budget for perturbations, which pays better than wider moves.
constexpr std::size_t kPartners = 5;
constexpr int kPerturbLimit = 60;  // up to here perturbations follow the descent
constexpr int kLongestWindow = 16; // positions a neighbourhood move may reorder
constexpr int kCrossingRounds = 4; // passes of cover-on-the-way moves

} // namespace

OrderPolish::OrderPolish(OrderEvaluator& evaluator, const ProxyDistances& distances, int taskCount,
                         std::uint64_t seed)
    : evaluator_(evaluator), distances_(distances), count_(taskCount), random_(seed),
      indexOf_(taskCount, 0), dirty_(taskCount, 0) {}

bool OrderPolish::tryWindow(int first, int last, bool anyLength) {
    const std::vector<int>& base = evaluator_.baseOrder();
    if (!anyLength && last - first + 1 > kLongestWindow) {
        std::copy(base.begin() + first, base.begin() + last + 1, candidate_.begin() + first);
        return false;
    }
    const double cost =
        evaluator_.candidateCost(candidate_, first, last, evaluator_.baseCost() - kImprovement);
    if (cost < kInfinity) {
        evaluator_.acceptCandidate();
        for (int k = first; k <= last; ++k)
            indexOf_[base[k]] = k;
        for (int k = std::max(first - 1, 0); k <= std::min(last + 1, count_ - 1); ++k)
            markDirty(base[k]);
        return true;
    }
    std::copy(base.begin() + first, base.begin() + last + 1, candidate_.begin() + first);
    return false;
}

bool OrderPolish::tryMoveSegment(int index, int length, int gap, bool reversed, bool anyLength) {
    // Gap g sits before base[g]; the segment base[index .. index+length) moves there.
    const std::vector<int>& base = evaluator_.baseOrder();
    auto segmentAt = [&](int to) {
        for (int s = 0; s < length; ++s)
            candidate_[to + s] = base[reversed ? index + length - 1 - s : index + s];
    };
    if (gap < index) {
        segmentAt(gap);
        std::copy(base.begin() + gap, base.begin() + index, candidate_.begin() + gap + length);
        return tryWindow(gap, index + length - 1, anyLength);
    }
    std::copy(base.begin() + index + length, base.begin() + gap, candidate_.begin() + index);
    segmentAt(gap - length);
    return tryWindow(index, gap - 1, anyLength);
}

std::vector<int> OrderPolish::partnerGaps(int index) const {
    std::vector<int> gaps;
    const std::vector<int>& marks = distances_.neighbours(evaluator_.baseOrder()[index]);
    for (std::size_t m = 0; m < std::min<std::size_t>(kPartners, marks.size()); ++m) {
        const int mark = marks[m];
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

bool OrderPolish::improveAt(int i) {
    const std::vector<int>& base = evaluator_.baseOrder();
    const std::vector<int> gaps = partnerGaps(i);

    // Or-opt: move base[i .. i+length) to another gap, either way round.
    for (int length = 1; length <= 3 && i + length <= count_; ++length)
        for (int g : gaps)
            if (g < i || g > i + length)
                for (int reversed = 0; reversed < (length == 1 ? 1 : 2); ++reversed)
                    if (tryMoveSegment(i, length, g, reversed != 0))
                        return true;

    // 2-opt (reverse a stretch so base[i] meets a partner, the start or the end), swaps.
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
            std::reverse_copy(base.begin() + first, base.begin() + last + 1,
                              candidate_.begin() + first);
            if (tryWindow(first, last))
                return true;
        }
        if (std::abs(j - i) > 1) {
            std::swap(candidate_[i], candidate_[j]);
            if (tryWindow(low, high))
                return true;
        }
    }
    return false;
}

bool OrderPolish::coverOnTheWay(const SolveControl& control) {
    // A transit that crosses a required cell (covered earlier at 3x along its floor, or to
    // be covered later) suggests covering that cell right there instead: a long-range move
    // that local neighbourhoods never propose (typically the way back to the end through
    // cells covered long before).
    const Problem& problem = *evaluator_.problem();
    const CornerGraph& graph = *problem.graph;
    const Walk walk = evaluator_.walk(evaluator_.baseOrder()); // the base is unchanged
    std::vector<std::pair<int, int>> crossings; // (step, task crossed by its transit)
    std::vector<char> covered(count_, 0);
    int step = 0;
    for (std::size_t i = 0; i < walk.edges.size(); ++i) {
        const GraphEdge& edge = graph.edges[walk.edges[i]];
        const int task = edge.cell >= 0 ? problem.taskOfCell[edge.cell] : -1;
        if (edge.kind == EdgeKind::Coverage && task >= 0 && !covered[task]) {
            covered[task] = 1;
            ++step;
            continue;
        }
        const int crossed = problem.taskOfCell[graph.nodes[walk.nodes[i + 1]].cell];
        if (crossed >= 0 &&
            (crossings.empty() || crossings.back() != std::make_pair(step, crossed)))
            crossings.push_back({step, crossed});
    }
    bool improved = false;
    for (const auto& [gap, task] : crossings) {
        if (exhausted())
            break;
        throwIfCancelled(control, "heuristic");
        const int index = indexOf_[task]; // positions shift after a move: gaps are guesses
        if (gap >= index && gap <= index + 1)
            continue;
        improved = tryMoveSegment(index, 1, std::min(gap, count_), false, true) || improved;
    }
    return improved;
}

void OrderPolish::coverOnTheWayRounds(const SolveControl& control) {
    for (int round = 0; round < kCrossingRounds && !exhausted() && coverOnTheWay(control); ++round)
        descend(control); // around what moved
}

void OrderPolish::markDirty(int task) {
    if (!dirty_[task]) {
        dirty_[task] = 1;
        queue_.push_back(task);
    }
}

void OrderPolish::rebase(const std::vector<int>& order) {
    candidate_ = order;
    for (int k = 0; k < count_; ++k)
        indexOf_[order[k]] = k;
}

void OrderPolish::descend(const SolveControl& control) {
    // Tasks whose surroundings changed are re-examined until none yields a better order.
    for (std::size_t next = 0; next < queue_.size() && !exhausted(); ++next) {
        const int task = queue_[next];
        dirty_[task] = 0;
        const int position = indexOf_[task];
        if (improveAt(position) || (position > 0 && !exhausted() && improveAt(position - 1)))
            markDirty(task);
        if (next % 32 == 0)
            throwIfCancelled(control, "heuristic");
    }
    for (int task : queue_)
        dirty_[task] = 0;
    queue_.clear();
}

void OrderPolish::keepLocalOptimum() {
    const double cost = evaluator_.baseCost();
    const std::vector<int>& order = evaluator_.baseOrder();
    if (!(cost < kInfinity) || std::any_of(optima_.begin(), optima_.end(),
                                           [&](const auto& o) { return o.order == order; }))
        return;
    optima_.push_back({cost, order});
    std::stable_sort(optima_.begin(), optima_.end(),
                     [](const auto& a, const auto& b) { return a.cost < b.cost; });
    const double limit = optima_.front().cost * (1.0 + kOptimaSlack) + kImprovement;
    while (optima_.size() > kKeptOptima || optima_.back().cost > limit)
        optima_.pop_back();
}

double OrderPolish::improve(std::vector<int>& order, std::uint64_t workBudget,
                            const SolveControl& control) {
    workLimit_ = evaluator_.work() + workBudget;
    if (!(evaluator_.setBase(order) < kInfinity))
        return kInfinity;
    rebase(order);
    coverOnTheWayRounds(control); // few moves, and where the proxy erred most they pay most
    // Then every task, costliest steps first: moves that remove an expensive transit are the
    // ones that pay, so a tight budget finds them early.
    std::vector<std::pair<double, int>> steps(count_);
    for (int k = 0; k < count_; ++k)
        steps[k] = {-evaluator_.baseStepCost(k), evaluator_.baseOrder()[k]};
    std::sort(steps.begin(), steps.end());
    for (const auto& step : steps)
        markDirty(step.second);
    descend(control);
    coverOnTheWayRounds(control);

    std::vector<int> best = evaluator_.baseOrder();
    double bestCost = evaluator_.baseCost();
    keepLocalOptimum();
    // Perturbations stop when the budget is spent or many in a row found nothing.
    const int patience = std::max(10, count_);
    for (int failures = 0;
         count_ >= 4 && count_ <= kPerturbLimit && failures < patience && !exhausted();
         ++failures) {
        // Perturb: swap two short adjacent stretches, sometimes reversing one.
        std::vector<int> trial = best;
        const int a = random_.below(count_ - 2);
        const int b = a + 1 + random_.below(std::min(count_ - a - 2, 5));
        const int c = b + 1 + random_.below(std::min(count_ - b, 5));
        std::rotate(trial.begin() + a, trial.begin() + b, trial.begin() + c);
        if (random_.below(2) == 1)
            std::reverse(trial.begin() + a, trial.begin() + a + (c - b));
        if (!(evaluator_.setBase(trial) < kInfinity))
            continue;
        rebase(trial);
        for (int k = std::max(a - 1, 0); k <= std::min(c, count_ - 1); ++k)
            markDirty(trial[k]);
        descend(control);
        keepLocalOptimum();
        if (evaluator_.baseCost() < bestCost - kImprovement) {
            best = evaluator_.baseOrder();
            bestCost = evaluator_.baseCost();
            failures = -1;
        }
    }
    order = best;
    return bestCost;
}

} // namespace fc::solver_detail

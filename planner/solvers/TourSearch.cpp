#include "solvers/TourSearch.h"

#include <algorithm>

namespace fc::solver_detail {

namespace {

constexpr double kImprovement = 1e-7; // smaller changes are rounding, not progress
constexpr int kKickSegment = 5;       // longest segment a perturbation moves

} // namespace

TourSearch::TourSearch(const Problem& problem, ProxyDistances& distances, std::uint64_t seed)
    : problem_(problem), distances_(distances), random_(seed), count_(problem.taskCount()),
      position_(count_, 0), option_(count_, 0), queued_(count_, 0) {}

int TourSearch::exitAt(int position) const {
    return position == 0 ? problem_.startNode : optionOf(tour_[position]).exit;
}

int TourSearch::entryAt(int position) const {
    return position == count_ + 1 ? problem_.endNode : optionOf(tour_[position]).entry;
}

int TourSearch::positionOf(int mark) const {
    return mark == kStartMark ? 0 : mark == kEndMark ? count_ + 1 : position_[mark];
}

double TourSearch::fullCost() {
    double total = 0.0;
    for (int p = 0; p <= count_; ++p)
        total += gap(p);
    return total;
}

std::vector<int> TourSearch::order() const {
    return std::vector<int>(tour_.begin() + 1, tour_.end() - 1);
}

void TourSearch::buildNearestNeighbour() {
    const CornerGraph& graph = *problem_.graph;
    std::vector<char> visited(count_, 0);
    std::vector<int> order;
    int here = problem_.startNode;
    const std::vector<int>* candidates = &distances_.nearStart();
    while (static_cast<int>(order.size()) < count_) {
        int chosen = -1, chosenOption = 0;
        double chosenCost = kInfinity;
        auto consider = [&](int task) {
            for (std::size_t o = 0; o < problem_.options[task].size(); ++o) {
                const double c = distances_.between(here, problem_.options[task][o].entry);
                if (c < chosenCost) {
                    chosen = task;
                    chosenOption = static_cast<int>(o);
                    chosenCost = c;
                }
            }
        };
        for (int mark : *candidates)
            if (mark >= 0 && !visited[mark])
                consider(mark);
        if (chosen < 0) { // every listed neighbour is taken: nearest by straight line
            int nearest = -1;
            double nearestDistance = kInfinity;
            for (int task = 0; task < count_; ++task) {
                if (visited[task])
                    continue;
                for (const CoverOption& option : problem_.options[task]) {
                    const double d =
                        distance(graph.nodes[here].position, graph.nodes[option.entry].position);
                    if (d < nearestDistance) {
                        nearest = task;
                        nearestDistance = d;
                    }
                }
            }
            consider(nearest);
        }
        visited[chosen] = 1;
        order.push_back(chosen);
        option_[chosen] = chosenOption;
        here = problem_.options[chosen][chosenOption].exit;
        candidates = &distances_.neighbours(chosen);
    }
    tour_.assign(1, kStartMark);
    tour_.insert(tour_.end(), order.begin(), order.end());
    tour_.push_back(kEndMark);
    refreshPositions(1, count_);
    cost_ = fullCost();
}

void TourSearch::startFrom(const std::vector<int>& order) {
    tour_.assign(1, kStartMark);
    tour_.insert(tour_.end(), order.begin(), order.end());
    tour_.push_back(kEndMark);
    refreshPositions(1, count_);
    std::fill(option_.begin(), option_.end(), 0);
    cost_ = fullCost();
    optimiseOptions(); // the best options for this order, when cheaper
}

void TourSearch::refreshPositions(int from, int to) {
    for (int p = std::max(from, 1); p <= std::min(to, count_); ++p)
        position_[tour_[p]] = p;
}

void TourSearch::activateAround(int position) {
    for (int p = position - 1; p <= position + 1; ++p) {
        if (p < 1 || p > count_ || queued_[tour_[p]])
            continue;
        queued_[tour_[p]] = 1;
        queue_.push_back(tour_[p]);
    }
}

void TourSearch::runQueue() {
    while (queueHead_ < queue_.size()) {
        const int task = queue_[queueHead_++];
        queued_[task] = 0;
        while (improve(task))
            continue; // keep improving around this task while moves pay
    }
    queue_.clear();
    queueHead_ = 0;
}

void TourSearch::optimise() {
    for (int round = 0; round < 5; ++round) {
        for (int p = 1; p <= count_; ++p)
            activateAround(p);
        runQueue();
        const double before = cost_;
        optimiseOptions();
        if (!(cost_ < before - kImprovement))
            break;
    }
}

bool TourSearch::improve(int task) {
    return tryOptionChange(task) || tryOrOpt(task) || tryTwoOpt(task);
}

bool TourSearch::tryOptionChange(int task) {
    const int p = position_[task];
    const double current = gap(p - 1) + gap(p);
    const int before = exitAt(p - 1), after = entryAt(p + 1);
    for (std::size_t o = 0; o < problem_.options[task].size(); ++o) {
        const CoverOption& option = problem_.options[task][o];
        const double changed =
            distances_.between(before, option.entry) + distances_.between(option.exit, after);
        if (changed < current - kImprovement) {
            option_[task] = static_cast<int>(o);
            cost_ += changed - current;
            activateAround(p);
            return true;
        }
    }
    return false;
}

bool TourSearch::tryOrOpt(int task) {
    const int p = position_[task];
    for (int length = 1; length <= 3; ++length) {
        for (int placement = 0; placement < (length == 1 ? 1 : 2); ++placement) {
            const int first = placement == 0 ? p : p - length + 1;
            const int last = first + length - 1;
            if (first < 1 || last > count_)
                continue;
            const std::vector<int>& marks = distances_.neighbours(task);
            const std::vector<double>& costs = distances_.neighbourCosts(task);
            // Gain criterion: the link made next to this task must cost less than removing
            // the segment saves (neighbours come nearest first; the closing link is only
            // looked up when some neighbour could pass).
            const double linksRemoved = gap(first - 1) + gap(last);
            if (marks.empty() || costs[0] >= linksRemoved)
                continue;
            const double removalGain =
                linksRemoved - distances_.between(exitAt(first - 1), entryAt(last + 1));
            for (std::size_t k = 0; k < marks.size(); ++k) {
                if (costs[k] >= removalGain)
                    break;
                const int q = positionOf(marks[k]);
                for (int g = q - 1; g <= q; ++g) {
                    if (g < 0 || g > count_ || (g >= first - 1 && g <= last))
                        continue;
                    const int x = exitAt(g), y = entryAt(g + 1);
                    const double base = distances_.between(x, y);
                    auto insertion = [&](int entry, int exit) {
                        const double partial = distances_.between(x, entry) - base;
                        if (partial - removalGain >= 0.0)
                            return kInfinity; // the second link cannot make up for it
                        return partial + distances_.between(exit, y);
                    };
                    if (length == 1) {
                        for (std::size_t o = 0; o < problem_.options[task].size(); ++o) {
                            const CoverOption& option = problem_.options[task][o];
                            const double delta = insertion(option.entry, option.exit) - removalGain;
                            if (delta < -kImprovement) {
                                moveSegment(first, last, g, false, static_cast<int>(o));
                                cost_ += delta;
                                return true;
                            }
                        }
                        continue;
                    }
                    for (int reversed = 0; reversed < 2; ++reversed) {
                        const double delta = (reversed ? insertion(exitAt(last), entryAt(first))
                                                       : insertion(entryAt(first), exitAt(last))) -
                                             removalGain;
                        if (delta < -kImprovement) {
                            moveSegment(first, last, g, reversed != 0, -1);
                            cost_ += delta;
                            return true;
                        }
                    }
                }
            }
        }
    }
    return false;
}

bool TourSearch::tryTwoOpt(int task) {
    const int p = position_[task];
    const std::vector<int>& marks = distances_.neighbours(task);
    const std::vector<double>& costs = distances_.neighbourCosts(task);
    // Gain criterion: the new link at this task must cost less than the link it replaces
    // there (after its exit when shift is 0, before its entry when shift is 1).
    const double replaced[2] = {gap(p), gap(p - 1)};
    for (std::size_t k = 0; k < marks.size(); ++k) {
        if (costs[k] >= std::max(replaced[0], replaced[1]))
            break;
        const int q = positionOf(marks[k]);
        const int low = std::min(p, q), high = std::max(p, q);
        for (int shift = 0; shift < 2; ++shift) {
            if (costs[k] >= replaced[shift])
                continue;
            // Reversing tour_[i+1..j] replaces gaps i and j (links tour_[i] with tour_[j]
            // when shift is 0, their successors when shift is 1).
            const int i = low - shift, j = high - shift;
            if (i < 0 || j > count_ || i >= j)
                continue;
            auto exitsLink = [&] { return distances_.between(exitAt(i), exitAt(j)); };
            auto entriesLink = [&] { return distances_.between(entryAt(i + 1), entryAt(j + 1)); };
            // The link at this task first: the other is only looked up if it could pay.
            const double partial = (shift == 0 ? exitsLink() : entriesLink()) - gap(i) - gap(j);
            if (partial >= 0.0)
                continue;
            const double delta = partial + (shift == 0 ? entriesLink() : exitsLink());
            if (delta < -kImprovement) {
                reverseRange(i + 1, j);
                cost_ += delta;
                activateAround(i);
                activateAround(i + 1);
                activateAround(j);
                activateAround(j + 1);
                return true;
            }
        }
    }
    return false;
}

void TourSearch::reverseRange(int first, int last) {
    std::reverse(tour_.begin() + first, tour_.begin() + last + 1);
    for (int p = first; p <= last; ++p)
        option_[tour_[p]] ^= 1; // options 2i and 2i+1 are the two directions of one edge
    refreshPositions(first, last);
}

void TourSearch::moveSegment(int first, int last, int gapAfter, bool reversed, int singleOption) {
    const int length = last - first + 1;
    const int before = tour_[first - 1], after = tour_[last + 1];
    int newFirst;
    if (gapAfter > last) {
        std::rotate(tour_.begin() + first, tour_.begin() + last + 1, tour_.begin() + gapAfter + 1);
        newFirst = gapAfter - length + 1;
        refreshPositions(first, gapAfter);
    } else {
        std::rotate(tour_.begin() + gapAfter + 1, tour_.begin() + first, tour_.begin() + last + 1);
        newFirst = gapAfter + 1;
        refreshPositions(gapAfter + 1, last);
    }
    if (reversed)
        reverseRange(newFirst, newFirst + length - 1);
    if (singleOption >= 0)
        option_[tour_[newFirst]] = singleOption;
    activateAround(newFirst);
    activateAround(newFirst + length - 1);
    activateAround(positionOf(before));
    activateAround(positionOf(after));
}

void TourSearch::optimiseOptions() {
    // Viterbi along the order: cheapest cost of leaving each task by each option.
    std::vector<std::vector<double>> best(count_ + 1);
    std::vector<std::vector<int>> from(count_ + 1);
    best[0] = {0.0};
    for (int p = 1; p <= count_; ++p) {
        const std::vector<CoverOption>& options = problem_.options[tour_[p]];
        best[p].assign(options.size(), kInfinity);
        from[p].assign(options.size(), 0);
        for (std::size_t o = 0; o < options.size(); ++o) {
            for (std::size_t prev = 0; prev < best[p - 1].size(); ++prev) {
                const int exit =
                    p == 1 ? problem_.startNode : problem_.options[tour_[p - 1]][prev].exit;
                const double c = best[p - 1][prev] + distances_.between(exit, options[o].entry);
                if (c < best[p][o]) {
                    best[p][o] = c;
                    from[p][o] = static_cast<int>(prev);
                }
            }
        }
    }
    double total = kInfinity;
    int choice = 0;
    for (std::size_t prev = 0; prev < best[count_].size(); ++prev) {
        const int exit =
            count_ == 0 ? problem_.startNode : problem_.options[tour_[count_]][prev].exit;
        const double c = best[count_][prev] + distances_.between(exit, problem_.endNode);
        if (c < total) {
            total = c;
            choice = static_cast<int>(prev);
        }
    }
    if (!(total < cost_ - kImprovement))
        return;
    for (int p = count_; p >= 1; --p) {
        option_[tour_[p]] = choice;
        choice = from[p][choice];
    }
    cost_ = total;
}

void TourSearch::iterate(int kicks, const SolveControl& control) {
    if (count_ < 3)
        return;
    std::vector<int> bestTour = tour_, bestOption = option_;
    double bestCost = cost_;
    for (int kick = 0; kick < kicks; ++kick) {
        if (kick % 64 == 0)
            throwIfCancelled(control, "heuristic");
        // Swap two short adjacent segments (a local double bridge), sometimes reversing
        // one: new links stay between nearby cells, whose distances are known.
        const int a = 1 + random_.below(count_ - 1);
        const int b = a + 1 + random_.below(std::min(count_ - a, kKickSegment));
        const int c = b + 1 + random_.below(std::min(count_ + 1 - b, kKickSegment));
        // swap [a,b) and [b,c)
        const double removed = gap(a - 1) + gap(b - 1) + gap(c - 1);
        std::rotate(tour_.begin() + a, tour_.begin() + b, tour_.begin() + c);
        refreshPositions(a, c - 1);
        if (random_.below(2) == 1)
            reverseRange(a, a + (c - b) - 1);
        cost_ += gap(a - 1) + gap(a + (c - b) - 1) + gap(c - 1) - removed;
        activateAround(a);
        activateAround(a + (c - b) - 1);
        activateAround(a + (c - b));
        activateAround(c - 1);
        runQueue();
        if (cost_ < bestCost - kImprovement) {
            bestTour = tour_;
            bestOption = option_;
            bestCost = cost_;
        } else {
            tour_ = bestTour;
            option_ = bestOption;
            cost_ = bestCost;
            refreshPositions(1, count_);
        }
    }
    optimise();
}

} // namespace fc::solver_detail

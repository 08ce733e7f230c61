// Energy-aware local search over neighbour lists: 2-opt (the reversed segment is priced
// both ways, as transformation costs need not be symmetric) and Or-opt (a run of one to
// three waypoints moved next to one of its cheapest neighbours, either way round). First
// improvement, until a pass over the tour finds none.
#include "tiling/WaypointIndex.h"
#include "tiling/WaypointOrder.h"

#include <algorithm>

namespace fc::tiling {
namespace {

constexpr int kNeighbours = 8;
constexpr int kMaxPasses = 100;
constexpr double kMinGain = 1e-9;

class Polisher {
public:
    Polisher(const OrderingProblem& problem, Tour tour)
        : p_(problem), t_(std::move(tour)), n_(static_cast<int>(t_.size())) {
        const WaypointIndex index(problem);
        for (int w = 0; w < n_; ++w)
            near_.push_back(index.cheapestMoves(w, kNeighbours));
        refresh();
    }

    Tour run() {
        for (int pass = 0; pass < kMaxPasses; ++pass) {
            bool improved = false;
            for (int a = 0; a < n_; ++a)
                improved = improveAround(a) || improved;
            if (!improved)
                break;
        }
        return startingAtZero(t_);
    }

private:
    int at(int k) const { return t_[(k % n_ + n_) % n_]; }
    double c(int a, int b) const { return p_.cost(a, b); }

    void refresh() {
        pos_.assign(n_, 0);
        forward_.assign(n_ + 1, 0.0);
        backward_.assign(n_ + 1, 0.0);
        for (int k = 0; k < n_; ++k) {
            pos_[t_[k]] = k;
            forward_[k + 1] = forward_[k] + c(at(k), at(k + 1));
            backward_[k + 1] = backward_[k] + c(at(k + 1), at(k));
        }
    }

    bool improveAround(int a) {
        for (int b : near_[a]) {
            const int pa = pos_[a], pb = pos_[b];
            // 2-opt adding a -> b (a first) or a's predecessor edge variant.
            if (pb > pa + 1 && twoOpt(pa, pb))
                return true;
            if (pb > pa && pa >= 1 && twoOpt(pa - 1, pb - 1))
                return true;
            if (orOpt(a, b))
                return true;
        }
        return false;
    }

    // Edges (x, x+1) and (y, y+1) become (x, y) and (x+1, y+1); x+1..y reversed.
    bool twoOpt(int x, int y) {
        if (y < x + 2 || y >= n_)
            return false;
        const double inside = (backward_[y] - backward_[x + 1]) - (forward_[y] - forward_[x + 1]);
        const double delta = c(at(x), at(y)) + c(at(x + 1), at(y + 1)) - c(at(x), at(x + 1)) -
                             c(at(y), at(y + 1)) + inside;
        if (delta > -kMinGain)
            return false;
        std::reverse(t_.begin() + x + 1, t_.begin() + y + 1);
        refresh();
        return true;
    }

    // Moves the run of `length` waypoints starting at b's position to follow a (or to
    // precede a's successor reversed), when that is cheaper.
    bool orOpt(int a, int b) {
        for (int length = 1; length <= 3; ++length) {
            const int s = pos_[b], e = s + length - 1, pa = pos_[a];
            if (s < 1 || e >= n_ || (pa >= s - 1 && pa <= e))
                continue;
            const int first = at(s), last = at(e), before = at(s - 1), after = at(e + 1);
            const int next = at(pa + 1);
            const double removed = c(before, first) + c(last, after) + c(a, next);
            const double runForward = forward_[e] - forward_[s];
            const double runBackward = backward_[e] - backward_[s];
            const double kept = c(before, after);
            const double asIs = kept + c(a, first) + c(last, next) - removed;
            const double flipped =
                kept + c(a, last) + c(first, next) + runBackward - runForward - removed;
            if (std::min(asIs, flipped) > -kMinGain)
                continue;
            Tour run(t_.begin() + s, t_.begin() + e + 1);
            if (flipped < asIs)
                std::reverse(run.begin(), run.end());
            t_.erase(t_.begin() + s, t_.begin() + e + 1);
            const int insertAt = (pa > e ? pa - length : pa) + 1;
            t_.insert(t_.begin() + insertAt, run.begin(), run.end());
            refresh();
            return true;
        }
        return false;
    }

    const OrderingProblem& p_;
    Tour t_;
    int n_;
    std::vector<std::vector<int>> near_;
    std::vector<int> pos_;
    std::vector<double> forward_, backward_; // prefix sums of the tour's moves each way
};

} // namespace

Tour polishTour(const OrderingProblem& problem, Tour tour) {
    if (problem.size() < 4 || !isTour(tour, problem.size()))
        return tour;
    return Polisher(problem, std::move(tour)).run();
}

} // namespace fc::tiling

#include "tiling/ppo/TourBuilder.h"

#include <algorithm>
#include <cmath>

namespace fc::tiling {
namespace {

float squashed(double v) {
    return static_cast<float>(v / std::sqrt(1.0 + v * v / 16.0));
}

} // namespace

void moveFeatures(const OrderingProblem& problem, int from, int to, double cheapest,
                  int freeNeighbours, int rank, int window, float* out) {
    const Pose& a = problem.poses[from];
    const Pose& b = problem.poses[to];
    const double unit = 4.0 * problem.blockLeg();
    const Vec2 d = b.waypoint() - a.waypoint();
    const double c = std::cos(a.heading), s = std::sin(a.heading);
    const double energyUnit = problem.robot.totalMass() * problem.blockLeg();
    const double energy = problem.cost(from, to);
    out[0] = squashed((c * d.x + s * d.y) / unit);
    out[1] = squashed((-s * d.x + c * d.y) / unit);
    out[2] = static_cast<float>(std::cos(b.heading - a.heading));
    out[3] = static_cast<float>(std::sin(b.heading - a.heading));
    out[4] = a.shape == b.shape ? 0.0f : 1.0f;
    out[5] = static_cast<float>(std::log1p(energy / energyUnit));
    out[6] = static_cast<float>(std::log1p(std::max(0.0, energy - cheapest) / energyUnit));
    out[7] = static_cast<float>(freeNeighbours) / kIsolationNeighbours;
    out[8] = static_cast<float>(rank) / static_cast<float>(window);
}

std::shared_ptr<const Neighbourhood> neighbourhoodOf(const OrderingProblem& problem) {
    auto result = std::make_shared<Neighbourhood>();
    const WaypointIndex index(problem);
    for (int w = 0; w < problem.size(); ++w)
        result->push_back(index.cheapestMoves(w, kIsolationNeighbours));
    return result;
}

TourBuilder::TourBuilder(const OrderingProblem& problem, int window,
                         std::shared_ptr<const Neighbourhood> neighbourhood)
    : problem_(problem), window_(window), neighbourhood_(std::move(neighbourhood)),
      remaining_(problem), visited_(problem.size(), 0), lastMove_(kCandidateFeatures, 0.0f) {
    if (problem.size() == 0)
        return;
    tour_.push_back(0);
    visited_[0] = 1;
    remaining_.remove(0);
    look();
}

void TourBuilder::look() {
    features_.assign(static_cast<std::size_t>(window_) * kCandidateFeatures, 0.0f);
    candidates_.clear();
    if (done())
        return;
    const int from = tour_.back();
    candidates_ = remaining_.cheapestMoves(from, window_);
    const double cheapest = problem_.cost(from, candidates_.front());
    for (int k = 0; k < static_cast<int>(candidates_.size()); ++k) {
        const int to = candidates_[k];
        int free = 0;
        for (int w : (*neighbourhood_)[to])
            free += w != from && !visited_[w];
        moveFeatures(problem_, from, to, cheapest, free, k, window_,
                     features_.data() + static_cast<std::size_t>(k) * kCandidateFeatures);
    }
}

double TourBuilder::step(int slot) {
    const int from = tour_.back(), to = candidates_.at(static_cast<std::size_t>(slot));
    std::copy_n(features_.begin() + static_cast<std::ptrdiff_t>(slot) * kCandidateFeatures,
                kCandidateFeatures, lastMove_.begin());
    double energy = problem_.cost(from, to);
    tour_.push_back(to);
    visited_[to] = 1;
    remaining_.remove(to);
    if (done())
        energy += problem_.cost(to, tour_.front());
    look();
    return energy;
}

} // namespace fc::tiling

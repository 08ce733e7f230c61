// The local view of the PPO ordering policy (seeds/001 sect. 4.2, made size-free): a tour is
// built from waypoint 0 one move at a time, choosing among the `window` cheapest moves to
// unvisited waypoints, each described relative to the robot's current pose. Plain C++; the
// network that chooses lives in tiling/ppo/torch/PointerPpo.
#pragma once

#include "tiling/WaypointIndex.h"
#include "tiling/WaypointOrder.h"

#include <memory>
#include <vector>

namespace fc::tiling {

// Per candidate move from pose `from` to pose `to` (a = block leg, M = total mass, e = the
// move's energy, e0 = the cheapest candidate's):
//   0, 1  the target waypoint in the robot's frame (x ahead along its heading), d = v / 4a,
//         squashed as d / sqrt(1 + d^2 / 16)
//   2, 3  cos and sin of the heading change
//   4     1 when the shape changes
//   5     log(1 + e / (M a))
//   6     log(1 + (e - e0) / (M a))
//   7     unvisited waypoints among the target's 8 cheapest moves, / 8 (isolation)
//   8     rank of the move among the candidates / window
constexpr int kCandidateFeatures = 9;
constexpr int kIsolationNeighbours = 8;
void moveFeatures(const OrderingProblem& problem, int from, int to, double cheapest,
                  int freeNeighbours, int rank, int window, float* out);

// Each waypoint's kIsolationNeighbours cheapest moves, shared by the builders of a problem.
using Neighbourhood = std::vector<std::vector<int>>;
std::shared_ptr<const Neighbourhood> neighbourhoodOf(const OrderingProblem& problem);

class TourBuilder {
public:
    TourBuilder(const OrderingProblem& problem, int window,
                std::shared_ptr<const Neighbourhood> neighbourhood);

    bool done() const { return static_cast<int>(tour_.size()) >= problem_.size(); }
    // The cheapest moves to unvisited waypoints, cheapest first (at most `window`; never
    // empty before done(): the index searches the whole floor when the window is sparse).
    const std::vector<int>& candidates() const { return candidates_; }
    // window x kCandidateFeatures, rows past the candidates zero.
    const std::vector<float>& features() const { return features_; }
    // Features of the move just made (zeros before the first), the decoder's input.
    const std::vector<float>& lastMove() const { return lastMove_; }
    // Visits candidates()[slot]; returns that move's energy, plus the return to waypoint 0
    // when it completes the tour.
    double step(int slot);
    const Tour& tour() const { return tour_; }

private:
    void look();

    const OrderingProblem& problem_;
    int window_;
    std::shared_ptr<const Neighbourhood> neighbourhood_;
    WaypointIndex remaining_;
    std::vector<char> visited_;
    Tour tour_;
    std::vector<int> candidates_;
    std::vector<float> features_, lastMove_;
};

} // namespace fc::tiling

// The PPO ordering policy of the tiling robot (seeds/001 sect. 4.2), made local so that it
// generalises to any floor: at each step a pointer network (LSTM encoder over the window of
// cheapest candidate moves, LSTM decoder over the moves made so far, additive attention)
// picks the next waypoint; a critic on the decoder state and the encoded window estimates
// the return. Trained as an actor-critic with PPO's clipped objective and GAE on random
// rooms (tiling/ppo/TrainingInstances), reward = -energy of each move. The interface is
// free of torch types; LibTorch stays in PointerPpo.cpp.
#pragma once

#include "tiling/WaypointOrder.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fc {

struct PointerPpoOptions {
    int hidden = 32;
    int window = 16;        // candidate moves the pointer attends over
    int batch = 16;         // tours built per update
    int roomWaypoints = 64; // waypoints of a training room window
    int trainingRooms = 12; // random rooms tiled for the training windows
    int epochsPerBatch = 4; // PPO passes over each batch
    double clip = 0.2;      // epsilon of the clipped ratio
    double learningRate = 3e-3;
    double gamma = 0.98;  // discount of the per-move rewards
    double lambda = 0.95; // GAE
    double entropyWeight = 0.01;
    std::uint64_t seed = 1;
};

struct PointerPpoProgress {
    int update = 0;
    double meanCost = 0.0; // of the sampled tours, per waypoint, in kg m
    double criticLoss = 0.0;
};

class PointerPpo {
public:
    explicit PointerPpo(const PointerPpoOptions& options = {});
    ~PointerPpo();

    // Up to `updates` PPO updates (and no longer than maxSeconds when it is positive).
    // Returns the updates done.
    int train(int updates, const std::function<void(const PointerPpoProgress&)>& progress = {},
              double maxSeconds = 0.0);
    // The greedy tour (most likely move at every step), from waypoint 0.
    tiling::Tour decode(const tiling::OrderingProblem& problem) const;
    // The cheapest of the greedy tour and `samples` tours sampled from the policy
    // (reproducible per seed).
    tiling::Tour decodeBest(const tiling::OrderingProblem& problem, int samples,
                            std::uint64_t seed) const;
    // The policy's probabilities over the window slots at the first move (slots past the
    // candidates are masked to zero).
    std::vector<double> firstMoveProbabilities(const tiling::OrderingProblem& problem) const;

    // The network's weights and sizes; load() replaces them (InputError for a bad file).
    void save(const std::string& path) const;
    void load(const std::string& path);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// PPO's clipped surrogate loss, -mean(min(r A, clip(r, 1-eps, 1+eps) A)) with
// r = exp(newLogp - oldLogp): the function the training minimises, for tests.
double ppoClippedLoss(const std::vector<double>& newLogp, const std::vector<double>& oldLogp,
                      const std::vector<double>& advantages, double clip);

} // namespace fc

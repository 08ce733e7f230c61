// Pointer network (LSTM encoder and decoder with additive attention) trained as an
// actor-critic with PPO's clipped objective to order the tiling robot's waypoints
// (seeds/001 sect. 4.2). The interface is free of torch types; LibTorch stays in
// PointerPpo.cpp.
#pragma once

#include "tiling/WaypointOrder.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace fc {

struct PointerPpoOptions {
    int hidden = 64;
    int batch = 64; // tours sampled per update
    int trainingWaypoints = 20;
    int epochsPerBatch = 4; // PPO passes over each batch
    double clip = 0.2;      // epsilon of the clipped ratio
    double learningRate = 1e-3;
    std::uint64_t seed = 1;
};

struct PointerPpoProgress {
    int update = 0;
    double meanCost = 0.0; // of the sampled tours, in the problem's energy units
    double criticLoss = 0.0;
};

class PointerPpo {
public:
    explicit PointerPpo(const PointerPpoOptions& options = {});
    ~PointerPpo();

    // `updates` PPO updates on random instances of options.trainingWaypoints waypoints.
    void train(int updates, const std::function<void(const PointerPpoProgress&)>& progress = {});
    // Greedy decoding: the most likely next waypoint at every step, from waypoint 0.
    tiling::Tour decode(const tiling::OrderingProblem& problem) const;

    void save(const std::string& path) const;
    void load(const std::string& path);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace fc

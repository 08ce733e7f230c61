// Registers the tiling robot's ordering method "ppo": a pointer network trained with PPO on
// random instances (learning/torch/PointerPpo), then decoded greedily on the floor's tiles.
#pragma once

#include <cstdint>
#include <vector>

namespace fc {

// Adds "ppo" to the tiling orders (tiling/WaypointOrder.h). The network is trained on first
// use per seed (kPpoTrainingUpdates updates of 64 random 20-waypoint instances, one
// thread) and kept for the process, so the first call's time includes the training.
constexpr int kPpoTrainingUpdates = 150;
void registerPpoOrdering();
// Mean cost of the sampled training tours per update, for the seed's network (empty until
// "ppo" has run with that seed).
std::vector<double> ppoTrainingCurve(std::uint64_t seed);

} // namespace fc

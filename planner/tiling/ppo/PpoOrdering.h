// Registers the tiling robot's ordering methods "ppo-policy" (the PPO pointer policy alone:
// the best of its greedy tour and 64 sampled tours) and "ppo" (that tour polished by the
// energy-aware 2-opt / Or-opt of tiling::polishTour), tiling/ppo/torch/PointerPpo.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fc {

// The policy is trained on first use per seed (kPpoTrainingUpdates updates, one thread,
// about 50 s of CPU; the first call's time includes it) and kept for the process, unless a model
// file is given.
constexpr int kPpoTrainingUpdates = 150;
constexpr int kPpoSamples = 64;

struct PpoOrderingSettings {
    std::string modelPath;    // load this network instead of training (InputError if bad)
    double trainSeconds = 0.; // > 0: train for this long instead of kPpoTrainingUpdates
    std::string savePath;     // save the network trained on first use here
};
void configurePpoOrdering(const PpoOrderingSettings& settings);

void registerPpoOrdering();
// Mean cost per waypoint of the sampled training tours per update, for the seed's network
// (empty until "ppo" has trained with that seed).
std::vector<double> ppoTrainingCurve(std::uint64_t seed);

} // namespace fc

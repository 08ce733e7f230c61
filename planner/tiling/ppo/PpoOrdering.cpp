#include "tiling/ppo/PpoOrdering.h"

#include "tiling/WaypointOrder.h"
#include "tiling/ppo/torch/PointerPpo.h"

#include <map>
#include <memory>
#include <mutex>

namespace fc {

namespace {

struct TrainedNetwork {
    std::unique_ptr<PointerPpo> network;
    std::vector<double> curve;
};

std::mutex trainedLock;
std::map<std::uint64_t, TrainedNetwork> trained;
PpoOrderingSettings settings;

PointerPpo& networkFor(std::uint64_t seed) {
    TrainedNetwork& entry = trained[seed];
    if (entry.network)
        return *entry.network;
    PointerPpoOptions options;
    options.seed = seed;
    auto network = std::make_unique<PointerPpo>(options);
    if (!settings.modelPath.empty()) {
        network->load(settings.modelPath);
    } else {
        const bool timed = settings.trainSeconds > 0.0;
        network->train(
            timed ? 1000000 : kPpoTrainingUpdates,
            [&entry](const PointerPpoProgress& p) { entry.curve.push_back(p.meanCost); },
            settings.trainSeconds);
        if (!settings.savePath.empty())
            network->save(settings.savePath);
    }
    entry.network = std::move(network);
    return *entry.network;
}

tiling::Tour policyTour(const tiling::OrderingProblem& problem, std::uint64_t seed) {
    const std::lock_guard<std::mutex> guard(trainedLock);
    return networkFor(seed).decodeBest(problem, kPpoSamples, seed);
}

} // namespace

void configurePpoOrdering(const PpoOrderingSettings& newSettings) {
    const std::lock_guard<std::mutex> guard(trainedLock);
    settings = newSettings;
    trained.clear();
}

void registerPpoOrdering() {
    tiling::registerOrderingMethod("ppo-policy", policyTour);
    tiling::registerOrderingMethod(
        "ppo", [](const tiling::OrderingProblem& problem, std::uint64_t seed) {
            return tiling::polishTour(problem, policyTour(problem, seed));
        });
}

std::vector<double> ppoTrainingCurve(std::uint64_t seed) {
    const std::lock_guard<std::mutex> guard(trainedLock);
    const auto found = trained.find(seed);
    return found == trained.end() ? std::vector<double>{} : found->second.curve;
}

} // namespace fc

#include "learning/ppo/PpoOrdering.h"

#include "learning/torch/PointerPpo.h"
#include "tiling/WaypointOrder.h"

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

} // namespace

void registerPpoOrdering() {
    tiling::registerOrderingMethod(
        "ppo", [](const tiling::OrderingProblem& problem, std::uint64_t seed) {
            const std::lock_guard<std::mutex> guard(trainedLock);
            TrainedNetwork& entry = trained[seed];
            if (!entry.network) {
                PointerPpoOptions options;
                options.seed = seed;
                entry.network = std::make_unique<PointerPpo>(options);
                entry.network->train(kPpoTrainingUpdates, [&entry](const PointerPpoProgress& p) {
                    entry.curve.push_back(p.meanCost);
                });
            }
            return entry.network->decode(problem);
        });
}

std::vector<double> ppoTrainingCurve(std::uint64_t seed) {
    const std::lock_guard<std::mutex> guard(trainedLock);
    const auto found = trained.find(seed);
    return found == trained.end() ? std::vector<double>{} : found->second.curve;
}

} // namespace fc

#include "learning/torch/DqnTargets.h"

#include <cmath>
#include <stdexcept>

namespace fc {

int maskedArgmax(const float* values, const char* mask, int count) {
    int best = -1;
    for (int a = 0; a < count; ++a) {
        if (mask != nullptr && !mask[a])
            continue;
        if (best < 0 || values[a] > values[best])
            best = a;
    }
    return best;
}

std::vector<float> doubleDqnTargets(const DoubleDqnBatch& batch, float gamma, bool maskArgmax) {
    const std::size_t n = batch.rewards.size();
    const auto actions = static_cast<std::size_t>(batch.actionCount);
    if (batch.actionCount <= 0 || batch.dones.size() != n ||
        batch.nextOnlineQ.size() != n * actions || batch.nextTargetQ.size() != n * actions)
        throw std::invalid_argument("doubleDqnTargets: inconsistent batch sizes");
    if (maskArgmax && batch.nextMask.size() != n * actions)
        throw std::invalid_argument("doubleDqnTargets: mask size differs from the Q values");
    if (!batch.steps.empty() && batch.steps.size() != n)
        throw std::invalid_argument("doubleDqnTargets: step counts differ from the batch size");

    std::vector<float> targets(n);
    for (std::size_t i = 0; i < n; ++i) {
        float bootstrap = 0.0f;
        if (batch.dones[i] < 0.5f) {
            const char* mask = maskArgmax ? batch.nextMask.data() + i * actions : nullptr;
            const int best =
                maskedArgmax(batch.nextOnlineQ.data() + i * actions, mask, batch.actionCount);
            if (best >= 0)
                bootstrap = batch.nextTargetQ[i * actions + static_cast<std::size_t>(best)];
        }
        const int steps = batch.steps.empty() ? 1 : batch.steps[i];
        if (steps < 1)
            throw std::invalid_argument("doubleDqnTargets: a transition spans no step");
        const auto discount = static_cast<float>(std::pow(gamma, steps));
        targets[i] = batch.rewards[i] + discount * (1.0f - batch.dones[i]) * bootstrap;
    }
    return targets;
}

} // namespace fc

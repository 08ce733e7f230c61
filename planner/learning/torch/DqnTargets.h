// The Double-DQN bootstrap targets (van Hasselt et al. 2016) as a pure function of plain
// vectors, so that the arithmetic is testable without LibTorch:
//   y_i = r_i + gamma^n_i * (1 - done_i) * Q_target(s'_i, argmax_a Q_online(s'_i, a)),
// the argmax taken over the actions valid in s'_i when masking is on; n_i = 1 except for
// n-step transitions (r_i then already sums n_i discounted rewards).
#pragma once

#include <vector>

namespace fc {

struct DoubleDqnBatch {
    std::vector<float> rewards;     // batch
    std::vector<float> dones;       // batch, 1 = terminal (no bootstrap)
    std::vector<float> nextOnlineQ; // batch x actionCount, row-major
    std::vector<float> nextTargetQ; // batch x actionCount, row-major
    std::vector<char> nextMask;     // batch x actionCount; may be empty when not masking
    std::vector<int> steps;         // batch, n_i >= 1; may be empty (all 1)
    int actionCount = 0;
};

// Throws std::invalid_argument on inconsistent sizes. With maskArgmax, a next state without
// any valid action bootstraps nothing (its value counts as 0).
std::vector<float> doubleDqnTargets(const DoubleDqnBatch& batch, float gamma, bool maskArgmax);

// Index of the largest value among entries with mask[i] != 0 (all entries when mask is
// empty); the first one on ties; -1 when no entry qualifies.
int maskedArgmax(const float* values, const char* mask, int count);

} // namespace fc

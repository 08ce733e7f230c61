// Fixed-capacity ring of transitions for experience replay (no LibTorch types).
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace fc {

struct Transition {
    std::vector<float> observation; // channels x SIZE x SIZE
    int action = 0;
    float reward = 0.0f;                // n-step: sum of gamma^i x r_i over the `steps` rewards
    std::vector<float> nextObservation; // channels x SIZE x SIZE
    std::vector<char> nextMask;         // per action, valid in nextObservation
    bool done = false;
    int steps = 1; // environment steps between observation and nextObservation
};

class ReplayMemory {
public:
    explicit ReplayMemory(std::size_t capacity);

    // Appends, overwriting the oldest transition once full.
    void push(Transition transition);
    // `count` indices drawn uniformly with replacement. Requires size() > 0.
    std::vector<std::size_t> sample(std::size_t count, std::mt19937_64& rng) const;

    const Transition& at(std::size_t index) const { return items_[index]; }
    std::size_t size() const { return items_.size(); }
    std::size_t capacity() const { return capacity_; }
    void clear();

private:
    std::size_t capacity_;
    std::size_t next_ = 0; // slot overwritten by the next push once full
    std::vector<Transition> items_;
};

} // namespace fc

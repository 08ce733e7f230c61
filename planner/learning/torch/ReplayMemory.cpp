#include "learning/torch/ReplayMemory.h"

#include <stdexcept>

namespace fc {

ReplayMemory::ReplayMemory(std::size_t capacity) : capacity_(capacity) {
    if (capacity == 0)
        throw std::invalid_argument("ReplayMemory: capacity must be positive");
}

void ReplayMemory::push(Transition transition) {
    if (items_.size() < capacity_) {
        items_.push_back(std::move(transition));
        return;
    }
    items_[next_] = std::move(transition);
    next_ = (next_ + 1) % capacity_;
}

std::vector<std::size_t> ReplayMemory::sample(std::size_t count, std::mt19937_64& rng) const {
    if (items_.empty())
        throw std::logic_error("ReplayMemory: sampling an empty memory");
    std::uniform_int_distribution<std::size_t> pick(0, items_.size() - 1);
    std::vector<std::size_t> indices(count);
    for (std::size_t& index : indices)
        index = pick(rng);
    return indices;
}

void ReplayMemory::clear() {
    items_.clear();
    next_ = 0;
}

} // namespace fc

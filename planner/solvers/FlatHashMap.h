// Open-addressing hash map from 64-bit keys to small values (linear probing, power-of-two
// capacity): the solvers' state and distance caches, where std::unordered_map's node
// allocations dominate the run time.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace fc::solver_detail {

template <class Value> class FlatHashMap {
public:
    static constexpr std::uint64_t kReservedKey = ~std::uint64_t{0}; // marks empty slots

    explicit FlatHashMap(std::size_t expected = 16) { rehash(capacityFor(expected)); }

    const Value* find(std::uint64_t key) const {
        for (std::size_t slot = hash(key) & mask_;; slot = (slot + 1) & mask_) {
            if (slots_[slot].key == key)
                return &slots_[slot].value;
            if (slots_[slot].key == kReservedKey)
                return nullptr;
        }
    }

    // Inserts (key, value) unless the key is present. Returns the stored value (valid until
    // the next insertion) and whether it was inserted.
    std::pair<Value*, bool> emplace(std::uint64_t key, const Value& value) {
        if (2 * (size_ + 1) > slots_.size())
            rehash(slots_.size() * 2);
        std::size_t slot = hash(key) & mask_;
        for (; slots_[slot].key != kReservedKey; slot = (slot + 1) & mask_)
            if (slots_[slot].key == key)
                return {&slots_[slot].value, false};
        slots_[slot] = {key, value};
        ++size_;
        return {&slots_[slot].value, true};
    }

    std::size_t size() const { return size_; }

private:
    static std::size_t capacityFor(std::size_t expected) {
        std::size_t capacity = 16;
        while (capacity < 2 * expected)
            capacity *= 2;
        return capacity;
    }

    static std::uint64_t hash(std::uint64_t key) { // splitmix64 finaliser
        key = (key ^ (key >> 30)) * 0xBF58476D1CE4E5B9ULL;
        key = (key ^ (key >> 27)) * 0x94D049BB133111EBULL;
        return key ^ (key >> 31);
    }

    struct Slot { // key and value side by side: one cache line per probe
        std::uint64_t key;
        Value value;
    };

    void rehash(std::size_t capacity) {
        std::vector<Slot> old(capacity, Slot{kReservedKey, Value{}});
        old.swap(slots_);
        mask_ = capacity - 1;
        size_ = 0;
        for (const Slot& slot : old)
            if (slot.key != kReservedKey)
                emplace(slot.key, slot.value);
    }

    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
    std::size_t size_ = 0;
};

} // namespace fc::solver_detail

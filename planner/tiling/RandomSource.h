// Seeded random numbers that are the same on every platform (the standard distributions
// are implementation-defined), for the ant colony and the genetic algorithm.
#pragma once

#include <cstdint>
#include <random>

namespace fc::tiling {

class RandomSource {
public:
    explicit RandomSource(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; } // [0, 1)
    int below(int n) { return static_cast<int>(uniform() * n); }                  // [0, n)

private:
    std::mt19937_64 engine_;
};

} // namespace fc::tiling

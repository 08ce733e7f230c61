// Minimum-weight perfect matching on a complete graph (the odd nodes of the Chinese Postman
// baseline). Boost 1.74's maximum_weighted_matching is not used: it returns wrong matchings,
// crashes or does not terminate on some graphs (boostorg/graph issues #399, #199, #223).
#pragma once

#include <vector>

namespace fc::baseline_detail {

// Above this many points the exact matching (2^n states) gives way to the greedy one.
constexpr int kExactMatchingLimit = 20;

// cost: symmetric, even size. Returns mate[i] for every i.
// Exact up to kExactMatchingLimit points, greedy with pair-swap improvement above.
std::vector<int> minimumWeightPerfectMatching(const std::vector<std::vector<double>>& cost);

// Exact: dynamic programming over the set of matched points (pair the lowest free point).
std::vector<int> exactPerfectMatching(const std::vector<std::vector<double>>& cost);

// Cheapest pairs first, then swaps partners of two pairs while that lowers the total; not
// guaranteed minimal.
std::vector<int> greedyPerfectMatching(const std::vector<std::vector<double>>& cost);

double matchingCost(const std::vector<std::vector<double>>& cost, const std::vector<int>& mate);

} // namespace fc::baseline_detail

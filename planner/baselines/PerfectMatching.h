// Minimum-weight perfect matching on a complete graph (the odd nodes of the Chinese Postman
// baseline), exact at every size. Boost 1.74's maximum_weighted_matching is not used: it
// returns wrong matchings, crashes or does not terminate on some graphs (boostorg/graph
// issues #399, #199, #223); LEMON's MaxWeightedPerfectMatching (Edmonds' blossom algorithm,
// O(n^3)) is.
#pragma once

#include <vector>

namespace fc::baselines {

// Above this many points the dynamic programme (2^n states) gives way to the blossom
// algorithm; both are exact.
constexpr int kExactMatchingLimit = 20;

// cost: symmetric, even size. Returns mate[i] for every i. Exact: the dynamic programme up to
// kExactMatchingLimit points, the blossom algorithm above.
std::vector<int> minimumWeightPerfectMatching(const std::vector<std::vector<double>>& cost);

// Exact: dynamic programming over the set of matched points (pair the lowest free point).
std::vector<int> exactPerfectMatching(const std::vector<std::vector<double>>& cost);

// Exact at any size: LEMON's MaxWeightedPerfectMatching on the complete graph with the
// costs negated.
std::vector<int> blossomPerfectMatching(const std::vector<std::vector<double>>& cost);

// Cheapest pairs first, then swaps partners of two pairs while that lowers the total; not
// guaranteed minimal.
std::vector<int> greedyPerfectMatching(const std::vector<std::vector<double>>& cost);

double matchingCost(const std::vector<std::vector<double>>& cost, const std::vector<int>& mate);

} // namespace fc::baselines

// The order in which the rings visit the loops and pieces inside a loop
// (pipeline/RingTour.h): a tour round a column, not back and forth across it.
#include "pipeline/RingTour.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

using namespace fc;
using fc::detail::tourOrder;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A small square of side 0.4 m round `centre`.
Ring square(Vec2 centre) {
    return {centre + Vec2{-0.2, -0.2}, centre + Vec2{0.2, -0.2}, centre + Vec2{0.2, 0.2},
            centre + Vec2{-0.2, 0.2}};
}

Vec2 centreOf(const Ring& ring) {
    Vec2 sum{0, 0};
    for (const Vec2& p : ring)
        sum = sum + p;
    return sum * (1.0 / static_cast<double>(ring.size()));
}

double tourLength(const std::vector<Ring>& rings, const std::vector<size_t>& order, Vec2 from,
                  Vec2 to) {
    double length = 0.0;
    Vec2 at = from;
    for (const size_t k : order) {
        length += norm(centreOf(rings[k]) - at);
        at = centreOf(rings[k]);
    }
    return length + norm(to - at);
}

} // namespace

TEST(RingTour, SliversRoundAColumnAreVisitedInTurn) {
    // Eight pieces on a circle of 4 m round a column, at UTM-sized coordinates, listed in a
    // shuffled order; the robot starts beside the first and comes back there.
    const Vec2 origin{512345.0, 5412345.0};
    const int turns[] = {0, 5, 2, 7, 1, 4, 6, 3};
    std::vector<Ring> rings;
    for (const int k : turns)
        rings.push_back(
            square(origin + Vec2{4.0 * std::cos(k * kPi / 4.0), 4.0 * std::sin(k * kPi / 4.0)}));
    const Vec2 start = origin + Vec2{4.6, 0.0};
    const std::vector<size_t> order = tourOrder(rings, start, start);
    ASSERT_EQ(order.size(), rings.size());
    std::vector<size_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (size_t k = 0; k < sorted.size(); ++k)
        EXPECT_EQ(sorted[k], k); // every ring once
    // Round the circle one way: each next piece is a neighbour of the last (45 degrees on).
    for (size_t i = 1; i < order.size(); ++i) {
        const int a = turns[order[i - 1]], b = turns[order[i]];
        EXPECT_EQ(std::min((a - b + 8) % 8, (b - a + 8) % 8), 1) << i;
    }
    // Out 0.6 m to the first piece, seven chords of 45 degrees, back from the last piece.
    const double chord = 8.0 * std::sin(kPi / 8.0);
    const Vec2 last = origin + Vec2{4.0 * std::cos(kPi / 4.0), 4.0 * std::sin(kPi / 4.0)};
    EXPECT_NEAR(tourLength(rings, order, start, start), 0.6 + 7 * chord + norm(last - start), 1e-6);
}

TEST(RingTour, TheTourEndsNearWhereThePathGoesNext) {
    // Pieces in a row along a corridor; the robot starts in the middle and must end at the
    // far east end: the west half first, then east.
    std::vector<Ring> rings;
    for (const double x : {4.0, -4.0, 8.0, -8.0, 2.0, -2.0, 6.0, -6.0})
        rings.push_back(square({x, 0.0}));
    const std::vector<size_t> order = tourOrder(rings, {0.0, 0.0}, Vec2{12.0, 0.0});
    ASSERT_EQ(order.size(), rings.size());
    EXPECT_LT(centreOf(rings[order.front()]).x, 0.0);
    EXPECT_DOUBLE_EQ(centreOf(rings[order.back()]).x, 8.0);
    // West 8 m and back, east 12 m: 28 m of centre to centre.
    EXPECT_NEAR(tourLength(rings, order, {0.0, 0.0}, {12.0, 0.0}), 28.0, 1e-9);
    // Without an end, nearest first is kept where 2-opt finds nothing shorter.
    EXPECT_EQ(tourOrder({}, {0.0, 0.0}, std::nullopt).size(), 0u);
}

// Seal excursions next to a transit are folded into it (issue 13: fewer reversals at stripe
// ends): the transit runs to the seal's far end and the robot drives the margin once.
#include "TestPlans.h"
#include "decomposition/Decomposition.h"
#include "path/ExcursionPruning.h"

#include <gtest/gtest.h>

using namespace fc;
using fc::detail::PathExcursion;

namespace {

// A 10 x 10 m room, with a wall segment (a thin obstacle) where `blocked` asks for one.
Decomposition room(bool blocked) {
    Plan plan;
    plan.boundary = test::rectangle(0, 0, 10, 10);
    if (blocked)
        plan.obstacles.push_back(test::rectangle(2.6, 1.6, 3.4, 4.0));
    DecompositionOptions options;
    options.robot = RobotProfile{0.6, 1.0, 1.0};
    return decompose(plan, options);
}

struct Folded {
    Polyline points;
    std::vector<SegmentKind> kinds; // of each kept segment
};

// Runs the fold on a path given in the decomposition's sweep frame.
Folded fold(const Decomposition& dec, const Polyline& local, std::vector<SegmentKind> arriving,
            const std::vector<PathExcursion>& excursions) {
    std::vector<char> keep(local.size(), 1);
    detail::foldExcursionsIntoTransits(local, excursions, dec.clearance(), dec.robot, keep,
                                       arriving);
    Folded out;
    for (size_t i = 0; i < local.size(); ++i)
        if (keep[i]) {
            if (!out.points.empty())
                out.kinds.push_back(arriving[i]);
            out.points.push_back(local[i]);
        }
    return out;
}

} // namespace

TEST(ExcursionFold, TransitRunsToTheSealsFarEnd) {
    const Decomposition dec = room(false);
    const Frame& f = dec.frame;
    // A transit from the middle to a stripe start, a seal half a column to the left and
    // back, then the stripe up.
    const Vec2 from = f.toLocal({6, 5}), a = f.toLocal({2, 1}), tip = f.toLocal({1.5, 1}),
               top = f.toLocal({2, 9});
    const Polyline path{from, a, tip, a, top};
    using K = SegmentKind;
    const Folded out =
        fold(dec, path, {K::Transit, K::Transit, K::Stripe, K::Stripe, K::Stripe}, {{1, 3, false}});
    ASSERT_EQ(out.points.size(), 4u);
    EXPECT_LT(distance(out.points[1], tip), 1e-9); // straight to the far end
    EXPECT_LT(distance(out.points[2], a), 1e-9);   // the margin once, back to the stripe
    EXPECT_EQ(out.kinds[0], K::Transit);
    EXPECT_LT(polylineLength(out.points), polylineLength(path));
    EXPECT_LT(countTurns(out.points), countTurns(path));
}

TEST(ExcursionFold, LeavesFromTheFarEndWhenTheTransitFollows) {
    const Decomposition dec = room(false);
    const Frame& f = dec.frame;
    // The stripe comes down to its end, seals to the left and back, then a transit away.
    const Vec2 top = f.toLocal({2, 9}), b = f.toLocal({2, 1}), tip = f.toLocal({1.5, 1}),
               to = f.toLocal({1, 6});
    const Polyline path{top, b, tip, b, to};
    using K = SegmentKind;
    const Folded out =
        fold(dec, path, {K::Transit, K::Stripe, K::Stripe, K::Stripe, K::Transit}, {{1, 3, false}});
    ASSERT_EQ(out.points.size(), 4u);
    EXPECT_LT(distance(out.points[2], tip), 1e-9);
    EXPECT_LT(distance(out.points[3], to), 1e-9);
    EXPECT_EQ(out.kinds[2], K::Transit);
    EXPECT_LT(countTurns(out.points), countTurns(path));
}

TEST(ExcursionFold, KeepsTheSealWhereTheShortcutHitsAWallOrNoTransitIsNext) {
    using K = SegmentKind;
    {
        // The transit passes the obstacle's corner L/2 clear; the shortcut to the seal's far
        // end would graze it.
        const Decomposition dec = room(true);
        const Frame& f = dec.frame;
        ASSERT_TRUE(dec.clearance().segmentIsClear(f.toLocal({4, 6}), f.toLocal({4, 1})));
        const Polyline path{f.toLocal({4, 6}), f.toLocal({4, 1}), f.toLocal({3.5, 1}),
                            f.toLocal({4, 1}), f.toLocal({5, 1})};
        const Folded out = fold(
            dec, path, {K::Transit, K::Transit, K::Stripe, K::Stripe, K::Stripe}, {{1, 3, false}});
        EXPECT_EQ(out.points.size(), path.size());
    }
    {
        // Stripes on both sides: nothing to fold into.
        const Decomposition dec = room(false);
        const Frame& f = dec.frame;
        const Polyline path{f.toLocal({2, 9}), f.toLocal({2, 1}), f.toLocal({1.5, 1}),
                            f.toLocal({2, 1}), f.toLocal({3, 1}), f.toLocal({3, 9})};
        const Folded out =
            fold(dec, path, {K::Transit, K::Stripe, K::Stripe, K::Stripe, K::Stripe, K::Stripe},
                 {{1, 3, false}});
        EXPECT_EQ(out.points.size(), path.size());
    }
}

// A seal at a stripe end whose next move turns a hair more than a right angle (a wall traced
// a millimetre off) is dropped like one at a square turn: the turn's mitre sweeps its margin.
// At a sharp turn the mitre is not assumed and the seal stays.
TEST(ExcursionPruning, ANearlySquareTurnSweepsTheSealsMargin) {
    const double w = 1.0;
    // Up a stripe to (7.5, 4.5) under a wall at y = 5, a seal half a column to the left and
    // back, then away to the right.
    auto path = [](Vec2 next) {
        return Polyline{{7.5, 0.5}, {7.5, 4.5}, {7.0, 4.5}, {7.5, 4.5}, next, {next.x, 0.5}};
    };
    const std::vector<PathExcursion> seal{{1, 3, true}};
    const std::vector<char> square = detail::prunableExcursions(path({8.5, 4.5}), seal, w);
    EXPECT_FALSE(square[2]); // the seal's far end is dropped
    const std::vector<char> nearly = detail::prunableExcursions(path({8.5, 4.49}), seal, w);
    EXPECT_FALSE(nearly[2]); // 90.6 degrees
    const std::vector<char> sharp = detail::prunableExcursions(path({8.5, 3.5}), seal, w);
    EXPECT_TRUE(sharp[2]); // 135 degrees: kept
}

// Under a traced wall a few centimetres higher beside the stripe's end (a ragged map cell),
// the square turn's mitre sweeps all of the seal's margin but a sliver a few centimetres
// deep: the seal, two turns and a metre, is dropped. A true wedge (the border rising a
// quarter of W over the half-column) keeps its seal.
TEST(ExcursionPruning, ARaggedWallsSliverNeedsNoSeal) {
    const double w = 1.0;
    auto path = [](double tipY) {
        return Polyline{{7.5, 0.5},
                        {7.5, 4.5},
                        {7.25, 0.5 * (4.5 + tipY)},
                        {7.0, tipY},
                        {7.25, 0.5 * (4.5 + tipY)},
                        {7.5, 4.5},
                        {8.5, 4.5},
                        {8.5, 0.5}};
    };
    const std::vector<PathExcursion> seal{{1, 5, true}};
    const std::vector<char> ragged = detail::prunableExcursions(path(4.55), seal, w);
    EXPECT_FALSE(ragged[3]); // the seal's far end is dropped
    const std::vector<char> wedge = detail::prunableExcursions(path(4.75), seal, w);
    EXPECT_TRUE(wedge[3]);
}

// Stripes that drive round small islands (decomposition/IslandDetours.h): which islands are
// driven round, and that the path round them keeps the clearance and rejoins itself.
#include "decomposition/IslandDetours.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace fc {
namespace {

Ring square(Vec2 at, double side) {
    return {at, at + Vec2{side, 0}, at + Vec2{side, side}, at + Vec2{0, side}};
}

double distanceToRing(const Ring& ring, Vec2 p) {
    double best = INFINITY;
    for (size_t i = 0; i < ring.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, ring[i], ring[(i + 1) % ring.size()]));
    return best;
}

// The smallest distance between the path's segments and the ring's edges (sampled).
double clearanceOf(const CoveragePath& path, const Ring& ring) {
    double best = INFINITY;
    for (size_t i = 0; i + 1 < path.points.size(); ++i)
        for (int k = 0; k <= 20; ++k) {
            const Vec2 p = path.points[i] + (path.points[i + 1] - path.points[i]) * (k / 20.0);
            best = std::min(best, distanceToRing(ring, p));
        }
    return best;
}

double lengthOf(const CoveragePath& path) {
    double length = 0.0;
    for (size_t i = 1; i < path.points.size(); ++i)
        length += norm(path.points[i] - path.points[i - 1]);
    return length;
}

CoveragePath line(Vec2 from, Vec2 to) {
    return {{from, to}, {SegmentKind::Stripe}};
}

TEST(IslandDetours, SmallFreeStandingIslandsAreDrivenRoundLargeOnesKept) {
    for (const Vec2 origin : {Vec2{0, 0}, Vec2{512345.0, 5432109.0}}) {
        const Ring hall = square(origin, 12);
        const Ring pillar = square(origin + Vec2{2, 2}, 0.5);
        const Ring courtyard = square(origin + Vec2{6, 6}, 4);
        // 0.4 m from the wall: the robot (0.6 m) cannot pass between, so no ring round it.
        const Ring byTheWall = square(origin + Vec2{0.4, 8}, 0.5);
        const IslandDetours islands = islandDetours(hall, {pillar, courtyard, byTheWall}, 0.3, 4.0);
        ASSERT_EQ(islands.zones.size(), 1u);
        ASSERT_EQ(islands.keptHoles.size(), 2u);
        const auto kept = [&](const Ring& hole) {
            return std::count(islands.keptHoles.begin(), islands.keptHoles.end(), hole) == 1;
        };
        EXPECT_TRUE(kept(courtyard));
        EXPECT_TRUE(kept(byTheWall));
        // The zone's ring is the pillar's outline grown by the clearance and 5 mm.
        for (const Vec2& p : islands.zones.front()) {
            EXPECT_GE(distanceToRing(pillar, p), 0.3);
            EXPECT_LE(distanceToRing(pillar, p), 0.306);
        }
    }
}

TEST(IslandDetours, IslandsCloseTogetherShareOneRing) {
    const Ring hall = square({0, 0}, 10);
    const IslandDetours islands =
        islandDetours(hall, {square({3, 3}, 0.4), square({3.8, 3}, 0.4)}, 0.3, 4.0);
    EXPECT_TRUE(islands.keptHoles.empty());
    EXPECT_EQ(islands.zones.size(), 1u);
}

// A speckled hall: 600 pillars 10 cm square on a 1 m grid (each its own ring, 1 m apart)
// and one pair 0.2 m apart, which the robot cannot pass between (one ring round both).
// The buffers join only pieces that meet (Boost's buffer of all of them at once took 10 s).
TEST(IslandDetours, ManySmallIslandsEachGetARingAndOnlyNeighboursMerge) {
    const Ring hall = square({0, 0}, 32);
    std::vector<Ring> pillars;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 20; ++j)
            pillars.push_back(square({1.0 + i, 1.0 + j}, 0.1));
    pillars.push_back(square({5.5, 25.0}, 0.1));
    pillars.push_back(square({5.8, 25.0}, 0.1));
    const IslandDetours islands = islandDetours(hall, pillars, 0.3, 4.0);
    EXPECT_TRUE(islands.keptHoles.empty());
    EXPECT_EQ(islands.zones.size(), 600u + 1u);
}

TEST(IslandDetours, AnIslandTheRobotCannotPassIsPartOfItsNeighbour) {
    // A bin 0.4 m from the courtyard: no ring round it, and no gap between them to part the
    // stripes at; the two are one hole, the gap filled.
    const Ring hall = square({0, 0}, 12);
    const Ring courtyard = square({6, 6}, 4), bin = square({5.1, 7}, 0.5);
    const IslandDetours islands = islandDetours(hall, {courtyard, bin}, 0.3, 4.0);
    EXPECT_TRUE(islands.zones.empty());
    ASSERT_EQ(islands.keptHoles.size(), 1u);
    const double area = std::abs(signedArea(islands.keptHoles.front()));
    EXPECT_GT(area, 16.0 + 0.25 + 0.5 * 0.4 - 0.02);
    EXPECT_LT(area, 16.0 + 0.25 + 0.5 * 0.4 + 0.05);
    // The merged hole covers both outlines whole: closing by round buffers (chords) cut
    // their convex corners by a millimetre or two, and a path round it came that much too
    // near them.
    for (const Ring* member : {&courtyard, &bin})
        for (const Vec2& corner : *member)
            EXPECT_TRUE(pointInRing(islands.keptHoles.front(), corner) ||
                        distanceToRing(islands.keptHoles.front(), corner) < 1e-9)
                << corner.x << ", " << corner.y << " lies "
                << distanceToRing(islands.keptHoles.front(), corner) << " m outside";
}

TEST(IslandDetours, AStripeThroughAnIslandGoesRoundItTheShorterWay) {
    for (const Vec2 origin : {Vec2{0, 0}, Vec2{512345.0, 5432109.0}}) {
        const Ring hall = square(origin, 10);
        const Ring pillar = square(origin + Vec2{4.5, 4.7}, 1.0); // centre (5, 5.2)
        const IslandDetours islands = islandDetours(hall, {pillar}, 0.3, 4.0);
        ASSERT_EQ(islands.zones.size(), 1u);
        const CoveragePath stripe = line(origin + Vec2{1, 5}, origin + Vec2{9, 5});
        const std::optional<CoveragePath> round = detouredPath(stripe, islands.zones);
        ASSERT_TRUE(round);
        EXPECT_EQ(round->points.front(), stripe.points.front());
        EXPECT_LT(norm(round->points.back() - stripe.points.back()), 1e-6);
        ASSERT_EQ(round->kinds.size() + 1, round->points.size());
        EXPECT_GE(clearanceOf(*round, pillar), 0.3);
        // Below the pillar (the shorter side): 8 m, plus down and up 0.605 m to the ring
        // 0.305 m below the pillar; its round corners make it a little shorter.
        EXPECT_GT(lengthOf(*round), 8.0 + 0.8);
        EXPECT_LT(lengthOf(*round), 8.0 + 2 * 0.605 + 1e-6);
        for (const Vec2& p : round->points)
            EXPECT_LT(p.y, origin.y + 5.0 + 1e-9);
        EXPECT_EQ(round->kinds.front(), SegmentKind::Stripe);
        EXPECT_EQ(round->kinds.back(), SegmentKind::Stripe);
    }
}

TEST(IslandDetours, APathAlreadyClearOfTheIslandsIsKept) {
    const Ring hall = square({0, 0}, 10);
    const IslandDetours islands = islandDetours(hall, {square({4.5, 4.5}, 1.0)}, 0.3, 4.0);
    const CoveragePath path{{{1, 1}, {9, 1}, {9, 2}, {1, 2}},
                            {SegmentKind::Stripe, SegmentKind::Stripe, SegmentKind::Stripe}};
    const std::optional<CoveragePath> round = detouredPath(path, islands.zones);
    ASSERT_TRUE(round);
    EXPECT_EQ(round->points, path.points);
}

TEST(IslandDetours, APathThatStartsInsideAZoneIsRefused) {
    const Ring hall = square({0, 0}, 10);
    const IslandDetours islands = islandDetours(hall, {square({4.5, 4.5}, 1.0)}, 0.3, 4.0);
    EXPECT_FALSE(detouredPath(line({4.3, 5}, {9, 5}), islands.zones));
}

TEST(IslandDetours, PathsInAndOutOfSeveralZonesRejoinThemselves) {
    // A boustrophedon over a hall with a grid of pillars: every detour keeps the clearance
    // and the path's ends stay where they were.
    const Ring hall = square({0, 0}, 20);
    std::vector<Ring> pillars;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            pillars.push_back(square({3.3 + 4.1 * i, 2.9 + 4.3 * j}, 0.45));
    const IslandDetours islands = islandDetours(hall, pillars, 0.3, 4.0);
    ASSERT_EQ(islands.zones.size(), pillars.size());
    CoveragePath path{{{0.5, 0.5}}, {}};
    for (int k = 0; k < 19; ++k) {
        const double y = 0.5 + k;
        const double from = k % 2 ? 19.5 : 0.5, to = k % 2 ? 0.5 : 19.5;
        if (k > 0) {
            path.points.push_back({from, y});
            path.kinds.push_back(SegmentKind::Stripe);
        }
        path.points.push_back({to, y});
        path.kinds.push_back(SegmentKind::Stripe);
    }
    const std::optional<CoveragePath> round = detouredPath(path, islands.zones);
    ASSERT_TRUE(round);
    EXPECT_EQ(round->points.front(), path.points.front());
    EXPECT_LT(norm(round->points.back() - path.points.back()), 1e-6);
    for (const Ring& pillar : pillars)
        EXPECT_GE(clearanceOf(*round, pillar), 0.3);
    EXPECT_GT(lengthOf(*round), lengthOf(path));
    EXPECT_LT(lengthOf(*round), lengthOf(path) + 16 * 3 * 1.2);
}

} // namespace
} // namespace fc

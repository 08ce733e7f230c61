#include "TestPlans.h"
#include "geometry/SegmentIndex.h"
#include "graph/CornerGraph.h"

#include <gtest/gtest.h>
#include <map>

using namespace fc;
using fc::test::rectangle;
using fc::test::shifted;

namespace {

std::map<EdgeKind, int> countKinds(const CornerGraph& g) {
    std::map<EdgeKind, int> n;
    for (const GraphEdge& e : g.edges)
        ++n[e.kind];
    return n;
}

} // namespace

TEST(CornerGraph, SimplePlanShape) {
    Plan p;
    p.boundary = rectangle(0, 0, 12, 8);
    p.obstacles = {rectangle(5, 3, 7, 5)};
    const Decomposition d = decompose(p, {});
    const CornerGraph g = buildCornerGraph(d);
    ASSERT_EQ(d.primaryCount(), 2);
    ASSERT_EQ(d.transitionCount(), 6);
    EXPECT_EQ(g.nodes.size(), 2u * 4 + 6u * 2);
    auto n = countKinds(g);
    EXPECT_EQ(n[EdgeKind::Coverage], 2 * 2 + 6);
    EXPECT_EQ(n[EdgeKind::Contour], 2 * 4);
    // Corners next to each shared border connect pairwise: 4 per pair of touching cells.
    EXPECT_EQ(n[EdgeKind::Inter], 4 * static_cast<int>(d.adjacencies.size()));
    for (const GraphCell& c : g.cells)
        EXPECT_EQ(c.coverageEdges.size(), c.kind == CellKind::Primary ? 2u : 1u);
}

TEST(CornerGraph, ParityRuleAndCornerOffsets) {
    Plan p; // one 4 x 3 room: 4 stripes (even): LB-RB and LT-RT
    p.boundary = rectangle(0, 0, 4, 3);
    const CornerGraph even = buildCornerGraph(decompose(p, {}));
    ASSERT_EQ(even.cells.size(), 1u);
    const auto& n = even.cells[0].nodes;
    EXPECT_NEAR(even.nodes[n[0]].position.x, 0.5, 1e-9);
    EXPECT_NEAR(even.nodes[n[0]].position.y, 0.5, 1e-9);
    EXPECT_NEAR(even.nodes[n[3]].position.x, 3.5, 1e-9);
    EXPECT_NEAR(even.nodes[n[3]].position.y, 2.5, 1e-9);
    const GraphEdge& c0 = even.edges[even.cells[0].coverageEdges[0]];
    EXPECT_EQ(c0.u, n[0]);
    EXPECT_EQ(c0.v, n[2]);                       // LB-RB
    EXPECT_NEAR(c0.length, 4 * 2 + 3 * 1, 1e-4); // traced borders keep a tiny margin

    p.boundary = rectangle(0, 0, 5, 3); // 5 stripes (odd): LB-RT and LT-RB
    const CornerGraph odd = buildCornerGraph(decompose(p, {}));
    const auto& m = odd.cells[0].nodes;
    const GraphEdge& o0 = odd.edges[odd.cells[0].coverageEdges[0]];
    EXPECT_EQ(o0.u, m[0]);
    EXPECT_EQ(o0.v, m[3]); // LB-RT
    int parallel = 0;
    for (const GraphEdge& e : odd.edges)
        parallel += e.parallel;
    EXPECT_EQ(parallel, 2);
}

TEST(CornerGraph, AllEdgeGeometryIsCollisionFree) {
    Plan p;
    p.boundary = {{20, 14}, {20, 3}, {15, 3}, {15, 0}, {0, 0}, {0, 10}, {4, 10}, {4, 14}};
    p.obstacles = {rectangle(7, 5, 13, 8), {{16, 8}, {17.5, 9.5}, {16, 11}, {14.5, 9.5}}};
    const Decomposition d = decompose(p, {});
    const CornerGraph g = buildCornerGraph(d);
    const SegmentIndex walls(d.freeSpace);
    for (const GraphEdge& e : g.edges) {
        EXPECT_GE(walls.polylineClearance(e.geometry), 0.5 - 2e-3) << "edge " << e.id;
        EXPECT_EQ(e.geometry.front(), g.nodes[e.u].position);
        EXPECT_EQ(e.geometry.back(), g.nodes[e.v].position);
    }
}

TEST(CornerGraph, DoorConnectsStackedRooms) {
    Plan p;
    p.boundary = {{0, 0}, {6, 0}, {6, 4},   {3.6, 4},   {3.6, 4.2}, {6, 4.2},
                  {6, 8}, {0, 8}, {0, 4.2}, {2.4, 4.2}, {2.4, 4},   {0, 4}};
    p.rooms = {{"South", rectangle(0, 0, 6, 4)}, {"North", rectangle(0, 4.2, 6, 8)}};
    const Decomposition d = decompose(p, {});
    const CornerGraph g = buildCornerGraph(d);
    bool crossesRooms = false;
    for (const GraphEdge& e : g.edges)
        if (e.kind == EdgeKind::Inter &&
            g.cells[g.nodes[e.u].cell].room != g.cells[g.nodes[e.v].cell].room)
            crossesRooms = true;
    EXPECT_TRUE(crossesRooms);
}

namespace {

// A 20 x 14 m room whose top wall carries a feature from x0 to x1: a tooth (depth > 0)
// bulging into the floor, or a notch (depth < 0) into the wall, as a traced map's walls
// have. Decomposed with headland bands, stripes across the top wall (L = 0.6 m, W = 1 m).
Decomposition bandBesideAFeature(double x0, double x1, double depth) {
    Plan p;
    const double y = 14 - depth;
    p.boundary = {{0, 0}, {20, 0}, {20, 14}, {x1, 14}, {x1, y}, {x0, y}, {x0, 14}, {0, 14}};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0;
    o.headland = Headland::Both;
    o.robot.robotDiameter = 0.6;
    o.robot.coverageWidth = 1.0;
    return decompose(p, o);
}

// Where the top band's pass runs past the feature (world x in (x0, x1)): (min y, max y) of
// the robot centre there on the band's edges, world frame; NaN when none passes.
std::pair<double, double> bandPassOver(const Decomposition& d, const CornerGraph& g, double x0,
                                       double x1) {
    double lo = NAN, hi = NAN;
    for (const GraphEdge& e : g.edges) {
        const bool band = e.kind == EdgeKind::Coverage ? d.cells[e.cell].headland
                                                       : d.cells[g.nodes[e.u].cell].headland &&
                                                             d.cells[g.nodes[e.v].cell].headland;
        if (!band)
            continue;
        for (size_t i = 1; i < e.geometry.size(); ++i) {
            const Vec2 a = d.frame.toWorld(e.geometry[i - 1]), b = d.frame.toWorld(e.geometry[i]);
            for (double x = x0 + 0.01; x < x1 - 0.005; x += 0.01) {
                if ((x - a.x) * (x - b.x) > 0 || a.x == b.x)
                    continue;
                const double y = a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x);
                if (y < 12.5)
                    continue;
                lo = std::isnan(lo) ? y : std::min(lo, y);
                hi = std::isnan(hi) ? y : std::max(hi, y);
            }
        }
    }
    return {lo, hi};
}

} // namespace

// A traced wall's tooth shallower than W/2 - L/2 leaves the robot room to pass in line: the
// band's single pass runs straight past it (0.4 m from it) instead of bending round it
// along the middle of the band, which cost turns and length on every ragged map wall.
TEST(CornerGraph, BandPassRunsStraightPastAShallowTooth) {
    const Decomposition d = bandBesideAFeature(4.2, 4.575, 0.1);
    ASSERT_TRUE(d.headland);
    const CornerGraph g = buildCornerGraph(d);
    const auto [lo, hi] = bandPassOver(d, g, 4.2, 4.575);
    ASSERT_FALSE(std::isnan(lo));
    EXPECT_NEAR(lo, 13.5, 1e-9);
    EXPECT_NEAR(hi, 13.5, 1e-9);
}

// A notch the robot fits into is floor the straight pass would miss: the pass still bends
// into it so that its head reaches the notch's end.
TEST(CornerGraph, BandPassStillReachesIntoANotch) {
    const Decomposition d = bandBesideAFeature(4.2, 5.4, -0.15);
    ASSERT_TRUE(d.headland);
    const CornerGraph g = buildCornerGraph(d);
    const auto [lo, hi] = bandPassOver(d, g, 4.6, 5.0);
    ASSERT_FALSE(std::isnan(lo));
    EXPECT_GE(hi + 0.5, 14.15 - 1e-3);
}

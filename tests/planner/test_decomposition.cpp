#include "TestPlans.h"
#include "decomposition/Decomposition.h"
#include "decomposition/StripeLattice.h"
#include "decomposition/StripePlanner.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <map>

using namespace fc;
using fc::test::rectangle;
using fc::test::shifted;

namespace {

Plan simplePlan() { // the paper's Fig. 2 situation (shared/plans/simple)
    Plan p;
    p.boundary = rectangle(0, 0, 12, 8);
    p.obstacles = {rectangle(5, 3, 7, 5)};
    return p;
}

double totalArea(const Decomposition& d) {
    double a = 0;
    for (const Cell& c : d.cells)
        a += c.area();
    return a;
}

} // namespace

TEST(Decomposition, RectangleWithBoxClassic) {
    DecompositionOptions o;
    o.transitionCells = false;
    const Decomposition d = decompose(simplePlan(), o);
    EXPECT_EQ(d.cells.size(), 4u); // left, below, above, right
    EXPECT_NEAR(totalArea(d), 96 - 4, 1e-9);
    EXPECT_EQ(d.adjacencies.size(), 4u);
}

TEST(Decomposition, RectangleWithBoxTransitionCells) {
    const Decomposition d = decompose(simplePlan(), {});
    // Left and right cells keep a primary and give up one strip each; the 2 m wide cells
    // above and below the box have two stripes and two critical sides: two transition cells.
    EXPECT_EQ(d.primaryCount(), 2);
    EXPECT_EQ(d.transitionCount(), 6);
    EXPECT_NEAR(totalArea(d), 92, 1e-9);
    for (const Cell& c : d.cells) {
        if (c.kind == CellKind::Transition) {
            EXPECT_EQ(c.stripes.size(), 1u);
            EXPECT_LE(c.width(), 1.0 + 1e-9);
        }
        EXPECT_TRUE(c.reachable());
    }
}

TEST(Decomposition, StripesEvenlySpacedHalfWidthInside) {
    const Decomposition d = decompose(simplePlan(), {});
    for (const Cell& c : d.cells) {
        if (c.kind != CellKind::Primary)
            continue;
        ASSERT_GE(c.stripes.size(), 2u);
        EXPECT_NEAR(c.stripes.front(), c.x0 + 0.5, 1e-9);
        EXPECT_NEAR(c.stripes.back(), c.x1 - 0.5, 1e-9);
        for (size_t i = 1; i < c.stripes.size(); ++i)
            EXPECT_LE(c.stripes[i] - c.stripes[i - 1], 1.0 + 1e-9);
        for (const Interval& s : c.stripeSpans) {
            EXPECT_NEAR(s.lo, 0.5, 1e-6);
            EXPECT_NEAR(s.hi, 7.5, 1e-6);
        }
    }
}

TEST(Decomposition, DiamondObstacle) {
    Plan p;
    p.boundary = rectangle(0, 0, 12, 8);
    p.obstacles = {{{6.2, 2.4}, {7.6, 3.7}, {6.0, 5.6}, {4.5, 4.0}}};
    DecompositionOptions o;
    o.transitionCells = false;
    const Decomposition d = decompose(p, o);
    EXPECT_EQ(d.cells.size(), 4u);
    const double hole = 0.5 * std::abs((7.6 - 4.5) * (5.6 - 2.4) - 0); // not exact: check sum
    (void)hole;
    double a = 0;
    for (const Cell& c : d.cells)
        a += c.area();
    EXPECT_NEAR(a, 96 - ringArea(p.obstacles[0]), 1e-6); // vertices snap to a 1e-9 grid
}

TEST(Decomposition, RectilinearNotchesDoNotSplit) {
    // shared/plans/room-notches: the notches make the floor/ceiling jump but never split.
    Plan p;
    p.boundary = {{20, 14}, {20, 3}, {15, 3}, {15, 0}, {0, 0}, {0, 10}, {4, 10}, {4, 14}};
    p.obstacles = {rectangle(7, 5, 13, 8)};
    DecompositionOptions o;
    o.transitionCells = false;
    const Decomposition d = decompose(p, o);
    EXPECT_EQ(d.cells.size(), 4u);
    EXPECT_NEAR(totalArea(d), ringArea(p.boundary) - 18, 1e-9);
}

TEST(Decomposition, SeveralHolesOnOneSlice) {
    Plan p;
    p.boundary = rectangle(0, 0, 10, 10);
    p.obstacles = {rectangle(4, 1, 6, 3), rectangle(4, 4, 6, 6), rectangle(4, 7, 6, 9)};
    DecompositionOptions o;
    o.transitionCells = false;
    const Decomposition d = decompose(p, o);
    EXPECT_EQ(d.cells.size(), 6u); // left, four between the holes, right
    EXPECT_NEAR(totalArea(d), 100 - 12, 1e-9);
}

TEST(Decomposition, RotatedPlanSameCellCount) {
    Plan p = simplePlan();
    for (double angle : {0.0, 30.0, 45.0, 90.0, 135.0, 180.0}) {
        DecompositionOptions o;
        o.transitionCells = false;
        o.stripeAngleDeg = angle;
        const Decomposition d = decompose(p, o);
        EXPECT_NEAR(totalArea(d), 92, 1e-6) << angle;
        EXPECT_GE(d.cells.size(), 4u) << angle;
    }
}

TEST(Decomposition, LargeCoordinatesDecomposeLikeSmallOnes) {
    const Decomposition a = decompose(simplePlan(), {});
    const Decomposition b = decompose(shifted(simplePlan(), {500000, 5000000}), {});
    ASSERT_EQ(a.cells.size(), b.cells.size());
    for (size_t i = 0; i < a.cells.size(); ++i) {
        EXPECT_NEAR(a.cells[i].area(), b.cells[i].area(), 1e-6);
        EXPECT_EQ(a.cells[i].stripes.size(), b.cells[i].stripes.size());
    }
}

TEST(Decomposition, CellsNeverStraddleRooms) {
    Plan p;
    p.boundary = rectangle(0, 0, 10, 6);
    p.rooms = {{"West", rectangle(0, 0, 4, 6)}, {"East", rectangle(4, 0, 10, 6)}};
    const Decomposition d = decompose(p, {});
    for (const Cell& c : d.cells) {
        if (c.room == 0)
            EXPECT_LE(c.x1, 4 + 1e-9);
        else
            EXPECT_GE(c.x0, 4 - 1e-9);
    }
    EXPECT_NEAR(totalArea(d), 60, 1e-9);
}

TEST(Decomposition, DoorGapJoinsLongestBorderRoom) {
    // Two rooms stacked with a wall between them and a 1.2 m door; the door strip
    // (outside both rooms) borders both equally and the lower room index wins.
    Plan p;
    p.boundary = {{0, 0}, {6, 0}, {6, 4},   {3.6, 4},   {3.6, 4.2}, {6, 4.2},
                  {6, 8}, {0, 8}, {0, 4.2}, {2.4, 4.2}, {2.4, 4},   {0, 4}};
    p.rooms = {{"South", rectangle(0, 0, 6, 4)}, {"North", rectangle(0, 4.2, 6, 8)}};
    const Decomposition d = decompose(p, {});
    EXPECT_EQ(d.roomNames.size(), 2u);
    double south = 0;
    for (const Cell& c : d.cells)
        if (c.room == 0)
            south += c.area();
    EXPECT_NEAR(south, 24 + 1.2 * 0.2, 1e-6); // vertices snap to a 1e-9 grid
    const bool along = std::any_of(d.adjacencies.begin(), d.adjacencies.end(),
                                   [](auto& a) { return a.kind == Adjacency::Kind::AlongSweep; });
    EXPECT_TRUE(along);
}

TEST(Decomposition, NarrowPassageReportedUnreachable) {
    Plan p; // two rooms joined by a 0.6 m wide corridor, W = 1
    p.boundary = {{0, 0},  {4, 0}, {4, 1.7}, {8, 1.7}, {8, 0}, {12, 0},
                  {12, 4}, {8, 4}, {8, 2.3}, {4, 2.3}, {4, 4}, {0, 4}};
    const Decomposition d = decompose(p, {});
    EXPECT_FALSE(d.unreachable.empty());
    double lost = 0;
    for (const UnreachableArea& u : d.unreachable)
        lost += u.area;
    // The corridor (4 x 0.6 m) minus the ends the heads reach from the rooms.
    EXPECT_GT(lost, 2.0);
    EXPECT_LE(lost, 2.4 + 1e-9);
    EXPECT_NEAR(d.unreachable[0].location.y, 2.0, 1e-9);
    int reachable = 0;
    for (const Cell& c : d.cells)
        reachable += c.reachable();
    EXPECT_EQ(reachable, 2); // both rooms, each its own cell
}

TEST(Decomposition, NarrowCellRuleIsDeterministic) {
    // A cell 1.5 W wide between two critical slices becomes two transition cells.
    Plan p;
    p.boundary = rectangle(0, 0, 10, 6);
    p.obstacles = {rectangle(4, 2, 5.5, 4)};
    const Decomposition d = decompose(p, {});
    // The sweep may run either way along x (from the side nearer the centroid).
    const double a = d.frame.toLocal(Vec2{4, 3}).x, b = d.frame.toLocal(Vec2{5.5, 3}).x;
    int narrow = 0;
    for (const Cell& c : d.cells)
        if (c.x0 >= std::min(a, b) - 1e-6 && c.x1 <= std::max(a, b) + 1e-6) {
            EXPECT_EQ(c.kind, CellKind::Transition);
            EXPECT_NEAR(c.width(), 0.75, 1e-9);
            ++narrow;
        }
    EXPECT_EQ(narrow, 4);
}

// Issue 13: wide cells meeting at the corner of a rotated box keep one lattice W apart;
// restarting W/2 inside every cell's edge added a stripe per cell (114 m instead of 102 m on
// shared/plans/simple-diamond).
TEST(StripeLattice, WideCellsAtAnObstacleCornerShareOneLattice) {
    Plan p;
    p.boundary = rectangle(0, 0, 12, 8);
    p.obstacles = {{{6.2, 2.4}, {7.6, 3.7}, {6.0, 5.6}, {4.5, 4.0}}};
    DecompositionOptions o;
    o.stripeAngleDeg = 0.0; // stripes along the 12 m walls: 8 lanes across the 8 m
    auto lanes = [&](bool lattice) {
        o.stripeLattice = lattice ? LatticeMode::AtCorners : LatticeMode::Own;
        const Decomposition d = decompose(p, o);
        EXPECT_TRUE(d.stripeLatticeAvailable);
        EXPECT_EQ(d.stripeLattice, lattice);
        std::vector<double> xs;
        for (const Cell& c : d.cells)
            xs.insert(xs.end(), c.stripes.begin(), c.stripes.end());
        std::sort(xs.begin(), xs.end());
        xs.erase(std::unique(xs.begin(), xs.end(),
                             [](double a, double b) { return std::abs(a - b) < 1e-9; }),
                 xs.end());
        return xs;
    };
    const std::vector<double> shared = lanes(true);
    ASSERT_EQ(shared.size(), 8u);
    for (size_t k = 0; k < shared.size(); ++k)
        EXPECT_NEAR(shared[k], 0.5 + k, 1e-9);
    EXPECT_GT(lanes(false).size(), shared.size()); // each cell W/2 inside its own edges
}

TEST(StripeLattice, CellsKeepTheirOwnStripesWhereTheLatticeWouldNotHold) {
    using detail::LatticeCell;
    using detail::LatticeLink;
    const double w = 1.0;
    // Two wide cells of one room meeting along the whole slice: one lattice, 12 stripes
    // instead of 5 + 8.
    const std::vector<LatticeCell> open{{0, 0.0, 4.5, 8, 8}, {0, 4.5, 12.0, 8, 8}};
    const detail::StripeLayout shared = detail::layOutStripes(open, {{0, 1, 4.5, 8}}, w);
    EXPECT_TRUE(shared.onLattice[0] && shared.onLattice[1]);
    EXPECT_EQ(shared.stripes[0].size() + shared.stripes[1].size(), 12u);
    EXPECT_NEAR(shared.stripes[1].front(), 4.5, 1e-12);
    EXPECT_NEAR(shared.stripes[1].back(), 11.5, 1e-12);
    // An obstacle's flank takes 2 m of the slice: the first cell needs its own last stripe.
    const detail::StripeLayout flank = detail::layOutStripes(open, {{0, 1, 4.5, 6}}, w);
    EXPECT_FALSE(flank.onLattice[0] || flank.onLattice[1]);
    EXPECT_EQ(flank.stripes[0], detail::evenStripePositions(0.0, 4.5, w));
    // Different rooms (their lattices start at their own walls), or a narrow cell.
    const std::vector<LatticeCell> rooms{{0, 0.0, 4.5, 8, 8}, {1, 4.5, 12.0, 8, 8}};
    EXPECT_FALSE(detail::layOutStripes(rooms, {{0, 1, 4.5, 8}}, w).onLattice[0]);
    const std::vector<LatticeCell> narrow{{0, 0.0, 4.5, 8, 8}, {0, 4.5, 5.9, 8, 8}};
    EXPECT_FALSE(detail::layOutStripes(narrow, {{0, 1, 4.5, 8}}, w).onLattice[0]);
    // Consecutive stripes are never more than W apart, lattice or not.
    for (const detail::StripeLayout& layout : {shared, flank}) {
        std::vector<double> all;
        for (const auto& s : layout.stripes)
            all.insert(all.end(), s.begin(), s.end());
        std::sort(all.begin(), all.end());
        for (size_t k = 1; k < all.size(); ++k)
            EXPECT_LE(all[k] - all[k - 1], w + 1e-12);
    }
}

// A noisy map's obstacle traced with a tooth: the slice at the tooth's tip (4.91) leaves a
// sliver cell beside the tooth, narrower than W, next to the wide cell above the obstacle's
// flank. The sliver closes the lower cell's side, so the lower cell spaces its stripes
// evenly, ending W/2 inside at 4.41; the wide cell must then not run the lattice from 5.5,
// which left 4.91 to 5.0 unswept along its whole height.
TEST(StripeLattice, ASideClosedByOneNeighbourIsClosedForAll) {
    using detail::LatticeCell;
    const double w = 1.0;
    const std::vector<LatticeCell> cells{
        {0, 0.0, 4.91, 12, 12}, {0, 4.91, 8.0, 11, 11}, {0, 4.91, 5.0, 1, 1}};
    const std::vector<detail::LatticeLink> links{{0, 1, 4.91, 11}, {0, 2, 4.91, 1}};
    const detail::StripeLayout layout = detail::layOutStripes(cells, links, w);
    ASSERT_FALSE(layout.stripes[0].empty());
    ASSERT_FALSE(layout.stripes[1].empty());
    // The depths either side of the shared side are swept by one of the two cells.
    EXPECT_LE(layout.stripes[1].front() - 0.5 * w, layout.stripes[0].back() + 0.5 * w + 1e-9);
    EXPECT_EQ(layout.onLattice[0], layout.onLattice[1]);
}

// Every x in [from, to] lies within W/2 of some cell's stripe.
void expectEveryDepthSwept(const detail::StripeLayout& layout, double from, double to, double w) {
    std::vector<double> all;
    for (const auto& s : layout.stripes)
        all.insert(all.end(), s.begin(), s.end());
    for (double x = from; x <= to; x += 0.01) {
        double nearest = INFINITY;
        for (double s : all)
            nearest = std::min(nearest, std::abs(s - x));
        EXPECT_LE(nearest, 0.5 * w + 1e-9) << "at " << x;
    }
}

TEST(StripeLattice, ACellBarelyWiderThanItsStripesHandsTheSliverAcross) {
    using detail::LatticeCell;
    const double w = 1.0;
    // A noisy map's box traced 2.05 m tall in a room 7.95 m deep: the cells beside it
    // would need three stripes for the 5 cm over 2 W. The cell below shares their lower
    // sides whole and has 0.1 m to spare, so its first stripe moves up 5 cm and sweeps the
    // sliver; they keep two stripes each.
    const std::vector<LatticeCell> cells{
        {0, 0.0, 3.0, 12, 12}, {0, 3.0, 5.05, 4, 4}, {0, 3.0, 5.05, 4, 4}, {0, 5.05, 7.95, 12, 12}};
    const std::vector<detail::LatticeLink> links{
        {0, 1, 3.0, 4}, {0, 2, 3.0, 4}, {1, 3, 5.05, 4}, {2, 3, 5.05, 4}};
    const double handOff = detail::maxHandOff(w, 0.6);
    EXPECT_NEAR(handOff, 0.15, 1e-12);
    EXPECT_NEAR(detail::maxHandOff(w, 0.9), 0.04, 1e-12); // W/2 - sliver stays >= L/2
    const detail::StripeLayout layout =
        detail::layOutStripes(cells, links, w, LatticeMode::AtCorners, handOff);
    EXPECT_EQ(layout.stripes[0], detail::evenStripePositions(0.0, 3.0, w));
    EXPECT_EQ(detail::layOutStripes(cells, links, w, LatticeMode::Own, handOff).stripes,
              layout.stripes);
    EXPECT_EQ(detail::layOutStripes(cells, links, w).stripes[1].size(), 3u); // none handed
    for (int side : {1, 2}) {
        ASSERT_EQ(layout.stripes[side].size(), 2u);
        EXPECT_NEAR(layout.stripes[side][0], 3.5, 1e-12);
        EXPECT_NEAR(layout.stripes[side][1], 4.5, 1e-12);
        EXPECT_TRUE(layout.onLattice[side]); // placed, not re-spaced per piece
    }
    ASSERT_EQ(layout.stripes[3].size(), 3u);
    EXPECT_NEAR(layout.stripes[3].front(), 5.5, 1e-12); // sweeps [5.0, 5.05] too
    EXPECT_NEAR(layout.stripes[3].back(), 7.45, 1e-12);
    // Every depth of the room lies within W/2 of a stripe, and the sliver's stripe runs
    // in the cell below, whose slice spans the side cells' whole lower sides.
    expectEveryDepthSwept(layout, 0.0, 7.95, w);

    // No hand-off: 0.2 m over 2 W (more than the share), a wall on the shared side, or a
    // cell below without room to spare.
    std::vector<LatticeCell> wider = cells;
    wider[1].x1 = wider[2].x1 = wider[3].x0 = 5.2;
    std::vector<detail::LatticeLink> widerLinks = links;
    widerLinks[2].x = widerLinks[3].x = 5.2;
    EXPECT_EQ(detail::layOutStripes(wider, widerLinks, w, LatticeMode::AtCorners, handOff)
                  .stripes[1]
                  .size(),
              3u);
    std::vector<detail::LatticeLink> walled = links;
    walled[2].length = 3.0; // a wall takes 1 m of the side cell's lower side
    EXPECT_EQ(
        detail::layOutStripes(cells, walled, w, LatticeMode::AtCorners, handOff).stripes[1].size(),
        3u);
    std::vector<LatticeCell> full = cells;
    full[3].x1 = 8.05; // 3 m below: no spare room
    EXPECT_EQ(
        detail::layOutStripes(full, links, w, LatticeMode::AtCorners, handOff).stripes[1].size(),
        3u);
    std::vector<LatticeCell> thin = cells;
    thin[3].x1 = 5.9; // a cell below narrower than W: its stripe goes where the robot fits
    EXPECT_EQ(
        detail::layOutStripes(thin, links, w, LatticeMode::AtCorners, handOff).stripes[1].size(),
        3u);
}

// A traced map's ragged outline starts cells a few centimetres wide across the whole floor
// (an event at each wall tooth). Restarting W/2 inside every such cell gives each its own
// full-length stripe; on the dense lattice they take the room's lattice lines, and a cell
// no line crosses is swept by its neighbours' stripes.
TEST(StripeLattice, DenseLatticeSweepsSliversWithTheNeighboursLines) {
    using detail::LatticeCell;
    const double w = 1.0;
    // One 10 m tall room: slices at 3.0, 3.3 (a 0.3 m sliver), 4.2 and 7.0; the sliver and
    // the next cell are shared whole with their neighbours but for 0.2 m of a pillar's face.
    const std::vector<LatticeCell> cells{
        {0, 0.0, 3.0, 10, 10}, {0, 3.0, 3.3, 10, 10}, {0, 3.3, 4.2, 10, 10}, {0, 4.2, 7.0, 10, 10}};
    const std::vector<detail::LatticeLink> links{
        {0, 1, 3.0, 10}, {1, 2, 3.3, 9.8}, {2, 3, 4.2, 9.8}};
    const detail::StripeLayout own = detail::layOutStripes(cells, links, w, LatticeMode::Own);
    const detail::StripeLayout dense = detail::layOutStripes(cells, links, w, LatticeMode::Dense);
    size_t ownCount = 0, denseCount = 0;
    for (size_t i = 0; i < cells.size(); ++i)
        ownCount += own.stripes[i].size(), denseCount += dense.stripes[i].size();
    EXPECT_EQ(ownCount, 3u + 1u + 1u + 3u);
    EXPECT_EQ(denseCount, 7u);             // one lattice line every W across the room's 7 m
    EXPECT_TRUE(dense.stripes[1].empty()); // the sliver: swept from both sides
    ASSERT_EQ(dense.stripes[2].size(), 1u);
    EXPECT_NEAR(dense.stripes[2][0], 3.5, 1e-12);
    // Every x of the room lies within W/2 of a stripe.
    expectEveryDepthSwept(dense, 0.0, 7.0, w);

    // A long wall on a side still gets its stripe W/2 inside it: a room ending at 7.3 m has
    // no lattice line within W/2 of its end wall (6.5 m is 0.8 m from it).
    std::vector<LatticeCell> longer = cells;
    longer[3].x1 = 7.3;
    const detail::StripeLayout walled = detail::layOutStripes(longer, links, w, LatticeMode::Dense);
    ASSERT_EQ(walled.stripes[3].size(), 4u);
    EXPECT_NEAR(walled.stripes[3][2], 6.5, 1e-12);
    EXPECT_NEAR(walled.stripes[3][3], 6.8, 1e-12);

    // A narrow cell at a doorway keeps its own stripe in its middle, off the lattice; the
    // sliver beside it then cannot rely on the lattice and sweeps itself.
    std::vector<LatticeCell> narrow = cells;
    narrow[2].keepsStripe = true;
    const detail::StripeLayout chained =
        detail::layOutStripes(narrow, links, w, LatticeMode::Dense);
    ASSERT_EQ(chained.stripes[2].size(), 1u);
    EXPECT_NEAR(chained.stripes[2][0], 3.75, 1e-12);
    EXPECT_FALSE(chained.onLattice[2]);
    ASSERT_EQ(chained.stripes[1].size(), 1u);
    EXPECT_NEAR(chained.stripes[1][0], 3.15, 1e-12);
}

// Cells without stripes are not required and their neighbours are joined across them.
TEST(StripeLattice, DenseDecompositionJoinsTheCellsAcrossASliver) {
    Plan p;
    p.boundary = rectangle(0, 0, 10, 8);
    // Two small pillars whose slices cut the room into cells 0.2-0.5 m wide.
    p.obstacles = {rectangle(3.0, 2.0, 3.2, 2.2), rectangle(3.4, 5.0, 3.6, 5.2)};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0;
    o.stripeLattice = LatticeMode::Dense;
    const Decomposition d = decompose(p, o);
    EXPECT_TRUE(d.stripeLattice);
    int swept = 0;
    for (const Cell& c : d.cells) {
        if (!c.sweptByNeighbours)
            continue;
        ++swept;
        EXPECT_TRUE(c.stripes.empty());
        // Some cell on its left is joined to some cell on its right.
        bool joined = false;
        for (const Adjacency& a : d.adjacencies)
            if (a.kind == Adjacency::Kind::AcrossSweep && d.cells[a.first].x1 <= c.x0 + 1e-9 &&
                d.cells[a.second].x0 >= c.x1 - 1e-9 && !d.cells[a.first].sweptByNeighbours &&
                !d.cells[a.second].sweptByNeighbours)
                joined = true;
        EXPECT_TRUE(joined) << c.id;
    }
    EXPECT_GT(swept, 0);
    EXPECT_TRUE(d.unreachable.empty());
}

// Headlands (DecompositionOptions::headland): along the walls the stripes end at, a band
// one W deep becomes cells of their own whose single pass runs W/2 from the wall; the
// stripes of the rest end W/2 inside the band. The bands belong to the room they border.
TEST(Headland, BandsAlongTheWallsTheStripesEndAt) {
    Plan p;
    p.boundary = rectangle(0, 0, 10, 6);
    p.rooms = {{"Hall", rectangle(0, 0, 10, 6)}};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0; // stripes along y in the world, ending at y = 0 and y = 6
    o.headland = Headland::Both;
    const Decomposition d = decompose(p, o);
    ASSERT_TRUE(d.headland);
    EXPECT_NEAR(totalArea(d), 60.0, 1e-9);
    ASSERT_EQ(d.roomNames.size(), 1u);
    int bandCells = 0;
    double lowestInnerEnd = INFINITY;
    for (const Cell& c : d.cells) {
        EXPECT_EQ(c.room, 0);
        const double height = c.ceilingAt(0.5 * (c.x0 + c.x1)) - c.floorAt(0.5 * (c.x0 + c.x1));
        for (const Interval& span : c.stripeSpans) {
            ASSERT_FALSE(span.empty());
            if (height <= 1.0 + 1e-9) { // a band: one pass W/2 from its wall
                EXPECT_NEAR(span.hi - span.lo, 0.0, 1e-9);
                EXPECT_NEAR(std::min(std::abs(span.lo - 0.5), std::abs(span.lo - 5.5)), 0.0, 1e-9);
            } else {
                lowestInnerEnd = std::min(lowestInnerEnd, span.lo);
            }
        }
        bandCells += height <= 1.0 + 1e-9 ? 1 : 0;
    }
    EXPECT_GE(bandCells, 2);
    EXPECT_NEAR(lowestInnerEnd, 1.5, 1e-9);
    // Without the option nothing changes.
    o.headland = Headland::None;
    const Decomposition plain = decompose(p, o);
    EXPECT_FALSE(plain.headland);
    for (const Cell& c : plain.cells)
        for (const Interval& span : c.stripeSpans)
            EXPECT_NEAR(span.lo, 0.5, 1e-9);
}

// No band where the room is too shallow for one beside a sweep (a 2.5 W corridor across
// the stripes), nor where a slab narrows to nothing (a wedge: its band would end in a point
// the robot cannot reach); the cells are the plain ones.
// A slab narrower than W at a chamfered corner continues its neighbour's band: the band
// runs the wall's whole length, and no corner sliver is left a cell of its own.
TEST(Headland, BandsRunIntoChamferedCorners) {
    Plan p;
    const double c = 0.2;
    p.boundary = {{c, 0},      {10 - c, 0}, {10, c},    {10, 6 - c},
                  {10 - c, 6}, {c, 6},      {0, 6 - c}, {0, c}};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0;
    o.headland = Headland::Both;
    const Decomposition d = decompose(p, o);
    ASSERT_TRUE(d.headland);
    double bandFrom = INFINITY, bandTo = -INFINITY;
    for (const Cell& cell : d.cells) {
        const double mid = 0.5 * (cell.x0 + cell.x1);
        if (cell.headland) {
            bandFrom = std::min(bandFrom, cell.x0);
            bandTo = std::max(bandTo, cell.x1);
        } else {
            EXPECT_GT(cell.ceilingAt(mid) - cell.floorAt(mid), 1.0) << cell.x0 << " " << cell.x1;
        }
    }
    EXPECT_NEAR(bandFrom, 0.0, 1e-9);
    EXPECT_NEAR(bandTo, 10.0, 1e-9);
}

// A traced wall's tooth (an obstacle's side bulging 0.1 m over 0.375 m, narrower than W)
// does not offset the band beside it: the band's inner edge stays W from the wall on either
// side of the tooth, under it too, so the band's pieces line up and join as one band, and
// their single pass runs on one line.
TEST(Headland, BandsRunPastATracedWallsTooth) {
    Plan p;
    p.boundary = rectangle(0, 0, 12, 10);
    p.obstacles = {
        Ring{{3, 5}, {5.35, 5}, {5.35, 4.9}, {5.725, 4.9}, {5.725, 5}, {9, 5}, {9, 8}, {3, 8}}};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0;
    o.headland = Headland::Both;
    const Decomposition d = decompose(p, o);
    ASSERT_TRUE(d.headland);
    // In the sweep frame the obstacle's toothed side is the floor of the floor beyond it, at
    // y = 5 (5.1 at the tooth; the frame's y runs against the world's here).
    double covered = 0.0;
    int passes = 0;
    for (const Cell& cell : d.cells) {
        const double mid = 0.5 * (cell.x0 + cell.x1);
        if (!cell.headland || cell.x0 < 3 - 1e-9 || cell.x1 > 9 + 1e-9 ||
            std::abs(cell.floorAt(mid) - 5.05) > 0.06)
            continue;
        covered += cell.x1 - cell.x0;
        for (double x : {cell.x0 + 1e-6, mid, cell.x1 - 1e-6})
            EXPECT_NEAR(cell.ceilingAt(x), 6.0, 1e-9) << "band piece " << cell.x0 << "-" << cell.x1;
        // One pass W/2 from the band's inner edge, in line with its neighbours' (under the
        // tooth too, where the robot keeps 0.4 m from it).
        for (const Interval& span : cell.stripeSpans) {
            if (span.empty())
                continue; // no pass of its own (its neighbours' sweep it)
            ++passes;
            EXPECT_NEAR(span.lo, 5.5, 1e-9) << "band piece " << cell.x0 << "-" << cell.x1;
            EXPECT_NEAR(span.hi, 5.5, 1e-9) << "band piece " << cell.x0 << "-" << cell.x1;
        }
    }
    EXPECT_NEAR(covered, 6.0, 1e-9); // the band runs the obstacle's whole side
    EXPECT_GE(passes, 5);
    EXPECT_NEAR(totalArea(d), 120.0 - 18.0 - 0.0375, 1e-9);
}

TEST(Headland, NoBandInShallowRoomsOrWedges) {
    DecompositionOptions o;
    o.stripeAngleDeg = 0.0; // stripes along world x
    o.headland = Headland::Both;
    Plan corridor;
    corridor.boundary = rectangle(0, 0, 20, 2.5); // stripes across its 2.5 m
    o.stripeAngleDeg = 90.0;
    const Decomposition c = decompose(corridor, o);
    EXPECT_FALSE(c.headland);
    EXPECT_NEAR(totalArea(c), 50.0, 1e-9);
    Plan wedge;
    wedge.boundary = {{0, 0}, {10, 0}, {0, 10}};
    o.stripeAngleDeg = 0.0;
    const Decomposition d = decompose(wedge, o);
    EXPECT_FALSE(d.headland);
    EXPECT_NEAR(totalArea(d), 50.0, 1e-9);
    o.headland = Headland::None;
    EXPECT_EQ(decompose(wedge, o).cells.size(), d.cells.size());
}

// A round wall traced with thousands of vertices: the border trace follows it as a smooth
// curve (thinned seeds, refined where the curve leaves its chords) instead of sampling
// every vertex five times, which made a 20,000-vertex circle plan in 40 s. The trace stays
// on the exact offset: the clear limit 0.3 m from the wall, then 0.2 m further in.
TEST(StripeSpans, ABorderTracedWithThousandsOfVerticesIsFollowedAsACurve) {
    const double radius = 15.0;
    const int n = 20000;
    Cell cell;
    cell.x0 = -radius, cell.x1 = radius;
    for (int k = 0; k <= n; ++k) {
        const double a = M_PI + M_PI * k / n; // the lower half circle, left to right
        cell.floor.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    cell.floor.front().x = -radius, cell.floor.back().x = radius;
    cell.ceiling = {{-radius, 0.0}, {radius, 0.0}};
    const ClearanceField field({cell.outline()}, 0.3, 0.5);
    const Polyline trace = detail::traceBorder(cell, -5.0, 5.0, false, field);
    ASSERT_GE(trace.size(), 2u);
    EXPECT_LT(trace.size(), 1000u); // some 4,400 vertices lie under it
    auto exact = [&](double x) {
        return -std::sqrt((radius - 0.3) * (radius - 0.3) - x * x) + 0.2;
    };
    EXPECT_NEAR(trace.front().x, -5.0, 1e-12);
    EXPECT_NEAR(trace.back().x, 5.0, 1e-12);
    for (size_t i = 0; i < trace.size(); ++i) {
        EXPECT_NEAR(trace[i].y, exact(trace[i].x), 2e-3) << "at " << trace[i].x;
        if (i > 0) {
            const Vec2 mid = (trace[i - 1] + trace[i]) * 0.5;
            EXPECT_NEAR(mid.y, exact(mid.x), 2e-3) << "chord at " << mid.x;
        }
    }
}

TEST(Decomposition, ARoomCutAlongALeaningJambStartsNoCellsThere) {
    // A map's doorway: the wall between two rooms is 0.2 m thick, the door 1.2 m wide, and
    // the segmentation cut the rooms in the middle of the doorway. The traced jamb leans by
    // 0.3 mm, so the border's end on it lies at another x than the jamb's corner. The south
    // room is swept as if the jamb stood straight: six stripes across its 6 m.
    auto southStripes = [](double lean) {
        Plan p;
        const double mid = 2.4 - 0.5 * lean; // where the border meets the leaning jamb
        p.boundary = {{0, 0}, {6, 0}, {6, 4},   {3.6, 4},          {3.6, 4.2}, {6, 4.2},
                      {6, 8}, {0, 8}, {0, 4.2}, {2.4 - lean, 4.2}, {2.4, 4},   {0, 4}};
        p.rooms = {
            {"South", {{0, 0}, {6, 0}, {6, 4}, {3.6, 4}, {3.6, 4.1}, {mid, 4.1}, {2.4, 4}, {0, 4}}},
            {"North",
             {{0, 4.2},
              {2.4 - lean, 4.2},
              {mid, 4.1},
              {3.6, 4.1},
              {3.6, 4.2},
              {6, 4.2},
              {6, 8},
              {0, 8}}}};
        DecompositionOptions o;
        o.stripeAngleDeg = 90.0; // stripes along the jambs
        const Decomposition d = decompose(p, o);
        size_t stripes = 0;
        for (const Cell& c : d.cells)
            if (c.room == 0)
                stripes += c.stripes.size();
        return stripes;
    };
    EXPECT_EQ(southStripes(0.0), 6u);
    EXPECT_EQ(southStripes(3e-4), 6u);
}

TEST(Decomposition, VerticesJitteredByMicrometresDecomposeAsDrawn) {
    // Two 6 x 8 m rooms round a 2 x 2 m block (tests/data/utm-offset.geojson), every vertex
    // moved by up to 60 um as a reprojection or a drawing tool's rounding does: the same
    // cells and stripes as drawn, at the sweep angle the jittered walls give (off by 1e-4
    // degrees). The walls leaned at it by tens of micrometres and cut slivers, a room 60 um
    // wider than 6 m took a seventh stripe, and a centroid micrometres off the middle
    // turned the sweep round: 10 to 17 cells for 8.
    Plan drawn;
    drawn.boundary = {{0, 0}, {12, 0}, {12, 8}, {0, 8}};
    drawn.obstacles = {{{5, 3}, {5, 5}, {7, 5}, {7, 3}}};
    drawn.rooms = {{"West", {{0, 0}, {6, 0}, {6, 8}, {0, 8}}},
                   {"East", {{6, 0}, {12, 0}, {12, 8}, {6, 8}}}};
    auto layout = [](const Plan& p, double angle) {
        DecompositionOptions o;
        o.stripeAngleDeg = angle;
        o.robot.robotDiameter = 0.6; // the defaults: a disc the robot drives W/2 off walls
        o.robot.coverageWidth = 1.0;
        const Decomposition d = decompose(p, o);
        size_t stripes = 0;
        for (const Cell& c : d.cells)
            stripes += c.stripes.size();
        return std::pair{d.cells.size(), stripes};
    };
    const auto asDrawn = layout(drawn, 90.0);
    std::uint64_t state = 7;
    auto jitter = [&] { // uniform in [-60, 60] um
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return 120e-6 * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
    };
    for (int trial = 0; trial < 5; ++trial) {
        std::map<std::pair<double, double>, Vec2> moved; // a shared vertex moves once
        auto move = [&](Ring& ring) {
            for (Vec2& v : ring) {
                auto [it, added] = moved.try_emplace({v.x, v.y}, v);
                if (added)
                    it->second = v + Vec2{jitter(), jitter()};
                v = it->second;
            }
        };
        Plan p = drawn;
        move(p.boundary);
        move(p.obstacles[0]);
        for (Room& room : p.rooms)
            move(room.outline);
        for (const double angle : {90.0, 90.0 + 1e-4, 90.0 - 1e-4})
            EXPECT_EQ(layout(p, angle), asDrawn) << "trial " << trial << " at " << angle;
    }
}

TEST(Decomposition, ItsClearanceFieldKeepsTheWallsAsDrawnNotAsStraightened) {
    // A wall leaning by 1.9 mm over 3 m is straightened for the sweep (the cells see it
    // upright), but the robot must keep L/2 from where it really is: a noisy ward map's
    // transit passed a corner of such a wall 1.1 mm inside L/2.
    Plan p;
    p.boundary = {{0, 0}, {10, 0}, {10, 6}, {6.0019, 6}, {6, 3}, {4, 3}, {4, 6}, {0, 6}};
    p.rooms = {{"Hall", p.boundary}};
    DecompositionOptions o;
    o.stripeAngleDeg = 90.0;
    o.robot.robotDiameter = 0.6;
    o.robot.coverageWidth = 1.0;
    const Decomposition d = decompose(p, o);
    const double wallX = 6.0 + 0.0019 * (5.5 - 3.0) / 3.0; // the drawn wall at y = 5.5
    const Vec2 tooClose{wallX + 0.2990, 5.5};              // 0.3008 m from the upright wall
    const Vec2 clear{wallX + 0.3010, 5.5};
    EXPECT_FALSE(d.clearance().isClear(d.frame.toLocal(tooClose)));
    EXPECT_TRUE(d.clearance().isClear(d.frame.toLocal(clear)));
    double area = 0.0;
    for (const Cell& c : d.cells)
        area += c.area();
    EXPECT_NEAR(area, 60.0 - 6.0, 0.01);
}

// The floor beside a bed's long side: the dense lattice's line there runs closer than L/2 to
// it (blocked along the bed), or the cell beside it is a sliver the robot cannot enter; a
// stripe W/2 off the side sweeps it, in the cell beyond the sliver where need be.
TEST(StripeLattice, DenseLatticeSweepsAlongABedsSideItsLineCannotPass) {
    auto unswept = [](const Plan& p) {
        DecompositionOptions o;
        o.stripeAngleDeg = 90.0;
        o.stripeLattice = LatticeMode::Dense;
        o.robot.robotDiameter = 0.6;
        o.robot.coverageWidth = 1.0;
        const Decomposition d = decompose(p, o);
        int missed = 0;
        for (double x = 6.27; x < 7.2; x += 0.05) {
            for (double y = 1.1; y < 2.9; y += 0.2) {
                const Vec2 q = d.frame.toLocal(Vec2{x, y});
                bool swept = false;
                for (const Cell& c : d.cells)
                    for (size_t k = 0; k < c.stripes.size() && k < c.stripeSpans.size(); ++k)
                        swept = swept ||
                                (std::abs(c.stripes[k] - q.x) <= 0.5 + 1e-9 &&
                                 !c.stripeSpans[k].empty() && q.y >= c.stripeSpans[k].lo - 0.5 &&
                                 q.y <= c.stripeSpans[k].hi + 0.5);
                missed += !swept;
            }
        }
        return missed;
    };
    // A 10 x 4 m ward room, its lattice W/2 inside the side walls (0.5, 1.5, ...): one bed's
    // side at 3.0 m has a line W/2 off it; the other's at 6.25 m has one 0.25 m off it. The
    // beds are 2.2 m long: a stripe the room's depth beside them costs less than a touch-up.
    Plan p;
    p.boundary = rectangle(0, 0, 10, 4);
    p.obstacles = {rectangle(2.0, 0.9, 3.0, 3.1), rectangle(5.25, 0.9, 6.25, 3.1)};
    EXPECT_EQ(unswept(p), 0);
    // The traced bed: a corner knocked 5 cm out, so the side is a step of the cell below
    // it and a sliver cell 5 cm wide runs beside the rest.
    p.obstacles[1] = {{5.25, 0.9}, {6.25, 0.9}, {6.25, 3.0}, {6.3, 3.1}, {5.25, 3.1}};
    EXPECT_EQ(unswept(p), 0);
}
